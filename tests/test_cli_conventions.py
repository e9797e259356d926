"""Command-line conventions: formats, output extensions, standard input, batches, help."""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path

from tests.conftest import SPECS
from tests.helpers_cli import cli, cli_process, write_spec

PLAIN = SPECS / "spur_plain.toml"


def test_unknown_output_extension_is_refused_before_computing(tmp_path):
    code, out, err = cli("run", PLAIN, "--output", tmp_path / "r.docx")
    assert code == 2 and out == ""
    assert err == (f"{tmp_path / 'r.docx'}: cannot write a report as .docx; use one of .json, "
                   ".jsonl, .md, .markdown, .csv, .html, .htm, .pdf, .txt or give --format\n")
    assert not (tmp_path / "r.docx").exists()


def test_html_and_csv_reports(tmp_path):
    for ext in ("html", "csv"):
        code, _, err = cli("run", PLAIN, "--output", tmp_path / f"r.{ext}", "--quiet")
        assert code in (0, 1), err
    html = (tmp_path / "r.html").read_text()
    assert html.startswith("<!DOCTYPE html>") and "</html>" in html
    raw = (tmp_path / "r.csv").read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")          # UTF-8 with BOM, for spreadsheets
    rows = list(csv.reader(io.StringIO(raw.decode("utf-8-sig"))))
    assert rows[0] == ["spec", "key", "symbol", "name", "value", "unit", "source", "status",
                       "severity", "limit", "message"]
    keys = {r[1]: r for r in rows[1:]}
    assert keys["results.geometry.a_w"][5] == "mm"
    assert any(k.startswith("checks.") for k in keys)


def test_jsonl_gives_one_document_a_line():
    code, out, _ = cli("run", PLAIN, SPECS / "spur_helical.toml", "--format", "jsonl")
    lines = out.splitlines()
    assert len(lines) == 2
    assert [json.loads(x)["kind"] for x in lines] == ["spur", "spur"]
    assert json.loads(lines[0])["spec"] == str(PLAIN)


def test_spec_from_standard_input():
    r = cli_process("run", "-", "--format", "json", input=PLAIN.read_text())
    assert r.returncode in (0, 1), r.stderr
    assert json.loads(r.stdout)["spec"] == "<stdin>"


def test_standard_input_given_twice_is_one_line_before_it_is_read():
    for command in ("run", "validate", "spur"):
        r = cli_process(command, "-", "-", input=PLAIN.read_text())
        assert r.returncode == 2 and r.stdout == ""
        assert r.stderr == "-: standard input is given more than once; it can be read once\n"


def test_keep_going_reports_the_usable_specs_and_still_exits_2(tmp_path):
    bad = write_spec(tmp_path, 'kind = "spur"\n', "bad.toml")
    code, out, err = cli("run", PLAIN, bad, "--format", "jsonl", "--keep-going")
    assert code == 2
    assert len(out.splitlines()) == 1 and "bad.toml" in err
    code, out, _ = cli("run", PLAIN, bad, "--format", "jsonl")
    assert code == 2 and out == ""


def test_validate_prints_an_ok_line_per_valid_file(tmp_path):
    bad = write_spec(tmp_path, 'kind = "spur"\n', "bad.toml")
    code, out, err = cli("validate", PLAIN, bad)
    assert code == 2
    assert out == f"{PLAIN}: ok (spur)\n" and "bad.toml" in err


def test_each_command_shows_only_its_options():
    _, spur, _ = cli("spur", "--help")
    _, bearing, _ = cli("bearing", "--help")
    _, pzdn, _ = cli("pzdn", "--help")
    assert "--select" not in spur and "--plot" in spur and "--profile" in spur
    assert "--select" in bearing and "--plot" not in bearing and "--profile" not in bearing
    assert "--plot" in pzdn and "--select" not in pzdn and "--profile" not in pzdn


def test_top_level_help_names_every_exit_code_and_completion():
    _, out, _ = cli("--help")
    text = " ".join(out.split())
    assert "3 internal error" in text
    assert "--install-completion" in out and "--show-completion" in out


def test_table_to_a_pipe_follows_columns_without_trailing_blanks(monkeypatch):
    monkeypatch.setenv("COLUMNS", "90")
    _, out, _ = cli("run", PLAIN, "--format", "table")
    lines = out.splitlines()
    assert all(line == line.rstrip() for line in lines)
    assert max(len(line) for line in lines) <= 90


def test_every_template_runs_as_printed_from_an_empty_folder(tmp_path):
    """A template is a sensible design that passes (or its first comment says why not)."""
    import os
    import subprocess
    import sys

    from geardesign.core import registry

    # this tree's package, not whichever one the interpreter finds from an empty folder
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [str(Path(__file__).resolve().parent.parent), os.environ.get("PYTHONPATH", "")])}
    for kind in registry.known_kinds():
        text = cli("template", kind)[1]
        path = tmp_path / f"{kind}.toml"
        path.write_text(text)
        r = subprocess.run([sys.executable, "-m", "geardesign", "run", path.name, "--format",
                            "json"], cwd=tmp_path, capture_output=True, text=True, env=env)
        first = text.splitlines()[0]
        assert r.returncode == 0 or "does not pass" in first, (kind, r.returncode, r.stderr)


def test_check_reports_moved_quantities_and_update_rewrites(tmp_path):
    spec = write_spec(tmp_path, PLAIN.read_text(), "pair.toml")
    code, out, err = cli("check", spec)
    assert code == 2 and "no pair.expected.json beside it" in err
    code, out, _ = cli("check", spec, "--update")
    assert code == 0 and out == f"{spec}: wrote pair.expected.json\n"
    code, out, _ = cli("check", spec)
    assert code == 0 and out == f"{spec}: unchanged\n"
    text = PLAIN.read_text()
    old = re.search(r"face_width = ([0-9.]+)", text).group(1)
    spec.write_text(text.replace(f"face_width = {old}", f"face_width = {float(old) * 1.1}"))
    code, out, _ = cli("check", spec)
    assert code == 1
    assert out.startswith(f"{spec}: ") and "quantities moved" in out
    assert "inputs.gear.face_width: " in out and "(+10 %)" in out


def test_golden_tests_for_a_users_folder(tmp_path):
    from geardesign.testing import golden_tests

    spec = write_spec(tmp_path, PLAIN.read_text(), "pair.toml")
    cli("check", spec, "--update")
    test = golden_tests(tmp_path)
    marks = test.pytestmark[0]
    assert [p.name for p in marks.args[1]] == ["pair.toml"]
    test(spec)   # passes: nothing moved
