"""Spur strength (GOST 21354-87): input rules, design failures, overrides, spectra,
design mode.  Published values are in tests/reference/spur; these test behaviour."""

import json

import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from geardesign.spur.strength import tables as T
from tests.conftest import flat
from tests.helpers_cli import cli, changed

BASE = {
    "kind": "spur",
    "gear": {"module": 4.0, "z1": 25, "z2": 100, "face_width": 63.0, "bearing_scheme": 5},
    "load": {"speed1": 960.0, "torque1": 220.0, "life_hours": 20000.0, "peak_torque1": 440.0},
    "material": {
        "pinion": {"grade": "40Kh", "treatment": "improved", "hardness_HB": 280.0},
        "wheel": {"grade": "40Kh", "treatment": "improved", "hardness_HB": 250.0},
    },
}


def spec(**changes) -> dict:
    """BASE with ``table__key=value`` changes (None removes the key)."""
    return changed(BASE, **changes)


def problems(data):
    with pytest.raises(InputError) as exc:
        run_data(data)
    return [p.line("s.toml") for p in exc.value.problems]


def test_base_passes_and_reports_every_factor():
    doc = run_data(BASE).document()
    assert doc["verdict"] == "pass"
    assert doc["methods"][-1] == "GOST 21354-87"
    for section, keys in {
        "factors": ["K_A", "K_Hv", "K_Hbeta", "K_Halpha", "K_Fv", "K_Fbeta", "K_Falpha", "K_H",
                    "K_F"],
        "contact": ["Z_E", "Z_H", "Z_eps", "sigma_H", "sigma_HP", "S_H1", "S_H2", "Z_N1", "Z_v1",
                    "Z_R1", "Z_X1"],
        "bending": ["Y_FS1", "Y_beta", "Y_eps", "sigma_F1", "sigma_FP1", "S_F1", "Y_N1", "Y_X1",
                    "Y_delta", "Y_A1"],
        "static": ["sigma_Hmax", "sigma_HPmax1", "sigma_Fmax1", "sigma_FPmax1"],
        "forces": ["F_t", "F_r", "F_a", "F_n", "M_a1"],
    }.items():
        for key in keys:
            assert key in doc["results"][section], (section, key)
            assert f"results.{section}.{key}" in doc["units"]


