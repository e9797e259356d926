"""ISO/TR 6336-30:2017, example 1 ("single helical case carburized gear pair"), pitting
side, factor by factor.

Source: the reference values of ISO/TR 6336-30:2017 Annex A as transcribed, with the input
data, in the public MATLAB class ``MATISO_6336.example_01`` (GitHub
``gfsReboucas/Drivetrain``, file ``MATISO_6336.m``, commit
4a88df348fc70d04254c84bd375bb2bab0d15d0d).  Pair: m_n = 8, z = 17/103, x = 0.145/0
(a_w = 500 given, so x2 follows), β = 15.8°, b = 100, basic rack D of ISO 53
(h_fP = 1.4, ρ_fP = 0.39), ISO grade 5, Ra = 1 µm, T1 = 9000 N·m at 360 min⁻¹, 50 000 h,
K_A = 1, ν40 = 320 mm²/s, C_a = 70 µm, σ_Hlim = 1500 MPa, S_Hmin = 1; K_Hβ = 1.16 as in the
report (its f_ma and shaft data are not part of the transcription).  The flank roughness
is R_z = 6·Ra = 6 µm (the spec's default), which reproduces the printed Z_R to 2·10⁻⁶.

Tolerances: the printed value's last digit, except where the report's transverse contact
ratio enters: its c_γα/c' gives ε_α = 1.5491 where the nominal geometry gives 1.5479
(the report's tip diameters are not transcribed), 0.08 %; c_γα, c_γβ, σ_H0, σ_H, S_H
and K_Fβ (N_F from the tooth depth) are compared within 0.1 %.
"""

from __future__ import annotations

from geardesign.core.registry import run_data
from tests.conftest import assert_ref

SPEC = {
    "kind": "spur",
    "gear": {"module": 8.0, "z1": 17, "z2": 103, "helix_angle": 15.8, "face_width": 100.0,
             "center_distance": 500.0, "x1": 0.145, "accuracy_grade": 6, "bearing_scheme": 5},
    "rack": {"addendum_coef": 1.0, "clearance_coef": 0.4, "root_radius_coef": 0.39},
    "load": {"speed1": 360.0, "torque1": 9000.0, "life_hours": 50000.0},
    "material": {w: {"treatment": "carburized", "hardness_HRC": 60.0, "roughness_Ra": 1.0,
                     "sigma_Hlim": 1500.0} for w in ("pinion", "wheel")},
    "options": {"method": "ISO 6336:2019"},
    "iso": {"accuracy_grade": 5, "lubricant_viscosity": 320.0, "tip_relief": 70.0,
            "S_Hmin": 1.0},
    "iso_factors": {"K_Hbeta": 1.16},
}

PRINTED = {  # section, key: (value, tolerance) — absolute unless "rel"
    ("iso6336_factors", "F_t"): (127352.0, 0.5),
    ("iso6336_factors", "v"): (2.664, 0.0005),
    ("iso6336_factors", "c_th"): (17.85584, 0.0005),
    ("iso6336_factors", "c_prime"): (12.37047, 0.0005),
    ("iso6336_factors", "K_v"): (1.003, 0.0005),
    ("iso6336_factors", "K_Halpha"): (1.0, 1e-9),
    ("iso6336_factors", "K_Falpha"): (1.0, 1e-9),
    ("iso6336_contact", "Z_eps"): (0.803, 0.0009),
    ("iso6336_contact", "Z_H"): (2.39533, 0.000005),
    ("iso6336_contact", "Z_E"): (189.81170, 0.000005),
    ("iso6336_contact", "Z_beta"): (1.01944, 0.000005),
    ("iso6336_contact", "Z_B"): (1.0, 1e-9),
    ("iso6336_contact", "Z_D"): (1.0, 1e-9),
    ("iso6336_contact", "Z_L"): (1.04739, 0.000005),
    ("iso6336_contact", "Z_v"): (0.96911, 0.000005),
    ("iso6336_contact", "Z_R"): (0.96599, 0.000005),
    ("iso6336_contact", "Z_W1"): (1.0, 1e-9),
    ("iso6336_contact", "Z_X1"): (1.0, 1e-9),
    ("iso6336_contact", "Z_NT1"): (0.91, 0.0005),
    ("iso6336_contact", "Z_NT2"): (0.962, 0.0005),
    ("iso6336_contact", "sigma_HP1"): (1338.48050, 0.001),
    ("iso6336_contact", "sigma_HP2"): (1414.52551, 0.001),
    ("iso6336_materials", "N_L1"): (1.080e9, 0.0005e9),
    ("iso6336_materials", "N_L2"): (1.783e8, 0.0005e8),
}
RELATIVE = {  # carry ε_α (see the notes): 0.1 %
    ("iso6336_factors", "c_gamma_alpha"): 17.46485,
    ("iso6336_factors", "c_gamma_beta"): 14.84512,
    ("iso6336_factors", "K_Fbeta"): 1.12803,
    ("iso6336_contact", "sigma_H0"): 1206.58207,
    ("iso6336_contact", "sigma_H1"): 1301.35343,
    ("iso6336_contact", "sigma_H2"): 1301.35343,
    ("iso6336_contact", "S_H1"): 1.02853,
    ("iso6336_contact", "S_H2"): 1.08696,
}


def test_tr6336_30_example_1_pitting():
    res = run_data(SPEC).document()["results"]
    for (sec, key), (value, tol) in PRINTED.items():
        assert_ref(res[sec][key], value, tol, f"ISO/TR 6336-30 ex. 1 {key}")
    for (sec, key), value in RELATIVE.items():
        assert abs(res[sec][key] / value - 1.0) <= 1e-3, (key, res[sec][key], value)
    assert abs(res["geometry"]["eps_alpha"] / 1.5491 - 1.0) < 1e-3
