"""The spec of a bearing read into typed inputs (N, mm, min⁻¹, h): the bearing (catalogue
row and/or given values), the load case or spectrum, the method's conditions; every rule
across keys that the schema cannot state raises a one-line :class:`InputError` here, and the
independent stages of a spec are reported in one round (:class:`Problems`)."""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.bearing import catalogue as CAT
from geardesign.bearing import life as L
from geardesign.bearing import pair as PR
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Bearing, Block, Conditions
from geardesign.bearing.conditions import (
    _type_words,
    fmt,
    resolve_conditions,
    with_c_u,
)
from geardesign.bearing.resolve import (
    Facts,
    _bearing_b,
    _catalogue_row,
    catalogue_bearing,
    resolve_bearing,
)
from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec

SHARE_TOL = 1e-6


_f = fmt


@dataclass(frozen=True)
class CheckInputs:
    """``mode = "check"``: one bearing under a load case or spectrum."""

    bearing: Bearing
    facts: Facts
    blocks: tuple[Block, ...]
    cond: Conditions
    ignored: tuple[str, ...]       # inputs the method does not use


@dataclass(frozen=True)
class SelectInputs:
    """``mode = "select"``: the catalogue bearings of a type and bore, smallest first."""

    kind: str
    d: float
    candidates: tuple[tuple[CAT.CatalogueBearing, Bearing], ...]
    blocks: tuple[Block, ...]
    cond: Conditions
    ignored: tuple[str, ...]
    replaced: tuple[tuple[str, object], ...]   # given designation and ratings it replaces
    life_required: float


@dataclass(frozen=True)
class PairInputs:
    """``mode = "pair"``: two angular contact or tapered roller bearings, A and B."""

    A: Bearing
    facts_a: Facts
    B: Bearing
    facts_b: Facts
    block: Block
    F_rB: float
    F_a: float                     # external axial load (signed) [N]
    induced_factor: float | None
    arrangement: str
    cond: Conditions
    ignored: tuple[str, ...]


Inputs = CheckInputs | SelectInputs | PairInputs


def resolve_blocks(spec: ValidatedSpec) -> list[Block]:
    ld = spec.data["load"]
    blocks = ld["spectrum"]
    if blocks is not None:
        for key in ("F_r", "F_a", "speed", "regime"):
            if ld[key] is not None:
                raise InputError.at(f"load.{key}", ld[key],
                                    "give either a single load case or [[load.spectrum]] blocks, "
                                    "not both; remove it")
        total = sum(x["time_share"] for x in blocks)
        if abs(total - 1.0) > SHARE_TOL:
            raise InputError(Problem("load.spectrum", f"time shares add up to {total:.6g}; they "
                                     f"must add up to 1", [x["time_share"] for x in blocks]))
        out = [Block(x["F_r"], x["F_a"], x["speed"], x["time_share"]) for x in blocks]
        for i, blk in enumerate(out):
            if blk.F_r == 0 and blk.F_a == 0:
                raise InputError(Problem(f"load.spectrum[{i}]", "F_r = F_a = 0: a block needs a "
                                                                "load; remove the block or give one"))
        return out
    if ld["F_r"] is None:
        raise InputError(Problem("load.F_r", "missing; required: a number >= 0 (N) (radial "
                                             "load), or [[load.spectrum]] blocks"))
    if ld["speed"] is None:
        raise InputError(Problem("load.speed", "missing; required: a number > 0 (min^-1) (speed "
                                               "of the rotating ring)"))
    if ld["F_a"] is None:
        ld["F_a"] = 0.0
        spec.assumed.append("load.F_a")
    if ld["F_r"] == 0 and ld["F_a"] == 0:
        raise InputError.at("load.F_r", 0.0, "F_r = F_a = 0: give the radial or the axial load")
    return [Block(ld["F_r"], ld["F_a"], ld["speed"], 1.0)]


def check_inputs_fit(bearing: Bearing, blocks: list) -> None:
    if bearing.kind in T.THRUST_TYPES and (bearing.alpha or 90.0) >= 90.0:
        for i, blk in enumerate(blocks):
            if blk.F_r > 0:
                key = "load.F_r" if len(blocks) == 1 else f"load.spectrum[{i}].F_r"
                raise InputError.at(key, blk.F_r, "a thrust bearing with α = 90° carries no radial "
                                                  "load; use 0, or a radial or angular bearing")


