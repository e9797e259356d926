"""ISO 6336 rating of the spur calculator: choice of method, input errors of every new key
(one line, exit 2), checks with advice, overrides, spectrum and peak load."""

from __future__ import annotations

import json

import pytest

from geardesign.core.errors import format_value
from geardesign.core.registry import run_data
from geardesign.spur.strength.iso6336.spec import ISO, ISO_FACTORS, OPTIONS_METHODS
from tests.helpers_cli import cli, run_bad

GOOD = """kind = "spur"
[gear]
module = 3.0
z1 = 20
z2 = 60
face_width = 30.0
bearing_scheme = 5
[load]
speed1 = 1450.0
torque1 = 70.0
life_hours = 20000.0
[material.pinion]
grade = "20KhN3A"
treatment = "carburized"
hardness_HRC = 59.0
[material.wheel]
grade = "20KhN3A"
treatment = "carburized"
hardness_HRC = 58.0
[options]
method = "ISO 6336:2019"
"""

DATA = {
    "kind": "spur",
    "gear": {"module": 3.0, "z1": 20, "z2": 60, "face_width": 30.0, "bearing_scheme": 5},
    "load": {"speed1": 1450.0, "torque1": 70.0, "life_hours": 20000.0},
    "material": {"pinion": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 59.0},
                 "wheel": {"grade": "20KhN3A", "treatment": "carburized", "hardness_HRC": 58.0}},
    "options": {"method": "ISO 6336:2019"},
}


def _run(advice: bool = True, **tables) -> dict:
    """The document of DATA with ``tables`` merged in; ``advice = False``: the rating
    without the advice search (the checks' own words, before a fix replaces some)."""
    from geardesign.core.registry import load_data

    data = json.loads(json.dumps(DATA))
    for key, value in tables.items():
        if isinstance(value, dict) and isinstance(data.get(key), dict):
            data[key].update(value)
        else:
            data[key] = value
    if advice:
        return run_data(data).document()
    calc, spec = load_data(data)
    return calc.rate(spec).document()


# ----------------------------------------------------------------------------- method choice


def test_iso_alone_reports_iso_sections_only():
    doc = _run()
    assert doc["methods"][-1] == "ISO 6336:2019" and "GOST 21354-87" not in doc["methods"]
    keys = set(doc["results"])
    assert {"iso6336_factors", "iso6336_contact", "iso6336_bending"} <= keys
    assert not {"contact", "bending", "factors"} & keys
    assert "iso.lubricant_viscosity" in doc["assumed"] and "iso.pinion.quality" in doc["assumed"]
    assert doc["verdict"] == "pass", [c for c in doc["checks"] if not c["passed"]]


def test_both_methods_side_by_side():
    doc = _run(options={"method": "GOST 21354-87",
                        "methods": ["GOST 21354-87", "ISO 6336:2019"]})
    assert doc["methods"][-2:] == ["GOST 21354-87", "ISO 6336:2019"]
    r = doc["results"]
    assert "sigma_H" in r["contact"] and "sigma_H1" in r["iso6336_contact"]
    codes = {c["code"] for c in doc["checks"]}
    assert {"CONTACT_FATIGUE", "ISO_PITTING_PINION", "BENDING_FATIGUE_WHEEL",
            "ISO_BENDING_WHEEL"} <= codes


def test_gost_stays_the_default():
    doc = _run(options={"method": "GOST 21354-87"})
    assert "iso6336_contact" not in doc["results"] and "iso" not in doc["inputs"]


def test_given_factor_replaces_the_computed_one():
    doc = _run(iso_factors={"K_Hbeta": 1.3, "Y_F1": 1.5})
    f, b = doc["results"]["iso6336_factors"], doc["results"]["iso6336_bending"]
    assert f["K_Hbeta"] == 1.3 and b["Y_F1"] == 1.5
    assert b["sigma_F01"] == pytest.approx(b["sigma_F01"] / b["Y_F1"] * 1.5)


def test_failing_pitting_and_bending_carry_advice(tmp_path):
    doc = _run(False, load={"torque1": 900.0})
    failed = {c["code"]: c["message"] for c in doc["checks"] if not c["passed"]}
    assert doc["verdict"] == "fail"
    assert "ISO_PITTING_PINION" in failed and "increase the centre distance to at least" in \
        failed["ISO_PITTING_PINION"]
    assert "σ_Hlim at least" in failed["ISO_PITTING_PINION"]
    assert "ISO_BENDING_WHEEL" in failed and "increase the module by" in failed["ISO_BENDING_WHEEL"]


