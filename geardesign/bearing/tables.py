"""Coefficient tables of the bearing life calculation: data only, one structure each.

Every table names its source and how far it was verified.  "Secondary" means
confirmed by a public implementation ([BBContact], [Dessia], [Jordanrobot]). The printed standards
(ISO 281:2007,
GOST 18855-94/-2013, ISO 76) were not available; where a table rests only on [Haidamaka2017] or a
textbook it is marked *unverified*.
"""

from __future__ import annotations

# ----------------------------------------------------------------------------- types

BALL_TYPES = ("deep_groove_ball", "angular_contact_ball", "self_aligning_ball", "thrust_ball")
ROLLER_TYPES = ("cylindrical_roller", "tapered_roller", "spherical_roller", "thrust_roller")
TYPES = BALL_TYPES[:3] + ROLLER_TYPES[:3] + ("thrust_ball", "thrust_roller")
THRUST_TYPES = ("thrust_ball", "thrust_roller")

B_M = {
    # b_m, rating factor for contemporary material and manufacturing quality.
    # ISO 281:2007 Table 1 via [ISO281] table 1; ball value 1.3 confirmed (secondary)
    # by the standards check (public ISO 281 transcription).  Others unverified.
    "deep_groove_ball": 1.3,
    "angular_contact_ball": 1.3,
    "self_aligning_ball": 1.3,
    "thrust_ball": 1.3,
    "cylindrical_roller": 1.1,
    "tapered_roller": 1.1,
    "spherical_roller": 1.15,
    "thrust_roller": 1.0,
}

# ----------------------------------------------------------------------------- f_c

F_C_BALL = (
    # γ = D_w·cos α/D_pw; f_c for (single-row deep groove and single/double-row angular
    # contact, double-row deep groove, self-aligning).  ISO 281:2007 Table 2 via [ISO281]; the first
    # column confirmed (secondary) by the standards check, which also
    # reports a row γ = 0.19 (60.0) not listed here (interpolation differs by <= 0.1).
    (0.01, 29.1, 27.5, 9.9), (0.02, 35.8, 33.9, 12.4), (0.03, 40.3, 38.2, 14.3),
    (0.04, 43.8, 41.5, 15.9), (0.05, 46.7, 44.2, 17.3), (0.06, 49.1, 46.5, 18.6),
    (0.07, 51.1, 48.4, 19.9), (0.08, 52.8, 50.0, 21.1), (0.09, 54.3, 51.4, 22.3),
    (0.10, 55.5, 52.6, 23.4), (0.12, 57.5, 54.5, 25.6), (0.14, 58.8, 55.7, 27.7),
    (0.16, 59.6, 56.5, 29.7), (0.18, 59.9, 56.8, 31.7), (0.20, 59.9, 56.8, 33.5),
    (0.22, 59.6, 56.5, 35.2), (0.24, 59.0, 55.9, 36.8), (0.26, 58.2, 55.1, 38.2),
    (0.28, 57.1, 54.1, 39.4), (0.30, 56.0, 53.0, 40.3), (0.32, 54.6, 51.8, 40.9),
    (0.34, 53.2, 50.4, 41.2), (0.36, 51.7, 48.9, 41.4), (0.38, 50.0, 47.4, 41.4),
    (0.40, 48.4, 45.8, 41.2),
)

F_C_ROLLER = (
    # γ = D_we·cos α/D_pw; f_c of radial roller bearings.  ISO 281:2007 (radial roller f_c
    # table) via [ISO281], which reproduces it from the ISO/TR 1281-1 closed
    # form within ±0.08.  Unverified against the printed standard.
    (0.01, 52.1), (0.02, 60.8), (0.03, 66.5), (0.04, 70.7), (0.05, 74.1), (0.06, 76.9),
    (0.07, 79.2), (0.08, 81.2), (0.09, 82.8), (0.10, 84.2), (0.11, 85.4), (0.12, 86.4),
    (0.13, 87.1), (0.14, 87.7), (0.15, 88.2), (0.16, 88.5), (0.17, 88.7), (0.18, 88.8),
    (0.19, 88.8), (0.20, 88.7), (0.21, 88.5), (0.22, 88.2), (0.23, 87.9), (0.24, 87.5),
    (0.25, 87.0), (0.26, 86.4), (0.27, 85.8), (0.28, 85.2), (0.29, 84.5), (0.30, 83.8),
)

# ----------------------------------------------------------------------------- X, Y, e

