"""Drive stages: how each calculator is run as a stage of a drive.

A stage adapter puts the stage's input torque and speed (and the drive's life, regime,
application factor and peak torque, where the stage spec does not give its own) into the
stage spec and reads back the ratio, the efficiency, the output torque and speed, the mesh
forces on the input and output members (for the shafts) and the worst safety margin.  A
spur stage is read into typed inputs (:func:`geardesign.spur.inputs.from_spec`) and solved
once per pass (:func:`geardesign.spur.solve.solve`); its values come from the typed record,
and its report (with the advice of its failed checks) is written only when the drive's
report asks for it, from the last pass.  The worm, Novikov and planetary stages run their
calculators.  No formula of a calculator is repeated here.
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

WORM_ITERATIONS = 4


@dataclass(frozen=True)
class Duty:
    L_h: float
    regime: str
    K_A: float
    peak_ratio: float | None
    method: str | None = None      # strength method of the stages that give none


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


def _run(data: dict, where: str, original: dict | None = None) -> Result:
    """Validate and compute a stage spec; problems name the stage.  The stage's report says
    which of its loads the drive set (``original`` is the stage spec as written)."""
    try:
        calc, spec = load_data(data, where)
        res = calc.compute(spec)
    except InputError as exc:
        raise _named(exc, where) from None
    _set_by_drive(res, data, original)
    return res


def _validate(data: dict, where: str) -> None:
    try:
        load_data(copy.deepcopy(data), where)
    except InputError as exc:
        raise _named(exc, where) from None


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


def run_novikov(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
                where: str) -> StageRun:
    d = copy.deepcopy(data)
    u = _ratio(d, where, "Novikov")
    e, src = (eta, "spec") if eta is not None else (ETA_CYLINDRICAL, "assumed (handbook)")
    load = _table(d, "load", where)
    load["torque2"], load["speed1"] = T_in * u * e, n_in
    _put(load, "life", duty.L_h)
    _put(load, "application_factor", duty.K_A)
    res = _run(d, where, data)
    v = values(res)
    margins = {"S_H": v["S_H"] / v["S_H_min"], "S_F1": v["S_F1"] / v["S_F_min"],
               "S_F2": v["S_F2"] / v["S_F_min"]}
    worst = min(margins, key=margins.get)
    F_t, F_r, F_a = v["F_t"], v["F_r"], v["F_a"]
    return StageRun("novikov", v["u"], e, src, T_in, n_in, T_in * v["u"] * e, n_in / v["u"],
                    (Member(F_t, F_r, F_a, v["d1"] / 2), Member(F_t, F_r, F_a, v["d2"] / 2)),
                    margins[worst], worst, True, given=res)


def run_worm(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
             where: str) -> StageRun:
    """The worm calculator takes the wheel torque: iterate T2 until the worm torque it
    reports equals the stage's input torque (the efficiency depends on the sliding speed,
    so a few steps settle it)."""
    d = copy.deepcopy(data)
    u = _ratio(d, where, "worm")
    load = _table(d, "load", where)
    load["speed1"] = n_in
    _put(load, "life", duty.L_h)
    T2 = T_in * u * (eta if eta is not None else 0.8)
    res = None
    for _ in range(WORM_ITERATIONS):
        load["torque2"] = T2
        res = _run(d, where, data)
        v = values(res)
        if abs(v["T1"] - T_in) <= 1e-9 * T_in:
            break
        T2 *= T_in / v["T1"]
    e = eta if eta is not None else v["eta"]
    src = "spec" if eta is not None else "worm calculator"
    margins = {"S_H": v["S_H"], "S_F": v["S_F"]}
    worst = min(margins, key=margins.get)
    worm = Member(v["F_t1"], v["F_r"], v["F_t2"], v["d_w1"] / 2)
    wheel = Member(v["F_t2"], v["F_r"], v["F_t1"], v["d2"] / 2)
    return StageRun("worm", u, e, src, T_in, n_in, T_in * u * e, n_in / u, (worm, wheel),
                    margins[worst], worst, False, given=res)


def run_planetary(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
                  where: str) -> StageRun:
    """A planetary train as a stage: the drive sets the input member's speed and torque.
    Its shafts are coaxial and the planets balance the radial mesh forces (with equal
    load sharing), so the stage puts no radial or axial load on the shafts."""
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
    res = _run(d, where, data)
    r = sections(res)
    ops = res.inputs["operation"]
    n_out = r["kinematics"][f"n_{ops['output']}"]
    T_out = abs(r["power"][f"T_{ops['output']}"])
    e = eta if eta is not None else r["efficiency"]["eta"]
    src = "spec" if eta is not None else "planetary calculator"
    if eta is not None:
        T_out = T_in * abs(n_in / n_out) * eta
    margins = {}
    for mesh in ("sun_planet", "planet_ring"):
        v = r.get(f"strength_{mesh}")
        if v:
            margins.update(_margins(v, f"{mesh}."))
    worst = min(margins, key=margins.get) if margins else ""
    zero = Member(0.0, 0.0, 0.0, 0.0)
    return StageRun("planetary", abs(n_in / n_out), e, src, T_in, n_in, T_out, abs(n_out),
                    (zero, zero), margins.get(worst), worst, n_out * n_in < 0, given=res)
