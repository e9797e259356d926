"""The command line contract (DESIGN.md): commands, formats, exit codes, atomic output."""

import json
import re
import sys

import pytest

from geardesign import __version__
from geardesign.core.registry import KINDS
from tests.helpers_cli import cli, cli_process

GOOD = """kind = "spur"
title = "test pair"
[gear]
module = 2.0
z1 = 20
z2 = 40
face_width = 20.0
"""


@pytest.fixture
def good(tmp_path):
    p = tmp_path / "good.toml"
    p.write_text(GOOD, encoding="utf-8")
    return p


def spec(tmp_path, gear_lines, name="s.toml"):
    p = tmp_path / name
    p.write_text('kind = "spur"\n[gear]\nmodule = 2.0\nface_width = 20.0\n' + gear_lines,
                 encoding="utf-8")
    return p


DESIGN_FAILURES = {
    "undercut": ("z1 = 10\nz2 = 20\nx2 = 1.0\n", "UNDERCUT_PINION"),
    "pointed tip": ("z1 = 10\nz2 = 20\nx1 = 1.0\n", "POINTED_TIP_PINION"),
    "contact ratio below 1": ("z1 = 10\nz2 = 20\nx1 = 0.6\nx2 = 1.0\n", "CONTACT_RATIO"),
    # a pair that cannot mesh does not show its contact ratio as fulfilled
    "interference": ("z1 = 20\nz2 = 40\nx2 = -0.5\n", "CONTACT_RATIO, INTERFERENCE_PINION"),
}


@pytest.mark.parametrize("name", DESIGN_FAILURES)
def test_design_failure_exit_1_with_failed_check(tmp_path, name):
    lines, code_expected = DESIGN_FAILURES[name]
    path = spec(tmp_path, lines)
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1 and err == ""
    doc = json.loads(out)
    assert doc["verdict"] == "fail"
    failed = [c["code"] for c in doc["checks"] if not c["passed"] and c["severity"] == "error"]
    codes = code_expected.split(", ")
    assert failed == codes
    code, out, _ = cli("run", path, "--format", "table")
    assert code == 1
    for c in codes:
        assert re.search(rf"✘ FAIL\s+{c}\s", out)
    assert f"✘ FAIL: {len(codes)} check(s) failed: {code_expected}" in out


def test_allow_undercut_turns_the_check_into_a_warning(tmp_path):
    path = spec(tmp_path, "z1 = 10\nz2 = 20\nx2 = 1.0\nallow_undercut = true\n")
    code, out, _ = cli("run", path, "--format", "json")
    doc = json.loads(out)
    check = {c["code"]: c for c in doc["checks"]}["UNDERCUT_PINION"]
    assert code == 0 and check["severity"] == "warning" and not check["passed"]
    assert "increase x1 to at least 0.416" in check["message"]


def test_json_document_shape(good):
    code, out, err = cli("run", good, "--format", "json")
    assert code == 0 and err == ""
    doc = json.loads(out)
    assert list(doc) == ["geardesign", "spec", "kind", "title", "methods", "inputs", "assumed",
                         "results", "units", "checks", "verdict"]
    assert doc["geardesign"] == __version__ and doc["kind"] == "spur"
    assert doc["title"] == "test pair" and doc["verdict"] == "pass"
    assert "gear.x1" in doc["assumed"] and "gear.module" not in doc["assumed"]
    assert doc["units"]["results.geometry.d_a1"] == "mm"
    assert doc["units"]["results.geometry.alpha_tw"] == "deg"
    assert doc["units"]["inputs.gear.module"] == "mm"
    # one unit per numeric leaf
    for section, values in doc["results"].items():
        for key, value in values.items():
            if isinstance(value, (int, float)) and not isinstance(value, bool):
                assert f"results.{section}.{key}" in doc["units"]
    for c in doc["checks"]:
        assert set(c) == {"code", "severity", "passed", "message", "value", "limit", "source"}
        assert c["code"].isupper()


def test_default_format_is_json_off_a_terminal(good):
    code, out, _ = cli("run", good)
    assert code == 0 and json.loads(out)["kind"] == "spur"


def test_table_and_markdown(good):
    code, out, _ = cli("run", good, "--format", "table")
    assert code == 0
    for text in ("Geometry", "d_a1", "tip diameter, pinion", "assumed", "✔ PASS"):
        assert text in out
    code, out, _ = cli("run", good, "--format", "markdown")
    assert code == 0 and out.startswith("# geardesign") and "| d_a1 | tip diameter, pinion |" in out


def test_several_specs_give_a_json_array_and_the_worst_exit_code(tmp_path, good):
    bad = spec(tmp_path, "z1 = 10\nz2 = 20\nx1 = 1.0\n")
    code, out, _ = cli("run", good, bad, "--format", "json")
    docs = json.loads(out)
    assert code == 1 and [d["verdict"] for d in docs] == ["pass", "fail"]


def test_output_file_is_written_atomically(tmp_path, good):
    target = tmp_path / "out" / "report.md"
    target.parent.mkdir()
    code, out, err = cli("run", good, "--output", target)
    assert code == 0 and out == ""
    assert target.read_text(encoding="utf-8").startswith("# geardesign")  # from the extension
    assert "wrote" in err
    assert [p.name for p in target.parent.iterdir()] == ["report.md"]
    code, out, err = cli("run", good, "--output", tmp_path / "r.json", "--quiet")
    assert code == 0 and out == "" and err == ""
    assert json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))["kind"] == "spur"


