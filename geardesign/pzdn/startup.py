"""Three-mass start-up model of a knitting-machine drive with the driving mass in the
middle (KO-2 thesis §2.2, [Lopukhov] §2.2): closed-form solution with the
thesis' errors corrected.  Pure functions (``math`` only).

Model (all quantities reduced to the motor shaft)::

    2 —C12— 1 —C13— 3         T12 = C12(φ1 − φ2),  T13 = C13(φ1 − φ3)
    J1 φ1'' = T1 − T12 − T13
    J2 φ2'' = T12 − T2   once mass 2 has broken away (T12 >= T2), before: φ2 = 0
    J3 φ3'' = T13 − T3   once mass 3 has broken away (T13 >= T3), before: φ3 = 0

T1 is the motor torque (a step), T2, T3 the resisting moments, no damping.  The start-up
runs in three stages: 1) only mass 1 moves until the first link reaches its resisting
moment; 2) masses 1 and that one move until the other link reaches its moment; 3) all
three move.  In each stage the link torques x = (T12, T13) obey x'' + M·x = f, a 2×2 linear
system solved in modal form x = a + Σ v_i (A_i cos β_i t + B_i sin β_i t) (thesis eqs.
(12)-(27)).  The thesis writes the mode shape as A13 = +(J1/C12)(ω12² − β²)A12; the
correct sign is minus ([Lopukhov] §2.2), which with several arithmetic slips makes
its published T12max = 16.07, T13max = 28.3 N·m unreproducible: the corrected values for
its own data are 12.53 and 35.20 N·m.

The thesis treats only "mass 2 breaks away first"; the general form here also covers mass 3
first (the thesis' text variant C12 = 6.25, C13 = 33.3 N·m/rad) and both at once.
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class ThreeMass:
    """Torques N·m, inertias kg·m², stiffnesses N·m/rad."""

    T1: float
    T2: float
    T3: float
    J1: float
    J2: float
    J3: float
    C12: float
    C13: float


@dataclass
class Stage:
    """One stage: x_k(t) = a_k + Σ_i V_i[k] (A_i cos β_i τ + B_i sin β_i τ), τ = t − t0.

    ``moving`` = (mass 2, mass 3); ``w0`` = speeds (ω1, ω2, ω3) at t0 [rad/s]."""

    t0: float
    moving: tuple[bool, bool]
    a: tuple[float, float]
    beta: tuple[float, ...]
    V: tuple[tuple[float, float], ...]
    A: tuple[float, ...]
    B: tuple[float, ...]
    w0: tuple[float, float, float]
    t1: float = math.inf

    def torques(self, t: float) -> tuple[float, float]:
        tau = t - self.t0
        x = list(self.a)
        for b, v, A, B in zip(self.beta, self.V, self.A, self.B):
            h = A * math.cos(b * tau) + B * math.sin(b * tau)
            x[0] += v[0] * h
            x[1] += v[1] * h
        return x[0], x[1]

    def rates(self, t: float) -> tuple[float, float]:
        tau = t - self.t0
        x = [0.0, 0.0]
        for b, v, A, B in zip(self.beta, self.V, self.A, self.B):
            h = b * (-A * math.sin(b * tau) + B * math.cos(b * tau))
            x[0] += v[0] * h
            x[1] += v[1] * h
        return x[0], x[1]

    def integral(self, t: float) -> tuple[float, float]:
        """∫ x dt from t0 to t."""
        tau = t - self.t0
        x = [self.a[0] * tau, self.a[1] * tau]
        for b, v, A, B in zip(self.beta, self.V, self.A, self.B):
            h = (A * math.sin(b * tau) - B * math.cos(b * tau) + B) / b
            x[0] += v[0] * h
            x[1] += v[1] * h
        return x[0], x[1]

    def speeds(self, m: ThreeMass, t: float) -> tuple[float, float, float]:
        """Angular speeds (ω1, ω2, ω3) [rad/s]: integrals of the equations of motion."""
        tau = t - self.t0
        i12, i13 = self.integral(t)
        w1 = self.w0[0] + (m.T1 * tau - i12 - i13) / m.J1
        w2 = self.w0[1] + (i12 - m.T2 * tau) / m.J2 if self.moving[0] else 0.0
        w3 = self.w0[2] + (i13 - m.T3 * tau) / m.J3 if self.moving[1] else 0.0
        return w1, w2, w3

    def envelope(self) -> tuple[float, float]:
        """Upper bound of each link torque over all time: a_k + Σ |V_ik|·√(A_i² + B_i²)
        (thesis eqs. (26), (27))."""
        return tuple(self.a[k] + sum(abs(v[k]) * math.hypot(A, B)
                                     for v, A, B in zip(self.V, self.A, self.B))
                     for k in (0, 1))

    def amplitudes(self) -> list[tuple[float, float, float, float, float, float]]:
        """Per mode: (A_12, B_12, D_12, A_13, B_13, D_13), D = √(A² + B²) (eq. (26))."""
        out = []
        for v, A, B in zip(self.V, self.A, self.B):
            out.append((v[0] * A, v[0] * B, abs(v[0]) * math.hypot(A, B),
                        v[1] * A, v[1] * B, abs(v[1]) * math.hypot(A, B)))
        return out


def stage_matrix(m: ThreeMass, moving2: bool, moving3: bool):
    """M and f of x'' + M x = f for the link torques x = (T12, T13) with the given masses
    moving (from the equations of motion in the module docstring):

    M = [[C12(1/J1 + μ2/J2), C12/J1], [C13/J1, C13(1/J1 + μ3/J3)]],
    f = [C12(T1/J1 + μ2·T2/J2), C13(T1/J1 + μ3·T3/J3)],  μ = 1 if the mass moves."""
    m2, m3 = float(moving2), float(moving3)
    M = ((m.C12 * (1 / m.J1 + m2 / m.J2), m.C12 / m.J1),
         (m.C13 / m.J1, m.C13 * (1 / m.J1 + m3 / m.J3)))
    f = (m.C12 * (m.T1 / m.J1 + m2 * m.T2 / m.J2), m.C13 * (m.T1 / m.J1 + m3 * m.T3 / m.J3))
    return M, f


def frequencies(M) -> tuple[float, float]:
    """Circular frequencies β1 > β2 [s⁻¹] of x'' + M x = 0: β² the eigenvalues of M.

    For stage 2 (mass 2 moving) this is the thesis' eq. (15),
    β² = {C12(J1+J2) + C13J2 ± √([C12(J1+J2) + C13J2]² − 4C12C13J1J2)}/(2J1J2);
    for stage 3 eq. (23)."""
    tr = M[0][0] + M[1][1]
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    disc = math.sqrt(max(tr * tr - 4.0 * det, 0.0))
    return math.sqrt((tr + disc) / 2.0), math.sqrt(max((tr - disc) / 2.0, 0.0))


def modal_stage(m: ThreeMass, moving: tuple[bool, bool], t0: float, x0, dx0, w0) -> Stage:
    """Stage with at least one of the masses 2, 3 moving, from the link torques x0 and
    their rates dx0 at t0.

    Particular part a = M⁻¹f (thesis eqs. (14), (22)); mode shapes V_i = (1, (β_i² − M11)/M12)
    — the corrected form of the thesis' eq. (18): T13-mode = −(J1/C12)(ω12² − β_i²)·T12-mode,
    ω12² = C12(J1 + J2)/(J1J2); amplitudes from x(t0) and x'(t0) (eqs. (16)-(17), (24)-(25))."""
    M, f = stage_matrix(m, *moving)
    det = M[0][0] * M[1][1] - M[0][1] * M[1][0]
    a = ((M[1][1] * f[0] - M[0][1] * f[1]) / det, (M[0][0] * f[1] - M[1][0] * f[0]) / det)
    b1, b2 = frequencies(M)
    r = [(b * b - M[0][0]) / M[0][1] for b in (b1, b2)]
    u0, u1 = x0[0] - a[0], x0[1] - a[1]
    A1 = (u1 - r[1] * u0) / (r[0] - r[1])
    A2 = (r[0] * u0 - u1) / (r[0] - r[1])
    s0, s1 = dx0
    B1 = (s1 - r[1] * s0) / ((r[0] - r[1]) * b1)
    B2 = (r[0] * s0 - s1) / ((r[0] - r[1]) * b2)
    return Stage(t0, moving, a, (b1, b2), ((1.0, r[0]), (1.0, r[1])), (A1, A2), (B1, B2), w0)


