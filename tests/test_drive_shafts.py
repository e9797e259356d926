"""The drive with analysed shafts: steps, keys and fits on the shafts of a drive
(geardesign.drive.shaft_analysis), the mesh misalignment from the shafts' slopes and the
K_Hβ it gives, and the input rules."""

from __future__ import annotations

import copy
import math
import subprocess
import sys

import pytest

from geardesign.core.errors import InputError
from geardesign.core.registry import run_data
from geardesign.core.spec import load_toml
from geardesign.shaft.solve import Load, Material, Step, Support, analyse
from tests.conftest import SPECS

GOLDEN = SPECS / "drive_reducer_shafts_keys_thermal.toml"


def _data() -> dict:
    return load_toml(GOLDEN)


def _fast() -> dict:
    """The golden's drive without the heat balance, both stages rated to GOST: three
    analysed shafts, four keys and a fit."""
    d = _data()
    d.pop("lubrication")
    d.pop("thermal")
    d["stage"][0].pop("options")
    d["stage"][0].pop("iso")
    sh = d["shaft"][2]
    sh.pop("method")
    sh.pop("lubrication")
    return d


@pytest.fixture(scope="module")
def golden():
    return run_data(_data()).document()


def test_the_shaft_loads_equal_the_standalone_shaft_calculator(golden):
    """Intermediate shaft: the loads built here from the stage reports' mesh forces
    (geardesign.drive.shafts docstring: radial towards the axis, tangential against the
    rotation on the driving gear, with it on the driven one; the axial force's couple
    F_a·r) give the standalone shaft calculator the same reactions, deflections and
    safeties as the drive's nested shaft report."""
    d = _data()
    sh = d["shaft"][1]
    res = golden["results"]
    f1 = res["stage_reports"][0]["results"]
    f2 = res["stage_reports"][1]["results"]
    start = sh["start"]
    rot = -1                                   # shaft 2: one external mesh from the motor
    loads = []
    for gear, F, r, driving, T in (
            (sh["gear"][0], f1["forces"], f1["geometry"]["d_w2"] / 2, False,
             res["stages"][0]["T_out"]),
            (sh["gear"][1], f2["forces"], f2["geometry"]["d_w1"] / 2, True,
             -res["stages"][1]["T_in"])):
        th = math.radians(gear["mate_angle"])
        e, t = (math.cos(th), math.sin(th)), (-math.sin(th), math.cos(th))
        s = -rot if driving else rot
        fx = -F["F_r"] * e[0] + s * F["F_t"] * t[0]
        fy = -F["F_r"] * e[1] + s * F["F_t"] * t[1]
        fz = gear.get("axial_sign", 1) * F["F_a"]
        loads.append(Load(gear["position"] - start, Fy=fx, Fz=fy, Fx=fz, torque=T,
                          moment_y=-r * e[0] * fz / 1e3, moment_z=-r * e[1] * fz / 1e3))
    x = 0.0
    steps = []
    for st in sh["step"]:
        steps.append(Step(st["length"], st["diameter"]))
        x += st["length"]
    supports = [Support(0.0 - start, axial=True), Support(sh["bearing_b"] - start)]
    r = analyse(steps, loads, supports, Material(600, 350, 250, 150, 0.1, 0.05))
    nested = res["shaft_reports"][1]["results"]
    for mine, theirs in zip(r.supports, nested["supports"]):
        assert mine.R_y == pytest.approx(theirs["R_y"], rel=1e-9, abs=1e-6)
        assert mine.R_z == pytest.approx(theirs["R_z"], rel=1e-9, abs=1e-6)
        assert abs(mine.R_x) == pytest.approx(abs(theirs["R_x"]), rel=1e-9, abs=1e-9)
        assert mine.slope / (math.pi / 180 / 60) == pytest.approx(theirs["slope"], rel=1e-9)
    for mine, theirs in zip(r.loads, nested["loads"]):
        assert mine.w == pytest.approx(theirs["w"], rel=1e-9)
    # ... and the bearing loads of the drive's own statics are the same reactions
    rows = [b for b in res["bearings"] if b["shaft"] == 2]
    for row, theirs in zip(rows, nested["supports"]):
        assert row["F_r"] == pytest.approx(theirs["R"], rel=1e-9)
    # the torque between the gears is the torque through the shaft
    assert max(abs(v) for v in nested["diagrams"]["T"]) == pytest.approx(
        res["stages"][1]["T_in"], rel=1e-12)


