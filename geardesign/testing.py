"""Comparing result documents: the golden-file check of this project's suite, usable in a
user's own CI.

:func:`compare_documents` walks two JSON result documents and returns every difference:
structure and strings exactly, numbers to a relative tolerance that suits how each is
computed:

* a scalar to ``rtol`` (closed forms and solvers that run at 1e-12 agree to ~1e-12 on any
  machine), or to the looser tolerance of the solver that computed it (:data:`TOLERANCES`),
  and to ``atol`` absolutely (a quantity whose exact value is 0 is a rounding residue whose
  digits depend on the BLAS build and thread count);
* an array (a list of numbers, or of lists of numbers: a moment diagram, a time history)
  element by element to ``rtol`` times the array's largest magnitude (and ``atol``), so that
  a point near zero of a diagram is held to the precision of the diagram, not to its own
  digits; likewise each numeric column of a table (a list of rows of one kind: a shaft's
  supports or sections, a drive's stages), whose small entries (a reaction of 200 N beside
  one of 1560 N, from one linear solve) are as precise as its largest;
* an error *estimate* of a numerical method (its exact value depends on the numpy/scipy
  build) only below its bound (:data:`BOUNDS`, :data:`BOUND_CHECKS`).
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

from geardesign.core.records import dataclass

IGNORED = ("geardesign", "spec")
"""Keys of a document (and of the documents nested in it) that are not results: the program
version and the path of the spec."""

RTOL = 1e-9
"""Default relative tolerance: the precision every closed-form and solver result reaches
(solvers run at rtol 1e-12 or tighter, except those of :data:`TOLERANCES`)."""

ATOL = 1e-9
"""Default absolute tolerance, in each quantity's own unit (mm, N, N·m, MPa, s, rad, ...):
no result that matters is below 1e-6 in its unit, and the rounding residues of quantities
whose exact value is 0 (a coaxiality residual, the power of a fixed ring, a bearing force of
a balanced planet, the residual angle of an iterated pressure angle) reach 3e-10."""

TOLERANCES = {
    r"(^|\.)thermal\.": 1e-6,
    r"(^|\.)losses\.": 1e-6,
    r"(^|\.)ode\.": 1e-8,
}
"""Results of solvers looser than :data:`RTOL`, by key pattern: relative tolerance ten times
the solver's.  A drive's heat balance (the sump temperature and the thermal power limit by
bisection to 1e-7, ``drive/heat.py``) and the losses evaluated at that temperature; the
peaks of the pzdn start-up integration (DOP853 at rtol 1e-12, whose global error is larger
than its local tolerance and depends on the scipy version's step sequence)."""

BOUNDS = {
    r"(^|\.)floquet_max_dev$": 1e-6,
}
"""Error estimates, by key pattern: only ``value <= bound`` is required (the estimate of
the Floquet check is ~1e-9 and its digits depend on the LAPACK build)."""

BOUND_CHECKS = {"FLOQUET": 1e-6}
"""Checks whose ``value`` is such an error estimate, by check code: the value need only
stay below the bound, and the digits of the number in the message are not compared."""

_DIGITS = re.compile(r"[-+]?\d+(\.\d+)?([eE][-+]?\d+)?")


@dataclass(frozen=True)
class Difference:
    path: str
    old: Any
    new: Any

    @property
    def change(self) -> str:
        """The relative change of a number in per cent, or "changed"."""
        if _number(self.old) and _number(self.new) and self.old:
            return f"{(self.new - self.old) / abs(self.old) * 100.0:+.4g} %"
        return "changed"

    def line(self) -> str:
        return f"{self.path}: {self.old!r} -> {self.new!r} ({self.change})"


def _number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _bound(path: str) -> float | None:
    for pattern, bound in BOUNDS.items():
        if re.search(pattern, path):
            return bound
    return None


def compare_documents(actual: Any, expected: Any, rtol: float = RTOL,
                      atol: float = ATOL) -> list[Difference]:
    """Every difference between two result documents (empty when they agree): numbers to
    ``rtol`` (a scalar relative to itself, an array's elements relative to the array's
    largest magnitude; :data:`TOLERANCES` loosen the results of coarser solvers) and to
    ``atol`` absolutely; error estimates below their bound; all else exactly."""
    out: list[Difference] = []
    _walk(actual, expected, "", rtol, atol, out)
    return out


def _rtol(path: str, rtol: float) -> float:
    for pattern, tol in TOLERANCES.items():
        if re.search(pattern, path):
            return max(rtol, tol)
    return rtol


def _leaves(v: Any) -> list | None:
    """The numbers of an array (a non-empty list of numbers or of such lists), else None."""
    if not isinstance(v, list) or not v:
        return None
    out = []
    for x in v:
        if _number(x):
            out.append(x)
        else:
            sub = _leaves(x)
            if sub is None:
                return None
            out.extend(sub)
    return out


def _table(v: list) -> bool:
    """Rows of one kind (supports, sections, stages): dicts that are neither checks (whose
    values are of every kind) nor documents."""
    return all(isinstance(r, dict) and "code" not in r and "results" not in r for r in v)


def _walk(a: Any, e: Any, path: str, rtol: float, atol: float, out: list,
          scale: float | dict | None = None) -> None:
    """``scale``: the largest magnitude of the array a number belongs to, or of each column
    (by key) of the table a row belongs to."""
    if isinstance(e, dict) and isinstance(a, dict):   # every document, nested ones too
        a = {k: v for k, v in a.items() if k not in IGNORED}
        e = {k: v for k, v in e.items() if k not in IGNORED}
    if isinstance(e, dict):
        if not isinstance(a, dict) or list(a) != list(e):
            out.append(Difference(path or "$", _keys(e), _keys(a)))
            return
        estimate = BOUND_CHECKS.get(e.get("code")) if isinstance(e.get("code"), str) else None
        columns = scale if isinstance(scale, dict) else {}
        for k in e:
            sub = f"{path}.{k}" if path else k
            if estimate is not None and k == "value" and _number(a[k]) and _number(e[k]):
                if not (abs(a[k]) <= estimate and abs(e[k]) <= estimate):
                    out.append(Difference(sub, e[k], a[k]))
            elif estimate is not None and k == "message" and isinstance(a[k], str) \
                    and isinstance(e[k], str):
                if _DIGITS.sub("#", a[k]) != _DIGITS.sub("#", e[k]):
                    out.append(Difference(sub, e[k], a[k]))
            else:
                _walk(a[k], e[k], sub, rtol, atol, out, columns.get(k))
    elif isinstance(e, list):
        if not isinstance(a, list) or len(a) != len(e):
            out.append(Difference(path, _size(e), _size(a)))
            return
        if scale is None:
            leaves = _leaves(e)
            if leaves is not None:     # an array: one scale, its largest magnitude
                scale = max(abs(x) for x in leaves)
            elif _table(e):            # rows of one kind: each numeric column an array
                scale = {k: max(abs(r[k]) for r in e if _number(r.get(k)))
                         for k in {k for r in e for k, v in r.items() if _number(v)}}
        for i, (x, y) in enumerate(zip(a, e)):
            _walk(x, y, f"{path}[{i}]", rtol, atol, out, scale)
    elif _number(e) and _number(a):
        bound = _bound(path)
        if bound is not None:
            if not (abs(a) <= bound and abs(e) <= bound):
                out.append(Difference(path, e, a))
            return
        tol = _rtol(path, rtol) * max(scale if isinstance(scale, float | int) else 0.0,
                                       abs(a), abs(e))
        if not (math.isfinite(a) and math.isfinite(e) and abs(a - e) <= max(tol, atol)) \
                and a != e:
            out.append(Difference(path, e, a))
    elif a != e:
        out.append(Difference(path, e, a))


def _keys(d: Any) -> Any:
    return sorted(d) if isinstance(d, dict) else d


def _size(v: Any) -> Any:
    return f"[{len(v)} items]" if isinstance(v, list) else v


# --------------------------------------------------------------------------- golden files


def expected_path(spec) -> "Path":
    """``specs/x.toml`` -> ``specs/x.expected.json``."""
    from pathlib import Path

    spec = Path(spec)
    return spec.with_name(spec.name[: -len(spec.suffix)] + ".expected.json") if spec.suffix \
        else spec.with_name(spec.name + ".expected.json")


def _drop_paths(doc: Any) -> Any:
    if isinstance(doc, dict):
        return {k: _drop_paths(v) for k, v in doc.items() if k != "spec"}
    if isinstance(doc, list):
        return [_drop_paths(v) for v in doc]
    return doc


def golden_text(doc: dict) -> str:
    """The stored form of a result document: indented JSON without machine paths."""
    from geardesign.core.text import json_text

    return json_text(_drop_paths(doc), indent=2) + "\n"


def check_golden(spec, update: bool = False, rtol: float = RTOL,
                 atol: float = ATOL) -> list[Difference]:
    """Compute ``spec`` and compare it with its expected document (see :func:`expected_path`);
    with ``update`` the expected file is (re)written instead.  A changed verdict is always
    reported.  Raises :class:`geardesign.core.errors.InputError` for an unusable spec and
    ``FileNotFoundError`` when there is no expected file (and no ``update``).  The expected
    file is read and written through :mod:`geardesign.core.io`: a regular file of bounded
    size and nesting, written atomically, never through a link to a file outside the spec's
    folder."""
    from geardesign.core.errors import InputError, Problem
    from geardesign.core.io import check_target, read_json, write_atomic
    from geardesign.core.paths import resolved
    from geardesign.core.registry import load
    from geardesign.core.spec import load_toml

    path = expected_path(spec)
    try:
        folder = resolved(Path(spec).absolute().parent)
    except OSError as exc:
        raise InputError(Problem("", f"cannot be read ({exc.strerror})")) from None
    if update:                             # before the work: refused targets cost nothing
        check_target(path, folder, path.name, (spec,))
    data = load_toml(spec)                 # read once: a sweep spec or a calculator's spec
    if "sweep" in data:
        from geardesign.spur.sweep import run_data as run_sweep_data

        doc = run_sweep_data(data, str(spec)).document()
    else:
        calc, vspec = load(spec, data=data)
        doc = calc.compute(vspec).document()
    if update:
        write_atomic(path, golden_text(doc), inside=folder)
        return []
    expected = read_json(path, label=path.name)
    return compare_documents(doc, expected, rtol=rtol, atol=atol)


def golden_tests(folder, rtol: float = RTOL, atol: float = ATOL):
    """A pytest test over every ``*.toml`` with an ``*.expected.json`` beside it in
    ``folder``; in a test module of your project::

        from geardesign.testing import golden_tests
        test_golden = golden_tests("specs")

    ``pytest`` then fails on every spec whose results moved, naming each quantity with
    its old and new value; ``geardesign check --update SPEC`` rewrites an expected file on
    purpose."""
    from pathlib import Path

    import pytest

    specs = sorted(p for p in Path(folder).glob("*.toml") if expected_path(p).exists())

    @pytest.mark.parametrize("spec", specs, ids=[p.stem for p in specs])
    def test_golden(spec):
        moved = check_golden(spec, rtol=rtol, atol=atol)
        assert not moved, "\n".join(d.line() for d in moved[:50])

    return test_golden
