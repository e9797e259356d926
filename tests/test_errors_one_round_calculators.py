"""Every input error in one round for the shaft, connection, Geneva, wave gear and ball
clutch calculators (issue: "every input error in one round", "errors about what the user
wrote").  A user runs ``geardesign run spec.toml`` on the template with several
independent mistakes: every one is printed in the same run, exit 2, nothing written; a
rule that needs a wrong value is left out (it would follow from that mistake)."""

from __future__ import annotations

import itertools

import pytest

from .helpers_cli import cli, cli_process, run_bad, write_spec
from .test_errors_one_round import SPECS, edit, template

MISTAKES = {
    "shaft": {
        "bore": (("length = 80.0\ndiameter = 55.0", "length = 80.0\ndiameter = 55.0\nbore = 60.0"),),
        "din_key": (('grade = "45"', 'grade = "45"\nsteel_type = "structural"'),),
        "load_position": (("position = 195.0", "position = 295.0"),),
        "unbalanced": (("torque = -560.0", "torque = -500.0"),),
        "second_axial": (("position = 145.0", "position = 145.0\naxial = true"),),
        "din_option": (("speed = 200.0", "speed = 200.0\ndin743_load_case = 1"),),
    },
    "connection": {
        "hub": (("length = 56.0", "length = 56.0\nhub_length = 50.0"),),
        "din": (("shaft_diameter = 40.0", 'shaft_diameter = 40.0\nstandard = "DIN 6885-1"'),),
        "part_key": (("length = 56.0", "length = 56.0\nwidth = 12.0"),),
    },
    "geneva": {
        "no_dwell": (("slots = 4", "slots = 4\npins = 4"),),
        "no_barrel": (("\n[barrel]\n", "\n# [barrel]\n"), ("\nstations = 6", "\n# stations = 6"),
                      ("\ninertia = 25.0", "\n# inertia = 25.0"),
                      ("\nefficiency = 0.8 ", "\n# efficiency = 0.8 ")),
    },
    "wave_gear": {
        "rigid_teeth": (("flex_teeth = 200", "flex_teeth = 200\nrigid_teeth = 201"),),
        "shift_rule": (("rim_thickness = 2.5", 'rim_thickness = 2.5\nshift = 3.0\nshift_rule = "eq8"'),),
        "fillet": (("# pressure_angle = 20.0", "pressure_angle = 34.0"),),
    },
    "ball_clutch": {
        "socket": (("socket_depth = 4.0", "socket_depth = 9.0"),),
        "balls": (("balls = 6", "balls = 12"),),
        "preload": (("preload = 5.0", "# preload = 5.0"),),
        "coil": (("coil_diameter = 16.0", "coil_diameter = 4.0"),),
    },
}


def lines_of(tmp_path, kind: str, *names: str) -> list[str]:
    text = template(kind)
    for name in names:
        text = edit(text, *MISTAKES[kind][name])
    return run_bad(tmp_path, text)


SCHEMA_MISTAKE = {
    "shaft": (("speed = 200.0", "speed = -200.0"),),
    "connection": (("torque = 250.0", "torque = -250.0"),),
    "geneva": (("crank_speed = 30.0", "crank_speed = -30.0"),),
    "wave_gear": (("module = 1.0", "module = 0.0"),),
    "ball_clutch": (("speed = 1000.0", "speed = -1000.0"),),
}
"""A mistake the schema finds, in a key that no calculator rule of the mistakes reads."""


@pytest.mark.parametrize("kind", sorted(MISTAKES))
def test_every_mistake_of_a_spec_is_printed_in_one_run(tmp_path, kind):
    """``geardesign run`` on the template with all its mistakes and a schema mistake: every
    line of every mistake at once (each once), exit 2, nothing on stdout."""
    text = template(kind)
    for name in MISTAKES[kind]:
        text = edit(text, *MISTAKES[kind][name])
    alone = run_bad(tmp_path, edit(text, *SCHEMA_MISTAKE[kind]))
    assert len(alone) == len(set(alone))
    expected = set(run_bad(tmp_path, edit(template(kind), *SCHEMA_MISTAKE[kind])))
    for name in MISTAKES[kind]:
        expected |= set(lines_of(tmp_path, kind, name))
    assert set(alone) == expected
    assert len(alone) >= len(MISTAKES[kind]) + 1


