"""Dimension over balls/pins, chordal thickness and span checked against the geometry they
measure, solved numerically here from the definition of the involute (not from the closed
forms of :mod:`geardesign.spur.measurement`):

* a ball of diameter D in a tooth space is the circle (spur) or sphere (helical) whose
  centre on the space's centre line is at distance D/2 from both flanks; the flank is the
  involute θ(r) = s/d + inv α_t − inv α_r (external tooth, half angle) or the space
  η(r) = e/d + inv α_t − inv α_r of an internal gear; helical flanks are that involute
  turned by the helix, 2·w·tan β / d per axial length w.  The distance is minimised over
  the flank with scipy; tolerance 1e-6 mm.
* chordal thickness: the straight distance between the points where the reference circle
  cuts the two flanks; chordal height from the tip circle to that chord.
* span: W = (k − 1)·p_bn + s_bn, the normal base pitches plus the base tooth thickness
  s_bn = m_n cos α_n (π/2 + 2x tan α_n + z inv α_t)·… written from the base circle.

Published values could not be consulted for M_d; these checks fix the geometry instead.
"""

import math

import numpy as np
import pytest
from scipy.optimize import brentq, minimize, minimize_scalar

from geardesign.spur.measurement import Tooth, chordal, ideal_ball, over_balls

A20 = math.radians(20.0)


def _inv(a):
    return math.tan(a) - a


def _flank_half_angle(r, r_b, psi0):
    return psi0 - _inv(math.acos(min(r_b / r, 1.0)))


def _ball_M_numeric(z, m_n, alpha_n, beta, s_n, D, internal=False):
    alpha_t = math.atan(math.tan(alpha_n) / math.cos(beta))
    d = z * m_n / math.cos(beta)
    r_b = 0.5 * d * math.cos(alpha_t)
    psi0 = (s_n / math.cos(beta)) / d + _inv(alpha_t)    # transverse thickness / d
    centre_angle = 0.0 if internal else math.pi / z      # space centre line
    sign = 1.0

    def flank_point(r, w=0.0):
        # external: the flank of the tooth at angle 0 facing the space at +π/z;
        # internal: the flank bounding the space centred at 0 (half angle η(r))
        th = _flank_half_angle(r, r_b, psi0) * sign
        th += 2.0 * w * math.tan(beta) / d
        return np.array([r * math.cos(th), r * math.sin(th), w])

    def dist(R):
        c = np.array([R * math.cos(centre_angle), R * math.sin(centre_angle), 0.0])
        if beta == 0.0:
            res = minimize_scalar(lambda r: np.linalg.norm(flank_point(r) - c),
                                  bounds=(r_b, 2.0 * r_b), method="bounded",
                                  options={"xatol": 1e-12})
            return res.fun
        res = minimize(lambda v: np.linalg.norm(flank_point(v[0], v[1]) - c),
                       x0=[R, 0.0], method="Nelder-Mead",
                       options={"xatol": 1e-12, "fatol": 1e-13, "maxiter": 20000})
        return res.fun

    if internal:
        # the space of an internal gear has the shape of an external tooth: the ball lies
        # inside it, between the two flanks ±η(r)
        R = brentq(lambda R: dist(R) - 0.5 * D, r_b * 1.0001, 0.5 * d + m_n)
        chord = 1.0 if z % 2 == 0 else math.cos(0.5 * math.pi / z)
        return 2.0 * R * chord - D
    R = brentq(lambda R: dist(R) - 0.5 * D, r_b, d)
    chord = 1.0 if z % 2 == 0 else math.cos(0.5 * math.pi / z)
    return 2.0 * R * chord + D


@pytest.mark.parametrize("z, x, D", [(20, 0.0, 1.7), (21, 0.0, 1.7), (12, 0.5, 1.8),
                                     (57, -0.3, 1.65)])
def test_over_pins_spur_external(z, x, D):
    s_n = math.pi / 2 + 2 * x * math.tan(A20)
    t = Tooth(z, 1.0, A20, 0.0, s_n, z + 2 + 2 * x, z - 2.5)
    assert over_balls(t, D).M == pytest.approx(_ball_M_numeric(z, 1.0, A20, 0.0, s_n, D),
                                               abs=1e-6)


@pytest.mark.parametrize("z, e_n, D", [(40, math.pi / 2, 1.5), (41, math.pi / 2, 1.5),
                                       (60, math.pi / 2 + 0.2, 1.44)])
def test_between_pins_internal(z, e_n, D):
    t = Tooth(z, 1.0, A20, 0.0, e_n, z - 2, z + 2.5, internal=True)
    assert over_balls(t, D).M == pytest.approx(
        _ball_M_numeric(z, 1.0, A20, 0.0, e_n, D, internal=True), abs=1e-6)


@pytest.mark.parametrize("z, beta, D", [(20, 15.0, 1.7), (31, 30.0, 1.75)])
def test_over_balls_helical(z, beta, D):
    b = math.radians(beta)
    s_n = math.pi / 2
    t = Tooth(z, 1.0, A20, b, s_n, z / math.cos(b) + 2, z / math.cos(b) - 2.5)
    assert over_balls(t, D).M == pytest.approx(_ball_M_numeric(z, 1.0, A20, b, s_n, D),
                                               abs=2e-6)


def test_chosen_ball_touches_near_the_shifted_reference_circle():
    t = Tooth(30, 2.0, A20, 0.0, 2.0 * (math.pi / 2 + 0.4 * math.tan(A20)), 65.6, 57.0)
    D = ideal_ball(t, step=1e-9)
    assert over_balls(t, D).d_c == pytest.approx(60.0 + 2 * 0.2 * 2.0, abs=1e-6)


@pytest.mark.parametrize("z, x", [(12, 0.3), (25, 0.0), (80, -0.2)])
def test_chordal_thickness_and_height_spur(z, x):
    m = 3.0
    d, d_a = z * m, z * m + 2 * (1 + x) * m
    s = m * (math.pi / 2 + 2 * x * math.tan(A20))
    # flank points on the reference circle: polar angles ±s/d around the tooth centre (+y)
    half = s / d
    p1 = 0.5 * d * np.array([math.sin(half), math.cos(half)])
    p2 = 0.5 * d * np.array([-math.sin(half), math.cos(half)])
    chord = float(np.linalg.norm(p1 - p2))
    height = 0.5 * d_a - p1[1]
    c = chordal(Tooth(z, m, A20, 0.0, s, d_a, d - 2.5 * m))
    assert c.s_c == pytest.approx(chord, abs=1e-9)
    assert c.h_c == pytest.approx(height, abs=1e-9)
