"""Tooth profiles and the mesh picture of a spur/helical pair, written to files:

* ``--profile FILE.dxf``: closed polylines at true scale in mm, one layer per gear
  (PINION, WHEEL) and the line of action (LINE_OF_ACTION), $INSUNITS = 4 (mm); through
  ezdxf, an optional extra imported only here;
* ``--profile FILE.svg``: the same outlines as SVG paths, 1 user unit = 1 mm;
* ``--plot FILE.png|svg``: the mesh with the line of action, the active profile limits
  A and E, and the specific sliding and the relative contact stress along the path of
  contact (matplotlib, an optional extra).

Each file is written atomically.  The profiles carry the mean tooth-thickness allowance of
the [accuracy] table (nominal teeth without it).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from geardesign.core.io import atomic_path

PROFILE_FORMATS = (".dxf", ".svg")
PLOT_FORMATS = (".png", ".svg")
LAYERS = ("PINION", "WHEEL")


class ExportError(RuntimeError):
    """The file cannot be written (missing extra, unknown type, result without a pair)."""


def _pair_of(result):
    geom = getattr(result, "pair_geometry", None)
    if geom is None:
        raise ExportError("this result has no spur gear pair to draw (a kind = \"spur\" spec "
                          "is needed)")
    allow = [0.0, 0.0]
    for sec in result.sections:
        if sec.key == "accuracy":
            v = {r.key: r.value for r in sec.rows}
            allow = [0.5 * (v[f"E_sns{i}"] + v[f"E_sni{i}"]) for i in (1, 2)]
    return geom, tuple(allow)


def line_of_action(g) -> dict:
    """Points of the line of action in the drawing frame (pinion at the origin, wheel at
    (a_w, 0), an internal gear at (−a_w, 0)): tangency points N1, N2 on the base circles
    and the ends A, E of the path of contact (where the tip circles cut it), and the pitch
    point P.  Internal pair: N2 lies on the same side, N2 = N1 − g_w·n, and the contact
    starts at ρ1 = ρ_a2 − g_w ([ISO21771]; :mod:`geardesign.spur.internal`)."""
    a = g.alpha_tw
    r_b1, r_b2 = 0.5 * g.g1.d_b, 0.5 * g.g2.d_b
    n = np.array([math.sin(a), math.cos(a)])          # direction of increasing ρ1
    N1 = r_b1 * np.array([math.cos(a), -math.sin(a)])
    if getattr(g, "internal", False):
        N2 = np.array([-g.a_w, 0.0]) + r_b2 * np.array([math.cos(a), -math.sin(a)])
        rho_A = g.g2.rho_a - g.g_w
    else:
        N2 = np.array([g.a_w, 0.0]) - r_b2 * np.array([math.cos(a), -math.sin(a)])
        rho_A = g.g_w - g.g2.rho_a
    # N1 + t·n, t = ρ1 (roll distance of the pinion)
    N2_t = float(np.dot(N2 - N1, n))
    A = N1 + rho_A * n
    E = N1 + g.g1.rho_a * n
    P = N1 + 0.5 * g.g1.d_w * math.sin(a) * n
    N2 = N1 + N2_t * n
    # the drawn line: N1N2, or for an internal pair from N2 through N1 to E (the path of
    # contact lies beyond N1, on the far side from N2)
    ends = (N2, E) if getattr(g, "internal", False) else (N1, N2)
    return {"N1": N1, "N2": N2, "A": A, "E": E, "P": P, "dir": n, "ends": ends}


def write_profile(result, path) -> Path:
    """Write both gears in mesh to ``path`` (.dxf or .svg)."""
    from geardesign.spur.profile import mesh

    path = Path(path)
    ext = path.suffix.lower()
    if ext not in PROFILE_FORMATS:
        raise ExportError("the profile file must end in .dxf or .svg")
    g, allow = _pair_of(result)
    m = mesh(g, allow)
    if ext == ".dxf":
        return _write_dxf(m, g, path)
    return _write_svg(m, g, path)


def _write_dxf(m, g, path: Path) -> Path:
    try:
        import ezdxf
        from ezdxf import units
    except ImportError:
        raise ExportError("ezdxf is not installed, so no DXF can be written; install it with "
                          "`pip install ezdxf` (the dxf extra of geardesign), or write .svg") \
            from None
    doc = ezdxf.new("R2010", setup=False)
    doc.units = units.MM
    doc.header["$MEASUREMENT"] = 1
    for name, color in zip(LAYERS, (5, 1)):
        doc.layers.add(name, color=color)
    doc.layers.add("LINE_OF_ACTION", color=3)
    msp = doc.modelspace()
    for name, pts in zip(LAYERS, (m.pinion, m.wheel)):
        poly = msp.add_lwpolyline([], close=True, dxfattribs={"layer": name})
        v = np.zeros((len(pts), 5))             # x, y, start width, end width, bulge
        v[:, :2] = pts
        poly.lwpoints.set(v)                     # in one piece (appending point by point is
        #                                          quadratic in ezdxf)
    loa = line_of_action(g)
    msp.add_line(tuple(loa["ends"][0]), tuple(loa["ends"][1]),
                 dxfattribs={"layer": "LINE_OF_ACTION"})
    lo = np.minimum(m.pinion.min(axis=0), m.wheel.min(axis=0))
    hi = np.maximum(m.pinion.max(axis=0), m.wheel.max(axis=0))
    ext = ((float(lo[0]), float(lo[1]), 0.0), (float(hi[0]), float(hi[1]), 0.0))
    doc.header["$EXTMIN"], doc.header["$EXTMAX"] = ext
    msp.dxf.extmin, msp.dxf.extmax = ext     # ezdxf writes the header from the layout
    with atomic_path(path) as tmp:
        doc.saveas(tmp)
    return path


def _svg_path(pts: np.ndarray) -> str:
    head = f"M{pts[0, 0]:.6f},{-pts[0, 1]:.6f}"
    body = " ".join(f"L{x:.6f},{-y:.6f}" for x, y in pts[1:])
    return f"{head} {body} Z"


def _write_svg(m, g, path: Path) -> Path:
    lo = np.minimum(m.pinion.min(axis=0), m.wheel.min(axis=0)) - 1.0
    hi = np.maximum(m.pinion.max(axis=0), m.wheel.max(axis=0)) + 1.0
    w, h = hi - lo
    loa = line_of_action(g)
    text = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.3f}mm" height="{h:.3f}mm" '
        f'viewBox="{lo[0]:.6f} {-hi[1]:.6f} {w:.6f} {h:.6f}">',
        '<!-- geardesign: transverse tooth profiles in mesh, 1 unit = 1 mm, y up in the '
        'drawing is -y here -->',
        f'<path id="pinion" fill="none" stroke="#1f4e9e" stroke-width="0.05" '
        f'd="{_svg_path(m.pinion)}"/>',
        f'<path id="wheel" fill="none" stroke="#b22222" stroke-width="0.05" '
        f'd="{_svg_path(m.wheel)}"/>',
        f'<line id="line_of_action" x1="{loa["ends"][0][0]:.6f}" y1="{-loa["ends"][0][1]:.6f}" '
        f'x2="{loa["ends"][1][0]:.6f}" y2="{-loa["ends"][1][1]:.6f}" stroke="#2e8b57" '
        f'stroke-width="0.05"/>',
        '</svg>', '']
    with atomic_path(path) as tmp:
        Path(tmp).write_text("\n".join(text), encoding="utf-8")
    return path


def sliding_along_path(g, n: int = 101) -> dict:
    """Specific sliding ϑ1 = 1 − ρ2/(u ρ1), ϑ2 = 1 − u ρ1/ρ2 and the contact stress relative to
    the pitch point, √((1/ρ1 + 1/ρ2) / (1/ρ1P + 1/ρ2P)) (Hertz, one pair carrying the load),
    along the path of contact A…E; ρ1 the pinion's radius of curvature (theory of gearing;
    [Dobrov2017] (3)).  Internal pair: ρ2 = ρ1 + g_w on the concave internal flank, so
    1/ρ1 − 1/ρ2 in the stress ([ISO21771]; the sliding formulas hold as they are, both
    gears turning the same way)."""
    internal = getattr(g, "internal", False)
    sgn = -1.0 if internal else 1.0
    rho1 = np.linspace(sgn * (g.g_w - g.g2.rho_a), g.g1.rho_a, n)
    rho2 = g.g_w - rho1 if not internal else rho1 + g.g_w
    u = g.u
    th1 = 1.0 - rho2 / (u * rho1)
    th2 = 1.0 - u * rho1 / rho2
    r1p = 0.5 * g.g1.d_w * math.sin(g.alpha_tw)
    r2p = g.g_w - r1p if not internal else r1p + g.g_w
    rel = np.sqrt((1.0 / rho1 + sgn / rho2) / (1.0 / r1p + sgn / r2p))
    return {"rho1": rho1, "theta1": th1, "theta2": th2, "sigma_rel": rel}


def write_plot(result, path) -> Path:
    """The mesh picture and the sliding/stress curves to ``path`` (.png or .svg)."""
    from geardesign.spur.profile import mesh

    path = Path(path)
    if path.suffix.lower() not in PLOT_FORMATS:
        raise ExportError("the plot file must end in .png or .svg")
    g, allow = _pair_of(result)
    try:
        import matplotlib
    except ImportError:
        raise ExportError("matplotlib is not installed, so no plot can be written; install it "
                          "with `pip install matplotlib` (the plot extra of geardesign)") \
            from None
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    m = mesh(g, allow)
    loa = line_of_action(g)
    fig = Figure(figsize=(11.0, 5.5), tight_layout=True)
    ax, ax2 = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.3, 1.0]})
    ax.fill(m.pinion[:, 0], m.pinion[:, 1], color="#9db7e0", ec="#1f4e9e", lw=0.6,
            label=f"pinion z1 = {g.inp.z1}")
    internal = getattr(g, "internal", False)
    if internal:   # the ring: between its toothed contour and a rim circle
        from matplotlib.patches import PathPatch
        from matplotlib.path import Path as MPath

        t = np.linspace(0, 2 * np.pi, 721)[:-1]
        r_rim = 0.5 * g.g2.d_f + 2.0 * g.inp.m_n
        rim = np.column_stack([m.centre2[0] + r_rim * np.cos(t), r_rim * np.sin(t)])
        verts = np.vstack([rim, rim[:1], m.wheel[::-1], m.wheel[-1:]])
        codes = ([MPath.MOVETO] + [MPath.LINETO] * (len(rim) - 1) + [MPath.CLOSEPOLY]
                 + [MPath.MOVETO] + [MPath.LINETO] * (len(m.wheel) - 1) + [MPath.CLOSEPOLY])
        ax.add_patch(PathPatch(MPath(verts, codes), facecolor="#e8a0a0", edgecolor="#b22222",
                               lw=0.6, alpha=0.8, label=f"internal gear z2 = {g.inp.z2}"))
    else:
        ax.fill(m.wheel[:, 0], m.wheel[:, 1], color="#e8a0a0", ec="#b22222", lw=0.6, alpha=0.8,
                label=f"wheel z2 = {g.inp.z2}")
    t = np.linspace(0, 2 * np.pi, 721)
    for cx, gi in ((0.0, g.g1), (m.centre2[0], g.g2)):
        for d, style in ((gi.d_b, ":"), (gi.d_w, "--")):
            ax.plot(cx + 0.5 * d * np.cos(t), 0.5 * d * np.sin(t), "k", ls=style, lw=0.4)
    ax.plot(*np.array(loa["ends"]).T, color="#2e8b57", lw=1.0,
            label="line of action N1N2")
    for key in ("A", "P", "E"):
        ax.plot(*loa[key], "o", color="#2e8b57", ms=4)
        ax.annotate(key, loa[key], textcoords="offset points", xytext=(4, 4), fontsize=8)
    span = max(6.0 * g.inp.m_n, 1.3 * float(np.linalg.norm(loa["E"] - loa["A"])))
    cx = 0.5 * g.g1.d_w
    ax.set_xlim(cx - span, cx + span)
    ax.set_ylim(-span, span)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    ax.set_title(f"mesh at a_w = {g.a_w:.3f} mm (dotted: base circles, dashed: pitch circles)",
                 fontsize=9)
    ax.legend(loc="lower left", fontsize=7)
    s = sliding_along_path(g)
    ax2.plot(s["rho1"], s["theta1"], label="ϑ1 pinion")
    ax2.plot(s["rho1"], s["theta2"], label="ϑ2 wheel")
    ax2.set_ylim(max(-6.0, min(s["theta1"].min(), s["theta2"].min()) - 0.2), 1.2)
    ax2.set_xlabel("roll distance ρ1 of the pinion along the path A…E, mm")
    ax2.set_ylabel("specific sliding")
    ax2.axvline(0.5 * g.g1.d_w * math.sin(g.alpha_tw), color="grey", lw=0.5)
    ax3 = ax2.twinx()
    ax3.plot(s["rho1"], s["sigma_rel"], color="k", ls="--", lw=0.8,
             label="σ_H / σ_H(P), one pair")
    ax3.set_ylabel("contact stress relative to the pitch point")
    h1, l1 = ax2.get_legend_handles_labels()
    h2, l2 = ax3.get_legend_handles_labels()
    ax2.legend(h1 + h2, l1 + l2, loc="lower right", fontsize=7)
    ax2.grid(True, lw=0.3)
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format=path.suffix.lower()[1:], dpi=120)
    return path
