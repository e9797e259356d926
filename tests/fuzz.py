"""A mutation fuzzer for spec files, shared by the fuzz test and ``benchmarks/fuzz_long.py``.

A case is an example spec from ``specs/`` with one to three mutations: a number set to 0,
negative, tiny (5e-324), huge (1e300), NaN or infinity, scaled; a value's type swapped; a
key deleted or added; an array emptied, shortened or lengthened; and for drive specs the
same inside inline stages.  :func:`run_case` computes it as the command line would and
returns ``None`` when the outcome is acceptable — a result whose JSON holds no NaN,
infinity or negative safety factor, whose check messages print no ``nan``/``inf`` and which
every report format renders, or an input error whose every line names a key — else a short
crash signature.

The schema side (:func:`schema_fields`, :func:`boundary_values`, :func:`boundary_cases`)
sets one field of a spec's schema at a time to its minimum, its maximum, just inside and
just outside each, or to every allowed choice; :func:`combination` sets several at once;
:func:`toml_text` writes any mutated spec back as TOML for the command line.
"""

from __future__ import annotations

import copy
import json
import math
import random
import re
import signal
import tomllib
import traceback
from pathlib import Path

from geardesign.core.errors import InputError
from geardesign.core.registry import get, load_data
from geardesign.core.render import FORMATS, render
from geardesign.core.result import ResultDomainError
from geardesign.core.spec import Field, Table, TableList

SPECS = Path(__file__).resolve().parent.parent / "specs"
SLOW = ("comparison", "paper_spacing")
"""Specs whose numerical integrations take most of a second: fuzzed in the long run only."""

NUMBERS = (0, -1.0, 5e-324, -5e-324, 2.2e-308, 1e-300, -1e-300, 1e300, -1e300,
           float("nan"), float("inf"), float("-inf"))
SCALES = (0.0, 1e-6, 0.01, 0.5, 2.0, 100.0, 1e6, -1.0)
SWAPS = ("12", [2], {}, True, None)

TEXT_FORMATS = tuple(f for f in FORMATS if f != "pdf")
"""The formats :func:`geardesign.core.render.render` writes.  A PDF is the "html" report
printed by Chromium (``render_pdf``, tested in ``tests/test_report_browser.py``); ``render``
itself has no PDF and falls back to the table for that name, so "pdf" here would render
the table a second time."""


def spec_files(include_slow: bool = False) -> list[Path]:
    return [p for p in sorted(SPECS.glob("*.toml"))
            if include_slow or not any(s in p.name for s in SLOW)]


def _paths(d, path=()):
    if isinstance(d, dict):
        yield path, d
        for k, v in d.items():
            yield from _paths(v, path + (k,))
    elif isinstance(d, list):
        yield path, d
        for i, v in enumerate(d):
            yield from _paths(v, path + (i,))
    else:
        yield path, d


def _parent(d, path):
    for p in path[:-1]:
        d = d[p]
    return d


def _schema_mutation(data: dict, rng: random.Random) -> None:
    """A field of the spec's schema at one of its :func:`boundary_values` (inside or out)."""
    try:
        fields = _FIELDS[data["kind"]]
    except KeyError:
        fields = _FIELDS[data["kind"]] = list(schema_fields(get(data["kind"]).schema.root))
    path, f = rng.choice(fields)
    set_path(data, path, rng.choice(boundary_values(f))[1])


_FIELDS: dict = {}


def mutate(base: dict, rng: random.Random) -> dict:
    """One to three random mutations of a parsed spec (``kind`` is kept): a schema field at
    a boundary value, or a value made degenerate, retyped, deleted, added or resized."""
    data = copy.deepcopy(base)
    for _ in range(rng.randint(1, 3)):
        if rng.random() < 0.3:
            _schema_mutation(data, rng)
            continue
        nodes = [(p, v) for p, v in _paths(data) if p and p != ("kind",)]
        if not nodes:
            break
        path, value = rng.choice(nodes)
        parent = _parent(data, path)
        key = path[-1]
        op = rng.random()
        if isinstance(value, (int, float)) and not isinstance(value, bool) and op < 0.6:
            new = (rng.choice(NUMBERS) if rng.random() < 0.5 else value * rng.choice(SCALES))
            if isinstance(value, int) and rng.random() < 0.5:
                new = rng.choice((0, -1, 1, 2, 10 ** 6, value + 1, value * 3))
            parent[key] = new
        elif isinstance(value, list) and op < 0.6:
            choice = rng.random()
            if choice < 0.3:
                value.clear()
            elif choice < 0.6 and value:
                del value[rng.randrange(len(value)):]
            elif value:
                value.extend(copy.deepcopy(value[: rng.randint(1, len(value))]))
        elif op < 0.75:
            if isinstance(parent, dict):
                del parent[key]
            elif isinstance(parent, list) and parent:
                parent.pop(key)
        elif op < 0.9:
            parent[key] = copy.deepcopy(rng.choice(SWAPS))
            if parent[key] is None:
                parent[key] = 0
        elif isinstance(value, dict):
            value[rng.choice(("extra", "z1", "module", "speed1"))] = rng.choice((1, "x", 1e300))
    return data


class Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise Timeout()


def bad_numbers(doc) -> str | None:
    """The first NaN, infinity or negative safety factor in a JSON document, if any."""
    def walk(d, path):
        if isinstance(d, dict):
            for k, v in d.items():
                r = walk(v, f"{path}.{k}" if path else k)
                if r:
                    return r
        elif isinstance(d, list):
            for i, v in enumerate(d):
                r = walk(v, f"{path}[{i}]")
                if r:
                    return r
        elif isinstance(d, float):
            if not math.isfinite(d):
                return f"{path} = {d}"
            last = path.rsplit(".", 1)[-1]
            if last.startswith("S_") and d < 0 and "min" not in last:
                return f"{path} = {d} (negative safety factor)"
        return None
    return walk(doc, "")


NONFINITE_WORD = re.compile(r"(?<![\w.])[-+]?(nan|inf|infinity)(?![\w])", re.IGNORECASE)
"""``nan``, ``inf``, ``-inf`` printed as a word in a message (not "information", not ∞)."""


def judge(calc, spec, formats=TEXT_FORMATS) -> str | None:
    """Compute a validated spec and render it in ``formats``: ``None`` when the outcome is
    acceptable (a result or an input error naming keys), else a short signature.  "pdf"
    stands for its content, the "html" report (:data:`TEXT_FORMATS`), rendered once."""
    try:
        res = calc.compute(spec)
    except ResultDomainError as exc:
        # the result's guard caught a derived quantity outside its formula's domain: the
        # calculator should have refused the input that leads there, naming it
        return f"input error naming no key: {exc.problems[0].message[:120]}"
    except InputError:
        return None
    doc = res.document()
    bad = bad_numbers(json.loads(json.dumps(doc, allow_nan=True)))
    if bad:
        return f"garbage: {bad}"
    for c in res.checks:
        if NONFINITE_WORD.search(c.message):
            return f"non-finite in message of {c.code}: {c.message[:120]}"
    for fmt in dict.fromkeys("html" if f == "pdf" else f for f in formats):
        try:
            text = render([res], fmt)
        except Exception as exc:  # noqa: BLE001 - the signature of a renderer crash
            tb = traceback.extract_tb(exc.__traceback__)[-1]
            return f"render {fmt}: {type(exc).__name__} at {Path(tb.filename).name}:{tb.lineno}"
        if fmt in ("json", "jsonl") and re.search(r"\b(NaN|-?Infinity)\b", text):
            return f"render {fmt}: a non-finite number"
    return None


def run_case(data: dict, source: str, base_dir: Path, seconds: int = 10,
             formats=()) -> str | None:
    """``None`` when the case ends acceptably, else a one-line signature."""
    # a bound on the process's CPU time (user and system), not on the wall clock: a case is
    # not "unbounded work" because the machine is busy
    old = signal.signal(signal.SIGPROF, _alarm)
    signal.setitimer(signal.ITIMER_PROF, seconds)
    try:
        calc, spec = load_data(data, source)
        spec.base_dir = base_dir
        found = judge(calc, spec, formats)
        return f"{source}: {found}" if found else None
    except InputError:
        return None
    except Timeout:
        return f"{source}: timeout > {seconds} s of CPU time"
    except RecursionError:
        return f"{source}: RecursionError"
    except Exception as exc:  # noqa: BLE001 - the signature of a crash
        tb = traceback.extract_tb(exc.__traceback__)[-1]
        return f"{source}: {type(exc).__name__} at {Path(tb.filename).name}:{tb.lineno}"
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, old)


def cases(seed: int, n: int, include_slow: bool = False):
    """``n`` reproducible cases ``(data, source, base_dir)``."""
    rng = random.Random(seed)
    files = spec_files(include_slow)
    bases = {p: tomllib.loads(p.read_text(encoding="utf-8")) for p in files}
    for _ in range(n):
        p = rng.choice(files)
        yield mutate(bases[p], rng), p.name, p.parent


# --------------------------------------------------------------------------- the schema


def schema_fields(table: Table, path: tuple = ()):
    """``(data path, field)`` for every numeric field and every field with choices of a
    schema table (the first item of an array of tables; ``kind`` left out)."""
    for m in table.fields:
        if isinstance(m, TableList):
            yield from schema_fields(m.item, path + (m.key, 0))
        elif isinstance(m, Table):
            yield from schema_fields(m, path + (m.key,))
        elif isinstance(m, Field) and m.key != "kind" and (m.numeric or m.choices):
            yield path + (m.key,), m


