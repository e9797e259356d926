"""kind = "novikov": bad input gives one line per problem naming file, key, value and what
is allowed; exit 2; no traceback.  Every single-key rule of the schema and every rule
across keys of the calculator has its case here."""

import pytest

from tests.helpers_cli import cli, run_bad

GOOD = """kind = "novikov"
[gear]
module = 10.0
z1 = 12
z2 = 71
helix_angle = 22.747
face_width = 190.0
[material.pinion]
hardness = 302
[material.wheel]
hardness = 269
[load]
torque2 = 69500.0
"""


def replace(old, new):
    assert old in GOOD
    return GOOD.replace(old, new)


CASES = [
    # --- single-key rules (schema)
    ("module 0", replace("module = 10.0", "module = 0.0"),
     ["s.toml: gear.module = 0.0: must be a number >= 0.05 and <= 50 (mm)"]),
    ("z1 below 6", replace("z1 = 12", "z1 = 5"),
     ["s.toml: gear.z1 = 5: must be an integer >= 6 and <= 1000"]),
    ("helix angle 45", replace("helix_angle = 22.747", "helix_angle = 45.0"),
     ["s.toml: gear.helix_angle = 45.0: must be a number >= 0.0001 and < 45 (deg)"]),
    ("helix angle 0", replace("helix_angle = 22.747", "helix_angle = 0.0"),
     ["s.toml: gear.helix_angle = 0.0: must be a number >= 0.0001 and < 45 (deg)"]),
    ("face width 0", replace("face_width = 190.0", "face_width = 0.0"),
     ["s.toml: gear.face_width = 0.0: must be a number >= 0.001 and <= 5000 (mm)"]),
    ("shift above the Y_v domain", replace("face_width = 190.0",
                                           "face_width = 190.0\nx1 = 0.4\nx2 = -0.4"),
     ["s.toml: gear.x1 = 0.4: must be a number >= -0.5 and <= 0.3"]),
    ("shift below the Y_v domain", replace("face_width = 190.0",
                                           "face_width = 190.0\nx1 = 0.3\nx2 = -0.6"),
     ["s.toml: gear.x2 = -0.6: must be a number >= -0.5 and <= 0.3"]),
    ("hardness above 350 HB", replace("hardness = 302", "hardness = 400"),
     ["s.toml: material.pinion.hardness = 400: must be a number >= 100 and <= 350 (HB)"]),
    ("grade 4", GOOD + "[accuracy]\ngrade_smoothness = 4\n",
     ["s.toml: accuracy.grade_smoothness = 4: must be an integer >= 5 and <= 12"]),
    ("contact grade 13", GOOD + "[accuracy]\ngrade_contact = 13\n",
     ["s.toml: accuracy.grade_contact = 13: must be an integer >= 5 and <= 12"]),
    ("negative risk", GOOD + "[accuracy]\nrisk = -1.0\n",
     ["s.toml: accuracy.risk = -1.0: must be a number >= 0 and <= 5"]),
    ("misalignment 1°", GOOD + "[accuracy]\nmisalignment = 1.0\n",
     ["s.toml: accuracy.misalignment = 1.0: must be a number >= -0.5 and <= 0.5 (deg)"]),
    ("negative end relief", GOOD + "[accuracy]\nend_relief = -0.01\n",
     ["s.toml: accuracy.end_relief = -0.01: must be a number >= 0 and <= 1 (mm)"]),
    ("unknown error model", GOOD + '[accuracy]\nerror_model = "grade"\n',
     ['s.toml: accuracy.error_model = "grade": must be one of "grades", "explicit", "none" '
      '(did you mean "grades"?)']),
    ("pitch errors not a list", GOOD + '[accuracy]\nerror_model = "explicit"\n'
                                       "pitch_errors = 5.0\n",
     ["s.toml: accuracy.pitch_errors = 5.0: must be a list of 1 to 50 numbers >= -1000 and "
      "<= 1000 (µm)"]),
    ("phases 2", GOOD + "[analysis]\nphases = 2\n",
     ["s.toml: analysis.phases = 2: must be an integer >= 4 and <= 60"]),
    ("stiffness 0", GOOD + "[analysis]\nmesh_stiffness = 0.0\n",
     ["s.toml: analysis.mesh_stiffness = 0.0: must be a number >= 0.1 and <= 1000 (N/(mm·µm))"]),
    ("application factor below 1", replace("torque2 = 69500.0",
                                           "torque2 = 69500.0\napplication_factor = 0.5"),
     ["s.toml: load.application_factor = 0.5: must be a number >= 1 and <= 4"]),
    ("torque missing", replace("torque2 = 69500.0\n", ""),
     ["s.toml: load.torque2: missing; required: a number >= 1e-06 and <= 100000000 (N·m) "
      "(torque on the driven wheel)"]),
    ("unknown key", replace("face_width", "facewidth"),
     ['s.toml: gear.facewidth = 190.0: unknown key in [gear] (did you mean "face_width"?)',
      "s.toml: gear.face_width: missing; required: a number >= 0.001 and <= 5000 (mm) "
      "(working face width)"]),
    ("no material table", replace("[material.pinion]\nhardness = 302\n[material.wheel]\n"
                                  "hardness = 269\n", ""),
     ["s.toml: material: missing table [material] (materials)"]),
    ("unknown rack", GOOD + '[rack]\nname = "GOST 15023"\n',
     ['s.toml: rack.name = "GOST 15023": must be one of "GOST 15023-76", "custom" '
      '(did you mean "GOST 15023-76"?)']),
    # --- rules across keys (calculator)
    ("helix angle and centre distance",
     replace("helix_angle = 22.747", "helix_angle = 22.747\ncenter_distance = 450.0"),
     ["s.toml: gear.center_distance = 450.0: give either gear.helix_angle or "
      "gear.center_distance, not both"]),
    ("neither helix angle nor centre distance", replace("helix_angle = 22.747\n", ""),
     ["s.toml: gear.helix_angle: missing; required: give gear.helix_angle or "
      "gear.center_distance (β then follows from it)"]),
    ("centre distance too small", replace("helix_angle = 22.747", "center_distance = 400.0"),
     ["s.toml: gear.center_distance = 400.0: gives no helix angle in 0…45°: must be > "
      "m(z1 + z2)/2 = 415 mm and < m(z1 + z2)/(2cos 45°) = 586.8986 mm"]),
    ("centre distance too large", replace("helix_angle = 22.747", "center_distance = 600.0"),
     ["s.toml: gear.center_distance = 600.0: gives no helix angle in 0…45°: must be > "
      "m(z1 + z2)/2 = 415 mm and < m(z1 + z2)/(2cos 45°) = 586.8986 mm"]),
    ("shifts do not add up to 0", replace("face_width = 190.0", "face_width = 190.0\nx1 = 0.2"),
     ["s.toml: gear.x1 + gear.x2 = 0.2: must be 0: a Novikov pair works at the standard "
      "centre distance m(z1 + z2)/(2cos β); use x2 = -0.2"]),
    ("custom rack incomplete", GOOD + '[rack]\nname = "custom"\neps_q = 0.6\n',
     ['s.toml: rack.profile_angle: missing; required for rack.name = "custom"',
      's.toml: rack.lk_star: missing; required for rack.name = "custom"',
      's.toml: rack.addendum_coef: missing; required for rack.name = "custom"',
      's.toml: rack.dedendum_coef: missing; required for rack.name = "custom"']),
    ("standard rack value overridden", GOOD + "[rack]\neps_q = 0.6\n",
     ['s.toml: rack.eps_q = 0.6: applies only to rack.name = "custom" (the GOST 15023-76 '
      'values are data); remove it or set rack.name = "custom"']),
    ("pitch errors without the explicit model",
     GOOD + "[accuracy]\npitch_errors = [0.0, 10.0, 0.0, 0.0]\n",
     ['s.toml: accuracy.pitch_errors = [0.0, 10.0, 0.0, 0.0]: applies only with '
      'accuracy.error_model = "explicit"; remove it or set error_model = "explicit"']),
    ("lead error without the explicit model", GOOD + "[accuracy]\nlead_error = 10.0\n",
     ['s.toml: accuracy.lead_error = 10.0: applies only with accuracy.error_model = '
      '"explicit"; remove it or set error_model = "explicit"']),
    ("explicit model without pitch errors", GOOD + '[accuracy]\nerror_model = "explicit"\n',
     ['s.toml: accuracy.pitch_errors: missing; required with accuracy.error_model = '
      '"explicit": 4 values in µm, one per tooth pair in engagement (pairs 1…4 of '
      "Korotkin's Table 1)"]),
    ("explicit model, wrong count", GOOD + '[accuracy]\nerror_model = "explicit"\n'
                                           "pitch_errors = [0.0, 10.0]\n",
     ["s.toml: accuracy.pitch_errors = [0.0, 10.0]: needs 4 values, one per tooth pair in "
      "engagement (pairs 1…4 of Korotkin's Table 1), got 2"]),
    ("axial overlap beyond the scope", replace("face_width = 190.0", "face_width = 650.0"),
     ["s.toml: gear.face_width = 650.0: gives ε_β = 8.0001 > 8, beyond the scope of the phase "
      "analysis (Korotkin's Table 1 covers ε_β up to about 5); make the face width at most "
      "649.99 mm or reduce the helix angle"]),
    ("life without speed", replace("torque2 = 69500.0", "torque2 = 69500.0\nlife = 1000.0"),
     ["s.toml: load.life = 1000.0: needs load.speed1 (the number of cycles is 60·n1·L_h); "
      "give speed1 or remove life"]),
]