def test_advice_leads_to_a_passing_design():
    """The advised face width and centre distance are found by re-rating: with them the
    pair passes pitting."""
    import re

    doc = _run(load={"torque1": 250.0})
    msg = next(c["message"] for c in doc["checks"] if c["code"] == "ISO_PITTING_PINION")
    a_w = float(re.search(r"centre distance to at least ([0-9.]+) mm", msg).group(1))
    b = float(re.search(r"face width to at least ([0-9.]+) mm", msg).group(1))
    wider = _run(load={"torque1": 250.0}, gear={"face_width": b + 0.1})["results"]
    assert min(wider["iso6336_contact"]["S_H1"], wider["iso6336_contact"]["S_H2"]) >= 1.0
    k = (a_w + 0.1) / 120.0
    bigger = _run(load={"torque1": 250.0}, gear={"module": 3.0 * k, "face_width": 30.0 * k})
    c = bigger["results"]["iso6336_contact"]
    assert min(c["S_H1"], c["S_H2"]) >= 1.0


def test_face_width_advice_stays_within_the_face_width_ratio():
    """Beyond b_w/d_w1 = 1.6 the ISO advice offers no face width, only the centre distance
    (module and face width in proportion) and the material; the advice, a standard module
    in place of that centre distance."""
    doc = _run(False, load={"torque1": 300.0})
    msg = next(c["message"] for c in doc["checks"] if c["code"] == "ISO_PITTING_PINION")
    assert "face width to at least" not in msg
    assert "no face width within b_w/d_w1 <= 1.6 (up to 96.0 mm) passes" in msg
    assert "centre distance to at least" in msg
    advised = next(c for c in _run(load={"torque1": 300.0})["checks"]
                   if c["code"] == "ISO_PITTING_PINION")
    assert "gear.module" in advised["fix"]
    assert "centre distance to at least" not in advised["message"]


def test_peak_torque_gives_static_checks():
    doc = _run(load={"peak_torque1": 300.0})
    st = doc["results"]["iso6336_static"]
    assert st["S_Hst1"] > 0 and st["S_Fst2"] > 0
    codes = {c["code"] for c in doc["checks"]}
    assert {"ISO_STATIC_PITTING_PINION", "ISO_STATIC_BENDING_WHEEL"} <= codes


def test_spectrum_miner_sums():
    spectrum = [{"torque_ratio": 1.0, "time_share": 0.2}, {"torque_ratio": 0.5, "time_share": 0.8}]
    doc = _run(load={"spectrum": spectrum})
    sp = doc["results"]["iso6336_spectrum"]
    c = doc["results"]["iso6336_contact"]
    # lighter blocks: the spectrum is safer than the nominal torque over the whole life
    assert sp["S_Hspec1"] > c["S_H1"] and sp["S_Fspec2"] > doc["results"]["iso6336_bending"]["S_F2"]
    assert 0.0 <= sp["D_H1"] < 1.0


def test_planetary_meshes_rated_by_iso():
    from pathlib import Path

    import tomllib

    spec = tomllib.loads((Path(__file__).parent.parent / "specs" /
                          "planetary_2kh_reducer.toml").read_text(encoding="utf-8"))
    spec["strength"]["method"] = "ISO 6336:2019"
    doc = run_data(spec).document()
    codes = {c["code"] for c in doc["checks"]}
    assert "SUN_PLANET_ISO_PITTING_SUN" in codes and "PLANET_RING_ISO_BENDING_RING" in codes
    # a ring with a shaper: the internal-gear method, no rack note; without: the rack, named
    cut = "cutter" in spec
    assert ("PLANET_RING_ISO_INTERNAL_FORM_FACTOR" in codes) is not cut
    spec.pop("cutter", None)
    doc = run_data(spec).document()
    assert "PLANET_RING_ISO_INTERNAL_FORM_FACTOR" in {c["code"] for c in doc["checks"]}
    assert doc["results"]["strength_planet_ring"]["form_internal"] == "rack"


# ----------------------------------------------------------------------------- input errors


def _bad_value(field):
    if field.type == "boolean":
        return '"yes"', "yes"
    if field.type == "string":
        return '"nonsense"', "nonsense"
    if field.type == "integer":
        return str(int(field.maximum) + 1), int(field.maximum) + 1
    if field.maximum is not None:
        return repr(float(field.maximum) * 2 + 1), float(field.maximum) * 2 + 1
    return "-1.0", -1.0


def _fields():
    for f in ISO.fields:
        if hasattr(f, "type"):
            yield "iso", f
    for sub in ("pinion", "wheel"):
        for f in ISO.member(sub).fields:
            yield f"iso.{sub}", f
    for f in ISO_FACTORS.fields:
        yield "iso_factors", f


FIELDS = list(_fields())