RULES = [
    ("unknown grade", spec(material__pinion__grade="50Kh"),
     ['s.toml: material.pinion.grade = "50Kh": unknown steel (did you mean \'40Kh\', \'20Kh\', \'40KhN\'?); '
      "known: 45, 40Kh, 40KhN, 35KhM, 30KhGSA, 20Kh, 18KhGT, 20KhN3A, 12KhN3A, 38Kh2MYuA, 42CrMo4, 31CrMo12, 33CrMoV12-9, 34CrAlMo5-10, C45, 34CrNiMo6, 16MnCr5, 20MnCr5, 18CrNiMo7-6, 4340, 8620, 9310, 40KhL (and equivalents such as 41Cr4, 4140, 1045: `geardesign materials` lists them); or "
      "leave out grade and give the properties"]),
    ("treatment not for the grade", spec(material__pinion__treatment="carburized",
                                         material__pinion__hardness_HRC=60.0),
     ['s.toml: material.pinion.treatment = "carburized": not a treatment for steel 40Kh; use '
      "one of improved, through_hardened, induction, nitrided"]),
    ("hardness of the wrong kind", spec(material__wheel__hardness_HB=None,
                                        material__wheel__hardness_HRC=30.0),
     ['s.toml: material.wheel.hardness_HB: missing; required: the surface hardness in HB for '
      'treatment "improved" (not hardness_HRC)']),
    ("hardness impossible", spec(material__wheel__hardness_HB=800.0),
     ["s.toml: material.wheel.hardness_HB = 800.0: must be a number >= 100 and <= 700 (HB)"]),
    ("negative torque", spec(load__torque1=-5.0),
     ["s.toml: load.torque1 = -5.0: must be a number >= 1e-06 and <= 100000000 (N·m)"]),
    ("torque and power", spec(load__power=20.0),
     ["s.toml: load.power = 20.0: give torque1 or power, not both"]),
    ("no torque", spec(load__torque1=None),
     ["s.toml: load.torque1: missing; required with [material]: the nominal pinion torque in "
      "N·m (or load.power in kW)"]),
    ("no material", spec(material=None),
     ["s.toml: material: missing table [material.pinion] and [material.wheel]: required with "
      "load.torque1 or load.power for the strength calculation"]),
    ("no life", spec(load__life_hours=None),
     ["s.toml: load.life_hours: missing; required with [material]: the required life in hours"]),
    ("no bearing scheme", spec(gear__bearing_scheme=None),
     ["s.toml: gear.bearing_scheme: missing; required for the GOST 21354-87 rating: 1…7 as in "
      "the GOST 21354-87 chart (see geardesign template spur)"]),
    ("peak below nominal", spec(load__peak_torque1=100.0),
     ["s.toml: load.peak_torque1 = 100.0: smaller than the nominal torque T1 = 220 N·m; give "
      "the largest short-time torque"]),
    ("spectrum shares", spec(load__spectrum=[{"torque_ratio": 1.0, "time_share": 0.5},
                                             {"torque_ratio": 0.5, "time_share": 0.4}]),
     ["s.toml: load.spectrum = [... 2 items]: the time shares add up to 0.9; they must add up "
      "to 1"]),
    ("spectrum without the nominal block", spec(load__spectrum=[{"torque_ratio": 0.8,
                                                                 "time_share": 1.0}]),
     ["s.toml: load.spectrum = [... 1 items]: no block has torque_ratio = 1: torque1 must be "
      "the torque of the largest long-acting block"]),
    ("spectrum torque above nominal", spec(load__spectrum=[{"torque_ratio": 1.2,
                                                            "time_share": 1.0}]),
     ["s.toml: load.spectrum[0].torque_ratio = 1.2: must be a number >= 0.001 and <= 1"]),
    ("regime and spectrum", spec(load__regime="II", load__spectrum=[{"torque_ratio": 1.0,
                                                                     "time_share": 1.0}]),
     ['s.toml: load.regime = "II": give a regime or a spectrum, not both']),
    ("unknown regime", spec(load__regime="VI"),
     ['s.toml: load.regime = "VI": must be one of "0", "I", "II", "III", "IV", "V" '
      '(did you mean "V"?)']),
    ("nitrided without core hardness", spec(material__pinion__grade="38Kh2MYuA",
                                            material__pinion__treatment="nitrided",
                                            material__pinion__hardness_HB=None,
                                            material__pinion__hardness_HV=650.0),
     ["s.toml: material.pinion.core_HRC: missing; required for a nitrided gear (σ_Flim = "
      "12·HRC_core + 290), or give sigma_Flim"]),
    ("homogeneous without grade or yield strength", spec(material__wheel__grade=None),
     ['s.toml: material.wheel.sigma_T: missing; required for the static contact check of a '
      '"improved" gear (σ_HPmax = 2.8·σ_T): give the yield strength of the blank, or a grade, '
      "or sigma_HPmax"]),
    ("design without material", {"kind": "spur", "design": {"ratio": 4.0, "bearing_scheme": 5},
                                 "load": BASE["load"]},
     ["s.toml: material: missing table [material.pinion] and [material.wheel]: the design "
      "mode sizes the pair for them"]),
    ("both gear and design", dict(BASE, design={"ratio": 4.0}),
     ["s.toml: give exactly one of [gear] (gear pair (external or internal, spur or helical)) or [design] "
      "(design mode: propose a pair for the load, then check it); the spec has both"]),
]


@pytest.mark.parametrize("name, data, expected", RULES, ids=[r[0] for r in RULES])
def test_input_rules(name, data, expected):
    assert problems(data) == expected


