"""Golden files: every ``specs/<name>.toml`` has ``specs/<name>.expected.json`` beside it.

The expected documents are regression values produced by this code and reviewed by hand;
regenerate them only on purpose (``pytest tests/test_golden.py --update-golden``) and
review the diff like code.  The comparison is :func:`geardesign.testing.compare_documents`:
numbers to a relative 1e-9 (the precision every closed form and solver reaches), error
estimates only below their bound, strings, keys and structure exactly; the version and
the spec path are ignored.
"""

import json

import pytest

from geardesign.core.registry import run
from geardesign.testing import compare_documents
from tests.conftest import SPECS

SPEC_FILES = sorted(SPECS.glob("*.toml"))


def _drop_paths(doc):
    if isinstance(doc, dict):
        doc.pop("spec", None)
        for v in doc.values():
            _drop_paths(v)
    elif isinstance(doc, list):
        for v in doc:
            _drop_paths(v)


def test_every_spec_has_its_expected_file():
    assert SPEC_FILES, "no specs"
    for spec in SPEC_FILES:
        assert spec.with_suffix(".expected.json").exists(), spec.name


@pytest.mark.parametrize("spec", SPEC_FILES, ids=[p.stem for p in SPEC_FILES])
def test_golden(spec, update_golden):
    doc = run(spec).document()
    _drop_paths(doc)   # the path of a spec on this machine is not a result
    expected_path = spec.with_suffix(".expected.json")
    text = json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    if update_golden:
        expected_path.write_text(text, encoding="utf-8")
        pytest.skip("golden file rewritten")
    assert expected_path.exists(), f"{expected_path.name} missing: run with --update-golden"
    expected = json.loads(expected_path.read_text(encoding="utf-8"))
    moved = compare_documents(doc, expected)
    assert not moved, "\n".join(d.line() for d in moved[:20])


def test_error_estimates_compare_below_their_bound_only():
    """An error estimate of ~1e-9 (the Floquet check) differs between LAPACK builds in
    its leading digit; it must only stay below its bound."""
    a = {"results": {"resonance": {"floquet_max_dev": 3.1e-9, "Omega": 1.0}}}
    b = {"results": {"resonance": {"floquet_max_dev": 1.2e-9, "Omega": 1.0}}}
    assert compare_documents(a, b) == []
    c = {"results": {"resonance": {"floquet_max_dev": 1e-3, "Omega": 1.0 + 1e-6}}}
    moved = [d.path for d in compare_documents(c, b)]
    assert moved == ["results.resonance.floquet_max_dev", "results.resonance.Omega"]