def _step(f: Field, x: float) -> float:
    """A step just inside or outside a bound ``x``: one part in 10⁶, at least the field's
    resolution."""
    return max(abs(x) * 1e-6, getattr(f, "_tiny", 0.0) or 1e-9)


def boundary_values(f: Field) -> list[tuple[str, object]]:
    """``(label, value)``: the field's minimum and maximum, just inside and just outside each,
    or each of its choices; an array field gets a list of its element count."""
    if f.choices:
        values = [(f"= {c!r}", c) for c in f.choices]
    else:
        out = []
        integer = f.type == "integer" or f.items == "integer"
        for name, x, inclusive, sign in (("min", f.minimum, True, 1), ("gt", f.gt, False, 1),
                                         ("max", f.maximum, True, -1), ("lt", f.lt, False, -1)):
            if x is None:
                continue
            if integer:
                x = math.ceil(x) if sign > 0 else math.floor(x)
                inside, outside = x + sign, x - sign
                x, inside, outside = int(x), int(inside), int(outside)
            else:
                d = _step(f, x)
                inside, outside = x + sign * d, x - sign * d
            if inclusive:
                out += [(f"{name}", x), (f"{name} inside", inside), (f"{name} outside", outside)]
            else:
                out += [(f"{name} (excluded)", x), (f"{name} inside", inside)]
        values = out
    if f.type == "array":
        n = max(f.min_items, 1)
        values = [(label, [v] * n) for label, v in values]
    return values


def set_path(data: dict, path: tuple, value) -> None:
    """Set ``value`` at ``path`` (keys and list indices), creating or replacing the tables
    (and a first array item) on the way."""
    node = data
    for k, nxt in zip(path[:-1], path[1:]):
        want = list if isinstance(nxt, int) else dict
        if isinstance(node, list):
            while len(node) <= k:
                node.append({})
        if not isinstance(node[k] if isinstance(node, list) else node.get(k), want):
            node[k] = want()
        node = node[k]
    if isinstance(node, list):
        while len(node) <= path[-1]:
            node.append({})
    node[path[-1]] = value


def base_specs(include_slow: bool = False) -> dict:
    """``{kind: [(path, parsed spec), ...]}`` of the example specs (a sweep's [sweep] table
    removed: the spur spec remains)."""
    out: dict = {}
    for p in spec_files(include_slow):
        data = tomllib.loads(p.read_text(encoding="utf-8"))
        data.pop("sweep", None)
        out.setdefault(data["kind"], []).append((p, data))
    return out


def boundary_cases(bases: dict, rng: random.Random | None = None, every_spec: bool = False):
    """``(source, base dir, data, label)``: for every kind and every field of its schema, the
    field at each of :func:`boundary_values`, one field at a time, in one example spec of
    that kind (chosen by ``rng``, else the first) or in each (``every_spec``)."""
    for kind, specs in bases.items():
        for path, f in schema_fields(get(kind).schema.root):
            chosen = specs if every_spec else [rng.choice(specs) if rng else specs[0]]
            for p, base in chosen:
                for label, value in boundary_values(f):
                    data = copy.deepcopy(base)
                    set_path(data, path, value)
                    yield p.name, p.parent, data, f"{'.'.join(map(str, path))} {label}"


def combination(bases: dict, rng: random.Random, k: int = 4):
    """One spec with ``k`` fields of its schema at random boundary values (inside mostly)."""
    kind = rng.choice(sorted(bases))
    p, base = rng.choice(bases[kind])
    fields = list(schema_fields(get(kind).schema.root))
    data = copy.deepcopy(base)
    labels = []
    for path, f in rng.sample(fields, min(k, len(fields))):
        values = boundary_values(f)
        inside = [v for v in values if "outside" not in v[0] and "excluded" not in v[0]]
        label, value = rng.choice(inside if inside and rng.random() < 0.9 else values)
        set_path(data, path, value)
        labels.append(f"{'.'.join(map(str, path))} {label}")
    return p.name, p.parent, data, "; ".join(labels)


# --------------------------------------------------------------------------- TOML out


def _toml_value(v) -> str:
    """A value as TOML: tables inline, lists element by element (an array of tables holds
    tables), scalars as the sweep's spec writer writes them (``nan``, ``inf`` included)."""
    from geardesign.spur.sweep_io import _toml_scalar

    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v if x is not None) + "]"
    if isinstance(v, dict):
        return "{" + ", ".join(f"{json.dumps(str(k))} = {_toml_value(x)}"
                               for k, x in v.items() if x is not None) + "}"
    return _toml_scalar(v)


def toml_text(data: dict) -> str:
    """Any parsed (and mutated) spec as TOML: one line a top-level key, tables inline."""
    return "".join(f"{json.dumps(str(k))} = {_toml_value(v)}\n"
                   for k, v in data.items() if v is not None)
