"""The material library's EN, AISI/SAE and cast rows against the values printed by their
sources (docs/references.md, "Material data sheets"), browsing them by name and equivalent,
and a spur pair of library EN case-hardening steels rated by GOST 21354-87 and ISO 6336.

Tolerance: the values are stored as printed (MPa), or converted from ksi and rounded to
1 MPa ([MetalMart]); the checks allow 0.5 MPa for that rounding only.
"""

import json
from pathlib import Path

import pytest

from geardesign.materials import gear_steel as G
from geardesign.materials import worm_wheel as W
from tests.helpers_cli import cli

KSI = 6.894757  # MPa per ksi
ROOT = Path(__file__).resolve().parent.parent


def _sigma_T(grade: str, treatment: str) -> list[tuple[float, float]]:
    return [(hb, v) for hb, t, v in G.library()["steel"][grade]["sigma_T"] if t == treatment]


@pytest.mark.parametrize("grade, treatment, table, source", [
    # [Saarstahl] C45: +QT 40 < d <= 100 mm Rp0.2 >= 370; +N 100 < d <= 250 mm >= 275 MPa
    ("C45", "improved", [(0.0, 370.0)], "Saarstahl"),
    ("C45", "normalized", [(0.0, 275.0)], "Saarstahl"),
    # [Lucefin] 16MnCr5 test blank 63 mm: Rp0.2 >= 440 MPa; 20MnCr5 63 mm: >= 540 MPa
    ("16MnCr5", "carburized", [(0.0, 440.0)], "Lucefin"),
    ("20MnCr5", "carburized", [(0.0, 540.0)], "Lucefin"),
    # [ShivamSteel] SAE 8620 core, carburised, 63 mm: yield >= 490 MPa
    ("8620", "carburized", [(0.0, 490.0)], "ShivamSteel"),
    # [MatWeb] AISI E9310 mock carburized, 13 mm round: yield 986 MPa
    ("9310", "carburized", [(0.0, 986.0)], "MatWeb"),
    # [MatWeb] 4340 annealed 470 MPa; [MetalMart] 4 in. round: 119 ksi at 269 BHN,
    # 159 ksi at 341 BHN
    ("4340", "improved", [(0.0, 470.0), (269.0, 119 * KSI), (341.0, 159 * KSI)], "MetalMart"),
    # [Markmet] 40KhL (GOST 977-88) quenched and tempered: σ0.2 >= 500 MPa
    ("40KhL", "improved", [(0.0, 500.0)], "Markmet"),
])
def test_rows_reproduce_their_source(grade, treatment, table, source):
    got = _sigma_T(grade, treatment)
    assert [hb for hb, _ in got] == [hb for hb, _ in table]
    assert [v for _, v in got] == pytest.approx([v for _, v in table], abs=0.5)
    assert f"[{source}]" in G.source_of(grade)


def test_rows_without_a_found_yield_strength_say_so():
    """18CrNiMo7-6 (core strength) and 34CrNiMo6 (+QT table) were not found in a located
    text: the rows carry none, say so, and a rating that needs σ_T asks for it."""
    for grade in ("18CrNiMo7-6", "34CrNiMo6"):
        assert G.library()["steel"][grade]["sigma_T"] == []
        assert "not found" in G.source_of(grade)
    m = {"grade": "34CrNiMo6", "treatment": "improved", "hardness_HB": 300.0,
         "hardness_HRC": None, "hardness_HV": None, "core_HRC": None, "blank": "forging",
         "root_ground": False}
    with pytest.raises(Exception) as exc:
        G.resolve(m, "material.pinion")
    assert "row of steel 34CrNiMo6 has no yield strength" in str(exc.value)
    # carburized: σ_HPmax = 44 HRC needs no σ_T, and the Ni flag gives σ_Flim 950, S_F 1.55
    c = G.resolve({**m, "grade": "18CrNiMo7-6", "treatment": "carburized", "hardness_HB": None,
                   "hardness_HRC": 60.0}, "material.pinion")
    assert (c.sigma_Flim, c.S_F, c.sigma_HPmax, c.sigma_T) == (950.0, 1.55, 44 * 60.0, None)
    assert c.grade == "18CrNiMo7-6" and "EN 10084" in c.source


