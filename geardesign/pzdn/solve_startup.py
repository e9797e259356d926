"""The three-mass start-up solved: closed form and/or numerical integration of the model
with the PZDN, the drive alone for the comparison, and the stiffness sweep
(:mod:`.startup`, :mod:`.simulate`).  Pure; the inputs are bounded in work by
:func:`geardesign.pzdn.startup_inputs.check_bounds`."""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.pzdn.startup import ThreeMass
from geardesign.pzdn.startup_inputs import Startup, models


@dataclass(frozen=True)
class ClosedFormResult:
    """The closed form of the model with the PZDN and what the report shows of it."""

    cf: object                   # startup.ClosedForm
    peak: tuple[float, float]    # envelope peaks T12max, T13max [N·m]
    stage2_start: tuple | None   # (T12, T13), (T12', T13') at the start of stage 2
    amplitudes2: tuple | None    # mode amplitudes of stage 2 (startup.Stage.amplitudes)
    amplitudes3: tuple | None    # of stage 3
    T12max_t: float              # largest T12 within t_end [N·m]
    T13max_t: float
    omega_min: tuple[float, float]   # lowest speeds of masses 2, 3 [rad/s]


@dataclass(frozen=True)
class StartupResult:
    model: ThreeMass             # with the link stiffnesses used
    spring_C: tuple[float, float]    # PZDN spring stiffness of each line [N·m/rad]
    beta3: tuple[float, float]   # natural circular frequencies, all masses moving [1/s]
    beta2: tuple[float, float]   # mass 3 at rest
    closed_form: ClosedFormResult | None
    sim: object | None           # simulate.Simulation
    history: tuple | None        # (t, T12, T13, ω1, ω2, ω3), each a list
    peaks: tuple[float, float]   # of the method used for the comparison and the sweep
    without: tuple[float, float] | None   # peaks of the drive alone
    sweep: tuple[tuple[float, float], ...]


def _closed_form(m: ThreeMass, t_end: float, beta: float) -> ClosedFormResult:
    from geardesign.pzdn import startup as SU

    cf = SU.solve(m, t_end)
    grid = SU.sample(cf, t_end, min(2.0 * math.pi / beta / 50.0, t_end / 2000.0))
    start = amp2 = amp3 = None
    if cf.order in ("2 first", "3 first"):
        s2 = cf.stages[1]
        start = (s2.torques(cf.tau1), s2.rates(cf.tau1))
        amp2 = tuple(s2.amplitudes())
    if cf.reached_stage3:
        amp3 = tuple(cf.stages[-1].amplitudes())
    return ClosedFormResult(cf, cf.peak(), start, amp2, amp3, max(grid[1]), max(grid[2]),
                            (min(grid[4]), min(grid[5])))


def _simulate(m: ThreeMass, si: Startup):
    from geardesign.pzdn.simulate import simulate

    return simulate(m, si.motor, si.t_end, si.damping_ratio, si.stick)


def _peaks(m: ThreeMass, si: Startup) -> tuple[float, float]:
    """Peak link torques by the integration when it is asked for, else the closed form."""
    from geardesign.pzdn import startup as SU

    if si.ode:
        sim = _simulate(m, si)
        return sim.T12_max, sim.T13_max
    return SU.solve(m, si.t_end).peak()


def solve_startup(si: Startup, finger_C: dict) -> StartupResult:
    """The start-up of ``si``; ``finger_C``: the stiffness at the finger of each named
    spring [N·m/rad]."""
    from geardesign.pzdn import startup as SU

    sC, m, m0, sweep = models(si, finger_C)
    b3 = SU.frequencies(SU.stage_matrix(m, True, True)[0])
    b2 = SU.frequencies(SU.stage_matrix(m, True, False)[0])
    cf = _closed_form(m, si.t_end, b3[0]) if si.closed_form else None
    sim = _simulate(m, si) if si.ode else None
    history = None
    if si.history_points > 0:
        npts = si.history_points
        if sim is not None:
            from geardesign.pzdn.simulate import histories

            history = histories(sim, m, npts, si.t_end)
        else:
            history = SU.sample(cf.cf, si.t_end, si.t_end / max(npts - 1, 1))
        history = tuple(list(h) for h in history)
    base = (sim.T12_max, sim.T13_max) if sim is not None else cf.peak
    return StartupResult(
        m, sC, tuple(b3), tuple(b2), cf, sim, history, base,
        _peaks(m0, si) if m0 is not None else None,
        tuple(_peaks(x, si) for x in sweep))
