"""Bad pzdn input: one line per problem naming file, key, value and what is allowed;
exit 2; no traceback; nothing on stdout.  Every cross-key rule of the calculator and the
single-key rules of the schema, one test each."""

import pytest

from tests.conftest import ROOT
from tests.helpers_cli import cli

SPRING = '''kind = "pzdn"
[[spring]]
torque = 22.1
wire_diameter = 6.0
index = 10.0
coil_diameter = 60.0
coils = 4
pitch = 8.0
sigma_allow = 1200.0
'''
STARTUP = '''kind = "pzdn"
[startup]
T1 = 26.5
T2 = 4.4
T3 = 17.7
J1 = 0.038
J2 = 0.026
J3 = 0.021
C12 = 8.33
C13 = 25.0
t_end = 0.5
'''
REG = '''kind = "pzdn"
[regression]
pzdn_stiffness = 25.0
drive_stiffness = 1940.0
'''
GEAR = (ROOT / "specs" / "pzdn_ko2_coupling_gear.toml").read_text(encoding="utf-8")
BODY = len('kind = "pzdn"\n')

CASES = {
    "nothing": 'kind = "pzdn"\n',
    "motor_alone": 'kind = "pzdn"\n[motor]\nspeed = 950.0\npower = 2.2\n' + REG[BODY:],
    "dup_name": SPRING.replace("torque = 22.1", 'name = "a"\ntorque = 22.1') + SPRING[BODY:].replace("torque = 22.1", 'name = "a"\ntorque = 22.1'),
    "schema_motor_speed": SPRING + "[motor]\nspeed = 0.0\n",
    "sigma_both": SPRING + 'sigma_over_tau = 1.5\n',
    "no_allow": SPRING.replace("sigma_allow = 1200.0\n", ""),
    "no_D": SPRING.replace("index = 10.0\n", "").replace("coil_diameter = 60.0\n", ""),
    "D_small": SPRING.replace("coil_diameter = 60.0", "coil_diameter = 5.0"),
    "D_small_outer": SPRING.replace("coil_diameter = 60.0", 'coil_diameter = 11.0\ndiameter_basis = "outer"'),
    "pitch_small": SPRING.replace("pitch = 8.0", "pitch = 5.0"),
    "arm_inside": SPRING + 'leg_arm = 25.0\n',
    "arm2_inside": SPRING + 'leg2_arm = 25.0\n',
    "slot_order": SPRING + 'slot_arms = [140.0, 80.0]\n',
    "slot_inside": SPRING + 'slot_arms = [20.0, 80.0]\n',
    "arm_out_of_slot": SPRING + 'leg_arm = 150.0\nslot_arms = [80.0, 140.0]\n',
    "no_coils": SPRING.replace("coils = 4\n", ""),
    "gear_peak": GEAR.replace("peak_torque = 48.6", "peak_torque = 10.0"),
    "gear_hardness": GEAR.replace("hardness_HB = 250.0\n", ""),
    "gear_grade": GEAR.replace('grade = "45"', 'grade = "46"', 1),
    "gear_treatment": GEAR.replace('treatment = "improved"', 'treatment = "carburized"\nhardness_HRC = 60.0', 1),
    "gear_shift_sum": GEAR.replace("\nz2 = 42\n", "\nz2 = 42\nx1 = -1.0\nx2 = -1.0\n"),
    "c12_both": STARTUP + 'C12_spring = "x"\n',
    "c12_neither": STARTUP.replace("C12 = 8.33\n", ""),
    "c12_unknown": STARTUP.replace("C12 = 8.33\n", 'C12_spring = "x"\n'),
    "c12_unknown_with": SPRING.replace("torque = 22.1", 'name = "knitting"\ntorque = 22.1') + STARTUP[BODY:].replace("C12 = 8.33\n", 'C12_spring = "take_down"\n'),
    "one_drive": STARTUP + 'C12_drive = 1940.0\n',
    "cf_rise": STARTUP + 'method = "closed_form"\nrise_time = 0.015\n',
    "cf_damp": STARTUP + 'method = "closed_form"\ndamping_ratio = 0.05\n',
    "cf_motor": STARTUP + 'method = "closed_form"\nmotor_model = "kloss"\n',
    "kloss_key": STARTUP + 'kloss_max_torque = 48.0\n',
    "curve_key": STARTUP + 'curve_speed = [0.0, 900.0]\n',
    "kloss_missing": STARTUP + 'motor_model = "kloss"\nkloss_max_torque = 48.0\n',
    "curve_missing": STARTUP + 'motor_model = "curve"\ncurve_speed = [0.0, 900.0]\n',
    "curve_len": STARTUP + 'motor_model = "curve"\ncurve_speed = [0.0, 900.0]\ncurve_torque = [40.0, 45.0, 0.0]\n',
    "curve_order": STARTUP + 'motor_model = "curve"\ncurve_speed = [0.0, 900.0, 800.0]\ncurve_torque = [40.0, 45.0, 0.0]\n',
    "plot_ext": STARTUP + 'plot = "x.pdf"\n',
    "plot_hist": STARTUP + 'plot = "x.png"\nhistory_points = 0\n',
    "no_tend": STARTUP.replace("t_end = 0.5\n", ""),
    "stall": STARTUP.replace("t_end = 0.5\n", "motor_speed = 950.0\n").replace("T1 = 26.5", "T1 = 20.0"),
    "reg_both": REG + 'C12 = 24.7\n',
    "reg_none": 'kind = "pzdn"\n[regression]\ndrive_stiffness = 1940.0\n',
    # single-key rules of the schema
    "schema_torque": SPRING.replace("torque = 22.1", "torque = -1.0"),
    "schema_curv": SPRING + 'curvature_factor = "wahll"\n',
    "schema_leg_model": SPRING + 'leg_model = "cantilever"\n',
    "schema_material": SPRING + 'material = "steel65"\n',
    "schema_slot": SPRING + 'slot_arms = [80.0]\n',
    "schema_coils": SPRING.replace("coils = 4", "coils = 0"),
    "schema_unknown": SPRING + 'wire_dia = 6.0\n',
    "schema_method": STARTUP + 'method = "rk4"\n',
    "schema_J": STARTUP.replace("J1 = 0.038", "J1 = 0.0"),
    "schema_zeta": STARTUP + 'damping_ratio = -0.1\n',
    "schema_sweep": STARTUP + 'sweep = []\n',
    "schema_hist": STARTUP + 'history_points = -1\n',
    "schema_z1": GEAR.replace("z1 = 20", "z1 = 3"),
    "schema_torque_on": GEAR.replace('torque_on = "wheel"', 'torque_on = "sun"'),
    "schema_reg": REG.replace("pzdn_stiffness = 25.0", "pzdn_stiffness = 0.0"),
}

