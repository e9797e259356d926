"""Internal gears on the drawing, checked against geometry built here, not against the code
under test:

* the ball between the internal teeth touches both flanks at the computed contact diameter:
  the distance from its centre to the involute, the involute written as the path of a point
  of a string unwound from the base circle (a parametric curve, minimised numerically), is
  D/2, for even and odd z and random gears;
* the constant chord of an internal tooth ends on its flanks;
* the exported internal outline (SVG, and DXF when ezdxf is installed) is an involute of the
  base circle: each flank is fitted by least squares to φ(r) = φ0 ± inv(arccos(r_b/r))
  with r_b free, and the fitted r_b, the residual and the tooth thickness on the reference
  circle are checked;
* the pinion placed in the ring does not cross it, and the mesh's backlash is the one of
  the thickness allowances;
* the thermal change of the backlash has the sign of the geometry: a warmer housing opens an
  external pair and closes an internal one.
"""

import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import least_squares, minimize_scalar

from geardesign.core.registry import run_data
from geardesign.spur.export import write_profile
from geardesign.spur.measurement import Tooth, constant_chord, ideal_ball, over_balls
from geardesign.spur.profile import mesh
from geardesign.spur.tolerances.backlash import Thermal

A20 = math.radians(20.0)


def _involute_point(r_b: float, eta_b: float, t: float, side: float) -> np.ndarray:
    """Point of roll angle t of the involute that leaves the base circle at the polar angle
    ``side``·η_b (angles from the +y axis toward +x) and unwinds toward the y axis."""
    phi = side * (eta_b - t)
    e = np.array([math.sin(phi), math.cos(phi)])
    tangent = side * np.array([math.cos(phi), -math.sin(phi)])
    return r_b * e + r_b * t * tangent


def _distance_to_flank(c: np.ndarray, r_b: float, eta_b: float, side: float,
                       t_max: float) -> tuple[float, float]:
    """Least distance from ``c`` to the flank and the radius of the nearest point."""
    ts = np.linspace(0.0, t_max, 2001)
    phi = side * (eta_b - ts)                 # the same curve as _involute_point, on a grid
    px = r_b * np.sin(phi) + side * r_b * ts * np.cos(phi)
    py = r_b * np.cos(phi) - side * r_b * ts * np.sin(phi)
    k = int(np.argmin(np.hypot(px - c[0], py - c[1])))
    lo, hi = ts[max(k - 1, 0)], ts[min(k + 1, len(ts) - 1)]
    res = minimize_scalar(lambda t: np.linalg.norm(_involute_point(r_b, eta_b, t, side) - c),
                          bounds=(lo, hi), method="bounded",
                          options={"xatol": 1e-13})
    p = _involute_point(r_b, eta_b, res.x, side)
    return float(res.fun), float(np.linalg.norm(p))


def _ring(z: int, m: float, x: float) -> tuple[Tooth, float, float]:
    """A spur internal gear (GOST 19274-73 shift x) as a Tooth with its space width, its
    base radius and the half-space angle at the base circle η_b = e/d + inv α."""
    d = z * m
    s = m * (0.5 * math.pi - 2.0 * x * math.tan(A20))
    e = math.pi * m - s
    d_a = d - 2.0 * (1.0 - x) * m
    d_f = d + 2.0 * (1.25 + x) * m
    t = Tooth(z, m, A20, 0.0, e, d_a, d_f, internal=True)
    return t, 0.5 * d * math.cos(A20), e / d + math.tan(A20) - A20


def _check_ball(z: int, m: float, x: float, D: float) -> None:
    t, r_b, eta_b = _ring(z, m, x)
    res = over_balls(t, D)
    c = np.array([0.0, 0.5 * res.d_M])        # the ball centre in the space at angle 0
    for side in (1.0, -1.0):
        dist, r_c = _distance_to_flank(c, r_b, eta_b, side, 1.2)
        assert dist == pytest.approx(0.5 * D, abs=1e-7 * m)
        assert 2 * r_c == pytest.approx(res.d_c, abs=1e-6 * m)
    # the dimension between two balls and the radial one from the centres' positions
    other = math.pi if z % 2 == 0 else math.pi * (1 - 1 / z)     # the opposite space
    c2 = 0.5 * res.d_M * np.array([math.sin(other), math.cos(other)])
    assert res.M == pytest.approx(np.linalg.norm(c2 - c) - D, abs=1e-9 * res.M)
    assert res.M_r == pytest.approx(0.5 * res.d_M - 0.5 * D, abs=1e-12 * res.M)


@pytest.mark.parametrize("z, m, x, D", [(56, 45.0, 0.5013, 80.0), (93, 21.0, -0.1171, 35.0),
                                        (72, 3.0, 0.2, 5.0), (71, 3.0, 0.0, 5.25)])
