"""Every renderer gets the same cleaned result (geardesign.core.result.cleaned): no format
fails on a value the JSON document reports as null; no check message shows nan or inf (a
check that meets such a number is "not rated" and fails); CSV cells that a spreadsheet
would run as a formula are neutralised; JSON escapes C1 controls and bidi overrides."""

import csv
import io
import json
import math
import random
import re
import tomllib

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data
from geardesign.core.render import csv_cell, render
from geardesign.core.result import NOT_RATED, Check
from tests import fuzz
from tests.helpers_cli import cli, write_spec

NONFINITE = re.compile(r"(?<![\w.])[-+]?(nan|inf(inity)?)(?![\w])", re.IGNORECASE)
SPECS = fuzz.spec_files()
BASES = {p: tomllib.loads(p.read_text(encoding="utf-8")) for p in SPECS}


def _compute(data, path):
    if "sweep" in data:
        from geardesign.spur.sweep import run_data

        return run_data(data, path.name)
    calc, spec = load_data(data, path.name)
    spec.base_dir = path.parent
    return calc.compute(spec)


def _messages(doc):
    for c in doc.get("checks", []):
        yield c["code"], c["message"]
    for v in doc.get("results", {}).values():
        for x in v if isinstance(v, list) else ():
            if isinstance(x, dict) and "checks" in x:
                yield from _messages(x)


def _no_constant(name):
    raise AssertionError(f"{name} in JSON")


@pytest.mark.parametrize("path", SPECS, ids=[p.stem for p in SPECS])
def test_every_format_of_every_example_renders_without_nan_or_inf(path):
    res = _compute(BASES[path], path)
    doc = None
    for fmt in fuzz.TEXT_FORMATS:
        text = render([res], fmt)
        if fmt == "json":
            doc = json.loads(text, parse_constant=_no_constant)
        elif fmt == "jsonl":
            for line in text.splitlines():
                json.loads(line, parse_constant=_no_constant)
        elif fmt == "csv":
            for row in csv.reader(io.StringIO(text)):
                assert not any(NONFINITE.fullmatch(cell) for cell in row), row
    for code, message in _messages(doc):
        assert not NONFINITE.search(message), f"{code}: {message}"


@pytest.mark.parametrize("name", ["epicycle_rim_raba", "epicycle_rim_hardened",
                                  "epicycle_rim_improved_fillet"])
def test_csv_of_specs_with_unbounded_list_values(name):
    """These examples hold an infinite value in a list row: null in JSON, empty in CSV."""
    code, out, err = cli("run", f"specs/{name}.toml", "--format", "csv")
    assert code in (0, 1) and err == ""
    json_code, doc, _ = cli("run", f"specs/{name}.toml", "--format", "json")
    assert json_code == code
    assert "null" in doc
    assert not NONFINITE.search(out.replace("info", ""))


@settings(max_examples=150, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SPECS), st.integers(0, 2 ** 32 - 1))
def test_no_check_message_of_a_mutated_example_shows_nan_or_inf(path, seed):
    data = fuzz.mutate(BASES[path], random.Random(seed))
    try:
        res = _compute(data, path)
    except (InputError, fuzz.Timeout):
        return
    except Exception:   # another engineer's crash class (tests/test_fuzz_specs.py)
        return
    for code, message in _messages(res.document()):
        assert not NONFINITE.search(message), f"{code}: {message}"


@pytest.mark.parametrize("message, word", [
    ("ϑ2(E) = nan", "ϑ2(E) = undefined"),
    ("L10h = inf h >= 20000 h", "L10h = unbounded h"),
    ("S = -inf", "S = unbounded (negative)"),
    ("x = NaN and y = Infinity", "x = undefined and y = unbounded")])
def test_a_check_that_meets_a_non_finite_number_is_not_rated(message, word):
    for severity in ("error", "warning"):
        c = Check("X", severity, True, message, 1.0, 2.0)
        assert not c.passed and c.message.startswith(NOT_RATED) and word in c.message
    info = Check("X", "info", True, message)
    assert info.passed and word in info.message
    # words that contain the letters are left alone
    assert Check("X", "error", True, "info: influence of nanometres").passed


def test_specific_sliding_at_an_undefined_end_is_not_rated(tmp_path):
    """spur_plain with z2 = 14: the pinion tip passes the wheel's tangency point, so ϑ2(E)
    does not exist; the sliding check says so instead of passing on ϑ1(A) alone."""
    text = (fuzz.SPECS / "spur_plain.toml").read_text().replace("z2 = 33", "z2 = 14")
    code, out, _ = cli("run", write_spec(tmp_path, text), "-f", "json")
    check = {c["code"]: c for c in json.loads(out)["checks"]}["SPECIFIC_SLIDING"]
    assert code == 1 and not check["passed"] and check["value"] is None
    assert check["message"].startswith("specific sliding at the roots not rated: ϑ2(E) "
                                       "undefined")