def test_input_rule_through_the_cli(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(
        'kind = "spur"\n[gear]\nmodule = 4.0\nz1 = 25\nz2 = 100\nface_width = 63.0\n'
        'bearing_scheme = 5\n[load]\nspeed1 = 960.0\ntorque1 = 200.0\nlife_hours = 2e4\n'
        '[material.pinion]\ngrade = "40Х"\ntreatment = "improved"\nhardness_HB = 280\n'
        '[material.wheel]\ngrade = "40X"\ntreatment = "improved"\nhardness_HB = 1000\n',
        encoding="utf-8")
    code, out, err = cli("run", path)
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        f"{path}: material.wheel.hardness_HB = 1000: must be a number >= 100 and <= 700 (HB)"]


def test_cyrillic_grade_names():
    doc = run_data(spec(material__pinion__grade="40Х", material__wheel__grade="12ХН3А",
                        material__wheel__treatment="carburized", material__wheel__hardness_HB=None,
                        material__wheel__hardness_HRC=58.0)).document()
    mats = doc["results"]["materials"]
    assert mats["material1"].startswith("40Kh") and mats["material2"].startswith("12KhN3A")


def rated(data: dict) -> dict:
    """The rating's document without the advice search (the checks' own words)."""
    from geardesign.core.registry import load_data

    calc, vs = load_data(data)
    return calc.rate(vs).document()


def test_overload_fails_with_advice():
    doc = rated(spec(load__torque1=600.0, load__peak_torque1=1200.0))
    assert doc["verdict"] == "fail"
    c = {c["code"]: c for c in doc["checks"]}["CONTACT_FATIGUE"]
    assert not c["passed"] and c["severity"] == "error"
    assert "increase the centre distance to at least" in c["message"]
    assert c["value"] > c["limit"]


def test_advised_face_width_passes_when_rerun():
    """The face-width advice is found by re-rating (K_Hβ grows with b_w): the advised width
    passes the check, and 1 % less does not (at 450 N·m it is within b_w/d_w1 <= 1.6)."""
    import re

    doc = run_data(spec(load__torque1=450.0, load__peak_torque1=900.0)).document()
    c = {c["code"]: c for c in doc["checks"]}["CONTACT_FATIGUE"]
    b = float(re.search(r"face width to at least ([0-9.]+) mm", c["message"]).group(1))
    ok = run_data(spec(load__torque1=450.0, load__peak_torque1=900.0,
                       gear__face_width=b + 0.05)).document()
    assert {c["code"]: c for c in ok["checks"]}["CONTACT_FATIGUE"]["passed"]
    short = run_data(spec(load__torque1=450.0, load__peak_torque1=900.0,
                          gear__face_width=0.99 * b)).document()
    assert not {c["code"]: c for c in short["checks"]}["CONTACT_FATIGUE"]["passed"]


def test_face_width_advice_stays_within_the_face_width_ratio():
    """Beyond b_w/d_w1 = 1.6 (the FACE_WIDTH_RATIO bound) the advice proposes no face width
    and names the bound; it still names the centre distance and the material, and the
    advice a standard module in place of the scaled centre distance."""
    msg = {c["code"]: c for c in rated(spec(load__torque1=600.0, load__peak_torque1=1200.0))[
        "checks"]}["CONTACT_FATIGUE"]["message"]
    assert "face width to at least" not in msg
    assert "no face width within b_w/d_w1 <= 1.6 (up to 160.0 mm) passes" in msg
    assert "increase the centre distance to at least" in msg and "harder" in msg
    doc = run_data(spec(load__torque1=600.0, load__peak_torque1=1200.0)).document()
    c = {c["code"]: c for c in doc["checks"]}["CONTACT_FATIGUE"]
    assert "gear.module" in c["fix"] and "harder" in c["message"]
    assert "increase the centre distance" not in c["message"]


