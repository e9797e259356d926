"""Levers of the drive advice (:mod:`geardesign.core.advice`).

**Stages.** A stage fails (``STAGE_i``) and its own report advises a change of the stage
spec (``gear.face_width = ...``).  The drive writes that change at the drive's own key path
(``stage[0].gear.face_width``) and re-rates the whole drive with it, so that the stage's
loads, efficiencies and the heat balance follow; a stage read from a file is changed in
that file, which the drive spec cannot name: no fix.  Candidates: the fixes of the stage's
failed checks merged into one change (where they do not set a key differently), then each
on its own.

**Bearings, shafts, connections.** Each is found on the part itself, with the loads the
drive computed for it (its nested report's inputs), so that no trial runs the drive's
stages or heat balance:

* ``BEARING_<i><A/B>``: the bearing calculator's own fix (the next catalogue bearing of
  the type and bore with a higher C_r, re-rated with the drive's reactions and oil) at
  ``shaft[k].support_a.designation``;
* ``CONNECTION_<i>_<j>``: the connection calculator's own fix (the standard key length, or
  two keys, within 1.5·d and the hub, re-rated with the torque through the hub) at
  ``shaft[k].key[j-1].length`` / ``.count``;
* ``SHAFT_<i>``: the shaft calculator re-rated with the drive's loads and supports, the
  steps scaled alike (:func:`geardesign.shaft.levers.scaled_steps`) but the bearing seats
  kept (their diameter is the bearing's bore) and the steps outboard of them no larger than
  the seat, at ``shaft[k].step[n].diameter``.  When no such scale passes (the shaft fails at or outboard
  of a seat), the next bores of the same bearing type and series with their seats and the
  other steps scaled alike (:func:`_bore_fix`), at ``shaft[k].support_a.designation`` with
  the steps.

The fixes are then written into the drive spec together and the drive re-rated once
(``per_check``): the heat balance (a larger bearing loses more), the mesh misalignment from
the shafts' slopes and the keys on a thicker step follow, and a check carries its fix only
when it passes then.  A part that no change within its proportions makes pass keeps its
words (the shaft's and the connection's messages name the next lever: a larger bearing
bore, a spline or an interference fit).

**Motor.** ``MOTOR_TORQUE`` (the machine needs more than the motor's nominal torque): the
next rated powers of :data:`MOTOR_POWERS` at or above the torque needed at the motor speed,
in the spec's own terms: ``motor.power`` [kW], or ``motor.torque`` [N·m] when the spec
gives the torque (that power's torque at the motor speed, T = 30 000·P/(π·n), rounded up
to 0.1 N·m).  The drive is re-rated (a larger motor raises the peak torque of the static
checks).

**Heat balance.** ``THERMAL`` (the sump above its permissible temperature), each re-rated
with the heat balance: a fan on the housing (``thermal.fan_velocity``, :data:`FAN_SPEEDS`
above the present one, at most the 10 m/s of a fan on the input shaft), a larger housing
area when the spec gives it (``thermal.area``, finned, at most :data:`AREA_MAX_FACTOR`
times), then an oil cooler (``thermal.cooler``) from the balance's own figure: the losses
at the permissible temperature beyond what the housing gives off there, rounded up to
0.1 kW.  The permissible temperature is the oil's, not a lever."""

from __future__ import annotations

import math
import re

from geardesign.core.advice import Lever

MAX_STAGES = 12
"""Stages whose advice is carried up (a drive has a few)."""

MAX_SHAFT_TRIES = 6
"""Scales of a drive's shaft re-rated at most (each a shaft analysis)."""

MAX_BORE_TRIES = 3
"""Scales of a drive's shaft with larger bearing bores re-rated at most."""


def _stage_fixes(i: int):
    def gen(data: dict, res):
        stages = data.get("stage") or []
        # the stage reports follow the inline stages one for one up to the first file
        inline = 0
        for st in stages:
            if not isinstance(st, dict) or st.get("file") is not None:
                break
            inline += 1
        reports = [r for key, _, r in res.parts if key == "stage_reports"]
        if i >= min(inline, len(reports)):
            return
        fixes = []
        for c in reports[i].failed:
            if c.fix and c.fix not in fixes:
                fixes.append(c.fix)
        if not fixes:
            return
        merged: dict = {}
        for fix in fixes:
            for k, v in fix:
                merged.setdefault(k, v)
        consistent = all(merged[k] == v for fix in fixes for k, v in fix)
        prefix = f"stage[{i}]."
        if consistent and len(fixes) > 1:
            yield tuple((prefix + k, v) for k, v in merged.items())
        for fix in fixes:
            yield tuple((prefix + k, v) for k, v in fix)
    return gen


