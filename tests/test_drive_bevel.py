"""Bevel stages in a drive: the stage's forces are the bevel calculator's (one source of
truth), the axial force reaches the shaft and its fixed bearing with the sign that hand,
rotation and driver give it, and a bad bevel stage is one line naming the stage (exit 2)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from geardesign.bevel import inputs as BI
from geardesign.bevel.solve import solve
from geardesign.core.registry import load
from geardesign.drive.bevel_stage import ETA_BEVEL, bevel_data, run_bevel
from geardesign.drive.shafts import gear_force
from geardesign.drive.stages import Duty
from tests.helpers_cli import cli, run_bad

SPEC = Path(__file__).resolve().parent.parent / "specs" / "drive_bevel_helical.toml"
TEXT = SPEC.read_text(encoding="utf-8")
DUTY = Duty(20000.0, "II", 1.25, 2.0)


def _stage() -> dict:
    import tomllib

    st = tomllib.loads(TEXT)["stage"][0]
    return {k: v for k, v in st.items() if k != "name"}


def test_bevel_stage_is_the_bevel_calculator():
    """Ratio, output torque and speed, margins and member forces of the stage are those of
    ``bevel.solve`` on the stage spec with the drive's torque and speed."""
    T, n = 41.762, 1455.0
    run = run_bevel(_stage(), T, n, DUTY, None, "stage[0]")
    from geardesign.core.registry import load_data

    sol = solve(BI.read(load_data(bevel_data(_stage(), T, n, DUTY, "w"), "w")[1].data))
    g, f = sol.geometry, sol.forces
    assert run.kind == "bevel" and not run.reverses
    assert run.ratio == g.u and run.efficiency == ETA_BEVEL
    assert math.isclose(run.T_out, T * g.u * ETA_BEVEL) and math.isclose(run.n_out, n / g.u)
    assert math.isclose(f.F_mt, 2e3 * T / g.pinion.d_m)
    for member, mf, gm in zip(run.members, (f.pinion, f.wheel), g.members):
        assert (member.F_t, member.F_r, member.F_a) == (mf.F_t, mf.F_r, mf.F_a)
        assert member.r == gm.d_m / 2
    rt = sol.inputs.rating
    S = [x for r in (sol.iso, sol.gost) for m in (r.pinion, r.wheel)
         for x in (m.S_H / rt.S_Hmin, m.S_F / rt.S_Fmin)]
    assert run.margin == min(S)
    assert run.result.kind == "bevel"
    assert any(c.code == "SET_BY_DRIVE" for c in run.result.checks)


@pytest.mark.parametrize("rotation", ["cw", "ccw"])
def test_axial_force_on_the_shaft_follows_hand_and_rotation(rotation):
    """The pinion's axial force on its shaft is axial_sign·F_a with F_a signed by the bevel
    calculator: turning the pinion the other way flips the spiral term (out of mesh for a
    left-hand pinion turning clockwise, into mesh counter-clockwise)."""
    st = _stage()
    st["load"] = dict(st["load"], rotation=rotation)
    run = run_bevel(st, 41.762, 1455.0, DUTY, None, "stage[0]")
    for which, sign in ((0, 1), (1, -1)):
        (_, _, fz), _ = gear_force(run.gear_load(which, 0.0, 0.0, sign), 1)
        assert fz == sign * run.members[which].F_a
    F_a1 = run.members[0].F_a
    assert (F_a1 > 0) == (rotation == "cw")
    # at Σ = 90° the pinion's axial force is the wheel's radial force
    assert math.isclose(F_a1, run.members[1].F_r, rel_tol=1e-12)


def test_bevel_helical_reducer_bearing_takes_the_pinion_thrust():
    """The fixed bearing (A) of the input shaft carries the bevel pinion's axial force, the
    intermediate shaft's the sum of the bevel wheel's and the helical pinion's."""
    from geardesign.drive.calculator import compute

    res = compute(load(SPEC)[1])
    stages = next(t for t in res.tables if t.key == "stages")
    bearings = next(t for t in res.tables if t.key == "bearings")
    assert [r["kind"] for r in stages.rows] == ["bevel", "spur", "spur"]
    run = run_bevel(_stage(), stages.rows[0]["T_in"], 1455.0, DUTY, None, "s")
    shaft1 = [r for r in bearings.rows if r["shaft"] == 1]
    assert math.isclose(shaft1[0]["F_a"], abs(run.members[0].F_a), rel_tol=1e-9)
    assert shaft1[1]["F_a"] == 0.0


def test_bad_bevel_stage_is_one_line_naming_the_stage(tmp_path):
    lines = run_bad(tmp_path, TEXT.replace("z2 = 43", "z2 = 12"))
    assert lines == ["s.toml: stage[0]: pair.z2 = 12: the wheel has at least as many teeth "
                     "as the pinion (z1 = 17); swap z1 and z2"]
    lines = run_bad(tmp_path, TEXT.replace('teeth = "spiral"', 'teeth = "helical"'))
    assert len(lines) == 1 and lines[0].startswith("s.toml: stage[0]: pair.teeth")


def test_bevel_is_a_drive_stage_kind():
    code, out, _ = cli("schema", "drive")
    assert code == 0 and '"bevel"' in out


def test_duty_application_factor_only_where_the_stage_gives_none():
    st = _stage()
    assert bevel_data(st, 10.0, 100.0, DUTY, "w")["load"]["application_factor"] == 1.25
    st["load"] = dict(st["load"], application_factor=1.5)
    d = bevel_data(st, 10.0, 100.0, DUTY, "w")
    assert d["load"]["application_factor"] == 1.5
    assert (d["load"]["torque"], d["load"]["speed"]) == (10.0, 100.0)


def test_bevel_stage_in_design_mode_is_sized_for_the_drive_torque():
    """A bevel stage with [design] is proposed for the torque the drive gives it: a larger
    torque never gets a smaller module."""
    st = _stage()
    st["pair"] = {k: v for k, v in st["pair"].items()
                  if k not in ("module", "z1", "z2", "face_width")}
    st["design"] = {"ratio": 2.5, "z1": 17}
    mods = []
    for T in (20.0, 80.0, 320.0):
        run = run_bevel(st, T, 1455.0, DUTY, None, "stage[0]")
        v = {r.key: r.value for s in run.result.sections for r in s.rows}
        assert run.margin >= 1.0 and v["z1_proposed"] == 17
        mods.append(v["module_proposed"])
    assert mods == sorted(mods) and mods[0] < mods[-1]
