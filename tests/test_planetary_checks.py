"""Planetary design failures: the report is computed in full, the failed check says what
to change, and the exit code is 1 (a failed error check) or 0 (warnings only)."""

from __future__ import annotations

import json

from tests.helpers_cli import cli
from tests.test_planetary_inputs import MATERIAL, spec, to_toml

THREE_K = {
    "kind": "planetary",
    "train": {"scheme": "3K", "planets": 3, "module": 0.3, "face_width": 3.0,
              "working_angle": 21.525},
    "teeth": {"sun": 12, "planet": 46, "ring": 102, "ring2": 105},
    "shift": {"sun": 0.3038},
    "ring": {"tip_shortening": 0.2},
    "operation": {"fixed": "ring", "input": "sun", "output": "ring2", "speed": 3000.0},
    "efficiency": {"model": "given", "external": 0.98, "internal": 0.98},
}


def run(tmp_path, data):
    path = tmp_path / "s.toml"
    path.write_text(to_toml(data), encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert "Traceback" not in err
    doc = json.loads(out)
    return code, doc, {c["code"]: c for c in doc["checks"]}


def failed(checks: dict, severity: str = "error") -> list[str]:
    return [k for k, c in checks.items() if not c["passed"] and c["severity"] == severity]


def test_base_reducer_passes(tmp_path):
    code, doc, checks = run(tmp_path, spec(train__center_distance=68.0))
    assert code == 0 and doc["verdict"] == "pass"
    assert checks["PLANET_RING_COAXIALITY"]["passed"]


def test_coaxiality_violated(tmp_path):
    code, doc, checks = run(tmp_path, spec(shift={"ring": 0.5}))
    assert code == 1 and failed(checks) == ["PLANET_RING_COAXIALITY"]
    assert checks["PLANET_RING_COAXIALITY"]["message"] == (
        "the planet–ring mesh runs at a_w = 68.8979 mm, the sun–planet mesh at 67.5000 mm "
        "(Δ = +1.3979 mm): the gears are not coaxial; set shift.ring = 0.0000 (GOST 19274-73 "
        "sign) or give train.center_distance and let the shifts follow")
    assert "planet_ring" in doc["results"]          # the report is still complete


def test_coaxiality_advice_in_the_iso_sign(tmp_path):
    code, _, checks = run(tmp_path, spec(teeth__ring=-72, shift={"ring": 0.2}))
    assert code == 1
    assert "set shift.ring = -0.0000 (ISO 21771 sign)" in \
        checks["PLANET_RING_COAXIALITY"]["message"] or \
        "set shift.ring = 0.0000 (ISO 21771 sign)" in checks["PLANET_RING_COAXIALITY"]["message"]


def test_coaxiality_beyond_any_shift(tmp_path):
    code, _, checks = run(tmp_path, spec(teeth={"sun": 18, "planet": 27, "ring": 40}))
    assert code == 1
    assert checks["PLANET_RING_COAXIALITY"]["message"].endswith(
        "no reasonable ring shift makes them coaxial; change the tooth numbers (with equal "
        "modules the ring needs about z_sun + 2·z_planet teeth); no change of the planet "
        "teeth (±2) and the centre distance (±1.5·m) passes the failed geometry checks "
        "together")


def test_neighbour_clearance(tmp_path):
    code, _, checks = run(tmp_path, spec(train__planets=5))
    assert code == 1 and failed(checks) == ["NEIGHBOUR"]
    assert checks["NEIGHBOUR"]["message"] == (
        "the tips of neighbouring planets overlap (clearance -7.649 mm <= 0): use at most 4 "
        "planets, or a larger centre distance (more sun teeth) with smaller planets")


def test_neighbour_gap_warning(tmp_path):
    code, _, checks = run(tmp_path, spec(train__planets=4, train__spacing="uneven",
                                         limits={"neighbour_gap": 5.0}))
    assert code == 0
    assert failed(checks, "warning") == ["NEIGHBOUR_GAP", "SUN_PLANET_SPECIFIC_SLIDING"]
    assert checks["NEIGHBOUR_GAP"]["message"].startswith(
        "the gap between neighbouring planets is small: 6.779 mm < 5·m")


def test_assembly_impossible_and_uneven_spacing(tmp_path):
    code, doc, checks = run(tmp_path, spec(train__planets=4))
    assert code == 1 and failed(checks) == ["ASSEMBLY"]
    assert checks["ASSEMBLY"]["message"] == (
        "4 equally spaced planets cannot be assembled (N_sun = 90: each must be a multiple of "
        "4); change the ring to 70 teeth (and make the meshes coaxial with shifts, "
        "train.center_distance), or set train.spacing = \"uneven\" to place them at 0.00, "
        "88.00, 180.00, 272.00 deg")
    code, doc, checks = run(tmp_path, spec(train__planets=4, train__spacing="uneven"))
    assert code == 0 and checks["ASSEMBLY"]["severity"] == "info"
    assert doc["results"]["assembly"]["planet_angles"] == [0.0, 88.0, 180.0, 272.0]


def test_involute_interference_at_the_planet_root_by_the_ring_tip(tmp_path):
    code, _, checks = run(tmp_path, spec(ring__tip_shortening=0.0))
    assert code == 1 and failed(checks) == ["PLANET_RING_INTERFERENCE_PLANET"]
    assert checks["PLANET_RING_INTERFERENCE_PLANET"]["message"] == (
        "involute interference at the planet root (planet–ring): the ring tip works below the "
        "planet's form circle (ρ_p = 3.847 mm < ρ_l = 5.081 mm); shorten the ring tip "
        "(ring.tip_shortening += 0.108) or increase shift.planet")


def test_involute_interference_at_the_ring(tmp_path):
    code, _, checks = run(tmp_path, spec(train__center_distance=68.0, cutter={"teeth": 20}))
    assert code == 1 and failed(checks) == ["PLANET_RING_INTERFERENCE_RING"]
    assert "cut the ring with a shaper of more teeth" in \
        checks["PLANET_RING_INTERFERENCE_RING"]["message"]


def test_tip_interference_of_a_small_tooth_difference(tmp_path):
    code, _, checks = run(tmp_path, spec(teeth={"sun": 12, "planet": 30, "ring": 36},
                                         train__allow_undercut=True))
    assert code == 1 and "PLANET_RING_TIP_INTERFERENCE" in failed(checks)
    assert checks["PLANET_RING_TIP_INTERFERENCE"]["message"].startswith(
        "planet–ring: the tips of the planet and the ring interfere outside the line of action "
        "(trochoidal tip interference, δ = -0.1861 < 0)")


def test_cutting_interference(tmp_path):
    code, _, checks = run(tmp_path, spec(train__center_distance=68.0, cutter={"teeth": 68}))
    assert code == 1 and failed(checks) == ["PLANET_RING_CUTTING_INTERFERENCE"]
    assert checks["PLANET_RING_CUTTING_INTERFERENCE"]["message"] == (
        "planet–ring: the shaper cutter (z0 = 68) cuts into the ring tips (δ0 = -0.5254 < 0); "
        "use a cutter with fewer teeth (z0 well below 72) or shorten the ring tips")


def test_self_locking_warns_forbids_or_is_required(tmp_path):
    """3K train with η_h = 0.98 per mesh: η^h_eb = 0.98² = 0.9604 < z_b z_f/(z_g z_e)
    = 0.9714, the classic self-locking condition of the reverse drive."""
    code, doc, checks = run(tmp_path, THREE_K)
    assert code == 0 and doc["results"]["efficiency"]["self_locking"] is True
    assert checks["SELF_LOCKING"]["severity"] == "warning" and not checks["SELF_LOCKING"]["passed"]
    assert checks["SELF_LOCKING"]["message"].startswith(
        "the train is self-locking: the output cannot drive the input back")
    code, _, checks = run(tmp_path, {**THREE_K, "efficiency": {**THREE_K["efficiency"],
                                                                 "self_locking": "forbid"}})
    assert code == 1 and failed(checks) == ["SELF_LOCKING"]
    data = {**THREE_K, "efficiency": {"model": "given", "external": 0.99, "internal": 0.995,
                                      "self_locking": "require"}}
    code, _, checks = run(tmp_path, data)
    assert code == 1 and failed(checks) == ["SELF_LOCKING"]
    assert checks["SELF_LOCKING"]["message"].startswith("the train is not self-locking")


def test_near_self_locking_warning(tmp_path):
    data = {**THREE_K, "efficiency": {"model": "given", "external": 0.99, "internal": 0.987}}
    code, doc, checks = run(tmp_path, data)
    assert code == 0
    assert not checks["NEAR_SELF_LOCKING"]["passed"]
    assert 0.0 < doc["results"]["efficiency"]["eta_reverse"] < 0.1


def test_contact_and_bending_fatigue_below_minimum(tmp_path):
    data = spec(train__center_distance=68.0, operation__torque=2500.0,
                strength={"life_hours": 20000.0}, material=MATERIAL)
    code, doc, checks = run(tmp_path, data)
    assert code == 1
    bad = failed(checks)
    assert "SUN_PLANET_CONTACT_FATIGUE" in bad and "SUN_PLANET_BENDING_FATIGUE_PLANET" in bad
    msg = checks["SUN_PLANET_CONTACT_FATIGUE"]["message"]
    assert msg.startswith("sun–planet: contact stress σ_H = ") and "harder sun material" in msg
    # the train scaled to a standard module replaces the words "increase the centre
    # distance by …" when it passes (found by re-rating)
    assert "increase the centre distance by" in msg or "set train.module = " in msg
    assert "planet root stress" in checks["SUN_PLANET_BENDING_FATIGUE_PLANET"]["message"]
    assert doc["results"]["strength_sun_planet"]["Y_A2"] < 1.0   # planet loaded both ways
    assert doc["results"]["strength_sun_planet"]["Y_A1"] == 1.0


def test_forward_drive_impossible(tmp_path):
    """The self-locking 3K train of the test above driven from the output ring: the sun
    cannot be driven."""
    data = {**THREE_K, "operation": {**THREE_K["operation"], "input": "ring2",
                                     "output": "sun", "speed": 10.0}}
    code, doc, checks = run(tmp_path, data)
    assert code == 1 and failed(checks) == ["FORWARD_DRIVE"]
    assert checks["FORWARD_DRIVE"]["message"].startswith(
        "the input cannot drive the output (efficiency -")
    assert checks["SELF_LOCKING"]["passed"]          # the sun drives the ring back


def test_real_process_json_and_no_heavy_imports():
    """A cold process: JSON on stdout only, and no scipy imported (the synthesis enumerates
    its tooth sets with numpy; an analysis spec imports neither, below)."""
    import subprocess
    import sys

    from tests.conftest import SPECS

    code = ("import sys, json; from pathlib import Path; from geardesign.core.registry import run;"
            f"run(Path({str(SPECS / 'planetary_synthesis_3k.toml')!r})).document();"
            "print(json.dumps(sorted(m for m in ('numpy', 'scipy') if m in sys.modules)))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout) == ["numpy"]
    code = code.replace("planetary_synthesis_3k", "planetary_2kh_reducer")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert json.loads(out.stdout) == []


def test_template_is_a_valid_passing_spec(tmp_path):
    code, text, _ = cli("template", "planetary")
    assert code == 0 and text.startswith("# geardesign planetary spec")
    path = tmp_path / "t.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = cli("run", path, "--format", "json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["verdict"] == "pass" and "strength_planet_ring" in doc["results"]
    code, out, _ = cli("list")
    assert "planetary" in out


def test_one_planet_has_no_neighbour():
    """A train with one planet has no neighbouring planet: NEIGHBOUR passes, no clearance
    row (2·a_w·sin(180°) − d_a would be the planet's own tip diameter, negative)."""
    import tomllib

    from geardesign.core.registry import run_data
    from tests.conftest import SPECS

    data = tomllib.loads((SPECS / "planetary_2kh_reducer.toml").read_text(encoding="utf-8"))
    data["train"]["planets"] = 1
    doc = run_data(data).document()
    codes = {c["code"]: c for c in doc["checks"]}
    assert codes["NEIGHBOUR"]["passed"] and "one planet" in codes["NEIGHBOUR"]["message"]
    assert "NEIGHBOUR_GAP" not in codes
    assert "neighbour_clearance" not in doc["results"]["assembly"]
