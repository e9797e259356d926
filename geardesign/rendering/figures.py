"""The pictures of a result for the report, as inline SVG: ``figures(res)`` maps a
section key (``""`` for the top of the report, after the summary) to a list of
:class:`Figure`.  Drawn from the result alone (its rows and tables, the spur pair's
geometry), never recomputed; a kind without a picture gets none.

* spur/helical pair: the tooth profiles in mesh with the pitch, base, tip and root circles
  and the line of action (:func:`geardesign.spur.export.profile_svg`);
* shaft: shear force, bending moment and torque, and deflection along the shaft, the
  critical sections marked;
* drive: the power flow motor → stages → output (torque, speed, ratio, efficiency of
  each stage) and the heat balance (losses per stage and kind, sump temperature);
* sweep: the ranked variants and the Pareto front in the plane of the first two
  objectives, each point labelled with its rank;
* worm: the pair in the mid-plane of the wheel, to scale;
* planetary: the layout to scale (sun, planets on the carrier circle, ring or rings);
* pzdn: the start-up torques and speeds; geneva: the motion law and the load over the
  crank angle; novikov: stresses and loads over the contact phases; ball clutch: the
  limit torque against speed; epicycle rim: the Mathieu stability chart.
"""

from __future__ import annotations

from geardesign.core.records import dataclass
from geardesign.rendering.svg import PALETTE, Chart, Series, chart_svg
from geardesign.rendering.typeset import SUPERSCRIPT, e, number_text, unit_text


@dataclass(frozen=True)
class Figure:
    caption: str
    svg: str          # an <svg> element


def _rows(res, key: str) -> dict:
    for s in res.sections:
        if s.key == key:
            return {r.key: r for r in s.rows}
    return {}


def _table(res, key: str):
    for t in res.tables:
        if t.key == key:
            return t
    return None


def _spur(res) -> dict:
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


def _shaft(res) -> dict:
    d = _rows(res, "diagrams")
    if "x" not in d or not isinstance(d["x"].value, list):
        return {}
    x = d["x"].value
    strength = _rows(res, "strength")
    marks = []
    for key, label in (("x_critical", "critical (fatigue)"),):
        row = strength.get(key)
        if row is not None and isinstance(row.value, (int, float)):
            name = strength.get("critical_section")
            marks.append((row.value, f"{label}: {name.value}" if name else label))
    sections = _table(res, "sections")
    if sections is not None and "S_static" in strength:
        worst = min((r for r in sections.rows if isinstance(r.get("S_static"), (int, float))),
                    key=lambda r: r["S_static"], default=None)
        if worst is not None and isinstance(worst.get("x"), (int, float)):
            marks.append((worst["x"], f"critical (static): {worst.get('label', '')}"))

    def series(keys):
        out = []
        for i, k in enumerate(keys):
            if k in d and isinstance(d[k].value, list) and len(d[k].value) == len(x):
                out.append(Series(d[k].symbol or k, x, d[k].value, PALETTE[i]))
        return out

    def unit(keys):
        return next((unit_text(d[k].unit) for k in keys if k in d), "")

    charts = []
    for title, keys, ylabel in (
            ("Shear force", ("V_y", "V_z"), "V"), ("Bending moment and torque",
                                                  ("M_y", "M_z", "M", "T"), "M, T"),
            ("Deflection", ("w_y", "w_z", "w"), "w")):
        ss = series(keys)
        if ss:
            charts.append(Chart("position along the shaft x, mm", f"{ylabel}, {unit(keys)}",
                                ss, title=title, marks=marks, height=220))
    figs = [Figure(c.title + " along the shaft" + (", critical sections marked" if marks
                                                    else ""), chart_svg(c)) for c in charts]
    return {"diagrams": [f for f in figs if f.svg]}


