"""The ``[startup]`` table read into a typed, frozen :class:`Startup`: link stiffnesses
(given, or the name of the ``[[spring]]`` that gives them), the motor model, the duration;
every rule across its keys raises a one-line :class:`InputError`."""

from __future__ import annotations

import math
from pathlib import Path

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.pzdn.simulate import Motor
from geardesign.pzdn.spring_inputs import fmt
from geardesign.pzdn.startup import ThreeMass


@dataclass(frozen=True)
class Startup:
    model: ThreeMass             # C12, C13 set once the springs are known (1.0 here)
    spring_C: tuple              # PZDN spring stiffness of each line; None: from a spring
    spring_names: tuple          # the [[spring]] named for each line (None: C given)
    drive_C: tuple | None        # stiffness of the drive alone, each line
    motor: Motor
    t_end: float                 # [s]
    t_end_source: str
    omega_n: float | None        # [rad/s]
    method: str                  # "closed_form", "ode" or "both"
    damping_ratio: float
    stick: bool
    history_points: int
    sweep: tuple[float, ...]     # stiffness factors λ
    plot: str | None

    @property
    def closed_form(self) -> bool:
        return self.method in ("closed_form", "both")

    @property
    def ode(self) -> bool:
        return self.method in ("ode", "both")


def _drop(spec: ValidatedSpec, table: dict, path: str) -> None:
    """Remove an assumed default that the calculation does not use from the echo."""
    key = path.rsplit(".", 1)[-1]
    if path in spec.assumed:
        spec.assumed.remove(path)
        table.pop(key, None)


def _link(st: dict, line: str, names: list) -> float | None:
    num, ref = st[f"C{line}"], st[f"C{line}_spring"]
    if num is None and ref is None:
        raise InputError(Problem(f"startup.C{line}", f"missing; give the link stiffness "
                                 f"C{line} [N·m/rad], or C{line}_spring, the name of the "
                                 f"[[spring]] that gives it"))
    if num is not None and ref is not None:
        raise InputError.at(f"startup.C{line}_spring", ref, f"give C{line} or "
                            f"C{line}_spring, not both")
    if ref is not None and ref not in names:
        known = ", ".join(f'"{n}"' for n in names) or "none: add [[spring]] tables"
        raise InputError.at(f"startup.C{line}_spring", ref,
                            f"no [[spring]] of that name; known: {known}")
    return num


def _links(st: dict, names: list) -> list:
    problems = Problems()
    Cs = [problems.stage(_link, st, line, names) for line in ("12", "13")]
    problems.raise_all()
    return Cs


def _motor(spec: ValidatedSpec, st: dict) -> Motor:
    if st["method"] == "closed_form":
        for k, default in (("rise_time", 0.0), ("damping_ratio", 0.0)):
            if st[k] != default and f"startup.{k}" not in spec.assumed:
                raise InputError.at(f"startup.{k}", st[k], "applies only to the numerical "
                                    "integration: the closed form is for a step torque without "
                                    "damping; use method = \"ode\" or \"both\"")
        if st["motor_model"] != "constant":
            raise InputError.at("startup.motor_model", st["motor_model"],
                                "the closed form needs a constant torque T1; use method = "
                                "\"ode\" or \"both\"")
    mm = st["motor_model"]
    kl = ("kloss_max_torque", "kloss_critical_slip", "synchronous_speed")
    cv = ("curve_speed", "curve_torque")
    for k in kl + cv:
        wanted = "kloss" if k in kl else "curve"
        if st[k] is not None and mm != wanted:
            raise InputError.at(f"startup.{k}", st[k],
                                f"applies only with motor_model = \"{wanted}\"")
    if mm == "kloss":
        for k in kl:
            if st[k] is None:
                raise InputError(Problem(f"startup.{k}", "missing; required with motor_model "
                                         "= \"kloss\" (breakdown torque, critical slip, "
                                         "synchronous speed)"))
        return Motor("kloss", st["T1"], st["rise_time"], st["kloss_max_torque"],
                     st["kloss_critical_slip"], math.pi * st["synchronous_speed"] / 30.0)
    if mm == "curve":
        for k in cv:
            if st[k] is None:
                raise InputError(Problem(f"startup.{k}", "missing; required with motor_model "
                                         "= \"curve\" (speeds and torques of the characteristic)"))
        sp, tq = st["curve_speed"], st["curve_torque"]
        if len(sp) != len(tq):
            raise InputError.at("startup.curve_torque", tq,
                                f"needs one torque per speed: {len(sp)} speeds, {len(tq)} "
                                f"torques")
        if any(b <= a for a, b in zip(sp, sp[1:])):
            raise InputError.at("startup.curve_speed", sp, "the speeds must increase strictly")
        return Motor("curve", st["T1"], st["rise_time"],
                     speeds=tuple(math.pi * n / 30.0 for n in sp), torques=tuple(tq))
    return Motor("constant", st["T1"], st["rise_time"])


def _plot(st: dict) -> None:
    if st["plot"] is not None:
        if Path(st["plot"]).suffix.lower() not in (".png", ".svg"):
            raise InputError.at("startup.plot", st["plot"], "the plot file must end in .png "
                                "or .svg")
        if st["history_points"] < 2:
            raise InputError.at("startup.history_points", st["history_points"],
                                "must be at least 2 to draw startup.plot")