def test_advised_centre_distance_passes_when_rerun():
    """The centre-distance advice scales the pair (module and face width with a_w) and is
    found by re-rating: the advised size passes, 1 % smaller does not."""
    import re

    doc = rated(spec(load__torque1=600.0, load__peak_torque1=1200.0))
    msg = {c["code"]: c for c in doc["checks"]}["CONTACT_FATIGUE"]["message"]
    a = float(re.search(r"centre distance to at least ([0-9.]+) mm", msg).group(1))
    k = a / doc["results"]["geometry"]["a_w"]

    def contact(kk):
        d = run_data(spec(load__torque1=600.0, load__peak_torque1=1200.0,
                          gear__module=4.0 * kk, gear__face_width=63.0 * kk)).document()
        return {c["code"]: c for c in d["checks"]}["CONTACT_FATIGUE"]["passed"]

    assert contact(k * 1.0005)
    assert not contact(k * 0.99)


def test_torque_in_newton_millimetres_is_flagged():
    doc = run_data(spec(load__torque1=520000.0, load__peak_torque1=None)).document()
    c = {c["code"]: c for c in doc["checks"]}["UNITS_TORQUE"]
    assert not c["passed"] and c["severity"] == "warning"
    assert "check the units (torque1 is in N·m" in c["message"]
    contact = {c["code"]: c for c in doc["checks"]}["CONTACT_FATIGUE"]["message"]
    assert "more than 300 % (far from passing: check the inputs and their units)" in contact


def test_static_overload_fails():
    doc = run_data(spec(load__peak_torque1=5000.0)).document()
    failed = {c["code"] for c in doc["checks"] if not c["passed"] and c["severity"] == "error"}
    assert "STATIC_CONTACT" in failed
    msg = {c["code"]: c for c in doc["checks"]}["STATIC_CONTACT"]["message"]
    assert "limit the peak torque to" in msg


def test_without_peak_torque_the_static_check_is_reported_as_not_made():
    doc = run_data(spec(load__peak_torque1=None)).document()
    c = {c["code"]: c for c in doc["checks"]}["STATIC_NOT_CHECKED"]
    assert c["severity"] == "info" and "static" not in doc["results"]


def test_given_factors_replace_computed_ones_and_are_marked(tmp_path):
    data = spec(factors={"K_Hbeta": 1.2, "Y_FS1": 4.0})
    v = flat(run_data(data).document())
    assert v["K_Hbeta"] == 1.2 and v["Y_FS1"] == 4.0
    toml = (
        'kind = "spur"\n[gear]\nmodule = 4.0\nz1 = 25\nz2 = 100\nface_width = 63.0\n'
        'bearing_scheme = 5\n[load]\nspeed1 = 960.0\ntorque1 = 200.0\nlife_hours = 2e4\n'
        '[material.pinion]\ngrade = "40Kh"\ntreatment = "improved"\nhardness_HB = 280\n'
        '[material.wheel]\ngrade = "40Kh"\ntreatment = "improved"\nhardness_HB = 250\n'
        '[factors]\nK_Hbeta = 1.2\n')
    spec_path = tmp_path / "f.toml"
    spec_path.write_text(toml, encoding="utf-8")
    code, out, _ = cli("run", spec_path, "--format", "markdown")
    assert code == 0 and "(given) | 1.2 | - | spec |" in out


def test_power_equals_torque():
    a = flat(run_data(spec()).document())
    b = flat(run_data(spec(load__torque1=None, load__power=220.0 * 960.0 * 3.141592653589793
                           / 30000.0)).document())
    assert abs(a["sigma_H"] - b["sigma_H"]) < 1e-9


def test_one_block_spectrum_equals_regime_0():
    a = flat(run_data(spec()).document())
    b = flat(run_data(spec(load__spectrum=[{"torque_ratio": 1.0, "time_share": 1.0}]))
             .document())
    for key in ("N_HE1", "N_FE2", "Z_N1", "sigma_HP", "sigma_FP2"):
        assert abs(a[key] - b[key]) <= 1e-9 * abs(a[key])