# ------------------------------------------------------------------ parts


def _shafts(data: dict) -> list[tuple[int, dict]]:
    """``(k, shaft table)`` of the spec's ``[[shaft]]`` entries that are tables."""
    return [(k, sh) for k, sh in enumerate(data.get("shaft") or []) if isinstance(sh, dict)]


def _part_fix(report, prefix: str, keys: dict) -> tuple | None:
    """The fix that the failed checks of a nested ``report`` carry, at the drive's path:
    ``keys`` maps the part's key to the drive's (``None``: not a key the drive can name)."""
    fix: dict = {}
    for c in report.failed:
        for k, v in c.fix:
            if k not in keys or fix.get(keys[k], v) != v:
                return None
            fix[keys[k]] = v
    if not fix or any(not c.fix for c in report.failed):
        return None
    return tuple((prefix + k, v) for k, v in fix.items())


def _bearings(data: dict, res) -> dict:
    reports = [r for key, _, r in res.parts if key == "bearing_reports"]
    out, n = {}, 0
    for k, sh in _shafts(data):
        for side in ("a", "b"):
            if n >= len(reports):
                return out
            report, n = reports[n], n + 1
            if report.failed:
                fix = _part_fix(report, f"shaft[{k}].support_{side}.",
                                {"bearing.designation": "designation"})
                if fix:
                    out[f"BEARING_{sh.get('index')}{side.upper()}"] = (
                        fix, "the next catalogue bearing of its type and bore, rated with "
                        "the drive's loads")
    return out


def _analysed(data: dict, res, part: str, each):
    """``(k, shaft, item, report)`` of the analysed shafts (those with steps) in the order of
    their nested reports ``part``: ``each(shaft)`` lists a shaft's items (its connections,
    or the shaft itself), one report each."""
    reports = iter(r for key, _, r in res.parts if key == part)
    for k, sh in _shafts(data):
        if not sh.get("step"):
            continue
        for item in each(sh):
            report = next(reports, None)
            if report is None:
                return
            yield k, sh, item, report


def _connections(data: dict, res) -> dict:
    out = {}
    for k, sh, (j, c), report in _analysed(data, res, "connection_reports",
                                           lambda sh: enumerate(sh.get("key") or [])):
        if report.failed and isinstance(c, dict):
            typ = c.get("type")
            fix = _part_fix(report, f"shaft[{k}].key[{j}].",
                            {f"{typ}.length": "length", f"{typ}.count": "count"})
            if fix:
                out[f"CONNECTION_{sh.get('index')}_{j + 1}"] = (
                    fix, "the connection rated with the torque through its hub")
    return out


def _seat_steps(part: dict, x) -> set[int]:
    """The steps of a shaft spec (the shaft calculator's) under the position ``x``."""
    seats, z = set(), 0.0
    for i, s in enumerate(part["step"]):
        if x is not None and z - 1e-9 <= x <= z + s["length"] + 1e-9:
            seats.add(i)
        z += s["length"]
    return seats


def _seats(part: dict) -> set[int]:
    """The steps of a shaft spec (the shaft calculator's) on which a support sits."""
    return set().union(set(), *(_seat_steps(part, sup.get("position"))
                                for sup in part.get("support") or []))


def _first_passing(report, k: int, trials, max_tries: int):
    """The first of ``trials`` (``(extra, steps_fix)``: drive keys set with it, the step
    diameters ``((step[i].diameter, d), ...)``) at which the shaft calculator, re-rating
    the spec the drive built (the nested ``report``'s inputs) alone, passes the failed
    checks and breaks none that passed; at most ``max_tries`` distinct ones re-rated.  The
    fix at the drive's keys, or ``None``."""
    from geardesign.core.advice import passes
    from geardesign.core.errors import InputError
    from geardesign.core.registry import load_data

    part = dict(report.document()["inputs"], kind="shaft")    # the spec the drive built
    steps = part["step"]
    diameters = [s["diameter"] for s in steps]
    todo = {c.code for c in report.failed}
    passing = {c.code for c in report.checks if c.severity == "error" and c.passed}
    last, tries = None, 0
    for extra, fix in trials:
        if fix == last:
            continue
        last, tries = fix, tries + 1
        if tries > max_tries:
            return None
        trial = dict(part, step=[dict(s, diameter=d) for s, (_, d) in zip(steps, fix)])
        try:
            calc, spec = load_data(trial)
            again = calc.rate(spec)
        except (InputError, ArithmeticError, ValueError):
            return None
        if passes(again, todo, passing, {c.code for c in report.checks}):
            return tuple(extra) + tuple((f"shaft[{k}].{key}", d)
                                        for (key, d), d0 in zip(fix, diameters) if d != d0)
    return None


