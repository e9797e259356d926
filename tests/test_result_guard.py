"""The one guard on every finished result (geardesign.core.result.guard) and the escaping
of control characters (geardesign.core.text.escape_controls)."""

import math

import pytest

from geardesign.core.errors import InputError, Problem
from geardesign.core.result import Check, DataTable, Result, ResultDomainError, guard
from geardesign.core.text import escape_controls


def _result(rows=(), checks=(), table=None):
    res = Result("spur", None, [], {}, [])
    sec = res.section("strength", "Strength")
    for key, value in rows:
        sec.add(key, value, "MPa", key)
    res.checks.extend(checks)
    if table is not None:
        res.tables.append(table)
    return res


def _ok(code="C"):
    return Check(code, "error", True, "ok", 1.0, 1.0)


def test_nan_in_a_passing_design_is_an_input_error_naming_the_quantity():
    with pytest.raises(ResultDomainError) as e:
        guard(_result([("sigma_H", math.nan)], [_ok()]))
    assert isinstance(e.value, InputError)
    assert [p.line("s.toml") for p in e.value.problems] == [
        "s.toml: the inputs give an undefined (NaN) sigma_H (results.strength.sigma_H), "
        "which the method cannot compute: check the input values and their units"]


def test_nan_in_a_table_cell_is_refused():
    t = DataTable("stages", "Stages", [("u", "u", "-")], [{"u": 2.0}, {"u": math.nan}])
    with pytest.raises(ResultDomainError, match=r"NaN\) u \(results\.stages\[1\]\.u\)"):
        guard(_result(table=t))


def test_negative_safety_factor_life_or_contact_ratio_is_refused():
    for key in ("S_F1", "L10h", "eps_alpha"):
        with pytest.raises(ResultDomainError, match=f"a negative {key} "):
            guard(_result([(key, -1.0)]))
    # a minimum (key ending in _min) is a limit, not a result
    guard(_result([("S_F_min", -1.0)]))


def test_a_check_cannot_pass_on_infinity():
    with pytest.raises(ResultDomainError) as e:
        guard(_result(checks=[Check("LIFE", "error", True, "ok", math.inf, 1.0)]))
    assert str(e.value) == ("the inputs give an unbounded (infinite) value of check LIFE "
                            "(checks), which the method cannot compute: check the input "
                            "values and their units")
    # a failed check on infinity is reported as it is
    guard(_result(checks=[Check("LIFE", "error", False, "fails", math.inf, 1.0)]))


def test_nan_in_a_check_is_always_refused():
    with pytest.raises(ResultDomainError, match="NaN\\) limit of check C"):
        guard(_result(checks=[Check("C", "error", False, "x", 1.0, math.nan)]))


def test_infinite_rows_are_listed_as_undefined_never_silent():
    res = guard(_result([("L10h", math.inf), ("sigma_H", 500.0)]))
    doc = res.document()
    assert doc["undefined"] == ["results.strength.L10h"]
    assert doc["results"]["strength"]["L10h"] is None


def test_nan_in_a_design_that_already_fails_is_reported_undefined():
    res = guard(_result([("sigma_H", math.nan)],
                        [Check("C", "error", False, "fails", 1.0, 2.0)]))
    assert res.document()["undefined"] == ["results.strength.sigma_H"]


@pytest.mark.parametrize("raw, shown", [
    ("a\nb", "a\\x0ab"),
    ("\x1b[31mred", "\\x1b[31mred"),
    ("\x00\x7f\x85\x9f", "\\x00\\x7f\\x85\\x9f"),
    ("a\u202eb\u2066c\u2069", "a\\u202eb\\u2066c\\u2069"),
    ("l\u2028p\u2029", "l\\u2028p\\u2029"),
    ("µm N·m σ_H ✘", "µm N·m σ_H ✘"),
])
def test_escape_controls(raw, shown):
    assert escape_controls(raw) == shown


def test_a_problem_is_always_one_line_without_escapes():
    line = Problem("a\nb", "bad\x1b[2J", "v\r\n\u202e").line("f\n.toml")
    assert line == 'f\\x0a.toml: a\\x0ab = "v\\x0d\\x0a\\u202e": bad\\x1b[2J'
    assert "\n" not in line and "\x1b" not in line