def _drive(res) -> dict:
    stages = _table(res, "stages")
    if stages is None or not stages.rows:
        return {}
    d = _rows(res, "drive")
    figs = [Figure("Power flow: motor → stages → output, torque and speed at each shaft, "
                   "ratio and efficiency of each stage", _power_flow(stages.rows, d))]
    bearings = _table(res, "bearings")
    life = _bearing_lives(bearings.rows, res.checks) if bearings is not None else ""
    if life:
        figs.append(Figure("Bearing lives (logarithmic scale) against the required life "
                           "(red line), and the radial load of each bearing", life))
    losses = _table(res, "losses")
    thermal = _rows(res, "thermal")
    heat = _heat_balance(losses, thermal) if losses is not None else ""
    if heat:
        figs.append(Figure("Heat balance: power losses per stage and kind, and the sump "
                           "temperature they settle at", heat))
    return {"": figs}


def _val(row, unit):
    v = row.get(unit) if isinstance(row, dict) else None
    return v if isinstance(v, (int, float)) and not isinstance(v, bool) else None


def _power_flow(rows: list, drive: dict) -> str:
    n = len(rows)
    bw, gap, h = 150, 70, 150
    W = 2 * 110 + n * bw + (n + 1) * gap
    out = [f'<svg class="diagram" viewBox="-2 0 {W + 4} {h}" role="img" aria-label="power flow" '
           f'xmlns="http://www.w3.org/2000/svg" font-family="sans-serif" font-size="12">',
           '<defs><marker id="arrow" viewBox="0 0 10 10" refX="10" refY="5" markerWidth="7" '
           'markerHeight="7" orient="auto"><path d="M0,0L10,5L0,10z" fill="#555"/></marker>'
           '</defs>']

    def box(x, title, lines, fill):
        out.append(f'<rect x="{x}" y="35" width="{bw if lines else 110}" height="80" rx="6" '
                   f'fill="{fill}" stroke="#555"/>')
        wdt = bw if lines else 110
        out.append(f'<text x="{x + wdt / 2}" y="56" text-anchor="middle" font-weight="bold">'
                   f'{e(title)}</text>')
        for j, line in enumerate(lines):
            out.append(f'<text x="{x + wdt / 2}" y="{76 + 17 * j}" text-anchor="middle">'
                       f'{e(line)}</text>')

    def shaft_label(x, T, nn):
        if T is not None:
            out.append(f'<text x="{x}" y="28" text-anchor="middle">T = {e(number_text(T, "N·m"))}'
                       f' N·m</text>')
        if nn is not None:
            out.append(f'<text x="{x}" y="136" text-anchor="middle">n = '
                       f'{e(number_text(nn, "min^-1"))} min⁻¹</text>')

    def arrow(x1, x2):
        out.append(f'<line x1="{x1}" y1="75" x2="{x2}" y2="75" stroke="#555" stroke-width="2" '
                   f'marker-end="url(#arrow)"/>')

    P = drive.get("P_m")
    box(0, "motor", [], "#eef3fb")
    if P is not None and isinstance(P.value, (int, float)):
        out.append(f'<text x="55" y="80" text-anchor="middle">{e(number_text(P.value, "kW"))}'
                   f' kW</text>')
    x = 110
    for i, r in enumerate(rows):
        arrow(x, x + gap)
        shaft_label(x + gap / 2, _val(r, "T_in"), _val(r, "n_in"))
        x += gap
        u, eta = _val(r, "ratio"), _val(r, "efficiency")
        lines = [str(r.get("name") or r.get("kind") or "")[:22]]
        if u is not None:
            lines.append(f"u = {number_text(u, '-')}" + (f", η = {number_text(eta, '-')}"
                                                         if eta is not None else ""))
        fill = "#fbeaea" if str(r.get("verdict", "")).lower() == "fail" else "#eef7ef"
        box(x, f"stage {r.get('stage', i + 1)}", lines, fill)
        x += bw
    arrow(x, x + gap)
    last = rows[-1]
    shaft_label(x + gap / 2, _val(last, "T_out"), _val(last, "n_out"))
    box(x + gap, "output", [], "#eef3fb")
    Po = drive.get("P_out")
    if Po is not None and isinstance(Po.value, (int, float)):
        out.append(f'<text x="{x + gap + 55}" y="80" text-anchor="middle">'
                   f'{e(number_text(Po.value, "kW"))} kW</text>')
    out.append("</svg>")
    return "".join(out)


