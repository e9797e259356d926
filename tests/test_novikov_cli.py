"""kind = "novikov" through the command line: design failures exit 1 with the failed
check named and advice; warnings do not fail; template and schema are usable; the JSON
has units for every numeric leaf and no NaN."""

import json
import re

import pytest

from geardesign.core.registry import run
from tests.conftest import SPECS
from tests.helpers_cli import cli

BASE = """kind = "novikov"
[gear]
module = {module}
z1 = {z1}
z2 = {z2}
helix_angle = {beta}
face_width = {b_w}
[material.pinion]
hardness = 300
[material.wheel]
hardness = 270
[accuracy]
grade_smoothness = {kp}
grade_contact = {kp}
[load]
torque2 = {T2}
"""
PASSING = dict(module=3.15, z1=21, z2=64, beta=18.0, b_w=50.0, kp=7, T2=250.0)


def spec(tmp_path, **kw):
    p = tmp_path / "s.toml"
    p.write_text(BASE.format(**{**PASSING, **kw}), encoding="utf-8")
    return p


def failed(doc):
    return [c["code"] for c in doc["checks"] if not c["passed"] and c["severity"] == "error"]


def test_passing_design_exits_0(tmp_path):
    code, out, err = cli("run", spec(tmp_path), "--format", "json")
    assert code == 0 and err == ""
    assert json.loads(out)["verdict"] == "pass"


DESIGN_FAILURES = {
    "contact interrupted": (dict(b_w=10.0), ["CONTACT_CONTINUITY"],
                            "increase the face width to at least 20.7 mm"),
    "contact stress": (dict(T2=900.0), ["SIGMA_H", "SIGMA_F_PINION", "SIGMA_F_WHEEL"],
                       "improve the accuracy grades"),
}


@pytest.mark.parametrize("name", DESIGN_FAILURES)
def test_design_failure_exit_1_with_advice(tmp_path, name):
    kw, codes, advice = DESIGN_FAILURES[name]
    path = spec(tmp_path, **kw)
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1 and err == ""
    doc = json.loads(out)
    assert doc["verdict"] == "fail" and failed(doc) == codes
    assert advice in next(c["message"] for c in doc["checks"] if c["code"] == codes[0])
    code, out, _ = cli("run", path, "--format", "table")
    assert code == 1
    assert re.search(rf"✘ FAIL\s+{codes[0]}\s", out)
    assert f"✘ FAIL: {len(codes)} check(s) failed: {', '.join(codes)}" in out


def test_overlap_ratio_warns_below_1_2(tmp_path):
    # b_w between (1 − δ)·p_x and 1.2·p_x: continuous, but little overlap
    code, out, _ = cli("run", spec(tmp_path, b_w=30.0), "--format", "json")
    doc = json.loads(out)
    checks = {c["code"]: c for c in doc["checks"]}
    assert checks["CONTACT_CONTINUITY"]["passed"]
    assert not checks["OVERLAP_RATIO"]["passed"]
    assert checks["OVERLAP_RATIO"]["severity"] == "warning"
    assert "increase the face width to at least 38.5 mm" in checks["OVERLAP_RATIO"]["message"]


def test_psi_clamping_is_reported(tmp_path):
    doc = json.loads(cli("run", spec(tmp_path), "--format", "json")[1])
    c = next(c for c in doc["checks"] if c["code"] == "PSI_RANGE")
    assert not c["passed"] and c["severity"] == "warning"
    assert "outside 0.05…0.25" in c["message"] and "clamped" in c["message"]


def test_every_numeric_result_has_a_unit_and_no_nan():
    for path in sorted(SPECS.glob("novikov_*.toml")):
        doc = run(path).document()
        text = json.dumps(doc, allow_nan=False)
        assert "NaN" not in text
        for sec, block in doc["results"].items():
            for key, value in block.items():
                numeric = isinstance(value, (int, float)) and not isinstance(value, bool)
                if numeric or (isinstance(value, list) and value
                               and not isinstance(value[0], str)):
                    assert f"results.{sec}.{key}" in doc["units"], (path.name, sec, key)


def test_template_is_a_valid_spec(tmp_path):
    code, text, _ = cli("template", "novikov")
    assert code == 0 and 'kind = "novikov"' in text
    p = tmp_path / "t.toml"
    p.write_text(text, encoding="utf-8")
    code, out, err = cli("validate", p)
    assert code == 0, err


def test_schema_and_list():
    code, out, _ = cli("schema", "novikov")
    js = json.loads(out)
    assert code == 0 and js["properties"]["kind"]["const"] == "novikov"
    assert js["properties"]["gear"]["properties"]["x1"]["maximum"] == 0.3
    code, out, _ = cli("list")
    assert re.search(r"^novikov\s", out, re.M)


def test_kind_command(tmp_path):
    code, out, _ = cli("novikov", spec(tmp_path), "--format", "markdown")
    assert code == 0 and "## Phase stresses (critical values)" in out
