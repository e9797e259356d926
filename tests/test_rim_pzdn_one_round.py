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
    ("blank_size = 34.0\n", "blank_size = 34.0\nsigma_m1 = 800.0\n",
     "material.sigma_m1 = 800.0: must be below sigma_u"),
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


PZDN_MISTAKES = (
    ("peak_torque = 48.6", "peak_torque = 10.0",
     "coupling_gear.peak_torque = 10.0: smaller than the working torque"),
    ('grade = "45"', 'grade = "46"', 'coupling_gear.pinion.grade = "46": unknown steel'),
    ("sigma_allow = 1200.0\n", "sigma_allow = 1200.0\nsigma_over_tau = 1.5\n",
     "spring[0].sigma_over_tau = 1.5: give sigma_allow or sigma_over_tau"),
    ("pitch = 8.0\nsigma_allow = 1000.0", "pitch = 5.0\nsigma_allow = 1000.0",
     "spring[1].pitch = 5.0: smaller than the wire diameter"),
    ("coils = 5\n", 'coils = 5\ncurvature_factor = "wahll"\n',
     'spring[1].curvature_factor = "wahll": must be one of'),
    ("coil_diameter = 54.0\n", "coil_diameter = 54.0\nleg_arm = 20.0\n",
     "spring[1].leg_arm = 20.0: must exceed the coil radius"),
    ("C12 = 8.33\n", 'C12 = 8.33\nC12_spring = "x"\n',
     'startup.C12_spring = "x": give C12 or C12_spring, not both'),
    ("C13 = 25.0\n", 'C13_spring = "y"\n',
     'startup.C13_spring = "y": no [[spring]] of that name'),
    ("J3 = 0.021\n", "J3 = 0.021\nkloss_max_torque = 48.0\n",
     'startup.kloss_max_torque = 48.0: applies only with motor_model = "kloss"'),
    ("drive_stiffness = 1940.0\n", "drive_stiffness = 1940.0\nC12 = 24.7\n",
     "regression.C12 = 24.7: give C12, or pzdn_stiffness"),
)

SECOND_SPRING = """
[[spring]]
torque = 20.0
wire_diameter = 6.0
coil_diameter = 54.0
coils = 5
pitch = 8.0
sigma_allow = 1000.0

"""


def _pzdn_tables() -> str:
    from tests.test_pzdn_inputs import BODY, REG, SPRING, STARTUP

    return ("\n" + SPRING[BODY:] + SECOND_SPRING + "\n" + STARTUP[BODY:] + "\n"
            + REG[BODY:])


def test_pzdn_every_independent_mistake_in_one_round(tmp_path):
    gear = (SPECS / "pzdn_ko2_coupling_gear.toml").read_text(encoding="utf-8")
    _refused_in_one_round(tmp_path, gear + _pzdn_tables(), PZDN_MISTAKES)


def test_pzdn_good_combined_spec_runs(tmp_path):
    gear = (SPECS / "pzdn_ko2_coupling_gear.toml").read_text(encoding="utf-8")
    path = tmp_path / "s.toml"
    path.write_text(gear + _pzdn_tables(), encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code in (0, 1) and "Traceback" not in err, err


def _same(a, b, depth: int = 0) -> bool:
    """Equal values, NaN equal to NaN, objects compared by their attributes."""
    import dataclasses
    import math

    if depth > 12:
        return True
    if isinstance(a, float) and isinstance(b, float):
        return a == b or (math.isnan(a) and math.isnan(b))
    if isinstance(a, (list, tuple)):
        return (type(a) is type(b) and len(a) == len(b)
                and all(_same(x, y, depth + 1) for x, y in zip(a, b)))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k], depth + 1) for k in a)
    if type(a).__module__ == "numpy":
        import numpy as np

        return bool(np.array_equal(a, b, equal_nan=True))
    if dataclasses.is_dataclass(a) or hasattr(a, "__dict__"):
        return type(a) is type(b) and _same(vars(a), vars(b), depth + 1)
    return a == b


def _pure(name: str, package: str) -> None:
    import importlib

    inputs = importlib.import_module(f"geardesign.{package}.inputs")
    solve = importlib.import_module(f"geardesign.{package}.solve").solve
    data = tomllib.loads((SPECS / name).read_text(encoding="utf-8"))
    _, spec = registry.load_data(data, name)
    inp = inputs.read(spec)
    before = copy.deepcopy(inp)
    first, second = solve(inp), solve(inp)
    assert _same(inp, before)
    assert _same(first, second)


@pytest.mark.parametrize("name", sorted(p.name for p in SPECS.glob("epicycle_rim_*.toml")))
def test_rim_solve_is_pure(name):
    _pure(name, "epicycle_rim")


@pytest.mark.parametrize("name", sorted(p.name for p in SPECS.glob("pzdn_*.toml")))
def test_pzdn_solve_is_pure(name):
    _pure(name, "pzdn")


def test_rim_schema_and_rule_mistakes_in_one_round(tmp_path):
    """A value refused by the schema (ring.z) leaves out only the rules that need it: the
    shifts' sum and the material are still checked."""
    _refused_in_one_round(tmp_path, _rim_spec(), (
        ("z = 64\n", "z = 5\n", "ring.z = 5: must be an integer >= 12"),
        RIM_MISTAKES[0], RIM_MISTAKES[2]))
