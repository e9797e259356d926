"""Citations used in the epicycle_rim reports, in one place so that a reference is corrected
once.

Paper A: S. S. Gutyria, S. A. Medvedev, Yu. M. Khomiak, A. N. Chanchin, "Probabilistic
analysis of the fatigue strength of the epicycle of a trolleybus wheel gearbox", Visnyk NTU
"KhPI", series "Problems of mechanical drive", 2017, No. 25 (1247), pp. 37-41 (Raba 118/77
ring gear of the MAZ-103T trolleybus).

Paper B: V. P. Yaglinskyi, S. S. Gutyria, A. M. Chanchin, V. M. Zheglova, "Influence of
parametric oscillations on the fatigue strength of a wheel-gearbox epicycle", same journal
series, 2017.

GOST 25.504-82 (calculation of fatigue-strength characteristics, Serensen-Kogaev statistical
similarity theory): its text could not be consulted; every formula cited to it below is
taken from paper A, which applies it, and is marked so (``GOST25504``).
"""

A = "Gutyria et al. 2017"
B = "Yaglinskyi et al. 2017"
GOST25504 = "GOST 25.504-82 via Gutyria 2017"
GOST21354 = "GOST 21354-87"
ISO6336_3 = "ISO 6336-3 Y_B (unverified); AGMA 2001 K_B"
ROARK = "thin-ring theory (estimate)"
MATHIEU = "Mathieu eq., DLMF §28.4"
MATHIEU_SERIES = "Yaglinskyi et al. 2017 (8); A&S 20.2.25"
FLOQUET = "Floquet theory"
PHASING = "Parker & Lin 2004 (unverified)"
KINEMATICS = "2K-H kinematics, fixed ring"
ASSEMBLY = "planetary assembly conditions"
PRACTICE = "design practice"
MINER = "Palmgren-Miner rule"
