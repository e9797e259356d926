"""Golden files: every ``specs/<name>.toml`` has ``specs/<name>.expected.json`` beside it.

The expected documents are regression values produced by this code and reviewed by hand;
regenerate them only on purpose (``pytest tests/test_golden.py --update-golden``) and
review the diff like code.  Numbers compare to a relative 1e-9 (absolute 1e-12); strings,
keys and structure exactly; the version field is ignored.
"""

import json
import math

import pytest

from geardesign.core.registry import run
from tests.conftest import SPECS

SPEC_FILES = sorted(SPECS.glob("*.toml"))


def _compare(actual, expected, path="$"):
    if isinstance(expected, dict):
        assert isinstance(actual, dict), path
        assert list(actual) == list(expected), f"{path}: keys differ"
        for k in expected:
            _compare(actual[k], expected[k], f"{path}.{k}")
    elif isinstance(expected, list):
        assert isinstance(actual, list) and len(actual) == len(expected), path
        for i, (a, e) in enumerate(zip(actual, expected)):
            _compare(a, e, f"{path}[{i}]")
    elif isinstance(expected, float) and not isinstance(expected, bool):
        assert isinstance(actual, (int, float)), path
        assert math.isclose(actual, expected, rel_tol=1e-9, abs_tol=1e-12), (
            f"{path}: {actual!r} != {expected!r}")
    else:
        assert actual == expected, f"{path}: {actual!r} != {expected!r}"


def test_every_spec_has_its_expected_file():
    assert SPEC_FILES, "no specs"
    for spec in SPEC_FILES:
        assert spec.with_suffix(".expected.json").exists(), spec.name


@pytest.mark.parametrize("spec", SPEC_FILES, ids=[p.stem for p in SPEC_FILES])
def test_golden(spec, update_golden):
    doc = run(spec).document()
    expected_path = spec.with_suffix(".expected.json")
    text = json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    if update_golden:
        expected_path.write_text(text, encoding="utf-8")
        pytest.skip("golden file rewritten")
    assert expected_path.exists(), f"{expected_path.name} missing: run with --update-golden"
    expected = json.loads(expected_path.read_text(encoding="utf-8"))
    doc.pop("geardesign")
    expected.pop("geardesign")
    _compare(doc, expected)
