"""pzdn design checks: an impossible or unsafe design is a failed check with advice
(exit 1, the report still printed); warnings do not fail the design (exit 0)."""

import json

import pytest

from tests.helpers_cli import cli
from tests.test_pzdn_inputs import SPRING, STARTUP

FAILURES = {
    # spring stress above the allowable
    "overstressed": (SPRING.replace("torque = 22.1", "torque = 30.0"), "SPRING_STRESS_1",
                     "spring 1 overstressed: σ = 1533 MPa > [σ] = 1200 MPa at T = 30 N·m; use "
                     "a wire of at least d_min = 6.51 mm, a stronger material or a smaller "
                     "design torque"),
    # coils / geometry impossible: index out of range, coils touching at full wind-up
    "index too small": (SPRING.replace("coil_diameter = 60.0", "coil_diameter = 18.0")
                        .replace("index = 10.0", "index = 3.0"), "SPRING_INDEX_1",
                        "spring 1: index D/d = 3.00 outside 4…20: the coil cannot be wound that "
                        "tight; use D >= 24.0 mm or a thinner wire"),
    "index too large": (SPRING.replace("wire_diameter = 6.0", "wire_diameter = 2.5")
                        .replace("torque = 22.1", "torque = 1.5").replace("index = 10.0\n", ""),
                        "SPRING_INDEX_1",
                        "spring 1: index D/d = 24.00 outside 4…20: the coil is too slack to keep "
                        "its shape; use D <= 50.0 mm or a thicker wire"),
    "coils touch": (SPRING.replace("pitch = 8.0", "pitch = 6.5") + "stop_angle = 200.0\n",
                    "COILS_TOUCH_1",
                    "spring 1: the coils touch before the full wind-up of 200° (pitch there "
                    "5.48 mm < d = 6 mm, body held at H = 25.5 mm): increase the pitch to at "
                    "least 7.11 mm, or let the body lengthen (ends_fixed_axially = false)"),
    "close-wound body held": (SPRING.replace("pitch = 8.0", "pitch = 6.0"), "COILS_TOUCH_1",
                              "spring 1: the coils touch before the full wind-up of 70° (pitch "
                              "there 5.64 mm < d = 6 mm, body held at H = 24.0 mm): increase the "
                              "pitch to at least 6.39 mm, or let the body lengthen "
                              "(ends_fixed_axially = false)"),
    "arbor": (SPRING + "arbor_diameter = 52.0\n", "ARBOR_CLEARANCE_1",
              "spring 1: wound up by 70° the inner diameter shrinks to 51.23 mm and grips the "
              "52 mm arbor: use a thinner arbor, a larger coil diameter or more coils"),
    # the coupling slips below the working torque
    "slip": (SPRING + "stop_angle = 45.0\n", "COUPLING_SLIP_1",
             "spring 1: the coupling reaches its stop at T_lim = 14.25 N·m, below the working "
             "torque 22.1 N·m, so it slips in normal running; raise stop_angle to at least "
             "69.8° or stiffen the spring (fewer coils, thicker wire, shorter finger arm)"),
    "stress at the torque limit": (SPRING + "stop_angle = 90.0\n", "SPRING_STRESS_AT_LIMIT_1",
                                   "spring 1: at the torque limit 28.50 N·m the coils reach "
                                   "σ = 1456 MPa > [σ]; lower stop_angle to at most 74.2° or "
                                   "use a thicker wire"),
    # the finger position that sets the stiffness
    "target unreachable": (SPRING + "leg_arm = 100.0\ntarget_stiffness = 30.0\n",
                           "TARGET_STIFFNESS_1",
                           "spring 1: target stiffness 30 N·m/rad unreachable: even with the "
                           "finger at the coil the stiffness is at most 18.141 N·m/rad (coils "
                           "alone) — use fewer coils or a thicker wire for a stiffer spring"),
    "target outside the slot": (SPRING + "leg_arm = 100.0\nslot_arms = [80.0, 140.0]\n"
                                "target_stiffness = 17.5\n", "TARGET_STIFFNESS_1",
                                "spring 1: target stiffness 17.5 N·m/rad needs the finger at "
                                "l = 55.2 mm, outside the slot 80…140 mm; lengthen the slot or "
                                "change the coils"),
    # start-up
    "motor too weak": (STARTUP.replace("T1 = 26.5", "T1 = 20.0"), "STARTUP_TORQUE",
                       "the motor starting torque 20.00 N·m does not exceed the resisting "
                       "moments T2 + T3 = 22.10 N·m: the machine cannot accelerate; use a "
                       "stronger motor or reduce the load"),
    "no break-away within t_end": (STARTUP.replace("t_end = 0.5", "t_end = 0.03"), "BREAKAWAY",
                                   "a driven mass never breaks away within t_end: its link "
                                   "never reaches the resisting moment; raise T1 or t_end, or "
                                   "check T2, T3"),
}