def test_summary_tables_and_nested_reports(golden):
    res = golden["results"]
    assert [r["shaft"] for r in res["shafts"]] == [1, 2, 3]
    assert len(res["shaft_reports"]) == 3 and len(res["connection_reports"]) == 5
    assert [r["type"] for r in res["connections"]] == ["key", "key", "key", "fit", "key"]
    # the coupling key of the input shaft carries the motor side torque, the output's the
    # machine's torque, with the drive's application factor
    c = res["connections"]
    assert c[0]["T"] == pytest.approx(res["stages"][0]["T_in"])
    assert c[4]["T"] == pytest.approx(1100.0) and c[4]["K_A"] == 1.25
    rep = res["connection_reports"][4]
    assert rep["inputs"]["load"]["torque"] == pytest.approx(1100.0)
    assert rep["inputs"]["key"]["shaft_diameter"] == 55.0
    codes = {ch["code"] for ch in golden["checks"]}
    assert {"SHAFT_1", "SHAFT_2", "SHAFT_3", "CONNECTION_3_1", "CONNECTION_3_2"} <= codes
    for row in res["shafts"]:
        assert row["S"] > 0 and row["n_cr"] > 0 and row["slope_A"] >= 0
    assert "thermal" in res and res["face_load"]


def test_face_load_factor_from_the_shafts_is_at_least_one(golden):
    rows = golden["results"]["face_load"]
    assert [r["method"] for r in rows] == ["ISO 6336:2019", "GOST 21354-87"]
    for r in rows:
        assert r["f_sh"] > 0 and r["K_Hbeta_shafts"] >= 1.0 and r["K_Hbeta_before"] >= 1.0
    # the ISO stage is rated with it: its report carries f_sh and that K_Hβ
    iso = golden["results"]["stage_reports"][0]["results"]["iso6336_factors"]
    assert iso["f_sh"] == pytest.approx(rows[0]["f_sh"])
    assert iso["K_Hbeta"] == pytest.approx(rows[0]["K_Hbeta_shafts"])
    # the GOST stage keeps its chart value
    gost = golden["results"]["stage_reports"][1]["results"]["factors"]
    assert gost["K_Hbeta"] == pytest.approx(rows[1]["K_Hbeta_before"])


def _thinner(d: dict, factor: float) -> dict:
    """The intermediate shaft's steps between the bearing seats scaled by ``factor``."""
    d = copy.deepcopy(d)
    for st in d["shaft"][1]["step"][1:-1]:
        st["diameter"] *= factor
    return d


def test_face_load_factor_grows_when_a_shaft_is_made_thinner():
    base = run_data(_fast()).document()["results"]["face_load"]
    thin = run_data(_thinner(_fast(), 0.8)).document()["results"]["face_load"]
    for a, b in zip(base, thin):
        assert b["f_sh"] > a["f_sh"]
        assert b["K_Hbeta_shafts"] > a["K_Hbeta_shafts"] >= 1.0
        assert b["K_Hbeta_before"] == pytest.approx(a["K_Hbeta_before"])   # the chart


def test_misalignment_is_the_relative_slope_along_the_line_of_action():
    """f_sh = |(θ_pinion − θ_wheel)·n|·b with n the direction of the mesh force."""
    doc = run_data(_fast()).document()
    res = doc["results"]
    arcmin = math.pi / 180 / 60
    g = {(r["shaft"], r["stage"]): r for r in res["shaft_gears"]}
    f = res["stage_reports"][1]["results"]
    p, w = g[(2, 2)], g[(3, 2)]
    # shaft 2 turns backwards (rotation −1); its pinion drives: the force on it is
    # −F_r·e + F_t·t with e = (1, 0) (mate_angle 0), t = (0, 1)
    n = (-f["forces"]["F_r"], f["forces"]["F_t"])
    norm = math.hypot(*n)
    d = ((p["slope_x"] - w["slope_x"]) * n[0] + (p["slope_y"] - w["slope_y"]) * n[1]) / norm
    row = next(r for r in res["face_load"] if r["stage"] == 2)
    assert row["f_bend"] == pytest.approx(d * arcmin * 80.0 * 1e3, rel=1e-9)
    assert row["f_sh"] == pytest.approx(abs(row["f_bend"] + row["f_twist"]), rel=1e-12)


