"""Drawing data of an internal pair against the printed KISSsoft reports: the planet–ring
meshes of the NREL 5 MW planetary stages 1 (ring z = 56, even) and 2 (ring z = 93, odd),
through the spur calculator (``gear.internal = true``, ``[accuracy]``, ``[drawing]``).

Source: KISSsoft Release 03/2017 A, "Calculation of a spur planetary gear stage", GitHub
``gfsReboucas/Drivetrain``, files ``@NREL_5MW/stage_01.rtf`` and ``stage_02.rtf``, commit
4a88df348fc70d04254c84bd375bb2bab0d15d0d ([KISSsoft2017]; [NREL]):

* section 6 "Measurements for tooth thickness": the tooth thickness allowances DIN 3967
  cd25 A_s.e/i (planet −0.175/−0.255 mm; rings −0.430/−0.590 and −0.320/−0.450 mm), the
  number of spaces k and the span W_k with its limits W_k.e/i, the effective ball D_Meff,
  the radial single-ball dimension M_rK and M_rK.e/i, the dimension between two balls M_dK
  and M_dK.e/i, the chordal tooth thickness s_c and s_c.e/i; the centre-distance
  allowances A_a.e/i (ISO 286 js7: ±0.045 and ±0.035 mm, printed with the opposite sign for
  the internal mesh) and the circumferential backlash j_tw (transverse section, working
  pitch circle) of the planet–ring mesh;
* section 7 "Gear accuracy", ISO 1328-1:1995 grade 6: f_pt, F_p, F_α, f_fα, f_Hα, F_β,
  f_fβ, f_Hβ, F_r of the planet and the ring.

The inputs are the reports' (m, z, b, a_w, the stage's cutter z0, the ring's root radius
0.30); the planet's shift is the planetary calculator's (KISSsoft prints it to four
decimals), the ring's follows from a_w.  geardesign's normal backlash j_n is along the line
of action; KISSsoft prints j_tw = j_n / cos α_wt (spur) and a "normal backlash"
j_tw·cos α_n, so j_tw is compared.

Tolerances: lengths printed to 0.001 mm, ±0.0006 mm; tolerances in µm printed as integers,
exact.  KISSsoft's chordal limits are s_c + A_s.e/i (the allowance added to the chord, e.g.
96.702 − 0.175 = 96.527 for the stage-1 planet); geardesign takes the chord of the thinner
arc, whose change is A_s·cos(s_n/d_n): 96.5286, 0.0016–0.0023 mm apart on the planets
(±0.003 on their chordal limits; the rings' agree to 0.0006).  The limits are ordered
(largest, smallest): the upper allowance gives the smaller dimension between balls and the
smaller span over spaces of an internal gear.
"""

import math

import pytest

from geardesign.core.registry import run_data
from tests.conftest import assert_ref
from tests.reference.planetary._util import planetary
from tests.reference.planetary.test_kisssoft_nrel_stages import STAGE1, STAGE2

STAGES = {
    1: {"data": STAGE1, "m": 45.0, "z1": 17, "z2": 56, "b": 491.0, "a_w": 863.0, "z0": 36,
        "fa": 45.0, "A1": (-175.0, -255.0), "A2": (-430.0, -590.0), "D": (110.0, 80.0)},
    2: {"data": STAGE2, "m": 21.0, "z1": 36, "z2": 93, "b": 550.0, "a_w": 584.0, "z0": 30,
        "fa": 35.0, "A1": (-175.0, -255.0), "A2": (-320.0, -450.0), "D": (40.0, 35.0)},
}

# stage: key → printed value (section 6 of each report; limits as (largest, smallest))
PRINTED = {
    1: {"k1": 3, "k2": 8, "W2": 1047.070, "W2_upper": 1047.624, "W2_lower": 1047.474,
        "M2": 2445.378, "M2_upper": 2446.970, "M2_lower": 2446.539,
        "M_r2": 1222.689, "M_r2_upper": 1223.485, "M_r2_lower": 1223.270,
        "s_chord2": 54.260, "s_chord2_upper": 53.830, "s_chord2_lower": 53.670,
        "M1": 1008.755, "M1_upper": 1008.484, "M1_lower": 1008.360,
        "M_r1": 506.303, "M_r1_upper": 506.167, "M_r1_lower": 506.104,
        "W1": 367.520, "W1_upper": 367.356, "W1_lower": 367.281,
        "s_chord1": 96.702, "s_chord1_upper": 96.527, "s_chord1_lower": 96.447},
    2: {"k1": 5, "k2": 11, "W2": 676.615, "W2_upper": 677.038, "W2_lower": 676.916,
        "M2": 1900.511, "M2_upper": 1901.836, "M2_lower": 1901.454,
        "M_r2": 950.393, "M_r2_upper": 951.056, "M_r2_lower": 950.865,
        "s_chord2": 34.775, "s_chord2_upper": 34.455, "s_chord2_lower": 34.325,
        "M1": 836.492, "M1_upper": 836.128, "M1_lower": 835.961,
        "M_r1": 418.246, "M_r1_upper": 418.064, "M_r1_lower": 417.981,
        "W1": 296.803, "W1_upper": 296.638, "W1_lower": 296.563,
        "s_chord1": 40.670, "s_chord1_upper": 40.495, "s_chord1_lower": 40.415},
}