def test_ball_touches_both_internal_flanks(z, m, x, D):
    _check_ball(z, m, x, D)


@settings(max_examples=25, deadline=None)
@given(z=st.integers(30, 160), m=st.sampled_from([1.0, 2.5, 6.0, 20.0]),
       x=st.floats(-0.4, 0.8))
def test_chosen_ball_touches_both_flanks(z, m, x):
    t, _, _ = _ring(z, m, x)
    _check_ball(z, m, x, ideal_ball(t, step=1e-6 * m))


@pytest.mark.parametrize("z, x", [(56, 0.5), (93, -0.1), (41, 0.3)])
def test_constant_chord_of_an_internal_tooth_ends_on_its_flanks(z, x):
    m = 10.0
    t, r_b, eta_b = _ring(z, m, x)
    c = constant_chord(t)
    # the tooth centred on angle 0 is between the spaces at ±π/z: its right flank is the
    # left flank of the space at +π/z, i.e. the involute rotated by π/z
    y = 0.5 * t.d_a + c.h_c                    # the chord's distance from the axis
    p = np.array([0.5 * c.s_c, y])
    rot = -math.pi / z                          # into the frame of the space at +π/z
    R = np.array([[math.cos(rot), math.sin(rot)], [-math.sin(rot), math.cos(rot)]])
    dist, _ = _distance_to_flank(R @ p, r_b, eta_b, -1.0, 1.2)
    assert dist == pytest.approx(0.0, abs=1e-7 * m)


# ----------------------------------------------------------------------------- outline

SPEC = {"kind": "spur", "title": "internal pair",
        "gear": {"internal": True, "module": 3.0, "z1": 24, "z2": 71, "x1": 0.3,
                 "center_distance": 71.5, "face_width": 30.0, "cutter_teeth": 25},
        "accuracy": {"standard": "ISO 1328-1:2013", "grade": 7, "fa": 30.0,
                     "A_sne1": -40.0, "A_sne2": -70.0, "T_sn1": 40.0, "T_sn2": 60.0}}


def _svg_paths(path) -> dict:
    text = path.read_text(encoding="utf-8")
    out = {}
    for pid, d in re.findall(r'<path id="(\w+)"[^>]* d="([^"]+)"', text):
        nums = np.array([float(v) for v in re.findall(r"-?\d+\.\d+", d)]).reshape(-1, 2)
        nums[:, 1] *= -1.0                     # SVG y down
        out[pid] = nums
    return out


def _flank_runs(pts: np.ndarray, lo: float, hi: float) -> list[np.ndarray]:
    """Contiguous runs of outline points with lo < r < hi (one run per flank)."""
    r = np.hypot(pts[:, 0], pts[:, 1])
    inside = (r > lo) & (r < hi)
    runs, cur = [], []
    for p, ok in zip(pts, inside):
        if ok:
            cur.append(p)
        elif cur:
            runs.append(np.array(cur))
            cur = []
    if cur:
        runs.append(np.array(cur))
    return [rn for rn in runs if len(rn) >= 10]


def _fit_involute(run: np.ndarray, r_b0: float) -> tuple[float, float, float, float]:
    """Least-squares fit of φ(r) = φ0 + s·inv(arccos(r_b/r)) (s = ±1, φ0 and r_b free);
    returns r_b, φ0, s and the largest normal residual r_b·|Δφ| [mm]."""
    r = np.hypot(run[:, 0], run[:, 1])
    phi = np.unwrap(np.arctan2(run[:, 1], run[:, 0]))
    best = None
    for s in (1.0, -1.0):
        def resid(p):
            a = np.arccos(np.clip(p[1] / r, -1.0, 1.0))
            return p[1] * (phi - p[0] - s * (np.tan(a) - a))

        a0 = np.arccos(r_b0 / r[0])
        fit = least_squares(resid, [phi[0] - s * (math.tan(a0) - a0), 0.99 * r_b0],
                            xtol=1e-15, ftol=1e-15, gtol=1e-15)
        err = float(np.max(np.abs(fit.fun)))
        if best is None or err < best[3]:
            best = (float(fit.x[1]), float(fit.x[0]), s, err)
    return best


@pytest.fixture(scope="module")
def ring_svg(tmp_path_factory):
    res = run_data(SPEC)
    path = tmp_path_factory.mktemp("p") / "internal.svg"
    write_profile(res, path)
    return res, _svg_paths(path)