def test_twist_of_the_gears_by_hand():
    """Stage 2: its pinion sits on shaft 2 right of the stage-1 wheel, so the torque T_in
    enters the pinion's face from −z and leaves through the teeth: the flanks close up at
    the −z end by r_b1·T·b/(2·G·J_1).  Its wheel sits on shaft 3 left of the output
    coupling: the torque enters through the teeth and leaves at +z, the flanks close up at
    the +z end by r_b2·T_out·b/(2·G·J_2) (Saint-Venant torsion, [Roark] table 10.1 case 1;
    J = π·d_w⁴/32, G = E/2.6)."""
    res = run_data(_fast()).document()["results"]
    geo = res["stage_reports"][1]["results"]["geometry"]
    st = res["stages"][1]
    G = 2.06e5 / 2.6
    b = 80.0
    cos_a = math.cos(math.radians(geo["alpha_tw"]))

    def tw(T, d):
        return (d / 2 * cos_a) * T * 1e3 * b / (2 * G * math.pi * d ** 4 / 32) * 1e3

    want = tw(st["T_in"], geo["d_w1"]) - tw(st["T_out"], geo["d_w2"])
    row = next(r for r in res["face_load"] if r["stage"] == 2)
    assert row["f_twist"] == pytest.approx(want, rel=1e-6)
    assert row["f_twist"] > 0


@pytest.mark.parametrize("T_L, T_R, want", [
    (1000.0, 0.0, 0.5),        # torque enters at −z, all taken off by the teeth
    (0.0, -1000.0, -0.5),      # the same from +z: the mirror image
    (1000.0, 500.0, 0.75),     # half goes on through the body to a gear beyond
    (-1000.0, 0.0, 0.5),       # the other sense of rotation: the same separation
    (0.0, 1000.0, -0.5),       # a driven gear whose torque leaves at +z
])
def test_face_twist_closed_forms(T_L, T_R, want):
    """δ = −sgn(T_g)·r_b·(T_L + T_R)/2·b/(G·J), in units of r_b·T·b/(G·J)."""
    from geardesign.drive.misalignment import face_twist
    G, J = 2.06e5 / 2.6, math.pi * 60.0 ** 4 / 32
    unit = 28.0 * 1000.0e3 * 60.0 / (G * J) * 1e3
    assert face_twist(T_L, T_R, 60.0, 60.0, 28.0, 2.06e5) == pytest.approx(want * unit,
                                                                          rel=1e-12)
    assert face_twist(500.0, 500.0, 60.0, 60.0, 28.0, 2.06e5) == 0.0   # no gear torque


def test_without_the_new_tables_nothing_changes():
    d = _fast()
    for sh in d["shaft"]:
        for k in ("step", "material", "key", "start", "coupling"):
            sh.pop(k, None)
    doc = run_data(d).document()
    for k in ("shafts", "shaft_gears", "connections", "face_load", "shaft_reports"):
        assert k not in doc["results"]


# ------------------------------------------------------------------ input rules


def _problem(d: dict) -> str:
    with pytest.raises(InputError) as exc:
        run_data(d)
    assert len(exc.value.problems) == 1
    p = exc.value.problems[0]
    return (
        f"{p.key} = {p.value}: {p.message}" if isinstance(p.value, (int, float, str))
        else f"{p.key}: {p.message}")


def test_step_diameter_at_a_bearing_must_be_its_bore():
    d = _fast()
    d["shaft"][0]["step"][2]["diameter"] = 36.0
    assert _problem(d) == ("shaft[0].step[2].diameter = 36.0: bearing A (SKF 6207 (GOST 207)) "
                           "at z = 0 mm sits on this step and its bore is d = 35 mm: the "
                           "bearing seat's diameter must equal the bore")


def test_a_bearing_at_a_shoulder_may_sit_on_either_step():
    d = _fast()
    sh = d["shaft"][0]
    # bearing A moved to the shoulder between the seal (32) and its seat (35)
    sh["bearing_a"] = -10.0
    run_data(d)


