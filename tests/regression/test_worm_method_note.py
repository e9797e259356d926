"""Regression values: a synthetic worm example (ours, recomputed by hand with the same textbook
formulas), not published numbers.  They guard against unintended
changes; the published references are in ``tests/reference/worm``.

Known difference: the hand calculation interpolates the friction angle ρ' in degrees between the
table's ρ' columns (1.409°); this code interpolates f' and takes ρ' = arctan f' (1.4106°).
The efficiency and everything after it differ by about 1.5·10⁻⁴ relative, inside the
tolerances below.
"""

from geardesign.core.registry import run_data
from tests.conftest import flat

NOTE = {
    "kind": "worm",
    "gear": {"module": 6.3, "diameter_factor": 10.0, "z1": 2, "z2": 40, "center_distance": 160.0},
    "load": {"torque2": 500.0, "speed1": 1450.0, "life": 20000.0},
    "wheel": {"material": "BrO10N1F1_centrifugal"},
    "thermal": {"ambient": 20.0, "heat_transfer": 13.0, "base_share": 0.3},
}

EXPECTED = {  # key: (note value, tolerance)
    "x": (0.3968, 5e-5), "d1": (63.000, 5e-4), "d2": (252.000, 5e-4), "d_w1": (68.000, 5e-4),
    "gamma": (11.3099, 5e-5), "gamma_w": (10.4975, 5e-5), "d_a1": (75.600, 5e-4),
    "d_f1": (47.880, 5e-4), "d_a2": (269.600, 5e-4), "d_f2": (241.880, 5e-4),
    "d_aM2": (279.05, 5e-3), "p_x": (19.792, 5e-4), "p_z1": (39.584, 5e-4),
    "v1": (5.163, 5e-4), "v_s": (5.251, 5e-4), "v2": (0.957, 5e-4),
    "rho": (1.409, 2e-3),            # ρ' interpolated in degrees by the hand calculation, see above
    "eta_m": (0.8788, 2e-4), "eta": (0.8436, 2e-4), "T1": (29.63, 1e-2), "P1": (4.500, 1e-3),
    "F_t2": (3968.3, 0.05), "F_t1": (871.6, 0.15), "F_r": (1444.3, 0.05),
    "sigma_H": (166.0, 0.05), "N": (8.70e7, 5e5), "K_HL": (0.7631, 5e-5), "C_v": (0.9260, 5e-5),
    "sigma_HP": (181.2, 0.05), "a_w_req": (150.9, 0.05), "z_v2": (42.08, 5e-3),
    "Y_F2": (1.521, 5e-4), "sigma_F": (10.66, 5e-3), "K_FL": (0.6088, 5e-5),
    "sigma_FP": (39.0, 0.05), "area": (0.887, 5e-4), "t_oil": (66.9, 0.1),
    "b1_min": (92.4 + 25.0, 0.05),   # 92.4 interpolated at x = 0.397, + 25 mm grinding
}


def test_note_example_a8():
    v = flat(run_data(NOTE).document())
    for key, (value, tol) in EXPECTED.items():
        assert abs(v[key] - value) <= tol, (key, v[key], value)


def test_note_example_ivanov_bending_and_face_width():
    """With b2 = 0.355·a_w = 56.8 mm the hand calculation gets σ_F = 11.81 MPa (Ivanov's form) and
    2δ = 103.25°, and says a validation rule should catch b2 > 0.75·d_a1 = 56.7 mm."""
    spec = dict(NOTE, gear=dict(NOTE["gear"], face_width=56.8),
                method={"bending_formula": "ivanov"})
    doc = run_data(spec).document()
    v = flat(doc)
    assert abs(v["sigma_F"] - 11.81) <= 5e-3
    assert abs(v["wrap_angle"] - 103.25) <= 5e-3
    face = {c["code"]: c for c in doc["checks"]}["FACE_WIDTH"]
    assert not face["passed"] and face["severity"] == "error"
    assert face["message"] == (
        "b2 = 56.8 mm > 0.75·d_a1 = 56.7 mm: the rim ends overhang the worm threads and carry "
        "nothing; reduce face_width to at most 56.7 mm")


def test_design_mode_reproduces_the_note():
    """Design mode from T2, n1, u and the material proposes the hand calculation's pair."""
    spec = {"kind": "worm", "mode": "design", "gear": {"ratio": 20.0},
            "load": {"torque2": 500.0, "speed1": 1450.0},
            "wheel": {"material": "BrO10N1F1_centrifugal"}}
    v = flat(run_data(spec).document())
    assert (v["z1"], v["z2"], v["q"], v["m"], v["a_w"]) == (2, 40, 10.0, 6.3, 160.0)
    assert abs(v["x"] - 0.3968) <= 5e-5
