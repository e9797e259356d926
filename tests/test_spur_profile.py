"""Exported tooth profiles checked against the geometry, not against the profile code:

* every point between the form circle and the tip circle lies on the involute of its gear
  within 0.1 µm: the involute is written here from its definition (base circle, tooth
  thickness on the reference circle, [ISO21771]);
* the tooth thickness on the reference circle of the exported outline equals the closed
  form s_t = m_t(π/2 + 2x tan α_n) + E_sn/cos β (arc);
* the two gears placed in mesh do not overlap, and the gap between them is no more than the
  backlash computed from the thickness allowances;
* the DXF file reopens in ezdxf with a layer per gear, $INSUNITS = 4 (mm) and the extents of
  the two tip circles (skipped without ezdxf).
"""

import math
import re

import numpy as np
import pytest

from geardesign.core.registry import run_data
from geardesign.spur.export import write_profile
from geardesign.gears.geometry import BasicRack, PairInput, pair_geometry
from geardesign.spur.profile import flank, mesh, outline

A20 = math.radians(20.0)


def _pair(z1=19, z2=47, x1=0.35, x2=-0.1, m=3.0, beta=0.0):
    return pair_geometry(PairInput(m, z1, z2, x1, x2, math.radians(beta), 30.0,
                                   BasicRack(A20)))


def _involute_deviation(pts, z, m_n, x, beta, allowance_um, r_from, r_to):
    """Largest normal distance [mm] of the points with r_from < r < r_to from the involute
    flanks of a gear whose first tooth is centred on angle 0."""
    alpha_t = math.atan(math.tan(A20) / math.cos(beta))
    d = z * m_n / math.cos(beta)
    r_b = 0.5 * d * math.cos(alpha_t)
    s_t = (m_n * (math.pi / 2 + 2 * x * math.tan(A20)) + allowance_um * 1e-3) / math.cos(beta)
    psi0 = s_t / d + math.tan(alpha_t) - alpha_t
    r = np.hypot(pts[:, 0], pts[:, 1])
    sel = (r > r_from + 1e-9) & (r < r_to - 1e-9)
    r, ang = r[sel], np.arctan2(pts[sel, 1], pts[sel, 0])
    a_r = np.arccos(r_b / r)
    half = psi0 - (np.tan(a_r) - a_r)
    pitch = 2 * math.pi / z
    rel = np.mod(ang + 0.5 * pitch, pitch) - 0.5 * pitch     # angle from the nearest tooth
    # on a flank the polar angle is ±half(r); the normal distance is r_b·Δangle
    return float(np.max(r_b * np.abs(np.abs(rel) - half))), int(sel.sum())


@pytest.mark.parametrize("z, x, beta", [(19, 0.35, 0.0), (47, -0.1, 0.0), (23, 0.0, 15.0)])
def test_points_lie_on_the_involute(z, x, beta):
    g = _pair(z1=z, x1=x, beta=beta)
    f = flank(g, 0, -40.0)
    pts = outline(f)
    dev, n = _involute_deviation(pts, z, 3.0, x, math.radians(beta), -40.0,
                                 max(0.5 * g.g1.d_l, 0.5 * g.g1.d_b), 0.5 * g.g1.d_a)
    assert n > 50 * z
    assert dev < 1e-4, f"{dev * 1e3:.4f} µm off the involute"


def test_tooth_thickness_on_the_reference_circle():
    for beta in (0.0, 20.0):
        g = _pair(beta=beta)
        for i, (z, x) in enumerate(((19, 0.35), (47, -0.1))):
            f = flank(g, i, -60.0)
            r = 0.5 * g.gears[i].d
            th = float(np.interp(r, f.r, f.theta))
            s_closed = (3.0 * (math.pi / 2 + 2 * x * math.tan(A20)) - 0.060) / math.cos(
                math.radians(beta))
            assert 2 * r * th == pytest.approx(s_closed, abs=1e-9)
            assert r in f.r          # the reference circle is a vertex of the outline


