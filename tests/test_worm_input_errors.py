"""Worm specs with bad input: one line per problem naming file, key, value and what is
allowed; exit 2; no traceback.  One case per input rule of the worm calculator (schema
rules and the rules across keys in ``geardesign/worm/inputs.py``)."""

import pytest

from tests.helpers_cli import cli, cli_process, run_bad

GOOD = """kind = "worm"
[gear]
module = 6.3
diameter_factor = 10.0
z1 = 2
z2 = 40
center_distance = 160.0
[load]
torque2 = 500.0
speed1 = 1450.0
[wheel]
material = "BrO10N1F1_centrifugal"
"""

DESIGN = """kind = "worm"
mode = "design"
[gear]
ratio = 20.0
[load]
torque2 = 500.0
speed1 = 1450.0
[wheel]
material = "BrO10N1F1_centrifugal"
"""


def replace(old, new, text=GOOD):
    assert old in text
    return text.replace(old, new)


SPECTRUM = "[[load.spectrum]]\ntorque_ratio = {r1}\ntime_share = {s1}\n"

CASES = [
    # ---- single keys (schema)
    ("z1 = 5", replace("z1 = 2", "z1 = 5"),
     ["s.toml: gear.z1 = 5: must be an integer >= 1 and <= 4"]),
    ("z2 = 8", replace("z2 = 40", "z2 = 8"),
     ["s.toml: gear.z2 = 8: must be an integer >= 10 and <= 400"]),
    ("x out of range", replace("center_distance = 160.0", "x = 1.5"),
     ["s.toml: gear.x = 1.5: must be a number >= -1 and <= 1"]),
    ("negative module", replace("module = 6.3", "module = -6.3"),
     ["s.toml: gear.module = -6.3: must be a number >= 0.05 and <= 100 (mm)"]),
    ("q too large", replace("diameter_factor = 10.0", "diameter_factor = 50.0"),
     ["s.toml: gear.diameter_factor = 50.0: must be a number >= 5 and <= 40"]),
    ("bad mode", 'mode = "desing"\n' + GOOD,
     ['s.toml: mode = "desing": must be one of "check", "design" (did you mean "design"?)']),
    ("worm type ZN2", replace("z2 = 40", 'z2 = 40\nworm_type = "ZN2"'),
     ['s.toml: gear.worm_type = "ZN2": must be one of "ZA", "ZI", "ZN1", "ZK1" '
      '(did you mean "ZN1"?)']),
    ("unknown key", replace("z2 = 40", "z2 = 40\nshift = 0.1"),
     ["s.toml: gear.shift = 0.1: unknown key in [gear]; allowed: module, diameter_factor, z1, "
      "z2, ratio, x, center_distance, worm_type, profile_angle, hand, face_width, worm_length"]),
    ("missing torque", replace("torque2 = 500.0\n", ""),
     ["s.toml: load.torque2: missing; required: a number >= 1e-06 and <= 10000000 (N·m) (torque on "
      "the wheel shaft (the largest long-acting torque))"]),
    ("missing wheel", GOOD.split("[wheel]")[0],
     ["s.toml: wheel: missing table [wheel] (wheel rim material)"]),
    ("unknown material", replace('"BrO10N1F1_centrifugal"', '"bronze"'),
     ['s.toml: wheel.material = "bronze": must be one of "BrO10N1F1_centrifugal", '
      '"BrO10F1_sand", "BrO10F1_chill", "BrO5Ts5S5_sand", "BrO5Ts5S5_chill", '
      '"BrA10Zh4N4_centrifugal", "BrA10Zh4N4_chill", "BrA9Zh3L_sand", "BrA9Zh3L_chill", '
      '"LTs23A6Zh3Mts2_sand", "LTs23A6Zh3Mts2_chill", "SCh15", "SCh18", "SCh20", "CuSn12-C-GZ", "CuSn12Ni2-C-GS", "CuSn12Ni2-C-GZ", "CuZn25Al5Mn4Fe3-C-GZ", "custom"']),
    ("spectrum share above 1", replace("[wheel]", SPECTRUM.format(r1=1.0, s1=1.5) + "[wheel]"),
     ["s.toml: load.spectrum[0].time_share = 1.5: must be a number >= 1e-06 and <= 1"]),
    ("torque ratio above 1", replace("[wheel]", SPECTRUM.format(r1=1.2, s1=1.0) + "[wheel]"),
     ["s.toml: load.spectrum[0].torque_ratio = 1.2: must be a number >= 0.001 and <= 1"]),
    ("friction level", GOOD + '[friction]\nlevel = "middle"\n',
     ['s.toml: friction.level = "middle": must be one of "low", "mean", "high"']),
    ("bearing efficiency", GOOD + "[friction]\nbearing_efficiency = 1.2\n",
     ["s.toml: friction.bearing_efficiency = 1.2: must be a number > 0.5 and <= 1"]),
    ("deflection limit", GOOD + "[worm]\ndeflection_limit = 0.5\n",
     ["s.toml: worm.deflection_limit = 0.5: must be a number >= 0.0001 and <= 0.1"]),
    ("base share", GOOD + "[thermal]\nbase_share = 1.5\n",
     ["s.toml: thermal.base_share = 1.5: must be a number >= 0 and <= 1"]),
    # ---- rules across keys (calculator)
    ("check mode: module and z1 missing", replace("z1 = 2\n", "", replace("module = 6.3\n", "")),
     ['s.toml: gear.module: missing; required with mode = "check": a number >= 0.05 and <= 100 '
      "(mm) (axial module of the worm (= transverse module of the wheel))",
      's.toml: gear.z1: missing; required with mode = "check": an integer >= 1 and <= 4 '
      "(number of worm starts)"]),
    ("check mode: q and z2 missing",
     replace("z2 = 40\n", "", replace("diameter_factor = 10.0\n", "")),
     ['s.toml: gear.diameter_factor: missing; required with mode = "check": a number >= 5 and '
      "<= 40 (worm diameter factor d1/m)",
      's.toml: gear.z2: missing; required with mode = "check": an integer >= 10 and <= 400 '
      "(number of wheel teeth)"]),
    ("x and centre distance disagree", replace("z2 = 40", "z2 = 40\nx = 0.2"),
     ["s.toml: gear.x = 0.2: does not match center_distance = 160 mm, which needs x = 0.3968; "
      "give x or center_distance, not both"]),
    ("centre distance needs |x| > 1", replace("center_distance = 160.0", "center_distance = 170.0"),
     ["s.toml: gear.center_distance = 170.0: needs the wheel shift x = 1.9841, outside ±1 "
      "(GOST 19650-97); with m = 6.3 mm, q = 10, z2 = 40 the centre distance must be "
      "151.2 ... 163.8 mm"]),
    ("ratio disagrees with z2/z1", replace("z2 = 40", "z2 = 40\nratio = 25.0"),
     ["s.toml: gear.ratio = 25.0: does not match z2/z1 = 40/2 = 20 (more than 4 % apart); give "
      "z1 and z2 or the ratio, or make them agree"]),
    ("q too small for the basic worm",
     replace("center_distance = 160.0", "x = 0.0", replace("diameter_factor = 10.0",
                                                           "diameter_factor = 5.0"))
     + "[basic_worm]\naddendum_coef = 2.0\nclearance_coef = 1.0\n",
     ["s.toml: gear.diameter_factor = 5.0: too small for the basic worm: the root diameter "
      "d_f1 = m·(q − 2(h_a* + c*)) must be > 0, so q > 6"]),
    ("custom material without group", replace('"BrO10N1F1_centrifugal"', '"custom"'),
     ['s.toml: wheel.group: missing; required with material = "custom": one of "I", "II", '
      '"III" (material group)']),
    ("custom group I without strengths",
     replace('"BrO10N1F1_centrifugal"', '"custom"\ngroup = "I"'),
     ["s.toml: wheel.sigma_B: missing; required for a group I wheel (tensile strength, MPa)",
      "s.toml: wheel.sigma_T: missing; required for a group I wheel (yield strength, MPa)"]),
    ("custom group III without bending strength",
     replace('"BrO10N1F1_centrifugal"', '"custom"\ngroup = "III"'),
     ["s.toml: wheel.sigma_bu: missing; required for a group III wheel (bending strength, "
      "MPa)"]),
    ("sigma_H0 with a group I wheel", GOOD + "[method]\nsigma_H0 = 300.0\n",
     ["s.toml: method.sigma_H0 = 300.0: applies only to group II and III wheels ([σ]_H = "
      "σ_H0 − k·v_s); remove it for a group I (tin bronze) wheel"]),
    ("spectrum shares do not add up",
     replace("[wheel]", SPECTRUM.format(r1=1.0, s1=0.5) + SPECTRUM.format(r1=0.5, s1=0.3)
             + "[wheel]"),
     ["s.toml: load.spectrum: the time shares add up to 0.8; they must add up to 1"]),
    ("peak torque below torque2", replace("speed1 = 1450.0", "speed1 = 1450.0\npeak_torque = 400.0"),
     ["s.toml: load.peak_torque = 400.0: smaller than load.torque2 = 500 N·m; the peak must be "
      ">= the long-acting torque (or leave it out)"]),
    ("friction factor with a given coefficient",
     GOOD + "[friction]\ncoefficient = 0.03\nmaterial_factor = 1.2\n",
     ["s.toml: friction.material_factor = 1.2: applies only to the table's f'; remove it or "
      "remove friction.coefficient"]),
    ("fan speed without fan", GOOD + "[thermal]\nfan_speed = 1000.0\n",
     ["s.toml: thermal.fan_speed = 1000.0: applies only with thermal.fan = true; remove it or "
      "set fan = true"]),
    ("oil limit below ambient", GOOD + "[thermal]\nambient = 40.0\noil_limit = 35.0\n",
     ["s.toml: thermal.oil_limit = 35.0: must be above thermal.ambient = 40 °C"]),
    # ---- design mode
    ("design table in check mode", GOOD + '[design]\ncenter_distance_rows = "both"\n',
     ['s.toml: design.center_distance_rows = "both": applies only with mode = "design"; remove '
      'it or set mode = "design"']),
    ("design mode with module and centre distance", 'mode = "design"\n' + GOOD,
     ['s.toml: gear.module = 6.3: is proposed by mode = "design"; remove it, or use mode = '
      '"check" to check a given pair',
      's.toml: gear.center_distance = 160.0: is proposed by mode = "design"; remove it, or use '
      'mode = "check" to check a given pair']),
    ("design mode with a shift", replace("ratio = 20.0", "ratio = 20.0\nx = 0.2", DESIGN),
     ['s.toml: gear.x = 0.2: is proposed by mode = "design"; remove it, or use mode = "check" '
      "to check a given pair"]),
    ("design mode without ratio", replace("ratio = 20.0", "z2 = 40", DESIGN),
     ['s.toml: gear.ratio: missing; with mode = "design" give the ratio (z1 optional) or both '
      "z1 and z2"]),
    ("design ratio gives too many teeth", replace("ratio = 20.0", "ratio = 300.0\nz1 = 2", DESIGN),
     ["s.toml: gear.ratio = 300.0: gives z2 = round(u·z1) = 600, outside 10 ... 400; choose "
      "another ratio or z1"]),
    ("design: cast iron far too fast",
     replace("speed1 = 1450.0", "speed1 = 3000.0",
             replace('"BrO10N1F1_centrifugal"', '"SCh20"', DESIGN)),
     ['s.toml: wheel.material = "SCh20": [σ]_H = -175.0 MPa at the estimated sliding speed '
      "10.71 m/s: a group III wheel cannot carry this drive; choose a group I bronze"]),
    ("design: beyond the centre-distance series",
     replace("speed1 = 1450.0", "speed1 = 100.0",
             replace("torque2 = 500.0", "torque2 = 200000.0", DESIGN)),
     ["s.toml: load.torque2 = 200000.0: needs a centre distance of 845.3 mm ([σ]_H = 273.4 MPa "
      "at the estimated sliding speed 2.63 m/s), beyond the GOST 2144-76 series (500 mm); use "
      "a stronger wheel material or split the drive"]),
]


@pytest.mark.parametrize("name, text, expected", CASES, ids=[c[0] for c in CASES])
def test_one_line_per_problem(tmp_path, name, text, expected):
    assert run_bad(tmp_path, text) == expected


def test_validate_runs_the_rules_across_keys(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(replace("center_distance = 160.0", "center_distance = 170.0"),
                    encoding="utf-8")
    code, out, err = cli("validate", path)
    assert code == 2 and out == "" and "outside ±1" in err


def test_no_traceback_in_a_real_process(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(replace("z2 = 40", "z2 = 40\nx = 0.2"), encoding="utf-8")
    proc = cli_process("run", path)
    assert proc.returncode == 2
    assert proc.stdout == "" and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1
