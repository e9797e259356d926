"""Regression values: our own recomputations of [Matusevich2017], [Malashchenko2017] and
[Gavrilov2017] (not printed in the papers). They guard this code against
change; the published values are in ``tests/reference/planetary``."""

from __future__ import annotations

import math

import pytest

from geardesign.core.registry import run_data
from geardesign.planetary.efficiency import efficiency, efficiency_2kh_braked_carrier, flow
from geardesign.planetary.kinematics import Train, speeds


def sweep(i, a_min=15.0, a_max=24.0, xa_min=-1.0, xa_max=1.36, N=41):
    return (a_min + (a_max - a_min) / (N - 1) * (i - 1),
            xa_min + (xa_max - xa_min) / (N - 1) * (i - 1))


def doc3k(alpha, x_a):
    return run_data({
        "kind": "planetary",
        "train": {"scheme": "3K", "planets": 3, "module": 0.3, "face_width": 3.0,
                  "working_angle": alpha},
        "teeth": {"sun": 12, "planet": 46, "ring": 102, "ring2": 105},
        "shift": {"sun": x_a},
        "ring": {"tip_shortening": 0.2},
        "operation": {"fixed": "ring", "input": "sun", "output": "ring2"},
    }).document()["results"]


# [Matusevich2017], first sweep: i: (x_g, x_b, x_e, ε_ag, Δϑ_ag, η_ag, s_a sun)
FIRST = {
    24: (-0.324, 0.836, -0.762, 1.483, 3.813, 0.609, 0.1186),
    31: (-0.416, 1.134, -0.573, 1.306, -2.011, 0.561, 0.0226),
    41: (-0.448, 1.757, -0.105, 1.043, -2.627, 0.502, -0.1251),
}


@pytest.mark.parametrize("i", sorted(FIRST))
def test_first_sweep_table(i):
    r = doc3k(*sweep(i))
    x_g, x_b, x_e, eps, dth, eta, s_a = FIRST[i]
    g = r["gears"]
    assert g["x_planet"] == pytest.approx(x_g, abs=6e-4)
    assert g["x_ring"] == pytest.approx(x_b, abs=6e-4)
    assert g["x_ring2"] == pytest.approx(x_e, abs=6e-4)
    assert r["sun_planet"]["eps_alpha"] == pytest.approx(eps, abs=6e-4)
    assert r["sun_planet"]["delta_theta"] == pytest.approx(dth, abs=6e-4)
    assert r["sun_planet"]["eta_p"] == pytest.approx(eta, abs=6e-4)
    assert g["s_an_sun"] == pytest.approx(s_a, abs=6e-5)


def test_first_sweep_interference_zone():
    """B.10: for x_a < 0.232 the sun's lower active point would lie inside its base circle
    (the denominator of eq. (32) is negative): the hand calculation's sample i = 11 (ϑ_p = 2.457) is
    meaningless; the tool reports the sliding as undefined and fails the interference
    check."""
    doc = run_data({
        "kind": "planetary",
        "train": {"scheme": "3K", "planets": 3, "module": 0.3, "face_width": 3.0,
                  "working_angle": sweep(11)[0]},
        "teeth": {"sun": 12, "planet": 46, "ring": 102, "ring2": 105},
        "shift": {"sun": sweep(11)[1]},
        "ring": {"tip_shortening": 0.2},
        "operation": {"fixed": "ring", "input": "sun", "output": "ring2"},
    }).document()
    assert doc["results"]["sun_planet"]["theta_p"] is None
    bad = {c["code"] for c in doc["checks"] if not c["passed"]}
    assert "SUN_PLANET_INTERFERENCE_SUN" in bad


# second sweep, i: (x_g, x_b, x_e, Δϑ_ag, η_ag, η_bg, η_ef, a_w)
SECOND = {
    28: (-0.0935, 1.2827, -0.3774, 5.954, 0.580, 0.0527, 0.0784, 8.761),
    32: (0.1004, 1.7100, -0.0118, 4.622, 0.554, 0.0511, 0.0739, 8.816),
}