def _shaft_fix(report, k: int):
    """The least scale of a drive shaft's steps (seats kept) that passes its checks,
    re-rated by the shaft calculator alone; ``None`` when none within the scales does."""
    from geardesign.shaft.levers import scale_order, scaled_steps

    part = report.document()["inputs"]
    if not part.get("step"):
        return None
    seats = _seats(part)
    diameters = [s["diameter"] for s in part["step"]]
    return _first_passing(report, k, (((), scaled_steps(diameters, scale, seats))
                                      for scale in scale_order(report)), MAX_SHAFT_TRIES)


def _bore_fix(report, k: int, shaft: dict):
    """The least scale of a drive shaft's steps with the bearing seats grown to the next
    bores of the same bearing type and series (:func:`geardesign.bearing.catalogue.candidates`),
    the bearings changed with them, re-rated by the shaft calculator alone; ``None`` when
    a support has no catalogue row or none within the scales passes."""
    from geardesign.bearing import catalogue as CAT
    from geardesign.shaft.levers import SCALES, first_scale, scaled_steps

    part = report.document()["inputs"]
    if not part.get("step") or not part.get("support"):
        return None
    seats = []                                   # (drive key, catalogue row, seat steps)
    for sup in part["support"]:
        side = str(sup.get("name", "")).lower()
        des = (shaft.get(f"support_{side}") or {}).get("designation")
        row = CAT.find(des) if isinstance(des, str) else None
        idx = _seat_steps(part, sup.get("position"))
        if row is None or not idx:
            return None
        seats.append((f"shaft[{k}].support_{side}.designation", row, idx))
    diameters = [s["diameter"] for s in part["step"]]

    def trials():
        k0 = first_scale(report)
        for scale in (x for x in SCALES if x >= k0 - 1e-9):
            grown, bearings = list(diameters), []
            for key, row, idx in seats:
                need = max(diameters[i] for i in idx) * scale
                bore = next((b for b in CAT.bores(row.type) if b >= need - 1e-9 and b > row.d),
                            None)
                rows = [] if bore is None else CAT.candidates(row.type, bore, [row.series])
                if not rows:
                    return
                bearings.append((key, rows[0].designation))
                for i in idx:
                    grown[i] = bore
            yield bearings, scaled_steps(grown, scale, set().union(*(i for _, _, i in seats)))

    return _first_passing(report, k, trials(), MAX_BORE_TRIES)


def _shafts_fixes(data: dict, res) -> dict:
    out = {}
    for k, sh, _, report in _analysed(data, res, "shaft_reports", lambda sh: (sh,)):
        if report.failed:
            fix = _shaft_fix(report, k)
            if fix:
                out[f"SHAFT_{sh.get('index')}"] = (
                    fix, "the steps between the bearing seats scaled alike, rounded up to "
                    "whole mm, rated with the drive's loads")
                continue
            fix = _bore_fix(report, k, sh)
            if fix:
                out[f"SHAFT_{sh.get('index')}"] = (
                    fix, "the next bearing bores of the same series with their seats, the "
                    "other steps scaled alike, rated with the drive's loads")
    return out


def part_fixes(data: dict, res):
    """Proposals of the ``per_check`` lever: every part's fix, then those of the bearings
    and connections alone (when a shaft's thicker steps upset a check that passed)."""
    found = {**_bearings(data, res), **_connections(data, res)}
    shafts = _shafts_fixes(data, res) if any(
        c.code.startswith("SHAFT_") for c in res.failed) else {}
    yield {**found, **shafts}
    if shafts and found:
        yield found


MAX_SHAFTS = 13
"""Shafts whose checks carry a fix (a drive of up to 12 stages)."""