def _bearing_lives(rows: list, checks: list) -> str:
    """Horizontal bars of the bearings' lives on a logarithmic scale, the required life
    (the limit of the ``BEARING_…`` checks) as a red line, the radial load beside."""
    import math

    lives = [(r, _val(r, "life")) for r in rows]
    lives = [(r, v) for r, v in lives if v is not None and v > 0]
    need = next((c.limit for c in checks if c.code.startswith("BEARING_")
                 and isinstance(c.limit, (int, float)) and c.limit > 0), None)
    if not lives:
        return ""
    values = [v for _, v in lives] + ([need] if need else [])
    lo = 10 ** math.floor(math.log10(min(values)))
    hi = 10 ** math.ceil(math.log10(max(values)))
    if hi <= lo:
        hi = lo * 10
    W, L, R, bar = 640, 80, 200, 16
    H = 30 + len(lives) * (bar + 8) + 36
    pw = W - L - R

    def X(v):
        return L + (math.log10(v) - math.log10(lo)) / (math.log10(hi) - math.log10(lo)) * pw

    out = [f'<svg class="chart" viewBox="0 0 {W} {H}" role="img" aria-label="bearing lives" '
           f'xmlns="http://www.w3.org/2000/svg" font-family="sans-serif" font-size="11">']
    y = 20
    for r, v in lives:
        ok = need is None or v >= need
        out.append(f'<text x="{L - 6}" y="{y + 12}" text-anchor="end">shaft '
                   f'{e(r.get("shaft", ""))}, {e(r.get("bearing", ""))}</text>'
                   f'<rect x="{L}" y="{y}" width="{max(1.0, X(v) - L):.1f}" height="{bar}" '
                   f'fill="{PALETTE[2] if ok else PALETTE[1]}"/>')
        fr = _val(r, "F_r")
        out.append(f'<text x="{W - R + 6}" y="{y + 12}">{e(number_text(v, "h"))} h'
                   + (f", F_r {e(number_text(fr, 'N'))} N" if fr is not None else "")
                   + "</text>")
        y += bar + 8
    k = lo
    while k <= hi * 1.0001:
        out.append(f'<line x1="{X(k):.1f}" x2="{X(k):.1f}" y1="14" y2="{y}" stroke="#ddd"/>'
                   f'<text x="{X(k):.1f}" y="{y + 14}" text-anchor="middle">'
                   f'10{str(round(math.log10(k))).translate(SUPERSCRIPT)}</text>')
        k *= 10
    if need:
        out.append(f'<line x1="{X(need):.1f}" x2="{X(need):.1f}" y1="14" y2="{y}" '
                   f'stroke="#b22222" stroke-width="2"/><text x="{X(need) + 4:.1f}" y="12" '
                   f'fill="#b22222">required {e(number_text(need, "h"))} h</text>')
    out.append(f'<text x="{L + pw / 2:.1f}" y="{H - 6}" text-anchor="middle">life L, h '
               f'(logarithmic)</text></svg>')
    return "".join(out)


LOSS_KINDS = (("mesh", "mesh"), ("churning", "churning"), ("bearings", "bearings"),
              ("seals", "seals"), ("other", "by own η"))


