"""Sweeps and design mode a designer would accept: the face width ratio bounded on both
sides (one rule for the spur check and the sweep), the sweep's ψ_bd/ψ_ba windows, a note
when the first variant sits on a range's boundary, design mode naming itself the handbook's
first estimate, and templates that are clean examples.  Each runs the command a user types."""

from __future__ import annotations

import json

import pytest

from geardesign.core.registry import known_kinds
from geardesign.spur.checks import PSI_BA_WINDOW, PSI_BD_MAX, PSI_BD_MIN, face_width_ratio_ok
from tests.conftest import SPECS
from tests.helpers_cli import cli, write_spec

PAIR = (SPECS / "sweep_spur_reducer.toml").read_text(encoding="utf-8").split("[sweep]")[0]

PANCAKE = PAIR + """[sweep]
"gear.module" = {values = [3.0, 4.0, 5.0, 6.0, 8.0]}
"gear.z1" = {from = 18, to = 30, step = 4}
"gear.z2" = {from = 72, to = 120, step = 12}
"gear.face_width" = {from = 20.0, to = 200.0, step = 5.0}
ratio = [3.9, 4.1]
top = 20
"""


def _sweep(path, *args):
    code, out, err = cli("sweep", path, *args, "--format", "json")
    assert "Traceback" not in err
    return code, (json.loads(out) if out else None), err


def _checks(doc) -> dict:
    return {c["code"]: c for c in doc["checks"]}


def test_the_rule_has_two_sides():
    assert face_width_ratio_ok(0.5) and not face_width_ratio_ok(0.1)
    assert not face_width_ratio_ok(1.7)
    assert face_width_ratio_ok(PSI_BD_MIN) and face_width_ratio_ok(PSI_BD_MAX)


def test_a_narrow_wheel_is_a_face_width_warning(tmp_path):
    text = (SPECS / "spur_reducer_through_hardened.toml").read_text(encoding="utf-8")
    spec = write_spec(tmp_path, text.replace("face_width = 63.0", "face_width = 12.0"))
    code, out, err = cli("run", spec, "--format", "json")
    assert "Traceback" not in err
    check = _checks(json.loads(out))["FACE_WIDTH_RATIO"]
    assert not check["passed"] and check["severity"] == "warning"
    assert "< 0.2" in check["message"] and "narrow wheel" in check["message"]
    assert check["limit"] == PSI_BD_MIN


def test_the_sweep_keeps_to_the_proportions_of_the_standard(tmp_path):
    """The lightest variant of a wide face-width range is no pancake: every ranked variant
    lies inside the default ψ_bd and ψ_ba windows, and its emitted spec passes the spur
    check of the same rule."""
    spec = write_spec(tmp_path, PANCAKE)
    code, doc, err = _sweep(spec)
    assert code == 0, err
    ranked = doc["results"]["ranked"]
    assert ranked
    for r in ranked:
        assert PSI_BD_MIN <= r["psi_bd"] <= PSI_BD_MAX
        assert PSI_BA_WINDOW[0] <= r["b_w"] / r["a_w"] <= PSI_BA_WINDOW[1]
    assert doc["results"]["rejections"]["FACE_WIDTH_RATIO"] > 0
    assert doc["inputs"]["psi_bd"] == [PSI_BD_MIN, PSI_BD_MAX]
    code, text, err = cli("sweep", spec, "--emit-spec", "1")
    assert code == 0, err
    best = write_spec(tmp_path, text, "best.toml")
    code, out, err = cli("run", best, "--format", "json")
    assert _checks(json.loads(out))["FACE_WIDTH_RATIO"]["passed"]


@pytest.mark.parametrize("window,pancake", [("", False),
                                            ("psi_bd = [0.05, 1.6]\npsi_ba = [0.01, 1.25]\n",
                                             True)])
def test_the_narrowest_face_keeps_to_the_window(tmp_path, window, pancake):
    """Ranked by face width, the narrowest passing face is a pancake unless the window
    (default: the standard's) keeps it out."""
    text = PANCAKE.replace("top = 20", 'top = 20\nobjectives = ["face_width", "mass"]')
    code, doc, err = _sweep(write_spec(tmp_path, text + window))
    assert code == 0, err
    first = doc["results"]["ranked"][0]
    assert (first["psi_bd"] < PSI_BD_MIN) is pancake