def test_iso_material_types_come_from_the_rows():
    from geardesign.spur.strength.iso6336 import part5 as P5

    label = "{}, x, 1"
    assert P5.type_from_treatment("improved", label.format("40KhL")) == "V_cast_alloy"
    assert P5.type_from_treatment("improved", label.format("C45")) == "V"
    assert P5.type_from_treatment("carburized", label.format("18CrNiMo7-6")) == "Eh"
    assert P5.type_from_treatment("nitrided", label.format("31CrMo12")) == "NT"
    # GOST rows keep the rule by treatment
    assert P5.type_from_treatment("improved", label.format("40Kh")) == "V_alloy"
    assert P5.type_from_treatment("improved", label.format("45")) == "V"


def _rows(*args):
    code, out, err = cli("materials", *args, "--format", "json")
    assert code == 0, err
    return json.loads(out)


def test_browse_finds_the_new_rows():
    rows = _rows("18CrNiMo7-6")
    assert [(r["name"], r["treatment"], r["iso6336_5"]) for r in rows] == [
        ("18CrNiMo7-6", "carburized", "Eh")]
    assert rows[0]["sigma_Flim"] == "950"          # Ni-bearing carburized steel
    assert {r["name"] for r in _rows("4340")} == {"4340"}
    assert {r["name"] for r in _rows("AISI 4340")} == {"4340"}
    assert {r["name"] for r in _rows("1045")} == {"C45"}
    assert {r["name"] for r in _rows("1.6587")} == {"18CrNiMo7-6"}
    bronze = _rows("CuSn12")
    assert {r["name"] for r in bronze} == {"CuSn12-C-GZ", "CuSn12Ni2-C-GS", "CuSn12Ni2-C-GZ"}
    assert all("[EN1982]" in r["source"] for r in bronze)


@pytest.mark.parametrize("word, line", [
    ("18CrNiMo7", 'geardesign materials: no material matches "18CrNiMo7x" (did you mean '
                  '"18CrNiMo7-6"'),
    ("4304", 'geardesign materials: no material matches "4304x" (did you mean "4340"'),
])
def test_did_you_mean(word, line):
    code, out, err = cli("materials", word + "x")
    assert code == 2 and out == "" and err.startswith(line)


def test_equivalents_resolve_in_a_spec_material():
    m = {"grade": "AISI 4340", "treatment": "improved", "hardness_HB": 300.0,
         "hardness_HRC": None, "hardness_HV": None, "core_HRC": None, "blank": "forging",
         "root_ground": False}
    r = G.resolve(m, "material.wheel")
    assert r.grade == "4340" and r.sigma_T == pytest.approx(119 * KSI, abs=0.5)
    assert "read as 4340" in r.warnings[0]
    assert G.resolve({**m, "grade": "C45"}, "material.wheel").grade == "C45"


def test_worm_wheel_rows_reproduce_their_source():
    # [LooserBronze] CuSn12-C-GZ: Rp0.2 >= 150, Rm >= 280 MPa, v <= 20 m/s
    b = W.get("CuSn12-C-GZ")
    assert (b.group, b.sigma_T, b.sigma_B, b.v_s_max) == ("I", 150.0, 280.0, 20.0)
    # [Kemper] CuSn12Ni2-C-GS: Rm 280, Rp0.2 160 MPa; [BronzeTable] GZ: 300, 180 MPa
    assert (W.get("CuSn12Ni2-C-GS").sigma_B, W.get("CuSn12Ni2-C-GS").sigma_T) == (280.0, 160.0)
    assert (W.get("CuSn12Ni2-C-GZ").sigma_B, W.get("CuSn12Ni2-C-GZ").sigma_T) == (300.0, 180.0)
    # [FitscherGuss] CuZn25Al5Mn4Fe3-C GZ: Rm 750, Rp0.2 480 MPa
    z = W.get("CuZn25Al5Mn4Fe3-C-GZ")
    assert (z.group, z.sigma_B, z.sigma_T) == ("II", 750.0, 480.0)
    assert "[Kemper]" in W.get("CuSn12Ni2-C-GS").source
    assert "unverified" in W.get("SCh20").source