def first_stage(m: ThreeMass) -> Stage:
    """Stage 1, only mass 1 moves: T1j = C1j/(C12 + C13)·T1·(1 − cos Ω0 t),
    Ω0 = √((C12 + C13)/J1) (thesis eqs. (12), (13))."""
    Cs = m.C12 + m.C13
    W0 = math.sqrt(Cs / m.J1)
    a = (m.C12 / Cs * m.T1, m.C13 / Cs * m.T1)
    return Stage(0.0, (False, False), a, (W0,), ((1.0, m.C13 / m.C12),), (-a[0],), (0.0,),
                 (0.0, 0.0, 0.0))


def breakaway_time(T1: float, Tj: float, Cj: float, Cs: float, W0: float) -> float:
    """Time at which the link to mass j reaches its resisting moment in stage 1:
    τ = arccos(1 − Tj·(C12 + C13)/(T1·C1j))/Ω0 (thesis eq. (12)); ∞ if the step torque
    never gets there (argument < −1)."""
    arg = 1.0 - Tj * Cs / (T1 * Cj)
    if arg < -1.0:
        return math.inf
    return math.acos(arg) / W0


@dataclass
class ClosedForm:
    model: ThreeMass
    stages: list[Stage] = field(default_factory=list)
    order: str = ""                 # "2 first", "3 first", "together", "none"
    tau1: float = math.inf          # end of stage 1 (from switch-on)
    tau2: float = math.inf          # duration of stage 2
    t_break: tuple[float, float] = (math.inf, math.inf)   # break-away of masses 2, 3
    reached_stage3: bool = False

    @property
    def stage3(self) -> Stage | None:
        return self.stages[-1] if self.reached_stage3 else None

    def stage_at(self, t: float) -> Stage:
        for s in self.stages:
            if t < s.t1:
                return s
        return self.stages[-1]

    def torques(self, t: float) -> tuple[float, float]:
        return self.stage_at(t).torques(t)

    def speeds(self, t: float) -> tuple[float, float, float]:
        return self.stage_at(t).speeds(self.model, t)

    def peak(self) -> tuple[float, float]:
        """Largest link torques: the stage-3 envelope (thesis eq. (27)) together with the
        maxima reached in stages 1 and 2 (which the thesis leaves out)."""
        out = [-math.inf, -math.inf]
        for s in self.stages[:-1] if self.reached_stage3 else self.stages:
            for k, v in enumerate(_stage_max(s)):
                out[k] = max(out[k], v)
        if self.reached_stage3:
            for k, v in enumerate(self.stages[-1].envelope()):
                out[k] = max(out[k], v)
        return out[0], out[1]