def test_key_longer_than_its_hub():
    d = _fast()
    d["shaft"][1]["key"][0]["length"] = 65.0
    assert _problem(d) == ("shaft[1].key[0].length = 65.0: the key is longer than its hub "
                           "(hub_length = 60 mm): give length <= 60")


def test_gear_outside_the_steps():
    d = _fast()
    d["shaft"][0]["gear"][0]["position"] = 120.0
    d["shaft"][0]["step"][-1]["length"] = 5.0        # the shaft now ends at 145 mm
    d["shaft"][0]["bearing_b"] = 140.0
    d["shaft"][0]["gear"][0]["position"] = 150.0
    assert _problem(d) == ("shaft[0].gear[0].position = 150.0: the gear lies outside the "
                           "shaft steps: must be within -80…145 mm (start + the step lengths)")


def test_keys_need_steps_and_torque():
    d = _fast()
    sh = d["shaft"][1]
    for k in ("step", "material"):
        sh.pop(k)
    for other in (d["shaft"][0], d["shaft"][2]):
        other.pop("step")
        other.pop("key")
    assert _problem(d).startswith("shaft[1].step: missing; the connections")
    d = _fast()
    d["shaft"][1]["key"][0]["position"] = 0.0        # at the bearing: no torque there
    assert _problem(d).startswith("shaft[1].key[0].position = 0.0: no torque passes")


def test_bad_step_names_the_shaft():
    d = _fast()
    d["shaft"][2]["step"][0]["bore"] = 70.0
    assert _problem(d).startswith("shaft[2].step[0].bore = 70.0: must be smaller")


