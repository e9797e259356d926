"""ISO 6336 through the drive: ``[load] method`` reaches the spur and planetary stages that
name none, a stage's own choice wins, the mesh forces (shafts, bearings) do not depend on
the method, and the worst margin is taken over every method a stage was rated by."""

from __future__ import annotations

import copy
from pathlib import Path

from geardesign.core.registry import run_data
from tests.helpers_cli import run_bad
from tests.test_iso6336_inputs import DATA

ROOT = Path(__file__).resolve().parent.parent

DRIVE = {
    "kind": "drive",
    "motor": {"power": 5.5, "speed": 1450.0},
    "load": {"life_hours": 20000.0, "method": "ISO 6336:2019"},
    "stage": [{"kind": "spur", "gear": DATA["gear"], "material": DATA["material"]}],
}


def _drive(**load) -> dict:
    d = copy.deepcopy(DRIVE)
    d["load"].update(load)
    return d


def test_forces_do_not_depend_on_the_method():
    gost = copy.deepcopy(DATA)
    gost["options"] = {"method": "GOST 21354-87"}
    a = run_data(gost).document()["results"]["forces"]
    b = run_data(copy.deepcopy(DATA)).document()["results"]["forces"]
    assert a == b


def test_margins_of_both_methods_are_kept_apart():
    data = copy.deepcopy(DATA)
    data["options"] = {"methods": ["GOST 21354-87", "ISO 6336:2019"]}
    r = run_data(copy.deepcopy(data)).document()["results"]
    from geardesign.spur.inputs import from_tables
    from geardesign.spur.solve import solve

    m = solve(from_tables(**{k: v for k, v in data.items() if k != "kind"})).margins()
    assert set(m) == {"S_H1", "S_H2", "S_F1", "S_F2", "ISO S_H1", "ISO S_H2", "ISO S_F1",
                      "ISO S_F2"}
    assert m["S_H1"] == r["contact"]["S_H1"] / r["contact"]["S_H1_min"]
    assert m["ISO S_F2"] == r["iso6336_bending"]["S_F2"] / r["iso6336_bending"]["S_Fmin"]


def test_drive_method_reaches_a_stage_that_names_none():
    doc = run_data(_drive()).document()
    stage = doc["results"]["stage_reports"][0]
    assert stage["methods"][-1] == "ISO 6336:2019"
    assert "GOST 21354-87" not in stage["methods"]
    assert doc["results"]["stages"][0]["margin_of"].startswith("ISO S_")


def test_a_stage_keeps_its_own_method():
    d = _drive()
    d["stage"][0]["options"] = {"method": "GOST 21354-87"}
    doc = run_data(d).document()
    assert doc["results"]["stage_reports"][0]["methods"][-1] == "GOST 21354-87"
    assert not doc["results"]["stages"][0]["margin_of"].startswith("ISO")


def test_drive_method_domain(tmp_path):
    spec = (ROOT / "specs" / "drive_two_stage_reducer.toml").read_text(encoding="utf-8")
    spec = spec.replace("[load]\n", '[load]\nmethod = "ISO 6336"\n', 1)
    lines = run_bad(tmp_path, spec)
    assert len(lines) == 1 and lines[0].startswith('s.toml: load.method = "ISO 6336": must be ')
    assert "ISO 6336:2019" in lines[0] and "GOST 21354-87" in lines[0]


def test_drive_regime_reaches_only_the_gost_stages(tmp_path):
    """The drive's GOST 21354-87 regime is not written into a planetary or spur stage rated
    by ISO 6336 alone (whose spec refuses a regime it does not read); a GOST stage still
    gets it."""
    import shutil

    from geardesign.core.registry import run

    text = (ROOT / "specs" / "drive_planetary_spur_iso.toml").read_text(encoding="utf-8")
    shutil.copy(ROOT / "specs" / "planetary_2kh_reducer.toml", tmp_path)
    for method, regime in (("ISO 6336:2019", None), ("GOST 21354-87", "III")):
        path = tmp_path / "drive.toml"
        path.write_text(text.replace('method = "ISO 6336:2019"\n',
                                     f'method = "{method}"\nregime = "III"\n', 1),
                        encoding="utf-8")
        stages = run(path).document()["results"]["stage_reports"]
        assert stages[0]["inputs"]["strength"].get("regime") == regime
        assert stages[0]["methods"][-1] == method
        assert stages[1]["kind"] == "spur"          # the spur stage likewise
        assert stages[1]["inputs"]["load"].get("regime") == regime