def _heat_balance(losses, thermal: dict) -> str:
    rows = [r for r in losses.rows if _val(r, "total") is not None]
    if not rows:
        return ""
    total = max(_val(r, "total") for r in rows) or 1.0
    W, L, bar = 640, 70, 22
    H = 34 + len(rows) * (bar + 12) + 30
    out = [f'<svg class="chart" viewBox="0 0 {W} {H}" role="img" aria-label="heat balance" '
           f'xmlns="http://www.w3.org/2000/svg" font-family="sans-serif" font-size="11">']
    for j, (key, label) in enumerate(LOSS_KINDS):
        out.append(f'<rect x="{L + 90 * j}" y="8" width="10" height="10" '
                   f'fill="{PALETTE[j]}"/><text x="{L + 90 * j + 14}" y="17">{e(label)}</text>')
    pw = W - L - 80
    y = 34
    for r in rows:
        x = L
        out.append(f'<text x="{L - 6}" y="{y + 15}" text-anchor="end">stage '
                   f'{e(r.get("stage", ""))}<title>{e(r.get("name", ""))}</title></text>')
        for j, (key, _) in enumerate(LOSS_KINDS):
            v = _val(r, key) or 0.0
            w = max(0.0, v / total * pw)
            if w > 0:
                out.append(f'<rect x="{x:.1f}" y="{y}" width="{w:.1f}" height="{bar}" '
                           f'fill="{PALETTE[j]}"><title>{e(key)}: {e(number_text(v, "W"))} W'
                           f'</title></rect>')
            x += w
        out.append(f'<text x="{x + 5:.1f}" y="{y + 15}">{e(number_text(_val(r, "total"), "W"))}'
                   f' W</text>')
        y += bar + 12
    t, pv, pq = thermal.get("t_oil"), thermal.get("P_V"), thermal.get("P_Q")
    if t is not None and isinstance(t.value, (int, float)):
        text = f"sump temperature {number_text(t.value, '°C')} °C"
        if pv is not None and isinstance(pv.value, (int, float)):
            text += f": losses P_V = {number_text(pv.value, 'W')} W"
        if pq is not None and isinstance(pq.value, (int, float)):
            text += f" = heat dissipated P_Q = {number_text(pq.value, 'W')} W"
        out.append(f'<text x="{L}" y="{y + 12}">{e(text)}</text>')
    out.append("</svg>")
    return "".join(out)


def _sweep(res) -> dict:
    ranked, front = _table(res, "ranked"), _table(res, "pareto")
    objectives = list(((res.inputs or {}).get("sweep") or {}).get("objectives") or [])
    if ranked is None or not ranked.rows:
        return {}
    names = objectives[:2] if len(objectives) > 1 else (objectives or ["mass"])[:1] + ["margin"]
    cols = {k: (h, u) for k, h, u in ranked.columns}
    if not all(n in cols for n in names):
        return {}

    def axis(n):
        head, unit = cols[n]
        u = unit_text(unit)
        return f"{head}, {u}" if u else head

    def pts(rows):
        ok = [r for r in rows if _val(r, names[0]) is not None and _val(r, names[1]) is not None]
        ok.sort(key=lambda r: r[names[0]])
        return ([r[names[0]] for r in ok], [r[names[1]] for r in ok],
                [f"#{r.get('rank')}" for r in ok])

    x, y, lab = pts(ranked.rows)
    series = [Series("ranked variants (#rank)", x, y, PALETTE[0], marker=True, line=False,
                     point_labels=lab)]
    if front is not None and front.rows:
        fx, fy, _ = pts(front.rows)
        series.append(Series("Pareto front", fx, fy, PALETTE[1], marker=True))
    c = Chart(axis(names[0]), axis(names[1]), series, zero=False, height=320)
    return {"": [Figure(f"Ranked variants and the Pareto front of {names[0]} and "
                              f"{names[1]}", chart_svg(c))]}


def _largest(values: list) -> list:
    """An array of arrays (a value per contact point of each phase) as the largest of
    each inner array; a flat array as it is."""
    out = []
    for v in values:
        if isinstance(v, list):
            finite = [x for x in v if isinstance(x, (int, float))]
            out.append(max(finite) if finite else None)
        else:
            out.append(v)
    return out


def _curves(res, key: str, x: str, xlabel: str, groups, x_from: str = "") -> dict:
    """Charts of the arrays of section ``key`` over the array ``x`` (of section
    ``x_from``, else the same): ``groups`` of ``(title, keys, ylabel)``; a key that is
    missing or of another length is left out; an array of arrays is drawn as the largest
    value of each (:func:`_largest`)."""
    d = _rows(res, key)
    dx = _rows(res, x_from) if x_from else d
    if x not in dx or not isinstance(dx[x].value, list):
        return {}
    xs = dx[x].value
    unit_x = unit_text(dx[x].unit)
    figs = []
    for title, keys, ylabel in groups:
        ss = [Series(d[k].symbol or k, xs, _largest(d[k].value), PALETTE[i % len(PALETTE)])
              for i, k in enumerate(keys)
              if k in d and isinstance(d[k].value, list) and len(d[k].value) == len(xs)]
        if ss:
            u = unit_text(d[keys[0]].unit) if keys[0] in d else ""
            c = Chart(f"{xlabel}, {unit_x}" if unit_x else xlabel,
                      f"{ylabel}, {u}" if u else ylabel, ss, title=title, height=240)
            figs.append(Figure(title, chart_svg(c)))
    return {key: figs}


