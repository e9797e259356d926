"""[accuracy] and [drawing] of the spur calculator: tolerances, backlash, test dimensions,
the drawing data table, the tip option, --profile/--plot, and the one-line input errors."""

import json
import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from geardesign.core.registry import run_data
from geardesign.spur.tolerances import iso1328
from tests.helpers_cli import cli, run_bad, write_spec

BASE = """kind = "spur"
[gear]
module = 4.0
z1 = 25
z2 = 100
face_width = 63.0
x1 = 0.3
x2 = -0.3
"""
GOST = BASE + """[accuracy]
standard = "GOST 1643-81"
grade = 8
mating = "B"
T_H1 = 100
T_H2 = 160
"""


def _doc(tmp_path, text):
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code in (0, 1), err
    return code, json.loads(out)


@pytest.mark.parametrize("text, line", [
    (GOST.replace("grade = 8", "grade = 2"),
     "s.toml: accuracy.grade = 2: unknown accuracy grade of GOST 1643-81: give 3…12 (1 and 2 "
     "are reserved by the standard)"),
    (GOST.replace("GOST 1643-81\"", "ISO 1328-1:2013\"").replace('mating = "B"\n', "")
     .replace("T_H1 = 100\nT_H2 = 160\n", "fa = 50\nT_sn1 = 60\nT_sn2 = 80\n")
     .replace("grade = 8", "grade = 12"),
     "s.toml: accuracy.grade = 12: unknown flank tolerance class of ISO 1328-1:2013: give 1…11"),
    (GOST + "[drawing]\nball_diameter1 = 20.0\n",
     "s.toml: drawing.ball_diameter1 = 20.0: the ball does not touch the flanks: it would touch "
     "the flanks at d = 114.7834 mm, beyond the involute, which ends at d = 110.4000 mm: choose "
     "a smaller ball"),
    (GOST + "[drawing]\nball_diameter1 = 2.0\n",
     "s.toml: drawing.ball_diameter1 = 2.0: the ball does not touch the flanks: it is too small: "
     "it would sink below the base circle into the tooth space; choose a larger ball"),
    (GOST + "[drawing]\nk1 = 15\n",
     "s.toml: drawing.k1 = 15: impossible span: the calliper would touch at d = 197.2648 mm, "
     "outside the involute 95.7930…110.4000 mm; use k = 2…5"),
    (GOST + "[drawing]\nk2 = 100\n",
     "s.toml: drawing.k2 = 100: must be 1…99 (fewer than the 100 teeth)"),
    (GOST.replace("T_H1 = 100\n", ""),
     "s.toml: accuracy.T_H1: missing; required with GOST 1643-81: the tolerance T_H on the "
     "additional rack shift of the pinion in µm (GOST 1643-81, T_H by F_r and the type of "
     "backlash tolerance)"),
    (GOST.replace('mating = "B"\n', ""),
     "s.toml: accuracy.mating: missing; required with GOST 1643-81: the type of mating H, E, D, "
     "C, B or A"),
    (GOST.replace("GOST 1643-81\"", "ISO 1328-1:2013\""),
     's.toml: accuracy.T_H1 = 100.0: applies to GOST 1643-81 only; remove it with standard = '
     '"ISO 1328-1:2013"'),
    (GOST + "expansion_housing = 10.5\n",
     "s.toml: accuracy.expansion_housing = 10.5: applies only with an operating temperature "
     "(temperature_housing, _pinion, _wheel)"),
])
def test_bad_input_is_one_line(tmp_path, text, line):
    assert run_bad(tmp_path, text) == [line]


