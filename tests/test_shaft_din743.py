"""kind = "shaft" with ``[shaft] method = "DIN743"``: the method's spec keys and defaults,
every input rule of the method (exact one-line message, exit 2), the report (DIN factors,
S_min 1.2), a failing design with advice, random shafts (finite positive safeties), the
drive's shafts by DIN 743, and the DIN 743 formulas against hand values.  The factors
against an independent implementation: tests/reference/shaft/test_din743_independent.py."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.core.spec import parse_toml
from geardesign.shaft.din743 import part1 as P1
from geardesign.shaft.din743 import part2 as P2
from geardesign.shaft.din743 import part3 as P3
from geardesign.shaft.din743 import rating as R
from geardesign.shaft.solve import Material, Options, analyse
from tests.helpers_cli import run_bad, run_failing
from tests.test_shaft import BASE, shafts

DIN = BASE.replace("[shaft]\nspeed = 200.0\n", '[shaft]\nspeed = 200.0\nmethod = "DIN743"\n') \
    .replace('grade = "45"\nhardness_HB = 270.0\n', 'grade = "C45"\n')


def test_din_spec_passes_with_din_factors_and_defaults():
    doc = run_data(parse_toml(DIN)).document()
    assert doc["verdict"] == "pass"
    assert "DIN 743-1/-2/-3 (2012)" in doc["methods"]
    assert not any(m.startswith("GOST") for m in doc["methods"])
    sh = doc["inputs"]["shaft"]
    assert (sh["S_min"], sh["S_static_min"], sh["din743_load_case"],
            sh["din743_hard_surface"]) == (1.2, 1.2, 2, False)
    assert {"shaft.S_min", "shaft.din743_load_case"} <= set(doc["assumed"])
    fat = doc["results"]["fatigue"]
    assert {"beta_sigma", "beta_tau", "K_2", "K_F", "K_sigma", "K_tau", "sigma_WK",
            "tau_WK", "psi_sigma", "sigma_ADK", "tau_ADK", "S", "S_static"} <= set(fat[0])
    notches = {r["concentrator"] for r in fat}
    assert {"key", "fillet"} <= notches
    mat = doc["results"]["material"]
    assert mat["sigma_B_dB"] == 700.0 and mat["d_eff"] == 55.0
    assert math.isclose(mat["K_1B"], 1 - 0.26 * math.log10(55 / 16), rel_tol=1e-12)


def test_given_S_min_is_kept():
    doc = run_data(parse_toml(DIN.replace('method = "DIN743"\n',
                                          'method = "DIN743"\nS_min = 1.8\n'))).document()
    assert doc["inputs"]["shaft"]["S_min"] == 1.8
    assert next(c for c in doc["checks"] if c["code"] == "FATIGUE")["limit"] == 1.8


def test_gost_grade_45_is_C45_and_strengths_override():
    a = run_data(parse_toml(DIN)).document()
    b = run_data(parse_toml(DIN.replace('grade = "C45"', 'grade = "45"'))).document()
    assert a["results"]["strength"]["S"] == b["results"]["strength"]["S"]
    c = run_data(parse_toml(DIN.replace(
        'grade = "C45"', 'sigma_B = 700.0\nsigma_T = 490.0\nsteel_type = "quenched_tempered"'
    ))).document()
    assert math.isclose(c["results"]["strength"]["S"], a["results"]["strength"]["S"],
                        rel_tol=1e-12)


@pytest.mark.parametrize("change, line", [
    (('method = "DIN743"', 'method = "ISO"'),
     's.toml: shaft.method = "ISO": must be one of "GOST", "DIN743"'),
    (('grade = "C45"', 'grade = "40KhN"'),
     's.toml: material.grade = "40KhN": a GOST grade without an EN equivalent in DIN 743-3; '
     'known: ' + ", ".join(P3.tables()["steel"]) + ' (and the GOST grades 45, 40Kh); or '
     'leave out grade and give sigma_B, sigma_T and steel_type'),
    (('grade = "C45"', 'grade = "St52"'),
     's.toml: material.grade = "St52": not a steel of DIN 743-3; known: '
     + ", ".join(P3.tables()["steel"]) + ' (and the GOST grades 45, 40Kh); or leave out '
     'grade and give sigma_B, sigma_T and steel_type'),
    (('grade = "C45"', 'sigma_B = 800.0\nsigma_T = 600.0'),
     "s.toml: material.steel_type: missing; method DIN743 without a grade needs sigma_B, "
     "sigma_T and steel_type: the DIN 743-3 steel type (structural, quenched_tempered, "
     "case_hardening, case_hardening_CrNiMo, nitriding) (or give an EN grade of DIN 743-3 "
     "as material.grade)"),
    (('grade = "C45"', 'grade = "C45"\nhardness_HB = 240.0'),
     "s.toml: material.hardness_HB = 240.0: used only by the GOST method; DIN 743 takes the "
     "endurance limits and the mean-stress sensitivity from sigma_B (DIN 743-3) and one row "
     "per grade: leave it out, or give sigma_B and sigma_T of the blank"),
    (('grade = "C45"', 'grade = "C45"\nsteel_type = "nitriding"'),
     's.toml: material.steel_type = "nitriding": steel C45 is quenched_tempered in DIN '
     '743-3: leave out steel_type, or leave out grade'),
    (("keyway = true", 'keyway = true\nkeyway_cutter = "disc_cutter"'),
     's.toml: step[1].keyway_cutter = "disc_cutter": DIN 743-2 gives the notch factor of a '
     'key seat cut by an end mill only: no data for a disc cutter (use end_mill, or method '
     'GOST)'),
])
def test_din_input_errors(tmp_path, change, line):
    old, new = change
    assert old in DIN
    assert run_bad(tmp_path, DIN.replace(old, new, 1)) == [line]


@pytest.mark.parametrize("change, line", [
    (('grade = "45"\nhardness_HB = 270.0', 'grade = "45"\nhardness_HB = 270.0\nd_eff = 80.0'),
     's.toml: material.d_eff = 80.0: used only by [shaft] method = "DIN743" (this spec rates '
     'by GOST)'),
    (("speed = 200.0", "speed = 200.0\ndin743_load_case = 1"),
     "s.toml: shaft.din743_load_case = 1: used only by method = \"DIN743\" (this spec rates "
     "by GOST)"),
])
def test_din_keys_are_refused_by_gost(tmp_path, change, line):
    old, new = change
    assert old in BASE
    assert run_bad(tmp_path, BASE.replace(old, new, 1)) == [line]


@pytest.mark.parametrize("F", [60000.0, 90000.0])
def test_weak_din_shaft_fails_with_advice_that_reaches_S(tmp_path, F):
    """The advised scale of the diameters, applied to the whole shaft, passes DIN 743
    (K_1, K_2, K_3 and β change with d: the calculator analysed the scaled shaft)."""
    from tests.test_shaft import apply_scale_advice

    text = DIN.replace("Fy = 3000.0", f"Fy = {F}")
    doc = run_failing(tmp_path, text)
    fat = next(c for c in doc["checks"] if c["code"] == "FATIGUE")
    assert not fat["passed"] and fat["limit"] == 1.2
    again = run_data(apply_scale_advice(text, fat["message"])).document()
    assert again["results"]["strength"]["S"] >= 1.2
    assert next(c for c in again["checks"] if c["code"] == "FATIGUE")["passed"]


# ------------------------------------------------------- notches by geometry (DIN 743-2)

# DIN with a round groove at the right end of step 1 (into the 45 mm seat), a rectangular
# groove at the right end of step 2 (55 mm; a generous fillet of the shoulder beside it) and
# a cross-bore in step 3
GROOVES = DIN.replace("[[step]]\nlength = 40.0\ndiameter = 45.0\n",
                      "[[step]]\nlength = 40.0\ndiameter = 45.0\ngroove_depth = 1.0\n"
                      "groove_radius = 1.0\n") \
    .replace("keyway = true\n", "keyway = true\nfillet = 4.0\ngroove_depth = 1.5\n"
             "groove_width = 1.85\ngroove_radius = 0.2\n") \
    .replace("[[step]]\nlength = 60.0\ndiameter = 45.0\n",
             "[[step]]\nlength = 60.0\ndiameter = 45.0\ncross_bore = 5.0\n"
             "cross_bore_at = 40.0\n")


def test_grooves_and_cross_bore_are_rated_and_named():
    doc = run_data(parse_toml(GROOVES)).document()
    fat = {r["label"]: r for r in doc["results"]["fatigue"]}
    assert fat["step 1|2"]["concentrator"] == "round groove"
    assert fat["step 2|3"]["concentrator"] == "ring groove"
    cb = fat["cross-bore in step 3"]
    assert cb["concentrator"] == "cross-bore"
    sec = {r["label"]: r for r in doc["results"]["sections"]}
    assert sec["step 1|2"]["d"] == 43.0          # the groove root 45 − 2·1
    assert sec["step 2|3"]["d"] == 52.0          # 55 − 2·1.5
    assert sec["cross-bore in step 3"]["x"] == 160.0
    # the groove root is rated as a round groove of the DIN 743-2 formulas
    din = R.material(P3.steel("C45"), 55.0)
    n = R.round_groove(45.0, 1.0, 1.0, din, False)
    assert math.isclose(fat["step 1|2"]["beta_sigma"], n.beta_b, rel_tol=1e-12)
    assert math.isclose(n.alpha_b, P2.alpha_shoulder(43.0, 45.0, 1.0, "bending",
                                                     "round_groove"), rel_tol=1e-15)
    # the cross-bore's nominal stress is on the net section
    A, W, Wp = P2.cross_bore_section(45.0, 5.0)
    assert math.isclose(sec["cross-bore in step 3"]["sigma_a"],
                        sec["cross-bore in step 3"]["M"] * 1e3 / W, rel_tol=1e-9)
    # the grooves lower the safety of their sections below that of the shaft without them
    plain = GROOVES.replace("groove_depth = 1.0\ngroove_radius = 1.0\n", "").replace(
        "groove_depth = 1.5\ngroove_width = 1.85\ngroove_radius = 0.2\n", "")
    plain = {r["label"]: r
             for r in run_data(parse_toml(plain)).document()["results"]["fatigue"]}
    assert fat["step 1|2"]["S"] < plain["step 1|2"]["S"]
    assert fat["step 2|3"]["S"] < plain["step 2|3"]["S"]


def test_v_notch_is_rated_at_its_root():
    text = GROOVES.replace("groove_depth = 1.0\ngroove_radius = 1.0\n",
                           'groove_depth = 3.0\ngroove_shape = "V"\n')
    doc = run_data(parse_toml(text)).document()
    fat = {r["label"]: r for r in doc["results"]["fatigue"]}
    sec = {r["label"]: r for r in doc["results"]["sections"]}
    assert fat["step 1|2"]["concentrator"] == "V-notch" and sec["step 1|2"]["d"] == 39.0
    n = R.v_notch(45.0, 3.0, R.material(P3.steel("C45"), 55.0))
    assert math.isclose(fat["step 1|2"]["beta_sigma"], n.beta_b, rel_tol=1e-12)


def test_shallow_round_groove_warns_outside_the_alpha_range():
    text = GROOVES.replace("groove_depth = 1.0\ngroove_radius = 1.0\n",
                           "groove_depth = 0.3\ngroove_radius = 11.0\n")
    doc = run_data(parse_toml(text)).document()
    warn = next(c for c in doc["checks"] if c["code"] == "FILLET_TABLE_RANGE")
    assert "step 1|2" in warn["message"]


@pytest.mark.parametrize("F, x, where", [(60000.0, 60.0, "round groove"),
                                         (100000.0, 60.0, "round groove"),
                                         (100000.0, 110.0, "ring groove")])
def test_weak_grooved_shaft_fails_with_advice_that_passes(tmp_path, F, x, where):
    """A grooved shaft (no keyway) that fails DIN 743 at a groove: the advised scale (the
    grooves scale with the diameters) applied to the spec passes."""
    from tests.test_shaft import apply_scale_advice

    text = GROOVES.replace("keyway = true\n", "").replace("position = 80.0",
                                                          f"position = {x}") \
        .replace("Fy = 3000.0", f"Fy = {F}")
    doc = run_failing(tmp_path, text)
    fat = next(c for c in doc["checks"] if c["code"] == "FATIGUE")
    assert not fat["passed"] and f"{where}):" in fat["message"]
    assert "grooves' depth, radius and width" in fat["message"]
    again = run_data(apply_scale_advice(text, fat["message"])).document()
    assert again["results"]["strength"]["S"] >= 1.2
    assert next(c for c in again["checks"] if c["code"] == "FATIGUE")["passed"]


@pytest.mark.parametrize("change, line", [
    (("groove_depth = 1.0\n", ""),
     "s.toml: step[0].groove_radius = 1.0: needs groove_depth (the depth of the groove at the "
     "step's right end)"),
    (("groove_radius = 1.0\n", ""),
     "s.toml: step[0].groove_radius: missing; a groove (groove_depth) needs its radius: the "
     "radius of a round groove, or the root radius of a rectangular groove (with "
     "groove_width)"),
    (("groove_depth = 1.0\n", "groove_depth = 1.0\ngroove_K_sigma = 2.0\n"),
     "s.toml: step[0].groove_depth = 1.0: give the groove by its factors (groove_K_sigma) or "
     "by its geometry (groove_depth), not both"),
    (("groove_depth = 1.0\n", "groove_depth = 12.0\n"),
     "s.toml: step[0].groove_depth = 12.0: at most diameter/4 = 11.25 mm (a groove root "
     "below half the step's diameter is no groove)"),
    (("groove_depth = 1.0\n", "groove_depth = 5.0\nbore = 36.0\n"),
     "s.toml: step[0].groove_depth = 5.0: must be less than (diameter − bore)/2 = 4.5 mm: the "
     "groove root must stay outside the bore"),
    (("groove_radius = 1.0\n", "groove_radius = 0.0\n"),
     "s.toml: step[0].groove_radius = 0.0: must be above 0 for a round groove (a sharp groove "
     "is a rectangular one: give groove_width)"),
    (("groove_radius = 1.0\n", "groove_radius = 300.0\n"),
     "s.toml: step[0].groove_radius = 300.0: the round groove is 48.9 mm wide at the surface, "
     "more than the step's length 40 mm"),
    (("groove_radius = 0.2\n", "groove_radius = 1.0\n"),
     "s.toml: step[1].groove_radius = 1.0: the root radius of a rectangular groove is at most "
     "its depth 1.5 mm and half its width 0.925 mm"),
    (("groove_width = 1.85\n", "groove_width = 81.0\n"),
     "s.toml: step[1].groove_width = 81.0: more than the step's length 80 mm"),
    (("cross_bore = 5.0\n", "cross_bore = 14.0\n"),
     "s.toml: step[2].cross_bore = 14.0: at most 0.3·diameter = 13.5 mm (the range of the "
     "cross-bore's factors taken here)"),
    (("cross_bore = 5.0\n", "cross_bore = 5.0\nbore = 10.0\n"),
     "s.toml: step[2].cross_bore = 5.0: DIN 743-2 rates a cross-bore through a solid shaft "
     "only (this step has a bore)"),
    (("cross_bore_at = 40.0\n", "cross_bore_at = 59.0\n"),
     "s.toml: step[2].cross_bore_at = 59.0: the hole must lie within the step: 2.5…57.5 mm "
     "from its left end"),
    (("cross_bore = 5.0\n", ""),
     "s.toml: step[2].cross_bore_at = 40.0: needs cross_bore (the diameter of the hole)"),
    (("cross_bore = 5.0\ncross_bore_at = 40.0\n",
      "cross_bore = 5.0\ncross_bore_at = 40.0\ngroove_depth = 1.0\ngroove_radius = 1.0\n"),
     "s.toml: step[2].groove_depth = 1.0: a groove sits at the right end of its step, and the "
     "last step ends with the shaft: give it on the step to the left of the groove's "
     "shoulder"),
    (("groove_radius = 1.0\n", 'groove_shape = "V"\ngroove_radius = 1.0\n'),
     's.toml: step[0].groove_radius = 1.0: a V-notch (groove_shape = "V") is given by its '
     'depth alone (DIN 743-2: a sharp notch of the test specimen): leave it out'),
    (("groove_radius = 1.0\n", 'groove_shape = "V"\n'),
     "s.toml: step[0].groove_depth = 1.0: a V-notch of DIN 743-2 holds for 0.05 <= t/d <= "
     "0.2 (d = diameter − 2t the root): t from 2.05 to 6.43 mm, the root outside the bore"),
    (("groove_radius = 1.0\n", 'groove_radius = 1.0\ngroove_shape = "rectangular"\n'),
     's.toml: step[0].groove_width: missing; groove_shape = "rectangular" needs the width of '
     'the groove'),
    (("groove_width = 1.85\n", 'groove_width = 1.85\ngroove_shape = "round"\n'),
     's.toml: step[1].groove_width = 1.85: a round groove has no width: leave it out, or give '
     'groove_shape = "rectangular"'),
    (("groove_width = 1.85\n", "groove_width = 0.0\n"),
     "s.toml: step[1].groove_width = 0.0: must be a number >= 0.001 and <= 5000 (mm)"),
])
def test_groove_and_cross_bore_input_errors(tmp_path, change, line):
    old, new = change
    assert old in GROOVES
    assert run_bad(tmp_path, GROOVES.replace(old, new, 1)) == [line]


@pytest.mark.parametrize("key, value, what", [
    ("groove_depth", "1.0", "groove"), ("groove_radius", "1.0", "groove"),
    ("groove_width", "2.0", "groove"), ("groove_shape", '"V"', "groove"),
    ("cross_bore", "4.0", "cross-bore"),
    ("cross_bore_at", "20.0", "cross-bore")])
def test_din_step_keys_are_refused_by_gost(tmp_path, key, value, what):
    hint = (": give the groove's factors groove_K_sigma/groove_K_tau" if what == "groove"
            else "")
    text = BASE.replace("[[step]]\nlength = 40.0\n", f"[[step]]\nlength = 40.0\n{key} = "
                        f"{value}\n", 1)
    assert run_bad(tmp_path, text) == [
        f's.toml: step[0].{key} = {value}: a DIN 743 key, used only by [shaft] method = '
        f'"DIN743" (this spec rates by GOST, whose tables have no factors of a {what} by its '
        f'geometry{hint})']


def test_load_case_1_and_hard_surface_change_the_result():
    a = run_data(parse_toml(DIN)).document()["results"]["strength"]
    b = run_data(parse_toml(DIN.replace('method = "DIN743"', 'method = "DIN743"\n'
                                        'din743_hard_surface = true'))).document()
    assert b["results"]["strength"]["S_static"] < a["S_static"]   # K_2F 1.2 -> 1.0
    c = run_data(parse_toml(DIN.replace('method = "DIN743"', 'method = "DIN743"\n'
                                        'din743_load_case = 1'))).document()
    assert c["results"]["strength"]["S"] != a["S"]


C45 = R.material(P3.steel("C45"), 60.0)
DIN_MAT = Material(C45.sigma_B_d, C45.sigma_S_d, 0.5 * 700 * C45.K_1B, 0.3 * 700 * C45.K_1B,
                   0.1, 0.05, din=C45)


@settings(max_examples=40, deadline=None)
@given(shafts())
def test_random_shafts_have_finite_positive_din_safeties(case):
    steps, loads, supports = case
    for lc in (1, 2):
        r = analyse(steps, loads, supports, DIN_MAT,
                    Options(speed=100.0, method="DIN743", load_case=lc))
        for s in r.sections:
            # S = 0 only where the mean stress alone yields the section (load case 1)
            assert s.S_static > 0 and (s.S > 0 or (lc == 1 and s.S_static < 1.0))
            d = s.din
            assert d.K_sigma > 0 and d.K_tau > 0 and d.notch.beta_b >= 1.0
            for v in (d.sigma_WK, d.tau_WK, d.sigma_ADK, d.tau_ADK, d.sigma_FK, d.tau_FK):
                assert math.isfinite(v)


@settings(max_examples=40, deadline=None)
@given(shafts(), st.sampled_from(["round", "rectangular", "V"]), st.floats(0.06, 0.15))
def test_random_grooved_shafts_have_finite_positive_din_safeties(case, shape, f):
    """Every step but the last with a groove of that shape (depth f·d/2 within each
    shape's domain) and a cross-bore of 0.1·d: finite, positive safeties, β >= 1, and the
    sections at the groove roots and the holes exist."""
    from dataclasses import replace

    steps, loads, supports = case
    grooved = []
    for i, s in enumerate(steps):
        t = f * s.diameter / 2.0
        g = {} if i == len(steps) - 1 else {
            "round": {"groove_depth": t, "groove_radius": t},
            "rectangular": {"groove_depth": t, "groove_width": 1.4 * t,
                            "groove_radius": 0.1 * t},
            "V": {"groove_depth": t, "groove_shape": "V"}}[shape]
        grooved.append(replace(s, cross_bore=0.1 * s.diameter, **g))
    r = analyse(grooved, loads, supports, DIN_MAT, Options(speed=100.0, method="DIN743"))
    labels = [s.label for s in r.sections]
    assert sum("cross-bore" in lb for lb in labels) == len(steps)
    for s in r.sections:
        assert s.S_static > 0 and s.S > 0
        d = s.din
        assert d.notch.beta_b >= 1.0 and d.notch.beta_t >= 1.0
        for v in (d.sigma_WK, d.tau_WK, d.sigma_ADK, d.tau_ADK, d.sigma_FK, d.tau_FK):
            assert math.isfinite(v)


# ------------------------------------------------------------------ formulas by hand


def test_size_factors_at_their_ends():
    assert P2.K_2(7.5) == 1.0 and P2.K_2(5.0) == 1.0
    assert math.isclose(P2.K_2(150.0), 0.8, rel_tol=1e-12)
    assert math.isclose(P2.K_2(400.0), 0.8, rel_tol=1e-12)
    assert math.isclose(P2.K_3(150.0, 2.0), 1 - 0.2 * math.log10(2.0), rel_tol=1e-12)


@pytest.mark.parametrize("typ, strength, d_2", [
    ("structural", "B", 300.0), ("structural", "S", 300.0),
    ("quenched_tempered", "B", 300.0), ("quenched_tempered", "S", 300.0),
    ("case_hardening", "B", 150.0), ("case_hardening_CrNiMo", "S", 300.0),
    ("nitriding", "B", 300.0)])
def test_K1_branches_meet_their_end_value(typ, strength, d_2):
    """Each K_1 branch reaches its constant end value at d_2 to the printed digit (a check
    of the transcribed constants)."""
    row = P3.tables()["K_1"][f"{typ}_{strength}"]
    assert abs(P3.K_1(typ, d_2 - 1e-9, strength) - row["K_min"]) < 0.005
    assert P3.K_1(typ, 10.0, strength) == 1.0


def test_gamma_F_and_K_2F():
    assert P1.gamma_F(1.4, True, False) == 1.0
    assert P1.gamma_F(1.5, True, False) == 1.05
    assert P1.gamma_F(2.5, True, False) == 1.1
    assert P1.gamma_F(3.2, True, False) == 1.15
    assert P1.gamma_F(3.2, False, False) == 1.0 and P1.gamma_F(3.2, True, True) == 1.0
    assert (P1.K_2F("bending", False, False), P1.K_2F("bending", False, True),
            P1.K_2F("torsion", False, True), P1.K_2F("tension", False, False),
            P1.K_2F("torsion", True, False)) == (1.2, 1.1, 1.0, 1.0, 1.0)


def test_amplitude_strength_is_continuous_at_the_branch_limit():
    WK, FK, psi = 200.0, 500.0, 0.15
    lim1 = (FK - WK) / (1 - psi)
    assert math.isclose(P1.amplitude_strength(1, lim1, 1.0, FK, WK, psi),
                        P1.amplitude_strength(1, lim1 * (1 + 1e-12), 1.0, FK, WK, psi),
                        rel_tol=1e-9)
    lim2 = (FK - WK) / (WK - FK * psi)
    a = 100.0
    assert math.isclose(P1.amplitude_strength(2, lim2 * a, a, FK, WK, psi),
                        P1.amplitude_strength(2, lim2 * a * (1 + 1e-12), a, FK, WK, psi),
                        rel_tol=1e-9)
    # no mean stress: the fatigue limit itself in both cases
    assert P1.amplitude_strength(1, 0.0, a, FK, WK, psi) == WK
    assert P1.amplitude_strength(2, 0.0, a, FK, WK, psi) == WK


def test_drive_shafts_by_din743():
    """A drive's [shaft.strength] takes the method like [shaft] of the shaft calculator."""
    from pathlib import Path

    from geardesign.core.registry import load

    path = Path("specs/drive_reducer_shafts_keys_thermal.toml")
    text = path.read_text(encoding="utf-8")
    text = text.replace('grade = "40Kh"\nhardness_HB = 270.0', 'grade = "42CrMo4"') \
        .replace('grade = "45"\nhardness_HB = 240.0', 'grade = "C45"')
    data = parse_toml(text)
    for sh in data["shaft"]:
        sh.setdefault("strength", {})["method"] = "DIN743"
    calc, spec = load(path, data=data)
    doc = calc.compute(spec).document()
    rows = doc["results"]["shafts"]
    assert all(r["S_min"] == 1.2 and r["S_static_min"] == 1.2 for r in rows)
    for part in doc["results"]["shaft_reports"]:
        assert "DIN 743-1/-2/-3 (2012)" in part["methods"]
