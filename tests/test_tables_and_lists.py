"""Tables that never cut a number, the material list with its allowables, bearing
designations as they are written (suffixes, makers' prefixes, the report's own string),
shell completion, and the CSV report: each as the command a user types."""

from __future__ import annotations

import csv
import io
import json
import re

import pytest
from typer.testing import CliRunner

from geardesign import completion
from geardesign.core.render import column_groups, fit_widths, fmt
from tests.conftest import SPECS
from tests.helpers_cli import cli, write_spec

SWEEP_BASE = (SPECS / "sweep_spur_reducer.toml").read_text(encoding="utf-8").split("[sweep]")[0]

SWEEP = SWEEP_BASE + """[sweep]
"gear.module" = {values = [2.5, 3.0]}
"gear.z1" = {values = [22, 25]}
"gear.x1" = {values = [0.3058, 0.41]}
"gear.helix_angle" = {values = [0.0, 12.5]}
"gear.face_width" = {values = [45.0, 55.0]}
top = 8
"""

CUT = re.compile(r"\S…(?=\s|$)", re.M)
"""A cell rich cut short: a word ending in an ellipsis (a range "2.5 … 3" has spaces)."""


def _tokens(text: str) -> set[str]:
    return set(text.split())


def _numbers_whole(doc_rows: list[dict], text: str) -> None:
    """Every number of the JSON rows appears whole (as a word) in the table text."""
    words = _tokens(text)
    for row in doc_rows:
        for key, value in row.items():
            if isinstance(value, float) and not isinstance(value, bool):
                shown = fmt(value)
                assert shown in words, f"{key} = {shown} is not printed whole"


