"""A mutation fuzzer for spec files, shared by the fuzz test and ``benchmarks/fuzz_long.py``.

A case is an example spec from ``specs/`` with one to three mutations: a number set to 0,
negative, tiny (5e-324), huge (1e300), NaN or infinity, scaled; a value's type swapped; a
key deleted or added; an array emptied, shortened or lengthened; and for drive specs the
same inside inline stages.  :func:`run_case` computes it as the command line would and
returns ``None`` when the outcome is acceptable — a result whose JSON holds no NaN,
infinity or negative safety factor, or an input error — else a short crash signature.
"""

from __future__ import annotations

import copy
import json
import math
import random
import signal
import tomllib
import traceback
from pathlib import Path

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data

SPECS = Path(__file__).resolve().parent.parent / "specs"
SLOW = ("comparison", "paper_spacing")
"""Specs whose numerical integrations take most of a second: fuzzed in the long run only."""

NUMBERS = (0, -1.0, 5e-324, 1e-300, 1e300, float("nan"), float("inf"), float("-inf"))
SCALES = (0.0, 1e-6, 0.01, 0.5, 2.0, 100.0, 1e6, -1.0)
SWAPS = ("12", [2], {}, True, None)


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


def mutate(base: dict, rng: random.Random) -> dict:
    """One to three random mutations of a parsed spec (``kind`` is kept)."""
    data = copy.deepcopy(base)
    for _ in range(rng.randint(1, 3)):
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


def run_case(data: dict, source: str, base_dir: Path, seconds: int = 10) -> str | None:
    """``None`` when the case ends acceptably, else a one-line signature."""
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(seconds)
    try:
        calc, spec = load_data(data, source)
        spec.base_dir = base_dir
        doc = calc.compute(spec).document()
        text = json.dumps(doc, allow_nan=True)
        bad = bad_numbers(json.loads(text))
        if bad:
            return f"{source}: garbage: {bad}"
        return None
    except InputError:
        return None
    except Timeout:
        return f"{source}: timeout > {seconds} s"
    except RecursionError:
        return f"{source}: RecursionError"
    except Exception as exc:  # noqa: BLE001 - the signature of a crash
        tb = traceback.extract_tb(exc.__traceback__)[-1]
        return f"{source}: {type(exc).__name__} at {Path(tb.filename).name}:{tb.lineno}"
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def cases(seed: int, n: int, include_slow: bool = False):
    """``n`` reproducible cases ``(data, source, base_dir)``."""
    rng = random.Random(seed)
    files = spec_files(include_slow)
    bases = {p: tomllib.loads(p.read_text(encoding="utf-8")) for p in files}
    for _ in range(n):
        p = rng.choice(files)
        yield mutate(bases[p], rng), p.name, p.parent
