"""Input errors as a user meets them: every problem of a spec in one round, and each
error names what the user wrote (issue: "every input error in one round", "errors about
what the user wrote").  Each test runs the command a user would type on the template
(`geardesign template KIND`) with a few edits, and asserts on the lines printed."""

from __future__ import annotations

import copy
import random
import re
import tomllib
from pathlib import Path

import pytest

from geardesign.core import registry
from geardesign.core.errors import InputError

from .helpers_cli import cli, write_spec

SPECS = Path(__file__).resolve().parent.parent / "specs"


def template(kind: str) -> str:
    code, out, err = cli("template", kind)
    assert code == 0, err
    return out


def edit(text: str, *pairs: tuple[str, str]) -> str:
    """The template with each ``old`` line start replaced once by ``new``."""
    for old, new in pairs:
        assert old in text, old
        text = text.replace(old, new, 1)
    return text


def refused(tmp_path, kind: str, text: str, *options: str) -> list[str]:
    """``geardesign KIND s.toml``: exit 2, nothing on stdout; the lines printed."""
    path = write_spec(tmp_path, text)
    code, out, err = cli(kind, path, "--format", "json", *options)
    assert code == 2, err
    assert out == "" and "Traceback" not in err
    return [line.replace(str(path), "s.toml") for line in err.splitlines()]


# --------------------------------------------------------------- every error in one round


def test_spur_template_with_nine_mistakes_is_answered_in_one_run(tmp_path):
    """Nine mistakes of the schema and the two the calculator finds (a missing
    bearing_scheme, a hardness missing for the treatment) are printed together; the
    spectrum rule that needs the wrong torque_ratio is left out (it would follow from it)."""
    text = edit(template("spur"),
                ("module = 4.0", "module = -4.0"),
                ("z1 = 25", "z1 = 2.5"),
                ("face_width = 63.0", "face_width = 63.0\nfacewidth = 63.0"),
                ("bearing_scheme = 5  #", "# bearing_scheme = 5  #"),
                ("speed1 = 960.0", 'speed1 = "fast"'),
                ("life_hours = 20000.0", "life_hours = -1.0"),
                ("torque_ratio = 1.0", "torque_ratio = 1.5"),
                ('treatment = "improved"', 'treatment = "imprved"'),
                ("hardness_HB = 250.0", "hardnes_HB = 250.0"))
    assert refused(tmp_path, "spur", text) == [
        's.toml: gear.facewidth = 63.0: unknown key in [gear] (did you mean "face_width"?)',
        "s.toml: gear.module = -4.0: must be a number >= 0.05 and <= 100 (mm)",
        "s.toml: gear.z1 = 2.5: must be an integer >= 5 and <= 1000",
        's.toml: load.speed1 = "fast": must be a number >= 0.001 and <= 1000000 (min^-1), or '
        'a quantity in min^-1 like "4 min^-1" ("fast" is not understood)',
        "s.toml: load.life_hours = -1.0: must be a number >= 0.001 and <= 10000000 (h)",
        "s.toml: load.spectrum[0].torque_ratio = 1.5: must be a number >= 0.001 and <= 1",
        's.toml: material.pinion.treatment = "imprved": must be one of "normalized", '
        '"improved", "through_hardened", "induction", "carburized", "nitrided" (did you mean '
        '"improved"?)',
        's.toml: material.wheel.hardnes_HB = 250.0: unknown key in [material.wheel] (did you '
        'mean "hardness_HB"?)',
        "s.toml: gear.bearing_scheme: missing; required for the GOST 21354-87 rating: 1…7 as "
        "in the GOST 21354-87 chart (see geardesign template spur)",
        "s.toml: material.wheel.hardness_HB: missing; required: the surface hardness in HB "
        'for treatment "improved"',
    ]


def test_spur_calculator_rules_are_reported_together(tmp_path):
    """No schema problem: the geometry rule (centre distance) and the strength inputs
    (spectrum shares, a missing hardness, a missing bearing scheme) in one run."""
    text = edit(template("spur"),
                ("# center_distance =  #", "center_distance = 150.0  #"),
                ("bearing_scheme = 5  #", "# bearing_scheme = 5  #"),
                ("time_share = 0.5", "time_share = 0.6"),
                ("hardness_HB = 250.0", "# hardness_HB = 250.0"))
    assert refused(tmp_path, "spur", text) == [
        "s.toml: gear.center_distance = 150.0: smaller than possible: must exceed (d_b1 + "
        "d_b2)/2 = 234.9232 mm, where the base circles touch (x1 + x2 = 0 gives a_w = 250 mm)",
        "s.toml: gear.bearing_scheme: missing; required for the GOST 21354-87 rating: 1…7 as "
        "in the GOST 21354-87 chart (see geardesign template spur)",
        "s.toml: load.spectrum = [... 3 items]: the time shares add up to 1.1; they must add "
        "up to 1",
        "s.toml: material.wheel.hardness_HB: missing; required: the surface hardness in HB "
        'for treatment "improved"',
    ]


