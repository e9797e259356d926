"""The worked examples (``>>> ``) in the docstrings of every module of ``geardesign`` run as
tests, and every formula module carries at least one.

A *formula module* is a module whose public functions compute physics from the cited
equations (geometry, kinematics, loads, stresses, factors, lives, losses, heat, fits): its
examples are the reader's check of the equation against a handbook value or an identity.
Modules of input rules, reports, records, rendering and command line are not formula modules.
"""

from __future__ import annotations

import doctest
import importlib
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "geardesign"
FLAGS = doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(ROOT).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def with_examples() -> list[str]:
    """Modules whose source holds a ``>>> `` example (found without importing them)."""
    return sorted(_module_name(p) for p in PACKAGE.rglob("*.py")
                  if "__pycache__" not in p.parts and ">>> " in p.read_text(encoding="utf-8"))


EXAMPLES = with_examples()

FORMULA_MODULES = [
    # involute and shared gear geometry
    "geardesign.involute", "geardesign.gears.geometry", "geardesign.gears.internal_formulas",
    "geardesign.gears.span", "geardesign.gears.losses",
    # spur and helical pairs: kinematics, loads, measurement, tolerances
    "geardesign.spur.kinematics", "geardesign.spur.loads", "geardesign.spur.measurement",
    "geardesign.spur.tolerances.backlash", "geardesign.spur.tolerances.gost1643",
    "geardesign.spur.tolerances.iso1328",
    # strength: GOST 21354-87 and ISO 6336
    "geardesign.spur.strength.gost21354.contact", "geardesign.spur.strength.gost21354.bending",
    "geardesign.spur.strength.gost21354.load_factors",
    "geardesign.spur.strength.iso6336.part1", "geardesign.spur.strength.iso6336.part2",
    "geardesign.spur.strength.iso6336.part3", "geardesign.spur.strength.iso6336.part5",
    "geardesign.spur.strength.iso6336.part21", "geardesign.spur.strength.iso6336.tooth_form",
    # fatigue (GOST 25.504), shafts (DIN 743), connections (keys, splines, fits)
    "geardesign.fatigue.gost25504", "geardesign.fatigue.probability",
    "geardesign.shaft.strength", "geardesign.shaft.din743.part1",
    "geardesign.shaft.din743.part2", "geardesign.shaft.din743.part3",
    "geardesign.connection.key", "geardesign.connection.spline", "geardesign.connection.fit",
    "geardesign.connection.iso286",
    # bearings, bevel pairs, drive losses and heat
    "geardesign.bearing.life", "geardesign.bearing.pair", "geardesign.bearing.rib",
    "geardesign.bevel.geometry", "geardesign.bevel.forces", "geardesign.bevel.rating",
    "geardesign.bevel.gost_route",
    "geardesign.drive.losses", "geardesign.drive.thermal", "geardesign.drive.misalignment",
    "geardesign.drive.split",
    # worm, wave, Geneva, ball clutch, planetary kinematics
    "geardesign.worm.kinematics", "geardesign.worm.geometry",
    "geardesign.wave_gear.flexwheel", "geardesign.geneva.kinematics",
    "geardesign.ball_clutch.spring", "geardesign.planetary.kinematics",
    # spectra, beams, bearing factors, heat, efficiencies, contact and rim stresses, springs
    "geardesign.spur.strength.iso6336.part6", "geardesign.shaft.beam",
    "geardesign.bearing.a_iso", "geardesign.bearing.load_factors", "geardesign.drive.heat",
    "geardesign.planetary.efficiency", "geardesign.planetary.geometry",
    "geardesign.worm.strength", "geardesign.worm.thermal", "geardesign.novikov.stress",
    "geardesign.novikov.geometry", "geardesign.ball_clutch.contact",
    "geardesign.ball_clutch.clutch", "geardesign.epicycle_rim.stress",
    "geardesign.epicycle_rim.mathieu", "geardesign.pzdn.spring", "geardesign.pzdn.linear",
    "geardesign.novikov.factors", "geardesign.wave_gear.rim",
]
"""Formula modules that must carry at least one runnable example."""

FORMULA_NAMES = {"formulas", "geometry", "kinematics", "life", "contact", "bending",
                 "load_factors", "losses", "strength", "fatigue", "beam", "heat", "thermal",
                 "stress", "efficiency", "spring"}
"""Module names that say "physics": a new module of such a name is a formula module unless
:data:`NOT_FORMULA` says why not."""

NOT_FORMULA = {
    "geardesign.spur.strength.gost21354.formulas":
        "gathers the functions of contact, bending and load_factors under one name",
    "geardesign.planetary.strength": "rates each mesh by the spur rating (composition)",
    "geardesign.spur.strength.iso6336.scuffing": "composes the formulas of iso6336.part21",
    "geardesign.spur.profile": "samples flank outlines for the drawings from gears.geometry",
}
"""Modules that look like formula modules but compose or gather formulas kept elsewhere."""


def _modules() -> list[str]:
    return sorted(_module_name(p) for p in PACKAGE.rglob("*.py")
                  if "__pycache__" not in p.parts and p.name != "__init__.py")


@pytest.mark.parametrize("name", EXAMPLES)
def test_docstring_examples_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=FLAGS, report=False)
    assert result.failed == 0, f"{name}: {result.failed} of {result.attempted} examples fail"
    assert result.attempted > 0, f"{name}: a '>>> ' in the source but no example found"


@pytest.mark.parametrize("name", FORMULA_MODULES)
def test_every_formula_module_has_an_example(name):
    assert name in EXAMPLES, f"{name}: a formula module without a runnable example"


def test_modules_named_as_formulas_are_formula_modules():
    named = {m for m in _modules() if m.rsplit(".", 1)[-1] in FORMULA_NAMES}
    unlisted = sorted(named - set(FORMULA_MODULES) - set(NOT_FORMULA))
    assert not unlisted, f"formula modules missing from FORMULA_MODULES: {unlisted}"
    assert set(NOT_FORMULA) <= set(_modules()), "NOT_FORMULA names a module that is gone"