SPUR = """kind = "spur"
[gear]
module = 4.0
z1 = 21
z2 = 86
helix_angle = 12.0
face_width = 60.0
x1 = 0.3
accuracy_grade = 7
bearing_scheme = 5
[load]
speed1 = 1000.0
torque1 = 900.0
life_hours = 20000.0
[material.pinion]
grade = "18CrNiMo7-6"
treatment = "carburized"
hardness_HRC = 60.0
[material.wheel]
grade = "18CrNiMo7-6"
treatment = "carburized"
hardness_HRC = 58.0
"""


@pytest.mark.parametrize("options, sections", [
    ("", ("contact", "bending")),
    ('[options]\nmethod = "ISO 6336:2019"\n', ("iso6336_contact", "iso6336_materials")),
])
def test_spur_pair_of_18CrNiMo7_6_runs_by_both_methods(tmp_path, options, sections):
    spec = tmp_path / "s.toml"
    spec.write_text(SPUR + options, encoding="utf-8")
    code, out, err = cli("run", str(spec), "--format", "json")
    assert code in (0, 1), err
    doc = json.loads(out)
    for s in sections:
        assert s in doc["results"], list(doc["results"])
    mats = doc["results"]["materials" if "materials" in doc["results"] else "iso6336_materials"]
    assert mats["material1"].startswith("18CrNiMo7-6, carburized")
    assert mats["material1_source"].startswith("library row 18CrNiMo7-6: EN 10084")
    if "iso6336_materials" in doc["results"]:
        assert doc["results"]["iso6336_materials"]["type1"] == "Eh"


def test_unknown_grade_in_a_spec_gets_did_you_mean():
    m = {"grade": "18CrNiMo7", "treatment": "carburized", "hardness_HB": None,
         "hardness_HRC": 60.0, "hardness_HV": None, "core_HRC": None, "blank": "forging",
         "root_ground": False}
    with pytest.raises(Exception) as exc:
        G.resolve(m, "material.pinion")
    assert "did you mean '18CrNiMo7-6'" in str(exc.value)


def test_worm_report_names_the_wheel_row_and_its_source(tmp_path):
    text = (ROOT / "specs" / "worm_single_start_reducer.toml").read_text(encoding="utf-8")
    spec = tmp_path / "w.toml"
    spec.write_text(text.replace('"BrO10F1_chill"', '"CuSn12-C-GZ"'), encoding="utf-8")
    code, out, err = cli("run", str(spec), "--format", "json")
    assert code in (0, 1), err
    st = json.loads(out)["results"]["strength"]
    assert (st["material"], st["sigma_B"], st["sigma_T"]) == ("CuSn12-C-GZ", 280.0, 150.0)
    assert st["material_source"].startswith("library row CuSn12-C-GZ: [EN1982]")


def test_bearing_and_drive_reports_name_their_rows():
    code, out, _ = cli("run", str(ROOT / "specs" / "bearing_select_reducer.toml"),
                       "--format", "json")
    r = json.loads(out)["results"]
    assert r["bearing"]["data_source"] == "[SKF6000] p. 526"
    assert r["life"]["oil_source"] == "library row VG 150: [SKF6000] p. 59"
    code, out, _ = cli("run", str(ROOT / "specs" / "drive_two_stage_reducer.toml"),
                       "--format", "json")
    r = json.loads(out)["results"]
    assert all(b["source"].startswith("[SKF6000] p. ") for b in r["bearings"])
    mats = r["stage_reports"][0]["results"]["materials"]
    assert mats["material1_source"].startswith("library row 40Kh: ")


def test_cyrillic_cast_steel_name():
    assert G.normalize_grade("40ХЛ") == "40KhL"
    assert G.normalize_grade("40XL") == "40KhL"
