"""Advice found by re-rating, for every calculator: a failed check whose advice names a
spec change carries that change as ``Check.fix``, and the change is one that passes.

A calculator lists its *levers* in ``geardesign.<kind>.levers.LEVERS``: each names the
error checks it can make pass and yields candidate changes of the spec, smallest first
(a larger standard diameter, the next catalogue bearing, a shorter roller, ...).  For each
lever whose checks fail, :func:`advise` writes each candidate into the spec as written
(:func:`apply_fix`), re-rates it with the calculator itself and takes the first at which
every failed check of the lever passes and no error check that passes now fails.  The
search is bounded (:data:`MAX_TRIES` candidates per lever); when no candidate passes the
check keeps its own words and carries no fix.  A closed form is not trusted: the candidate
is always re-rated, so that the advice passes as printed.

A lever ``per_check`` proposes one fix for each failed check at once (a drive's bearing,
shaft and connection checks, each found by re-rating that part alone with the loads the
drive computed): all proposed fixes are written in together and the spec re-rated once;
each check that then passes carries its own fix (at most :data:`MAX_PROPOSALS` proposals).
"""

from __future__ import annotations

import copy
import math
import dataclasses
import re
from collections.abc import Callable, Iterable

from geardesign.core.errors import InputError
from geardesign.core.rerating import RERATING as _RERATING
from geardesign.core.rerating import rerating  # noqa: F401 (API)
from geardesign.core.result import Result, fix_text

MAX_TRIES = 40
"""Candidates re-rated per lever at most."""

MAX_PROPOSALS = 2
"""Proposals of a ``per_check`` lever re-rated at most."""


@dataclasses.dataclass(frozen=True)
class Lever:
    """``codes``: the error checks this lever can make pass; ``candidates(data, result)``
    yields changes ``((key, value), ...)`` of the spec as written (``data``), in the order
    in which they are preferred; ``what`` says in words what the change is ("the next
    standard diameters").  ``per_check``: ``candidates`` yields proposals
    ``{code: (fix, what)}``, one fix per failed check, re-rated together (see the
    module).  ``supersedes``: regular expressions of clauses of the check's
    own words that the found change replaces (the same lever as a figure the user would
    not set, such as a centre distance scaled by a factor); they are left out of the
    message that carries the change."""

    codes: tuple[str, ...]
    candidates: Callable[[dict, Result], Iterable]
    what: str
    per_check: bool = False
    supersedes: tuple[str, ...] = ()


def without(message: str, clauses: Iterable[str]) -> str:
    """``message`` without each clause matching one of the regular expressions ``clauses``,
    with the "or" that joined it to the rest."""
    for pattern in clauses:
        m = re.search(pattern, message)
        if m is None:
            continue
        before, after = message[:m.start()], message[m.end():]
        for joint in (", or ", " or "):
            if after.startswith(joint):
                after = after[len(joint):]
                break
            if before.endswith(joint):
                before = before[:-len(joint)]
                break
        message = re.sub(r":\s*;", ";", before + after).rstrip(": ")
    return message


_PART = re.compile(r"([^.\[\]]+)(?:\[(\d+)\])?")


def apply_fix(data: dict, fix) -> dict:
    """A copy of the spec ``data`` with the values of ``fix`` (pairs or a mapping) written
    in.  Keys are dotted paths as the checks print them: ``gear.face_width``,
    ``step[2].diameter``, ``stage[0].gear.module`` (array items counted from 0, as in the
    input error messages)."""
    out = copy.deepcopy(data)
    for key, value in (fix.items() if isinstance(fix, dict) else fix):
        parts = [(m.group(1), m.group(2)) for m in _PART.finditer(key)]
        node = out
        for i, (name, index) in enumerate(parts):
            last = i == len(parts) - 1
            if index is None:
                if last:
                    node[name] = value
                else:
                    node = node.setdefault(name, {})
            else:
                node = node[name][int(index)]
                if last:
                    raise KeyError(key)
    return out


def rerate(calc, spec, fix) -> Result | None:
    """The result of ``spec`` re-rated with ``fix`` written in, without advice; ``None``
    when the changed spec is refused."""
    from geardesign.core.spec import validate

    token = _RERATING.set(True)
    try:
        vs = validate(calc.schema, apply_fix(spec.raw, fix), spec.source)
        vs.base_dir = spec.base_dir
        return calc.rate(vs)
    except (InputError, ArithmeticError, ValueError, KeyError, IndexError, TypeError):
        return None
    finally:
        _RERATING.reset(token)


def passes(res: Result, todo: set, passing: set, known: set | None = None) -> bool:
    """Every check of ``todo`` passes in ``res``, every error check of ``passing`` still
    does, and no error check that the result before did not have (``known``: its codes)
    appears failed (a check a calculator makes only in some states, such as the limit
    torque of a clutch that no longer releases by speed)."""
    now = {c.code: c.passed for c in res.checks if c.severity == "error"}
    if not all(now.get(k, True) for k in passing):
        return False
    if known is not None and not all(ok for k, ok in now.items() if k not in known):
        return False
    return all(now.get(k, False) for k in todo)


