"""``solve(inputs)`` of the split calculators is pure (issue 28, "inputs → solve → report"):
it reads only its typed inputs, changes none of them (nor the spec they came from), and
gives the same record on a second call; the report then needs nothing else to show it."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from geardesign.core import registry

SPECS = Path(__file__).resolve().parent.parent / "specs"

KINDS = {
    "novikov": ("geardesign.novikov.inputs", "geardesign.novikov.solve"),
    "bearing": ("geardesign.bearing.inputs", "geardesign.bearing.solve"),
    "planetary": ("geardesign.planetary.inputs", "geardesign.planetary.solve"),
}

CASES = [(kind, p) for kind in KINDS for p in sorted(SPECS.glob(f"{kind}_*.toml"))]


def _read(kind: str, path: Path):
    import importlib

    _, spec = registry.load(path)
    inputs = importlib.import_module(KINDS[kind][0])
    solve = importlib.import_module(KINDS[kind][1]).solve
    return spec, inputs.read(spec), solve


@pytest.mark.parametrize("kind, path", CASES, ids=[p.stem for _, p in CASES])
def test_solve_changes_nothing_and_repeats_itself(kind, path):
    spec, inp, solve = _read(kind, path)
    data, assumed, before = copy.deepcopy(spec.data), list(spec.assumed), repr(inp)
    first = solve(inp)
    assert repr(inp) == before, "solve() changed its inputs"
    assert spec.data == data and spec.assumed == assumed, "solve() changed the spec"
    assert repr(solve(inp)) == repr(first), "a second solve() gave another record"


@pytest.mark.parametrize("kind, path", CASES[:1] + [c for c in CASES if "select" in c[1].stem
                                                     or "pair" in c[1].stem],
                         ids=lambda x: getattr(x, "stem", x))
def test_the_record_is_frozen(kind, path):
    import dataclasses

    _, inp, solve = _read(kind, path)
    record = solve(inp)
    assert dataclasses.is_dataclass(record) and record.__dataclass_params__.frozen
    assert dataclasses.is_dataclass(inp) and inp.__dataclass_params__.frozen


READERS = ("bearing", "epicycle_rim", "novikov", "planetary", "pzdn", "worm")
"""Calculators whose ``inputs.read(spec)`` turns a validated spec into typed inputs."""

READ_CASES = [(kind, p) for kind in READERS for p in sorted(SPECS.glob(f"{kind}_*.toml"))]


@pytest.mark.parametrize("kind, path", READ_CASES, ids=[p.stem for _, p in READ_CASES])
def test_a_spec_read_once_reads_again_alike(kind, path):
    """The advice re-rates a copy of a spec already read (``ValidatedSpec(data, assumed)``
    after :func:`read` dropped the defaults it does not echo): reading that copy gives the
    same inputs, never an exception (a planetary ISO spec once raised KeyError there)."""
    import importlib

    from geardesign.core.spec import ValidatedSpec

    read = importlib.import_module(f"geardesign.{kind}.inputs").read
    _, spec = registry.load(path)
    first = read(spec)
    again = ValidatedSpec(copy.deepcopy(spec.data), list(spec.assumed), spec.source,
                          spec.base_dir)
    assert repr(read(again)) == repr(first)