def test_bad_input_exits_2_with_one_line(tmp_path):
    text = GOLDEN.read_text(encoding="utf-8").replace(
        "hub_length = 60.0\nlength = 50.0", "hub_length = 60.0\nlength = 61.0")
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    proc = subprocess.run([sys.executable, "-m", "geardesign", "run", str(path)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stderr.strip() == (f"{path}: shaft[1].key[0].length = 61.0: the key is longer "
                                   "than its hub (hub_length = 60 mm): give length <= 60")


# ---------------------------------------------- the fast spec (benchmarks/time_cases.py)


def fast_text() -> str:
    """The text of :func:`_fast`'s spec (timed as a cold process by
    benchmarks/time_cases.py)."""
    s = GOLDEN.read_text(encoding="utf-8")
    s = s[:s.index("[lubrication]")] + s[s.index("[[stage]]"):]
    s = s.replace(s[s.index("[stage.iso.scuffing]"):s.index("fzg_load_stage = 12\n") + 20], "")
    for cut in ('[stage.options]\nmethod = "ISO 6336:2019"\n', 'method = "iso281_2007"\n',
                '[shaft.lubrication]\ncontamination = "normal"\n'):
        assert cut in s
        s = s.replace(cut, "")
    return s


def test_fast_text_is_the_fast_spec(tmp_path):
    path = tmp_path / "fast.toml"
    path.write_text(fast_text(), encoding="utf-8")
    assert load_toml(path) == _fast()


def test_an_analysed_shaft_needs_all_its_gears():
    d = _fast()
    d["shaft"][1]["gear"].pop(1)
    d["shaft"][1]["key"].pop(1)
    assert _problem(d) == ("shaft[1].gear: shaft 2 is analysed (it has steps), so the "
                           "torque's path needs all its gears: add a [[shaft.gear]] for the "
                           "input member of stage 2")


def test_a_key_on_a_shaft_without_steps():
    d = _fast()
    d["shaft"][1].pop("step")
    assert _problem(d).startswith("shaft[1].step: missing; the connections")


def test_unknown_connection_key_names_both_tables():
    d = _fast()
    d["shaft"][2]["key"][0]["bogus"] = 1
    text = _problem(d)
    assert text.startswith("shaft[2].key[0].bogus = 1: unknown key in [fit]; allowed: diameter")
    assert text.endswith("; or the drive's type, position, hub_length, name, application_factor")


def test_a_failing_shaft_fails_the_drive_with_its_advice():
    d = _fast()
    d["shaft"][1]["step"][4]["diameter"] = 30.0      # the stage 2 pinion's seat
    doc = run_data(d).document()
    c = next(c for c in doc["checks"] if c["code"] == "SHAFT_2")
    assert not c["passed"] and c["severity"] == "error" and doc["verdict"] == "fail"
    assert c["message"].startswith("intermediate shaft fails (positions x from the shaft's "
                                   "left end: z = x − 12 mm): FATIGUE: fatigue safety S = ")
    assert "scale every step's diameter (and bore and fillet radius) by" in c["message"]
    assert "at gear of stage 2 (x = 152 mm) from 30 to" in c["message"]


def test_informative_K_Hbeta_is_the_spur_calculators_iso_rating(golden):
    """The GOST stage's informative K_Hβ is what the spur calculator's own ISO 6336 rating
    gives for the stage (as the drive loads it) with iso.f_sh set: one formula."""
    row = next(r for r in golden["results"]["face_load"] if r["method"] == "GOST 21354-87")
    spec = copy.deepcopy(golden["results"]["stage_reports"][row["stage"] - 1]["inputs"])
    spec["options"] = {"method": "ISO 6336:2019"}
    spec["load"].pop("regime", None)   # the GOST regime: not read by ISO 6336
    spec.setdefault("iso", {})["f_sh"] = row["f_sh"]
    doc = run_data(spec).document()
    assert doc["results"]["iso6336_factors"]["K_Hbeta"] == pytest.approx(
        row["K_Hbeta_shafts"], rel=1e-12)
    assert doc["results"]["iso6336_factors"]["f_sh"] == pytest.approx(row["f_sh"])


@pytest.mark.parametrize("where, value, line", [
    (("bearing_b",), 170.0, "shaft[0].bearing_b = 170.0: bearing B lies outside the shaft "
                            "steps: must be within -80…160 mm (start + the step lengths)"),
    (("coupling",), -90.0, "shaft[0].coupling = -90.0: the coupling lies outside the shaft "
                           "steps: must be within -80…160 mm (start + the step lengths)"),
    (("key", 0, "position"), 161.0, "shaft[0].key[0].position = 161.0: the hub lies outside "
                                    "the shaft steps: must be within -80…160 mm (start + the "
                                    "step lengths)"),
])
def test_positions_outside_the_steps(where, value, line):
    d = _fast()
    t = d["shaft"][0]
    for k in where[:-1]:
        t = t[k]
    t[where[-1]] = value
    assert _problem(d) == line


def test_fit_longer_than_its_hub():
    d = _fast()
    d["shaft"][2]["key"][0]["length"] = 90.0
    assert _problem(d) == ("shaft[2].key[0].length = 90.0: the fit is longer than its hub "
                           "(hub_length = 80 mm): give length <= 80")


def _with_load(d: dict, **load) -> dict:
    d = copy.deepcopy(d)
    d["shaft"][2].setdefault("load", []).append(load)
    return d


def test_external_load_on_the_output_shaft_by_the_lever_rule():
    """A sprocket's pull F = 3000 N in the drive's +y direction at z = 284 mm on the output
    shaft (bearings at z_A = 0, z_B = 200): statics of a beam on two supports give the
    added reactions ΔR_A = +F·(z − z_B)/L and ΔR_B = −F·(z − z_A)/L (along y), i.e.
    +1260 N and −4260 N; the beam (shaft calculator, the shaft's y is its z) and the
    bearing loads of the drive agree."""
    base = run_data(_fast()).document()["results"]
    new = run_data(_with_load(_fast(), position=284.0, force=3000.0, angle=90.0,
                              name="sprocket")).document()["results"]
    a, b = base["shaft_reports"][2]["results"], new["shaft_reports"][2]["results"]
    dA = b["supports"][0]["R_z"] - a["supports"][0]["R_z"]
    dB = b["supports"][1]["R_z"] - a["supports"][1]["R_z"]
    assert dA == pytest.approx(3000.0 * (284.0 - 200.0) / 200.0, rel=1e-9)
    assert dB == pytest.approx(-3000.0 * 284.0 / 200.0, rel=1e-9)
    assert b["supports"][0]["R_y"] == pytest.approx(a["supports"][0]["R_y"], abs=1e-9)
    brg = {(r["shaft"], r["bearing"]): r["F_r"] for r in new["bearings"]}
    assert brg[(3, "A")] == pytest.approx(b["supports"][0]["R"], rel=1e-9)
    assert brg[(3, "B")] == pytest.approx(b["supports"][1]["R"], rel=1e-9)
    assert any(ld["name"] == "sprocket" for ld in b["loads"])


def test_external_load_without_steps_loads_the_bearings():
    d = _fast()
    for sh in d["shaft"]:
        for k in ("step", "key", "material", "strength"):
            sh.pop(k, None)
    base = run_data(d).document()["results"]["bearings"]
    new = run_data(_with_load(d, position=100.0, force=2000.0, angle=90.0, axial=-500.0)
                   ).document()["results"]["bearings"]
    a = {(r["shaft"], r["bearing"]): r for r in base}
    b = {(r["shaft"], r["bearing"]): r for r in new}
    assert b[(3, "A")]["F_r"] != pytest.approx(a[(3, "A")]["F_r"])
    assert b[(1, "A")]["F_r"] == pytest.approx(a[(1, "A")]["F_r"])       # other shafts
    fixed = b[(3, "A")]["F_a"] or b[(3, "B")]["F_a"]
    assert fixed == pytest.approx(500.0)


def test_external_load_outside_the_steps():
    with pytest.raises(InputError) as e:
        run_data(_with_load(_fast(), position=900.0, force=100.0))
    assert "shaft[2].load[0].position" in str(e.value)


def test_elastic_bearings_tilt_the_shaft_by_superposition():
    """Bearing stiffnesses on the intermediate shaft: the bearing loads stay (two supports:
    statically determinate), each bearing deflects by w = −R/c in each plane, and the slope
    at each gear grows by the rigid-body tilt (w_B − w_A)/L (superposition, [Roark])."""
    rigid = run_data(_fast()).document()["results"]
    d = _fast()
    c_A, c_B = 2.0e5, 5.0e5
    d["shaft"][1].update(stiffness_a=c_A, stiffness_b=c_B)
    soft = run_data(d).document()["results"]
    assert [b["F_r"] for b in soft["bearings"]] == pytest.approx(
        [b["F_r"] for b in rigid["bearings"]], rel=1e-9)
    sup = soft["shaft_reports"][1]["results"]["supports"]
    A, B = sup
    L = B["x"] - A["x"]
    arcmin = 180 * 60 / math.pi
    tilt_y = (-B["R_y"] / c_B + A["R_y"] / c_A) / L * arcmin
    tilt_z = (-B["R_z"] / c_B + A["R_z"] / c_A) / L * arcmin
    for p in (A, B):
        c = c_A if p is A else c_B
        assert p["w"] == pytest.approx(math.hypot(p["R_y"], p["R_z"]) / c, rel=1e-9)
    g0 = [g for g in rigid["shaft_gears"] if g["shaft"] == 2]
    g1 = [g for g in soft["shaft_gears"] if g["shaft"] == 2]
    for a, b in zip(g0, g1):
        assert b["slope_x"] - a["slope_x"] == pytest.approx(tilt_y, rel=1e-6, abs=1e-9)
        assert b["slope_y"] - a["slope_y"] == pytest.approx(tilt_z, rel=1e-6, abs=1e-9)
    f0 = {r["stage"]: r["f_sh"] for r in rigid["face_load"]}
    f1 = {r["stage"]: r["f_sh"] for r in soft["face_load"]}
    assert f1 != pytest.approx(f0)


def test_bearing_stiffness_domain():
    d = _fast()
    d["shaft"][1]["stiffness_a"] = 10.0
    with pytest.raises(InputError) as e:
        run_data(d)
    assert "shaft[1].stiffness_a" in str(e.value)


def test_a_bearing_load_beyond_the_bearing_calculator_says_where_it_comes_from():
    """An external force within its own domain can give a bearing load beyond the bearing
    calculator's: one line that says the load is the drive's and what to change."""
    with pytest.raises(InputError) as e:
        run_data(_with_load(_fast(), position=284.0, force=1e8))
    msg = str(e.value)
    assert "shaft[2].support_b: load.F_r" in msg
    assert "the bearing load the drive derived from the forces on the shaft" in msg
