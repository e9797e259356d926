"""GOST 21354-87 rating: the load factors and peak stresses obey what the standard's
relations imply for every valid pair.

Each property failed on the rating before it was corrected:

* K_Hα and K_Fα are never below 1 (the cap 0.95ε_α²/ε_β was applied after the floor);
* K_Fα·Y_ε ≤ 1: one tooth never takes more than the whole F_t (the ISO cap
  ε_γ/(0.25ε_α + 0.75) was paired with the GOST Y_ε = 1/ε_α);
* K_Fβ = (K⁰_Hβ)^N_F with K⁰_Hβ before running-in (soft pairs were raised from the run-in
  K_Hβ);
* σ_Hmax and σ_Fmax do not depend on K_A (T_max is an actual torque; K_A was counted again
  in K_Hmax and K_Fmax).
"""

from __future__ import annotations

import math

from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from tests.conftest import flat
from tests.helpers_cli import run_bad, run_failing


def _doc(gear: dict, load: dict, mats: dict | None = None) -> dict:
    spec = {"kind": "spur", "gear": gear, "load": load}
    if mats:
        spec["material"] = mats
    return run_data(spec).document()


SOFT = {"pinion": {"grade": "40Kh", "treatment": "improved", "hardness_HB": 280.0},
        "wheel": {"grade": "45", "treatment": "improved", "hardness_HB": 240.0}}
HARD = {"pinion": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 58.0},
        "wheel": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 56.0}}

pairs = st.fixed_dictionaries({
    "module": st.sampled_from([2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0]),
    "z1": st.integers(17, 40),
    "u": st.floats(1.0, 5.0),
    "helix_angle": st.sampled_from([0.0, 8.0, 12.0, 15.0, 20.0, 25.0, 30.0]),
    "psi": st.floats(0.1, 1.2),
    "x1": st.floats(0.0, 0.5),
    "grade": st.integers(6, 9),
    "scheme": st.integers(1, 7),
    "hard": st.booleans(),
    "torque": st.floats(50.0, 20000.0),
    "speed": st.floats(50.0, 3000.0),
})


def _spec(p: dict, K_A: float = 1.0, peak: float | None = None):
    z2 = max(17, round(p["z1"] * p["u"]))
    d1 = p["module"] * p["z1"] / math.cos(math.radians(p["helix_angle"]))
    gear = {"module": p["module"], "z1": p["z1"], "z2": z2, "helix_angle": p["helix_angle"],
            "face_width": round(p["psi"] * d1, 1), "x1": p["x1"], "x2": 0.0,
            "accuracy_grade": p["grade"], "bearing_scheme": p["scheme"]}
    load = {"speed1": p["speed"], "torque1": p["torque"], "application_factor": K_A,
            "life_hours": 10000.0}
    if peak is not None:
        load["peak_torque1"] = peak
    return gear, load, HARD if p["hard"] else SOFT


def _rate(p: dict, **kw) -> dict | None:
    gear, load, mats = _spec(p, **kw)
    try:
        return flat(_doc(gear, load, mats))
    except InputError:
        return None