@pytest.mark.parametrize("i", sorted(SECOND))
def test_second_sweep_table(i):
    r = doc3k(*sweep(i, xa_min=0.298, xa_max=0.306))
    x_g, x_b, x_e, dth, e_ag, e_bg, e_ef, a_w = SECOND[i]
    assert r["gears"]["x_planet"] == pytest.approx(x_g, abs=6e-5)
    assert r["gears"]["x_ring"] == pytest.approx(x_b, abs=6e-5)
    assert r["gears"]["x_ring2"] == pytest.approx(x_e, abs=6e-5)
    assert r["sun_planet"]["delta_theta"] == pytest.approx(dth, abs=6e-4)
    assert r["sun_planet"]["eta_p"] == pytest.approx(e_ag, abs=6e-4)
    assert r["planet_ring"]["eta_p"] == pytest.approx(e_bg, abs=6e-5)
    assert r["planet_ring2"]["eta_p"] == pytest.approx(e_ef, abs=6e-5)
    assert r["assembly"]["a_w_sun_planet"] == pytest.approx(a_w, abs=6e-4)


def test_neighbour_clearance_of_the_3k_example():
    """B.5: 2 a_w sin 60° = 15.222 mm against the planet tip 14.394 mm: gap ≈ 0.83 mm."""
    r = doc3k(*sweep(30, xa_min=0.298, xa_max=0.306))
    assert r["assembly"]["neighbour_clearance"] == pytest.approx(0.8275, abs=5e-4)


@pytest.mark.parametrize("i, w4, value", [(1, 25, 0.9557), (4, 10, 0.9473), (5, 15, 0.7918),
                                          (8, 10, 0.7823), (18, 5, 0.6299)])
def test_braked_carrier_table_eq_14(i, w4, value):
    """A.5, own evaluation of eq. (14) (η^(4) = 0.97, ω_1 = 100 rad/s)."""
    assert efficiency_2kh_braked_carrier(i, 0.97, 100.0, w4) == pytest.approx(value, abs=6e-5)


@pytest.mark.parametrize("i, w4, value", [(0.2, 15, 0.7918), (0.4, 25, 0.8435),
                                          (2.0, 10, 0.9683), (10.0, 25, 0.9690)])
def test_braked_carrier_table_eq_17(i, w4, value):
    assert efficiency_2kh_braked_carrier(i, 0.97, 100.0, w4, "ring") == pytest.approx(
        value, abs=6e-5)


def test_braked_carrier_example_torques():
    """A.3: i = 4, ω_1 = 100, ω_4 = 10 rad/s, T_1 = 1 N·m → T_3 = 3.88, T_4 = −4.88 N·m,
    η_13 = 0.947, all outputs over all inputs 0.973."""
    t = Train("2K-H", 20, 30, 80, 4)
    s = speeds(t, {"sun": 100.0, "carrier": 10.0})
    f = flow(t, s, {"sun": 0.97, "ring": 1.0}, "sun", 1.0, ("ring", "carrier"), driven="ring")
    assert f.T["ring"] == pytest.approx(3.88, abs=1e-12)
    assert f.T["carrier"] == pytest.approx(-4.88, abs=1e-12)
    assert efficiency(f, ("sun", "carrier"), "ring") == pytest.approx(0.9473, abs=6e-5)
    assert -(f.P["ring"] + f.P["carrier"]) / f.P["sun"] == pytest.approx(0.973, abs=6e-4)


def test_3k_efficiencies():
    """D.4/E14 with η^h_ab = 0.97 and η^h_eb = 0.98: forward η^b_ae = 0.579 (the hand calculation's
    decomposition η^b_aH·η^b_He; the exact planet balance gives the same to 4 digits);
    reverse: the hand calculation's decomposition gives 0.306, the exact balance 0.298 (the carrier is
    no real intermediate member of a 3K train)."""
    t = Train("3K", 12, 46, 102, 3, None, 105)
    s = speeds(t, {"ring": 0.0, "sun": 1000.0})
    e_b = 0.97 / 0.985
    eta = {"sun": 0.985, "ring": e_b, "ring2": 0.98 / e_b}
    f = flow(t, s, eta, "sun", 1.0, ("ring", "ring2"), driven="ring2")
    assert efficiency(f, ("sun",), "ring2") == pytest.approx(0.579, abs=6e-4)
    r = flow(t, s, eta, "ring2", -f.T["ring2"], ("sun", "ring"), driven="sun")
    assert efficiency(r, ("ring2",), "sun") == pytest.approx(0.2979, abs=1e-4)
    assert math.isclose(1 - (1 - 0.97) * 102 / 114, 0.9732, abs_tol=6e-5)