DEEP_GROOVE = (
    # Radial contact groove (deep groove) ball bearings: columns f0·Fa/C0r (ISO form),
    # Fa/C0r (textbook form, GOST 18855-94 practice), e, Y for Fa/Fr > e with X = 0.56.
    # ISO 281:2007 Table 3 / GOST 18855-94; same values in both editions.  The Fa/C0r column
    # is the one printed in the NTN catalogue example (CAT. No. 2202/E, A-26: Fa/Cor = 0.10
    # gives e = 0.29, Y = 1.48) and in five public implementations ([ISO281] table 3).
    (0.172, 0.014, 0.19, 2.30), (0.345, 0.028, 0.22, 1.99), (0.689, 0.056, 0.26, 1.71),
    (1.03, 0.084, 0.28, 1.55), (1.38, 0.11, 0.30, 1.45), (2.07, 0.17, 0.34, 1.31),
    (3.45, 0.28, 0.38, 1.15), (5.17, 0.42, 0.42, 1.04), (6.89, 0.56, 0.44, 1.00),
)
DEEP_GROOVE_X = 0.56

ANGULAR_VARIABLE = {
    # Angular contact ball bearings with α = 10° and 15°: entry i·f0·Fa/C0r (same break
    # points as DEEP_GROOVE), rows (e, Y single row [X_single], Y double row Fa/Fr <= e
    # [X = 1], Y double row Fa/Fr > e [X_double]).  ISO 281:2007 Table 3 via [ISO281] table 3: α =
    # 10° single row corroborated by a public implementation, the rest
    # medium-high confidence (unverified).
    10.0: {"X_single": 0.46, "X_double": 0.75, "rows": (
        (0.29, 1.88, 2.18, 3.06), (0.32, 1.71, 1.98, 2.78), (0.36, 1.52, 1.76, 2.47),
        (0.38, 1.41, 1.63, 2.29), (0.40, 1.34, 1.55, 2.18), (0.44, 1.23, 1.42, 2.00),
        (0.49, 1.10, 1.27, 1.79), (0.54, 1.01, 1.17, 1.64), (0.54, 1.00, 1.16, 1.63))},
    15.0: {"X_single": 0.44, "X_double": 0.72, "rows": (
        (0.38, 1.47, 1.65, 2.39), (0.40, 1.40, 1.57, 2.28), (0.43, 1.30, 1.46, 2.11),
        (0.46, 1.23, 1.38, 2.00), (0.47, 1.19, 1.34, 1.93), (0.50, 1.12, 1.26, 1.82),
        (0.55, 1.02, 1.14, 1.66), (0.56, 1.00, 1.12, 1.63), (0.56, 1.00, 1.12, 1.63))},
}

ANGULAR_12_TEXTBOOK = (
    # GOST series 36000 (α = 12°), single row: entry i·Fa/C0r, e, Y with X = 0.45.  Russian
    # textbook table (Dunaev & Lelikov) via [ISO281] table 3; unverified (α = 12° is
    # not an ISO row).
    (0.014, 0.30, 1.81), (0.029, 0.34, 1.62), (0.057, 0.37, 1.46), (0.086, 0.41, 1.34),
    (0.11, 0.45, 1.22), (0.17, 0.48, 1.13), (0.29, 0.52, 1.04), (0.43, 0.54, 1.01),
    (0.57, 0.54, 1.00),
)
ANGULAR_12_X = 0.45

ANGULAR_FIXED = (
    # α, e, single row Fa/Fr > e (X, Y), double row Fa/Fr <= e (X, Y), double row > e (X, Y).
    # ISO 281:2007 Table 3 (single- and double-row angular contact ball bearings); confirmed
    # (secondary) by the standards check.  Intermediate angles: linear interpolation.
    (20.0, 0.57, 0.43, 1.00, 1.0, 1.09, 0.70, 1.63),
    (25.0, 0.68, 0.41, 0.87, 1.0, 0.92, 0.67, 1.41),
    (30.0, 0.80, 0.39, 0.76, 1.0, 0.78, 0.63, 1.24),
    (35.0, 0.95, 0.37, 0.66, 1.0, 0.66, 0.60, 1.07),
    (40.0, 1.14, 0.35, 0.57, 1.0, 0.55, 0.57, 0.93),
    (45.0, 1.34, 0.33, 0.50, 1.0, 0.47, 0.54, 0.81),
)

# Self-aligning ball bearings (ISO 281:2007 Table 3, [ISO281] table 3): e = 1.5 tan α;
# Fa/Fr <= e: X = 1, Y = 0.42 cot α; > e: X = 0.65, Y = 0.65 cot α.
SELF_ALIGNING = {"e_tan": 1.5, "X_le": 1.0, "Y_le_cot": 0.42, "X_gt": 0.65, "Y_gt_cot": 0.65}

