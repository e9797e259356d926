"""Worm design checks: every failed check names what is wrong and what to change; a design
that fails an error check exits 1 with its full report; warnings keep exit 0.  Also the
design mode, the effect of the options, and the cost of a run."""

import copy
import json
import math
import re
import subprocess
import sys

import pytest

from geardesign.core.registry import run_data
from tests.conftest import flat
from tests.helpers_cli import cli

NOTE = {
    "kind": "worm",
    "gear": {"module": 6.3, "diameter_factor": 10.0, "z1": 2, "z2": 40, "center_distance": 160.0},
    "load": {"torque2": 500.0, "speed1": 1450.0},
    "wheel": {"material": "BrO10N1F1_centrifugal"},
}


def spec(**changes) -> dict:
    """The synthetic pair with changes given as table__key=value (None removes the key)."""
    data = copy.deepcopy(NOTE)
    for path, value in changes.items():
        table, key = path.split("__")
        data.setdefault(table, {})
        if value is None:
            data[table].pop(key, None)
        else:
            data[table][key] = value
    return data


def failed(doc: dict, severity: str = "error") -> dict:
    return {c["code"]: c["message"] for c in doc["checks"]
            if not c["passed"] and c["severity"] == severity}


HOIST = dict(gear__z1=1, gear__z2=44, gear__module=5.0, gear__diameter_factor=20.0,
             load__speed1=100.0, load__torque2=200.0)

ERRORS = {
    "self-locking when it is not wanted": (spec(**HOIST), {
        "SELF_LOCKING": "the pair is self-locking (γ_w = 2.86° <= ρ' = 3.41°): η = 0.437 and "
                        "the wheel cannot drive the worm; use more starts or a smaller q so "
                        "that γ_w > ρ', or set load.self_locking = \"require\" if it is wanted"}),
    "not self-locking when required": (spec(load__self_locking="require"), {
        "SELF_LOCKING": "the pair is not self-locking (γ_w = 10.50° > ρ' = 1.41°): the load can "
                        "drive the worm backwards; use z1 = 1 and a larger q so that "
                        "γ_w < ρ', or fit a brake"}),
    "contact stress above allowable": (spec(load__torque2=700.0), {
        "CONTACT_STRESS": "σ_H = 196.4 MPa > [σ]_H = 181.2 MPa: set gear.center_distance = "
                          "200, gear.module = 8, gear.diameter_factor = 10 (a standard pair, "
                          "x = 0; it passes when re-rated), use a stronger wheel material, or "
                          "harden and grind the worm"}),
    "sliding speed beyond the material": (spec(wheel__material="BrA9Zh3L_sand"), {
        "SLIDING_SPEED": "v_s = 5.25 m/s > 5 m/s allowed for BrA9Zh3L_sand (group II): "
                         "scuffing and wear; use a tin bronze for high sliding speeds (group "
                         "I), or lower the worm speed"}),
    "oil too hot": (spec(thermal__heat_transfer=9.0, thermal__base_share=0.0), {
        "OIL_TEMPERATURE": "oil temperature 108.2 °C > t_lim = 90 °C: add cooling fins (a "
                           "larger thermal.housing_area), a fan on the worm shaft (thermal.fan "
                           "= true), a water coil, or set gear.center_distance = "
                           "200, gear.module = 8, gear.diameter_factor = 10 (a standard pair, "
                           "x = 0; it passes when re-rated)"}),
    "worm deflection too large": (spec(worm__bearing_span=1500.0), {
        "WORM_DEFLECTION": "worm deflection f = 1.6077 mm > f_lim = 0.01·m = 0.0630 mm: the "
                           "worm bends out of mesh; set gear.center_distance = 315, "
                           "gear.module = 12.5, gear.diameter_factor = 10 (a standard pair, "
                           "x = 0.2; it passes when re-rated), or shorten the bearing span "
                           "(l = 1500 mm)"}),
    "face width above 0.75 d_a1": (spec(gear__face_width=60.0), {
        "FACE_WIDTH": "b2 = 60 mm > 0.75·d_a1 = 56.7 mm: the rim ends overhang the worm "
                      "threads and carry nothing; reduce face_width to at most 56.7 mm"}),
    "worm too short": (spec(gear__worm_length=80.0), {
        "WORM_LENGTH": "worm thread length b1 = 80 mm < 117.42 mm required for z2 = 40, "
                       "x = 0.3968 (grinding allowance included); increase worm_length to at "
                       "least 118 mm"}),
    "bending stress above a given allowable": (spec(wheel__sigma_FP=8.0), {
        "BENDING_STRESS": "σ_F = 10.7 MPa > [σ]_F = 8.0 MPa: the wheel teeth break; set "
                          "gear.center_distance = 200, gear.module = 8, gear.diameter_factor "
                          "= 10 (a standard pair, x = 0; it passes when re-rated), or use a "
                          "stronger wheel material"}),
    "peak torque": (spec(load__peak_torque=8000.0), {
        "CONTACT_STRESS_PEAK": "σ_Hmax = 664.1 MPa > [σ]_Hmax = 660.0 MPa at the peak torque "
                               "8000 N·m: the flanks yield; limit the peak torque (a torque "
                               "limiter), or set gear.center_distance = 200, gear.module = 8, "
                               "gear.diameter_factor = 10 (a standard pair, x = 0; it passes "
                               "when re-rated)",
        "BENDING_STRESS_PEAK": "σ_Fmax = 170.5 MPa > [σ]_Fmax = 132.0 MPa at the peak torque "
                               "8000 N·m: limit the peak torque, or set gear.center_distance = "
                               "200, gear.module = 8, gear.diameter_factor = 10 (a standard "
                               "pair, x = 0; it passes when re-rated)"}),
}