def _duration(st: dict) -> tuple[float, str, float | None]:
    Js = st["J1"] + st["J2"] + st["J3"]
    eps = (st["T1"] - st["T2"] - st["T3"]) / Js
    omega_n = math.pi * st["motor_speed"] / 30.0 if st["motor_speed"] is not None else None
    if st["t_end"] is not None:
        return st["t_end"], "spec", omega_n
    if omega_n is None:
        raise InputError(Problem("startup.t_end", "missing; give the duration t_end [s] or "
                                 "motor_speed (the start-up then lasts until the mean speed "
                                 "reaches it)"))
    if eps <= 0:
        raise InputError.at("startup.T1", st["T1"],
                            f"does not exceed T2 + T3 = {fmt(st['T2'] + st['T3'])} N·m, so the "
                            f"machine never reaches motor_speed; give t_end to compute the "
                            f"stalled start, or a larger T1")
    return omega_n / eps, "ω_n·ΣJ/(T1 − T2 − T3)", omega_n


def _drive(st: dict) -> tuple | None:
    drive = (st["C12_drive"], st["C13_drive"])
    if (drive[0] is None) != (drive[1] is None):
        missing = "C13_drive" if drive[1] is None else "C12_drive"
        raise InputError(Problem(f"startup.{missing}", "missing; give the drive stiffness of "
                                 "both lines (C12_drive and C13_drive) or of neither"))
    return drive if drive[0] is not None else None


def startup(spec: ValidatedSpec, st: dict, names: list) -> Startup:
    """The [startup] table ``st``; ``names``: the names of the [[spring]] tables.  The
    link stiffnesses, the drive alone, the motor, the plot and the duration are checked
    independently (every mistake in one round)."""
    problems = Problems()
    Cs = problems.stage(_links, st, names)
    drive = problems.stage(_drive, st)
    motor = problems.stage(_motor, spec, st)
    problems.stage(_plot, st)
    duration = problems.stage(_duration, st)
    problems.raise_all()
    t_end, src, omega_n = duration
    method = st["method"]
    damping, stick = st.get("damping_ratio", 0.0), st.get("stick", False)
    if method == "closed_form":   # defaults that only the integration uses: not echoed
        for k in ("rise_time", "damping_ratio", "stick", "motor_model"):
            _drop(spec, st, f"startup.{k}")
    model = ThreeMass(st["T1"], st["T2"], st["T3"], st["J1"], st["J2"], st["J3"], 1.0, 1.0)
    return Startup(model, tuple(Cs), (st["C12_spring"], st["C13_spring"]), drive, motor,
                   t_end, src, omega_n, method,
                   damping, stick, st["history_points"], tuple(st["sweep"] or ()), st["plot"])


# ----------------------------------------------------------------------------- models

MAX_PERIODS = 5_000
"""Oscillation periods of the stiffest mode over the start-up that the closed form resolves
(50 samples each): the bound on its time and memory (about 0.2 ms a period)."""
MAX_PERIODS_ODE = 500
"""The same bound for the numerical integration (about 3 ms a period at rtol 1e-12)."""


def link(spring_C: float, drive_C: float | None) -> float:
    """Link stiffness of a line: the PZDN spring in series with the drive, when given
    [N·m/rad] (:func:`geardesign.pzdn.startup.series`)."""
    from geardesign.pzdn.startup import series

    return series(spring_C, drive_C) if drive_C is not None else spring_C


def models(si: Startup, finger_C: dict) -> tuple:
    """The start-up models: with the PZDN, without it (drive alone, or None) and one per
    sweep factor λ.  ``finger_C``: the stiffness at the finger of each named spring
    [N·m/rad]."""
    from dataclasses import replace

    sC = tuple(c if c is not None else finger_C[name]
               for c, name in zip(si.spring_C, si.spring_names))
    drive = si.drive_C or (None, None)
    m = replace(si.model, C12=link(sC[0], drive[0]), C13=link(sC[1], drive[1]))
    m0 = (replace(m, C12=si.drive_C[0], C13=si.drive_C[1]) if si.drive_C is not None
          else None)
    sweep = tuple(replace(m, C12=m.C12 * lam, C13=m.C13 * lam) for lam in si.sweep)
    return sC, m, m0, sweep


def bounded(si: Startup, m: ThreeMass) -> float:
    """The stiffest circular frequency β [1/s] of ``m``; an input error when the start-up
    holds more periods of it than are resolved in bounded time."""
    from geardesign.pzdn import startup as SU

    beta = SU.frequencies(SU.stage_matrix(m, True, True)[0])[0]
    periods = si.t_end * beta / (2.0 * math.pi)
    limit = MAX_PERIODS_ODE if si.ode else MAX_PERIODS
    if not periods <= limit:
        raise InputError(Problem(
            "startup", f"the start-up lasts {fmt(si.t_end)} s and the stiffest mode "
            f"oscillates at {fmt(beta / (2.0 * math.pi))} Hz: {periods:.3g} periods, more than "
            f"the {limit} that are resolved in bounded time"
            + (" by the integration" if si.ode else "") + "; give a shorter startup.t_end "
            "or check J1, J2, J3 [kg*m^2] and the link stiffnesses [N·m/rad]"))
    return beta


def check_bounds(si: Startup, finger_C: dict) -> None:
    """Every model of the start-up (with, without the PZDN, the sweep) in bounded time."""
    _, m, m0, sweep = models(si, finger_C)
    for model in (m, m0, *sweep):
        if model is not None:
            bounded(si, model)
