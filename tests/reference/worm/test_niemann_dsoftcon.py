"""Niemann–Winter, Maschinenelemente Band III, worm example "Beispiel 3" (p. 102), as
printed by the public worm-gear program WormGear (André Dewispelaere, Dware) in its
calculation reports http://www.dsoftcon.be/WormGear/en/GeometryOutputHtml.htm and
http://www.dsoftcon.be/WormGear/en/ForcesOutputHtml.htm (DIN 3975 geometry, DIN 3996
forces).  Values nobody here computed; tolerance one unit of the printed last digit.

Input (printed): flank form E (involute worm, ZI), α_n = 20°, m_x = 10.42 mm, z1 = 1,
z2 = 40, d1 = 83.2 mm, a = 250 mm, h_a* = 1, h_f* = 1.2 (c* = 0.2), worm driving.  The
worm speed is not in the printed excerpt; n1 = 1500 min⁻¹ is the only round speed that
gives the printed v_g = 6.59 m/s (1499 ... 1501 min⁻¹ do).

DIN 3996 takes the friction coefficient from its own law (μ_z = 0.026 printed, ρ_z =
1.4954°); our table is not that law, so the test gives the printed friction angle as
friction.coefficient = tan 1.4954° and compares the efficiencies, which use the same
formula tan γ/tan(γ + ρ) in both methods.  (The printed μ_z = 0.026 is rounded: tan 1.4954°
= 0.02610.)  The static release efficiency is checked the same way with μ_zA = 0.120.
"""

import math

from geardesign.core.registry import run_data
from tests.conftest import assert_ref, dms, flat

BASE = {
    "kind": "worm",
    "gear": {"module": 10.42, "diameter_factor": 83.2 / 10.42, "z1": 1, "z2": 40,
             "center_distance": 250.0, "worm_type": "ZI", "profile_angle": 20.0},
    "load": {"torque2": 1000.0, "speed1": 1500.0},
    "wheel": {"material": "BrO10N1F1_centrifugal"},
}

GEOMETRY = {  # key: (printed value, tolerance)
    "q": (7.985, 5e-4),
    "d1": (83.200, 5e-4),
    "d2": (416.800, 5e-4),
    # 7° 8'18": the report truncates the seconds (its 2023 run prints the input 7.13860° as
    # 7° 8'18" too), so the printed value means 18" <= γ − 7°8' < 19"
    "gamma": (dms(7, 8, 18.5), 0.5 / 3600),
    "a_w": (250.000, 5e-4),
    "x": (0.0, 5e-5),
    "p_z1": (32.7354, 5e-5),
    "u": (40.0, 5e-5),
    # printed 20.14373; tan α_x = tan α_n/cos γ gives 20.1437237 (6.3e-6° below the printed
    # last digit: the program evaluates α_x by another path, e.g. from its generating tool
    # d0 = 120 mm); accepted within 1e-5°, a documented deviation
    "alpha_x": (20.14373, 1e-5),
    "alpha_n": (20.00000, 5e-6),
    "p_x": (32.7354, 5e-5),
    "m_n": (10.3392, 5e-5),
    "d_a1": (104.040, 5e-4),
    "d_a2": (437.640, 5e-4),
    "d_f1": (58.192, 5e-4),
    "d_f2": (391.792, 5e-4),
}


def _run(friction: float) -> dict:
    spec = dict(BASE, friction={"coefficient": friction})
    return run_data(spec).document()


def test_niemann_beispiel_3_geometry():
    v = flat(_run(math.tan(math.radians(1.4954))))
    for key, (expected, tol) in GEOMETRY.items():
        assert_ref(v[key], expected, tol, f"Niemann–Winter III Beispiel 3: {key}")
    assert_ref(v["a_w"] - v["d1"] / 2 - v["d2"] / 2, 0.0, 1e-9, "x = 0 at a = 250")


def test_niemann_beispiel_3_sliding_speed_and_efficiency():
    doc = _run(math.tan(math.radians(1.4954)))
    v = flat(doc)
    assert_ref(v["v_s"], 6.59, 0.005, "sliding velocity v_g")
    assert_ref(v["rho"], 1.4954, 5e-5, "sliding friction angle ρ_z")
    assert_ref(v["eta_m"], 0.82, 0.005, "gear teeth efficiency, worm driving η_z")
    assert_ref(v["eta_reverse"], 0.79, 0.005, "gear teeth efficiency, gear driving η'_z")
    assert v["self_locking"] is False  # printed: "Worm gear pair is self jamming  -"
    checks = {c["code"]: c for c in doc["checks"]}
    assert checks["SELF_LOCKING"]["passed"]


def test_niemann_beispiel_3_release_from_standstill():
    v = flat(_run(0.120))
    assert_ref(v["rho"], 6.8428, 5e-5, "static friction angle ρ_zA")
    assert_ref(v["eta_m"], 0.503, 5e-4, "gear teeth static efficiency η_zA")
    assert v["self_locking"] is False  # γ = 7.14° > ρ_zA = 6.84°: not self-locking at rest