def _pzdn(res) -> dict:
    return _curves(res, "history", "t", "time t", (
        ("Start-up: torques in the springs", ("T12", "T13"), "T"),
        ("Start-up: speeds of the three masses", ("omega1", "omega2", "omega3"), "ω")))


def _geneva(res) -> dict:
    out = _curves(res, "motion_law", "phi", "crank angle φ", (
        ("Motion law of the wheel, relative to the crank",
         ("omega2_ratio", "eps2_ratio", "power_ratio"), "ratio"),))
    out.update(_curves(res, "load", "phi", "crank angle φ", (
        ("Crank torque during the indexing", ("M1",), "M_1"),
        ("Force on the slot", ("F",), "F")), x_from="motion_law"))
    return out


def _novikov(res) -> dict:
    return _curves(res, "phases", "phase", "contact phase", (
        ("Stresses over the phases of engagement (largest over the contact points)",
         ("sigma_H", "sigma_F"), "σ"),
        ("Tooth load over the phases of engagement (largest over the contact points)",
         ("F_ideal", "F_max"), "F")))


def _ball_clutch(res) -> dict:
    return _curves(res, "speed", "n_grid", "speed n", (
        ("Limit torque against speed", ("T_lim_curve",), "T_lim"),))


def _epicycle_rim(res) -> dict:
    d = _rows(res, "resonance")
    if "chart_b" not in d:
        return {}
    q = d["chart_b"].value
    ss = []
    for n in range(8):           # a_n(q) solid, b_n(q) dashed, one colour per order
        for name, dash in ((f"chart_a{n}", ""), (f"chart_b{n}", "4 3")):
            if name in d and isinstance(d[name].value, list) and len(d[name].value) == len(q):
                ss.append(Series(f"order {n}" if not dash else "", q, d[name].value,
                                 PALETTE[n % len(PALETTE)], dash=dash))
    if "chart_line_a" in d:
        ss.append(Series("working line a = 2q/μ", q, d["chart_line_a"].value, "#000000",
                         dash="2 2"))
    c = Chart("q of Mathieu's equation", "characteristic value a", ss,
              title="Ince–Strutt stability chart", height=320, zero=False)
    return {"resonance": [Figure("Ince–Strutt chart of Mathieu's equation: characteristic "
                                 "values a_n(q) solid and b_n(q) dashed (unstable between "
                                 "them), and the working line of the rim", chart_svg(c))]}


def _planetary(res) -> dict:
    g, asm = _rows(res, "gears"), _rows(res, "assembly")
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


def _worm(res) -> dict:
    """The worm pair in the mid-plane of the wheel, to scale: the wheel's outside, tip,
    reference and root circles, the worm as its tip cylinder of length b1 with the
    reference and root lines, the centre distance a_w."""
    g = _rows(res, "geometry")
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


_BY_KIND = {"worm": _worm, "spur": _spur, "shaft": _shaft, "drive": _drive, "sweep": _sweep, "pzdn": _pzdn,
            "geneva": _geneva, "novikov": _novikov, "ball_clutch": _ball_clutch,
            "epicycle_rim": _epicycle_rim, "planetary": _planetary}


def figures(res) -> dict:
    """The figures of ``res`` by section key (``""``: after the summary)."""
    make = _BY_KIND.get(res.kind)
    if make is None:
        return {}
    try:
        out = make(res)
    except (KeyError, TypeError, ValueError, ZeroDivisionError, OverflowError):
        return {}          # a picture never stops the report
    return {k: [f for f in v if f.svg] for k, v in out.items()}


def has_figure(res) -> bool:
    return any(figures(res).values())


def plot_svg(res) -> str | None:
    """Every picture of ``res`` in one SVG document (``--plot FILE.svg``), or None when
    its kind has none."""
    from geardesign.rendering.svg import stack_svg

    figs = [f for fs in figures(res).values() for f in fs]
    if not figs:
        return None
    return stack_svg([f.svg for f in figs], [f.caption for f in figs])