# Radial roller bearings with α != 0 (ISO 281:2007, [ISO281]): e = 1.5 tan α;
# single row: <= e X = 1, Y = 0; > e X = 0.4, Y = 0.4 cot α.  Double row: <= e X = 1,
# Y = 0.45 cot α; > e X = 0.67, Y = 0.67 cot α.
ROLLER_RADIAL = {
    1: {"X_le": 1.0, "Y_le_cot": 0.0, "X_gt": 0.4, "Y_gt_cot": 0.4},
    2: {"X_le": 1.0, "Y_le_cot": 0.45, "X_gt": 0.67, "Y_gt_cot": 0.67},
}

# Thrust roller bearings with α != 90° (ISO 281:2007, [ISO281], medium confidence,
# unverified): e = 1.5 tan α; single direction Fa/Fr > e: X = tan α, Y = 1; double
# direction <= e: X = 1.5 tan α, Y = 0.67; > e: X = tan α, Y = 1.
THRUST_ROLLER = {"e_tan": 1.5, "X_gt_tan": 1.0, "Y_gt": 1.0, "X_le_tan": 1.5, "Y_le": 0.67}

# ----------------------------------------------------------------------------- static

STATIC_Y0_ANGULAR = (
    # ISO 76 single-row angular contact ball bearings, X0 = 0.5, Y0 by α (double row: X0 = 1,
    # Y0 doubled).  Confirmed (secondary) by the standards check (Dessia-tech/
    # MechanicalComponents).
    (5.0, 0.52), (10.0, 0.50), (15.0, 0.46), (20.0, 0.42), (25.0, 0.38), (30.0, 0.33),
    (35.0, 0.29), (40.0, 0.26), (45.0, 0.22),
)
STATIC_DEEP_GROOVE = (0.6, 0.5)           # X0, Y0 (ISO 76; standards check, secondary)
# Self-aligning ball and radial roller bearings with α != 0: X0 = 0.5 (single row) / 1
# (double row), Y0 = 0.22·cot α / 0.44·cot α (ISO 76 via [ISO76]; medium
# confidence, unverified).
STATIC_ROLLER = {1: (0.5, 0.22), 2: (1.0, 0.44)}

# ----------------------------------------------------------------------------- life factors

A1_GOST94 = (
    # Reliability R %, a1 of GOST 18855-94 (= ISO 281:1990).  Printed in the SKF ConCentra
    # manual (Table 1: 1, 0.62, 0.53, 0.44, 0.33, 0.21) and jordanrobot/Calculators
    # docs/bearing_rolling_life.md (after Nose Seiko); NTN CAT. No. 2202/E Table 3.2 shows
    # 0.62 at L5.  The edition tabulates a1 only up to 99 %.
    (90.0, 1.0), (95.0, 0.62), (96.0, 0.53), (97.0, 0.44), (98.0, 0.33), (99.0, 0.21),
)

A1_ISO2007 = (
    # Reliability R %, a1 of ISO 281:2007 (= GOST 18855-2013), 90 ... 99.95 %.  Transcribed in
    # [ISO281] and cross-checked there with a public implementation; every value
    # equals 0.95·(ln(100/R)/ln(100/90))^(2/3) + 0.05 to the printed digits.  The standard's
    # own table was not seen.
    (90.0, 1.0), (95.0, 0.64), (96.0, 0.55), (97.0, 0.47), (98.0, 0.37), (99.0, 0.25),
    (99.2, 0.22), (99.4, 0.19), (99.6, 0.16), (99.8, 0.12), (99.9, 0.093), (99.92, 0.087),
    (99.94, 0.080), (99.95, 0.077),
)

A_ISO_BALL = (
    # κ from (inclusive), c2, c3 in a_ISO = 0.1·[1 − (2.5671 − c2/κ^c3)^0.83·(e_C·C_u/P)^(1/3)]^−9.3
    # (ISO 281:2007 eq. (31)–(33) as transcribed in a public solver; standards check §5).
    # c3 = 0.19087 for 0.4 <= κ < 1: see life.a_iso for the choice against 0.019087.
    (0.1, 2.2649, 0.054381), (0.4, 1.9987, 0.19087), (1.0, 1.9987, 0.071739),
)
A_ISO_ROLLER = (
    # a_ISO = 0.1·[1 − (1.5859 − c2/κ^c3)·(e_C·C_u/P)^0.4]^−9.185 (ISO 281:2007 eq. (34)–(36),
    # same transcription).
    (0.1, 1.3993, 0.054381), (0.4, 1.2348, 0.19087), (1.0, 1.2348, 0.071739),
)
A_ISO_BALL_CONST = (2.5671, 0.83, 1.0 / 3.0, 9.3)     # constant, exponent, r exponent, slope
A_ISO_ROLLER_CONST = (1.5859, 1.0, 0.4, 9.185)
A_ISO_MAX = 50.0
A_ISO_MAX_EP = 3.0          # EP additives with κ < 1 and e_C >= 0.2 (ISO 281 §9.3.3.4, secondary)
EP_E_C_MIN = 0.2
KAPPA_MIN = 0.1
KAPPA_MAX = 4.0
THRUST_LOAD_DIVISOR = {"thrust_ball": 3.0, "thrust_roller": 2.5}   # medium confidence

