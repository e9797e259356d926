"""Tables of ISO 6336:2019 as data: material lines of part 5, life-factor points of parts 2
and 3, the constants of the dynamic factor (part 1) and the helix-modification constants of
the face load factor (part 1).  The formula modules read them; no number of a table is
written anywhere else.
"""

from __future__ import annotations

# --- ISO 6336-5:2016 (cited by ISO 6336-2/-3:2019), σ_Hlim and σ_Flim = A·x + B ---------
# Material types (the standard's abbreviations):
#   St        normalized low-carbon wrought steel (x = HBW)
#   St_cast   cast steel (HBW)
#   GTS       black malleable cast iron, perlitic (HBW)
#   GGG       nodular cast iron, perlitic/bainitic (HBW)
#   GGG_ferr  nodular cast iron, ferritic (HBW)
#   GG        grey cast iron (HBW)
#   V         through-hardened wrought carbon steel (HV)
#   V_alloy   through-hardened wrought alloy steel (HV)
#   V_cast    through-hardened cast carbon steel (HV)
#   V_cast_alloy through-hardened cast alloy steel (HV)
#   Eh        case-hardened (carburized) wrought steel (HV of the surface)
#   IF        flame or induction hardened wrought steel (HV of the surface)
#   NT        nitriding steel, nitrided (HV of the surface)
#   NV        through-hardening steel, nitrided (HV of the surface)
#   NV_nitrocar  through-hardening steel, nitrocarburized (HV of the surface)
# Per type: hardness scale, hardness range of the lines, and per quality grade (ML, MQ, ME)
# the (A, B) of σ_Hlim and of σ_Flim [MPa].  ISO 6336-5:2016 clause 5, Table 2 (lines of
# Figures 4 to 16).
MATERIAL_LINES = {
    "St": {"scale": "HBW", "range": (110.0, 210.0),
           "H": {"ML": (1.000, 190.0), "MQ": (1.000, 190.0), "ME": (1.520, 250.0)},
           "F": {"ML": (0.455, 69.0), "MQ": (0.455, 69.0), "ME": (0.386, 147.0)}},
    "St_cast": {"scale": "HBW", "range": (140.0, 210.0),
                "H": {"ML": (0.986, 131.0), "MQ": (0.986, 131.0), "ME": (1.143, 237.0)},
                "F": {"ML": (0.313, 62.0), "MQ": (0.313, 62.0), "ME": (0.254, 137.0)}},
    "GTS": {"scale": "HBW", "range": (135.0, 250.0),
            "H": {"ML": (1.371, 143.0), "MQ": (1.371, 143.0), "ME": (1.333, 267.0)},
            "F": {"ML": (0.345, 77.0), "MQ": (0.345, 77.0), "ME": (0.403, 128.0)}},
    "GGG": {"scale": "HBW", "range": (175.0, 300.0),
            "H": {"ML": (1.434, 211.0), "MQ": (1.434, 211.0), "ME": (1.500, 250.0)},
            "F": {"ML": (0.350, 119.0), "MQ": (0.350, 119.0), "ME": (0.380, 134.0)}},
    "GGG_ferr": {"scale": "HBW", "range": (175.0, 300.0),
                 "H": {"ML": (1.434, 211.0), "MQ": (1.434, 211.0), "ME": (1.500, 250.0)},
                 "F": {"ML": (0.350, 119.0), "MQ": (0.350, 119.0), "ME": (0.380, 134.0)}},
    "GG": {"scale": "HBW", "range": (150.0, 240.0),
           "H": {"ML": (1.033, 132.0), "MQ": (1.033, 132.0), "ME": (1.465, 122.0)},
           "F": {"ML": (0.256, 8.0), "MQ": (0.256, 8.0), "ME": (0.200, 53.0)}},
    "V": {"scale": "HV", "range": (135.0, 210.0),
          "H": {"ML": (0.963, 283.0), "MQ": (0.925, 360.0), "ME": (0.838, 432.0)},
          "F": {"ML": (0.250, 108.0), "MQ": (0.240, 163.0), "ME": (0.283, 202.0)}},
    "V_alloy": {"scale": "HV", "range": (200.0, 360.0),
                "H": {"ML": (1.313, 188.0), "MQ": (1.313, 373.0), "ME": (2.213, 260.0)},
                "F": {"ML": (0.423, 104.0), "MQ": (0.425, 187.0), "ME": (0.358, 231.0)}},
    "V_cast": {"scale": "HV", "range": (130.0, 215.0),
               "H": {"ML": (0.831, 300.0), "MQ": (0.831, 300.0), "ME": (0.951, 345.0)},
               "F": {"ML": (0.224, 117.0), "MQ": (0.224, 117.0), "ME": (0.286, 167.0)}},
    "V_cast_alloy": {"scale": "HV", "range": (200.0, 360.0),
                     "H": {"ML": (1.276, 298.0), "MQ": (1.276, 298.0), "ME": (1.350, 356.0)},
                     "F": {"ML": (0.364, 161.0), "MQ": (0.364, 161.0), "ME": (0.356, 186.0)}},
    "Eh": {"scale": "HV", "range": (600.0, 800.0),
           "H": {"ML": (0.0, 1300.0), "MQ": (0.0, 1500.0), "ME": (0.0, 1650.0)},
           "F": {"ML": (0.0, 312.0), "MQ": (0.0, 425.0), "ME": (0.0, 500.0)}},
    "IF": {"scale": "HV", "range": (485.0, 615.0),
           "H": {"ML": (0.740, 602.0), "MQ": (0.541, 882.0), "ME": (0.505, 1013.0)},
           "F": {"ML": (0.305, 76.0), "MQ": (0.138, 290.0), "ME": (0.271, 237.0)}},
    "NT": {"scale": "HV", "range": (650.0, 900.0),
           "H": {"ML": (0.0, 1125.0), "MQ": (0.0, 1250.0), "ME": (0.0, 1450.0)},
           "F": {"ML": (0.0, 270.0), "MQ": (0.0, 420.0), "ME": (0.0, 468.0)}},
    "NV": {"scale": "HV", "range": (450.0, 650.0),
           "H": {"ML": (0.0, 788.0), "MQ": (0.0, 998.0), "ME": (0.0, 1217.0)},
           "F": {"ML": (0.0, 258.0), "MQ": (0.0, 363.0), "ME": (0.0, 432.0)}},
    "NV_nitrocar": {"scale": "HV", "range": (450.0, 650.0),
                    "H": {"ML": (0.0, 650.0), "MQ": (0.0, 950.0), "ME": (0.0, 950.0)},
                    "F": {"ML": (0.0, 224.0), "MQ": (0.0, 388.0), "ME": (0.0, 388.0)}},
}
QUALITIES = ("ML", "MQ", "ME")