def test_exported_internal_flanks_are_involutes_of_the_base_circle(ring_svg):
    res, paths = ring_svg
    g = res.pair_geometry
    g2 = g.g2
    ring = paths["wheel"] - np.array([-g.a_w, 0.0])       # about the ring's own centre
    runs = _flank_runs(ring, 0.5 * g2.d_a + 1e-3, 0.5 * g2.d_l - 1e-3)
    assert len(runs) == 2 * g2.z
    r_b = 0.5 * g2.d_b
    fits = [_fit_involute(run, r_b) for run in runs]
    for rb_fit, _, _, err in fits:
        assert rb_fit == pytest.approx(r_b, rel=1e-6)
        assert err < 2e-6                                   # mm, coordinates printed to 1e-6
    # the tooth thickness on the reference circle from two fitted flanks of one tooth
    # (a run with s = +1 then one with s = −1 bound a tooth: θ grows with r in both)
    r = 0.5 * g2.d
    a = math.acos(r_b / r)
    inv_a = math.tan(a) - a
    widths = []
    for (_, p1, s1, _), (_, p2, s2, _) in zip(fits, fits[1:]):
        if s1 == -1.0 and s2 == 1.0:          # trailing flank (φ0 − θ), leading (φ0 + θ)
            gap = (p2 + inv_a) - (p1 - inv_a)
            widths.append(r * ((gap + math.pi) % (2 * math.pi) - math.pi))
    s_t = 3.0 * (0.5 * math.pi - 2.0 * g2.x * math.tan(A20)) + (-70.0 - 60.0 / 2) * 1e-3
    # the profile carries the mean allowance −70 − 60/2 µm (export module)
    assert len(widths) >= g2.z - 1
    assert max(abs(w - s_t) for w in widths) < 1e-5     # mm; 1e-6 mm coordinates


def test_the_pinion_stays_inside_the_ring(ring_svg):
    from matplotlib.path import Path as MPath

    res, paths = ring_svg
    hole = MPath(paths["wheel"])
    assert hole.contains_points(paths["pinion"]).all()


@pytest.mark.parametrize("allow", [(0.0, 0.0), (-40.0, -70.0)])
def test_mesh_backlash_is_the_allowances_backlash(allow):
    g = run_data(SPEC).pair_geometry
    m = mesh(g, allow)
    # nominal teeth at the a_w of their shifts mesh without backlash; the allowances open
    # j_t = −(E1 + E2)·cos α_n / cos α_wt on the working pitch circle (spur), [ISO21771]
    expected = -(allow[0] + allow[1]) * 1e-3 * math.cos(A20) / math.cos(g.alpha_tw)
    assert m.j_t == pytest.approx(expected, abs=1e-6)
    mc = mesh(g, allow, contact=True)
    from matplotlib.path import Path as MPath

    assert MPath(mc.wheel).contains_points(mc.pinion).mean() > 0.999