@pytest.mark.parametrize("name", ERRORS)
def test_failed_error_checks(name):
    data, expected = ERRORS[name]
    doc = run_data(data).document()
    assert doc["verdict"] == "fail"
    assert failed(doc) == expected


def test_undercut_for_few_wheel_teeth():
    doc = run_data(spec(gear__z1=1, gear__z2=20, gear__module=5.0, gear__center_distance=None,
                        gear__x=0.0)).document()
    assert failed(doc)["UNDERCUT_WHEEL"] == (
        "z2 = 20 < 26: the wheel teeth are undercut off the mid-plane and weak; use z2 >= 26 "
        "(28 or more for a power drive)")
    assert failed(doc, "warning")["WHEEL_TEETH"].startswith("z2 = 20 < 28: few wheel teeth")


def test_undercut_in_the_mid_plane_for_a_negative_shift():
    doc = run_data(spec(gear__z1=1, gear__z2=26, gear__module=5.0, gear__center_distance=None,
                        gear__x=-1.0)).document()
    assert failed(doc)["UNDERCUT_WHEEL"] == (
        "wheel undercut in the mid-plane: x = -1 < x_min = -0.5181; set gear.center_distance "
        "= 160, gear.module = 8, gear.diameter_factor = 12.5, gear.x = 0.75 (a standard pair; "
        "it passes when re-rated), or use more wheel teeth")


def test_contact_ratio_below_one():
    doc = run_data(spec(gear__z1=1, gear__z2=26, gear__x=1.0, gear__center_distance=None,
                        basic_worm__addendum_coef=0.5)).document()
    assert failed(doc)["CONTACT_RATIO"] == (
        "ε_α ≈ 0.645 < 1 in the wheel mid-plane: the mesh is not continuous; reduce x (no "
        "standard pair up to a_w = 500 mm passes when re-rated), or use more wheel teeth")


