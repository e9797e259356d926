"""The loads of a drive's shafts and their bearings: the sense of rotation of each shaft,
the gears on it with their mesh forces (:class:`~geardesign.drive.shafts.GearLoad`), the
bearing reactions (:func:`~geardesign.drive.shafts.reactions`) and the bearing calculator's
result for each support, and the table and checks of the bearings' lives and their system
life.  Used by the drive's report (:mod:`.calculator`) and its heat
balance (:mod:`.lubrication`)."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem

from geardesign.core.records import dataclass
from geardesign.core.registry import load_data, run_data
from geardesign.core.result import DataTable, Result, check
from geardesign.drive.shafts import GearLoad, external_loads, reactions
from geardesign.drive.stages import StageRun, values


def _shaft_rotation(runs: list[StageRun]) -> list[int]:
    """Sense of rotation of shafts 1…N+1 (+1 for the motor shaft): an external mesh
    reverses it; a worm stage's crossed axes keep the sign by convention."""
    s = [1]
    for r in runs:
        s.append(-s[-1] if r.reverses else s[-1])
    return s


def shaft_loads(sh: dict, k: int, runs: list[StageRun]) -> list[tuple[dict, int, GearLoad]]:
    """The gears of the k-th [[shaft]]: ``(gear table, member, GearLoad)``, member 0 the
    input member of the stage, 1 its output member."""
    idx, key = sh["index"], f"shaft[{k}]"
    out = []
    for j, g in enumerate(sh["gear"]):
        st = g["stage"]
        if st == idx:
            which = 0            # input member of stage idx
        elif st == idx - 1:
            which = 1            # output member of stage idx-1
        else:
            raise InputError.at(f"{key}.gear[{j}].stage", st,
                                f"shaft {idx} carries stage {idx - 1} (output) and stage "
                                f"{idx} (input) only")
        if st > len(runs):
            raise InputError.at(f"{key}.gear[{j}].stage", st,
                                f"the drive has {len(runs)} stages")
        out.append((g, which, runs[st - 1].gear_load(which, g["position"],
                                                     math.radians(g["mate_angle"]),
                                                     g["axial_sign"])))
    return out


def shaft_cases(shafts: list, runs: list[StageRun], n_m: float, L_h: float) -> list[dict]:
    """The bearings of the shafts with their loads: one entry per bearing, ``{"shaft",
    "side", "key", "name", "F_r", "F_a", "n", "data"}`` (``data``: the bearing spec)."""
    rot = _shaft_rotation(runs)
    speeds = [n_m] + [r.n_out for r in runs]
    cases = []
    for k, sh in enumerate(shafts):
        idx = sh["index"]
        key = f"shaft[{k}]"
        if idx > len(runs) + 1:
            raise InputError.at(f"{key}.index", idx, f"the drive has {len(runs) + 1} shafts "
                                f"(1 … {len(runs) + 1})")
        if sh["bearing_b"] == sh["bearing_a"]:
            raise InputError.at(f"{key}.bearing_b", sh["bearing_b"],
                                "the two bearings must be at different positions")
        loads = [ld for _, _, ld in shaft_loads(sh, k, runs)] + external_loads(sh)
        R = reactions(sh["bearing_a"], sh["bearing_b"], loads, rot[idx - 1])
        name = sh["name"] or f"shaft {idx}"
        for side in ("a", "b"):
            F_r = R.F_rA if side == "a" else R.F_rB
            F_a = R.axial if sh["fixed"] == side else 0.0
            data = {"kind": "bearing", "method": sh["method"], "bearing": dict(sh[f"support_{side}"]),
                    "load": {"F_r": F_r, "F_a": F_a, "speed": speeds[idx - 1]},
                    "requirements": {"life": L_h}}
            if sh.get("lubrication"):
                data["lubrication"] = dict(sh["lubrication"])
            cases.append(dict(shaft=idx, side=side, key=key, name=name, F_r=F_r, F_a=F_a,
                              n=speeds[idx - 1], data=data))
    return cases


#: The loads the drive sets on a bearing (:func:`shaft_cases`).
BEARING_LOADS = ("load.F_r", "load.F_a", "load.speed")


def rate_bearing(case: dict, memo: dict):
    """The bearing of one entry of :func:`shaft_cases` rated through its typed interface
    (:func:`geardesign.bearing.inputs.read`, :func:`geardesign.bearing.solve.solve`): its
    record (:class:`~geardesign.bearing.solve.Rated`), no report.  The spec is validated
    once per run (``memo``, :mod:`.reuse`); a later pass with other loads checks them by
    their schema fields and the bearing's reader of loads.  Problems name the shaft's
    support."""
    import dataclasses

    from geardesign.bearing import inputs as BI
    from geardesign.bearing.life import BearingError
    from geardesign.bearing.solve import solve
    from geardesign.bearing.spec import SCHEMA
    from geardesign.core.registry import _say_default
    from geardesign.drive import reuse

    where = f"{case['key']}.support_{case['side']}"
    data = case["data"]
    key = reuse.fingerprint("bearing", where, data, BEARING_LOADS)
    inp = None
    if key in memo:
        first = memo[key]
        spec = reuse.reloaded(SCHEMA, first.spec, data, BEARING_LOADS)
        if spec is not None and isinstance(first.inputs, BI.CheckInputs):
            try:
                blocks = BI.resolve_blocks(spec)
                BI.check_inputs_fit(first.inputs.bearing, blocks)
                inp = dataclasses.replace(first.inputs, blocks=tuple(blocks))
            except InputError:
                inp = None       # read again below: the problem as the calculator says it
    try:
        fresh = inp is None
        if fresh:
            _, spec = load_data(data, where)
        try:
            if fresh:
                inp = BI.read(spec)
                memo[key] = _Read(spec, inp)
            try:
                return solve(inp)
            except BearingError as exc:
                raise BI.assessment_error(exc, spec.data) from None
        except InputError as exc:      # as the calculator's compute says them
            raise InputError([_say_default(p, spec) for p in exc.problems]) from None
    except InputError as exc:
        raise InputError([_bearing_problem(where, p) for p in exc.problems]) from None


