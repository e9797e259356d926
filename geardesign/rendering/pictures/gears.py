"""The pictures of the gear pairs: the spur/helical teeth in mesh
(:func:`geardesign.spur.export.profile_svg`), the planetary layout to scale (sun, planets
on the carrier circle, ring or rings) and the worm pair in the mid-plane of the wheel."""

from __future__ import annotations

from geardesign.rendering.pictures.base import Figure, rows
from geardesign.rendering.typeset import e, number_text


def spur_figures(res) -> dict:
    if getattr(res, "pair_geometry", None) is None:
        return {}
    from geardesign.spur.export import ExportError, profile_svg

    try:
        svg = profile_svg(res, zoom=True)
    except (ExportError, ValueError, IndexError):   # a pair the outline cannot be drawn for
        return {}
    return {"geometry": [Figure("Tooth profiles in mesh (transverse section): pitch circles "
                                "dashed, base circles dotted, tip and root circles thin; "
                                "line of action with the ends A, E of the path of contact "
                                "and the pitch point P", svg)]}


def planetary_figures(res) -> dict:
    g, asm = rows(res, "gears"), rows(res, "assembly")
    angles = asm.get("planet_angles")
    a_w = asm.get("a_w_sun_planet")
    if angles is None or a_w is None or "d_a_sun" not in g:
        return {}
    svg = _layout(g, a_w.value, angles.value)
    return {"gears": [Figure("Layout to scale: sun, planets on the carrier circle, ring(s); "
                             "tip circles solid, root circles dashed", svg)]} if svg else {}


def _layout(g: dict, a_w: float, angles: list) -> str:
    import math

    def val(k):
        row = g.get(k)
        return abs(row.value) if row is not None and isinstance(row.value, (int, float)) \
            else None

    rings = [n for n in ("ring", "ring2") if val(f"d_f_{n}")]
    R = max([val(f"d_f_{n}") / 2 for n in rings] + [a_w + val("d_a_planet") / 2]) * 1.06
    sw = R / 250
    out = [f'<svg class="diagram" viewBox="{-R:.3f} {-R:.3f} {2 * R:.3f} {2 * R:.3f}" '
           f'role="img" aria-label="planetary layout" xmlns="http://www.w3.org/2000/svg" '
           f'style="max-width:460px">']

    def circle(cx, cy, d, color, dash=False, fill="none"):
        if d:
            dd = f' stroke-dasharray="{4 * sw:.3f} {2 * sw:.3f}"' if dash else ""
            out.append(f'<circle cx="{cx:.3f}" cy="{cy:.3f}" r="{d / 2:.3f}" fill="{fill}" '
                       f'stroke="{color}" stroke-width="{sw:.3f}"{dd}/>')

    for n, color in zip(rings, ("#b22222", "#8a5a00")):
        circle(0, 0, val(f"d_a_{n}"), color, fill="none")
        circle(0, 0, val(f"d_f_{n}"), color, dash=True)
    circle(0, 0, 2 * a_w, "#777", dash=True)                     # carrier circle
    circle(0, 0, val("d_a_sun"), "#1f4e9e", fill="#dbe5f5")
    circle(0, 0, val("d_f_sun"), "#1f4e9e", dash=True)
    for ang in angles:
        t = math.radians(ang)
        x, y = a_w * math.cos(t), -a_w * math.sin(t)
        out.append(f'<line x1="0" y1="0" x2="{x:.3f}" y2="{y:.3f}" stroke="#777" '
                   f'stroke-width="{2 * sw:.3f}"/>')
        circle(x, y, val("d_a_planet"), "#2e8b57", fill="#dff0e5")
        circle(x, y, val("d_f_planet"), "#2e8b57", dash=True)
        circle(x, y, 4 * sw, "#555", fill="#555")
    circle(0, 0, 6 * sw, "#555", fill="#555")
    out.append("</svg>")
    return "".join(out)


def worm_figures(res) -> dict:
    """The worm pair in the mid-plane of the wheel, to scale: the wheel's outside, tip,
    reference and root circles, the worm as its tip cylinder of length b1 with the
    reference and root lines, the centre distance a_w."""
    g = rows(res, "geometry")
    need = ("a_w", "d1", "d_a1", "d_f1", "d2", "d_a2", "d_f2")
    if not all(k in g and isinstance(g[k].value, (int, float)) for k in need):
        return {}
    v = {k: float(g[k].value) for k in need}
    dam2 = float(g["d_aM2"].value) if "d_aM2" in g else v["d_a2"]
    b1 = float(g["b1"].value) if "b1" in g else 2.0 * v["d_a1"]
    a = v["a_w"]
    R = max(dam2 / 2, b1 / 2) * 1.08
    top = -(a + v["d_a1"] / 2) - 0.06 * R
    height = (dam2 / 2 + 0.06 * R) - top
    sw = R / 220
    out = [f'<svg class="diagram" viewBox="{-R:.3f} {top:.3f} {2 * R:.3f} {height:.3f}" '
           f'role="img" aria-label="worm pair" xmlns="http://www.w3.org/2000/svg" '
           f'style="max-width:520px" font-family="sans-serif" font-size="{R / 22:.3f}">']
    for d, dash, color in ((dam2, "", "#b22222"), (v["d_a2"], "", "#b22222"),
                           (v["d2"], f"{6 * sw} {2 * sw} {sw} {2 * sw}", "#555"),
                           (v["d_f2"], f"{4 * sw} {2 * sw}", "#b22222")):
        dd = f' stroke-dasharray="{dash}"' if dash else ""
        out.append(f'<circle cx="0" cy="0" r="{d / 2:.3f}" fill="none" stroke="{color}" '
                   f'stroke-width="{sw:.3f}"{dd}/>')
    y0 = -a
    out.append(f'<rect x="{-b1 / 2:.3f}" y="{y0 - v["d_a1"] / 2:.3f}" width="{b1:.3f}" '
               f'height="{v["d_a1"]:.3f}" fill="#dbe5f5" stroke="#1f4e9e" '
               f'stroke-width="{sw:.3f}"/>')
    for d, dash in ((v["d1"], f"{6 * sw} {2 * sw} {sw} {2 * sw}"), (v["d_f1"], f"{4 * sw} {2 * sw}")):
        for sgn in (-1, 1):
            y = y0 + sgn * d / 2
            out.append(f'<line x1="{-b1 / 2:.3f}" x2="{b1 / 2:.3f}" y1="{y:.3f}" y2="{y:.3f}" '
                       f'stroke="#1f4e9e" stroke-width="{sw / 2:.3f}" stroke-dasharray="{dash}"/>')
    out.append(f'<line x1="0" y1="0" x2="0" y2="{y0:.3f}" stroke="#2e8b57" '
               f'stroke-width="{sw:.3f}"/><text x="{2 * sw:.3f}" y="{y0 / 2:.3f}" '
               f'fill="#2e8b57">a_w = {e(number_text(a, "mm"))} mm</text></svg>')
    return {"geometry": [Figure("Worm pair in the mid-plane of the wheel, to scale: wheel "
                                "outside, tip, reference (dash-dot) and root (dashed) "
                                "circles; worm tip cylinder of length b1 with its reference "
                                "and root lines", "".join(out))]}
