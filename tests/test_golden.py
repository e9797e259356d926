"""Golden files: every ``specs/<name>.toml`` has ``specs/<name>.expected.json`` beside it.

The expected documents are regression values produced by this code and reviewed by hand;
regenerate them only on purpose (``pytest tests/test_golden.py --update-golden``) and
review the diff like code.  The comparison is :func:`geardesign.testing.compare_documents`:
numbers to a relative 1e-9 (the precision every closed form and solver reaches), error
estimates only below their bound, strings, keys and structure exactly; the version and
the spec path are ignored.
"""

import pytest

from geardesign.testing import check_golden, compare_documents
from tests.conftest import SPECS

SPEC_FILES = sorted(SPECS.glob("*.toml"))


def test_every_spec_has_its_expected_file():
    assert SPEC_FILES, "no specs"
    for spec in SPEC_FILES:
        assert spec.with_suffix(".expected.json").exists(), spec.name


@pytest.mark.parametrize("spec", SPEC_FILES, ids=[p.stem for p in SPEC_FILES])
def test_golden(spec, update_golden):
    """The same check a user's CI runs (``geardesign check``, ``golden_tests``)."""
    if update_golden:
        check_golden(spec, update=True)
        pytest.skip("golden file rewritten")
    moved = check_golden(spec)
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


def test_error_estimate_checks_compare_to_their_bound():
    """A check whose value is an error estimate (FLOQUET) passes while both values stay under
    its bound, whatever digits the LAPACK build gives, in the value and in the message."""
    def doc(v):
        return {"checks": [{"code": "FLOQUET", "value": v, "limit": 1e-6,
                            "message": f"agree (max |Δa| = {v:.1e})"}]}
    assert compare_documents(doc(1.2437e-9), doc(1.2373e-9)) == []
    assert compare_documents(doc(3.1e-9), doc(1.2e-9)) == []
    moved = [d.path for d in compare_documents(doc(2e-3), doc(1.2e-9))]
    assert moved == ["checks[0].value"]
