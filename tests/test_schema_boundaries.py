"""Schema boundaries: for every kind and every numeric field (and every field with choices)
of its spec schema, an example spec of that kind with that field at its minimum, its
maximum, just inside and just outside each, or at each choice, one field at a time; then
random combinations of several fields at such values.  Every case ends in a result (exit 0
or 1) whose document holds no NaN or infinity, whose messages print no ``nan``/``inf`` and
which every report format renders, or in input errors that each name a key (exit 2) —
never in an internal error (exit 3).

The cases are built from the schemas (``geardesign schema KIND``) by ``tests/fuzz.py``.  CI
runs a fixed-seed sample of them; ``GEARDESIGN_BOUNDARY_CASES=N`` runs N (``all``: every
field in every example spec of its kind, every format each time), and
``GEARDESIGN_BOUNDARY_COMBINATIONS=N`` sets the number of random combinations.
"""

from __future__ import annotations

import functools
import json
import os
import random

import pytest

from geardesign.core.registry import get
from tests import fuzz

SEED = 27
SAMPLE = os.environ.get("GEARDESIGN_BOUNDARY_CASES", "1500")
COMBINATIONS = int(os.environ.get("GEARDESIGN_BOUNDARY_COMBINATIONS", "300"))
TABLE_EVERY = 1 if SAMPLE == "all" else 12
"""The rich table is the slowest renderer by far: in the CI sample every 12th case renders
it (every case renders the other formats)."""

BASES = fuzz.base_specs()


def _formats(i: int) -> tuple:
    other = tuple(f for f in fuzz.TEXT_FORMATS if f != "table")
    return other + (("table",) if i % TABLE_EVERY == 0 else ())


@functools.cache
def _cases() -> tuple:
    """The sample (built once: two tests read it)."""
    every = SAMPLE == "all"
    cases = list(fuzz.boundary_cases(BASES, random.Random(SEED), every_spec=every))
    if not every and int(SAMPLE) < len(cases):
        # a sample that still holds every (kind, field): one value of each first
        rng = random.Random(SEED)
        rng.shuffle(cases)
        seen, first, rest = set(), [], []
        for c in cases:
            key = (c[2]["kind"], c[3].split(" ")[0])
            (rest if key in seen else first).append(c)
            seen.add(key)
        cases = (first + rest)[:max(int(SAMPLE), len(first))]
    return tuple(cases)


def _verdicts(cases, formats_of) -> list[str]:
    failures = []
    for i, (source, base_dir, data, label) in enumerate(cases):
        found = fuzz.run_case(data, source, base_dir, seconds=60, formats=formats_of(i))
        if found:
            failures.append(f"{found}\n    [{label}] {json.dumps(data, default=str)[:600]}")
    return failures


def test_every_field_at_its_boundaries_one_at_a_time():
    cases = _cases()
    failures = _verdicts(cases, _formats)
    assert not failures, f"{len(failures)} of {len(cases)} cases:\n" + "\n".join(failures[:20])


def test_random_combinations_of_boundary_values():
    rng = random.Random(SEED + 1)
    cases = [fuzz.combination(BASES, rng, k=rng.randint(2, 6)) for _ in range(COMBINATIONS)]
    failures = _verdicts(cases, _formats)
    assert not failures, f"{len(failures)} of {len(cases)} cases:\n" + "\n".join(failures[:20])


def test_the_sample_covers_every_kind_and_every_field():
    """The CI sample holds at least one case of every field of every kind's schema."""
    want = {(kind, ".".join(map(str, path)))
            for kind in BASES for path, _ in fuzz.schema_fields(
                get(kind).schema.root)}
    got = set()
    for source, _, data, label in _cases():
        got.add((data["kind"], label.split(" ")[0]))
    assert want <= got, sorted(want - got)[:10]


@pytest.mark.parametrize("kind", sorted(BASES))
def test_every_choice_and_bound_of_a_kind_is_reachable(kind):
    """Each kind has an example spec and numeric fields with both bounds (the case list is
    not empty by accident)."""
    fields = list(fuzz.schema_fields(get(kind).schema.root))
    assert fields and BASES[kind]
    assert all(fuzz.boundary_values(f) for _, f in fields)