SETTINGS = settings(max_examples=60, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


@SETTINGS
@given(pairs)
def test_transverse_factors_are_at_least_one_and_one_tooth_takes_at_most_the_load(p):
    v = _rate(p)
    assume(v is not None and v["eps_alpha"] >= 1.0)
    assert v["K_Halpha"] >= 1.0
    assert v["K_Falpha"] >= 1.0
    assert v["K_Falpha"] * v["Y_eps"] <= 1.0 + 1e-12


@SETTINGS
@given(pairs)
def test_bending_face_factor_comes_from_the_factor_before_running_in(p):
    v = _rate(p)
    assume(v is not None)
    assert math.isclose(v["K_Fbeta"], v["K0_Hbeta"] ** v["N_F"], rel_tol=1e-12)
    assert v["K0_Hbeta"] >= v["K_Hbeta"] - 1e-12


@SETTINGS
@given(pairs, st.floats(1.0, 2.5))
def test_peak_stresses_do_not_depend_on_the_application_factor(p, K_A):
    peak = 2.0 * p["torque"]
    a = _rate(p, K_A=1.0, peak=peak)
    b = _rate(p, K_A=K_A, peak=peak)
    assume(a is not None and b is not None)
    for key in ("sigma_Hmax", "sigma_Fmax1", "sigma_Fmax2"):
        assert math.isclose(a[key], b[key], rel_tol=1e-9), key


WIDE_HELICAL = """kind = "spur"
[gear]
module = 6.0
z1 = 42
z2 = 54
helix_angle = 30.0
face_width = 80.0
center_distance = 336.0
x1 = 0.5
accuracy_grade = 8
bearing_scheme = 5
[load]
speed1 = 2100.0
torque1 = 20000.0
life_hours = 10000.0
[material.pinion]
grade = "20KhN3A"
treatment = "carburized"
hardness_HRC = 56.0
[material.wheel]
grade = "20KhN3A"
treatment = "carburized"
hardness_HRC = 56.0
"""


def test_wide_helical_pair_with_k_h_alpha_cap_below_one_fails_contact(tmp_path):
    """Issue example: z 42/54, m_n 6, β 30°, b_w 80, a_w 336, 20KhN3A 56 HRC, grade 8,
    n1 2100 min⁻¹, T1 20 000 N·m.  ε_β > 0.95ε_α² puts the cap of K_Hα at 0.796; the
    rating used it (σ_H 1068 MPa, passed).  With K_Hα = 1, σ_H ≈ 1198 MPa > σ_HP 1173 MPa."""
    doc = run_failing(tmp_path, WIDE_HELICAL)
    v = flat(doc)
    assert v["K_Halpha_max"] < 1.0
    assert v["K_Halpha"] == 1.0
    assert math.isclose(v["sigma_H"], 1198.0, rel_tol=0.01)
    assert v["sigma_H"] > v["sigma_HP"]
    contact = [c for c in doc["checks"] if c["code"].startswith("CONTACT") and not c["passed"]]
    assert contact, doc["checks"]
    assert "increase" in contact[0]["message"] or "harden" in contact[0]["message"]


def test_k_f_alpha_times_y_eps_of_the_issue_pair_is_at_most_one():
    """Issue example: z 27/108, m 3, β 12°, grade 9 printed K_Fα 2.74 (σ_F 60 % high)."""
    d1 = 3.0 * 27 / math.cos(math.radians(12.0))
    v = flat(_doc({"module": 3.0, "z1": 27, "z2": 108, "helix_angle": 12.0,
                    "face_width": round(0.8 * d1), "accuracy_grade": 9,
                    "bearing_scheme": 5},
                   {"speed1": 1000.0, "torque1": 300.0, "life_hours": 10000.0}, SOFT))
    assert v["K_Falpha"] * v["Y_eps"] <= 1.0 + 1e-12
    assert v["K_Falpha"] < 2.0


def test_every_factor_can_be_given_and_is_marked(tmp_path):
    base = {"module": 4.0, "z1": 25, "z2": 100, "helix_angle": 10.0, "face_width": 63.0,
            "bearing_scheme": 5}
    load = {"speed1": 960.0, "torque1": 500.0, "life_hours": 10000.0, "peak_torque1": 900.0}
    given = {"Z_H": 2.4, "Z_eps": 0.8, "Z_N1": 1.1, "Z_v1": 1.05, "Z_X1": 0.98, "Y_N1": 1.2,
             "Y_X1": 1.0, "Y_delta": 1.0, "Y_beta": 0.9, "Y_eps": 0.7, "N_HG1": 5e7,
             "N_FG": 3e6, "Z_Nmax1": 2.0, "S_FSt": 2.0, "Y_A1": 0.9}
    doc = run_data({"kind": "spur", "gear": base, "load": load, "factors": given,
                    "material": SOFT}).document()
    v = flat(doc)
    for key, value in given.items():
        assert v[key] == value, key


def test_a_factor_outside_its_domain_is_an_input_error(tmp_path):
    lines = run_bad(tmp_path, """kind = "spur"
[gear]
module = 4.0
z1 = 25
z2 = 100
face_width = 63.0
[load]
speed1 = 960.0
torque1 = 500.0
[factors]
K_Halpha = 0.8
Y_eps = 1.5
""")
    assert lines == [
        "s.toml: factors.K_Halpha = 0.8: must be a number >= 1 and <= 10",
        "s.toml: factors.Y_eps = 1.5: must be a number >= 0.1 and <= 1",
        # the other mistake of the spec, in the same round
        "s.toml: material: missing table [material.pinion] and [material.wheel]: required "
        "with load.torque1 or load.power for the strength calculation",
    ]


def test_every_factor_key_has_its_domain_in_the_error_line(tmp_path):
    from geardesign.spur.spec import _FACTOR_NAMES

    base = """kind = "spur"
[gear]
module = 4.0
z1 = 25
z2 = 100
face_width = 63.0
[factors]
"""
    for key, _, lo, hi in _FACTOR_NAMES:
        bad = hi * 2.0
        lines = run_bad(tmp_path, base + f"{key} = {bad!r}\n")
        lo_s = str(int(lo)) if float(lo).is_integer() and abs(lo) < 1e15 else repr(lo)
        hi_s = str(int(hi)) if float(hi).is_integer() and abs(hi) < 1e15 else repr(hi)
        assert lines == [f"s.toml: factors.{key} = {bad!r}: must be a number >= {lo_s} and "
                         f"<= {hi_s}"], key