MAX_CONNECTIONS = 12
"""Connections per shaft whose checks carry a fix."""

PART_CODES = tuple(
    [f"BEARING_{i}{s}" for i in range(1, MAX_SHAFTS + 1) for s in "AB"]
    + [f"SHAFT_{i}" for i in range(1, MAX_SHAFTS + 1)]
    + [f"CONNECTION_{i}_{j}" for i in range(1, MAX_SHAFTS + 1)
       for j in range(1, MAX_CONNECTIONS + 1)])
"""The checks of the drive's parts."""


# ------------------------------------------------------------------ motor, heat balance

MOTOR_POWERS = (0.06, 0.09, 0.12, 0.18, 0.25, 0.37, 0.55, 0.75, 1.1, 1.5, 2.2, 3, 4, 5.5, 7.5,
                11, 15, 18.5, 22, 30, 37, 45, 55, 75, 90, 110, 132, 160, 200, 250, 315, 355,
                400, 450, 500, 560, 630, 710, 800, 900, 1000)
"""Rated output powers of motors [kW], [IEC60072-1] (the same series as GOST 12139-84)."""

MOTOR_STEPS = 3
"""Rated powers tried at and above the one needed."""

FAN_SPEEDS = (5.0, 10.0)
"""Air velocities of a fan along the housing tried [m/s] (a fan on the input shaft blows
5–10 m/s; 10 m/s is the figure of the check's own words)."""

AREA_MAX_FACTOR = 1.5
"""Largest housing area advised, times the given one (cooling fins)."""

COOLER_FACTORS = (1.0, 1.25, 1.6, 2.5)
"""Oil coolers tried, times the figure of the balance."""


def _inputs(res, table: str) -> dict:
    v = res.inputs.get(table) if isinstance(res.inputs, dict) else None
    return v if isinstance(v, dict) else {}


def _failed(res, code: str):
    return next((c for c in res.failed if c.code == code), None)


def _larger_motor(data: dict, res):
    c = _failed(res, "MOTOR_TORQUE")
    n = _inputs(res, "motor").get("speed")
    if c is None or not c.value or not n:
        return
    need = c.value * n * math.pi / 30000.0                   # kW at the motor speed
    given_torque = isinstance((data.get("motor") or {}).get("torque"), (int, float))
    for P in [p for p in MOTOR_POWERS if p >= need * (1.0 - 1e-9)][:MOTOR_STEPS]:
        if given_torque:
            yield (("motor.torque", math.ceil(P * 30000.0 / (math.pi * n) * 10.0) / 10.0),)
        else:
            yield (("motor.power", float(P)),)


def _fan(data: dict, res):
    if _failed(res, "THERMAL") is None:
        return
    v = _inputs(res, "thermal").get("fan_velocity") or 0.0
    yield from ((("thermal.fan_velocity", x),) for x in FAN_SPEEDS if x > v)


def _area(data: dict, res):
    A = (data.get("thermal") or {}).get("area")
    if _failed(res, "THERMAL") is None or not isinstance(A, (int, float)):
        return
    for f in (1.2, AREA_MAX_FACTOR):
        yield (("thermal.area", round(A * f, 2)),)


_COOLER = re.compile(r"an oil cooler of ([0-9.]+) kW")


def _cooler(data: dict, res):
    c = _failed(res, "THERMAL")
    m = None if c is None else _COOLER.search(c.message)
    if m is None:
        return
    kw = sorted({max(0.1, math.ceil(float(m.group(1)) * f * 10.0 - 1e-9) / 10.0)
                 for f in COOLER_FACTORS})
    yield from ((("thermal.cooler", x),) for x in kw)


LEVERS = tuple(Lever((f"STAGE_{i + 1}",), _stage_fixes(i),
                     f"the change stage {i + 1}'s report advises, at the drive's key path")
               for i in range(MAX_STAGES)) + (
    Lever(PART_CODES, part_fixes, "each part re-rated alone", per_check=True),
    Lever(("MOTOR_TORQUE",), _larger_motor, "the next rated motor power, IEC 60072-1",
          supersedes=(r"choose a motor of at least [0-9.]+ kW",)),
    Lever(("THERMAL",), _fan, "a fan blowing along the housing"),
    Lever(("THERMAL",), _area, "a finned housing, within 1.5 times the area"),
    Lever(("THERMAL",), _cooler, "an oil cooler, rated from the heat balance"))
