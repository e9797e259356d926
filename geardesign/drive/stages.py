"""Drive stages: how each calculator is run as a stage of a drive.

A stage adapter puts the stage's input torque and speed (and the drive's life, regime,
application factor and peak torque, where the stage spec does not give its own) into the
stage spec, reads it into the calculator's typed inputs (validated once per run:
:func:`read_stage`, :mod:`.reuse`), solves it once per pass (the calculator's ``solve``:
:mod:`geardesign.spur.solve`, :mod:`geardesign.worm.solve`, :mod:`geardesign.novikov.solve`,
:mod:`geardesign.planetary.solve`) and reads from the typed record the ratio, the
efficiency, the output torque and speed, the mesh forces on the input and output members
(for the shafts) and the worst safety margin.  The stage's report (with the advice of its
failed checks) is written only when the drive's report asks for it, from the last pass
(:func:`finish`).  No formula of a calculator is repeated here.  The adapters by kind are
the table ``ADAPTERS`` of :mod:`.calculator`: a new stage kind is one adapter there.
"""

from __future__ import annotations

import copy
from dataclasses import field
from typing import Any, Callable

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.registry import load_data
from geardesign.core.result import Result
from geardesign.drive.shafts import GearLoad

#: Efficiency of a closed cylindrical (spur, helical, Novikov) stage when the spec gives
#: none, without bearing losses: handbook 0.97–0.98 (Dunaev & Lelikov, table 1.1; verify).
ETA_CYLINDRICAL = 0.98

WORM_LOADS = NOVIKOV_LOADS = ("load.torque2", "load.speed1")
"""The loads the drive sets on a worm or a Novikov stage."""
PLANETARY_LOADS = ("operation.speed", "operation.torque", "strength.peak_torque")
"""The loads the drive sets on a planetary stage."""


@dataclass(frozen=True)
class Duty:
    L_h: float
    regime: str
    K_A: float
    peak_ratio: float | None
    method: str | None = None      # strength method of the stages that give none
    memo: dict = field(default_factory=dict, compare=False, hash=False, repr=False)
    """The run's store of validated stage and bearing specs (:mod:`.reuse`)."""


@dataclass(frozen=True)
class Member:
    """Mesh forces on a stage's input or output member (N) at radius r (mm)."""

    F_t: float
    F_r: float
    F_a: float
    r: float


@dataclass
class StageRun:
    """A stage computed in one pass.  ``record``: the typed record of a spur stage
    (:class:`geardesign.spur.solve.Record`); ``result``: the stage's report, written on
    first use (``make_report``) or given (the other calculators)."""

    kind: str
    ratio: float
    efficiency: float
    efficiency_source: str
    T_in: float
    n_in: float
    T_out: float
    n_out: float
    members: tuple[Member, Member]
    margin: float | None
    margin_of: str
    reverses: bool                 # output turns opposite to the input (external mesh)
    record: Any = None
    make_report: Callable[[], Result] | None = field(default=None, repr=False)
    given: Result | None = field(default=None, repr=False)
    spec: Any = field(default=None, repr=False)    # the stage's validated spec
    geometry: Any = field(default=None, repr=False)
    """The pair's geometry (:class:`geardesign.gears.geometry.PairGeometry`) of a
    cylindrical stage, its ``inp`` the pair's input (the loss model's mesh)."""

    @property
    def result(self) -> Result:
        if self.given is None:
            self.given = self.make_report()
        return self.given

    @result.setter
    def result(self, res: Result) -> None:
        self.given = res

    @property
    def inputs(self) -> dict:
        """The stage's validated spec data (what its report echoes)."""
        if self.spec is not None:
            return self.spec.data
        if self.record is not None:
            return self.record.inputs.spec.data
        return self.result.inputs

    def gear_load(self, which: int, z: float, mate_angle: float, axial_sign: int) -> GearLoad:
        m = self.members[which]
        return GearLoad(m.F_t, m.F_r, m.F_a, m.r, z, mate_angle, driving=(which == 0),
                        axial_sign=axial_sign)


def sections(res: Result) -> dict:
    """The report sections of a result as its JSON document has them, ``{section: {key:
    value}}`` (values cleaned as there), without writing the whole document."""
    from geardesign.core.result import clean_value

    out: dict = {}
    for sec in res.sections:
        block = out.setdefault(sec.key, {})
        for row in sec.rows:
            block[row.key] = clean_value(row.value)
    return out