@pytest.mark.parametrize("name, text, expected", CASES, ids=[c[0] for c in CASES])
def test_one_line_per_problem(tmp_path, name, text, expected):
    assert run_bad(tmp_path, text) == expected


def test_validate_reports_rules_across_keys(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(replace("face_width = 190.0", "face_width = 190.0\nx1 = 0.2"),
                    encoding="utf-8")
    code, out, err = cli("validate", path)
    assert code == 2 and out == "" and "gear.x1 + gear.x2 = 0.2: must be 0" in err
    path.write_text(GOOD, encoding="utf-8")
    code, out, _ = cli("validate", path)
    assert code == 0 and out.strip().endswith("s.toml: ok (novikov)")


def test_every_input_error_in_one_round(tmp_path):
    """Nine mistakes, one run (issue: "every input error in one round"): a schema error, rack
    constants given to the standard rack, a shift sum, helix angle and centre distance
    together, a lead error without the explicit model, a life without a speed — and, in
    the same run, the face width beyond the phase analysis, read on a pair that could be
    built."""
    text = (replace("z1 = 12", "z1 = 5")
            .replace("face_width = 190.0", "face_width = 190.0\nx1 = 0.1")
            .replace("helix_angle = 22.747", "helix_angle = 22.747\ncenter_distance = 450.0")
            .replace("torque2 = 69500.0", "torque2 = 69500.0\nlife = 1000.0")
            + "[rack]\neps_q = 0.3\nlk_star = 0.7\n[accuracy]\nlead_error = 2.0\n")
    assert run_bad(tmp_path, text) == [
        "s.toml: gear.z1 = 5: must be an integer >= 6 and <= 1000",
        's.toml: rack.lk_star = 0.7: applies only to rack.name = "custom" (the GOST 15023-76 '
        'values are data); remove it or set rack.name = "custom"',
        's.toml: rack.eps_q = 0.3: applies only to rack.name = "custom" (the GOST 15023-76 '
        'values are data); remove it or set rack.name = "custom"',
        "s.toml: gear.x1 + gear.x2 = 0.1: must be 0: a Novikov pair works at the standard "
        "centre distance m(z1 + z2)/(2cos β); use x2 = -0.1",
        "s.toml: gear.center_distance = 450.0: give either gear.helix_angle or "
        "gear.center_distance, not both",
        's.toml: accuracy.lead_error = 2.0: applies only with accuracy.error_model = '
        '"explicit"; remove it or set error_model = "explicit"',
        "s.toml: load.life = 1000.0: needs load.speed1 (the number of cycles is 60·n1·L_h); "
        "give speed1 or remove life",
    ]
    wide = (replace("face_width = 190.0", "face_width = 5000.0")
            .replace("torque2 = 69500.0", "torque2 = 69500.0\nlife = 1000.0")
            + '[accuracy]\nerror_model = "explicit"\nlead_error = 2.0\n')
    lines = run_bad(tmp_path, wide)
    assert [line.split(" = ")[0].split(":")[1].strip() for line in lines] == [
        "load.life", "gear.face_width"]
