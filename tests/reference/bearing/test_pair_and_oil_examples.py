"""Published worked examples of paired bearings with induced axial loads and of the oil
viscosity at the operating temperature.

* [NSK] (NSK Rolling Bearings, CAT. No. E1102e), section 5.7, example 5, pp. A34–A36: tapered
  roller bearings HR30305DJ (bearing 1: C_r = 38 000 N, e = 0.83, Y1 = 0.73) and HR30206J
  (bearing 2: C_r = 43 000 N, e = 0.38, Y2 = 1.60) back to back, n = 600 min^-1, external
  axial load Fae = 2 000 N on bearing 1; radial loads from the shaft geometry Fr1 = 1 569 N,
  Fr2 = 3 931 N.  NSK's induced force is 0.6·F_r/Y.  Printed: Fa1 = Fae + 0.6/Y2·Fr2 =
  3 474 N, Fa2 = 0 (bearing 2 carries only its own induced force, which does not enter its
  P), P1 = 3 164 N, Lh1 = 109 750 h, P2 = 3 931 N, Lh2 = 80 400 h.  NSK reads the life from
  f_h = f_n·C/P with f_n = (33.3/n)^(3/10) and L_h = 500·f_h^(10/3): the tolerance 0.6 %
  covers its rounding of f_h to three digits (5.04, 4.59).
* [NTN] (CAT. No. 2202/E) example 4, p. A-27: tapered roller bearings 4T-32206 (bearing 1,
  Y = 1.60) and 4T-32205 (bearing 2, Y = 1.60) face to face on a gear shaft, Fr1 = 5.98 kN,
  Fr2 = 4.18 kN, no external axial load: Fa2 = 0.5·Fr1/Y1 = 1.87 kN (printed).
* [SKF6000] p. 59: "ISO VG 32 … for 70 °C" gives at least about 11 mm²/s (read in diagram 6,
  drawn for VI 95); p. 81, example 5/2: base oil ν40 = 200 mm²/s read in diagram 6 at 50, 60
  and 65 °C: 120, 75, 60 mm²/s.  Chart readings: ±5 %.
* [ASTMD2270] example: ν40 = 22.83, ν100 = 5.05 mm²/s give VI = 156.
* Angular contact pairs: no published worked example with numbers was found (searched the
  SKF, NSK, NTN, URB catalogue texts and the web pages corpus); the cases of [SKF6000]
  table 4, p. 416, are checked one by one with R = 0.88 (40°).
"""

import pytest

from geardesign.bearing import pair as PR
from geardesign.materials import lubricants as OIL
from tests.conftest import assert_ref
from tests.reference.bearing._util import document
from tests.conftest import flat

NSK_A = {"type": "tapered_roller", "C_r": 38000.0, "e": 0.83, "Y": 0.73}
NSK_B = {"arrangement": "back_to_back", "F_r": 3931.0, "C_r": 43000.0, "e": 0.38, "Y": 1.60,
         "induced_factor": 0.6}


def nsk_example_5():
    doc = document("iso281_2007", NSK_A, {"F_r": 1569.0, "F_a": 2000.0, "speed": 600.0},
                   mode="pair", pair=dict(NSK_B))
    return flat(doc), doc


def test_nsk_example_5_axial_loads():
    v, doc = nsk_example_5()
    r = doc["results"]["pair"]
    assert r["K_a_carrier"] == "A"                 # back to back, F_a from A towards B
    assert_ref(r["F_aA"], 3474.0, 0.5, "[NSK] ex. 5 Fa1 = Fae + 0.6/Y2·Fr2")
    assert_ref(r["F_iB"], 3474.0 - 2000.0, 0.5, "[NSK] ex. 5 0.6/Y2·Fr2")


def test_nsk_example_5_lives():
    v, doc = nsk_example_5()
    assert_ref(doc["results"]["load"]["P"], 3164.0, 0.5, "[NSK] ex. 5 P1 = 0.4·1569 + 0.73·3474")
    assert_ref(doc["results"]["life"]["L10h"], 109750.0, 0.006 * 109750.0, "[NSK] ex. 5 Lh1 (f_h rounded: ±0.6 %)")
    b = doc["results"]["bearing_B"]
    assert_ref(b["P"], 3931.0, 1e-9, "[NSK] ex. 5 P2 = Fr2 (Fa2/Fr2 <= e)")
    assert_ref(b["L10h"], 80400.0, 0.006 * 80400.0, "[NSK] ex. 5 Lh2 (f_h rounded: ±0.6 %)")
    assert doc["verdict"] == "pass"


