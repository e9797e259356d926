"""Robustness: every golden spec with a few of its numbers perturbed (scaled, zeroed,
negated) must either compute (pass or fail, JSON without NaN) or be refused with input
errors — never raise anything else.  A fixed seed keeps the run reproducible."""

import copy
import json
import random
import tomllib

import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data
from tests.conftest import SPECS

SLOW = ("comparison", "paper_spacing")   # numerical integrations: covered by their own tests
FUZZED = [p for p in sorted(SPECS.glob("*.toml")) if not any(s in p.name for s in SLOW)]
RUNS = 12


def _leaves(d, path=()):
    if isinstance(d, dict):
        for k, v in d.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(d, list):
        for i, v in enumerate(d):
            yield from _leaves(v, path + (i,))
    else:
        yield path, d


def _set(d, path, value):
    for p in path[:-1]:
        d = d[p]
    d[path[-1]] = value


@pytest.mark.parametrize("spec", FUZZED, ids=[p.stem for p in FUZZED])
def test_perturbed_specs_never_crash(spec):
    base = tomllib.loads(spec.read_text(encoding="utf-8"))
    numbers = [(p, v) for p, v in _leaves(base)
               if isinstance(v, (int, float)) and not isinstance(v, bool)]
    rng = random.Random(spec.name)
    for _ in range(RUNS):
        data = copy.deepcopy(base)
        for path, v in rng.sample(numbers, min(len(numbers), rng.randint(1, 3))):
            if isinstance(v, int):
                new = max(0, v + rng.choice((-3, -1, 1, 2, 5, 20, 1 - v)))
            else:
                new = v * rng.choice((0.0, 0.01, 0.1, 0.5, 0.9, 1.1, 2.0, 10.0, 100.0, -1.0))
            _set(data, path, new)
        try:
            calc, s = load_data(data, spec.name)
            s.base_dir = spec.parent
            doc = calc.compute(s).document()
        except InputError:
            continue
        json.dumps(doc, allow_nan=False)