#: Surface-hardened types: Z_W = 1 between two of them; y_α, y_β of the hardened class.
SURFACE_HARDENED = ("Eh", "IF", "NT", "NV", "NV_nitrocar")
#: Grey and ferritic nodular cast iron: their own running-in allowances.
CAST_IRON_GREY = ("GG", "GGG_ferr")

# --- life factors -------------------------------------------------------------------
# Points (N_L, Z_NT) of the life curves, interpolated on log-log scales; the last point is
# the long-life value at 10^10 cycles for normal conditions (0.85) and 1.0 with optimum
# lubrication, material, manufacturing and experience.  ISO 6336-2:2019 Table 2.
ZNT_CURVES = {
    # St, V, GGG (perl., bai.), GTS (perl.), Eh, IF, when limited pitting is permitted
    "limited_pitting": ((6e5, 1.6), (1e7, 1.3), (1e9, 1.0)),
    # the same materials, no pitting permitted: reference 5·10^7
    "steel": ((1e5, 1.6), (5e7, 1.0)),
    # GG, GGG (ferr.), NT, NV (nitrided)
    "nitrided": ((1e5, 1.3), (2e6, 1.0)),
    # NV (nitrocarburized)
    "nitrocarburized": ((1e5, 1.1), (2e6, 1.0)),
}
ZNT_GROUP = {"St": "steel", "St_cast": "steel", "GTS": "steel", "GGG": "steel", "V": "steel",
             "V_alloy": "steel", "V_cast": "steel", "V_cast_alloy": "steel", "Eh": "steel",
             "IF": "steel", "GG": "nitrided", "GGG_ferr": "nitrided", "NT": "nitrided",
             "NV": "nitrided", "NV_nitrocar": "nitrocarburized"}
# ISO 6336-3:2019 Table 3, points (N_L, Y_NT); reference 3·10^6 for every group.
YNT_CURVES = {
    "through_hardened": ((1e4, 2.5), (3e6, 1.0)),   # St, V, GGG (perl., bai.), GTS (perl.)
    "case_hardened": ((1e3, 2.5), (3e6, 1.0)),      # Eh, IF (root hardened)
    "nitrided": ((1e3, 1.6), (3e6, 1.0)),           # NT, NV (nitrided), GG, GGG (ferr.)
    "nitrocarburized": ((1e3, 1.1), (3e6, 1.0)),    # NV (nitrocarburized)
}
YNT_GROUP = {"St": "through_hardened", "St_cast": "through_hardened",
             "GTS": "through_hardened", "GGG": "through_hardened", "V": "through_hardened",
             "V_alloy": "through_hardened", "V_cast": "through_hardened",
             "V_cast_alloy": "through_hardened", "Eh": "case_hardened", "IF": "case_hardened",
             "GG": "nitrided", "GGG_ferr": "nitrided", "NT": "nitrided", "NV": "nitrided",
             "NV_nitrocar": "nitrocarburized"}