WARNINGS = {
    "regression out of range": ('kind = "pzdn"\n[regression]\nC12 = 24.7\n', "REGRESSION_RANGE",
                                "C12 = 24.7 N·m/rad lies outside 970…2910 N·m/rad around the "
                                "centre C0 = 1940 of the fitted design: the regression is "
                                "extrapolated there (the thesis itself uses it at 24.7 N·m/rad); "
                                "use the start-up model ([startup]) for a soft PZDN"),
    "spring too stiff for the wind-up": (SPRING.replace("coils = 4", "coils = 2")
                                         + "[motor]\nspeed = 950.0\n", "SPRING_WINDUP_1",
                                         "spring 1 too stiff for the motor wind-up: it turns "
                                         "34.9° at T = 22.1 N·m, the design angle is 45.0°; use "
                                         "at least 3 working coils (or a longer finger arm)"),
    "index outside the thesis' range": (SPRING.replace("coil_diameter = 60.0",
                                                       "coil_diameter = 84.0")
                                        .replace("index = 10.0", "index = 14.0"),
                                        "SPRING_INDEX_RANGE_1",
                                        "spring 1: index D/d = 14.00 outside the thesis' range "
                                        "4…12; prefer D = 24…72 mm for d = 6 mm"),
    "given index disagrees with D/d": (SPRING.replace("index = 10.0", "index = 8.0"),
                                       "SPRING_INDEX_MISMATCH_1",
                                       "spring 1: the given index c = 8 differs by 25 % from "
                                       "D/d = 10.00; k was taken with c = 8 (as the thesis); "
                                       "with D/d it is 1.0833 (σ = 1129 MPa): give index = "
                                       "10.00 or leave it out"),
    "allowables ratio": (SPRING.replace("sigma_allow = 1200.0", "tau_allow = 800.0\n"
                                        "sigma_over_tau = 1.8"), "SIGMA_OVER_TAU_1",
                         "spring 1: [σ]/[τ] = 1.80 outside the thesis' 1.25…1.5; check the "
                         "allowables"),
}


def _run(tmp_path, text):
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    return code, json.loads(out), err


@pytest.mark.parametrize("name", list(FAILURES))
def test_design_failure_exit_1(tmp_path, name):
    text, code_expected, message = FAILURES[name]
    code, doc, err = _run(tmp_path, text)
    assert code == 1 and err == ""
    assert doc["verdict"] == "fail"
    failed = {c["code"]: c for c in doc["checks"] if not c["passed"] and c["severity"] == "error"}
    assert code_expected in failed
    # a fix found by re-rating is appended: "; set KEY = VALUE (…; it passes when re-rated)"
    msg = failed[code_expected]["message"]
    assert msg == message or (msg.startswith(message + "; set ")
                              and msg.endswith("it passes when re-rated)")), msg


@pytest.mark.parametrize("name", list(WARNINGS))
def test_warning_does_not_fail(tmp_path, name):
    text, code_expected, message = WARNINGS[name]
    code, doc, _ = _run(tmp_path, text)
    assert code == 0 and doc["verdict"] == "pass"
    warned = {c["code"]: c for c in doc["checks"] if not c["passed"]}
    assert warned[code_expected]["severity"] == "warning"
    assert warned[code_expected]["message"] == message


def test_failed_design_prints_the_full_table(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(FAILURES["slip"][0], encoding="utf-8")
    code, out, _ = cli("run", path, "--format", "table")
    assert code == 1
    assert "✘ FAIL" in out and "COUPLING_SLIP_1" in out and "T_lim" in out


def test_coupling_gear_checks_come_from_the_spur_calculator(tmp_path):
    from tests.test_pzdn_inputs import GEAR

    code, doc, _ = _run(tmp_path, GEAR.replace("module = 2.5", "module = 0.5"))
    assert code == 1
    failed = {c["code"]: c for c in doc["checks"] if not c["passed"] and c["severity"] == "error"}
    assert list(failed) == ["COUPLING_GEAR"]
    assert failed["COUPLING_GEAR"]["message"] == (
        "coupling gear fails CONTACT_FATIGUE, BENDING_FATIGUE_PINION, BENDING_FATIGUE_WHEEL, "
        "STATIC_CONTACT, STATIC_BENDING_PINION, STATIC_BENDING_WHEEL of the spur calculator: "
        "see its report below for what to change (module, face width, materials)")
    (spur,) = doc["results"]["coupling_gear_rating"]
    assert spur["verdict"] == "fail"
    assert {"BENDING_FATIGUE_WHEEL", "BENDING_FATIGUE_PINION"} <= {
        c["code"] for c in spur["checks"] if not c["passed"]}