@pytest.mark.parametrize("value", ["[0.3, 0.2]", "[0.0, 1.0]", "0.2", "[0.2, \"a\"]"])
def test_a_bad_window_is_one_line(tmp_path, value):
    spec = write_spec(tmp_path, PANCAKE + f"psi_bd = {value}\n")
    code, doc, err = _sweep(spec)
    assert code == 2 and doc is None
    assert err.count("\n") == 1 and "sweep.psi_bd" in err and "b_w/d_w1" in err


def test_the_first_variant_on_a_range_boundary_is_named(tmp_path):
    spec = write_spec(tmp_path, PAIR + """[sweep]
"gear.module" = {values = [2.0, 2.5, 3.0]}
"gear.z1" = {from = 22, to = 30, step = 4}
"gear.z2" = {from = 90, to = 120, step = 6}
"gear.helix_angle" = {values = [0.0, 15.0]}
"gear.face_width" = {from = 40.0, to = 60.0, step = 10.0}
ratio = [3.9, 4.1]
""")
    code, doc, err = _sweep(spec)
    assert code == 0, err
    first = doc["results"]["ranked"][0]
    assert first["helix_angle"] == pytest.approx(15.0)
    edge = _checks(doc)["SWEEP_RANGE_EDGE"]
    assert edge["severity"] == "warning" and not edge["passed"]
    assert "gear.helix_angle = 15 at the top of 0 … 15" in edge["message"]
    code, text, _ = cli("sweep", spec, "--format", "table")
    assert "SWEEP_RANGE_EDGE" in text


def test_design_mode_says_it_is_the_first_estimate_and_points_to_the_sweep():
    code, text, err = cli("run", SPECS / "spur_design.toml", "--format", "table")
    assert code == 0, err
    assert "DESIGN_FIRST_ESTIMATE" in text
    flat = " ".join(text.split())
    assert "handbook's first estimate" in flat and "geardesign sweep" in flat
    doc = json.loads(cli("run", SPECS / "spur_design.toml", "--format", "json")[1])
    note = _checks(doc)["DESIGN_FIRST_ESTIMATE"]
    assert note["severity"] == "info" and note["passed"]
    assert note["value"] == doc["results"]["design"]["a_w_proposed"]


def test_the_drive_template_computes_the_drive_its_title_names(tmp_path):
    code, text, _ = cli("template", "drive")
    assert "1455/58" in text
    spec = write_spec(tmp_path, text)
    code, out, err = cli("run", spec, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert len(doc["results"]["stages"]) == 2
    assert doc["results"]["drive"]["n_out"] == pytest.approx(58.0, rel=0.04)
    assert _checks(doc)["OUTPUT_SPEED"]["passed"]


def test_a_wanted_overall_ratio_is_checked(tmp_path):
    text = cli("template", "drive")[1].replace("[split]", "[split]\nratio = 20.0")
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code == 1, err
    check = _checks(json.loads(out))["OVERALL_RATIO"]
    assert not check["passed"] and "split.ratio = 20" in check["message"]


def _warnings(doc: dict) -> list[str]:
    out = [c["code"] for c in doc["checks"] if not c["passed"] and c["severity"] != "info"]
    for value in doc["results"].values():
        if isinstance(value, list):
            for item in value:
                if isinstance(item, dict) and "checks" in item:
                    out += _warnings(item)
    return out


@pytest.mark.parametrize("kind", known_kinds())
def test_every_template_is_a_clean_example(tmp_path, kind):
    """Every template is a clean example: its second line says what it shows, and it runs
    without a failed check or warning (published cases with their warnings are in specs/).
    The one warning a template keeps is ``METHOD_UNVERIFIED``: a calculator whose numbers are
    not yet all checked against a published example says so in every result (docs/bevel.md)."""
    code, text, err = cli("template", kind)
    assert code == 0 and err == ""
    assert "# This example: " in text.split("\n", 3)[1]
    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code == 0, err
    assert [w for w in _warnings(json.loads(out)) if w != "METHOD_UNVERIFIED"] == []