@pytest.mark.parametrize("columns", ["80", "120"])
def test_sweep_tables_print_every_number_whole(tmp_path, monkeypatch, columns):
    spec = write_spec(tmp_path, SWEEP)
    code, out, err = cli("sweep", spec, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    monkeypatch.setenv("COLUMNS", columns)
    code, text, err = cli("sweep", spec, "--format", "table")
    assert code == 0, err
    assert not CUT.search(text)
    assert max(len(line) for line in text.splitlines()) <= int(columns)
    _numbers_whole(doc["results"]["ranked"] + doc["results"]["pareto"], text)
    assert "0.3058" in _tokens(text)


@pytest.mark.parametrize("columns", ["80", "120"])
def test_design_variant_table_prints_every_number_whole(monkeypatch, columns):
    code, out, _ = cli("run", SPECS / "spur_design.toml", "--format", "json")
    doc = json.loads(out)
    monkeypatch.setenv("COLUMNS", columns)
    code, text, _ = cli("run", SPECS / "spur_design.toml", "--format", "table")
    assert code == 0
    assert not CUT.search(text)
    assert max(len(line) for line in text.splitlines()) <= int(columns)
    _numbers_whole(doc["results"]["design_variants"], text)


def test_materials_list_shows_the_allowables_and_follows_columns(monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    code, text, err = cli("materials", "--format", "table")
    assert code == 0, err
    assert max(len(line) for line in text.splitlines()) <= 80
    assert "σ_Hlim" in text and "σ_Flim" in text
    assert "2*HB" in text and "1.75*HB" in text     # the allowables of an improved steel
    monkeypatch.setenv("COLUMNS", "200")
    code, wide, _ = cli("materials", "--format", "table")
    assert max(len(line) for line in wide.splitlines()) <= 200
    assert len(wide.splitlines()) < len(text.splitlines())


def test_widths_never_go_below_the_longest_word():
    widths = fit_widths([4, 7, 3], [30, 40, 3], 30)
    assert sum(widths) <= 30 and widths[1] >= 7 and widths[0] >= 4
    assert fit_widths([10, 10], [10, 10], 5) == [10, 10]      # cannot: never cut
    groups = column_groups([4, 20, 20, 20], 50)
    assert all(g[0] == 0 for g in groups) and sorted({i for g in groups for i in g}) == [0, 1,
                                                                                          2, 3]


BEARING = cli("template", "bearing")[1].replace('designation = "6208"',
                                               'designation = "{designation}"', 1)
assert "{designation}" in BEARING
BEARING = BEARING.replace("{", "{{").replace("}", "}}").replace("{{designation}}",
                                                                "{designation}")


@pytest.mark.parametrize("written,variant", [
    ("6208-2RS", "2RS = contact seals on both sides"),
    ("6208-2Z", "2Z = shields on both sides"),
    ("6208 ZZ", "ZZ = shields on both sides"),
    ("6208-2RS1/C3", "C3 = radial internal clearance C3"),
])
def test_bearing_designations_with_suffixes_read_as_the_catalogue_row(tmp_path, written,
                                                                      variant):
    spec = write_spec(tmp_path, BEARING.format(designation=written))
    code, out, err = cli("run", spec, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    read = [c for c in doc["checks"] if c["code"] == "DESIGNATION_READ"]
    assert read and "catalogue row SKF 6208" in read[0]["message"]
    assert variant in read[0]["message"]
    plain = json.loads(cli("run", write_spec(tmp_path, BEARING.format(designation="6208"),
                                             "p.toml"), "--format", "json")[1])
    assert doc["results"] == plain["results"]       # the same row, the same life


@pytest.mark.parametrize("written", ["SKF 6208", "SKF 6208 (GOST 208)", "skf 6208"])
def test_the_designation_the_report_prints_reads_back(tmp_path, written):
    spec = write_spec(tmp_path, BEARING.format(designation=written))
    code, out, err = cli("run", spec, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    plain = json.loads(cli("run", write_spec(tmp_path, BEARING.format(designation="6208"),
                                             "p.toml"), "--format", "json")[1])
    assert doc["results"] == plain["results"]
    printed = doc["results"]["bearing"]["designation"]
    again = json.loads(cli("run", write_spec(tmp_path, BEARING.format(designation=printed),
                                             "q.toml"), "--format", "json")[1])
    assert again["results"] == plain["results"]


def test_a_maker_named_twice_differently_is_one_input_error(tmp_path):
    text = BEARING.format(designation="NTN 6208")
    text = re.sub(r"(?m)^# maker =.*$", 'maker = "SKF"', text, count=1)
    spec = write_spec(tmp_path, text)
    code, out, err = cli("run", spec, "--format", "json")
    assert code == 2 and out == ""
    assert "bearing.designation" in err and "NTN" in err and "SKF" in err


def test_bearings_list_reads_a_written_designation():
    code, out, _ = cli("bearings", "6208-2RS", "--format", "json")
    assert code == 0
    assert {r["designation"] for r in json.loads(out)} == {"6208"}


def _complete(words: str) -> list[str]:
    from geardesign import cli as CLI

    CLI._register_kinds()
    cword = len(words.split()) - (0 if words.endswith(" ") else 1)
    res = CliRunner().invoke(CLI.app, [], prog_name="geardesign",
                             env={"_GEARDESIGN_COMPLETE": "complete_bash",
                                  "COMP_WORDS": words, "COMP_CWORD": str(cword)})
    return res.output.split()


def test_completion_callbacks():
    assert "spur" in completion.kinds("") and completion.kinds("sp") == ["spur"]
    assert completion.bearing_types("tap") == ["tapered_roller"]
    assert "gear.module=" in completion.vary_keys("gear.m")
    assert completion.vary_keys("gear.module=2") == []
    assert completion.material_families("o") == ["oil"]
    assert "csv" in completion.formats("c")


def test_the_shell_completes_kinds_types_and_vary_keys():
    assert _complete("geardesign template sp") == ["spur"]
    assert "drive" in _complete("geardesign schema ")
    assert _complete("geardesign bearings --type tap") == ["tapered_roller"]
    assert _complete("geardesign sweep s.toml --vary gear.mod") == ["gear.module="]
    assert "markdown" in _complete("geardesign run s.toml --format m")


def test_csv_is_utf8_with_bom_with_inputs_and_checks_in_their_columns(tmp_path):
    out_file = tmp_path / "r.csv"
    code, _, err = cli("run", SPECS / "spur_reducer_through_hardened.toml", "-o", out_file,
                       "-q")
    assert code == 0, err
    raw = out_file.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")
    rows = list(csv.DictReader(io.StringIO(raw.decode("utf-8-sig"))))
    keys = {r["key"]: r for r in rows}
    assert keys["inputs.gear.module"]["value"] == "4.0"
    assert keys["inputs.gear.module"]["unit"] == "mm"
    assert keys["results.geometry.a_w"]["unit"] == "mm"
    check = keys["checks.CONTACT_FATIGUE"]
    assert check["status"] == "pass" and check["severity"] == "error"
    assert check["message"].startswith("σ_H = ") and float(check["limit"]) > 0
    assert float(check["value"]) > 0
    assert all(not r["status"] for r in rows if not r["key"].startswith("checks."))
    assert "σ" in raw.decode("utf-8-sig")


def test_catalogue_csv_lists_begin_with_a_bom():
    code, out, _ = cli("materials", "45", "--format", "csv")
    assert code == 0 and out.startswith("\ufeff")


TABLE_SPECS = ("spur_design", "drive_two_stage_reducer", "planetary_3k_high_ratio",
               "bearing_select", "shaft_reducer_output", "worm_design", "spur_gost_vs_iso")


@pytest.mark.parametrize("name", TABLE_SPECS)
def test_reports_fit_the_width_and_print_data_numbers_whole(name):
    """The class of the defect: every report, at 60, 80 and 120 columns, stays within the
    width, cuts no cell, and prints every number of its data tables whole."""
    from rich.cells import cell_len

    from geardesign.core.registry import load
    from geardesign.core.render import render

    calc, spec = load(SPECS / f"{name}.toml", None)
    res = calc.compute(spec)
    doc = json.loads(render([res], "json"))
    rows = [r for t in res.tables for r in doc["results"][t.key]]
    for width in (60, 80, 120):
        text = render([res], "table", width=width)
        assert max(cell_len(line) for line in text.splitlines()) <= width
        assert not CUT.search(text)
        _numbers_whole(rows, text)
