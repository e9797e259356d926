"""Robustness: every example spec, mutated (numbers to 0, negative, tiny, huge, NaN,
infinity; types swapped; keys deleted and added; arrays emptied, cut or grown; inline
drive stages likewise), either computes — a JSON document without NaN, infinity or a
negative safety factor — or is refused with input errors.  Never another exception,
never a run over its time bound.

The engine is ``tests/fuzz.py``; ``python benchmarks/fuzz_long.py 20000`` runs the long
version (README, "Robustness").
"""

import json
import random

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests import fuzz

BASES = {p: __import__("tomllib").loads(p.read_text(encoding="utf-8"))
         for p in fuzz.spec_files()}
FILES = sorted(BASES)


@settings(max_examples=400, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(FILES), st.integers(0, 2 ** 32 - 1))
def test_mutated_specs_end_in_a_result_or_an_input_error(path, seed):
    data = fuzz.mutate(BASES[path], random.Random(seed))
    failure = fuzz.run_case(data, path.name, path.parent, seconds=10)
    assert failure is None, f"{failure}\n{json.dumps(data, default=str)[:3000]}"