@dataclass(frozen=True)
class _Read:
    """A bearing spec validated in a run and its typed inputs."""

    spec: object
    inputs: object


def run_bearing(case: dict) -> Result:
    """The bearing calculator's result for one entry of :func:`shaft_cases`; problems
    name the shaft's support."""
    where = f"{case['key']}.support_{case['side']}"
    try:
        return run_data(case["data"], where)
    except InputError as exc:
        raise InputError([_bearing_problem(where, p) for p in exc.problems]) from None


def _bearing_problem(where: str, p: Problem) -> Problem:
    """A problem of a bearing spec the drive built: its ``load`` table is the drive's (the
    reactions of the shaft), so say so and what to change instead of naming a key the
    designer never wrote."""
    if p.key.startswith("load."):
        return Problem(f"{where}: {p.key}", f"{p.message} — this is the bearing load the drive "
                       f"derived from the forces on the shaft: reduce them (torque, external "
                       f"loads) or move the bearings", p.value)
    return Problem(f"{where}: {p.key}", p.message, p.value)


def bearing_runs(shafts: list, runs: list[StageRun], n_m: float, L_h: float,
                  bearing_oil=None) -> list[tuple[dict, Result]]:
    """The bearings of the shafts by the bearing calculator: ``(case, result)``;
    ``bearing_oil(case)`` (with [lubrication]) puts the drive's oil and its sump temperature
    into a bearing's [lubrication] table."""
    out = []
    for case in shaft_cases(shafts, runs, n_m, L_h):
        if bearing_oil is not None:
            bearing_oil(case)
        out.append((case, run_bearing(case)))
    return out


def bearing_report(res: Result, bearings: list, L_h: float) -> None:
    """Bearing lives of the shafts and their system life."""
    from geardesign.bearing.life import system_life

    rows, lives, balls = [], [], []
    for case, br in bearings:
        idx, side, name = case["shaft"], case["side"], case["name"]
        F_r, F_a, speed = case["F_r"], case["F_a"], case["n"]
        v = values(br)
        life = v.get("L_sah", v.get("L_nmh", v.get("L10h")))
        lives.append(life)
        balls.append("ball" in str(v.get("type", "ball")))
        rows.append(dict(shaft=idx, bearing=side.upper(), designation=v.get("designation"),
                         F_r=F_r, F_a=F_a, n=speed, life=life,
                         verdict=br.verdict,
                         source=v.get("data_source") or "given in the spec"))
        res.parts.append(("bearing_reports", f"{name}, bearing {side.upper()}", br))
        failed = [c.code for c in br.failed]
        res.checks.append(check(
            f"BEARING_{idx}{side.upper()}", not failed, "error",
            f"{name}, bearing {side.upper()} fails {', '.join(failed)} (F_r = {F_r:.0f} N, "
            f"F_a = {F_a:.0f} N): see its report below",
            f"{name}, bearing {side.upper()}: life {life:.0f} h (F_r = {F_r:.0f} N, "
            f"F_a = {F_a:.0f} N)", life, L_h, "bearing calculator"))
    res.tables.append(DataTable("bearings", "Bearings", [
        ("shaft", "shaft", None), ("bearing", "bearing", None),
        ("designation", "designation", None), ("F_r", "F_r", "N"), ("F_a", "F_a", "N"),
        ("n", "n", "min^-1"), ("life", "life", "h"), ("verdict", "verdict", None),
        ("source", "data used", None)], rows))
    slope = 10.0 / 9.0 if any(balls) else 9.0 / 8.0
    L_sys = system_life(lives, slope)
    sec = res.section("drive", "Drive")
    sec.add("L_system", L_sys, "h", "L_sys", f"system life of the {len(lives)} bearings "
            f"(Weibull slope {slope:.3f})", "Lundberg–Palmgren")
    res.checks.append(check(
        "BEARING_SYSTEM_LIFE", L_sys >= L_h, "warning",
        f"the {len(lives)} bearings together reach {L_sys:.0f} h at 90 % reliability, below the "
        f"required {L_h:g} h: one of them fails early with that probability; take larger "
        f"bearings for the shortest lives",
        f"system life of the {len(lives)} bearings {L_sys:.0f} h >= {L_h:g} h", L_sys, L_h,
        "Lundberg–Palmgren"))