def test_dxf_layers_of_an_internal_pair(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    res = run_data(SPEC)
    write_profile(res, tmp_path / "p.dxf")
    doc = ezdxf.readfile(tmp_path / "p.dxf")
    msp = doc.modelspace()
    wheel = [e for e in msp.query("LWPOLYLINE") if e.dxf.layer == "WHEEL"]
    assert len(wheel) == 1 and wheel[0].closed
    g = res.pair_geometry
    pts = np.array([(p[0], p[1]) for p in wheel[0].get_points()]) - np.array([-g.a_w, 0.0])
    r = np.hypot(pts[:, 0], pts[:, 1])
    assert r.min() == pytest.approx(0.5 * g.g2.d_a, abs=1e-9)
    assert r.max() == pytest.approx(0.5 * g.g2.d_f, abs=1e-9)


# ----------------------------------------------------------------------------- backlash


def test_a_warmer_housing_opens_an_external_pair_and_closes_an_internal_one():
    hot_housing = Thermal(60.0, 20.0, 20.0, 23e-6, 11.5e-6, 11.5e-6)
    assert hot_housing.delta_a(100.0, 50.0, 150.0) > 0.0
    assert hot_housing.delta_a(50.0, 50.0, 150.0, internal=True) < 0.0
    # a warmer internal gear opens its mesh, a warmer pinion closes it
    hot_ring = Thermal(20.0, 20.0, 60.0, 23e-6, 11.5e-6, 11.5e-6)
    assert hot_ring.delta_a(50.0, 50.0, 150.0, internal=True) > 0.0
    # all at one temperature with one material: a_w = r_w2 − r_w1 grows like the radii
    same = Thermal(60.0, 60.0, 60.0, 11.5e-6, 11.5e-6, 11.5e-6)
    assert same.delta_a(50.0, 50.0, 150.0, internal=True) == pytest.approx(0.0, abs=1e-15)


# ----------------------------------------------------------------------------- CLI

INTERNAL = """kind = "spur"
[gear]
internal = true
module = 3.0
z1 = 24
z2 = 71
x1 = 0.3
center_distance = 71.5
face_width = 30.0
cutter_teeth = 25
[accuracy]
standard = "GOST 1643-81"
grade = 7
mating = "C"
T_H1 = 60
T_H2 = 100
"""


@pytest.mark.parametrize("extra, line", [
    ("[drawing]\nball_diameter2 = 0.5\n",
     "s.toml: drawing.ball_diameter2 = 0.5: the ball does not touch the flanks: it would touch "
     "the flanks at d = 226.1409 mm, beyond the involute, which ends at d = 222.8972 mm: choose "
     "a larger ball"),
    ("[drawing]\nball_diameter2 = 9.0\n",
     "s.toml: drawing.ball_diameter2 = 9.0: the ball does not touch the flanks: it is too "
     "large: its centre would lie inside the base circle; choose a smaller ball"),
    ("[drawing]\nk2 = 30\n",
     "s.toml: drawing.k2 = 30: impossible span: the calliper would touch at d = 332.5588 mm, "
     "outside the involute 210.9021…222.8972 mm; use k = 8…11"),
])
def test_bad_internal_drawing_inputs_name_the_key(tmp_path, extra, line):
    from tests.helpers_cli import run_bad

    assert run_bad(tmp_path, INTERNAL + extra) == [line]


def test_internal_pair_report_profile_and_plot(tmp_path):
    from tests.helpers_cli import cli, write_spec

    spec = write_spec(tmp_path, INTERNAL)
    code, out, err = cli("run", spec, "--format", "table", "--profile", tmp_path / "p.svg",
                         "--plot", tmp_path / "m.svg")
    assert code in (0, 1), err
    assert "internal gear" in out and "between two balls" in out
    assert (tmp_path / "p.svg").read_text().count("<path") == 2
    assert (tmp_path / "m.svg").stat().st_size > 1000


# ----------------------------------------------------------------------------- robustness


@settings(max_examples=40, deadline=None)
@given(z1=st.integers(12, 40), dz=st.integers(6, 120), x1=st.floats(-0.3, 0.8),
       x2=st.floats(-0.3, 1.0), m=st.sampled_from([1.0, 3.0, 8.0]),
       beta=st.sampled_from([0.0, 12.0]), gost=st.booleans(),
       temps=st.booleans())
def test_internal_drawing_never_crashes(z1, dz, x1, x2, m, beta, gost, temps):
    """Random internal pairs with [accuracy] and [drawing]: a report with finite numbers or
    one input error, nothing else."""
    import json

    from geardesign.core.errors import InputError

    acc = ({"standard": "GOST 1643-81", "grade": 8, "mating": "B", "T_H1": 80.0, "T_H2": 120.0}
           if gost else {"standard": "ISO 1328-1:1995", "grade": 7, "fa": 40.0, "T_sn1": 50.0,
                         "T_sn2": 80.0})
    if temps:
        acc.update(temperature_housing=70.0, temperature_wheel=50.0)
    data = {"kind": "spur", "title": "t",
            "gear": {"internal": True, "module": m, "z1": z1, "z2": z1 + dz, "x1": x1, "x2": x2,
                     "helix_angle": beta, "face_width": 10 * m},
            "accuracy": acc, "drawing": {}}
    try:
        doc = run_data(data).document()
    except InputError:
        return
    text = json.dumps(doc, allow_nan=False)          # raises on NaN or inf
    assert "test_dimensions" in doc["results"] and text
    v = doc["results"]["test_dimensions"]
    assert v["M2_upper"] >= v["M2_lower"] and v["W2_upper"] >= v["W2_lower"]
    assert v["M2"] < v["M2_lower"]                   # thinner teeth: wider spaces


def test_plot_curves_end_at_the_reports_sliding():
    """The plot's sliding along the path A…E of an internal pair ends at the report's values
    (geardesign.spur.kinematics.sliding_at_ends), and the stress ratio is 1 at the pitch
    point."""
    from geardesign.spur.export import sliding_along_path
    from geardesign.spur.kinematics import sliding_at_ends

    g = run_data(SPEC).pair_geometry
    s = sliding_along_path(g, n=2001)
    e = sliding_at_ends(g)
    assert (s["theta1"][0], s["theta2"][0]) == pytest.approx((e.theta1_A, e.theta2_A), rel=1e-12)
    assert (s["theta1"][-1], s["theta2"][-1]) == pytest.approx((e.theta1_E, e.theta2_E),
                                                               rel=1e-12)
    r1p = 0.5 * g.g1.d_w * math.sin(g.alpha_tw)
    assert np.interp(r1p, s["rho1"], s["sigma_rel"]) == pytest.approx(1.0, abs=1e-5)