def test_gost_backlash_and_limits(tmp_path):
    code, doc = _doc(tmp_path, GOST)
    assert code == 0
    acc, t = doc["results"]["accuracy"], doc["results"]["test_dimensions"]
    assert acc["jn_min_required"] == 185          # B, a_w = 250 mm: IT10 of 180…250
    assert acc["fa"] == 92.5                      # class V: ½·IT10
    # the balance gives exactly j_n min at a_w − f_a
    assert acc["jn_min"] == pytest.approx(185.0, abs=1e-9)
    cos_a = math.cos(math.radians(20.0))
    for n in (1, 2):
        assert t[f"W{n}_upper"] == pytest.approx(t[f"W{n}"] + acc[f"E_sns{n}"] * 1e-3 * cos_a)
        assert t[f"W{n}_lower"] == pytest.approx(t[f"W{n}"] + acc[f"E_sni{n}"] * 1e-3 * cos_a)
        assert t[f"M{n}_lower"] < t[f"M{n}_upper"] < t[f"M{n}"]
        assert t[f"s_chord{n}_lower"] < t[f"s_chord{n}_upper"] < t[f"s_chord{n}"]
    # T_H → thickness tolerance 2·T_H·tan α
    assert acc["E_sns1"] - acc["E_sni1"] == pytest.approx(2 * 100 * math.tan(math.radians(20)))
    assert doc["methods"][-1] == "GOST 1643-81"
    table = {r["parameter"]: r for r in doc["results"]["drawing"]}
    assert table["number of teeth"]["pinion"] == 25 and table["number of teeth"]["wheel"] == 100
    assert table["mating gear: number of teeth"]["pinion"] == 100
    assert table["accuracy"]["pinion"] == "8-B GOST 1643-81"
    assert table["span over k teeth"]["pinion_es"] == pytest.approx(
        t["W1_upper"] - t["W1"])
    assert table["centre distance"]["wheel_es"] == pytest.approx(0.0925)


def test_thermal_expansion_changes_the_backlash(tmp_path):
    hot = GOST + "temperature_housing = 70\ntemperature_pinion = 20\ntemperature_wheel = 20\n"
    _, doc = _doc(tmp_path, hot)
    acc = doc["results"]["accuracy"]
    # housing grows by a_w·α·Δt = 250·11.5e-6·50 mm = 143.75 µm → 2·Δa·sin α_w µm more backlash
    assert acc["j_thermal"] == pytest.approx(2 * 143.75 * math.sin(math.radians(20)), rel=1e-9)
    assert "accuracy.expansion_housing" in doc["assumed"]
    cold_gears = GOST + "temperature_pinion = 90\ntemperature_wheel = 90\n"
    _, doc = _doc(tmp_path, cold_gears)
    acc = doc["results"]["accuracy"]
    assert acc["j_thermal"] < 0 and acc["jn_min_hot"] == pytest.approx(185.0)


def test_jamming_pair_fails(tmp_path):
    text = GOST.replace('mating = "B"', 'mating = "H"') + "E_Hs1 = 0\nE_Hs2 = 0\n"
    code, doc = _doc(tmp_path, text)
    assert code == 1
    c = {c["code"]: c for c in doc["checks"]}
    assert not c["BACKLASH_JAM"]["passed"] and "jam" in c["BACKLASH_JAM"]["message"]


def test_iso_tolerances_in_the_report(tmp_path):
    text = BASE + """[accuracy]
standard = "ISO 1328-1:2013"
grade = 6
fa = 40
T_sn1 = 50
T_sn2 = 70
"""
    code, doc = _doc(tmp_path, text)
    acc = doc["results"]["accuracy"]
    ref = iso1328.flank_tolerances(6, 100.0, 4.0, 63.0)
    assert acc["f_pT1"] == ref.f_pT and acc["F_alphaT1"] == ref.F_alphaT
    assert acc["jn_min_required"] == pytest.approx(iso1328.jbn_min(250.0, 4.0))
    assert acc["E_sni2"] == pytest.approx(acc["E_sns2"] - 70.0)


def test_user_k_and_ball(tmp_path):
    _, doc = _doc(tmp_path, BASE + "[drawing]\nk1 = 3\nball_diameter2 = 7.0\n")
    t = doc["results"]["test_dimensions"]
    assert t["k1"] == 3 and t["D2"] == 7.0
    assert "accuracy" not in doc["results"] and "W1_upper" not in t
    assert any(r["parameter"] == "dimension over balls" for r in doc["results"]["drawing"])