def values(res: Result) -> dict:
    """Every row of a result's sections by key (a later section's row wins), as read from
    its JSON document."""
    out = {}
    for block in sections(res).values():
        out.update(block)
    return out


def _margins(section: dict, prefix: str = "") -> dict:
    """Safety margins S/S_min of one rating section: GOST 21354-87 rows give each gear's
    S_min (``S_H1_min``), ISO 6336 rows one for the pair (``S_Hmin``)."""
    out = {}
    for k in ("S_H1", "S_H2", "S_F1", "S_F2"):
        need = section.get(f"{k}_min", section.get(f"{k[:3]}min"))
        if section.get(k) is not None and need:
            out[prefix + k] = section[k] / need
    return out


def _named(exc: InputError, where: str) -> InputError:
    return InputError([Problem(f"{where}: {p.key}" if p.key else where, p.message, p.value)
                       for p in exc.problems])


_SET_BY_DRIVE = {
    "spur": ("load", ("torque1", "speed1")), "novikov": ("load", ("torque2", "speed1")),
    "worm": ("load", ("torque2", "speed1")), "planetary": ("operation", ("torque", "speed")),
    "bevel": ("load", ("torque", "speed")),
}
"""The loads a drive always sets on a stage (its own values are not used)."""


def _set_by_drive(res: Result, data: dict, original: dict | None) -> None:
    """The info check of a stage report that says which of its loads the drive set
    (``data``: the stage spec with the drive's loads, ``original`` as written)."""
    kind = data.get("kind")
    if kind in _SET_BY_DRIVE:
        from geardesign.core.result import check

        table, keys = _SET_BY_DRIVE[kind]
        own = (original or {}).get(table)
        own = own if isinstance(own, dict) else {}
        set_ = ", ".join(f"{table}.{k} = {data[table][k]:.6g}" for k in keys
                         if data[table].get(k) is not None)
        replaced = [f"{table}.{k}" for k in keys if own.get(k) is not None]
        res.checks.append(check(
            "SET_BY_DRIVE", False, "info",
            f"the drive sets {set_} from the motor and the stages before"
            + (f" (the stage's own {', '.join(replaced)} not used)" if replaced else "")
            + "; life, application factor and peak torque come from the drive where the "
              "stage gives none", "", None, None, "drive"))


def _table(d: dict, key: str, where: str) -> dict:
    """The stage's table ``key`` (created when absent), refused when it is not a table:
    the drive fills in loads before the stage's own calculator validates it."""
    value = d.setdefault(key, {})
    if not isinstance(value, dict):
        raise InputError.at(f"{where}: {key}", value, f"must be a table [{key}]")
    return value


def _ratio(d: dict, where: str, kind: str) -> float:
    """z2/z1 of a worm or Novikov stage, read before the stage's own calculator validates
    the spec (the drive needs the ratio to set the stage's load): the tooth numbers must be
    positive whole numbers here already."""
    gear = d.get("gear")
    if gear is None:
        gear = {}
    if not isinstance(gear, dict):
        raise InputError.at(f"{where}: gear", gear, "must be a table [gear]")
    for key in ("z1", "z2"):
        if key not in gear:
            raise InputError(Problem(f"{where}: gear.{key}", f"missing; the drive needs the "
                                     f"tooth numbers of the {kind} stage"))
        z = gear[key]
        if isinstance(z, bool) or not isinstance(z, int) or not 1 <= z <= 1000:
            raise InputError.at(f"{where}: gear.{key}", z, "must be an integer >= 1 and "
                                "<= 1000")
    return gear["z2"] / gear["z1"]


def _put(table: dict, key: str, value) -> None:
    if table.get(key) is None and value is not None:
        table[key] = value