def advise(calc, spec, res: Result, levers: Iterable[Lever]) -> Result:
    """``res`` with a fix on each failed check that a lever makes pass (see the module)."""
    if spec.raw is None or not res.failed:
        return res
    failed = {c.code for c in res.failed}
    passing = {c.code for c in res.checks if c.severity == "error" and c.passed}
    known = {c.code for c in res.checks}
    found: dict[str, tuple] = {}
    superseded: dict[str, tuple] = {}
    for lever in levers:
        todo = failed & set(lever.codes) - set(found)
        todo = {k for k in todo if not any(c.fix for c in res.failed if c.code == k)}
        if not todo:
            continue
        if lever.per_check:
            found.update(_per_check(calc, spec, res, lever, todo, passing))
            continue
        for n, fix in enumerate(lever.candidates(spec.raw, res)):
            if n >= MAX_TRIES:
                break
            again = rerate(calc, spec, fix)
            if again is not None and passes(again, todo, passing, known):
                for k in todo:
                    found[k] = (tuple(fix), lever.what)
                    superseded[k] = lever.supersedes
                break
    if not found:
        return res
    checks = []
    for c in res.checks:
        if c.code in found and not c.passed and not c.fix:
            fix, what = found[c.code]
            clauses = superseded.get(c.code, ())
            tail = f"; set {fix_text(fix)} ({what}; it passes when re-rated)"
            # the advice stays the end of the message (Check.advice), without the clauses
            # the fix replaces, as the message
            advice = (without(c.advice, clauses) + tail).lstrip("; ") if c.advice else ""
            c = dataclasses.replace(c, fix=fix, message=without(c.message, clauses) + tail,
                                    advice=advice)
        checks.append(c)
    res.checks = checks
    return res


def _per_check(calc, spec, res: Result, lever: Lever, todo: set, passing: set) -> dict:
    """The fixes of a ``per_check`` lever that pass when re-rated together (see the
    module): ``{code: (fix, what)}``."""
    found: dict = {}
    for n, proposal in enumerate(lever.candidates(spec.raw, res)):
        if n >= MAX_PROPOSALS:
            break
        proposal = {k: v for k, v in proposal.items() if k in todo and k not in found}
        merged: dict = {}
        for code, (fix, _) in list(proposal.items()):
            if any(merged.get(k, v) != v for k, v in fix):    # sets a key differently
                del proposal[code]
                continue
            merged.update(fix)
        if not proposal:
            continue
        again = rerate(calc, spec, tuple(merged.items()))
        if again is None:
            continue
        if not passes(again, set(), passing, {c.code for c in res.checks}):
            continue
        now = {c.code: c.passed for c in again.checks if c.severity == "error"}
        for code, (fix, what) in proposal.items():
            if now.get(code, False):
                found[code] = (tuple(fix), what)
        if set(todo) <= set(found):
            break
    return found


def fmt(v: float) -> str:
    """A number as the fix prints it (at most four decimals)."""
    return f"{v:.4f}".rstrip("0").rstrip(".")


def _get(data: dict, key: str):
    node = data
    for part in key.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node if isinstance(node, (int, float)) and not isinstance(node, bool) else None


def to_limit(code: str, key: str, up: bool, digits: int = 1, steps: int = 12,
             of: str = "limit", scale: Callable[[dict], float] | None = None):
    """Candidates for one spec key ``key`` read off the failed check ``code``: its
    ``limit`` (or ``value``, ``of = "value"``) times ``scale(data)`` (e.g. the module when
    the limit is a ratio to it), rounded to ``digits`` decimals away from the failure
    (``up``: the key must grow), then ``steps`` further steps of one last digit."""
    def gen(data: dict, res: Result):
        c = next((c for c in res.checks if c.code == code and not c.passed), None)
        v = None if c is None else getattr(c, of)
        if v is None:
            return
        v *= scale(data) if scale is not None else 1.0
        q = 10 ** digits
        first = math.ceil(v * q - 1e-9) if up else math.floor(v * q + 1e-9)
        for i in range(steps):
            x = (first + i if up else first - i) / q
            if x > 0:
                yield ((key, x),)
    return gen


def scaled(key: str, factors: Iterable[float], digits: int = 2,
           default: Callable[[dict], float | None] | None = None):
    """Candidates for one spec key: its present value (``default(data)`` when the spec
    does not give it) times each factor, rounded to ``digits`` decimals."""
    def gen(data: dict, _res: Result):
        v = _get(data, key)
        if v is None and default is not None:
            v = default(data)
        if v is None:
            return
        seen = set()
        for f in factors:
            x = round(v * f, digits)
            if x > 0 and x not in seen and x != v:
                seen.add(x)
                yield ((key, x),)
    return gen