WARNINGS = {
    "q and m not a standard pair": (
        spec(gear__diameter_factor=9.0, gear__center_distance=None, gear__x=0.0),
        "STANDARD_PAIR", "(m, q) = (6.3, 9) is not a recommended pair (GOST 19672-74 table as "
                         "recalled); with m = 6.3 mm use q = 8, 10, 12.5, 14, 16, 20"),
    "module not standard": (
        spec(gear__module=6.5, gear__center_distance=None, gear__x=0.0), "STANDARD_PAIR",
        "m = 6.5 mm is not a GOST 19672-74 module (first row 1, 1.25, 1.6, 2, 2.5, 3.15, 4, 5, "
        "6.3, 8, 10, 12.5, 16, 20, 25 mm): no standard hob; use one of these"),
    "centre distance not standard": (
        spec(gear__center_distance=162.0), "STANDARD_CENTER_DISTANCE",
        "a_w = 162 mm is not a GOST 2144-76 centre distance (next: 180 mm): standard housings "
        "and hobs do not fit; use a standard a_w and let x follow"),
    "shift outside the preferred range": (
        spec(gear__center_distance=163.0), "SHIFT_RANGE",
        "x = 0.873 outside the preferred -0.5 ... +0.7: the wheel teeth become pointed; change "
        "a_w, m or q to bring x nearer 0"),
    "many wheel teeth": (
        spec(gear__z2=90, gear__diameter_factor=20.0, gear__center_distance=None, gear__x=0.0),
        "WHEEL_TEETH", "z2 = 90 > 80: the worm becomes long and flexible for a power drive; use "
                       "more starts, two stages, or check WORM_DEFLECTION closely"),
    "slender worm": (
        spec(gear__diameter_factor=8.0, gear__z2=50, gear__center_distance=None, gear__x=0.0),
        "WORM_STIFFNESS_Q", "q = 8 < 0.212·z2 = 10.6: slender worm; use a larger q or mind "
                            "WORM_DEFLECTION"),
    "three starts": (
        spec(gear__z1=3, gear__center_distance=None, gear__x=0.0), "WORM_STARTS",
        "z1 = 3 is not a GOST 2144-76 number of starts (1, 2, 4): no standard hob; use z1 = 2 "
        "or 4"),
    "self-locking not dependable": (
        spec(gear__z1=1, gear__z2=48, gear__module=5.0, gear__diameter_factor=16.0,
             load__speed1=100.0, load__torque2=1500.0, wheel__material="BrA9Zh3L_sand",
             load__self_locking="require"),
        "SELF_LOCKING_RELIABILITY", "γ_w = 3.58° > 3.5°: self-locking is not dependable under "
                                    "vibration or shocks; fit a brake or use γ_w < 3.5°"),
}


@pytest.mark.parametrize("name", WARNINGS)
def test_warnings_keep_the_verdict(name):
    data, code, message = WARNINGS[name]
    doc = run_data(data).document()
    assert doc["verdict"] == "pass", failed(doc)
    assert failed(doc, "warning")[code] == message


def test_self_locking_any_is_information():
    doc = run_data(spec(load__self_locking="any", **HOIST)).document()
    sl = {c["code"]: c for c in doc["checks"]}["SELF_LOCKING"]
    assert sl["severity"] == "info" and sl["passed"]
    assert sl["message"] == "the pair is self-locking (γ_w = 2.86° <= ρ' = 3.41°)"
    assert flat(doc)["eta_reverse"] == 0.0