E_C_GUIDE = {
    # Contamination level: (e_C range for D_pw < 100 mm, for D_pw >= 100 mm).  ISO 281:2007
    # guide table as printed by the MESYS manual (mesys.ag/manual/lubrication_2.html) and [ISO281].
    # The tool uses the middle of the range unless e_C is given.
    "extreme": ((1.0, 1.0), (1.0, 1.0)),
    "high": ((0.6, 0.8), (0.8, 0.9)),
    "normal": ((0.5, 0.6), (0.6, 0.8)),
    "slight": ((0.3, 0.5), (0.4, 0.6)),
    "typical": ((0.1, 0.3), (0.2, 0.4)),
    "severe": ((0.0, 0.1), (0.0, 0.1)),
    "very_severe": ((0.0, 0.0), (0.0, 0.0)),
}

C_U_ESTIMATE = {
    # C_u ≈ C0/22 (ball), C0/8.2 (roller) for D_pw <= 100 mm; beyond, times
    # (100/D_pw)^0.5 (ball) or ^0.3 (roller).  ISO 281:2007 annex approximation via [Haidamaka2017]
    # (medium confidence, unverified).
    "ball": (22.0, 0.5),
    "roller": (8.2, 0.3),
}

# ----------------------------------------------------------------------------- Russian practice

K_T = (
    # Bearing temperature °C, temperature factor K_т (Russian textbooks via [Dunaev]; unverified).
    # Below 100 °C K_т = 1.
    (100.0, 1.00), (125.0, 1.05), (150.0, 1.10), (175.0, 1.15), (200.0, 1.25), (225.0, 1.35),
    (250.0, 1.40),
)

V_OUTER = 1.2        # rotation factor V when the outer ring rotates (inner ring: 1.0)

A23 = {
    # Combined factor a23 (material + operating conditions), GOST 18855-94 practice
    # (Russian textbooks, [Dunaev]; column "usual" high confidence, the others
    # medium, all unverified): ranges for usual conditions / hydrodynamic oil film without
    # excessive misalignment / ESR or vacuum steel + oil film + no misalignment.
    "deep_groove_ball": ((0.7, 0.8), (1.2, 1.4), (2.0, 2.3)),
    "angular_contact_ball": ((0.7, 0.8), (1.2, 1.4), (2.0, 2.3)),
    "self_aligning_ball": ((0.5, 0.6), (0.8, 1.0), (1.6, 2.0)),
    "cylindrical_roller": ((0.5, 0.6), (0.8, 1.0), (1.6, 2.0)),
    "tapered_roller": ((0.6, 0.7), (0.9, 1.1), (1.7, 2.0)),
    "spherical_roller": ((0.3, 0.4), (0.6, 0.7), (1.1, 1.4)),
}
A23_CONDITIONS = ("usual", "hydrodynamic", "premium")

K_E = {
    # Equivalence factor of the typical load regimes (GOST 21354-87 regimes; Russian
    # textbooks via [Dunaev], unverified): P_E = K_E·P_max.  Check:
    # K_E ≈ μ^(1/3) with μ = 1, 0.5, 0.25, 0.18, 0.125, 0.063.
    "0": 1.0, "I": 0.8, "II": 0.63, "III": 0.56, "IV": 0.5, "V": 0.4,
}

WEIBULL_SLOPE = {"ball": 10.0 / 9.0, "roller": 9.0 / 8.0}
# Weibull slope e of the system life L = (Σ L_i^−e)^(−1/e): 10/9 ball, 9/8 roller
# (Lundberg–Palmgren; NTN CAT. No. 2202/E formula (3.6), whose Example 4 it reproduces).

# ----------------------------------------------------------------------------- limits

S0_MIN_DEFAULT = 1.0        # catalogue practice: normal demands (NTN Table 3.4, [ISO76])
MIN_LOAD_RATIO = {"ball": 0.01, "roller": 0.02}  # P_min/C_r: below, the elements skid ([SKFMinLoad])
LIFE_UNITS_MAX = 1e7        # h: a life beyond (1 100 years) with P below P_min reads as a unit slip
HIGH_LOAD_RATIO = 0.5       # P > 0.5·C_r: ISO 281 accuracy reduced ([NTN])
LOW_SPEED = 10.0            # min^-1: below, dynamic life is meaningless ([NTN])
HOT = 150.0                 # °C: dimensional stabilisation needed above ([NTN])
D_W_SPLIT = 25.4            # mm, ball diameter where the C_r formula changes
