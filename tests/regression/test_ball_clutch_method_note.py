"""Regression values: a synthetic example (ours; [Malashchenko2025] prints no numbers).

z3 = 6 steel balls of 16 mm (16.84 g) on d5 = 60 mm, α2 = 45°, c = 20 N/mm, y0 = 5 mm,
n = 1000 min⁻¹, f = f_g = 0.10; spring d = 2.5 mm, D = 16 mm, G = 78.5 GPa.
"""

import math

import pytest

from geardesign.ball_clutch import clutch as C
from geardesign.ball_clutch import spring as SP
from geardesign.core.registry import run
from tests.conftest import SPECS


def _close(actual, printed):
    text = repr(printed)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(actual - printed) <= 1.01 * 10 ** -decimals


@pytest.fixture(scope="module")
def r():
    return run(SPECS / "ball_clutch_check.toml").document()["results"]


def test_c5_limit_torques(r):
    s = r["safety"]
    assert _close(s["m"] * 1000, 16.84)
    assert _close(s["F_c"], 5.54)
    assert _close(s["T_lim_frictionless"], 17.00)
    assert _close(s["T_lim_frictionless"] / 6, 2.834)
    assert _close(s["T_lim"], 23.68)
    assert _close(s["T_lim"] / 6, 3.946)


@pytest.mark.parametrize("n, T", [(0, 25.06), (500, 24.72), (1000, 23.68), (2000, 19.51),
                                  (3000, 12.57)])
def test_c5_speed_dependence(n, T):
    m = C.ball_mass(0.016, 7850.0)
    F_c = C.centrifugal_force(m, 0.03, n * math.pi / 30)
    assert _close(C.limit_torque(100.0, F_c, 6, 0.03, math.radians(45), 0.1, 0.1), T)


def test_c5_force_sharing():
    F_t1, F_t2 = C.ball_forces(23.675, 8, 0.05, 6, 0.06)
    assert _close(F_t1, 118.4)
    assert _close(F_t2, 131.5)


def test_c5_spring():
    n_a = SP.active_coils(78500.0, 2.5, 16.0, 20.0)
    assert _close(n_a, 4.68)
    assert _close(16.0 / 2.5, 6.40)
    assert _close(SP.wahl_factor(6.4), 1.235)
    assert _close(20.0 * (5 + 4), 180)
    assert abs(SP.shear_stress(180.0, 2.5, 16.0) - 580) < 1.0    # printed "580 MPa"