def test_tip_shortening_option():
    gear = {"module": 3.0, "z1": 12, "z2": 24, "x1": 0.6, "x2": 0.36, "face_width": 20.0}
    short = run_data({"kind": "spur", "gear": gear}).document()["results"]["geometry"]
    nominal = run_data({"kind": "spur", "gear": dict(gear, tip_shortening=False)}).document()
    g = nominal["results"]["geometry"]
    assert g["d_a1"] == pytest.approx(36.0 + 2 * (1 + 0.6) * 3.0)       # ISO 21771 nominal
    assert g["d_a2"] == pytest.approx(72.0 + 2 * (1 + 0.36) * 3.0)
    assert short["d_a1"] == pytest.approx(g["d_a1"] - 2 * short["delta_y"] * 3.0)
    assert nominal["inputs"]["gear"]["tip_shortening"] is False


def test_profile_and_plot_files(tmp_path):
    pytest.importorskip("matplotlib")
    spec = write_spec(tmp_path, GOST)
    code, _, err = cli("spur", spec, "-q", "--profile", tmp_path / "p.svg",
                       "--plot", tmp_path / "m.svg")
    assert code == 0, err
    assert (tmp_path / "p.svg").read_text().startswith("<?xml")
    assert "<svg" in (tmp_path / "m.svg").read_text()
    code, _, err = cli("run", spec, "-q", "--profile", tmp_path / "p.png")
    assert code == 2 and err.strip().endswith("the profile file must end in .dxf or .svg")
    assert not (tmp_path / "p.png").exists()


@settings(max_examples=30, deadline=None, suppress_health_check=list(HealthCheck))
@given(m_n=st.sampled_from([1.0, 2.0, 2.5, 3.5, 6.0, 10.0, 16.0]), z1=st.integers(17, 40),
       u=st.floats(1.0, 5.0), beta=st.sampled_from([0.0, 8.0, 15.0, 22.0]),
       b_over_m=st.floats(6.0, 25.0), standard=st.sampled_from(iso1328.EDITIONS),
       grade=st.integers(3, 10))
def test_rating_and_drawing_use_the_same_tolerances(m_n, z1, u, beta, b_over_m, standard,
                                                    grade):
    """The ISO 6336 rating's f_pb, f_fα, f_Hβ and F_β of a random gear pair are the larger of
    the drawing's f_pT·cos α_t, f_fαT, f_HβT and F_βT of its two gears: one computation
    reached through both paths ([accuracy] of the drawing, [iso] of the rating, the edition
    and the class coming from [accuracy])."""
    z2 = max(z1, round(u * z1))
    spec = {"kind": "spur",
            "gear": {"module": m_n, "z1": z1, "z2": z2, "helix_angle": beta,
                     "face_width": round(b_over_m * m_n, 1), "bearing_scheme": 5},
            "load": {"speed1": 1000.0, "torque1": 0.05 * (z1 * m_n) ** 2, "life_hours": 20000.0},
            "material": {w: {"treatment": "carburized", "hardness_HRC": 60.0}
                         for w in ("pinion", "wheel")},
            "options": {"method": "ISO 6336:2019"},
            "accuracy": {"standard": standard, "grade": grade, "fa": 40.0, "T_sn1": 50.0,
                         "T_sn2": 70.0}}
    res = run_data(spec).document()["results"]
    acc, f = res["accuracy"], res["iso6336_factors"]
    assert f["tolerance_standard"] == standard and f["grade"] == grade
    alpha_t = math.radians(res["geometry"]["alpha_t"])
    pair = {k: max(acc[k + "1"], acc[k + "2"]) for k in ("f_pT", "f_falphaT", "f_HbetaT",
                                                        "F_betaT")}
    assert f["f_pb"] == pytest.approx(pair["f_pT"] * math.cos(alpha_t), rel=1e-12)
    assert (f["f_falpha"], f["f_Hbeta"], f["F_beta"]) == (
        pair["f_falphaT"], pair["f_HbetaT"], pair["F_betaT"])
