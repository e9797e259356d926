"""kind = "wave_gear": every input rule (exact one-line message, exit 2), every failed check
(exit 1) and warning; K_zh behaviour."""

import json
import math

import pytest

from geardesign.core.registry import run_data
from geardesign.wave_gear import rim as R
from tests.helpers_cli import cli, write_spec as spec, run_failing, failed_errors, run_bad

GOOD = """kind = "wave_gear"
[gear]
module = 1.0
flex_teeth = 200
rim_thickness = 2.5
[material]
sigma_m1 = 450.0
K_sigma = 1.6
"""


def gear(extra):
    return GOOD.replace("rim_thickness = 2.5\n", "rim_thickness = 2.5\n" + extra)


BAD = [
    ("rigid teeth not a multiple of the waves", gear("rigid_teeth = 203\n"),
     ["s.toml: gear.rigid_teeth = 203: z_b − z_g = 3 must be a positive multiple of the "
      "number of waves U = 2; use rigid_teeth = 202 (or 204)"]),
    ("rigid wheel smaller", gear("rigid_teeth = 198\n"),
     ["s.toml: gear.rigid_teeth = 198: z_b − z_g = -2 must be a positive multiple of the "
      "number of waves U = 2; use rigid_teeth = 202 (or 204)"]),
    ("shift and rule", gear('shift = 3.0\nshift_rule = "eq8"\n'),
     ['s.toml: gear.shift_rule = "eq8": applies only when gear.shift is not given; remove '
      "one of them"]),
    ("fillet too large", GOOD + "[rack]\nroot_radius_coef = 0.9\n",
     ["s.toml: rack.root_radius_coef = 0.9: too large: root fillet ρ_f* = 0.9 does not fit "
      "the tooth space (flat bottom half-width -0.2998 < 0); reduce it"]),
    ("one wave", gear("waves = 1\n"),
     ["s.toml: gear.waves = 1: must be an integer >= 2 and <= 4"]),
    ("no endurance limit", GOOD.replace("sigma_m1 = 450.0\n", ""),
     ["s.toml: material.sigma_m1: missing; required: a number >= 0.001 and <= 3000 (MPa) "
      "(bending endurance limit (symmetric cycle))"]),
]


@pytest.mark.parametrize("name", [b[0] for b in BAD])
def test_bad_input_one_line_exit_2(tmp_path, name):
    _, text, expected = next(b for b in BAD if b[0] == name)
    assert run_bad(tmp_path, text) == expected


FAILS = [
    ("rim too thin", GOOD.replace("rim_thickness = 2.5", "rim_thickness = 1.2"),
     "RIM_THICKNESS",
     "rim thickness H0 = 1.2 mm is only 1.2·m: the teeth dominate the rim stiffness "
     "(K_zh = 1.92); use H0 >= 1.5 mm, preferably 2.5...3 mm"),
    ("endurance", GOOD.replace("sigma_m1 = 450.0", "sigma_m1 = 200.0"), "FLEX_ENDURANCE",
     "fatigue safety factor of the flexible wheel s = 1.22 < s_min = 1.5 (σ_a = 163 MPa "
     "against σ_-1 = 200 MPa): reduce the radial deflection to w0 <= 0.816 mm, increase the "
     "wheel diameter (σ ∝ 1/r_m²) or use a steel with σ_-1 >= 245 MPa"),
]


@pytest.mark.parametrize("name", [f[0] for f in FAILS])
def test_design_failures_exit_1(tmp_path, name):
    _, text, code_expected, message = next(f for f in FAILS if f[0] == name)
    doc = run_failing(tmp_path, text)
    failed = failed_errors(doc)
    assert [c["code"] for c in failed] == [code_expected]
    # a fix found by re-rating is appended: "; set KEY = VALUE (…; it passes when re-rated)"
    msg = failed[0]["message"]
    assert msg == message or (msg.startswith(message + "; set ")
                              and msg.endswith("it passes when re-rated)")), msg