def _stage_max(s: Stage, n: int = 400) -> tuple[float, float]:
    """Largest link torques of a finite stage (sampled, refined by the closed form)."""
    t_end = s.t1 if math.isfinite(s.t1) else s.t0 + 10.0 * 2 * math.pi / min(s.beta)
    best = [-math.inf, -math.inf]
    for j in range(n + 1):
        x = s.torques(s.t0 + (t_end - s.t0) * j / n)
        best = [max(best[0], x[0]), max(best[1], x[1])]
    return best[0], best[1]


def _upward_crossing(fun, t0: float, t_max: float, dt: float) -> float:
    """First t in (t0, t_max] where fun changes from < 0 to >= 0 (scan + bisection)."""
    t, g = t0, fun(t0)
    n = 0
    while t < t_max:
        t_next = min(t + dt, t_max)
        g_next = fun(t_next)
        if g < 0.0 <= g_next:
            lo, hi = t, t_next
            for _ in range(80):
                mid = 0.5 * (lo + hi)
                if fun(mid) < 0.0:
                    lo = mid
                else:
                    hi = mid
            return 0.5 * (lo + hi)
        t, g = t_next, g_next
        n += 1
    return math.inf


def solve(m: ThreeMass, t_max: float) -> ClosedForm:
    """Closed-form start-up (step motor torque, no damping) up to ``t_max`` [s] for the
    search of the second break-away.

    τ1 from eq. (12); initial conditions of stage 2 from eq. (13); τ2 is the first *upward*
    crossing of the other link torque through its resisting moment (the thesis reads it off
    a graph, its Appendix В, and gets 0.2412 s where the first crossing is at 0.00785 s)."""
    cf = ClosedForm(m)
    s1 = first_stage(m)
    cf.stages.append(s1)
    Cs, W0 = m.C12 + m.C13, s1.beta[0]
    t2 = breakaway_time(m.T1, m.T2, m.C12, Cs, W0)
    t3 = breakaway_time(m.T1, m.T3, m.C13, Cs, W0)
    tau1 = min(t2, t3)
    if not math.isfinite(tau1):
        cf.order = "none"
        return cf
    cf.tau1 = tau1
    s1.t1 = tau1
    together = math.isclose(t2, t3, rel_tol=1e-9, abs_tol=1e-12)
    x0, dx0 = s1.torques(tau1), s1.rates(tau1)
    w0 = s1.speeds(m, tau1)
    if together:
        cf.order = "together"
        cf.t_break = (tau1, tau1)
        cf.tau2 = 0.0
        cf.stages.append(modal_stage(m, (True, True), tau1, x0, dx0, w0))
        cf.reached_stage3 = True
        return cf
    first = 0 if t2 < t3 else 1
    cf.order = "2 first" if first == 0 else "3 first"
    moving = (first == 0, first == 1)
    s2 = modal_stage(m, moving, tau1, x0, dx0, w0)
    cf.stages.append(s2)
    other = 1 - first
    T_other = (m.T2, m.T3)[other]
    period = 2.0 * math.pi / s2.beta[0]
    t_cross = _upward_crossing(lambda t: s2.torques(t)[other] - T_other, tau1, t_max,
                               period / 200.0)
    if not math.isfinite(t_cross):
        cf.t_break = (tau1, math.inf) if first == 0 else (math.inf, tau1)
        return cf
    s2.t1 = t_cross
    cf.tau2 = t_cross - tau1
    cf.t_break = (tau1, t_cross) if first == 0 else (t_cross, tau1)
    x0, dx0 = s2.torques(t_cross), s2.rates(t_cross)
    w0 = s2.speeds(m, t_cross)
    cf.stages.append(modal_stage(m, (True, True), t_cross, x0, dx0, w0))
    cf.reached_stage3 = True
    return cf