# section 7, ISO 1328-1:1995 grade 6: (planet, ring) in µm
TOLERANCES = {
    1: {"f_pT": (33, 38), "F_pT": (81, 132), "F_alphaT": (42, 51), "f_falphaT": (33, 40),
        "f_HalphaT": (27, 32), "F_betaT": (30, 34), "f_fbetaT": (21, 24),
        "f_HbetaT": (21, 24), "F_rT": (65, 105)},
    2: {"f_pT": (19, 22), "F_pT": (67, 97), "F_alphaT": (30, 35), "f_falphaT": (23, 27),
        "f_HalphaT": (19, 22), "F_betaT": (30, 32), "f_fbetaT": (21, 23),
        "f_HbetaT": (21, 23), "F_rT": (53, 78)},
}

# circumferential backlash j_tw of the planet–ring mesh (largest, smallest) and its part
# from the centre-distance allowance, mm
BACKLASH = {1: ((0.859, 0.567), 0.028), 2: ((0.708, 0.463), 0.020)}


def _spec(stage: int) -> dict:
    s = STAGES[stage]
    x_planet = planetary(s["data"])["results"]["gears"]["x_planet"]
    return {
        "kind": "spur", "title": f"NREL stage {stage} planet–ring",
        "gear": {"internal": True, "module": s["m"], "z1": s["z1"], "z2": s["z2"],
                 "x1": x_planet, "center_distance": s["a_w"], "face_width": s["b"],
                 "cutter_teeth": s["z0"], "cutter_tip_radius_coef": 0.30},
        "accuracy": {"standard": "ISO 1328-1:1995", "grade": 6, "fa": s["fa"],
                     "A_sne1": s["A1"][0], "A_sne2": s["A2"][0],
                     "T_sn1": s["A1"][0] - s["A1"][1], "T_sn2": s["A2"][0] - s["A2"][1]},
        "drawing": {"ball_diameter1": s["D"][0], "ball_diameter2": s["D"][1]},
    }


@pytest.fixture(scope="module", params=[1, 2])
def stage(request):
    return request.param, run_data(_spec(request.param)).document()


def test_test_dimensions_of_planet_and_ring(stage):
    n, doc = stage
    v = doc["results"]["test_dimensions"]
    for key, printed in PRINTED[n].items():
        tol = 0.003 if key.startswith("s_chord1_") else 0.0006
        assert_ref(v[key], printed, tol, f"KISSsoft stage {n}: {key}")


def test_iso1328_1995_tolerances_of_planet_and_ring(stage):
    n, doc = stage
    v = doc["results"]["accuracy"]
    for key, (planet, ring) in TOLERANCES[n].items():
        assert v[f"{key}1"] == planet, f"KISSsoft stage {n}: {key} planet"
        assert v[f"{key}2"] == ring, f"KISSsoft stage {n}: {key} ring"


def test_backlash_with_the_rings_allowances(stage):
    n, doc = stage
    v = doc["results"]["geometry"]
    alpha_tw = math.radians(v["alpha_tw"])   # reported in degrees
    cos_aw = math.cos(alpha_tw)
    (j_max, j_min), j_fa = BACKLASH[n]
    b = doc["results"]["accuracy"]
    assert_ref(b["jn_max"] * 1e-3 / cos_aw, j_max, 0.0006, f"KISSsoft stage {n}: jtw max")
    assert_ref(b["jn_min"] * 1e-3 / cos_aw, j_min, 0.0006, f"KISSsoft stage {n}: jtw min")
    # the part of the centre distance: 2·A_a·tan α_wt
    assert_ref(2 * STAGES[n]["fa"] * 1e-3 * math.tan(alpha_tw), j_fa, 0.0006,
               f"KISSsoft stage {n}: jtw_Aa")


def test_the_drawing_table_names_the_internal_gear(stage):
    n, doc = stage
    rows = {r["parameter"].split(" (")[0]: r for r in doc["results"]["drawing"]}
    assert rows["toothing"]["wheel"] == "internal"
    m = rows["dimension over balls"]
    assert m["wheel"] == pytest.approx(PRINTED[n]["M2"], abs=0.0006)
    assert m["wheel_es"] == pytest.approx(PRINTED[n]["M2_upper"] - PRINTED[n]["M2"], abs=0.0012)
    assert m["wheel_ei"] == pytest.approx(PRINTED[n]["M2_lower"] - PRINTED[n]["M2"], abs=0.0012)


# diameters where the calliper (d_MWk.m) and the ball (d_MMr.m) touch the ring's flanks at
# the mean allowance, as printed (section 6), with the printed number of spaces
CONTACT = {1: (8, 2589.383, 2555.762), 2: (11, 1956.100, 1948.395)}


@pytest.mark.parametrize("n", [1, 2])
def test_ring_contact_diameters_at_the_mean_allowance(n):
    from geardesign.gears.span import base_tangent_length
    from geardesign.spur.measurement import Tooth, over_balls

    s = STAGES[n]
    x2 = planetary(s["data"])["results"]["gears"]["x_ring"]      # GOST 19274-73 sign
    m, z, a = s["m"], s["z2"], math.radians(20.0)
    mean = 0.5 * (s["A2"][0] + s["A2"][1]) * 1e-3
    s_n = m * (0.5 * math.pi - 2 * x2 * math.tan(a)) + mean
    ball = over_balls(Tooth(z, m, a, 0.0, math.pi * m - s_n, 0.0, 0.0, True), s["D"][1])
    k, d_mw, d_mm = CONTACT[n]
    # thinner internal teeth = a larger shift in the GOST sign
    x_mean = x2 - mean / (2 * m * math.tan(a))
    _, _, d_W = base_tangent_length(z, x_mean, m, a, a, 0.0, z * m, z * m * math.cos(a), k)
    assert_ref(d_W, d_mw, 0.0006, f"KISSsoft stage {n}: dMWk.m")
    assert_ref(ball.d_c, d_mm, 0.0006, f"KISSsoft stage {n}: dMMr.m")
