"""The worked values in the docstrings of the ISO 6336 and GOST 21354-87 formula modules
(each marked with its source: KISSsoft reports, ISO/TR 6336-30, the standard's tables, a
value worked from the formula) run as tests in tests/test_doctests.py; every public formula names its reference (a key
of docs/references.md in brackets)."""

import importlib
import inspect
import re

import pytest

ISO = "geardesign.spur.strength.iso6336."
GOST = "geardesign.spur.strength.gost21354."
MODULES = [ISO + m for m in ("part1", "part2", "part3", "part5", "part21", "tooth_form")] + \
    [GOST + m for m in ("contact", "bending", "load_factors")]
FORMULAS = MODULES + [ISO + "part6"]


@pytest.mark.parametrize("name", FORMULAS)
def test_every_formula_names_its_reference(name):
    """Each public function of a formula module has a docstring that names a key of
    docs/references.md."""
    from pathlib import Path

    keys = set(re.findall(r"^\| \[([^\]]+)\]", (Path(__file__).resolve().parent.parent / "docs"
                                                / "references.md").read_text(encoding="utf-8"),
                          re.M))
    module = importlib.import_module(name)
    for fname, obj in vars(module).items():
        if not inspect.isfunction(obj) or obj.__module__ != name or fname.startswith("_"):
            continue
        cited = set(re.findall(r"\[([A-Za-z][^\]\s]*)\]", obj.__doc__ or ""))
        assert cited & keys, f"{name}.{fname}: no reference key in its docstring"
