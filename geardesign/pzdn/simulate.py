"""Numerical integration of the three-mass start-up model (``startup`` module docstring)
with what the closed form leaves out: a motor torque that rises over a time or follows a
motor characteristic, viscous damping in the links, and resisting moments that are
reactive (a mass that comes to rest sticks until its link torque exceeds the resisting
moment again).

The equations are those of the thesis' model ([Lopukhov] §2.2):

    J1 ω1' = T_m(t, ω1) − T12 − T13
    J2 ω2' = T12 − T2  (moving),   T12 = C12(φ1 − φ2) + c12(ω1 − ω2)
    J3 ω3' = T13 − T3  (moving),   T13 = C13(φ1 − φ3) + c13(ω1 − ω3)

with the damping coefficient of a link c_1j = 2ζ·√(C_1j·J1·Jj/(J1 + Jj)) (ζ the damping
ratio of the link's own two-mass oscillator).  Integrated piecewise between events
(break-away, sticking, end of the torque rise); maxima are taken on a fine grid of the
solution and refined by a parabola through the three samples around the largest one.

Two integrators, one event logic (:func:`simulate`):

* a constant motor torque (with or without its linear rise) leaves the model linear between
  events, ẏ = A·y + b₀ + b₁·t, whose exact solution is the matrix exponential of the
  augmented system (:mod:`geardesign.pzdn.linear`): no step-size error, numpy only, a few
  hundredths of a second for a whole comparison with its stiffness sweep;
* a motor characteristic (Kloss, curve) makes it non-linear: the DOP853 Runge-Kutta method
  of scipy (rtol 1e-12, so that the results do not depend on the step sequence beyond
  ~1e-10) with dense output, scipy imported only then (about 1 s).

The exact path finds the events as scipy does: a sign change of the event function between
two steps in the direction asked for (steps of 1/32 of the shortest period here), the
earliest one refined to ~4 ulp.  The model is linear and the exponential exact, so the
choice costs no precision (the tests compare both paths on the same model).
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.pzdn.linear import exact_segment, link_row, linear_system
from geardesign.pzdn.startup import ThreeMass


@dataclass(frozen=True)
class Motor:
    """Motor torque T_m(t, ω1) [N·m] on the (reduced) motor shaft.

    ``model``: ``"constant"`` (T1), ``"kloss"`` (T_k, s_k, ω_0) or ``"curve"`` (speeds
    [rad/s] and torques [N·m], linear between points, constant beyond the ends).  Each is
    multiplied by min(t/t_r, 1) when a rise time t_r > 0 is given."""

    model: str = "constant"
    T1: float = 0.0
    rise_time: float = 0.0
    T_k: float = 0.0
    s_k: float = 0.0
    omega0: float = 0.0
    speeds: tuple = ()
    torques: tuple = ()

    def static(self, w: float) -> float:
        if self.model == "kloss":
            return kloss(w, self.T_k, self.s_k, self.omega0)
        if self.model == "curve":
            return curve(w, self.speeds, self.torques)
        return self.T1

    def torque(self, t: float, w: float) -> float:
        ramp = 1.0 if self.rise_time <= 0.0 or t >= self.rise_time else t / self.rise_time
        return ramp * self.static(w)


def kloss(w: float, T_k: float, s_k: float, omega0: float) -> float:
    """Static characteristic of an induction motor, the Kloss formula
    T = 2·T_k/(s/s_k + s_k/s), s = 1 − ω/ω0 (T_k the breakdown torque, s_k the critical
    slip; standard electric-drive textbooks, e.g. Chilikin, *Electric drive*; from memory).
    T = 0 at synchronous speed."""
    s = 1.0 - w / omega0
    if abs(s) < 1e-12:
        return 0.0
    return 2.0 * T_k / (s / s_k + s_k / s)


def curve(w: float, speeds: tuple, torques: tuple) -> float:
    """Piecewise-linear motor characteristic T(ω), constant beyond its ends."""
    if w <= speeds[0]:
        return torques[0]
    for j in range(1, len(speeds)):
        if w <= speeds[j]:
            f = (w - speeds[j - 1]) / (speeds[j] - speeds[j - 1])
            return torques[j - 1] + f * (torques[j] - torques[j - 1])
    return torques[-1]


def damping(C: float, J1: float, Jj: float, zeta: float) -> float:
    """Damping coefficient of a link c = 2ζ·√(C·J1Jj/(J1 + Jj)) [N·m·s/rad] (viscous damper
    in parallel with the spring; ζ relative to the link's two-mass oscillator)."""
    return 2.0 * zeta * math.sqrt(C * J1 * Jj / (J1 + Jj))


@dataclass
class Simulation:
    T12_max: float
    T13_max: float
    t12_max: float
    t13_max: float
    t_break: list                     # first break-away of masses 2, 3 [s] (None: never)
    sticks: list                      # number of times masses 2, 3 came to rest again
    w_min: list                       # lowest speeds of masses 2, 3 after break-away
    final_speeds: tuple
    segments: list = field(default_factory=list)   # (t0, t1, dense solution)
    exact: bool = False               # the linear model's exact solution (else DOP853)

    def state(self, t):
        """State vectors (φ1, ω1, φ2, ω2, φ3, ω3) at the times ``t`` (array)."""
        import numpy as np

        t = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.empty((6, t.size))
        for j, (t0, t1, sol) in enumerate(self.segments):
            last = j == len(self.segments) - 1
            mask = (t >= t0) & ((t < t1) | (last & (t <= t1 + 1e-12)))
            if mask.any():
                out[:, mask] = sol(np.clip(t[mask], t0, t1))
        return out


# ----------------------------------------------------------------- the simulation


def simulate(m: ThreeMass, motor: Motor, t_end: float, zeta: float = 0.0, stick: bool = True,
             grid_step: float | None = None) -> Simulation:
    """Integrate the start-up from rest over 0 … t_end [s].

    ``m.T1`` is not used (the motor gives the torque); ``grid_step`` is the spacing of the
    samples on which the maxima are searched (default: 1/50 of the shortest period of the
    stage-3 modes, at most t_end/2000).  A constant motor torque (rising linearly over
    ``motor.rise_time`` or not) is integrated exactly (:func:`linear_system`), in steps of
    1/32 of that period in which the events are detected; a motor characteristic by
    scipy's DOP853 (module docstring)."""
    import numpy as np

    from geardesign.pzdn.startup import frequencies, stage_matrix

    c12 = damping(m.C12, m.J1, m.J2, zeta)
    c13 = damping(m.C13, m.J1, m.J3, zeta)
    beta_max = frequencies(stage_matrix(m, True, True)[0])[0]
    period = 2.0 * math.pi / beta_max
    if grid_step is None:
        grid_step = min(period / 50.0, t_end / 2000.0)
    linear = motor.model == "constant"

    def links(y):
        T12 = m.C12 * (y[0] - y[2]) + c12 * (y[1] - y[3])
        T13 = m.C13 * (y[0] - y[4]) + c13 * (y[1] - y[5])
        return T12, T13

    moving = [False, False]

    def rhs(t, y):
        T12, T13 = links(y)
        dy = np.zeros(6)
        dy[0] = y[1]
        dy[1] = (motor.torque(t, y[1]) - T12 - T13) / m.J1
        if moving[0]:
            dy[2] = y[3]
            dy[3] = (T12 - m.T2) / m.J2
        if moving[1]:
            dy[4] = y[5]
            dy[5] = (T13 - m.T3) / m.J3
        return dy

    def event_rows():
        """(row over z, direction, kind, j): break-away of a mass at rest (its link torque
        rises through its resisting moment), stop of a moving one (its speed falls through
        0) when masses stick."""
        out = []
        for j, (C, cj, T) in enumerate(((m.C12, c12, m.T2), (m.C13, c13, m.T3))):
            if not moving[j]:
                row = link_row(C, cj, j)
                row[7] = -T
                out.append((row, 1.0, "break", j))
            elif stick:
                row = np.zeros(8)
                row[3 + 2 * j] = 1.0
                out.append((row, -1.0, "stop", j))
        return out

    def ode_segment(t, t_stop, y, events):
        from scipy.integrate import solve_ivp

        def ev(row, direction):
            def g(t, y):
                return float(row[:6] @ y + row[6] * t + row[7])
            g.terminal, g.direction = True, direction
            return g

        sol = solve_ivp(rhs, (t, t_stop), y, method="DOP853", rtol=1e-12, atol=1e-14,
                        dense_output=True, events=[ev(r, d) for r, d, _, _ in events] or None,
                        max_step=period / 4.0)
        fired = None
        if sol.status == 1:
            fired = next(i for i, te in enumerate(sol.t_events) if len(te))
        return float(sol.t[-1]), sol.y[:, -1].copy(), fired, sol.sol

    def torque_line(t):
        """T_m = T1·min(t/t_r, 1) on the segment that starts at t: (constant, slope)."""
        if 0.0 < motor.rise_time and t < motor.rise_time - 1e-12:
            return 0.0, motor.T1 / motor.rise_time
        return motor.T1, 0.0

    y = np.zeros(6)
    t = 0.0
    sim = Simulation(-math.inf, -math.inf, 0.0, 0.0, [None, None], [0, 0],
                     [math.inf, math.inf], (), exact=linear)
    breaks = [motor.rise_time] if 0.0 < motor.rise_time < t_end else []  # kink of the ramp
    guard = 0
    while t < t_end - 1e-12 and guard < 10000:
        guard += 1
        events = event_rows()
        t_stop = min([b for b in breaks if b > t + 1e-12] + [t_end])
        if linear:
            a = linear_system(m, (c12, c13), moving, torque_line(t))
            t_new, z, fired, sol = exact_segment(
                a, t, t_stop, np.concatenate((y, [t, 1.0])),
                [(r, d) for r, d, _, _ in events], period / 32.0)
            y_new = z[:6].copy()
        else:
            t_new, y_new, fired, sol = ode_segment(t, t_stop, y, events)
        if t_new > t:
            sim.segments.append((t, t_new, sol))
        y = y_new
        if fired is not None:
            _, _, kind, j = events[fired]
            if kind == "break":
                moving[j] = True
                if sim.t_break[j] is None:
                    sim.t_break[j] = t_new
            else:
                y[3 + 2 * j] = 0.0
                if links(y)[j] < (m.T2, m.T3)[j]:
                    moving[j] = False
                    sim.sticks[j] += 1
        t = t_new

    # maxima on a fine grid of the dense output, refined by a parabola
    n = max(int(math.ceil(t_end / grid_step)), 2)
    ts = np.linspace(0.0, t_end, n + 1)
    ys = sim.state(ts)
    T12 = m.C12 * (ys[0] - ys[2]) + c12 * (ys[1] - ys[3])
    T13 = m.C13 * (ys[0] - ys[4]) + c13 * (ys[1] - ys[5])
    for k, series in enumerate((T12, T13)):
        i = int(np.argmax(series))
        value, when = float(series[i]), float(ts[i])
        if 0 < i < n:
            y0, y1, y2 = series[i - 1], series[i], series[i + 1]
            den = y0 - 2.0 * y1 + y2
            if den < 0.0:
                off = 0.5 * (y0 - y2) / den
                value = float(y1 - 0.25 * (y0 - y2) * off)
                when = float(ts[i] + off * (ts[1] - ts[0]))
        if k == 0:
            sim.T12_max, sim.t12_max = value, when
        else:
            sim.T13_max, sim.t13_max = value, when
    for j in (0, 1):
        if sim.t_break[j] is not None:
            after = ts >= sim.t_break[j]
            sim.w_min[j] = float(np.min(ys[3 + 2 * j][after])) if after.any() else 0.0
    sim.final_speeds = (float(y[1]), float(y[3]), float(y[5]))
    sim.c = (c12, c13)
    return sim


def histories(sim: Simulation, m: ThreeMass, points: int, t_end: float):
    """(t, T12, T13, ω1, ω2, ω3) lists at ``points`` equally spaced times."""
    import numpy as np

    ts = np.linspace(0.0, t_end, points)
    ys = sim.state(ts)
    c12, c13 = sim.c
    T12 = m.C12 * (ys[0] - ys[2]) + c12 * (ys[1] - ys[3])
    T13 = m.C13 * (ys[0] - ys[4]) + c13 * (ys[1] - ys[5])
    return tuple([float(v) for v in arr] for arr in (ts, T12, T13, ys[1], ys[3], ys[5]))
