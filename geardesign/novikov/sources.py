"""Citations used in the Novikov reports, in one place so that a reference is corrected once.

*Korotkin 2017*: V. I. Korotkin, "Algorithm of the program for calculating Novikov gears
with basic rack per GOST 15023-76 under real multi-pair engagement" (NOVGOST-17), Bulletin
of NTU "KhPI", series "Problems of mechanical drive", 2017, No. 25 (1247).
*Cyclogram 2017*: N. V. Matyushenko, A. V. Fedchenko, V. A. Berezhnoi, "Numerical study of
the cyclogram and of the overlap at re-engagement of adjacent teeth", same issue.
Equation, table and figure numbers are those of the papers.
"""

RACK = "GOST 15023-76 (values unverified, see docs)"
KOROTKIN = "Korotkin 2017"
GEOM = "Korotkin 2017, Table 1; theory of gearing"
TABLE1 = "Korotkin 2017, Table 1"
PHASES = "Korotkin 2017, phase step Δb = p_x/(b_w·f_z)"
CYCLOGRAM = "Cyclogram 2017, criteria 1-2 (sign corrected)"
SHARING = "Korotkin 2017, system (2)"
KW = "Korotkin 2017, eq. (1), Table 2"
BENDING = "Korotkin 2017, eq. (3), (6), Table 3"
CONTACT = "Korotkin 2017, eq. (4), (5), Table 4"
YV = "Korotkin 2017, Y_v formulas"
RHO_P = "[Korotkin2017] eq. (4) (reconstructed)"
ELLIPSE = "Hertz line contact over l_k (assumption, [Korotkin2017] eq. (4))"
COMPLIANCE = "c'·2a (assumption)"
TOLERANCES = "GOST 1643-81 as fitted in ZPCIL (FPB.h, FCBE.h)"
ERROR_MODEL = "probabilistic design value γ·σ (assumption, [GOST1643])"
FORCES = "theory of gearing (textbook)"
G21354 = "GOST 21354-87 ([ZPCIL] SGMHLB.h, CONTAU.h, IZGIBU.h, YLIFE.h; [DANNYE])"
MODULES = "GOST 14186-69 (from memory)"
PRACTICE = "design practice"