def test_select_flag_replaces_the_designation_of_the_template(tmp_path):
    """`geardesign bearing template.toml --select`: the flag replaces the designation (which
    names the type and bore to select in) instead of refusing it; the report says so."""
    import json

    path = write_spec(tmp_path, template("bearing"))
    code, out, err = cli("bearing", path, "--select", "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    checks = {c["code"]: c for c in doc["checks"]}
    assert checks["SELECTION_REPLACES"]["message"] == (
        'mode = "select" chooses the bearing: the given designation = 6208 is replaced by '
        "the selection (of deep groove ball bearings with d = 40 mm)")
    assert checks["SELECTION"]["passed"]


def test_select_reports_every_missing_input_at_once(tmp_path):
    text = edit(template("bearing"),
                ('designation = "6208"', '# designation = "6208"'),
                ("life = 20000.0", "# life = 20000.0"))
    lines = refused(tmp_path, "bearing", text, "--select")
    assert lines == [
        's.toml: requirements.life: missing; required in mode = "select": a number > 0 (h)',
        's.toml: bearing.type: missing; required in mode = "select" (or a '
        'bearing.designation naming type and bore): one of "angular_contact_ball", '
        '"cylindrical_roller", "deep_groove_ball", "spherical_roller", "tapered_roller", '
        '"thrust_ball"',
        's.toml: bearing.d: missing; required in mode = "select" (or a bearing.designation '
        "naming type and bore): the bore diameter of the shaft seat (mm)",
    ]


def test_planetary_schema_geometry_and_strength_problems_in_one_run(tmp_path):
    """A wrong planet count (schema), an impossible centre distance (geometry), a missing
    speed and a missing hardness (strength inputs): four lines, one run."""
    text = edit(template("planetary"), ("planets = 3", "planets = 30"),
                ("center_distance = 68.0", "center_distance = 66.0"),
                ("speed = 1450.0", "# speed = 1450.0"))
    ring = text.index("[material.ring]")
    hb = text.index("hardness_HB = 230.0", ring)
    text = text[:hb] + "# " + text[hb:]
    assert refused(tmp_path, "planetary", text) == [
        "s.toml: train.planets = 30: must be an integer >= 1 and <= 24",
        "s.toml: train.center_distance = 66.0: gives shift.ring = -0.9803 (derived from "
        "train.center_distance by coaxiality and the teeth): too negative for the planet–ring "
        "mesh: inv α_tw = -0.00491723 <= 0, no working pressure angle exists; x_ring − "
        "x_planet (GOST sign) must be > -0.7371",
        "s.toml: operation.speed: missing; required with [strength]: the input speed",
        "s.toml: material.ring.hardness_HB: missing; required: the surface hardness in HB for "
        'treatment "improved"',
    ]


def test_worm_wheel_duty_and_geometry_problems_in_one_run(tmp_path):
    text = edit(template("worm"), ("center_distance = 160.0", "center_distance = 100.0"),
                ('material = "BrO10N1F1_centrifugal"', 'material = "custom"'),
                ("time_share = 0.4", "time_share = 0.5"))
    assert refused(tmp_path, "worm", text) == [
        's.toml: wheel.group: missing; required with material = "custom": one of "I", "II", '
        '"III" (material group)',
        "s.toml: load.spectrum: the time shares add up to 1.1; they must add up to 1",
        "s.toml: gear.center_distance = 100.0: needs the wheel shift x = -9.1270, outside ±1 "
        "(GOST 19650-97); with m = 6.3 mm, q = 10, z2 = 40 the centre distance must be "
        "151.2 ... 163.8 mm",
    ]


# --------------------------------------------------------------- errors name the user's input


def test_module_in_inches_names_the_module_not_the_ball_the_tool_chose(tmp_path):
    text = edit(template("spur"), ("module = 4.0", "module = 0.1575"))
    assert refused(tmp_path, "spur", text) == [
        "s.toml: gear.module = 0.1575: the thickness allowances -85.7…-158.5 µm (from "
        "[accuracy]) on s_n1 = 0.2474 mm leave the pinion's tooth too thin for a measuring "
        "ball: the ball chosen for it (D1 = 0.27 mm, derived from the module and z1) sinks "
        "below the base circle; check the unit of the module (mm), give smaller allowances "
        "in [accuracy], or give drawing.ball_diameter1",
    ]


def test_a_ball_the_user_gave_is_named_as_his(tmp_path):
    text = edit(template("spur"), ("module = 4.0", "module = 0.1575"),
                ("# ball_diameter1 =  #", "ball_diameter1 = 0.27  #"))
    lines = refused(tmp_path, "spur", text)
    assert lines[0] == (
        "s.toml: drawing.ball_diameter1 = 0.27: the ball sinks below the base circle of the "
        "thinnest tooth the thickness allowances -85.7…-158.5 µm (from [accuracy]) on s_n1 = "
        "0.2474 mm permit: choose a larger ball")


def test_shaft_diameter_in_metres_names_the_diameter_not_the_supports(tmp_path):
    """No support stiffness is given: the singular beam is the slender step's doing."""
    text = edit(template("shaft"), ("diameter = 45.0", "diameter = 0.045"))
    assert refused(tmp_path, "shaft", text) == [
        "s.toml: step[0].diameter = 0.045: the shaft cannot be solved as a beam (its "
        "stiffness matrix is singular): this step's bending stiffness EI = 0.0415 N·mm² is "
        "2.8e-13 of the stiffest step's; diameters are in mm (in metres 0.045 would be 45 mm)",
    ]


def test_derived_ring_shift_names_the_centre_distance(tmp_path):
    """The shifts follow from train.center_distance: an impossible ring shift is reported
    on the centre distance, with the shift it derived."""
    text = edit(template("planetary"), ("center_distance = 68.0", "center_distance = 66.0"))
    assert refused(tmp_path, "planetary", text) == [
        "s.toml: train.center_distance = 66.0: gives shift.ring = -0.9803 (derived from "
        "train.center_distance by coaxiality and the teeth): too negative for the planet–ring "
        "mesh: inv α_tw = -0.00491723 <= 0, no working pressure angle exists; x_ring − "
        "x_planet (GOST sign) must be > -0.7371",
    ]


def test_a_default_value_in_an_error_says_it_is_the_default(tmp_path):
    """efficiency.model is not in the spec: the error says it is the default."""
    text = (SPECS / "planetary_nrel_stage1.toml").read_text(encoding="utf-8")
    text = text.replace("[shift]\nsun = 0.6170", "[shift]\nsun = 0.000617")
    lines = refused(tmp_path, "planetary", text)
    assert lines[0].startswith('s.toml: efficiency.model = "niemann": the default (not in '
                               'the spec): the loss factor H_V')


# --------------------------------------------------------------- the class


def _given(data, key: str) -> bool:
    """Whether ``key`` (``a.b[1].c``, a drive's ``stage[0]: gear.z1``) is in the spec."""
    node = data
    for part in re.findall(r"[^.\[\]]+|\[\d+\]", key.replace(": ", ".")):
        if part.startswith("["):
            i = int(part[1:-1])
            if not isinstance(node, list) or i >= len(node):
                return False
            node = node[i]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            return False
    return True


def names_the_users_input(data: dict, problem) -> bool:
    """An error line names a key of the spec, or says that its key is missing, a default,
    or derived from named inputs (or concerns the whole file)."""
    m = problem.message
    if not problem.key or m.startswith("missing") or "derived from" in m or "default" in m:
        return True
    return all(_given(data, k.strip()) for k in problem.key.split("+"))


def _leaves(node, path=()):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from _leaves(v, path + (k,))
    elif isinstance(node, list) and node and all(isinstance(x, dict) for x in node):
        for i, v in enumerate(node):
            yield from _leaves(v, path + (i,))
    elif path != ("kind",):
        yield path, node


SIZES = ("module", "diameter", "center_distance")
"""Sizes whose unit slips (inches, metres) are tried on every spec that has them."""


def _perturbed(data: dict, rng: random.Random, n: int):
    """Copies of a spec, each with one value removed or slipped in its unit (inches,
    metres, kilo-, milli-, the sign): the first of each :data:`SIZES` in inches and in
    metres, and ``n`` random ones."""
    leaves = list(_leaves(data))
    sizes = {}
    for path, value in leaves:
        if path[-1] in SIZES and isinstance(value, float):
            sizes.setdefault(path[-1], path)
    chosen = [(path, f) for path in sizes.values() for f in (1 / 25.4, 1e-3)]
    chosen += [(rng.choice(leaves)[0], rng.choice([None, 1 / 25.4, 25.4, 1e-3, 1e3, -1.0, 0.5]))
               for _ in range(n)]
    for path, factor in chosen:
        new = copy.deepcopy(data)
        node = new
        for part in path[:-1]:
            node = node[part]
        value = node[path[-1]]
        if factor is None or isinstance(value, bool) or not isinstance(value, (int, float)):
            del node[path[-1]]
        else:
            node[path[-1]] = type(value)(round(value * factor) if isinstance(value, int)
                                         else value * factor)
        yield path, new


EXAMPLES = sorted(p for p in SPECS.glob("*.toml") if not p.name.startswith("sweep"))


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.stem)
def test_every_error_names_an_input_the_user_gave(path):
    """Each example spec with a value removed or slipped in its unit: every error line
    names a key the spec holds, or says that its key is missing, a default or derived
    from named inputs (never a value the tool chose as if the user had written it)."""
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    rng = random.Random(path.stem)
    for changed, spec in _perturbed(data, rng, 3):
        try:
            calc, validated = registry.load_data(copy.deepcopy(spec), path.name)
            calc.compute(validated)
        except InputError as exc:
            for problem in exc.problems:
                assert names_the_users_input(spec, problem), (changed, problem.line(""))