def test_design_failure_exits_1_with_the_full_report(tmp_path):
    path = tmp_path / "hot.toml"
    path.write_text(
        'kind = "worm"\n[gear]\nmodule = 6.3\ndiameter_factor = 10.0\nz1 = 2\nz2 = 40\n'
        'center_distance = 160.0\n[load]\ntorque2 = 500.0\nspeed1 = 1450.0\n[wheel]\n'
        'material = "BrO10N1F1_centrifugal"\n[thermal]\nheat_transfer = 9.0\nbase_share = 0.0\n',
        encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 1 and err == ""
    doc = json.loads(out)
    assert doc["verdict"] == "fail" and "t_oil" in doc["results"]["thermal"]
    code, out, _ = cli("run", path, "--format", "table")
    assert code == 1
    assert re.search(r"✘ FAIL\s+OIL_TEMPERATURE\s", out)
    assert "✘ FAIL: 1 check(s) failed: OIL_TEMPERATURE" in out


# ----------------------------------------------------------------------------- options


def test_fan_cools_and_reports_its_coefficient():
    hot = flat(run_data(spec(thermal__heat_transfer=9.0, thermal__base_share=0.0)).document())
    fan = flat(run_data(spec(thermal__heat_transfer=9.0, thermal__base_share=0.0,
                             thermal__fan=True)).document())
    assert fan["t_oil"] < hot["t_oil"]
    assert math.isclose(fan["K_T_fan"], 21.0 + (29.0 - 21.0) * 450.0 / 500.0)  # 1450 min^-1


def test_tin_free_bronze_has_more_friction():
    bronze = flat(run_data(spec()).document())
    alu = flat(run_data(spec(wheel__material="BrA9Zh3L_sand")).document())
    assert math.isclose(alu["f"], 1.4 * bronze["f_table"]) and alu["eta"] < bronze["eta"]
    assert math.isclose(alu["sigma_HP"], 300.0 - 25.0 * alu["v_s"])


def test_reversing_load_lowers_the_bending_allowable():
    one_way = flat(run_data(spec()).document())
    rev = flat(run_data(spec(load__reversing=True)).document())
    assert math.isclose(rev["sigma_FP"], one_way["K_FL"] * 0.16 * 285.0)
    assert rev["sigma_FP"] < one_way["sigma_FP"]


def test_spectrum_raises_k_beta_and_lowers_the_cycles():
    data = spec()
    data["load"]["spectrum"] = [{"torque_ratio": 1.0, "time_share": 0.5},
                                {"torque_ratio": 0.5, "time_share": 0.5}]
    v = flat(run_data(data).document())
    assert math.isclose(v["X"], 0.75)
    assert math.isclose(v["K_beta"], 1.0 + (40.0 / 86.0) ** 3 * 0.25)
    assert math.isclose(v["N_HE"], v["N"] * (0.5 + 0.5 * 0.5 ** 4))


def test_given_friction_coefficient_replaces_the_table():
    v = flat(run_data(spec(friction__coefficient=0.05)).document())
    assert math.isclose(v["f"], 0.05) and math.isclose(v["rho"], math.degrees(math.atan(0.05)))


def test_design_mode_rows_and_standard_proposal():
    data = {"kind": "worm", "mode": "design", "gear": {"ratio": 20.0},
            "load": {"torque2": 500.0, "speed1": 1450.0},
            "wheel": {"material": "BrO10N1F1_centrifugal"}}
    doc = run_data(data).document()
    d = doc["results"]["design"]
    assert d["a_w_proposed"] == 160.0 and d["standard"] is True
    assert d["a_w_required"] < 160.0 and d["q_design"] == 10.0
    assert doc["checks"][0]["code"] == "DESIGN_STANDARD" and doc["checks"][0]["passed"]
    assert doc["verdict"] == "pass"


def test_design_mode_without_a_standard_module_warns():
    data = {"kind": "worm", "mode": "design", "gear": {"ratio": 25.0, "diameter_factor": 9.0},
            "load": {"torque2": 500.0, "speed1": 1450.0},
            "wheel": {"material": "BrO10N1F1_centrifugal"}}
    doc = run_data(data).document()
    assert failed(doc, "warning")["DESIGN_STANDARD"] == (
        "no GOST 19672-74 module and diameter factor give |x| <= 1 at a_w = 160 mm with q = 9; "
        "the module m = 5.4237 mm is not standard: leave gear.diameter_factor out so that q "
        'may change, or set design.center_distance_rows = "both"')


def test_result_keys_are_unique_across_sections():
    for data in (spec(), {"kind": "worm", "mode": "design", "gear": {"ratio": 20.0},
                          "load": {"torque2": 500.0, "speed1": 1450.0},
                          "wheel": {"material": "BrO10N1F1_centrifugal"}}):
        doc = run_data(data).document()
        keys = [k for sec in doc["results"].values() for k in sec]
        assert len(keys) == len(set(keys))


def test_template_validates_and_runs(tmp_path):
    code, out, _ = cli("template", "worm")
    assert code == 0
    path = tmp_path / "t.toml"
    path.write_text(out, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code in (0, 1) and err == ""
    assert json.loads(out)["kind"] == "worm"


def test_no_numpy_scipy_or_rich_in_a_json_run(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(
        'kind = "worm"\n[gear]\nmodule = 6.3\ndiameter_factor = 10.0\nz1 = 2\nz2 = 40\n'
        '[load]\ntorque2 = 500.0\nspeed1 = 1450.0\n[wheel]\nmaterial = "SCh20"\n',
        encoding="utf-8")
    code = ("import sys; sys.argv=['geardesign','run',%r,'--format','json'];"
            "from geardesign.cli import main\ntry:\n main()\nexcept SystemExit: pass\n"
            "heavy=[m for m in ('numpy','scipy','rich') if m in sys.modules]\n"
            "assert not heavy, heavy" % str(path))
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr


@pytest.mark.parametrize("ratio, says", [(5.0, True), (6.0, True), (6.5, False), (20.0, False)])
def test_a_ratio_no_worm_pair_can_give_says_so(ratio, says):
    """Below u = 26/4 = 6.5 no number of starts gives the wheel the 26 teeth it needs: the
    undercut check says to use a cylindrical stage instead of asking for teeth the ratio
    cannot have."""
    import tomllib
    from pathlib import Path

    data = tomllib.loads((Path(__file__).resolve().parent.parent / "specs" /
                          "worm_design.toml").read_text(encoding="utf-8"))
    data["gear"]["ratio"] = ratio
    checks = {c.code: c for c in run_data(data, "s.toml").checks}
    tail = "a worm pair needs u >= 6.5, use a cylindrical stage for this ratio"
    message = checks["UNDERCUT_WHEEL"].message
    assert (tail in message) == says, message