EXPECTED = {
    'nothing': [
        's.toml: nothing to compute: give [[spring]] tables, [coupling_gear], [startup] or [regression]',
    ],
    'motor_alone': [
        's.toml: motor: applies only with [[spring]] tables (the wind-up angle of method A); remove it or add the springs',
    ],
    'dup_name': [
        's.toml: spring[1].name = "a": spring[0] has the same name; give each spring its own name',
    ],
    'schema_motor_speed': [
        's.toml: motor.speed = 0.0: must be a number >= 0.001 and <= 100000 (min^-1)',
    ],
    'sigma_both': [
        's.toml: spring[0].sigma_over_tau = 1.5: give sigma_allow or sigma_over_tau (× tau_allow), not both',
    ],
    'no_allow': [
        's.toml: spring[0].sigma_allow: missing; give the allowable bending stress sigma_allow, or tau_allow (with sigma_over_tau, default 1.5), or a material from the library',
    ],
    'no_D': [
        's.toml: spring[0].coil_diameter: missing; give the coil diameter or the spring index (index), or both',
    ],
    'D_small': [
        's.toml: spring[0].coil_diameter = 5.0: must exceed the wire diameter d = 6 mm (a mean coil diameter up to it leaves no bore); increase it or use a thinner wire',
    ],
    'D_small_outer': [
        's.toml: spring[0].coil_diameter = 11.0: must exceed 2·d = 12 mm (an outer coil diameter up to it leaves no bore); increase it or use a thinner wire',
    ],
    'pitch_small': [
        's.toml: spring[0].pitch = 5.0: smaller than the wire diameter d = 6 mm: the coils would overlap; give pitch >= d (= d: close-wound)',
    ],
    'arm_inside': [
        's.toml: spring[0].leg_arm = 25.0: must exceed the coil radius D/2 = 30 mm: the arm is measured from the spring axis to the load point',
    ],
    'arm2_inside': [
        's.toml: spring[0].leg2_arm = 25.0: must exceed the coil radius D/2 = 30 mm: the arm is measured from the spring axis to the load point',
    ],
    'slot_order': [
        's.toml: spring[0].slot_arms = [140.0, 80.0]: give [least arm, largest arm] with least < largest',
    ],
    'slot_inside': [
        's.toml: spring[0].slot_arms = [20.0, 80.0]: the slot must lie outside the coil: least arm > D/2 = 30 mm',
    ],
    'arm_out_of_slot': [
        's.toml: spring[0].leg_arm = 150.0: the finger must sit in its slot: 80 … 140 mm',
    ],
    'no_coils': [
        's.toml: spring[0].coils: missing; give the number of working coils, or [motor] (or design_angle) to compute it from the wind-up angle (method A)',
    ],
    'gear_peak': [
        's.toml: coupling_gear.peak_torque = 10.0: smaller than the working torque 22.1 N·m; give the largest short-time torque',
    ],
    'gear_hardness': [
        's.toml: coupling_gear.pinion.hardness_HB: missing; required: the surface hardness in HB for treatment "improved"',
    ],
    'gear_grade': [
        's.toml: coupling_gear.pinion.grade = "46": unknown steel (did you mean \'45\'?); known: 45, 40Kh, 40KhN, 35KhM, 30KhGSA, 20Kh, 18KhGT, 20KhN3A, 12KhN3A, 38Kh2MYuA, 42CrMo4, 31CrMo12, 33CrMoV12-9, 34CrAlMo5-10, C45, 34CrNiMo6, 16MnCr5, 20MnCr5, 18CrNiMo7-6, 4340, 8620, 9310, 40KhL (and equivalents such as 41Cr4, 4140, 1045: `geardesign materials` lists them); or leave out grade and give the properties',
    ],
    'gear_treatment': [
        's.toml: coupling_gear.pinion.treatment = "carburized": not a treatment for steel 45; use one of normalized, improved, induction',
    ],
    'gear_shift_sum': [
        's.toml: coupling_gear.x1 + coupling_gear.x2 = -2.0: too negative: inv α_tw = -0.00857757 <= 0, no working pressure angle exists; x1 + x2 must be > -1.2694',
    ],
    'c12_both': [
        's.toml: startup.C12_spring = "x": give C12 or C12_spring, not both',
    ],
    'c12_neither': [
        's.toml: startup.C12: missing; give the link stiffness C12 [N·m/rad], or C12_spring, the name of the [[spring]] that gives it',
    ],
    'c12_unknown': [
        's.toml: startup.C12_spring = "x": no [[spring]] of that name; known: none: add [[spring]] tables',
    ],
    'c12_unknown_with': [
        's.toml: startup.C12_spring = "take_down": no [[spring]] of that name; known: "knitting"',
    ],
    'one_drive': [
        's.toml: startup.C13_drive: missing; give the drive stiffness of both lines (C12_drive and C13_drive) or of neither',
    ],
    'cf_rise': [
        's.toml: startup.rise_time = 0.015: applies only to the numerical integration: the closed form is for a step torque without damping; use method = "ode" or "both"',
    ],
    'cf_damp': [
        's.toml: startup.damping_ratio = 0.05: applies only to the numerical integration: the closed form is for a step torque without damping; use method = "ode" or "both"',
    ],
    'cf_motor': [
        's.toml: startup.motor_model = "kloss": the closed form needs a constant torque T1; use method = "ode" or "both"',
    ],
    'kloss_key': [
        's.toml: startup.kloss_max_torque = 48.0: applies only with motor_model = "kloss"',
    ],
    'curve_key': [
        's.toml: startup.curve_speed = [0.0, 900.0]: applies only with motor_model = "curve"',
    ],
    'kloss_missing': [
        's.toml: startup.kloss_critical_slip: missing; required with motor_model = "kloss" (breakdown torque, critical slip, synchronous speed)',
    ],
    'curve_missing': [
        's.toml: startup.curve_torque: missing; required with motor_model = "curve" (speeds and torques of the characteristic)',
    ],
    'curve_len': [
        's.toml: startup.curve_torque = [40.0, 45.0, 0.0]: needs one torque per speed: 2 speeds, 3 torques',
    ],
    'curve_order': [
        's.toml: startup.curve_speed = [0.0, 900.0, 800.0]: the speeds must increase strictly',
    ],
    'plot_ext': [
        's.toml: startup.plot = "x.pdf": the plot file must end in .png or .svg',
    ],
    'plot_hist': [
        's.toml: startup.history_points = 0: must be at least 2 to draw startup.plot',
    ],
    'no_tend': [
        's.toml: startup.t_end: missing; give the duration t_end [s] or motor_speed (the start-up then lasts until the mean speed reaches it)',
    ],
    'stall': [
        's.toml: startup.T1 = 20.0: does not exceed T2 + T3 = 22.1 N·m, so the machine never reaches motor_speed; give t_end to compute the stalled start, or a larger T1',
    ],
    'reg_both': [
        's.toml: regression.C12 = 24.7: give C12, or pzdn_stiffness (with drive_stiffness), not both',
    ],
    'reg_none': [
        's.toml: regression.pzdn_stiffness: missing; give the PZDN stiffness pzdn_stiffness (and drive_stiffness in series), or the link stiffness C12',
    ],
    'schema_torque': [
        's.toml: spring[0].torque = -1.0: must be a number >= 1e-06 and <= 1000000 (N·m)',
    ],
    'schema_curv': [
        's.toml: spring[0].curvature_factor = "wahll": must be one of "thesis", "wahl", "en13906" (did you mean "wahl"?)',
    ],
    'schema_leg_model': [
        's.toml: spring[0].leg_model = "cantilever": must be one of "thesis", "shigley", "en13906_radial", "en13906_tangential"',
    ],
    'schema_material': [
        's.toml: spring[0].material = "steel65": must be one of "music_wire", "hard_drawn", "oil_tempered", "chrome_vanadium", "chrome_silicon", "stainless_302", "60S2A", "65G"',
    ],
    'schema_slot': [
        's.toml: spring[0].slot_arms = [80.0]: must be a list of 2 to 2 numbers >= 0.001 and <= 10000 (mm)',
    ],
    'schema_coils': [
        's.toml: spring[0].coils = 0: must be a number >= 0.5 and <= 1000',
    ],
    'schema_unknown': [
        's.toml: spring[0].wire_dia = 6.0: unknown key in [spring[0]] (did you mean "wire_diameter"?)',
    ],
    'schema_method': [
        's.toml: startup.method = "rk4": must be one of "closed_form", "ode", "both"',
    ],
    'schema_J': [
        's.toml: startup.J1 = 0.0: must be a number >= 1e-09 and <= 1000000 (kg*m^2)',
    ],
    'schema_zeta': [
        's.toml: startup.damping_ratio = -0.1: must be a number >= 0 and <= 2',
    ],
    'schema_sweep': [
        's.toml: startup.sweep = []: must be a list of 1 to 50 numbers >= 0.001 and <= 1000',
    ],
    'schema_hist': [
        's.toml: startup.history_points = -1: must be an integer >= 0 and <= 100000',
    ],
    'schema_z1': [
        's.toml: coupling_gear.z1 = 3: must be an integer >= 5 and <= 1000',
    ],
    'schema_torque_on': [
        's.toml: coupling_gear.torque_on = "sun": must be one of "wheel", "pinion"',
    ],
    'schema_reg': [
        's.toml: regression.pzdn_stiffness = 0.0: must be a number >= 1e-06 and <= 1000000000 (N·m/rad)',
    ],
}


@pytest.mark.parametrize("name", list(CASES))
def test_bad_input(tmp_path, name):
    path = tmp_path / "s.toml"
    path.write_text(CASES[name], encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 2
    assert out == ""
    assert "Traceback" not in err
    assert [line.replace(str(path), "s.toml") for line in err.splitlines()] == EXPECTED[name]


def test_every_case_has_its_message():
    assert set(CASES) == set(EXPECTED)