def test_ntn_example_4_pair_without_external_load():
    doc = document("gost18855_94", {"type": "tapered_roller", "C_r": 54500.0, "e": 0.37,
                                    "Y": 1.60},
                   {"F_r": 5980.0, "speed": 2000.0}, mode="pair",
                   pair={"arrangement": "face_to_face", "F_r": 4180.0, "C_r": 42000.0,
                         "e": 0.37, "Y": 1.60}, factors={"a23": 1.0})
    r = doc["results"]["pair"]
    assert_ref(r["F_aB"], 1870.0, 5.0, "[NTN] ex. 4 Fa2 = 0.5·Fr1/Y1 = 1.87 kN")
    assert_ref(doc["results"]["bearing_B"]["P"], 0.4 * 4180.0 + 1.60 * r["F_aB"], 1e-6,
               "[NTN] ex. 4 Pr2 = X·Fr2 + Y·Fa2 (the printed 4.66 kN follows Y = 1.60)")
    assert_ref(doc["results"]["bearing_B"]["P"], 4660.0, 5.0, "[NTN] ex. 4 Pr2 = 4.66 kN")
    assert_ref(doc["results"]["load"]["P"], 5980.0, 1e-9, "[NTN] ex. 4 Pr1 = Fr1")


@pytest.mark.parametrize("F_rA, F_rB, K_a, F_aA, F_aB", [
    # [SKF6000] table 4, p. 416, R = 0.88; K_a carried by B (cases 1a-1c)
    (5000.0, 3000.0, 1000.0, 0.88 * 5000.0, 0.88 * 5000.0 + 1000.0),      # 1a
    (3000.0, 5000.0, 2000.0, 0.88 * 3000.0, 0.88 * 3000.0 + 2000.0),      # 1b: K_a >= R·ΔF_r
    (3000.0, 5000.0, 1000.0, 0.88 * 5000.0 - 1000.0, 0.88 * 5000.0),      # 1c
])
def test_skf_table_4_cases(F_rA, F_rB, K_a, F_aA, F_aB):
    f = PR.solve(PR.induced_angular(F_rA, 40.0), PR.induced_angular(F_rB, 40.0), K_a)
    assert (f.F_aA, f.F_aB) == pytest.approx((F_aA, F_aB), rel=1e-12)


def test_angular_pair_through_the_catalogue():
    # two SKF 7208 BECBP back to back; K_a = 1 000 N from A towards B is carried by A
    doc = document("iso281_2007", {"designation": "7208 B"},
                   {"F_r": 3000.0, "F_a": 1000.0, "speed": 1500.0}, mode="pair",
                   pair={"arrangement": "back_to_back", "F_r": 5000.0})
    r = doc["results"]["pair"]
    assert r["K_a_carrier"] == "A"
    assert (r["F_aA"], r["F_aB"]) == pytest.approx((0.88 * 5000.0 + 1000.0, 0.88 * 5000.0))
    assert doc["results"]["load"]["X"] == 0.35 and doc["results"]["load"]["Y"] == 0.57


def test_skf_viscosity_chart_readings():
    n100 = OIL.nu100_from_vi(32.0, 95.0)
    assert OIL.viscosity_at(70.0, 32.0, n100) >= 11.0 * 0.95, "[SKF6000] p. 59 VG 32 at 70 °C"
    n100 = OIL.nu100_from_vi(200.0, 95.0)
    for t, nu in ((50.0, 120.0), (60.0, 75.0), (65.0, 60.0)):
        assert_ref(OIL.viscosity_at(t, 200.0, n100), nu, 0.05 * nu,
                   f"[SKF6000] p. 81 ex. 5/2 ν at {t:g} °C (chart: ±5 %)")


def test_astm_d2270_example():
    assert round(OIL.viscosity_index(22.83, 5.05)) == 156
    assert OIL.nu100_from_vi(22.83, 156.46) == pytest.approx(5.05, rel=1e-3)


def test_oil_grade_in_a_bearing_run():
    doc = document("iso281_2007", {"designation": "6208"}, {"F_r": 3000.0, "speed": 1500.0},
                   lubrication={"oil": "ISO VG 68", "temperature": 60.0,
                                "contamination": "normal"})
    life = doc["results"]["life"]
    assert life["oil"] == "VG 68" and life["nu40"] == 68.0 and life["VI"] == 95.0
    assert life["nu"] == pytest.approx(OIL.viscosity_at(60.0, 68.0, OIL.nu100_from_vi(68.0,
                                                                                        95.0)))
    assert life["kappa"] == pytest.approx(life["nu"] / life["nu1"])
    assert "lubrication.viscosity_index" in doc["assumed"]


def test_kappa_and_nu1_given():
    base = dict(bearing={"designation": "6208"}, load={"F_r": 3000.0, "speed": 1500.0})
    d1 = document("iso281_2007", base["bearing"], base["load"],
                  lubrication={"kappa": 2.0, "contamination": "normal"})
    assert d1["results"]["life"]["kappa"] == 2.0 and "nu1" not in d1["results"]["life"]
    d2 = document("iso281_2007", base["bearing"], base["load"],
                  lubrication={"viscosity": 30.0, "nu1": 15.0, "contamination": "normal"})
    assert d2["results"]["life"]["kappa"] == 2.0
    assert d1["results"]["life"]["a_ISO"] == pytest.approx(d2["results"]["life"]["a_ISO"])