@pytest.mark.parametrize("table, field", FIELDS, ids=[f"{t}.{f.key}" for t, f in FIELDS])
def test_every_new_key_has_its_domain(tmp_path, table, field):
    text, value = _bad_value(field)
    lines = run_bad(tmp_path, GOOD + f"[{table}]\n{field.key} = {text}\n")
    assert len(lines) == 1
    assert lines[0].startswith(f"s.toml: {table}.{field.key} = {format_value(value)}: must be "
                               f"{field.rule()}")


@pytest.mark.parametrize("text", ['["ISO 6336"]', "[]", '"ISO 6336:2019"'])
def test_methods_list(tmp_path, text):
    lines = run_bad(tmp_path, GOOD.replace('method = "ISO 6336:2019"', f"methods = {text}"))
    assert len(lines) == 1 and lines[0].startswith("s.toml: options.methods = ")
    assert lines[0].endswith(f"must be {OPTIONS_METHODS.rule()}")


CROSS = [
    ("offset without shaft", "[iso]\npinion_offset = 20.0\n",
     ["s.toml: iso.pinion_offset = 20.0: given without iso.shaft_span and iso.shaft_diameter: "
      "the shaft deflection needs all three (or give iso.f_sh)"]),
    ("offset beyond the span", "[iso]\npinion_offset = 80.0\nshaft_span = 100.0\n"
     "shaft_diameter = 40.0\n",
     ["s.toml: iso.pinion_offset = 80.0: lies outside the bearing span (s <= l/2 = 50 mm)"]),
    ("bore beyond the root", "[iso.pinion]\ninner_diameter = 60.0\n",
     ["s.toml: iso.pinion.inner_diameter = 60.0: must be smaller than the root diameter "
      "d_f = 52.500 mm"]),
    ("rim too thin", "[iso.wheel]\nrim_thickness = 3.0\n",
     ["s.toml: iso.wheel.rim_thickness = 3.0: too thin: ISO 6336-3 rates rims thicker than "
      "0.5·h = 3.375 mm (Y_B); thicken the rim"]),
    ("rim larger than the body", "[iso.wheel]\nrim_thickness = 80.0\ninner_diameter = 100.0\n",
     ["s.toml: iso.wheel.rim_thickness = 80.0: larger than the gear body between the bore "
      "and the root circle"]),
    ("class 0 of the 2013 edition", "[iso]\naccuracy_grade = 0\n",
     ["s.toml: iso.accuracy_grade = 0: is not a class of ISO 1328-1:2013: give 1…11"]),
    ("grade 12 of the 1995 edition is fine, class 12 of 2013 is not",
     '[iso]\naccuracy_grade = 12\ntolerance_standard = "ISO 1328-1:2013"\n',
     ["s.toml: iso.accuracy_grade = 12: is not a class of ISO 1328-1:2013: give 1…11"]),
]


@pytest.mark.parametrize("name, extra, expected", CROSS, ids=[c[0] for c in CROSS])
def test_inputs_that_depend_on_each_other(tmp_path, name, extra, expected):
    assert run_bad(tmp_path, GOOD + extra) == expected


def test_iso_tables_need_no_material_for_geometry(tmp_path):
    """A geometry-only spec may name ISO 6336: nothing to rate, no error."""
    text = GOOD.split("[load]")[0] + '[options]\nmethod = "ISO 6336:2019"\n'
    path = tmp_path / "g.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 0, err
    assert "iso6336_contact" not in json.loads(out)["results"]


@pytest.mark.parametrize("table", ["[iso]\nS_Hmin = 1.2\n", "[iso_factors]\nK_v = 1.1\n",
                                   "[iso.pinion]\nRz_flank = 3.0\n"])
def test_iso_tables_are_refused_under_gost_alone(tmp_path, table):
    """[iso] and [iso_factors] with the GOST 21354-87 method alone would be silently unused:
    one line naming the table and the keys that select the ISO rating (with or without
    [material]); valid as soon as the ISO rating is chosen too."""
    gost = GOOD.replace('method = "ISO 6336:2019"', 'method = "GOST 21354-87"')
    key = table.split("]")[0][1:].split(".")[0]
    expected = [f"s.toml: {key}: [{key}] is read only by the ISO 6336 rating, and this spec "
                f"rates by GOST 21354-87: set options.method = \"ISO 6336:2019\" or "
                f"options.methods = [\"GOST 21354-87\", \"ISO 6336:2019\"], or leave [{key}] out"]
    assert run_bad(tmp_path, gost + table) == expected
    geometry = gost.split("[load]")[0] + "[options]\n" + gost.split("[options]\n")[1]
    assert run_bad(tmp_path, geometry + table) == expected
    both = GOOD.replace('method = "ISO 6336:2019"',
                        'methods = ["GOST 21354-87", "ISO 6336:2019"]')
    path = tmp_path / "both.toml"
    path.write_text(both + table, encoding="utf-8")
    assert cli("run", path, "--format", "json")[0] in (0, 1)    # rated: no input error


