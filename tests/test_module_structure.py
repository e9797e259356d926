"""The shape of the code (issue 28, "each calculator: inputs → solve → report"): no module
of the package over :data:`MAX_LINES` lines unless it is listed here with its reason, and the
calculators that are split show ``inputs.py`` (spec → typed inputs, every input rule),
``solve.py`` (inputs → record, pure) and ``report.py`` (record → rows and checks) behind a
short ``calculator.py``."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parent.parent / "geardesign"

MAX_LINES = 400
"""A module longer than this mixes what should be apart (rules, physics, rows, checks)."""

LONG: dict[str, str] = {}
"""Modules over :data:`MAX_LINES` lines, each with its reason."""

SPLIT = ("novikov", "bearing", "planetary", "shaft", "worm", "bevel", "epicycle_rim", "pzdn")
"""Calculators in the shape inputs → solve → report."""

SHORT_CALCULATOR = 60
"""A split calculator's ``calculator.py`` only joins the three parts."""


def _lines(path: Path) -> int:
    return len(path.read_text(encoding="utf-8").splitlines())


def _modules():
    return sorted(p for p in PACKAGE.rglob("*.py") if "__pycache__" not in p.parts)


def test_no_module_is_longer_than_the_limit_without_a_reason():
    long = {p.relative_to(PACKAGE).as_posix(): _lines(p) for p in _modules()
            if _lines(p) > MAX_LINES}
    unlisted = {k: n for k, n in long.items() if k not in LONG}
    assert not unlisted, (f"modules over {MAX_LINES} lines: split them, or list them in LONG "
                          f"with the reason: {unlisted}")


def test_every_listed_long_module_exists_and_says_why():
    for key, reason in LONG.items():
        assert (PACKAGE / key).is_file(), f"{key}: listed but gone; remove it from LONG"
        assert reason.strip(), key


@pytest.mark.parametrize("kind", SPLIT)
def test_a_split_calculator_shows_inputs_solve_report(kind):
    pkg = PACKAGE / kind
    for part in ("inputs", "solve", "report", "calculator"):
        assert (pkg / f"{part}.py").is_file(), f"{kind}: no {part}.py"
    assert _lines(pkg / "calculator.py") <= SHORT_CALCULATOR
    solve = ast.parse((pkg / "solve.py").read_text(encoding="utf-8"))
    assert any(isinstance(n, ast.FunctionDef) and n.name == "solve" for n in solve.body), \
        f"{kind}/solve.py has no solve(inputs)"


@pytest.mark.parametrize("kind", SPLIT)
def test_solve_builds_no_report_rows_and_reads_no_spec(kind):
    """solve() is the calculator's typed interface: no Result, no Section, no spec."""
    tree = ast.parse((PACKAGE / kind / "solve.py").read_text(encoding="utf-8"))
    forbidden = {"Result", "Section", "ValidatedSpec"}      # the report's and the spec's types
    for node in ast.walk(tree):
        if isinstance(node, ast.ImportFrom):
            assert node.module != "geardesign.core.spec", f"{kind}/solve.py reads the spec"
            used = {a.name for a in node.names} & forbidden
            assert not used, f"{kind}/solve.py imports {used}"
        elif isinstance(node, ast.Name):
            assert node.id not in forbidden, f"{kind}/solve.py uses {node.id}"
        elif isinstance(node, ast.Attribute):
            assert node.attr not in forbidden | {"section"}, f"{kind}/solve.py uses .{node.attr}"


def test_the_planetary_train_edits_no_other_calculator_s_messages():
    """Checks carry names and advice as data (the builders take the members and the keys
    to name): the planetary composes its mesh checks without regular expressions."""
    for path in (PACKAGE / "planetary").glob("*.py"):
        text = path.read_text(encoding="utf-8")
        tree = ast.parse(text)
        for node in ast.walk(tree):
            if isinstance(node, (ast.Import, ast.ImportFrom)):
                names = ([a.name for a in node.names] if isinstance(node, ast.Import)
                         else [node.module or ""])
                assert "re" not in names, f"{path.name} imports re"
        assert ".sub(" not in text, path.name


def test_a_mesh_check_names_its_members_and_keeps_its_advice():
    """The spur strength checks of a planetary mesh name the sun and the planet and the
    planetary's peak-torque key; the advice is the end of the message, as data."""
    from geardesign.core.registry import run_data
    from geardesign.core.spec import load_toml

    data = load_toml(PACKAGE.parent / "specs" / "planetary_2kh_reducer.toml")
    data["operation"]["torque"] = 1500.0
    data["strength"].pop("peak_torque", None)
    res = run_data(data, "p.toml")
    failed = [c for c in res.checks if c.code.startswith("SUN_PLANET_") and not c.passed
              and c.severity == "error"]
    assert failed, [c.code for c in res.checks]
    for c in failed:
        assert c.message.startswith("sun–planet: ")
        assert c.advice and c.message.endswith(c.advice)
        assert "pinion" not in c.message and "wheel" not in c.message
    assert any(c.code in ("SUN_PLANET_BENDING_FATIGUE_SUN", "SUN_PLANET_BENDING_FATIGUE_PLANET")
               for c in failed)
    static = [c for c in res.checks if c.code == "SUN_PLANET_STATIC_NOT_CHECKED"]
    assert static and "strength.peak_torque" in static[0].message
