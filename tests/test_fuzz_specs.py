"""Robustness: every example spec, mutated (a schema field at its bounds, just inside or
outside them, or at each choice; numbers to 0, negative, denormal, ±1e±300, NaN, infinity;
types swapped; keys deleted and added; arrays emptied, cut or grown; inline drive stages
likewise), either computes — a JSON document without NaN, infinity or a negative safety
factor, messages without ``nan``/``inf``, rendered in the format drawn — or is refused with
input errors that name a key.  Never another exception, never a run over its time bound.
Then the same through every command of the command line (``run`` in every format, the
kind's own command, ``validate``, ``check``): exit 0, 1 or 2, never 3.

The engine is ``tests/fuzz.py``; ``python benchmarks/fuzz_long.py 100000`` runs the long
version (README, "Robustness").  Hypothesis runs derandomized: a red run repeats.
"""

import json
import random
import shutil

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from tests import fuzz
from tests.helpers_cli import cli

BASES = {p: __import__("tomllib").loads(p.read_text(encoding="utf-8"))
         for p in fuzz.spec_files()}
FILES = sorted(BASES)
FORMATS = st.sampled_from(tuple(f for f in fuzz.FORMATS if f != "table") * 4 + ("table",))
"""Every format; the rich table, by far the slowest renderer, one draw in 21."""


@settings(max_examples=2000, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(FILES), st.integers(0, 2 ** 32 - 1), FORMATS)
def test_mutated_specs_end_in_a_result_or_an_input_error(path, seed, fmt):
    data = fuzz.mutate(BASES[path], random.Random(seed))
    failure = fuzz.run_case(data, path.name, path.parent, seconds=60, formats=(fmt,))
    assert failure is None, \
        f"{failure}\n{json.dumps(data, default=str)[:3000]}"


@pytest.fixture(scope="module")
def spec_dir(tmp_path_factory):
    """A copy of specs/ (stage files and expected files beside the mutated spec)."""
    d = tmp_path_factory.mktemp("specs")
    for p in fuzz.SPECS.iterdir():
        if p.is_file():
            shutil.copy(p, d / p.name)
    return d


COMMANDS = st.sampled_from(("run", "kind", "validate", "check"))


@settings(max_examples=300, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow,
                                 HealthCheck.function_scoped_fixture])
@given(st.sampled_from(FILES), st.integers(0, 2 ** 32 - 1), COMMANDS, FORMATS)
def test_mutated_specs_through_every_command(spec_dir, path, seed, command, fmt):
    data = fuzz.mutate(BASES[path], random.Random(seed))
    case = spec_dir / f"case_{path.name}"
    case.write_text(fuzz.toml_text(data), encoding="utf-8")
    expected = fuzz.SPECS / path.name.replace(".toml", ".expected.json")
    if expected.exists():
        shutil.copy(expected, case.with_name(case.name.replace(".toml", ".expected.json")))
    kind = data["kind"]
    args = {"run": ("run", case, "--format", fmt), "kind": (kind, case, "--format", fmt),
            "validate": ("validate", case), "check": ("check", case)}[command]
    code, out, err = cli(*args)
    assert code in (0, 1, 2), f"exit {code}: {err[-2000:]}\n{fuzz.toml_text(data)[:2000]}"
    assert "internal error" not in err and "Traceback" not in err, err
