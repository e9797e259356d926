"""The start-up integration of the pzdn model: the exact solution of the linear model (a
constant motor torque, with its rise) equals scipy's DOP853 on the same model, and the
matrix exponential behind it equals scipy's."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.pzdn.linear import expm
from geardesign.pzdn.simulate import Motor, simulate
from geardesign.pzdn.startup import ThreeMass

KO2 = ThreeMass(26.5, 4.4, 17.7, 0.038, 0.026, 0.021, 8.313035135329345, 24.668508391688757)
"""The KO-2 model of ``specs/pzdn_ko2_startup_comparison.toml`` (thesis §2.2)."""


@settings(max_examples=40, deadline=None)
@given(st.integers(1, 8), st.floats(0.01, 30.0), st.integers(0, 2 ** 32 - 1))
def test_expm_equals_scipy(n, scale, seed):
    from scipy.linalg import expm as scipy_expm

    x = np.random.default_rng(seed).standard_normal((n, n)) * scale / n
    want = scipy_expm(x)
    assert np.allclose(expm(x), want, rtol=1e-12, atol=1e-12 * np.abs(want).max())


def test_expm_of_a_rotation_and_a_stack():
    """exp([[0, θ], [−θ, 0]]) is the rotation by θ; a stack is exponentiated matrix by
    matrix."""
    thetas = np.array([0.0, 0.3, 2.0, 40.0])
    x = np.zeros((4, 2, 2))
    x[:, 0, 1], x[:, 1, 0] = thetas, -thetas
    e = expm(x)
    assert np.allclose(e[:, 0, 0], np.cos(thetas), atol=1e-13)
    assert np.allclose(e[:, 0, 1], np.sin(thetas), atol=1e-13)


def _constant_through_the_curve(motor: Motor) -> Motor:
    """The same constant torque as a flat motor characteristic: integrated by DOP853."""
    return Motor("curve", rise_time=motor.rise_time, speeds=(0.0, 1.0e4),
                 torques=(motor.T1, motor.T1))


def _agree(a, b, rtol):
    assert math.isclose(a.T12_max, b.T12_max, rel_tol=rtol)
    assert math.isclose(a.T13_max, b.T13_max, rel_tol=rtol)
    assert math.isclose(a.t12_max, b.t12_max, rel_tol=rtol, abs_tol=1e-9)
    assert math.isclose(a.t13_max, b.t13_max, rel_tol=rtol, abs_tol=1e-9)
    assert a.sticks == b.sticks
    for x, y in zip(a.t_break, b.t_break):
        assert (x is None) == (y is None) and (x is None or math.isclose(x, y, rel_tol=rtol))
    for x, y in zip(a.final_speeds, b.final_speeds):
        assert math.isclose(x, y, rel_tol=rtol, abs_tol=1e-8)


@pytest.mark.parametrize("rise, zeta, stick", [(0.0, 0.0, False), (0.015, 0.05, True),
                                               (0.2, 0.3, True)])
def test_exact_linear_solution_equals_dop853_on_ko2(rise, zeta, stick):
    motor = Motor("constant", T1=KO2.T1, rise_time=rise)
    exact = simulate(KO2, motor, 0.5, zeta, stick)
    ode = simulate(KO2, _constant_through_the_curve(motor), 0.5, zeta, stick)
    _agree(exact, ode, 1e-8)
    t = np.linspace(0.0, 0.5, 37)
    assert np.allclose(exact.state(t), ode.state(t), rtol=1e-8, atol=1e-8)


@settings(max_examples=6, deadline=None)
@given(st.floats(0.3, 3.0), st.floats(0.2, 5.0), st.floats(0.0, 0.05),
       st.floats(0.0, 0.5), st.booleans())
def test_exact_linear_solution_equals_dop853(stiff, load, rise, zeta, stick):
    """Random stiffness level, resisting moments, torque rise, damping and sticking: the
    events (break-away, stops) and the peaks agree."""
    m = ThreeMass(26.5, 4.4 * load / 2.0, 17.7 * load / 2.0, 0.038, 0.026, 0.021,
                  8.3 * stiff, 24.7 * stiff)
    motor = Motor("constant", T1=m.T1, rise_time=rise)
    exact = simulate(m, motor, 0.4, zeta, stick)
    ode = simulate(m, _constant_through_the_curve(motor), 0.4, zeta, stick)
    _agree(exact, ode, 1e-7)


@settings(max_examples=30, deadline=None)
@given(st.integers(1, 8), st.integers(0, 300), st.integers(1, 70), st.integers(0, 2 ** 32 - 1))
def test_orbit_equals_successive_steps(n, steps, block, seed):
    """The block stepping (:func:`geardesign.pzdn.linear.orbit`) gives the states of n
    successive products e·z to the rounding of the steps, whatever the block length."""
    from geardesign.pzdn.linear import orbit

    rng = np.random.default_rng(seed)
    e = expm(rng.standard_normal((n, n)) * 0.3 / n)
    z = rng.standard_normal(n)
    got = orbit(e, z, steps, block)
    assert got.shape == (steps, n)
    want, s = [], z
    for _ in range(steps):
        s = e @ s
        want.append(s)
    if steps:
        scale = np.abs(np.array(want)).max(axis=1, keepdims=True)
        assert np.all(np.abs(got - np.array(want)) <= 1e-11 * np.maximum(scale, 1e-300))


@pytest.mark.parametrize("rise, zeta, stick", [(0.0, 0.0, False), (0.015, 0.05, True),
                                               (0.2, 0.3, True)])
def test_events_do_not_depend_on_how_the_steps_are_grouped(monkeypatch, rise, zeta, stick):
    """The steps of the exact path are tested for events a chunk at a time: a chunk of 3
    steps (events found across chunk ends) gives the events and peaks of the default."""
    import geardesign.pzdn.linear as linear

    motor = Motor("constant", T1=KO2.T1, rise_time=rise)
    whole = simulate(KO2, motor, 0.5, zeta, stick)
    monkeypatch.setattr(linear, "_CHUNK", 3)
    small = simulate(KO2, motor, 0.5, zeta, stick)
    _agree(whole, small, 1e-12)


@settings(max_examples=10, deadline=None)
@given(st.floats(0.3, 3.0), st.floats(0.0, 0.3), st.integers(8, 400), st.booleans())
def test_the_exact_solution_on_a_grid_is_the_exponential_at_each_time(stiff, zeta, n, ragged):
    """A segment's solution at the times of a uniform grid (stepped by one exponential)
    and at irregular times (one exponential per spacing) equals exp(Ã(t − t0))·z0 at each
    time."""
    from geardesign.pzdn.linear import _Exact, linear_system

    m = ThreeMass(26.5, 4.4, 17.7, 0.038, 0.026, 0.021, 8.3 * stiff, 24.7 * stiff)
    a = linear_system(m, (zeta, zeta), (True, True), (m.T1, 0.0))
    z0 = np.array([0.0, 1.0, 0.0, 0.5, 0.0, 0.2, 0.01, 1.0])
    t = np.linspace(0.02, 0.3, n)
    if ragged:
        t = t + np.random.default_rng(n).uniform(0.0, 1e-4, n)
    got = _Exact(a, 0.01, z0)(t)
    want = np.array([(expm(a * (x - 0.01)) @ z0)[:6] for x in t]).T
    assert np.allclose(got, want, rtol=1e-10, atol=1e-10 * np.abs(want).max())
