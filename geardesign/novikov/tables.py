"""Coefficient tables of Korotkin's NOVGOST-17 algorithm, as data.

Source: V. I. Korotkin, "Algorithm of the program for calculating Novikov gears with basic
rack per GOST 15023-76 under real multi-pair engagement", Bulletin of NTU "KhPI", series
"Problems of mechanical drive", 2017, No. 25 (1247) — cited below as *Korotkin 2017* ([Korotkin2017]
tables 2-4). Every value
below was read in the paper's tables; a corrected value is a one-line change here.

Each polynomial table is a tuple of four coefficient rows ``(c0, c1, c2, c3)``; the row
``cp`` multiplies ``(ψ + 0.1)^(−p)`` and its element ``q`` multiplies ``(t − 0.05)^q``
(equations (1) and (6) of the paper).
"""

from __future__ import annotations

#: Table 2 of Korotkin 2017: coefficients B_pq of polynomial (1) for the compliance ratio K_W.
KW_COEFFS: tuple[tuple[float, ...], ...] = (
    (1.088542071, 0.707414624, 8.80136403, -5.49138098, -72.72337279, 195.0130164,
     -229.7322108),
    (-0.0527394841, -0.592761524, -4.38685466, 14.25159435),
    (0.01081320750, 0.1523174518, 0.565335262, -3.688630532, 3.23146680),
    (-0.000745032335, -0.0112961032, -0.01119600776, 0.0584688517, 1.293088808, -5.310617105,
     5.911151313),
)

#: Table 3 of Korotkin 2017: coefficients D_pq of polynomial (6) for the bending-stress ratio
#: K_F.  (The summation limits printed above (6) read "3 3 8 4" in the scan; the number of
#: coefficients in Table 3 shows that the first is 8.)
KF_COEFFS: tuple[tuple[float, ...], ...] = (
    (1.871506319, 1.563476694, 14.4470097, 55.6401674, -1093.467710, 5971.510165,
     -16042.47377, 21557.73546, -11933.42610),
    (-0.5665708370, -1.170819861, -8.103911818, 18.40037290),
    (0.1191335146, 0.2645474414, 1.545329623, -10.77790889, 59.06894715, -134.1429969,
     -246.2482220, 1333.126216, -1332.943804),
    (-0.008074840884, -0.01593320543, -0.08783776606, 0.2492244718, -0.03371973321),
)

#: Equation (5) of Korotkin 2017: K_ψ as a quartic in ψ, coefficients of ψ^0 … ψ^4.  It
#: interpolates the five nodes (0.05; 0.724) (0.10; 0.936) (0.15; 0.923) (0.20; 0.878)
#: (0.25; 0.794) and is meaningless outside them ([Korotkin2017] eq. (4)).
KPSI_COEFFS: tuple[float, ...] = (-0.106, 26.4, -238.8666667, 923.9999998, -1333.333333)

#: Table 4 of Korotkin 2017: the contact-stress ratio K_H, rows t (distance of the contact
#: point from mid-face, fraction of b_w), columns ψ.  Rows in increasing t.  The paper prints
#: the row between 0.450 and 0.475 as "0.463"; the grid spacing shows 0.4625 (0.463 is its
#: rounding to three decimals).
KH_PSI: tuple[float, ...] = (0.05, 0.10, 0.15, 0.20, 0.25)
KH_ROWS: tuple[tuple[float, tuple[float, ...]], ...] = (
    (0.000, (1.000, 1.000, 1.000, 1.003, 1.000)),
    (0.150, (1.000, 1.000, 1.000, 1.009, 1.000)),
    (0.200, (1.000, 1.009, 1.000, 1.017, 1.059)),
    (0.250, (1.022, 1.014, 1.039, 1.035, 1.106)),
    (0.275, (1.022, 1.018, 1.045, 1.043, 1.188)),
    (0.300, (1.040, 1.037, 1.071, 1.070, 1.376)),
    (0.325, (1.090, 1.055, 1.090, 1.096, 1.612)),
    (0.350, (1.126, 1.083, 1.123, 1.287, 1.835)),
    (0.375, (1.183, 1.133, 1.168, 1.574, 2.000)),
    (0.400, (1.277, 1.197, 1.265, 1.722, 2.153)),
    (0.425, (1.410, 1.284, 1.594, 1.939, 2.318)),
    (0.450, (1.673, 1.591, 1.916, 2.139, 2.494)),
    (0.4625, (1.827, 1.858, 2.039, 2.243, 2.576)),
    (0.475, (2.102, 2.133, 2.213, 2.357, 2.659)),
    (0.500, (2.732, 2.385, 2.355, 2.470, 2.729)),
)

#: Validity range of the fitted factors K_W, K_F, K_ψ and of Table 4 (the fits were made on
#: ψ = 0.05 … 0.25 and t = 0 … 0.5; [Korotkin2017] table 3).
PSI_RANGE: tuple[float, float] = (0.05, 0.25)
T_RANGE: tuple[float, float] = (0.0, 0.5)

#: The 3-D tooth form factor Y_v of Korotkin 2017 ([Korotkin2017] eq. (5)): for each shift branch
#: and z_v branch, ``(A, B, p, e, q)`` in
#: Y_v = A·z_v^p + B·|x|^e·z_v^q (B carries the sign).  The two exponents q of the branch
#: x > 0 are unreadable in the scan; 1.17 and 1.16 are placeholders that make the two z_v
#: branches meet at z_v = 18 (results with x > 0 are flagged as unverified).
YV_SPLIT_ZV = 18.0
YV_BRANCHES: dict[tuple[str, str], tuple[float, float, float, float, float]] = {
    ("neg", "small"): (1.18, 2.08, -0.285, 1.15, -1.32),
    ("neg", "large"): (0.52, 1.17, 0.0, 1.33, -1.058),
    ("pos", "small"): (1.18, -3.59, -0.285, 1.0, -1.17),
    ("pos", "large"): (0.52, -3.50, 0.0, 1.0, -1.16),
}
YV_PLACEHOLDER_EXPONENTS = True
"""The x > 0 exponents above are placeholders (see :data:`YV_BRANCHES`)."""

#: Equation (4) of Korotkin 2017 (reconstructed reading, [Korotkin2017] eq. (4)):
#: σ_H = C·l_k^a·(F/cos α_k)^b·ρ_p^c·K_ψ·K_H with these constants (steel pair, MPa, N, mm).
SIGMA_H_CONST: tuple[float, float, float, float] = (19.93, -1.074, 0.69, -0.31)