def test_gost_regime_is_refused_with_iso_alone(tmp_path):
    """load.regime (a GOST 21354-87 typical regime) with ISO 6336 alone would be silently
    unused: one line; read with both methods; the GOST default is not echoed by ISO."""
    from geardesign.spur.strength.iso6336.spec import REGIME_NOT_READ

    text = GOOD.replace("life_hours = 20000.0\n", 'life_hours = 20000.0\nregime = "II"\n')
    assert run_bad(tmp_path, text) == [f's.toml: load.regime = "II": {REGIME_NOT_READ}']
    data = json.loads(json.dumps(DATA))
    doc = run_data(data).document()
    assert doc["inputs"]["load"].get("regime") is None and "load.regime" not in doc["assumed"]
    data["load"]["regime"] = "II"
    data["options"] = {"methods": ["GOST 21354-87", "ISO 6336:2019"]}
    assert run_data(data).document()["inputs"]["load"]["regime"] == "II"


def test_bearing_scheme_is_needed_by_gost_and_the_design_mode_only(tmp_path):
    """The GOST 21354-87 chart of K_Hβ: the ISO rating alone does not read it (K_Hβ by
    method C), so a check by ISO 6336 alone runs without it; the GOST rating and the design
    mode (which sizes the pair with the GOST K_Hβ) still require it."""
    data = json.loads(json.dumps(DATA))
    del data["gear"]["bearing_scheme"]
    r = run_data(data).document()["results"]
    assert r["iso6336_factors"]["K_Hbeta"] > 1.0
    assert "bearing_scheme" not in json.dumps(r["iso6336_factors"])
    no_scheme = GOOD.replace("bearing_scheme = 5\n", "")
    for text, key, why in (
            (no_scheme.replace('method = "ISO 6336:2019"', 'method = "GOST 21354-87"'),
             "gear", "the GOST 21354-87 rating"),
            (no_scheme.replace('method = "ISO 6336:2019"',
                               'methods = ["ISO 6336:2019", "GOST 21354-87"]'),
             "gear", "the GOST 21354-87 rating")):
        assert run_bad(tmp_path, text) == [
            f"s.toml: {key}.bearing_scheme: missing; required for {why}: 1…7 as in the GOST "
            f"21354-87 chart (see geardesign template spur)"]


@pytest.mark.parametrize("who, key, value", [
    ("pinion", "sigma_Flim", 900.0), ("wheel", "S_H", 1.2), ("pinion", "S_F", 1.8),
    ("wheel", "sigma_HPmax", 2500.0), ("pinion", "sigma_FSt", 1800.0),
    ("wheel", "root_ground", True)])
def test_gost_only_material_keys_are_refused_with_iso_alone(who, key, value):
    """A [material] key that only the GOST rating reads is an input error when ISO 6336 is
    the only method (it would be silently unused), and valid with both methods."""
    from geardesign.core.errors import InputError
    from geardesign.spur.strength.iso6336.spec import GOST_ONLY_MATERIAL

    data = json.loads(json.dumps(DATA))
    data["material"][who][key] = value
    with pytest.raises(InputError) as exc:
        run_data(data)
    msg = GOST_ONLY_MATERIAL[key].format(gear=f"iso.{who}", pair="iso")
    assert [p.line("") for p in exc.value.problems] == [
        f"material.{who}.{key} = {format_value(value)}: {msg}"]
    data["options"] = {"methods": ["GOST 21354-87", "ISO 6336:2019"]}
    run_data(data).document()


def test_internal_gear_bore_is_refused():
    from geardesign.core.errors import InputError

    data = json.loads(json.dumps(DATA))
    data["gear"].update(internal=True, z2=72, internal_tip_shortening=0.15)
    data["iso"] = {"wheel": {"inner_diameter": 300.0}}
    with pytest.raises(InputError) as exc:
        run_data(data)
    assert [p.line("") for p in exc.value.problems] == [
        "iso.wheel.inner_diameter = 300.0: an internal gear has no bore: its body is the rim "
        "below the tooth roots (give iso.wheel.rim_thickness, or leave the key out)"]


def test_tolerance_edition_in_the_report():
    """The rating says which ISO 1328-1 edition its tolerances come from; grade 12 exists in
    the 1995 edition only."""
    f = _run()["results"]["iso6336_factors"]
    assert f["tolerance_standard"] == "ISO 1328-1:2013"
    f95 = _run(iso={"tolerance_standard": "ISO 1328-1:1995", "accuracy_grade": 12})
    f95 = f95["results"]["iso6336_factors"]
    assert f95["tolerance_standard"] == "ISO 1328-1:1995" and f95["grade"] == 12.0