@pytest.mark.parametrize("cell, shown", [
    ("=HYPERLINK(\"x\")", "'=HYPERLINK(\"x\")"), ("+cmd", "'+cmd"), ("-2+3", "'-2+3"),
    ("@SUM(A1)", "'@SUM(A1)"), ("\tx", "'\\x09x"), ("\rx", "'\\x0dx"),
    ("-1.5", "-1.5"), ("+2e3", "+2e3"), ("-inf", "'-inf"), ("plain", "plain"), ("-", "-"),
    (-1.5, -1.5), (0, 0),
])
def test_csv_cells_that_would_run_as_formulas_are_neutralised(cell, shown):
    assert csv_cell(cell) == shown


def test_a_spec_named_like_a_formula_starts_no_csv_row_with_it(tmp_path, monkeypatch):
    text = (fuzz.SPECS / "spur_plain.toml").read_text()
    write_spec(tmp_path, text, name="=cmd|' calc'!A0.toml")
    monkeypatch.chdir(tmp_path)
    code, out, err = cli("run", "=cmd|' calc'!A0.toml", "--format", "csv")
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(out)))[1:]
    assert rows and all(r[0].startswith("'=") for r in rows)
    numbers = [r[4] for r in rows if r[4][:1] == "-"]
    assert all(math.isfinite(float(v)) for v in numbers)   # negative numbers stay numbers


def test_json_escapes_c1_controls_and_bidi_overrides(tmp_path):
    title = "a\u202eb\x85c\u2066d\u200fe\x9bf\x7f"
    text = (fuzz.SPECS / "spur_plain.toml").read_text()
    text = re.sub(r'(?m)^title = .*$', lambda m: "title = " + json.dumps(title), text)
    spec = write_spec(tmp_path, text)
    for fmt in ("json", "jsonl", "table", "markdown", "csv", "html"):
        code, out, _ = cli("run", spec, "--format", fmt)
        assert code == 0
        assert not re.search("[\x7f-\x9f\u200e\u200f\u202a-\u202e\u2066-\u2069]", out), fmt
        if fmt == "json":
            assert json.loads(out)["title"] == title
            assert "\\u202e" in out and "\\u0085" in out


@settings(max_examples=300, deadline=None, derandomize=True)
@given(st.sampled_from([math.nan, math.inf, -math.inf]),
       st.sampled_from(["{:.2f}", "{:g}", "{:.3g}", "{:e}", "{}", "{!r}", "{:+.1f}", "{:8.3f}"]),
       st.text(max_size=20), st.text(max_size=20),
       st.sampled_from(["error", "warning", "info"]), st.booleans())
def test_no_formatted_non_finite_number_survives_in_a_check(value, spec, before, after,
                                                           severity, ok):
    """However a calculator formats an undefined or unbounded number into a message, the
    check shows it in words and cannot pass (an info check only reports)."""
    message = f"{before} x = {spec.format(value)} {after}"
    c = Check("X", severity, ok, message, 1.0, 2.0)
    assert not NONFINITE.search(c.message)
    assert c.passed == (ok and severity == "info")


def test_markdown_shows_markup_in_a_spec_as_text(tmp_path):
    """A title, a stage name or a message holding HTML, a link or an image is shown as
    written in the Markdown report, never run (rendered by markdown-it, the CommonMark
    parser rich depends on): no tag, link or image comes from the spec's text."""
    from markdown_it import MarkdownIt

    title = "<script>alert(1)</script> [x](http://e) ![i](http://e/p.png) <http://e> a\\b |c"
    text = (fuzz.SPECS / "spur_plain.toml").read_text()
    text = re.sub(r'(?m)^title = .*$', lambda m: "title = " + json.dumps(title), text)
    spec = write_spec(tmp_path, text, name="s[1](x).toml")
    code, out, _ = cli("run", spec, "--format", "markdown")
    assert code == 0
    md = MarkdownIt("commonmark").enable("table")
    html = md.render(out)
    assert "<script" not in html and "<a " not in html and "<img" not in html
    heading = md.parse(out)[1]                    # the first line, as the reader sees it
    assert heading.type == "inline"
    shown = "".join(c.content for c in heading.children)
    assert all(c.type == "text" for c in heading.children)
    assert f"— {title} [{spec}]" in shown


def test_a_file_name_that_is_not_utf8_is_shown_escaped_in_every_format(tmp_path):
    """A spec and an output whose names are not UTF-8 (Python holds the bytes as lone
    surrogates, which no encoder writes): every format is written, as valid UTF-8, with
    the bytes shown as ``\\udcXX``; the JSON document reads back to the same name."""
    import os

    name = os.fsdecode(b"bad\xff.toml")
    spec = write_spec(tmp_path, (fuzz.SPECS / "spur_plain.toml").read_text(), name=name)
    for fmt, ext in (("json", "json"), ("jsonl", "jsonl"), ("csv", "csv"),
                     ("markdown", "md"), ("html", "html"), ("table", "txt")):
        target = tmp_path / os.fsdecode(b"out\xfe." + ext.encode())
        code, out, err = cli("run", spec, "--format", fmt, "--output", target)
        assert code == 0, (fmt, err)
        text = target.read_bytes().decode("utf-8")          # valid UTF-8
        assert "\\udcff" in text, fmt
        if fmt == "json":
            assert json.loads(text)["spec"] == str(spec)
        code, out, err = cli("run", spec, "--format", fmt)
        assert code == 0 and "\\udcff" in out and "\udcff" not in out, fmt
