"""Tables of GOST 21354-87 and the series it uses, as data.

The standard's own text could not be consulted;
each table names the public implementations of the standard it was checked against:

* ZPCIL — GitHub ``s-berlin/ZPCIL_test`` (C++ port of the Fortran GOST 21354-87 program;
  the Fortran DATA statements are kept in comments; files named per table);
* DANNYE — a public MATLAB GOST 21354-87 program;
* Delphi — public reducer-design units ``CalculateCWheel`` and ``TPer``.
"""

from __future__ import annotations

# --- dynamic factor -----------------------------------------------------------------
# δ_H, δ_F: GOST 21354-87 table 8 (ZPCIL DLTH.h «ГОСТ таб 8 стр 22», DLTF.h; DANNYE).
# The GOST prints these 10× larger together with g_0 10× smaller (DANNYE: δ 0.06, g_0 5.6;
# ZPCIL: δ 0.006, g_0 56); the product δ·g_0 is what matters ([ZPCIL] DLTH.h, WV.h; [DANNYE]).
# Keys: (surface hardness class, tooth form); "soft" = the softer gear <= 350 HB.
DELTA_H = {
    ("soft", "spur"): 0.006, ("soft", "spur_relieved"): 0.004, ("soft", "helical"): 0.002,
    ("hard", "spur"): 0.014, ("hard", "spur_relieved"): 0.010, ("hard", "helical"): 0.004,
}
DELTA_F = {"spur": 0.016, "spur_relieved": 0.011, "helical": 0.006}

# g_0 [N/mm·(m/s)^-1·mm^-0.5 in GOST's scaling] and the limit w_max [N/mm] by accuracy grade
# (GOST 1643-81 smoothness norm) and module class (m <= 3.55, 3.55 < m <= 10, m > 10):
# GOST 21354-87 (ZPCIL WV.h, «Таблица 7», Fortran DATA; DANNYE prints G0 ÷ 10).
G0 = {6: (38, 42, 48), 7: (47, 53, 64), 8: (56, 61, 73), 9: (73, 82, 100),
      10: (100, 110, 135), 11: (135, 150, 180)}
W_MAX = {6: (160, 194, 250), 7: (240, 310, 450), 8: (380, 410, 590), 9: (700, 880, 1050),
         10: (1200, 1500, 1800), 11: (2200, 2800, 3300)}
MODULE_CLASSES = (3.55, 10.0)

# --- face load factor ----------------------------------------------------------------
# K_Hβ = 1 + A·ψ_bd + B·ψ_bd² (ψ_bd = b_w/d1) per bearing-arrangement scheme 1..7 of the
# GOST 21354-87 chart, for a pair that runs in (softer gear <= 350 HB) and one that does
# not.  Fit of the chart in ZPCIL AKHBT.h (Fortran DATA order; the C++ arrays are
# transposed, see tests/reference/spur/test_gost21354_tables.py).  A second public fit
# (Delphi CalculateCWheel) agrees within 0.03 for schemes 2-7 at ψ_bd <= 1.6.
KH_BETA_FIT = {  # scheme: ((A, B) run-in, (A, B) not run-in)
    1: ((0.33, 0.30), (0.78, 0.83)),
    2: ((0.217, 0.167), (0.417, 0.583)),
    3: ((0.098, 0.0521), (0.267, 0.111)),
    4: ((0.05, 0.05), (0.167, 0.111)),
    5: ((0.0433, 0.0333), (0.113, 0.077)),
    6: ((0.0153, 0.0347), (0.0388, 0.0812)),
    7: ((0.00586, 0.0246), (0.0304, 0.0396)),
}
SCHEMES = {
    1: "overhung gear, shaft on ball bearings",
    2: "overhung gear, shaft on roller bearings",
    3: "gear between bearings, strongly asymmetric, flexible shaft",
    4: "gear between bearings, asymmetric",
    5: "gear between bearings, asymmetric, stiff shaft",
    6: "gear between bearings, slightly asymmetric",
    7: "gear between bearings, symmetric",
}
PSI_BD_CHART_MAX = 1.6  # the charts end here; beyond it the fit is extrapolated

# --- contact: roughness factor Z_R (GOST 21354-87; ZPCIL CONTAU.h, DANNYE ZR) -----------
# (upper limit of Ra in µm, Z_R)
Z_R_TABLE = ((1.25, 1.0), (2.5, 0.95), (float("inf"), 0.90))

# --- typical load regimes (GOST 21354-87 / handbook table of μ_H, μ_F) -------------------
# Delphi units CalculateCWheel.Mu_H/Mu_F and TPer (identical listings).  μ_F for q_F = 9,
# regime III: both listings print 0.063, which cannot belong to the same load distribution
# as the other entries (a distribution fitted to μ_H and μ_F(q=6) reproduces regimes I, II,
# IV, V to 3 digits and predicts 0.031 for III); the handbook value 0.04 is used here.
REGIMES = ("0", "I", "II", "III", "IV", "V")
REGIME_NAMES = {"0": "constant", "I": "heavy", "II": "medium equiprobable",
                "III": "medium normal", "IV": "light", "V": "extra light"}
MU_H = {"0": 1.0, "I": 0.5, "II": 0.25, "III": 0.18, "IV": 0.125, "V": 0.063}
MU_F = {6: {"0": 1.0, "I": 0.3, "II": 0.143, "III": 0.065, "IV": 0.038, "V": 0.013},
        9: {"0": 1.0, "I": 0.2, "II": 0.1, "III": 0.04, "IV": 0.016, "V": 0.004}}

# --- series used by the design mode -----------------------------------------------------
# GOST 2185-66 centre distances a_w [mm], 1st and 2nd series.
CENTER_DISTANCES_1 = (40, 50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 500, 630, 800, 1000,
                      1250, 1600, 2000, 2500)
CENTER_DISTANCES_2 = (71, 90, 112, 140, 180, 225, 280, 355, 450, 560, 710, 900, 1120, 1400,
                      1800, 2240)
# GOST 2185-66 face width ratios ψ_ba = b_w/a_w.
PSI_BA = (0.1, 0.125, 0.16, 0.2, 0.25, 0.315, 0.4, 0.5, 0.63, 0.8, 1.0, 1.25)
# GOST 9563-60 modules [mm], 1st (preferred) and 2nd series ([GOST9563]).
MODULES_1 = (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0, 12.0, 16.0, 20.0, 25.0)
MODULES_2 = (1.125, 1.375, 1.75, 2.25, 2.75, 3.5, 4.5, 5.5, 7.0, 9.0, 11.0, 14.0, 18.0, 22.0)
# GOST 21354-87 design formula constant K_a [MPa^(1/3), with T1 in N·m] for steel pairs:
# 495 spur, 430 helical (the handbook values 49.5/43 with T in N·mm; verify).
K_A_DESIGN = {"spur": 495.0, "helical": 430.0}

# --- highest pitch-line velocity per accuracy grade [m/s] ------------------------------
# Handbook limits for GOST 1643-81 grades (Dunaev & Lelikov, table of accuracy grades by
# velocity; verify): beyond them the dynamic loads grow faster than GOST 21354-87's K_v.
V_MAX = {"spur": {6: 15.0, 7: 10.0, 8: 6.0, 9: 2.0, 10: 1.0, 11: 0.5},
         "helical": {6: 30.0, 7: 15.0, 8: 10.0, 9: 4.0, 10: 2.0, 11: 1.0}}