def test_spectrum_equivalent_cycles():
    blocks = [{"torque_ratio": 1.0, "time_share": 0.3}, {"torque_ratio": 0.6, "time_share": 0.5},
              {"torque_ratio": 0.3, "time_share": 0.2, "speed_ratio": 0.5}]
    v = flat(run_data(spec(load__spectrum=blocks)).document())
    n1, L = 960.0, 20000.0
    expected = 60 * L * n1 * (0.3 + 0.6 ** 3 * 0.5 + 0.3 ** 3 * 0.5 * 0.2)
    assert abs(v["N_HE1"] - expected) <= 1e-9 * expected
    expected_F = 60 * L * n1 * (0.3 + 0.6 ** 6 * 0.5 + 0.3 ** 6 * 0.5 * 0.2)
    assert abs(v["N_FE1"] - expected_F) <= 1e-9 * expected_F


def test_regime_scales_cycles():
    v = flat(run_data(spec(load__regime="III")).document())
    assert abs(v["N_HE1"] - T.MU_H["III"] * v["N_K1"]) < 1e-6
    assert abs(v["N_FE1"] - T.MU_F[6]["III"] * v["N_K1"]) < 1e-6


def test_reversed_loading_lowers_the_bending_allowable():
    a = flat(run_data(spec()).document())
    b = flat(run_data(spec(load__reverse_torque_ratio=1.0)).document())
    assert a["Y_A1"] == 1.0 and abs(b["Y_A1"] - 0.65) < 1e-12
    assert abs(b["sigma_FP1"] / a["sigma_FP1"] - 0.65) < 1e-12


def test_hardness_outside_the_treatment_range_warns():
    doc = run_data(spec(material__pinion__hardness_HB=380.0)).document()
    c = {c["code"]: c for c in doc["checks"]}["HARDNESS_RANGE_PINION"]
    assert c["severity"] == "warning" and "outside the range 200…350 HB" in c["message"]


def test_helical_pair_rule_and_transverse_factor():
    data = spec(gear__helix_angle=12.0, gear__z1=24, gear__z2=98,
                material__pinion__treatment="induction", material__pinion__hardness_HB=None,
                material__pinion__hardness_HRC=50.0)
    v = flat(run_data(data).document())
    assert 1.0 <= v["K_Halpha"] and 1.0 <= v["K_Falpha"]
    low = min(v["sigma_HP1"], v["sigma_HP2"])
    assert low <= v["sigma_HP"] <= 1.25 * low
    assert abs(v["sigma_HP"] - min(max(0.45 * (v["sigma_HP1"] + v["sigma_HP2"]), low),
                                   1.25 * low)) < 1e-9


def test_design_mode_proposes_a_passing_standard_pair():
    data = {"kind": "spur", "design": {"ratio": 4.0, "bearing_scheme": 6},
            "load": BASE["load"], "material": BASE["material"]}
    doc = run_data(data).document()
    d = doc["results"]["design"]
    assert doc["verdict"] == "pass" and d["proposal_passes"] is True
    assert d["a_w_proposed"] in T.CENTER_DISTANCES_1 + T.CENTER_DISTANCES_2
    assert d["a_w_proposed"] >= d["a_w_estimate"]
    assert d["module_proposed"] in T.MODULES_1
    assert abs(d["ratio_error"]) <= 4.0
    assert abs(doc["results"]["geometry"]["a_w"] - d["a_w_proposed"]) < 1e-6


def test_design_mode_helical_fits_beta_to_the_centre_distance():
    data = {"kind": "spur", "design": {"ratio": 3.15, "helix_angle": 12.0, "bearing_scheme": 6},
            "load": BASE["load"], "material": BASE["material"]}
    doc = run_data(data).document()
    g, d = doc["results"]["geometry"], doc["results"]["design"]
    assert abs(g["a_w"] - d["a_w_proposed"]) < 1e-9 and g["x_sum"] == 0.0
    assert 8.0 < d["helix_angle_proposed"] < 20.0