def test_quiet_prints_nothing_but_keeps_the_exit_code(tmp_path):
    path = spec(tmp_path, "z1 = 10\nz2 = 20\nx1 = 1.0\n")
    assert cli("run", path, "--quiet") == (1, "", "")


def test_kind_command_and_mismatch(good):
    code, out, _ = cli("spur", good, "--format", "json")
    assert code == 0 and json.loads(out)["kind"] == "spur"


def test_version_and_list():
    assert cli("--version") == (0, f"geardesign {__version__}\n", "")
    code, out, _ = cli("list")
    assert code == 0 and out.startswith("spur ") and "GOST 16532-70" in out


def test_template_is_a_valid_spec(tmp_path):
    code, text, _ = cli("template", "spur")
    assert code == 0 and text.startswith("# geardesign spur spec")
    path = tmp_path / "t.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["inputs"]["gear"]["z1"] == 25
    assert doc["verdict"] == "pass" and "contact" in doc["results"]


def test_schema_comes_from_the_same_definitions(tmp_path):
    code, text, _ = cli("schema", "spur")
    schema = json.loads(text)
    gear = schema["properties"]["gear"]
    assert gear["additionalProperties"] is False
    assert set(gear["required"]) == {"module", "z1", "z2", "face_width"}
    assert schema["allOf"] == [{"oneOf": [{"required": ["gear"]}, {"required": ["design"]}]}]
    assert gear["properties"]["z1"] == {
        "type": "integer", "description": "z1: number of teeth, pinion [-]", "x-unit": "-",
        "minimum": 5, "maximum": 1000}
    assert "[mm]" in gear["properties"]["module"]["description"]
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    _, template, _ = cli("template", "spur")
    jsonschema.validate(tomllib.loads(template), schema)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(tomllib.loads(GOOD.replace("z1 = 20", "z1 = 3")), schema)


def test_unknown_kind_for_template():
    code, out, err = cli("template", "spurr")
    assert code == 2 and out == ""
    assert err == ('geardesign: unknown calculator "spurr" (did you mean "spur"?); known: '
                   + ", ".join(KINDS) + "\n")


def test_real_process_json_only_on_stdout_and_no_heavy_imports(good):
    code = ("import sys, runpy; sys.argv = ['geardesign', 'run', %r, '--format', 'json'];\n"
            "try:\n    runpy.run_module('geardesign', run_name='__main__')\n"
            "except SystemExit as e:\n"
            "    heavy = [m for m in ('scipy', 'numpy', 'rich') if m in sys.modules]\n"
            "    sys.stderr.write('HEAVY=' + ','.join(heavy))\n"
            "    raise\n") % str(good)
    import subprocess

    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0
    json.loads(proc.stdout)
    assert proc.stderr.strip() == "HEAVY="
    proc = cli_process("run", good, "--format", "json")
    assert proc.returncode == 0 and json.loads(proc.stdout)["verdict"] == "pass"


def test_select_option(tmp_path, good):
    from tests.conftest import SPECS

    text = (SPECS / "bearing_select.toml").read_text(encoding="utf-8")
    path = tmp_path / "b.toml"
    path.write_text(text.replace('mode = "select"', 'mode = "check"'), encoding="utf-8")
    code, out, _ = cli("bearing", path, "--select", "--format", "json")
    assert "selection" in json.loads(out)["results"]
    code, out, err = cli("run", good, "--select")
    assert code == 2 and out == "" and err.strip().endswith("--select does not apply to a spur spec")


@pytest.mark.parametrize("kind", KINDS)
def test_every_template_runs_and_matches_its_schema(kind, tmp_path):
    """Each calculator's template is a complete spec (it computes: exit 0, or 1 where the
    example is a published design that fails a check) and its JSON Schema accepts it."""
    from tests.conftest import ROOT

    code, text, _ = cli("template", kind)
    assert code == 0
    path = ROOT / f"_template_{kind}_test.toml"   # templates may refer to specs/ files
    try:
        path.write_text(text, encoding="utf-8")
        code, out, err = cli("run", path, "--format", "json")
    finally:
        path.unlink()
    assert code in (0, 1), err
    assert json.loads(out)["kind"] == kind
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    code, schema_text, _ = cli("schema", kind)
    jsonschema.validate(tomllib.loads(text), json.loads(schema_text))


def test_undercut_advice_says_when_no_shift_helps(tmp_path):
    """z1 = 5: the shift that removes the undercut makes the tooth pointed; the advice names
    the tooth number instead of a shift that another check would then reject."""
    path = spec(tmp_path, "z1 = 5\nz2 = 40\n")
    doc = json.loads(cli("run", path, "--format", "json")[1])
    c = {c["code"]: c for c in doc["checks"]}["UNDERCUT_PINION"]
    assert c["message"] == (
        "pinion undercut: x1 = 0.0000 < x_min1 = 0.7075; no shift removes it and keeps a tip "
        "of 0.25·m_n (x1 = 0.708 makes the tooth pointed): use z1 >= 18, or set "
        "gear.allow_undercut = true if it is deliberate")
