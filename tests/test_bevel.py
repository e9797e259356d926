"""Bevel pairs: the cone relations, the virtual cylindrical gear identities, forces that
balance, safety factors that scale with the torque as the formulas say, the handbook forms
of the GOST route, and every input rule in one round (one line each, exit 2); the formula
doctests of the package run in tests/test_doctests.py."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign.bevel import forces as FO
from geardesign.bevel import geometry as GEO
from geardesign.bevel import inputs as I
from geardesign.bevel.solve import solve
from geardesign.core.registry import load
from tests.helpers_cli import run_bad

SPECS = Path(__file__).resolve().parent.parent / "specs"
STRAIGHT = SPECS / "bevel_straight_gost.toml"
SPIRAL = SPECS / "bevel_spiral_iso.toml"


def _inputs(path: Path) -> I.Inputs:
    return I.read(load(path)[1].data)


# --------------------------------------------------------------------------- properties

pairs = st.tuples(
    st.booleans(), st.integers(12, 40), st.integers(0, 60), st.floats(60.0, 120.0),
    st.floats(15.0, 40.0), st.floats(-0.1, 0.4), st.floats(0.15, 0.3),
    st.sampled_from(["outer", "mean"]), st.sampled_from(["constant_clearance", "tapered"]),
    st.sampled_from(["right", "left"]))
"""(spiral, z1, z2 − z1, Σ [deg], β_m [deg], x1, b/R_e, module_at, depth, hand)."""


def _pair(args) -> I.Pair:
    spiral, z1, extra, Sigma, beta, x1, b_ratio, module_at, depth, hand = args
    p = I.Pair(spiral, 3.0, module_at, z1, z1 + extra, math.radians(Sigma), 1.0,
               math.radians(beta) if spiral else 0.0, hand, math.radians(20.0), 1.0, 0.2,
               0.25, x1, 0.0, depth)
    d1, _ = I.pitch_angles(p.z1, p.z2, p.Sigma)
    R_e = GEO.modules(p, d1)[3]
    return dataclasses.replace(p, b=b_ratio * R_e)


@settings(max_examples=150, deadline=None)
@given(pairs)
def test_cone_and_virtual_gear_identities(args):
    p = _pair(args)
    g = GEO.pair_geometry(p)
    P, W = g.members
    assert math.isclose(P.delta + W.delta, p.Sigma, rel_tol=1e-12)
    # the pitch cones share the cone distance: d_e = 2·R_e·sin δ for both members
    for m in g.members:
        assert math.isclose(m.d_e, 2.0 * g.R_e * math.sin(m.delta), rel_tol=1e-12)
        assert math.isclose(m.d_m, 2.0 * g.R_m * math.sin(m.delta), rel_tol=1e-12)
    # the virtual gear ratio is the ratio of the virtual diameters and of the virtual teeth
    assert math.isclose(g.u_v, W.d_v / P.d_v, rel_tol=1e-12)
    assert math.isclose(g.u_v, W.z_v / P.z_v, rel_tol=1e-12)
    if abs(p.Sigma - math.pi / 2) < 1e-12:
        assert math.isclose(g.u_v, g.u ** 2, rel_tol=1e-12)
    # [ISO10300-1] annex A: ε_vγ = ε_vα + ε_vβ, ε_vβ over the effective face width 0.85·b
    assert math.isclose(g.eps_vg, g.eps_va + g.eps_vb, rel_tol=1e-12)
    assert math.isclose(g.eps_vb, 0.85 * g.b * math.sin(p.beta_m) / (math.pi * g.m_nm),
                        rel_tol=1e-12, abs_tol=1e-15)
    assert math.isclose(g.eps_va * g.p_vet, g.g_va, rel_tol=1e-12)
    assert math.isclose(g.m_nm, g.m_tm * math.cos(p.beta_m), rel_tol=1e-12)
    # constant clearance: each tip cone parallel to the mating root cone
    if p.depth == "constant_clearance":
        assert math.isclose(P.theta_a, W.theta_f) and math.isclose(W.theta_a, P.theta_f)
    # the virtual centre distance is the sum of the virtual radii
    assert math.isclose(g.a_v, 0.5 * (P.d_v + W.d_v), rel_tol=1e-12)


@settings(max_examples=150, deadline=None)
@given(pairs, st.sampled_from(["cw", "ccw"]), st.sampled_from(["pinion", "wheel"]))
def test_forces_balance_at_a_right_angle(args, rotation, driver):
    """At Σ = 90° the pinion's axial force is the wheel's radial force and vice versa,
    whatever the hand, rotation and driver; and a straight pair has the handbook forms."""
    p = _pair((*args[:3], 90.0, *args[4:]))
    inp = dataclasses.replace(_inputs(STRAIGHT), pair=p)
    inp = dataclasses.replace(inp, load=dataclasses.replace(inp.load, rotation=rotation,
                                                            driver=driver))
    g = GEO.pair_geometry(p)
    f = FO.forces(inp, g)
    assert math.isclose(f.pinion.F_a, f.wheel.F_r, rel_tol=1e-9, abs_tol=1e-9 * f.F_mt)
    assert math.isclose(f.pinion.F_r, f.wheel.F_a, rel_tol=1e-9, abs_tol=1e-9 * f.F_mt)
    # F_t, F_a, F_r of a member make the normal force F_t/(cos α_n cos β_m)
    for m in (f.pinion, f.wheel):
        F_n = f.F_mt / (math.cos(p.alpha_n) * math.cos(p.beta_m))
        assert math.isclose(math.hypot(f.F_mt, m.F_a, m.F_r), F_n, rel_tol=1e-9)
    if not p.spiral:
        ta = math.tan(p.alpha_n)
        assert math.isclose(f.pinion.F_a, f.F_mt * ta * math.sin(g.pinion.delta))
        assert math.isclose(f.pinion.F_r, f.F_mt * ta * math.cos(g.pinion.delta))


def test_hand_and_rotation_flip_the_spiral_thrust():
    """A right-hand driving pinion turning counter-clockwise (seen from its back) is pushed
    away from the apex (out of mesh); reversing the rotation, the hand or the driver flips the
    spiral term, and the two thrusts average to the straight-tooth value (the signs from the
    definitions: tests/test_bevel_published_forces.py)."""
    inp = _inputs(SPIRAL)
    g = GEO.pair_geometry(inp.pair)

    def F_a1(hand, rotation, driver):
        i = dataclasses.replace(inp, pair=dataclasses.replace(inp.pair, hand=hand),
                                load=dataclasses.replace(inp.load, rotation=rotation,
                                                         driver=driver))
        return FO.forces(i, g).pinion.F_a

    out = F_a1("right", "ccw", "pinion")
    into = F_a1("right", "cw", "pinion")
    assert out > 0 and into < out
    assert math.isclose(F_a1("left", "cw", "pinion"), out)
    assert math.isclose(F_a1("left", "ccw", "pinion"), into)
    assert math.isclose(F_a1("right", "ccw", "wheel"), into)
    F_t = FO.forces(inp, g).F_mt
    straight = F_t * math.tan(g.alpha_n) * math.sin(g.pinion.delta) / math.cos(g.beta_m)
    assert math.isclose(0.5 * (out + into), straight, rel_tol=1e-12)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from([STRAIGHT, SPIRAL]), st.floats(0.05, 20.0))
def test_safety_factors_scale_with_the_torque(path, k):
    """With constant factors (K_v given), S_H ∝ T^-1/2 and S_F ∝ T^-1 in both methods."""
    inp = _inputs(path)
    base = solve(inp)
    scaled = solve(dataclasses.replace(inp, load=dataclasses.replace(inp.load,
                                                                     T1=inp.load.T1 * k)))
    for r0, r1 in ((base.iso, scaled.iso), (base.gost, scaled.gost)):
        for m0, m1 in ((r0.pinion, r1.pinion), (r0.wheel, r1.wheel)):
            assert math.isclose(m1.S_H, m0.S_H / math.sqrt(k), rel_tol=1e-9)
            assert math.isclose(m1.S_F, m0.S_F / k, rel_tol=1e-9)


def test_gost_route_is_the_handbook_formula_at_a_right_angle():
    """Through the virtual spur pair, (u_v + 1)/(d_v1 u_v) = √(u² + 1)/(u·d_m1) at Σ = 90°:
    σ_H = Z_E Z_H √(F_t K_H √(u² + 1)/(θ_H b d_m1 u)), the form printed in [Dunaev] §2.6."""
    sol = solve(_inputs(STRAIGHT))
    g, r, f = sol.geometry, sol.gost, sol.forces
    u = g.u
    expected = r.Z_E * r.Z_H * math.sqrt(f.F_mt * r.K_H * math.sqrt(u * u + 1.0)
                                         / (r.theta_H * g.b * g.pinion.d_m * u))
    assert math.isclose(r.sigma_H, expected, rel_tol=1e-12)
    assert r.theta_H == r.theta_F == 0.85


def test_straight_gost_outer_dimensions_by_the_handbook_formulas():
    """[Chernavsky]/[Dunaev] straight bevel forms at Σ = 90°, x = 0: R_e = 0.5·m_te·√(z1² + z2²),
    d_ae = d_e + 2·m_te·cos δ, d_fe = d_e − 2.4·m_te·cos δ (c* = 0.2), tan δ1 = 1/u."""
    g = solve(_inputs(STRAIGHT)).geometry
    m, z1, z2 = g.m_te, g.pinion.z, g.wheel.z
    assert math.isclose(g.R_e, 0.5 * m * math.hypot(z1, z2), rel_tol=1e-12)
    assert math.isclose(math.tan(g.pinion.delta), z1 / z2, rel_tol=1e-12)
    for mb in g.members:
        assert math.isclose(mb.d_ae, mb.d_e + 2 * m * math.cos(mb.delta), rel_tol=1e-12)
        assert math.isclose(mb.d_fe, mb.d_e - 2.4 * m * math.cos(mb.delta), rel_tol=1e-12)


# --------------------------------------------------------------------------- input rules

GOOD = STRAIGHT.read_text(encoding="utf-8")


def test_every_input_rule_in_one_round(tmp_path):
    text = (GOOD.replace("face_width = 30.0", "face_width = 60.0")
            .replace("# spiral_angle = 0.0", "spiral_angle = 30.0"))
    assert run_bad(tmp_path, text) == [
        's.toml: pair.spiral_angle = 30.0: straight teeth have β_m = 0; remove spiral_angle '
        'or write teeth = "spiral"',
        "s.toml: pair.face_width = 60.0: must be at most 0.5·R_e = 53.85 mm (outer cone "
        "distance R_e = 107.7 mm); ISO 23509 recommends b <= R_e/3 = 35.9 mm"]


BAD = [
    ("z2 < z1", GOOD.replace("z2 = 50", "z2 = 15"),
     ["s.toml: pair.z2 = 15: the wheel has at least as many teeth as the pinion (z1 = 20); "
      "swap z1 and z2"]),
    ("crown gear", GOOD.replace("# shaft_angle = 90.0", "shaft_angle = 160.0"),
     ["s.toml: pair.shaft_angle = 160.0: with z2/z1 = 2.5 the wheel's pitch cone angle would "
      "be 147.6°; a crown or internal bevel gear (δ2 >= 89.5°) is not covered: use a smaller "
      "shaft angle"]),
    ("spiral without angle", GOOD.replace('# teeth = "straight"', 'teeth = "spiral"'),
     ["s.toml: pair.spiral_angle = 0.0: the default (not in the spec): spiral teeth need a "
      'mean spiral angle > 0 (e.g. 35); for β_m = 0 write teeth = "straight"']),
    ("negative torque", GOOD.replace("torque = 150.0", "torque = -150.0"),
     ["s.toml: load.torque = -150.0: must be a number >= 1e-06 and <= 10000000 (N·m)"]),
]


@pytest.mark.parametrize("name", [b[0] for b in BAD])
def test_bad_input_one_line_exit_2(tmp_path, name):
    _, text, expected = next(b for b in BAD if b[0] == name)
    assert run_bad(tmp_path, text) == expected


@settings(max_examples=150, deadline=None)
@given(pairs, st.sampled_from(["cw", "ccw"]), st.sampled_from(["pinion", "wheel"]))
def test_forces_balance_at_any_shaft_angle(args, rotation, driver):
    """In the plane of the two axes (x along the pitch cone generator from the apex), the
    axial force acts along the member's axis away from the apex and the radial force toward
    its axis: the pinion's and the wheel's in-plane forces are equal and opposite for any Σ."""
    p = _pair(args)
    inp = dataclasses.replace(_inputs(STRAIGHT), pair=p)
    inp = dataclasses.replace(inp, load=dataclasses.replace(inp.load, rotation=rotation,
                                                            driver=driver))
    g = GEO.pair_geometry(p)
    f = FO.forces(inp, g)
    d1, d2 = g.pinion.delta, g.wheel.delta
    axis = ((math.cos(d1), math.sin(d1)), (math.cos(d2), -math.sin(d2)))
    toward = ((-math.sin(d1), math.cos(d1)), (-math.sin(d2), -math.cos(d2)))
    total = [0.0, 0.0]
    for m, a, r in zip((f.pinion, f.wheel), axis, toward):
        for k in (0, 1):
            total[k] += m.F_a * a[k] + m.F_r * r[k]
    assert max(map(abs, total)) <= 1e-9 * f.F_mt


# --------------------------------------------------------------------------- design mode

DESIGN = SPECS / "bevel_design_spiral.toml"


@settings(max_examples=25, deadline=None)
@given(st.sampled_from([STRAIGHT, SPIRAL]), st.floats(0.2, 5.0), st.floats(1.0, 5.0),
       st.integers(14, 30))
def test_design_proposes_the_least_passing_module(path, k, u, z1):
    """The proposed pair passes every rating asked for, and the module one step smaller of the
    first series (same teeth, same K_be) does not: the first size from the torque."""
    from geardesign.bevel.design import face_width, passes, propose
    from geardesign.core.errors import InputError
    from geardesign.spur.strength.tables import MODULES_1

    inp = _inputs(path)
    inp = dataclasses.replace(inp, load=dataclasses.replace(inp.load, T1=inp.load.T1 * k))
    try:
        prop, trial = propose(inp, u, z1, 0.285)
    except InputError:
        return          # nothing in the series carries it: said in one line
    sol = solve(trial)
    assert passes(sol)
    assert trial.pair.b <= 0.285 * sol.geometry.R_e + 1e-9
    i = MODULES_1.index(prop.module)
    if i > 0:
        smaller = dataclasses.replace(trial.pair, m=MODULES_1[i - 1])
        b = face_width(smaller, 0.285)
        assert b <= 0.285 * GEO.pair_geometry(dataclasses.replace(smaller, b=b)).R_e + 1e-9
        assert not passes(solve(dataclasses.replace(trial, pair=dataclasses.replace(
            smaller, b=b))))


def test_design_spec_reports_the_proposal():
    from geardesign.bevel.calculator import compute

    res = compute(load(DESIGN)[1])
    v = {row.key: row.value for sec in res.sections for row in sec.rows}
    assert (v["z1_proposed"], v["z2_proposed"]) == (18, 45)
    assert v["module_proposed"] in (1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)
    assert v["m_nm"] == v["module_proposed"]
    assert not any(c.code.endswith(("_PITTING", "_BENDING")) and not c.passed
                   for c in res.checks)


def test_design_and_size_keys_exclude_each_other(tmp_path):
    text = DESIGN.read_text(encoding="utf-8").replace("x1 = 0.3", "x1 = 0.3\nmodule = 3.0")
    assert run_bad(tmp_path, text) == [
        "s.toml: pair.module = 3.0: leave it out: [design] proposes the module, the teeth "
        "and the face width (or remove [design])"]
    text = DESIGN.read_text(encoding="utf-8").replace("[design]\nratio = 2.5\nz1 = 18\n", "")
    lines = run_bad(tmp_path, text)
    assert len(lines) == 4 and all("missing; give it, or a [design] table" in x
                                   for x in lines)


def test_wheel_thickness_and_cutter_keys_change_only_the_wheel(tmp_path):
    """``xt2`` and ``root_radius2`` (a thickness modification with backlash, a wheel cutter
    of its own, as in [ISOTR10300-30] sample 1) change the wheel's tooth form and leave the
    pinion's, the contact stress and the geometry of the pinion alone; left out, the wheel
    has −xt1 and the pinion's ρ_a0*."""
    base = SPIRAL.read_text(encoding="utf-8")
    p = tmp_path / "s.toml"
    p.write_text(base.replace("x1 = 0.3", "x1 = 0.3\nxt1 = 0.05\nxt2 = -0.05"),
                 encoding="utf-8")
    same = solve(_inputs(p))
    ref = solve(_inputs(SPIRAL).__class__(
        dataclasses.replace(_inputs(SPIRAL).pair, xt1=0.05), *(
            getattr(_inputs(SPIRAL), k) for k in ("load", "material", "rating"))))
    assert same.iso.wheel.Y_Fa == pytest.approx(ref.iso.wheel.Y_Fa, rel=1e-12)
    p.write_text(base.replace("x1 = 0.3", "x1 = 0.3\nxt1 = 0.05\nxt2 = -0.11\n"
                              "root_radius2 = 0.37"), encoding="utf-8")
    own = solve(_inputs(p))
    assert own.geometry.wheel.xt == pytest.approx(-0.11)
    assert own.iso.pinion.Y_Fa == pytest.approx(ref.iso.pinion.Y_Fa, rel=1e-12)
    assert own.iso.sigma_H == pytest.approx(ref.iso.sigma_H, rel=1e-12)
    assert own.iso.wheel.Y_Fa != pytest.approx(ref.iso.wheel.Y_Fa, rel=1e-6)


def test_wheel_keys_bad_value_one_line(tmp_path):
    text = SPIRAL.read_text(encoding="utf-8").replace("x1 = 0.3", "x1 = 0.3\nxt2 = 0.9")
    assert run_bad(tmp_path, text) == [
        "s.toml: pair.xt2 = 0.9: must be a number >= -0.5 and <= 0.5"]
