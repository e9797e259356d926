"""Internal-gear geometry (geardesign.gears.internal) and its strength rating: identities,
the sign conventions, and the tip-interference formula against a brute-force simulation
of the tooth tips' paths."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.involute import inv
from geardesign.gears.geometry import BasicRack, GeometryError
from geardesign.gears.internal import (
    InternalPairInput,
    internal_pair_geometry,
    shift_difference_for_center_distance,
    x_from_iso,
    x_to_iso,
)
from geardesign.spur.strength import gost21354 as G

RACK = BasicRack(math.radians(20.0))


def pair(z1, z2, x1=0.0, x2=0.0, m=1.0, k2=0.0):
    return internal_pair_geometry(InternalPairInput(m, z1, z2, x1, x2, 0.0, 10.0, RACK, k2=k2))


def simulated_tip_margin(g, steps=3000) -> float:
    """Smallest distance [mm] by which a pinion tip corner stays outside the internal
    gear's teeth while the pair rolls (negative: the tips collide).  Carrier frame, ring
    centre at the origin, pinion centre at (0, a_w); zero backlash at the pitch point."""
    z1, z2 = g.inp.z1, g.inp.z2
    r1, r2 = 0.5 * g.g1.d, 0.5 * g.g2.d
    rb2, ra1, ra2 = 0.5 * g.g2.d_b, 0.5 * g.g1.d_a, 0.5 * g.g2.d_a
    alpha = RACK.alpha_n
    psi1 = g.g1.s_n / (2 * r1) + inv(alpha) - inv(math.acos(0.5 * g.g1.d_b / ra1))
    s2 = g.g2.s_n
    worst = math.inf
    for i in range(steps + 1):
        phi1 = -math.pi / 2 + math.pi * i / steps
        phi2 = phi1 * z1 / z2
        for j1 in range(-3, 4):
            c = phi1 + 2 * math.pi * j1 / z1
            for side in (-1, 1):
                ang = c + side * psi1
                px, py = -ra1 * math.sin(ang), g.a_w + ra1 * math.cos(ang)
                r = math.hypot(px, py)
                if r <= ra2 or r <= rb2:
                    continue
                th = math.atan2(-px, py) - phi2
                psi2 = s2 / (2 * r2) - inv(alpha) + inv(math.acos(rb2 / r))
                k = round((th - math.pi / z2) / (2 * math.pi / z2))
                d = abs(th - (math.pi / z2 + 2 * math.pi * k / z2))
                worst = min(worst, (d - psi2) * r)
    return worst


@pytest.mark.parametrize("z2, x2", [(36, 0.0), (37, 0.0), (38, 0.0), (39, 0.0), (40, 0.0),
                                    (36, 0.3), (38, 0.6), (45, 0.0)])
def test_tip_interference_formula_agrees_with_simulation(z2, x2):
    g = pair(30, z2, 0.0, x2)
    margin = simulated_tip_margin(g)
    assert (g.delta_tip >= 0.0) == (margin > -1e-6), (g.delta_tip, margin)


def test_contact_ratio_tooth_number_form():
    """ε_α = [z1 tan α_a1 − z2 tan α_a2 + (z2 − z1) tan α_tw]/(2π) (Matusevich eq. (31),
    lower signs) equals the line-of-action form."""
    g = pair(27, 72, 0.2, 0.5, m=3.0, k2=0.15)
    eps = (27 * math.tan(g.g1.alpha_a) - 72 * math.tan(g.g2.alpha_a)
           + 45 * math.tan(g.alpha_tw)) / (2 * math.pi)
    assert eps == pytest.approx(g.eps_alpha, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(12, 60), dz=st.integers(8, 80), x1=st.floats(-0.3, 0.8),
       xd=st.floats(-0.3, 1.0))
def test_center_distance_round_trip(z1, dz, x1, xd):
    z2 = z1 + dz
    try:
        g = pair(z1, z2, x1, x1 + xd)
    except GeometryError:
        return
    back, alpha = shift_difference_for_center_distance(g.a_w, 1.0, z1, z2, RACK.alpha_n, 0.0)
    assert back == pytest.approx(xd, abs=1e-9)
    assert alpha == pytest.approx(g.alpha_tw, abs=1e-12)
    # working pitch circles roll: d_w2 − d_w1 = 2 a_w, d_w2/d_w1 = u
    assert g.g2.d_w - g.g1.d_w == pytest.approx(2 * g.a_w, rel=1e-12)
    assert g.g2.d_w / g.g1.d_w == pytest.approx(z2 / z1, rel=1e-12)


def test_iso_and_gost_sign_conventions_give_the_same_gear():
    base = {"kind": "planetary",
            "train": {"planets": 3, "module": 3.0, "face_width": 30.0},
            "teeth": {"sun": 18, "planet": 27, "ring": 72},
            "shift": {"sun": 0.2, "planet": -0.2, "ring": -0.2},
            "ring": {"tip_shortening": 0.15},
            "operation": {"fixed": "ring", "input": "sun", "output": "carrier"}}
    gost = run_data(base).document()["results"]
    iso = dict(base, teeth={"sun": 18, "planet": 27, "ring": -72},
               shift={"sun": 0.2, "planet": -0.2, "ring": 0.2})
    iso = run_data(iso).document()["results"]
    for key in ("d_a_ring", "d_f_ring", "s_an_ring", "W_ring", "x_ring", "x_ring_iso"):
        assert iso["gears"][key] == gost["gears"][key]
    assert x_from_iso(0.2) == -0.2 and x_to_iso(x_from_iso(0.37)) == 0.37
    assert iso["train"]["ring_convention"].startswith("ISO 21771")


def test_internal_contact_stress_uses_u_minus_1():
    ext = G.sigma_h(190.0, 2.5, 0.9, 1000.0, 1.2, 2.5, 30.0, 60.0)
    inn = G.sigma_h(190.0, 2.5, 0.9, 1000.0, 1.2, 2.5, 30.0, 60.0, internal=True)
    assert inn / ext == pytest.approx(math.sqrt(1.5 / 3.5), rel=1e-12)


def test_internal_form_factor_is_the_rack_limit_of_the_external_one():
    assert G.y_fs_internal(0.3) == pytest.approx(G.y_fs(1e12, 0.3), rel=1e-9)