def _min_distance(P, Q):
    """Smallest distance from the vertices of P to the polyline Q (both N × 2)."""
    a, b = Q, np.roll(Q, -1, axis=0)
    ab = b - a
    L2 = np.maximum((ab ** 2).sum(axis=1), 1e-30)
    best = np.inf
    for chunk in np.array_split(P, max(1, len(P) // 200)):
        ap = chunk[:, None, :] - a[None, :, :]
        t = np.clip((ap * ab[None]).sum(axis=2) / L2[None], 0.0, 1.0)
        d = np.linalg.norm(ap - t[..., None] * ab[None], axis=2)
        best = min(best, float(d.min()))
    return best


def _inside(points, poly):
    """Even-odd ray casting: which points lie inside the closed polygon."""
    x, y = points[:, 0][:, None], points[:, 1][:, None]
    x1, y1 = poly[:, 0][None], poly[:, 1][None]
    x2, y2 = np.roll(poly[:, 0], -1)[None], np.roll(poly[:, 1], -1)[None]
    cross = ((y1 > y) != (y2 > y)) & (x < (x2 - x1) * (y - y1) / np.where(y2 == y1, 1e-30,
                                                                          y2 - y1) + x1)
    return cross.sum(axis=1) % 2 == 1


def _near(pts, centre, radius):
    return pts[np.hypot(pts[:, 0] - centre[0], pts[:, 1] - centre[1]) < radius]


@pytest.mark.parametrize("allow", [(-50.0, -70.0), (-10.0, -10.0)])
def test_gears_in_mesh_do_not_overlap_and_leave_the_computed_backlash(allow):
    g = _pair()
    j_n = -(allow[0] + allow[1]) * 1e-3 * math.cos(A20)      # [ISO21771] backlash, mm
    zone = (0.5 * g.g1.d_w, 0.0)
    for contact in (False, True):
        m = mesh(g, allow, contact=contact)
        P, Q = _near(m.pinion, zone, 4 * 3.0), _near(m.wheel, zone, 4 * 3.0)
        assert not _inside(P, m.wheel).any() and not _inside(Q, m.pinion).any()
        gap = min(_min_distance(P, m.wheel), _min_distance(Q, m.pinion))
        if contact:
            assert gap < 2e-3          # one flank closed (polyline chords)
        else:
            assert 0.0 < gap <= 0.5 * j_n + 1e-4     # each flank half of j_n (0.1 µm chords)
    # the circumferential backlash on the working circle matches the normal one
    m = mesh(g, allow)
    assert m.j_t * math.cos(g.alpha_tw) == pytest.approx(j_n, rel=1e-3)


SPEC = {"kind": "spur", "gear": {"module": 3.0, "z1": 19, "z2": 47, "x1": 0.35, "x2": -0.1,
                                 "face_width": 30.0},
        "accuracy": {"standard": "GOST 1643-81", "grade": 8, "mating": "C", "T_H1": 60.0,
                     "T_H2": 80.0}}


def test_dxf_reopens_with_layers_units_and_extents(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    res = run_data(SPEC)
    path = write_profile(res, tmp_path / "pair.dxf")
    doc = ezdxf.readfile(path)
    assert doc.header["$INSUNITS"] == 4
    msp = doc.modelspace()
    layers = {e.dxf.layer for e in msp.query("LWPOLYLINE")}
    assert layers == {"PINION", "WHEEL"}
    for e in msp.query("LWPOLYLINE"):
        assert e.closed
    g = res.pair_geometry
    pts = np.array([p[:2] for e in msp.query("LWPOLYLINE") for p in e.get_points("xy")])
    # true scale: the pinion's points reach its tip circle and no further, the wheel's too
    pin = np.array([p[:2] for e in msp.query('LWPOLYLINE[layer=="PINION"]')
                    for p in e.get_points("xy")])
    whl = np.array([p[:2] for e in msp.query('LWPOLYLINE[layer=="WHEEL"]')
                    for p in e.get_points("xy")])
    assert np.hypot(*pin.T).max() == pytest.approx(0.5 * g.g1.d_a, abs=1e-9)
    assert np.hypot(whl[:, 0] - g.a_w, whl[:, 1]).max() == pytest.approx(0.5 * g.g2.d_a,
                                                                          abs=1e-9)
    v = {r.key: r.value for s in res.sections for r in s.rows}
    e1 = 0.5 * (v["E_sns1"] + v["E_sni1"])        # mean allowance, µm: the rack cut deeper
    assert np.hypot(*pin.T).min() == pytest.approx(
        0.5 * g.g1.d_f + e1 * 1e-3 / (2 * math.tan(A20)), abs=1e-6)
    lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
    assert lo[0] == pytest.approx(pts[:, 0].min()) and hi[1] == pytest.approx(pts[:, 1].max())
    # the exported pinion points are on the involute (the file, not the code, is checked)
    dev, n = _involute_deviation(pin, 19, 3.0, 0.35, 0.0, e1, 0.5 * g.g1.d_l, 0.5 * g.g1.d_a)
    assert n > 0 and dev < 1e-4


def test_svg_is_written_at_true_scale(tmp_path):
    res = run_data(SPEC)
    text = write_profile(res, tmp_path / "pair.svg").read_text(encoding="utf-8")
    assert 'id="pinion"' in text and 'id="wheel"' in text
    w = float(re.search(r'width="([0-9.]+)mm"', text).group(1))
    g = res.pair_geometry
    r1, r2 = 0.5 * g.g1.d_a, 0.5 * g.g2.d_a
    lo = r1 * math.cos(math.pi / 19) + g.a_w + r2 * math.cos(math.pi / 47) + 2.0
    assert lo - 1e-3 <= w <= r1 + g.a_w + r2 + 2.0 + 1e-3