def steady_parts(m: ThreeMass) -> tuple[float, float]:
    """Stage-3 particular parts (common acceleration ε = (T1 − T2 − T3)/(J1 + J2 + J3)):
    a12 = [J2(T1 − T3) + (J1 + J3)T2]/ΣJ, a13 = [J3(T1 − T2) + (J1 + J2)T3]/ΣJ
    (thesis eq. (22); it prints a12 = 6 with (J1 + J2) for (J1 + J3): 5.746)."""
    Js = m.J1 + m.J2 + m.J3
    return ((m.J2 * (m.T1 - m.T3) + (m.J1 + m.J3) * m.T2) / Js,
            (m.J3 * (m.T1 - m.T2) + (m.J1 + m.J2) * m.T3) / Js)


def sample(cf: ClosedForm, t_end: float, dt: float):
    """Link torques and speeds of the closed form on a grid 0, dt, ..., t_end: lists
    (t, T12, T13, ω1, ω2, ω3)."""
    n = max(int(math.ceil(t_end / dt - 1e-9)), 1)
    out = ([], [], [], [], [], [])
    for j in range(n + 1):
        t = t_end * j / n
        s = cf.stage_at(t)
        x = s.torques(t)
        w = s.speeds(cf.model, t)
        for lst, v in zip(out, (t, x[0], x[1], w[0], w[1], w[2])):
            lst.append(v)
    return out


def series(*C: float) -> float:
    """Stiffness of springs in series, 1/C = Σ 1/C_i (thesis §2.3, from the equality of the
    potential energies, formula 1.226 of its ref. [21])."""
    return 1.0 / sum(1.0 / c for c in C)
