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
    starts at ρ1 = ρ_a2 − g_w ([ISO21771]; :mod:`geardesign.gears.internal`)."""
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
    if ext == ".svg":
        return _write_svg(result, path)
    g, allow = _pair_of(result)
    return _write_dxf(mesh(g, allow), g, path)


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


def _svg_path(pts: np.ndarray, box=None, digits: int = 6) -> str:
    """An outline as SVG path data (y up in the drawing is −y in SVG), closed; with ``box``
    (xmin, ymin, xmax, ymax) only the runs of points inside it, each an open subpath."""
    xy = pts.tolist()      # Python floats: formatted as numpy's, without the per-item cost
    if box is None:
        head = f"M{xy[0][0]:.{digits}f},{-xy[0][1]:.{digits}f}"
        body = " ".join(f"L{x:.{digits}f},{-y:.{digits}f}" for x, y in xy[1:])
        return f"{head} {body} Z"
    inside = ((pts[:, 0] >= box[0]) & (pts[:, 0] <= box[2]) & (pts[:, 1] >= box[1])
              & (pts[:, 1] <= box[3]))
    out, pen = [], False
    for (x, y), ok in zip(xy, inside.tolist()):
        if ok:
            out.append(f"{'L' if pen else 'M'}{x:.{digits}f},{-y:.{digits}f}")
        pen = bool(ok)
    return " ".join(out)


PROFILE_STROKE = 0.03
"""Stroke width of the tooth outlines as a fraction of the normal module: about 1 px at
the size a browser shows the pair, and a fine line in a CAD program (1 unit = 1 mm)."""


def profile_svg(result, zoom: bool = False) -> str:
    """The pair in mesh as an ``<svg>`` element: both outlines, the pitch (dashed), base
    (dotted), tip and root circles (thin), the line of action N1N2 with A, P and E; a
    ``viewBox`` in mm (1 unit = 1 mm), strokes relative to the module
    (:data:`PROFILE_STROKE`).  ``zoom``: the mesh region only (six modules or the path of
    contact around the pitch point, as the ``--plot`` picture), for the report; else both
    whole gears, for ``--profile FILE.svg``."""
    from geardesign.spur.profile import mesh

    g, allow = _pair_of(result)
    m = mesh(g, allow)
    loa = line_of_action(g)
    mn = g.inp.m_n
    sw = PROFILE_STROKE * mn
    if zoom:
        span = max(6.0 * mn, 1.3 * float(np.linalg.norm(loa["E"] - loa["A"])))
        cx = float(loa["P"][0])
        cy = float(loa["P"][1])
        box = (cx - 1.6 * span, cy - span, cx + 1.6 * span, cy + span)
        lo, hi = np.array(box[:2]), np.array(box[2:])
        clip = (box[0] - span, box[1] - span, box[2] + span, box[3] + span)
        digits = 4
    else:
        lo = np.minimum(m.pinion.min(axis=0), m.wheel.min(axis=0)) - 1.0
        hi = np.maximum(m.pinion.max(axis=0), m.wheel.max(axis=0)) + 1.0
        clip, digits = None, 6
    w, h = hi - lo
    size = (f'width="{w:.3f}mm" height="{h:.3f}mm" ' if not zoom
            else 'class="figure-profile" role="img" aria-label="tooth profiles in mesh" ')
    text = [f'<svg xmlns="http://www.w3.org/2000/svg" {size}'
            f'viewBox="{lo[0]:.6f} {-hi[1]:.6f} {w:.6f} {h:.6f}">']
    if not zoom:
        text.append('<!-- geardesign: transverse tooth profiles in mesh, 1 unit = 1 mm, '
                    'y up in the drawing is -y here -->')
    for name, centre, gi in (("pinion", (0.0, 0.0), g.g1), ("wheel", m.centre2, g.g2)):
        for circle, d, dash in (("pitch", gi.d_w, f"{4 * sw:.4f} {2 * sw:.4f}"),
                                ("base", gi.d_b, f"{sw:.4f} {2 * sw:.4f}"),
                                ("tip", gi.d_a, ""), ("root", gi.d_f, "")):
            dash_attr = f' stroke-dasharray="{dash}"' if dash else ""
            text.append(f'<circle id="{name}_{circle}" cx="{centre[0]:.6f}" '
                        f'cy="{-centre[1]:.6f}" r="{0.5 * abs(d):.6f}" fill="none" '
                        f'stroke="#777" stroke-width="{0.5 * sw:.4f}"{dash_attr}/>')
    text.append(f'<path id="pinion" fill="#9db7e0" fill-opacity="0.5" stroke="#1f4e9e" '
                f'stroke-width="{sw:.4f}" d="{_svg_path(m.pinion, clip, digits)}"/>')
    text.append(f'<path id="wheel" fill="#e8a0a0" fill-opacity="0.45" '
                f'stroke="#b22222" stroke-width="{sw:.4f}" '
                f'd="{_svg_path(m.wheel, clip, digits)}"/>')
    (x1, y1), (x2, y2) = loa["ends"]
    text.append(f'<line id="line_of_action" x1="{x1:.6f}" y1="{-y1:.6f}" x2="{x2:.6f}" '
                f'y2="{-y2:.6f}" stroke="#2e8b57" stroke-width="{sw:.4f}"/>')
    for key in ("A", "P", "E"):
        px, py = loa[key]
        text.append(f'<circle cx="{px:.6f}" cy="{-py:.6f}" r="{3 * sw:.4f}" fill="#2e8b57"/>'
                    f'<text x="{px + 4 * sw:.6f}" y="{-py - 4 * sw:.6f}" '
                    f'font-size="{0.6 * mn:.4f}" font-family="sans-serif">{key}</text>')
    text.append("</svg>")
    return "\n".join(text)


def _write_svg(result, path: Path) -> Path:
    text = '<?xml version="1.0" encoding="UTF-8"?>\n' + profile_svg(result) + "\n"
    with atomic_path(path) as tmp:
        Path(tmp).write_text(text, encoding="utf-8")
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
