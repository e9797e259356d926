"""Regression values: our recomputations of [RotaryDevices] and of Geneva kinematics
([Artobolevsky]), not published numbers.

D.4: Geneva kinematics table (external z = 3...8, internal z = 4, 6).
D.6: the spindle-block example (4-slot cross, 6 spindles, distributing shaft 30 min⁻¹).

Differences from the hand calculation, by design:

* B1 (constant part of J_p): the hand calculation prints 202.0 kg·m²; it used u1 = ω_d/ω_r in
  J_d/u1², which makes the motor rotor vanish (2·10⁻⁵ kg·m²).  The paper defines
  u1 = ω_r/ω_d ([RotaryDevices] eq. (2), "u1 = ω_p/ω_d"), so J_d/u1² = J_d·(ω_d/ω_r)² =
  116.8 kg·m² and B1 = 318.8 kg·m².  B1 is constant and does not change any power.
* Barrel turned against the spindles with η_b = 0.80, η_sh = 0.85: the hand calculation divides the
  negative spindle power by η (N = 3.106 kW, N_sh = −1.810 kW); geardesign multiplies
  power given back by η (the losses reduce what returns, as the hand calculation itself recommends):
  N_max = 3.616 kW.  The hand calculation's number is reproduced below with its rule.
"""

import math

import pytest

from geardesign.core.registry import run_data
from geardesign.geneva import kinematics as K
from geardesign.geneva.drive import (
    SpindleBlock, drive_point, inertia_coefficients, planetary_ratio)

# z: (ω2max/ω1, |ε2|max/ω1², φ deg, |ω2ε2|max/ω1³, φ deg, tan π/z)
EXTERNAL = {
    3: (6.4641, 31.392, 4.76, 159.31, 3.62, 1.732),
    4: (2.4142, 5.4070, 11.46, 10.015, 8.48, 1.000),
    5: (1.4259, 2.2988, 17.57, 2.4578, 12.65, 0.727),
    6: (1.0000, 1.3496, 22.90, 0.9903, 16.07, 0.577),
    8: (0.6199, 0.6998, 31.64, 0.3063, 21.21, 0.414),
}
INTERNAL = {4: (0.4142, 1.000, 0.0900), 6: (0.3333, 0.5774, 0.0491)}


def _close(actual, printed):
    text = repr(printed)
    decimals = len(text.split(".")[1]) if "." in text else 0
    return abs(actual - printed) <= 1.01 * 10 ** -decimals


@pytest.mark.parametrize("z", EXTERNAL)
def test_d4_external_table(z):
    w, e, phi_e, p, phi_p, jump = EXTERNAL[z]
    assert _close(K.peak_omega_ratio(K.crank_ratio(z), False), w)
    e_val, e_phi = K.peak_acceleration(z, False)
    assert _close(e_val, e) and _close(-math.degrees(e_phi), phi_e)
    p_val, p_phi = K.peak_power_factor(z, False)
    assert _close(p_val, p) and _close(-math.degrees(p_phi), phi_p)
    assert _close(K.entry_jump(z), jump)
    assert _close(math.degrees(2 * K.half_motion_angle(z, False)), 180.0 * (z - 2) / z)


@pytest.mark.parametrize("z", INTERNAL)
def test_d4_internal(z):
    w, e, p = INTERNAL[z]
    assert _close(K.peak_omega_ratio(K.crank_ratio(z), True), w)
    assert _close(K.peak_acceleration(z, True)[0], e)
    assert _close(K.peak_power_factor(z, True)[0], p)


def block(direction, eta_b=1.0, eta_sh=1.0):
    return SpindleBlock(J_b=25.0, M_tr=60.0, eta_b=eta_b, i_kb=4 / 6, n_sh=6, J_sh=0.03,
                        m_sh=25.0, R_b=0.12, u_p=planetary_ratio(60, 30, direction),
                        w_rab=1000 * math.pi / 30, eta_sh=eta_sh, J_d=0.05,
                        w_d=1450 * math.pi / 30, J_r=2.0)


