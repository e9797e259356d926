"""geardesign bearings / geardesign materials, equivalent grade names in a material table,
the rib capacity of NJ/NUP bearings ([SKF6000] p. 518)."""

import json

import pytest

from geardesign.bearing import rib as RB
from geardesign.materials import gear_steel as G
from tests.helpers_cli import cli
from tests.reference.bearing._util import document


def test_bearings_by_bore_and_type_as_json():
    code, out, err = cli("bearings", "--bore", "40", "--type", "cylindrical_roller",
                         "--format", "json")
    rows = json.loads(out)
    assert code == 0 and err == ""
    assert {r["designation"] for r in rows} >= {"NU 208", "NJ 208", "NUP 208", "NU 2308"}
    nu208 = next(r for r in rows if r["designation"] == "NU 208")
    assert nu208["C_r"] == 62000.0 and nu208["source"] == "[SKF6000] p. 526"


@pytest.mark.parametrize("fmt", ["table", "csv", "markdown", "jsonl"])
def test_bearings_in_every_format(fmt):
    code, out, _ = cli("bearings", "7208", "--format", fmt)
    assert code == 0 and "30208" in out and "7208 B" in out


@pytest.mark.parametrize("args, line", [
    (("bearings", "NU280"),
     'geardesign bearings: no bearing matches "NU280" (did you mean "NU 208", "NU 328", '
     '"NU 320"?)'),
    (("bearings", "--type", "tapered_roler"),
     'geardesign bearings: --type "tapered_roler" is not a bearing type (did you mean '
     '"tapered_roller", "spherical_roller"?); types: deep_groove_ball, angular_contact_ball, '
     'cylindrical_roller, tapered_roller, spherical_roller, thrust_ball'),
    (("materials", "42CrMo5"),
     'geardesign materials: no material matches "42CrMo5" (did you mean "42CrMo4", '
     '"34CrAlMo5-10", "34CrNiMo6"?)'),
    (("bearings", "62", "--format", "xml"),
     'geardesign: --format "xml" is not one of table, json, jsonl, csv, markdown'),
])
def test_unknown_names_get_did_you_mean(args, line):
    code, out, err = cli(*args)
    assert code == 2 and out == "" and err.strip() == line


def test_materials_find_equivalents_and_oils():
    code, out, _ = cli("materials", "4140", "--format", "json")
    rows = json.loads(out)
    assert code == 0 and {r["name"] for r in rows} == {"42CrMo4"}
    assert rows[0]["iso6336_5"] in ("V_alloy", "IF") and "kooz.si" in rows[0]["source"]
    code, out, _ = cli("materials", "VG 220", "--format", "json")
    oil = json.loads(out)[0]
    assert oil["nu40"] == 220.0 and oil["source"] == "[SKF6000] p. 59"
    code, out, _ = cli("materials", "--family", "worm_wheel", "--format", "json")
    assert code == 0 and all(r["family"] == "worm_wheel" for r in json.loads(out))


def _steel(grade, treatment="improved", **kw):
    m = {"grade": grade, "treatment": treatment, "hardness_HB": 280.0, "hardness_HRC": None,
         "hardness_HV": None, "core_HRC": None, "blank": "forging", "root_ground": False}
    m.update(kw)
    return G.resolve(m, "material.pinion")


def test_equivalent_names_resolve_with_a_note():
    m = _steel("AISI 4140")
    assert m.label.startswith("42CrMo4") and m.sigma_T == 500.0
    assert "read as 42CrMo4" in m.warnings[0]
    m = _steel("C45")   # a grade of its own (EN 10083-2), no longer read as GOST 45
    assert m.label.startswith("C45") and m.sigma_T == 370.0 and not m.warnings
    m = _steel("AISI 1045")
    assert m.label.startswith("C45") and "read as C45" in m.warnings[0]
    assert m.sigma_Hlim == 2 * 280.0 + 70.0
    assert _steel("45").sigma_T == 650.0 and not _steel("45").warnings
    assert _steel("40Kh").label.startswith("40Kh") and not _steel("40Kh").warnings


def test_through_hardened_yield_strength_is_flagged():
    m = _steel("40Kh", "through_hardened", hardness_HB=None, hardness_HRC=45.0)
    assert m.sigma_T == 785.0
    assert any("far below the yield strength at 45 HRC" in w for w in m.warnings)
    m = _steel("40Kh", "through_hardened", hardness_HB=None, hardness_HRC=45.0,
               sigma_T=1200.0)
    assert m.sigma_T == 1200.0 and not m.warnings


def test_rib_capacity_formula():
    # [SKF6000] p. 518 with NJ 208 (C0 = 53 kN), Fr = 5 kN, n = 1 500 min^-1, oil:
    # F_ap = 1.5·53·10^4/(1500·120) − 0.15·5 = 3.667 kN; F_a,max = 0.0045·80^1.5 = 3.220 kN
    r = RB.rib_capacity(53000.0, 5000.0, 1500.0, 40.0, 80.0, "2")
    assert r.F_ap == pytest.approx(3666.67, abs=0.01)
    assert r.F_a_max == pytest.approx(3219.94, abs=0.01)
    g = RB.rib_capacity(53000.0, 5000.0, 1500.0, 40.0, 80.0, "2", "grease")
    assert g.F_ap == pytest.approx(1e4 * 53.0 / (1500.0 * 120.0) * 1000.0 - 500.0)
    assert RB.rib_capacity(53000.0, 5000.0, 1500.0, 40.0, 90.0, "3").F_a_max == \
        pytest.approx(0.0023 * 90.0 ** 1.7 * 1000.0)


@pytest.mark.parametrize("des, F_a, ok", [("NJ 208", 3000.0, True), ("NJ 208", 4000.0, False),
                                          ("NUP 208", 3000.0, True), ("NU 208", 500.0, False)])
def test_axial_capacity_check(des, F_a, ok):
    doc = document("iso281_2007", {"designation": des}, {"F_r": 5000.0, "F_a": F_a,
                                                          "speed": 1500.0})
    c = next(c for c in doc["checks"] if c["code"] == "AXIAL_CAPACITY")
    assert c["passed"] is ok and c["severity"] == "error"
    assert doc["verdict"] == ("pass" if ok else "fail")