PAIRS = [(kind, a, b) for kind in sorted(MISTAKES)
         for a, b in itertools.combinations(MISTAKES[kind], 2)]


@pytest.mark.parametrize("kind,a,b", PAIRS, ids=lambda v: str(v))
def test_two_independent_mistakes_give_both_lines(tmp_path, kind, a, b):
    """The lines of two independent mistakes in one spec are the lines of each alone: the
    calculator collects its rule errors instead of stopping at the first."""
    both = lines_of(tmp_path, kind, a, b)
    assert set(both) == set(lines_of(tmp_path, kind, a)) | set(lines_of(tmp_path, kind, b))
    assert len(both) == len(set(both))


def test_shaft_with_three_mistakes_as_a_user_runs_it(tmp_path):
    """`python -m geardesign run spec.toml -o report.html`: three mistakes in three sections,
    three lines, exit 2, no report written."""
    text = edit(template("shaft"), *MISTAKES["shaft"]["bore"], *MISTAKES["shaft"]["din_key"],
                *MISTAKES["shaft"]["load_position"])
    path = write_spec(tmp_path, text)
    out = tmp_path / "report.html"
    proc = cli_process("run", path, "-o", out)
    assert proc.returncode == 2 and proc.stdout == "" and not out.exists()
    assert proc.stderr.replace(str(path), "s.toml").splitlines() == [
        "s.toml: step[1].bore = 60.0: must be smaller than the diameter 55 mm",
        's.toml: material.steel_type = "structural": used only by [shaft] method = "DIN743" '
        "(this spec rates by GOST)",
        "s.toml: load[1].position = 295.0: outside the shaft: must be within 0…230 mm (the "
        "sum of the step lengths)",
    ]


def test_a_wrong_step_length_leaves_out_the_positions_not_the_rest(tmp_path):
    """A dependent rule is not repeated: with a step length the schema refuses, the
    positions along the shaft cannot be checked (their range is the sum of the lengths),
    the other rules still are."""
    text = edit(template("shaft"), ("length = 10.0", "length = -10.0"),
                *MISTAKES["shaft"]["load_position"], *MISTAKES["shaft"]["bore"])
    assert run_bad(tmp_path, text) == [
        "s.toml: step[2].length = -10.0: must be a number >= 0.001 and <= 100000 (mm)",
        "s.toml: step[1].bore = 60.0: must be smaller than the diameter 55 mm",
    ]


# --------------------------------------------------------------- errors name the user's input


def test_shaft_yield_of_the_grade_names_the_given_ultimate_strength(tmp_path):
    """sigma_B given below the grade's yield strength: the line names sigma_B (given), not
    sigma_T (the grade's)."""
    text = edit(template("shaft"),
                ("hardness_HB = 270.0", "hardness_HB = 270.0\nsigma_B = 400.0"))
    lines = run_bad(tmp_path, text)
    assert len(lines) == 1 and lines[0].startswith("s.toml: material.sigma_B = 400.0: must be "
                                                  "above the yield strength σ_T = ")
    assert 'of the grade (derived from material.grade = "45")' in lines[0]


def test_fillet_of_the_default_rack_names_the_pressure_angle(tmp_path):
    lines = lines_of(tmp_path, "wave_gear", "fillet")
    assert lines[0].startswith("s.toml: rack.pressure_angle = 34.0: too large for the root "
                               "fillet")
    assert "ρ_f* from the default, not in the spec" in lines[0]


def test_self_locking_angle_says_which_frictions_are_defaults(tmp_path):
    text = edit(template("ball_clutch"), ("preload = 5.0", "# preload = 5.0"),
                ("# limit_torque =  #", "limit_torque = 20.0  #"),
                ("socket_angle = 45.0", "socket_angle = 80.0"))
    assert run_bad(tmp_path, text) == [
        "s.toml: safety.socket_angle = 80.0: must be below 78.6° with friction f = 0.1 (the "
        "default, not in the spec) and guide friction f_g = 0.1 (the default, not in the "
        "spec): at a larger angle the balls self-lock (cot(α2 + ρ) <= f_g) and no spring "
        "force gives safety.limit_torque"]


