"""Statics of a shaft on two bearings, against hand calculations written out here.

Beam on two simple supports A (z = 0) and B (z = L); forces from the gear mesh (radial
towards the shaft axis, tangential, axial at the pitch radius).  Each case gives the hand
result; the property test checks equilibrium (ΣF = 0, ΣM = 0) for random gear loads.
"""

import math
import random

import pytest

from geardesign.drive.shafts import GearLoad, gear_force, reactions


def test_radial_force_at_mid_span():
    # F_r = 1000 N towards the axis (mate at θ = 0: force along −x) at z = L/2:
    # each bearing carries 500 N along +x
    R = reactions(0.0, 100.0, [GearLoad(0.0, 1000.0, 0.0, 50.0, 50.0, 0.0, True)])
    assert R.R_A == pytest.approx((500.0, 0.0)) and R.R_B == pytest.approx((500.0, 0.0))


def test_overhung_tangential_force():
    # F_t = 1000 N at z = 150 beyond B (L = 100), driving gear, shaft turning +1, mate at
    # θ = 0: the force is −F_t along t = +y, i.e. (0, −1000).  Moments about A:
    # R_B·100 = 1000·150 -> R_B = +1500 (along +y), R_A = −500.
    R = reactions(0.0, 100.0, [GearLoad(1000.0, 0.0, 0.0, 40.0, 150.0, 0.0, True)], rotation=1)
    assert R.R_B == pytest.approx((0.0, 1500.0)) and R.R_A == pytest.approx((0.0, -500.0))


def test_axial_force_moment():
    # F_a = 1000 N along +z at radius 50 (contact at +x), mid-span of L = 100: the couple
    # F_a·r = 50 000 N·mm is taken by ±500 N along x; the axial 1000 N goes to the fixed one.
    R = reactions(0.0, 100.0, [GearLoad(0.0, 0.0, 1000.0, 50.0, 50.0, 0.0, True)])
    assert R.R_A == pytest.approx((-500.0, 0.0)) and R.R_B == pytest.approx((500.0, 0.0))
    assert R.axial == pytest.approx(1000.0)


def test_intermediate_shaft_two_gears():
    # Wheel of stage 1 (driven, mate at 180°) and pinion of stage 2 (driving, mate at 0°),
    # radial forces only: 400 N at z = 40 along +x (towards the axis from a mate at 180°),
    # 900 N at z = 120 along −x; L = 160.  Moments about A:
    # R_Bx·160 + 400·40 − 900·120 = 0 -> R_Bx = 575; forces: R_Ax = −(400 − 900) − 575 = −75.
    loads = [GearLoad(0.0, 400.0, 0.0, 100.0, 40.0, math.pi, False),
             GearLoad(0.0, 900.0, 0.0, 30.0, 120.0, 0.0, True)]
    R = reactions(0.0, 160.0, loads)
    assert R.R_B[0] == pytest.approx(575.0) and R.R_A[0] == pytest.approx(-75.0)
    assert R.R_A[1] == pytest.approx(0.0, abs=1e-9) and R.R_B[1] == pytest.approx(0.0, abs=1e-9)


def test_equilibrium_of_random_loads():
    rng = random.Random(7)
    for _ in range(200):
        zA, zB = rng.uniform(-50, 50), rng.uniform(60, 400)
        loads = [GearLoad(rng.uniform(0, 5e4), rng.uniform(0, 2e4), rng.uniform(0, 1e4),
                          rng.uniform(10, 300), rng.uniform(-100, 500),
                          rng.uniform(-math.pi, math.pi), rng.random() < 0.5,
                          rng.choice((-1, 1))) for _ in range(rng.randint(1, 3))]
        rot = rng.choice((-1, 1))
        R = reactions(zA, zB, loads, rot)
        Fx = R.R_A[0] + R.R_B[0]
        Fy = R.R_A[1] + R.R_B[1]
        Mx = -(zB - zA) * R.R_B[1]   # (B − A) × R_B, x component
        My = (zB - zA) * R.R_B[0]
        for g in loads:
            (fx, fy, fz), (px, py, pz) = gear_force(g, rot)
            Fx += fx
            Fy += fy
            Mx += py * fz - (pz - zA) * fy
            My += (pz - zA) * fx - px * fz
        scale = sum(abs(g.F_t) + abs(g.F_r) + abs(g.F_a) for g in loads)
        assert abs(Fx) < 1e-9 * scale and abs(Fy) < 1e-9 * scale
        assert abs(Mx) < 1e-7 * scale * 500 and abs(My) < 1e-7 * scale * 500