def test_informative_contact_models():
    v = flat(run_data(spec(options={"contact_model": "popov_n07", "crowning": 0.02})).document())
    assert v["sigma_H_n07"] < v["sigma_H"]
    assert 0.9 < v["sigma_H"] / v["sigma_H_n07"] < 1.1
    assert v["b_K"] < 63.0 / 2


def test_json_has_no_nan():
    text = json.dumps(run_data(spec()).document(), allow_nan=False)
    assert "NaN" not in text


def test_helix_angle_in_radians_is_flagged():
    doc = run_data(spec(gear__helix_angle=0.21)).document()
    c = {c["code"]: c for c in doc["checks"]}["UNITS_ANGLE"]
    assert not c["passed"] and c["severity"] == "warning"
    assert c["message"] == ("helix_angle = 0.21° is below 1°: check the units (degrees; 0.21 rad "
                            "would be 12.03°)")


def test_a_module_below_a_tenth_of_a_millimetre_is_flagged(tmp_path):
    from tests.helpers_cli import cli, write_spec

    path = write_spec(tmp_path, 'kind = "spur"\n[gear]\nmodule = 0.06\nz1 = 20\nz2 = 40\n'
                                'face_width = 0.6\n')
    code, out, err = cli("run", path, "--format", "json")
    import json

    c = {c["code"]: c for c in json.loads(out)["checks"]}["UNITS_MODULE"]
    assert c["message"] == ("module = 0.06 mm is below 0.1 mm (instrument gears start there): "
                            "check the units (module is in mm)")
    path = write_spec(tmp_path, 'kind = "spur"\n[gear]\nmodule = 0.004\nz1 = 20\nz2 = 40\n'
                                'face_width = 40.0\n')
    code, out, err = cli("run", path, "--format", "json")
    assert code == 2 and err.strip().endswith(
        "gear.module = 0.004: must be a number >= 0.05 and <= 100 (mm)")


def test_span_check_names_the_narrow_face_as_the_cause():
    from geardesign.core.registry import run_data

    doc = run_data({"kind": "spur", "gear": {"module": 3.0, "z1": 20, "z2": 80,
                                              "helix_angle": 30.0, "face_width": 12.0}}).document()
    c = {c["code"]: c for c in doc["checks"]}["SPAN_WHEEL"]
    assert not c["passed"]
    assert "cannot be measured: the face width b_w = 12 mm is not more than W2·sin β_b" in \
        c["message"]


DESIGN = {"kind": "spur",
          "design": {"ratio": 4.0, "psi_ba": 0.315, "helix_angle": 12.0, "bearing_scheme": 6},
          "load": {"speed1": 960.0, "torque1": 250.0, "life_hours": 20000.0, "regime": "III"},
          "material": {"pinion": {"grade": "40Kh", "treatment": "improved", "hardness_HB": 285.0},
                       "wheel": {"grade": "40Kh", "treatment": "improved", "hardness_HB": 255.0}}}


@pytest.mark.parametrize("ratio, advice", [
    (11.0, "widen design.ratio_tolerance to 4.9 %"),
    (11.5, "widen design.ratio_tolerance to 9 %"),
    (12.5, "split the ratio into two stages"),
])
def test_a_ratio_the_design_mode_cannot_fit_says_the_change_that_fits(ratio, advice):
    """A ratio no standard module and whole tooth numbers fit: the refusal says why (the
    teeth the module rule m >= 0.01·a_w leaves with z1 >= z1_min) and the change that fits
    one; a tolerance it names makes the design mode propose a pair."""
    data = json.loads(json.dumps(DESIGN))
    data["design"]["ratio"] = ratio
    with pytest.raises(InputError) as caught:
        run_data(data, "s.toml")
    message = caught.value.problems[0].message
    assert message.startswith("no pair of standard module and whole tooth numbers fits this "
                              "ratio within the tolerance: with z1 >= 17 the module rule")
    assert advice in message
    if "widen" in advice:
        data["design"]["ratio_tolerance"] = float(advice.split(" to ")[1].split(" ")[0])
        assert run_data(data, "s.toml").verdict in ("pass", "fail")
