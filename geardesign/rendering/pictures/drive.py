"""The pictures of a drive: the power flow motor → stages → output (torque, speed, ratio,
efficiency of each stage), the bearing lives and the heat balance (losses per stage and
kind, sump temperature)."""

from __future__ import annotations

from geardesign.rendering.pictures.base import Figure, rows, table, value
from geardesign.rendering.svg import PALETTE
from geardesign.rendering.typeset import SUPERSCRIPT, e, number_text


def drive_figures(res) -> dict:
    stages = table(res, "stages")
    if stages is None or not stages.rows:
        return {}
    d = rows(res, "drive")
    figs = [Figure("Power flow: motor → stages → output, torque and speed at each shaft, "
                   "ratio and efficiency of each stage", _power_flow(stages.rows, d))]
    bearings = table(res, "bearings")
    life = _bearing_lives(bearings.rows, res.checks) if bearings is not None else ""
    if life:
        figs.append(Figure("Bearing lives (logarithmic scale) against the required life "
                           "(red line), and the radial load of each bearing", life))
    losses = table(res, "losses")
    thermal = rows(res, "thermal")
    heat = _heat_balance(losses, thermal) if losses is not None else ""
    if heat:
        figs.append(Figure("Heat balance: power losses per stage and kind, and the sump "
                           "temperature they settle at", heat))
    return {"": figs}


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
        shaft_label(x + gap / 2, value(r, "T_in"), value(r, "n_in"))
        x += gap
        u, eta = value(r, "ratio"), value(r, "efficiency")
        lines = [str(r.get("name") or r.get("kind") or "")[:22]]
        if u is not None:
            lines.append(f"u = {number_text(u, '-')}" + (f", η = {number_text(eta, '-')}"
                                                         if eta is not None else ""))
        fill = "#fbeaea" if str(r.get("verdict", "")).lower() == "fail" else "#eef7ef"
        box(x, f"stage {r.get('stage', i + 1)}", lines, fill)
        x += bw
    arrow(x, x + gap)
    last = rows[-1]
    shaft_label(x + gap / 2, value(last, "T_out"), value(last, "n_out"))
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

    lives = [(r, value(r, "life")) for r in rows]
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
        fr = value(r, "F_r")
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
    rows = [r for r in losses.rows if value(r, "total") is not None]
    if not rows:
        return ""
    total = max(value(r, "total") for r in rows) or 1.0
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
            v = value(r, key) or 0.0
            w = max(0.0, v / total * pw)
            if w > 0:
                out.append(f'<rect x="{x:.1f}" y="{y}" width="{w:.1f}" height="{bar}" '
                           f'fill="{PALETTE[j]}"><title>{e(key)}: {e(number_text(v, "W"))} W'
                           f'</title></rect>')
            x += w
        out.append(f'<text x="{x + 5:.1f}" y="{y + 15}">{e(number_text(value(r, "total"), "W"))}'
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
