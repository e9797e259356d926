"""The drive calculator: stage chaining, files, failures, bearings, split."""

import json
import math
import os

import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import run, run_data
from geardesign.drive.split import split_ratio
from tests.conftest import SPECS
from tests.helpers_cli import cli

REDUCER = SPECS / "drive_two_stage_reducer.toml"


def test_two_stage_chain_carries_torque_speed_and_power():
    doc = run(REDUCER).document()
    d, stages = doc["results"]["drive"], doc["results"]["stages"]
    assert len(stages) == 2 and len(doc["results"]["stage_reports"]) == 2
    s1, s2 = stages
    assert s2["T_in"] == pytest.approx(s1["T_out"]) and s2["n_in"] == pytest.approx(s1["n_out"])
    assert s1["T_out"] == pytest.approx(s1["T_in"] * s1["ratio"] * s1["efficiency"])
    assert d["T_out"] == pytest.approx(1100.0)          # rated for the machine's torque
    assert d["u"] == pytest.approx(s1["ratio"] * s2["ratio"])
    assert d["n_out"] == pytest.approx(1455.0 / d["u"])
    # the stage report was computed with the drive's torque and speed
    st = doc["results"]["stage_reports"][1]
    assert st["inputs"]["load"]["torque1"] == pytest.approx(s2["T_in"])
    assert st["inputs"]["load"]["speed1"] == pytest.approx(s2["n_in"])


def test_bearing_life_matches_the_bearing_calculator_alone():
    doc = run(REDUCER).document()
    row = doc["results"]["bearings"][2]          # intermediate shaft, bearing A
    alone = run_data({"kind": "bearing", "method": "gost18855_94",
                      "bearing": {"designation": "6308"},
                      "load": {"F_r": row["F_r"], "F_a": row["F_a"], "speed": row["n"]},
                      "requirements": {"life": 20000.0}}).document()
    assert alone["results"]["life"]["L_sah"] == pytest.approx(row["life"], rel=1e-12)


def test_failing_stage_is_named_in_the_summary(tmp_path):
    text = REDUCER.read_text(encoding="utf-8").replace("face_width = 56.0", "face_width = 20.0")
    path = tmp_path / "d.toml"
    path.write_text(text, encoding="utf-8")
    code, out, _ = cli("run", path, "--format", "json")
    doc = json.loads(out)
    assert code == 1 and doc["verdict"] == "fail"
    c = {c["code"]: c for c in doc["checks"]}["STAGE_1"]
    assert not c["passed"] and "stage 1 \"high-speed helical\" (spur) fails CONTACT_FATIGUE" in \
        c["message"]
    assert doc["results"]["stages"][0]["verdict"] == "fail"
    code, out, _ = cli("run", path, "--format", "table")
    assert "✘ FAIL: 1 check(s) failed: STAGE_1" in out


def test_stage_file_is_resolved_relative_to_the_drive_spec(tmp_path):
    doc = run(SPECS / "drive_worm_spur.toml").document()
    assert doc["results"]["stages"][0]["kind"] == "worm"
    # run from another directory: same result
    cwd = os.getcwd()
    try:
        os.chdir(tmp_path)
        again = run(SPECS / "drive_worm_spur.toml").document()
    finally:
        os.chdir(cwd)
    assert again["results"]["drive"] == doc["results"]["drive"]


def _drive(tmp_path, name, stage_file):
    p = tmp_path / name
    p.write_text('kind = "drive"\n[motor]\npower = 1.5\nspeed = 1450.0\n[load]\n'
                 f'life_hours = 1000.0\n[[stage]]\nfile = "{stage_file}"\n', encoding="utf-8")
    return p


def test_missing_stage_file_is_one_line(tmp_path):
    path = _drive(tmp_path, "d.toml", "nope.toml")
    code, out, err = cli("run", path)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert err.startswith(f'{path}: stage[0].file = "nope.toml": file not found (')


def test_cycle_of_stage_files_is_one_line(tmp_path):
    _drive(tmp_path, "a.toml", "b.toml")
    b = _drive(tmp_path, "b.toml", "a.toml")
    code, out, err = cli("run", b)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "the stage files refer to each other in a cycle: a.toml -> b.toml" in err


@pytest.mark.parametrize("data, message", [
    ({"motor": {"speed": 1000.0}}, "motor.power: missing; give the motor's power (kW) or torque"),
    ({"motor": {"speed": 1000.0, "power": 1.0, "torque": 10.0}},
     "motor.torque = 10.0: give power or torque, not both"),
    ({"stage": [{"name": "x"}]}, 'stage[0].kind: missing; give the stage\'s calculator'),
    ({"stage": [{"kind": "drive"}]}, "stage[0].kind = \"drive\": an inline stage cannot be a drive"),
])
def test_input_rules(data, message):
    spec = {"kind": "drive", "motor": {"power": 1.5, "speed": 1450.0},
            "load": {"life_hours": 1000.0}}
    spec.update(data)
    if "stage" not in spec:
        spec["stage"] = [{"file": str(SPECS / "spur_reducer_through_hardened.toml")}]
    with pytest.raises(InputError) as exc:
        run_data(spec)
    assert exc.value.problems[0].line("").startswith(message)


