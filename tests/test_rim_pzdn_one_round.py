"""The epicycle_rim and pzdn calculators as inputs → solve → report: a spec with several
independent mistakes gets every line in one run (exit 2, nothing written), and ``solve()``
is pure (the same inputs give equal records and are left unchanged)."""

from __future__ import annotations

import copy
import tomllib
from pathlib import Path

import pytest

from geardesign.core import registry

from .helpers_cli import cli

SPECS = Path(__file__).resolve().parent.parent / "specs"

RIM_MISTAKES = (
    ("count = 3\n", "count = 3\nshifts = [0.4, 0.2, -0.5]\n",
     "planets.shifts = [0.4, 0.2, -0.5]: must sum to 0"),
    ("radius = 0.2\n", "radius = 4.6\n",
     "fillet.radius = 4.6: must be less than half the root chord"),
    ('grade = "30KhGSA"\n', 'grade = "30KhGSA"\nsigma_y = 800.0\n',
     "material.sigma_y = 800.0: must be below sigma_u"),
    ("form_factor = 3.3\n", "form_factor = 3.3\nnominal_bending_stress = 78.6\n",
     "load.nominal_bending_stress = 78.6: give either"),
    ('name = "acceleration"', 'name = "Acceleration"',
     'stage[0].name = "Acceleration": must be a lower-case name'),
    ("mu_F = 0.549\n", 'mu_F = 0.549\nmode = "light"\n',
     "stage[1]: give exactly one of mu_F, mode"),
    ("concentrator_depth = 0.635\n", "concentrator_depth = 0.635\nstress_gradient = 13.0\n",
     "fatigue.concentrator_depth = 0.635: not used when stress_gradient is given"),
    ("speed_range = [5.0, 55.0]", "speed_range = [55.0, 5.0]",
     "vehicle.speed_range = [55.0, 5.0]: must be [lowest, highest]"),
    ("natural_frequencies = [2233.0, 3770.0]\n",
     "natural_frequencies = [2233.0, 3770.0]\norders = [0]\n",
     "resonance.orders = [0]: must be a list"),
)


def _rim_spec() -> str:
    from tests.test_epicycle_rim_inputs import GOOD

    return GOOD


def _refused_in_one_round(tmp_path, text: str, mistakes) -> None:
    for old, new, _ in mistakes:
        assert old in text, old
        text = text.replace(old, new, 1)
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    out_file = tmp_path / "out.json"
    code, out, err = cli("run", path, "--format", "json", "--output", out_file)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and "Traceback" not in err
    assert not out_file.exists()
    for _, _, expected in mistakes:
        assert sum(expected in line for line in lines) == 1, (expected, lines)
    assert len(lines) == len(mistakes), lines


def test_rim_every_independent_mistake_in_one_round(tmp_path):
    _refused_in_one_round(tmp_path, _rim_spec(), RIM_MISTAKES)


def _pure(name: str, package: str) -> None:
    import importlib

    inputs = importlib.import_module(f"geardesign.{package}.inputs")
    solve = importlib.import_module(f"geardesign.{package}.solve").solve
    data = tomllib.loads((SPECS / name).read_text(encoding="utf-8"))
    _, spec = registry.load_data(data, name)
    inp = inputs.read(spec)
    before = copy.deepcopy(inp)
    first, second = solve(inp), solve(inp)
    assert inp == before
    assert repr(first) == repr(second)   # equal, NaN included


@pytest.mark.parametrize("name", sorted(p.name for p in SPECS.glob("epicycle_rim_*.toml")))
def test_rim_solve_is_pure(name):
    _pure(name, "epicycle_rim")