SPEC = {
    "kind": "geneva",
    "geneva": {"slots": 4, "center_distance": 200.0, "roller_diameter": 20.0,
               "crank_speed": 30.0},
    "barrel": {"stations": 6, "inertia": 25.0, "friction_torque": 60.0, "efficiency": 1.0},
    "spindles": {"count": 6, "inertia": 0.03, "mass": 25.0, "orbit_radius": 120.0,
                 "central_gear_teeth": 60, "spindle_gear_teeth": 30, "working_speed": 1000.0,
                 "efficiency": 1.0},
    "drive": {"motor_speed": 1450.0, "motor_inertia": 0.05, "shaft_inertia": 2.0},
}


def doc(direction="same", eta_b=1.0, eta_sh=1.0):
    data = {k: (dict(v) if isinstance(v, dict) else v) for k, v in SPEC.items()}
    data["spindles"]["direction"] = direction
    data["barrel"]["efficiency"] = eta_b
    data["spindles"]["efficiency"] = eta_sh
    return run_data(data).document()["results"]["drive"]


def test_d6_inertia_and_barrel_motion():
    r = doc()
    assert _close(r["B2"], 28.780)
    assert _close(r["B12"], 36.0)
    assert _close(r["omega_b_max"], 5.056)
    assert _close(r["eps_b_max"], 35.58)
    assert r["B1"] == pytest.approx(2.0 + 200.0 + 0.05 * (1450 / 30) ** 2, rel=1e-12)
    assert _close(r["B1"], 318.8)            # the hand calculation's 202.0 omits the motor rotor


@pytest.mark.parametrize("direction, N, phi, M_d", [
    ("same", 6.134, 9.09, 1952.6),
    ("opposite", 2.395, 7.13, 762.4),
])
def test_d6_peak_power_efficiency_one(direction, N, phi, M_d):
    r = doc(direction)
    assert _close(r["N_max"], N)
    assert _close(-r["phi_N_max"], phi)
    assert _close(r["M_d_max"], M_d)


def test_d6_peak_power_with_efficiencies_same_direction():
    r = doc("same", 0.80, 0.85)
    assert _close(r["N_max"], 7.509)
    assert _close(r["N_b_at_max"], 4.970)
    assert _close(r["N_sh_at_max"], 2.539)
    assert _close(-r["phi_N_max"], 9.05)   # note: 9.04° (its grid); closed search 9.049°


def test_d6_opposite_direction_efficiency_rule():
    r = doc("opposite", 0.80, 0.85)
    assert _close(r["N_max"], 3.616)       # negative spindle power multiplied by η_sh
    # the hand calculation's 3.106 kW divides the negative spindle power by η_sh as well
    s = block("opposite")
    B = inertia_coefficients(s, math.pi)
    lam, phi0 = K.crank_ratio(4), K.half_motion_angle(4, False)
    best = max(
        (drive_point(s, B, math.pi, K.omega_ratio(p, lam, False), K.eps_ratio(p, lam, False))
         for p in (-phi0 + 2 * phi0 * i / 20000 for i in range(20001))),
        key=lambda d: d.N_b / 0.80 + d.N_sh / 0.85)
    assert _close(best.N_b / 0.80 / 1000, 4.916)
    assert _close(best.N_sh / 0.85 / 1000, -1.810)
    assert _close((best.N_b / 0.80 + best.N_sh / 0.85) / 1000, 3.106)


def test_d6_lagrange_form_equals_direct_power_form():
    """D.3 check: with all η = 1, M_d·ω_r (eqs. (1)-(3)) equals N_b + N_sh (power balance)."""
    for direction in ("same", "opposite", "declutched"):
        s = block(direction)
        w_r = math.pi
        B = inertia_coefficients(s, w_r)
        lam, phi0 = K.crank_ratio(4), K.half_motion_angle(4, False)
        for i in range(101):
            p = -phi0 + 2 * phi0 * i / 100
            d = drive_point(s, B, w_r, K.omega_ratio(p, lam, False), K.eps_ratio(p, lam, False))
            assert abs(d.N_d - (d.N_b + d.N_sh)) < 1e-9
