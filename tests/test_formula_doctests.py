"""The worked values in the docstrings of the ISO 6336 formula modules (each marked with
its source: KISSsoft reports, ISO/TR 6336-30, the standard's tables) run as tests."""

import doctest
import importlib
import inspect

import pytest

MODULES = ["part1", "part2", "part3", "part5", "part21", "tooth_form"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(f"geardesign.spur.strength.iso6336.{name}")
    finder, runner = doctest.DocTestFinder(recurse=False), doctest.DocTestRunner()
    attempted = 0
    for fname, obj in vars(module).items():
        if not inspect.isfunction(obj) or fname.startswith("x_"):
            continue
        for test in finder.find(obj, fname, globs=vars(module)):
            result = runner.run(test)
            assert result.failed == 0, fname
            attempted += result.attempted
    assert attempted > 0