def needs_induced(b: Bearing, key: str) -> None:
    """The induced axial force of a pair bearing needs Y or e (tapered roller) or the
    contact angle (angular contact ball)."""
    if b.kind == "tapered_roller":
        tan_a = (b.e / 1.5) if b.e is not None else (
            math.tan(math.radians(b.alpha)) if b.alpha else None)
        if b.Y is None and not tan_a:
            raise InputError(Problem(f"{key}.Y", "missing; the induced axial force of a "
                                     "tapered roller bearing needs its catalogue Y or e"))
    elif b.alpha is None:
        raise InputError(Problem(f"{key}.contact_angle", "missing; the induced axial force of "
                                 "an angular contact ball bearing needs its contact angle"))


def _no_pair(spec: ValidatedSpec) -> None:
    if spec.data["pair"] is not None:
        raise InputError(Problem("pair", "used only with mode = \"pair\"; remove [pair] or set "
                                         "mode = \"pair\""))


def _check(spec: ValidatedSpec, problems: Problems):
    """The check mode's stages: loads, [pair] not used, the bearing; then the conditions."""
    blocks = problems.stage(resolve_blocks, spec)
    problems.stage(_no_pair, spec)
    found = problems.stage(resolve_bearing, spec)
    if found is Problems.FAILED:
        return None
    bearing, facts = found
    if blocks is not Problems.FAILED:
        problems.stage(check_inputs_fit, bearing, blocks)
    cond = problems.stage(resolve_conditions, spec, bearing)
    if cond is Problems.FAILED or blocks is Problems.FAILED:
        return None
    bearing = problems.stage(with_c_u, bearing, cond[0])
    if bearing is Problems.FAILED:
        return None
    return CheckInputs(bearing, facts, tuple(blocks), cond[0], cond[1])


def _select_keys(spec: ValidatedSpec) -> tuple:
    """Type and bore to select in (from a designation or given), what the selection
    replaces; every missing or contradicting key in one round."""
    b = spec.data["bearing"]
    req = spec.data["requirements"]
    problems = Problems()
    if req["life"] is None:
        problems.add(Problem("requirements.life", "missing; required in mode = \"select\": "
                                                  "a number > 0 (h)"))
    # the selection replaces the designation and its ratings: a designation names the type
    # and bore to select in (`--select` on a check spec runs as written)
    row = problems.stage(_catalogue_row, b) if b["designation"] is not None else None
    if row is Problems.FAILED:
        row = None
    replaced = tuple((k, b[k]) for k in ("designation", "C_r", "C_0r") if b[k] is not None)
    if row is not None:
        for key, value in (("type", row.type), ("d", row.d)):
            if b[key] is None:
                b[key] = value
            elif b[key] != value:
                problems.add(Problem(f"bearing.{key}", f"contradicts bearing.designation = "
                                     f"\"{b['designation']}\" ({_type_words(row.type)}, d = "
                                     f"{_f(row.d)} mm), which names the type and bore to select "
                                     f"in; remove one of them", b[key]))
    if b["type"] is None and b["designation"] is None:
        problems.add(Problem("bearing.type", "missing; required in mode = \"select\" (or a "
                             "bearing.designation naming type and bore): one of "
                             + ", ".join(f'"{k}"' for k in sorted({r.type for r in
                                                                   CAT.bearings()}))))
    if b["d"] is None and b["designation"] is None:
        problems.add(Problem("bearing.d", "missing; required in mode = \"select\" (or a "
                             "bearing.designation naming type and bore): the bore diameter of "
                             "the shaft seat (mm)"))
    problems.raise_all()
    kind, d = b["type"], b["d"]
    if not CAT.bores(kind):
        raise InputError.at("bearing.type", kind, "the catalogue holds no bearing of this type; "
                                                  "use \"deep_groove_ball\" or \"tapered_roller\"")
    series = b["series"]
    if series:
        known = CAT.series_of(kind)
        for s in series:
            if s not in known:
                raise InputError.at("bearing.series", series,
                                    f"series \"{s}\" of {_type_words(kind)} bearings is not in the "
                                    f"catalogue; known: " + ", ".join(f'"{k}"' for k in known))
    rows = CAT.candidates(kind, d, series)
    if not rows:
        all_bores = CAT.bores(kind)
        near = sorted(sorted(all_bores, key=lambda x: abs(x - d))[:2])
        raise InputError.at("bearing.d", d, f"no catalogue {_type_words(kind)} bearing has this "
                                            f"bore; nearest catalogue bores: "
                                            + ", ".join(_f(x) for x in near) + f" mm (of "
                                            f"{_f(all_bores[0])}…{_f(all_bores[-1])} mm)")
    return kind, d, rows, replaced, req["life"]