def test_cross_bore_at_the_default_middle_names_the_hole(tmp_path):
    text = edit(template("shaft"), ("speed = 200.0", 'speed = 200.0\nmethod = "DIN743"'),
                ('grade = "45"', 'grade = "C45"'), ("hardness_HB = 270.0", ""),
                ("length = 10.0\ndiameter = 62.0",
                 "length = 10.0\ndiameter = 62.0\ncross_bore = 12.0"))
    assert run_bad(tmp_path, text) == [
        "s.toml: step[2].cross_bore = 12.0: wider than the step's length 10 mm: the hole at "
        "its middle (the default of cross_bore_at, not in the spec) must lie within the step"]


# --------------------------------------------------------------- --select with a pair


def test_select_on_a_pair_spec_is_one_line_saying_what_is_allowed(tmp_path):
    """`geardesign run pair.toml --select`: the flag replaces mode = "check" (and its
    designation), not the pair the spec asks for; one line on the mode, not a complaint
    about [pair]."""
    text = (SPECS / "bearing_tapered_pair.toml").read_text(encoding="utf-8")
    path = write_spec(tmp_path, text)
    for command in (("run",), ("bearing",)):
        code, out, err = cli(*command, path, "--select")
        assert code == 2 and out == ""
        assert err.replace(str(path), "s.toml").splitlines() == [
            's.toml: mode = "pair": --select replaces only mode = "check" (the default); this '
            'spec sets mode = "pair": run it without --select, or write mode = "select" in '
            'place of "pair" and remove [pair]']


def test_select_still_replaces_a_written_check_mode(tmp_path):
    text = template("bearing").replace('kind = "bearing"', 'kind = "bearing"\nmode = "check"')
    code, out, err = cli("bearing", write_spec(tmp_path, text), "--select", "--format", "json")
    assert code == 0, err


# --------------------------------------------------------------- spur advice of a module


def test_a_module_fix_does_not_also_advise_a_scaled_centre_distance(tmp_path):
    """When the advice sets a standard module, the check's words no longer advise the
    continuous scaling (a centre distance of 510.3 mm, a module +211 %) that the user
    would not set."""
    import json

    text = edit(template("spur"), ("\ntorque1 = 250.0", "\ntorque1 = 2500.0"),
                ("peak_torque1 = 500.0", "peak_torque1 = 5000.0"))
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code == 1, err
    fixed = [c for c in json.loads(out)["checks"] if c.get("fix") and "gear.module" in c["fix"]]
    assert {c["code"] for c in fixed} >= {"CONTACT_FATIGUE", "BENDING_FATIGUE_PINION"}
    for c in fixed:
        assert "increase the centre distance" not in c["message"], c["message"]
        assert "increase the module by" not in c["message"], c["message"]
        assert "gear.center_distance" not in c["message"]


def test_without_leaves_out_a_clause_and_its_joint():
    from geardesign.core.advice import without
    from geardesign.spur.levers import SUPERSEDED

    assert without("S = 0.4: increase the centre distance to at least 510.3 mm (+104 %, module "
                   "and face width in proportion, found by re-rating), or use a harder wheel "
                   "material", SUPERSEDED) == "S = 0.4: use a harder wheel material"
    assert without("S = 0.9: use a harder material, or increase the module by 58 % (same "
                   "centre distance, fewer teeth)", SUPERSEDED) == "S = 0.9: use a harder material"
    assert without("S = 0.4 (spectrum): increase the centre distance by 52 % (module and face "
                   "width in proportion); no face width passes", SUPERSEDED) == \
        "S = 0.4 (spectrum); no face width passes"


def test_a_wrong_method_leaves_out_only_the_rules_of_a_method(tmp_path):
    """A misspelt [shaft] method: the schema's line, and the step and load rules that do
    not depend on the method, in one run."""
    text = edit(template("shaft"), ("speed = 200.0", 'speed = 200.0\nmethod = "DIN 743"'),
                *MISTAKES["shaft"]["bore"], *MISTAKES["shaft"]["load_position"])
    lines = run_bad(tmp_path, text)
    assert lines[0].startswith('s.toml: shaft.method = "DIN 743": must be one of "GOST", '
                               '"DIN743"')
    assert lines[1:] == [
        "s.toml: step[1].bore = 60.0: must be smaller than the diameter 55 mm",
        "s.toml: load[1].position = 295.0: outside the shaft: must be within 0…230 mm (the "
        "sum of the step lengths)",
    ]