def test_stage_errors_name_the_stage():
    spec = {"kind": "drive", "motor": {"power": 1.5, "speed": 1450.0},
            "load": {"life_hours": 1000.0},
            "stage": [{"kind": "spur", "gear": {"module": 2.0, "z1": 3, "z2": 40,
                                                 "face_width": 20.0}}]}
    with pytest.raises(InputError) as exc:
        run_data(spec)
    assert exc.value.problems[0].line("d.toml") == (
        "d.toml: stage[0]: gear.z1 = 3: must be an integer >= 5 and <= 1000")


def test_output_speed_and_motor_checks():
    text = REDUCER.read_text(encoding="utf-8")
    data = __import__("tomllib").loads(text)
    data["load"]["speed"] = 40.0
    data["load"]["torque"] = 1400.0
    doc = run_data(data).document()
    checks = {c["code"]: c for c in doc["checks"]}
    assert not checks["OUTPUT_SPEED"]["passed"] and "overall u = 36.375" in \
        checks["OUTPUT_SPEED"]["message"]
    assert not checks["MOTOR_TORQUE"]["passed"]


def test_split_rules():
    assert split_ratio(25.0, ["spur", "spur"], "developed") == pytest.approx([6.25, 4.0])
    assert split_ratio(27.0, ["spur"] * 3, "equal") == pytest.approx([3.0, 3.0, 3.0])
    r = split_ratio(100.0, ["worm", "spur"])
    assert r[1] == 2.5 and r[0] * r[1] == pytest.approx(100.0)
    # bevel-cylindrical: u_T = 1.1·sqrt(u) ([Dunaev]); three stages keep the product
    assert split_ratio(16.0, ["bevel", "spur"]) == pytest.approx([16.0 / 4.4, 4.4])
    r = split_ratio(40.0, ["bevel", "spur", "spur"])
    assert math.prod(r) == pytest.approx(40.0) and r[1] == pytest.approx(r[2])
    assert r[0] < 40.0 ** (1 / 3) < r[1]
    with pytest.raises(ValueError, match="bevel"):
        split_ratio(40.0, ["bevel", "bevel"])


def five_stage_text() -> str:
    """A five-stage spur drive (also timed by benchmarks/time_cases.py)."""
    stage = ('[[stage]]\nkind = "spur"\n[stage.gear]\nmodule = {m}\nz1 = 20\nz2 = 40\n'
             'face_width = {b}\nbearing_scheme = 6\n[stage.material.pinion]\ngrade = "40Kh"\n'
             'treatment = "improved"\nhardness_HB = 290.0\n[stage.material.wheel]\n'
             'grade = "40Kh"\ntreatment = "improved"\nhardness_HB = 260.0\n')
    return ('kind = "drive"\n[motor]\npower = 0.75\nspeed = 1450.0\n[load]\nlife_hours = '
            '10000.0\n' + "".join(stage.format(m=m, b=b) for m, b in
                                  ((1.0, 20.0), (1.5, 30.0), (2.0, 45.0), (3.0, 60.0),
                                   (4.0, 90.0))))


def test_five_stage_drive_runs(tmp_path):
    path = tmp_path / "five.toml"
    path.write_text(five_stage_text(), encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code in (0, 1), err
    assert len(json.loads(out)["results"]["stages"]) == 5


def test_template_runs(tmp_path):
    from tests.conftest import ROOT

    code, text, _ = cli("template", "drive")
    path = ROOT / "_drive_template_test.toml"   # the template refers to specs/... from the root
    try:
        path.write_text(text, encoding="utf-8")
        code, out, err = cli("run", path, "--format", "json")
    finally:
        path.unlink()
    assert code == 0, err
    assert json.loads(out)["results"]["split"]


def test_planetary_stage():
    doc = run(SPECS / "drive_planetary_spur.toml").document()
    s1, s2 = doc["results"]["stages"]
    plan = doc["results"]["stage_reports"][0]
    assert s1["kind"] == "planetary" and s1["ratio"] == pytest.approx(5.0)
    assert s1["efficiency"] == pytest.approx(plan["results"]["efficiency"]["eta"])
    assert plan["inputs"]["operation"]["torque"] == pytest.approx(s1["T_in"])
    assert s2["T_in"] == pytest.approx(s1["T_out"])


def test_each_stage_report_says_which_loads_the_drive_set():
    from geardesign.core.registry import run

    doc = run(SPECS / "drive_worm_spur.toml").document()
    notes = [c for part in doc["results"]["stage_reports"] for c in part["checks"]
             if c["code"] == "SET_BY_DRIVE"]
    assert len(notes) == 2
    assert notes[0]["message"].startswith("the drive sets load.torque2 = ")
    assert "(the stage's own load.torque2, load.speed1 not used)" in notes[0]["message"]