WARNINGS = [
    ("thin but allowed", GOOD.replace("rim_thickness = 2.5", "rim_thickness = 2.0"),
     "RIM_THICKNESS_LOW",
     "H0/m = 2 < 2.5: K_zh rises steeply below 2.5...3 (here 1.540); prefer H0 = 2.5...3 mm"),
    ("deflection", gear("radial_deflection = 1.5\n"), "DEFLECTION",
     "w0/m = 1.5 outside 0.8...1.3: too little deflection risks ratcheting, too much raises "
     "the bending stress; the paper's wheels have w0 = m"),
    ("large gear", GOOD + "[load]\noutput_torque = 200000.0\n", "AXIAL_FIXATION",
     "output torque 200000 N·m: in large wave gears the skewed generator discs screw into "
     "the flexible wheel and load its fastening axially; fix the generator and the flexible "
     "wheel axially without play and lubricate the disc contact"),
    ("low ratio", GOOD.replace("flex_teeth = 200", "flex_teeth = 100")
     .replace("sigma_m1 = 450.0", "sigma_m1 = 1000.0"), "RATIO_RANGE",
     "ratio 50.0 outside the usual single-stage range 60...320: a thick rim for the "
     "diameter, high stress; check the tooth numbers"),
]


@pytest.mark.parametrize("name", [w[0] for w in WARNINGS])
def test_warnings_exit_0(tmp_path, name):
    _, text, code_expected, message = next(w for w in WARNINGS if w[0] == name)
    code, out, _ = cli("run", spec(tmp_path, text), "--format", "json")
    doc = json.loads(out)
    assert code == 0
    warn = [c for c in doc["checks"] if not c["passed"]]
    assert [(c["code"], c["severity"]) for c in warn] == [(code_expected, "warning")]
    assert warn[0]["message"] == message


def test_k_zh_falls_with_rim_thickness_and_rises_with_tooth_height():
    rack = R.rack_space(math.radians(20.0))
    k = [R.stiffness_factor(nu, rack, 0.45) for nu in (1.0, 1.5, 2.0, 3.0, 5.0, 10.0)]
    assert all(a > b > 1.0 for a, b in zip(k, k[1:]))
    h = [R.stiffness_factor(2.5, rack, h) for h in (0.1, 0.25, 0.45, 1.0, 2.25)]
    assert all(a < b for a, b in zip(h, h[1:]))
    assert R.stiffness_factor(2.5, rack, 0.0) == 1.0


def test_defaults_and_assumed_values():
    doc = run_data({"kind": "wave_gear",
                    "gear": {"module": 1.0, "flex_teeth": 200, "rim_thickness": 2.5},
                    "material": {"sigma_m1": 450.0, "K_sigma": 1.6}}).document()
    assert {"gear.rigid_teeth", "gear.shift_rule", "gear.radial_deflection"} <= set(
        doc["assumed"])
    g = doc["results"]["geometry"]
    assert g["z_b"] == 202 and g["u_rigid_fixed"] == -100.0 and g["u_flex_fixed"] == 101.0
    assert g["x"] == pytest.approx(2.15 + 0.009 * 200)
    s = doc["results"]["strength"]
    assert s["sigma_smooth"] == pytest.approx(1.5 * 206000 * 1.0 * 2.5 / g["r_m"] ** 2)


def test_torsion_enters_the_combined_safety_factor():
    base = {"kind": "wave_gear",
            "gear": {"module": 1.0, "flex_teeth": 200, "rim_thickness": 2.5,
                     "shell_thickness": 1.0},
            "material": {"sigma_m1": 450.0, "K_sigma": 1.6},
            "load": {"output_torque": 2000.0, "reversing": True}}
    s = run_data(base).document()["results"]["strength"]
    assert s["tau"] == pytest.approx(2000e3 / (2 * math.pi * 103.95 ** 2 * 1.0))
    assert s["s_tau"] == pytest.approx(0.58 * 450 / s["tau"])
    assert s["s"] == pytest.approx(s["s_sigma"] * s["s_tau"] / math.hypot(s["s_sigma"],
                                                                          s["s_tau"]))


def test_template_runs(tmp_path):
    code, text, _ = cli("template", "wave_gear")
    code, out, err = cli("run", spec(tmp_path, text), "--format", "json")
    assert code == 0, err