N_LONG_LIFE = 1e10
LONG_LIFE = {"normal": 0.85, "optimum": 1.0}

# --- relative notch sensitivity: slip-layer thickness ρ' [mm] -------------------------
# ISO 6336-3:2019 Table 5 (the ρ' of the material at the endurance limit).  For St and V
# the value depends on the strength; the table's values at σ_B or σ_0.2 are used by
# :func:`..part3.rho_prime`.
RHO_PRIME = {"GG": 0.3124, "GGG_ferr": 0.3095, "Eh": 0.0030, "IF": 0.0030, "NT": 0.1005,
             "NV": 0.1005, "NV_nitrocar": 0.1005}
# (σ limit [MPa], ρ' [mm]) for normalized steel (σ_B) and for through-hardened steel,
# perlitic malleable and nodular cast iron (σ_0.2); interpolated linearly, clamped
RHO_PRIME_ST = ((300.0, 0.4445), (400.0, 0.3070))
RHO_PRIME_V = ((500.0, 0.0281), (600.0, 0.0194), (800.0, 0.0064), (1000.0, 0.0014))

# --- dynamic factor, method B: ISO 6336-1:2019 Table 8 (C_v1 … C_v7 by ε_γ) ----------
CV1 = 0.32
CV5 = 0.47

# --- face load factor, method C: ISO 6336-1:2019 Table 9 (B1, B2 by helix modification) -
HELIX_MODIFICATION = {
    "none": (1.0, 1.0),
    "helix_correction": (0.1, 1.0),
    "crowning": (0.5, 0.5),
    "helix_correction_and_crowning": (0.1, 0.5),
    "end_relief": (0.7, 0.7),
}

# --- gear material density for the reduced mass [kg/mm³]: steel --------------------
RHO_STEEL = 7.83e-6

# --- scuffing, integral temperature method (ISO/TS 6336-21:2017, ISO/TR 13989-2:2000) -----
# Pinion torque T_1T [N·m] of the FZG A/8.3/90 load stages 1 to 14 (ISO 14635-1, load arm
# 0.5 m), as tabulated in C. Fernandes, Gear-Calculation, file GearC/LoadStage.py
# ([Fernandes2020]); stage 14 reproduces KISSsoft's integral scuffing temperature 455.17 °C
# for ν40 = 220 mm²/s ([KISSsoft2017], stage 3).
FZG_TORQUE = {1: 3.3, 2: 13.7, 3: 35.25, 4: 60.75, 5: 94.1, 6: 135.3, 7: 183.35, 8: 239.25,
              9: 302.0, 10: 372.7, 11: 450.1, 12: 534.5, 13: 626.9333, 14: 714.2}

# Lubricant factor X_L of the mean coefficient of friction and of the test temperatures, by
# the base oil ([ISO6336-21], X_L).
SCUFFING_X_L = {"mineral": 1.0, "polyalphaolefin": 0.8, "polyglycol": 0.7,
                "polyglycol_water_soluble": 0.6, "traction_fluid": 1.5, "phosphate_ester": 1.3}

# Lubrication factor X_S of the bulk temperature, by the way the oil reaches the mesh
# ([ISO6336-21], X_S): dip (oil bath) 1.0, spray 1.2, gears submerged in oil 0.2.
SCUFFING_X_S = {"dip": 1.0, "spray": 1.2, "submerged": 0.2}

# Relative welding factor X_WrelT by the material and treatment of the flanks
# ([ISO6336-21], X_WrelT); the ISO 6336-5 material types map on the first column.
SCUFFING_X_WRELT = {"through_hardened": 1.00, "phosphated": 1.25, "copper_plated": 1.50,
                    "nitrided": 1.50, "carburized_low_austenite": 1.15, "carburized": 1.00,
                    "carburized_high_austenite": 0.85, "austenitic": 0.45}
SCUFFING_STRUCTURE = {"St": "through_hardened", "St_cast": "through_hardened",
                      "GTS": "through_hardened", "GGG": "through_hardened",
                      "GGG_ferr": "through_hardened", "GG": "through_hardened",
                      "V": "through_hardened", "V_alloy": "through_hardened",
                      "V_cast": "through_hardened", "V_cast_alloy": "through_hardened",
                      "Eh": "carburized", "IF": "through_hardened", "NT": "nitrided",
                      "NV": "nitrided", "NV_nitrocar": "nitrided"}

# Thermal contact coefficient B_M = √(λ_M·ρ_M·c_M) of steel [N/(mm·s^½·K)], the value
# KISSsoft prints for the NREL steels ([KISSsoft2017], stage 3: B_M 13.780).
B_M_STEEL = 13.78

# Volumetric thermal expansion of mineral oils [1/K] for the density at the oil temperature
# (the coefficient of the density-temperature tables of petroleum products, DIN 51757).
OIL_EXPANSION = 0.0007
