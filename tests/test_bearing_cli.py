"""Bearing calculator through the command line: design failures exit 1 with the failed
check and what to change; warnings of the standard's limits; the selection mode."""

import json
import re
import sys

import pytest

from geardesign.core.registry import run_data
from tests.helpers_cli import cli

GOOD = """kind = "bearing"
method = "gost18855_94"
[bearing]
designation = "6208"
[load]
F_r = 3000.0
F_a = 1000.0
speed = 1000.0
[factors]
K_b = 1.3
"""


def spec(tmp_path, text):
    p = tmp_path / "s.toml"
    p.write_text(text, encoding="utf-8")
    return p


def checks(doc):
    return {c["code"]: c for c in doc["checks"]}


def document(**tables):
    data = {"kind": "bearing", "method": "gost18855_94"}
    data.update(tables)
    return run_data(data).document()


def test_life_below_required_fails_and_names_a_bearing_that_passes(tmp_path):
    path = spec(tmp_path, GOOD + "[requirements]\nlife = 6000.0\n")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1 and err == ""
    doc = json.loads(out)
    assert doc["verdict"] == "fail"
    life = checks(doc)["LIFE"]
    assert not life["passed"] and life["severity"] == "error"
    assert life["message"] == (
        "L_sah = 5 114 h < required 6 000 h: use a bearing with C_r >= 34.3 kN (now 32.5 kN); "
        "the catalogue SKF 6308 (GOST 308) would give 9 959 h, or reduce the load or the "
        "required life; set bearing.designation = \"6308\" (the next catalogue bearing of "
        "this type and bore; it passes when re-rated)")
    assert life["fix"] == {"bearing.designation": "6308"}
    code, out, _ = cli("run", path, "--format", "table")
    assert code == 1 and re.search(r"✘ FAIL\s+LIFE\s", out)


def test_life_met_passes(tmp_path):
    code, out, _ = cli("run", spec(tmp_path, GOOD + "[requirements]\nlife = 3000.0\n"),
                       "--format", "json")
    assert code == 0 and checks(json.loads(out))["LIFE"]["passed"]


def test_static_safety_fails():
    doc = document(bearing={"designation": "6204"}, load={"F_r": 3000.0, "speed": 100.0,
                                                          "F_r0": 9000.0})
    c = checks(doc)["STATIC_SAFETY"]
    assert not c["passed"] and doc["verdict"] == "fail"
    assert c["message"] == ("s_0 = C_0r/P_0 = 0.728 < 1: permanent deformation of the raceways; "
                            "use a bearing with C_0r >= 9 kN or reduce the peak load; set "
                            "bearing.designation = \"6404\" (the next catalogue bearing of "
                            "this type and bore; it passes when re-rated)")


def test_axial_load_beyond_table_warns():
    doc = document(bearing={"designation": "6204"}, load={"F_r": 1000.0, "F_a": 4000.0,
                                                          "speed": 100.0})
    c = checks(doc)["AXIAL_TABLE"]
    assert c["severity"] == "warning" and not c["passed"]
    assert c["message"].startswith("f0·Fa/C0r = 7.94 is beyond the X/Y table")


def test_load_above_static_rating_and_high_load_warn():
    doc = document(bearing={"designation": "6003"}, load={"F_r": 4000.0, "speed": 100.0},
                   requirements={"s0_min": 0.5})
    c = checks(doc)
    assert not c["HIGH_LOAD"]["passed"] and not c["LOAD_ABOVE_C0"]["passed"]
    assert c["LOAD_ABOVE_C0"]["severity"] == "warning"


def test_kappa_below_0_1_warns_and_uses_0_1():
    doc = run_data({"kind": "bearing", "method": "iso281_2007", "bearing": {"designation": "6208"},
                    "load": {"F_r": 3000.0, "speed": 50.0},
                    "lubrication": {"viscosity": 2.0, "contamination": "normal"}}).document()
    c = checks(doc)["KAPPA_RANGE"]
    assert c["severity"] == "warning" and c["message"].startswith("κ = 0.0")
    assert doc["results"]["life"]["a_ISO"] == pytest.approx(0.1, abs=2e-3)
    assert "C_U_ESTIMATED" not in checks(doc)           # the catalogue gives C_u (P_u)
    assert doc["results"]["bearing"]["C_u"] == 800.0


def test_cylindrical_axial_load_ignored_warns():
    doc = document(bearing={"type": "cylindrical_roller", "C_r": 50000.0},
                   load={"F_r": 3000.0, "F_a": 500.0, "speed": 1000.0})
    assert checks(doc)["AXIAL_LOAD_IGNORED"]["severity"] == "warning"


def test_inputs_of_the_other_edition_are_reported():
    doc = document(bearing={"designation": "6208"}, load={"F_r": 3000.0, "speed": 1000.0},
                   lubrication={"viscosity": 20.0, "contamination": "normal"})
    assert checks(doc)["IGNORED_INPUTS"]["message"] == (
        'not used by method = "gost18855_94": [lubrication] (a_ISO belongs to ISO 281:2007)')


def test_select_mode_chooses_the_smallest_that_passes(tmp_path):
    text = GOOD.replace('designation = "6208"', 'type = "deep_groove_ball"\nd = 40.0').replace(
        'method = "gost18855_94"', 'method = "gost18855_94"\nmode = "select"')
    code, out, _ = cli("run", spec(tmp_path, text + "[requirements]\nlife = 6000.0\n"),
                       "--format", "json")
    doc = json.loads(out)
    assert code == 0
    assert doc["results"]["selection"]["candidates"] == ["6008", "6208", "6308", "6408"]
    assert doc["results"]["selection"]["selected"] == "SKF 6308 (GOST 308)"
    code, out, _ = cli("run", spec(tmp_path, text + "[requirements]\nlife = 30000.0\n"),
                       "--format", "json")
    doc = json.loads(out)
    assert code == 1 and doc["results"]["selection"]["selected"] == "none"
    sel = checks(doc)["SELECTION"]
    assert not sel["passed"] and "C_r >= 64.4 kN is needed" in sel["message"]
    assert "LIFE" not in checks(doc)


def test_json_has_no_nan(tmp_path):
    code, out, _ = cli("run", spec(tmp_path, GOOD),
                       "--format", "json")
    assert code == 0 and "NaN" not in out and "Infinity" not in out


def test_no_numpy_in_a_bearing_process(tmp_path):
    import subprocess
    path = spec(tmp_path, GOOD)
    code = ("import sys, runpy; sys.argv=['geardesign','run',%r,'--format','json'];"
            "from geardesign.cli import main\ntry:\n main()\nexcept SystemExit: pass\n"
            "assert 'numpy' not in sys.modules and 'scipy' not in sys.modules" % str(path))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
