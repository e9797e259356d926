"""Golden files: every ``specs/<name>.toml`` has ``specs/<name>.expected.json`` beside it.

The expected documents are regression values produced by this code and reviewed by hand;
regenerate them only on purpose (``pytest tests/test_golden.py --update-golden``) and
review the diff like code.  The comparison is :func:`geardesign.testing.compare_documents`:
scalars to a relative 1e-9 (the precision every closed form and solver reaches; coarser
solvers to ten times their tolerance) and an absolute 1e-9, arrays element by element to
1e-9 of their largest magnitude, error estimates only below their bound, strings, keys and
structure exactly; the version and the spec path are ignored.
"""

import pytest

from geardesign.testing import ATOL, RTOL, check_golden, compare_documents
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


def test_an_array_is_compared_at_the_scale_of_its_largest_element():
    """A moment diagram's point of -0.48 N·m in a diagram of 300 N·m, moved by 1.5e-7
    relative (7e-8 N·m: the rounding of a BLAS build), has not moved; the same change at
    the diagram's peak has."""
    def doc(m):
        return {"results": {"diagrams": {"M": m}}}
    base = [0.0, -0.48, 150.0, -300.0]
    near_zero = [0.0, -0.48 * (1 + 1.5e-7), 150.0, -300.0]
    assert compare_documents(doc(near_zero), doc(base)) == []
    peak = [0.0, -0.48, 150.0, -300.0 * (1 + 1.5e-7)]
    assert [d.path for d in compare_documents(doc(peak), doc(base))] == [
        "results.diagrams.M[3]"]
    nested = {"sidebands": [[10.0, 0.001], [20.0, 1000.0]]}      # one scale for all of them
    moved = {"sidebands": [[10.0, 0.001 + 1e-7], [20.0, 1000.0]]}
    assert compare_documents(moved, nested) == []


def test_a_scalar_is_compared_at_its_own_precision():
    """A scalar to rtol of itself; a rounding residue of an exact 0 to atol; the default
    tolerances are the documented ones (the command line's defaults are the same)."""
    assert (RTOL, ATOL) == (1e-9, 1e-9)
    one = {"results": {"a": {"x": 480.0, "residual": 1.1e-13}}}
    assert compare_documents({"results": {"a": {"x": 480.0 * (1 + 5e-10),
                                                "residual": -2.7e-10}}}, one) == []
    moved = compare_documents({"results": {"a": {"x": 480.0 * (1 + 2e-9),
                                                 "residual": 2e-9}}}, one)
    assert [d.path for d in moved] == ["results.a.x", "results.a.residual"]
    assert compare_documents({"results": {"a": {"x": 480.1, "residual": 0.0}}}, one,
                             rtol=1e-3) == []
    assert compare_documents({"results": {"a": {"x": 480.0, "residual": 1e-4}}}, one,
                             atol=1e-3) == []


def test_a_solver_result_is_compared_to_the_solver_tolerance():
    """The sump temperature of a drive is a bisection to 1e-7: it may move by that much;
    a result of the closed forms next to it may not."""
    one = {"results": {"thermal": {"t_oil": 46.88941556960344}, "drive": {"u": 12.5}}}
    two = {"results": {"thermal": {"t_oil": 46.88941556960344 * (1 + 3e-7)},
                       "drive": {"u": 12.5 * (1 + 3e-7)}}}
    assert [d.path for d in compare_documents(two, one)] == ["results.drive.u"]


def test_check_takes_the_tolerances(tmp_path):
    """geardesign check --rtol/--atol: a moved result passes at a looser tolerance."""
    import json
    import shutil

    from tests.helpers_cli import cli

    spec = tmp_path / "s.toml"
    shutil.copy(SPECS / "connection_key.toml", spec)
    assert cli("check", "--update", spec)[0] == 0
    golden = spec.with_name("s.expected.json")
    doc = json.loads(golden.read_text(encoding="utf-8"))
    key, value = next((k, v) for k, v in doc["results"]["strength"].items()
                      if isinstance(v, float) and v > 1.0)
    doc["results"]["strength"][key] = value * (1 + 1e-6)
    golden.write_text(json.dumps(doc), encoding="utf-8")
    code, out, _ = cli("check", spec)
    assert code == 1 and f"results.strength.{key}" in out
    assert cli("check", "--rtol", "1e-5", spec)[0] == 0
    assert cli("check", "--atol", str(2e-6 * value), spec)[0] == 0


def test_a_table_column_is_compared_at_the_scale_of_its_largest_entry():
    """A shaft's reaction of -200.7 N beside one of 1559.5 N (one linear solve) moved by
    1.3e-9 relative with two OpenBLAS threads on numpy 1.24: not a move; checks, whose
    values are of every kind, stay each at its own scale."""
    def supports(r):
        return {"supports": [{"name": "A", "R_y": r}, {"name": "B", "R_y": 1559.4760600217433}]}
    assert compare_documents(supports(-200.73680139945236),
                             supports(-200.73680113917942)) == []
    assert compare_documents(supports(-200.7370), supports(-200.73680113917942)) != []

    def checks(v):
        return {"checks": [{"code": "A", "value": v}, {"code": "B", "value": 20000.0}]}
    assert [d.path for d in compare_documents(checks(1.5 * (1 + 1e-8)), checks(1.5))] == [
        "checks[0].value"]