def read_stage(kind: str, d: dict, where: str, duty: Duty, paths: tuple[str, ...],
               read: Callable):
    """``(validated spec, typed inputs)`` of the stage spec ``d`` (``read``: the
    calculator's reader, spec → inputs): validated once per run, a later pass whose spec
    differs only in the loads the drive set (``paths``, ``"table.key"``) reusing it
    (:mod:`.reuse`); problems name the stage."""
    from geardesign.core.registry import _say_default, get
    from geardesign.drive import reuse

    key = reuse.fingerprint(kind, where, d, paths)
    spec = None
    if key in duty.memo:
        spec = reuse.reloaded(get(kind).schema, duty.memo[key], d, paths)
    fresh = spec is None
    if fresh:
        try:
            _, spec = load_data(d, where)
        except InputError as exc:
            raise _named(exc, where) from None
    try:
        inputs = read(spec)
    except InputError as exc:
        raise _named(InputError([_say_default(p, spec) for p in exc.problems]), where) \
            from None
    if fresh:
        duty.memo[key] = spec
    return spec, inputs


def solved(solve: Callable, inputs, spec, where: str):
    """``solve(inputs)``, its input problems (a formula outside its domain) naming the
    stage, as the calculator's ``compute`` would say them."""
    from geardesign.core.registry import _say_default

    try:
        return solve(inputs)
    except InputError as exc:
        raise _named(InputError([_say_default(p, spec) for p in exc.problems]), where) \
            from None


def finish(kind: str, spec, make: Callable[[], Result], where: str,
           original: dict | None) -> Result:
    """The report of a solved stage as its calculator's ``compute`` gives it (``make``:
    record → report; the result guard, the advice of its failed checks by re-rating, not
    searched when the drive itself is being re-rated: that reads verdicts only), with the
    loads the drive set (:func:`_set_by_drive`)."""
    import importlib
    import importlib.util

    from geardesign.core.rerating import rerating
    from geardesign.core.registry import _say_default, get
    from geardesign.core.result import guard

    try:
        try:
            res = guard(make())
        except InputError as exc:
            raise InputError([_say_default(p, spec) for p in exc.problems]) from exc
        if res.failed and not rerating() \
                and importlib.util.find_spec(f"geardesign.{kind}.levers") is not None:
            from geardesign.core.advice import advise

            levers = importlib.import_module(f"geardesign.{kind}.levers").LEVERS
            res = advise(get(kind), spec, res, levers)
    except InputError as exc:
        raise _named(exc, where) from None
    _set_by_drive(res, spec.data, original)
    return res


def run_novikov(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
                where: str) -> StageRun:
    """A Novikov pair solved once per pass (:func:`geardesign.novikov.solve.solve`) from
    its typed inputs; ratio, safety margins and mesh forces from the record, the report
    written on demand."""
    from geardesign.novikov import calculator as NC
    from geardesign.novikov import inputs as NI
    from geardesign.novikov import solve as NS

    d = copy.deepcopy(data)
    u = _ratio(d, where, "Novikov")
    e, src = (eta, "spec") if eta is not None else (ETA_CYLINDRICAL, "assumed (handbook)")
    load = _table(d, "load", where)
    load["torque2"], load["speed1"] = T_in * u * e, n_in
    _put(load, "life", duty.L_h)
    _put(load, "application_factor", duty.K_A)
    spec, inp = read_stage("novikov", d, where, duty, NOVIKOV_LOADS, NI.read)
    sol = solved(NS.solve, inp, spec, where)
    a, g, fo = sol.allow, sol.g, sol.forces
    margins = {"S_H": a.S_H / a.S_Hmin, "S_F1": a.S_F[0] / a.S_Fmin,
               "S_F2": a.S_F[1] / a.S_Fmin}
    worst = min(margins, key=margins.get)
    return StageRun("novikov", g.u, e, src, T_in, n_in, T_in * g.u * e, n_in / g.u,
                    (Member(fo.F_t, fo.F_r, fo.F_a, g.d1 / 2),
                     Member(fo.F_t, fo.F_r, fo.F_a, g.d2 / 2)),
                    margins[worst], worst, True, sol,
                    lambda: finish("novikov", spec, lambda: NC.result(spec, inp, sol), where,
                                   data), spec=spec)