def _select(spec: ValidatedSpec, problems: Problems):
    blocks = problems.stage(resolve_blocks, spec)
    problems.stage(_no_pair, spec)
    keys = problems.stage(_select_keys, spec)
    if blocks is Problems.FAILED or keys is Problems.FAILED:
        return None
    found = problems.stage(_candidates, spec, *keys, blocks)
    return None if found is Problems.FAILED else found


def _candidates(spec: ValidatedSpec, kind: str, d: float, rows: list, replaced: tuple,
                life: float, blocks: list) -> SelectInputs:
    f0 = spec.data["bearing"]["f0"]
    bearings = [catalogue_bearing(row) for row in rows]
    if f0 is not None:
        bearings = [replace(cand, f0=f0) for cand in bearings]
    # the conditions of the smallest candidate serve them all
    cond, ignored = resolve_conditions(spec, bearings[0])
    candidates = tuple((row, with_c_u(cand, cond)) for row, cand in zip(rows, bearings))
    return SelectInputs(kind, d, candidates, tuple(blocks), cond, ignored, replaced, life)


def _pair_inputs(spec: ValidatedSpec, blocks: list) -> PairInputs:
    p = spec.data["pair"]
    if p is None:
        raise InputError(Problem("pair", "missing; required in mode = \"pair\": bearing B's "
                                         "arrangement and radial load F_r"))
    if len(blocks) != 1:
        raise InputError(Problem("load.spectrum", "mode = \"pair\" takes a single load case "
                                 "(load.F_r, F_a, speed), not a spectrum"))
    A, facts_a = resolve_bearing(spec)
    if A.kind not in PR.pair_types():
        raise InputError.at("bearing.type" if spec.data["bearing"]["type"] else
                            "bearing.designation", spec.data["bearing"]["type"] or
                            spec.data["bearing"]["designation"],
                            "a pair with induced axial loads is one of angular contact ball "
                            "or tapered roller bearings")
    B, facts_b = _bearing_b(spec, A.kind)
    blk = blocks[0]
    F_a = blk.F_a
    ld = spec.data["load"]
    if "load.F_a" not in spec.assumed and ld["F_a"] is not None:
        F_a = ld["F_a"]
    needs_induced(A, "bearing")
    needs_induced(B, "pair")
    cond, ignored = resolve_conditions(spec, A)
    return PairInputs(with_c_u(A, cond), facts_a, with_c_u(B, cond), facts_b, blk, p["F_r"],
                      F_a, p["induced_factor"], p["arrangement"], cond, ignored)


def _pair(spec: ValidatedSpec, problems: Problems):
    blocks = problems.stage(resolve_blocks, spec)
    if blocks is Problems.FAILED:
        return None
    found = problems.stage(_pair_inputs, spec, blocks)
    return None if found is Problems.FAILED else found


_MODES = {"check": _check, "select": _select, "pair": _pair}


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The input stages on a spec whose schema problems are reported."""
    mode = spec.data["mode"]
    if isinstance(mode, str) and mode in _MODES:
        _MODES[mode](spec, problems)


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated spec, by its mode; every independent problem in one
    :class:`InputError`."""
    problems = Problems()
    inp = _MODES[spec.data["mode"]](spec, problems)
    problems.raise_all()
    return inp


def assessment_error(exc: L.BearingError, data: dict) -> InputError:
    """A formula's domain error as an input error naming the key (and its value)."""
    section, _, name = exc.key.partition(".")
    value = data.get(section, {}).get(name) if isinstance(data.get(section), dict) else None
    return InputError(Problem(exc.key, str(exc), value) if value is not None
                      else Problem(exc.key, str(exc)))
