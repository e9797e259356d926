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


def test_every_kind_has_an_example_spec_to_fuzz():
    """A calculator added without an example spec would escape every fuzz test above."""
    from geardesign.core.registry import known_kinds

    assert set(known_kinds()) <= {d["kind"] for d in BASES.values()}


INLINE = [(p, i, st["kind"]) for p, d in BASES.items() if d["kind"] == "drive"
          for i, st in enumerate(d.get("stage") or []) if st.get("kind")]
"""Every inline stage of an example drive spec: (spec, stage index, stage kind)."""


@settings(max_examples=300, deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(INLINE), st.integers(0, 2 ** 32 - 1))
def test_inline_stages_with_fields_at_their_bounds(stage, seed):
    """An inline drive stage (a bevel stage in every position, with each hand and sense of
    rotation among the choices) with one to four fields of its own kind's schema at their
    bounds, mostly just inside: a result or input errors naming a key, as above.  A stage
    kind with an inline example is covered without a change here."""
    path, i, kind = stage
    rng = random.Random(seed)
    data = __import__("copy").deepcopy(BASES[path])
    stages = data["stage"]
    stages.insert(rng.randrange(len(stages)), stages.pop(i))   # the stage in any position
    target = next(s for s in stages if s is not None and s.get("kind") == kind
                  and s.get("name") == BASES[path]["stage"][i].get("name"))
    fields = [(p, f) for p, f in fuzz.schema_fields(fuzz.get(kind).schema.root)]
    for p, f in rng.sample(fields, min(len(fields), rng.randint(1, 4))):
        values = fuzz.boundary_values(f)
        inside = [v for v in values if "outside" not in v[0] and "excluded" not in v[0]]
        fuzz.set_path(target, p, rng.choice(inside if inside and rng.random() < 0.9
                                            else values)[1])
    failure = fuzz.run_case(data, path.name, path.parent, seconds=60, formats=("json",))
    assert failure is None, f"{failure}\n{json.dumps(data, default=str)[:3000]}"


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(st.floats(1e-3, 1e4), st.sampled_from(("St", "V", "GGG", "GTS", "GG", "GGG_ferr", "Eh", "NT")),
       st.floats(1.0, 3000.0), st.floats(0.0, 200.0))
def test_running_in_allowances_stay_within_the_deviation(dev, material, sigma_Hlim, v):
    """ISO 6336-1 eqs. (61) and (75) give y_β = 320/σ_Hlim·F_βx and y_α = 160/σ_Hlim·f_pb:
    above the deviation itself for σ_Hlim below 320 (160) N/mm², leaving F_βy = F_βx − y_β
    negative, and with it K_Hβ (a drive stage with σ_Hlim = 150 crashed in the square root
    of the contact stress).  Capped: 0 <= y <= the deviation, every material, speed and
    σ_Hlim the schema allows."""
    from geardesign.spur.strength.iso6336 import part1 as P1

    for y in (P1.running_in_beta(dev, material, sigma_Hlim, v),
              P1.running_in_alpha(dev, material, sigma_Hlim, v)):
        assert 0.0 <= float(y) <= dev * (1 + 1e-12)