def run_worm(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
             where: str) -> StageRun:
    """A worm pair solved once per pass (:func:`geardesign.worm.solve.solve`).  The worm
    calculator takes the wheel torque: its efficiency does not depend on the torque
    (:func:`geardesign.worm.solve.efficiency`), so the wheel torque of the stage's input
    torque is T2 = T_in·u·η before the pair is solved."""
    from geardesign.worm import calculator as WC
    from geardesign.worm import inputs as WI
    from geardesign.worm import solve as WS

    d = copy.deepcopy(data)
    u = _ratio(d, where, "worm")
    load = _table(d, "load", where)
    load["speed1"] = n_in
    _put(load, "life", duty.L_h)
    load["torque2"] = T_in * u * (eta if eta is not None else 0.8)    # read for η only
    spec, inp = read_stage("worm", d, where, duty, WORM_LOADS, WI.read)
    load["torque2"] = T_in * u * solved(WS.efficiency, inp, spec, where)
    spec, inp = read_stage("worm", d, where, duty, WORM_LOADS, WI.read)
    rec = solved(WS.solve, inp, spec, where)
    a = rec.analysis
    e = eta if eta is not None else a.eta
    src = "spec" if eta is not None else "worm calculator"
    margins = {"S_H": a.sigma_HP / a.sigma_H, "S_F": a.sigma_FP / a.sigma_F}
    worst = min(margins, key=margins.get)
    worm = Member(a.ld.F_t1, a.ld.F_r, a.ld.F_t2, a.g.d_w1 / 2)
    wheel = Member(a.ld.F_t2, a.ld.F_r, a.ld.F_t1, a.g.d2 / 2)
    return StageRun("worm", u, e, src, T_in, n_in, T_in * u * e, n_in / u, (worm, wheel),
                    margins[worst], worst, False, rec,
                    lambda: finish("worm", spec, lambda: WC.result(spec, rec), where, data),
                    spec=spec)


def run_planetary(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
                  where: str) -> StageRun:
    """A planetary train as a stage: the drive sets the input member's speed and torque.
    Its shafts are coaxial and the planets balance the radial mesh forces (with equal
    load sharing), so the stage puts no radial or axial load on the shafts.  Solved once
    per pass (:func:`geardesign.planetary.solve.solve`) from its typed inputs; ratio,
    torque, efficiency and the meshes' margins from the record, the report on demand."""
    from geardesign.core.result import clean_value
    from geardesign.planetary import calculator as PC
    from geardesign.planetary import inputs as PI
    from geardesign.planetary import solve as PS

    d = copy.deepcopy(data)
    op = _table(d, "operation", where)
    op["speed"], op["torque"] = n_in, T_in
    op.pop("power", None)
    st = d.get("strength")
    if st is not None and not isinstance(st, dict):
        raise InputError.at(f"{where}: strength", st, "must be a table [strength]")
    if st is not None:
        _put(st, "life_hours", duty.L_h)
        _put(st, "application_factor", duty.K_A)
        _put(st, "method", duty.method)
        from geardesign.spur.strength.iso6336.spec import ISO_NAME

        if st.get("method") != ISO_NAME:     # the ISO 6336 rating has no GOST regime
            _put(st, "regime", duty.regime)
        if duty.peak_ratio is not None:
            _put(st, "peak_torque", T_in * duty.peak_ratio)
    spec, inp = read_stage("planetary", d, where, duty, PLANETARY_LOADS, PI.read)
    sol = solved(PS.solve, inp, spec, where)
    out_ = spec.data["operation"]["output"]
    n_out = sol.speeds.n[out_]
    T_out = abs(sol.power.flow.T[out_])
    e = eta if eta is not None else sol.efficiency.eta_f
    src = "spec" if eta is not None else "planetary calculator"
    if eta is not None:
        T_out = T_in * abs(n_in / n_out) * eta
    rated = {ms.mesh.name: ms.rating for ms in (sol.strength.meshes if sol.strength
                                                  is not None else ()) if ms.rating}
    margins = {}
    for mesh in ("sun_planet", "planet_ring"):
        if mesh in rated:
            margins.update(_margins({k: clean_value(v) for k, v in rated[mesh].v.items()},
                                    f"{mesh}."))
    worst = min(margins, key=margins.get) if margins else ""
    zero = Member(0.0, 0.0, 0.0, 0.0)
    return StageRun("planetary", abs(n_in / n_out), e, src, T_in, n_in, T_out, abs(n_out),
                    (zero, zero), margins.get(worst), worst, n_out * n_in < 0, sol,
                    lambda: finish("planetary", spec, lambda: PC.result(spec, inp, sol), where,
                                   data), spec=spec)
