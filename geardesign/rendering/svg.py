"""Small self-contained SVG charts for the report: axes with round ticks and labelled
axes, lines, markers with labels, vertical marks.  No matplotlib (a report without
``--plot`` imports none) and nothing outside the document; every text escaped.

Coordinates: each chart is an ``<svg>`` with a ``viewBox`` of ``width × height`` user
units and ``width: 100%`` in the page, so it scales with the column; its margins hold the
tick labels and the axis titles, which are therefore never clipped.
"""

from __future__ import annotations

import math
import re
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.rendering.typeset import e

PALETTE = ("#1f4e9e", "#b22222", "#2e8b57", "#8a5a00", "#6a3d9a", "#444444")
"""Line colours, in order (dark enough on white and on paper)."""


def nice_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    """About ``n`` round tick values (1, 2, 2.5, 5 × 10^k) covering [lo, hi]."""
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return [0.0, 1.0]
    if hi <= lo:
        pad = abs(lo) * 0.1 or 1.0
        lo, hi = lo - pad, hi + pad
    raw = (hi - lo) / max(n, 1)
    k = 10.0 ** math.floor(math.log10(raw))
    step = next(s * k for s in (1, 2, 2.5, 5, 10) if s * k >= raw)
    first = math.floor(lo / step + 1e-9) * step
    ticks, t = [], first
    while t <= hi + step * 0.5 and len(ticks) < 50:
        ticks.append(round(t, 12))
        t += step
    if ticks[-1] < hi - 1e-9 * step:
        ticks.append(round(t, 12))
    return ticks


def tick_text(v: float, ticks: list[float]) -> str:
    step = abs(ticks[1] - ticks[0]) if len(ticks) > 1 else 1.0
    if step >= 1 and abs(v) < 1e6:
        return f"{v:.0f}"
    if abs(v) >= 1e6 or (step < 1e-3 and v != 0):
        return f"{v:.2g}"
    dec = max(0, -math.floor(math.log10(step)) + (1 if step * 10 ** math.floor(
        -math.log10(step)) % 1 else 0))
    return f"{v:.{min(dec, 6)}f}"


@dataclass
class Series:
    label: str
    x: list
    y: list
    color: str = ""
    dash: str = ""           # SVG stroke-dasharray, "" solid
    marker: bool = False     # a dot at each point
    line: bool = True
    point_labels: list = field(default_factory=list)   # text beside each point


@dataclass
class Chart:
    """One x–y chart."""

    xlabel: str
    ylabel: str
    series: list
    title: str = ""
    marks: list = field(default_factory=list)      # (x, text): vertical dashed lines
    hlines: list = field(default_factory=list)     # (y, text): horizontal dashed lines
    width: int = 640
    height: int = 260
    zero: bool = True                              # show y = 0 when in range


def _finite(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def chart_svg(c: Chart, role_label: str = "") -> str:
    """The chart as an inline ``<svg>`` element."""
    labelled = [s for s in c.series if s.label]
    legend_row = len(labelled) > 1 or bool(labelled and labelled[0].marker)
    L, R, B = 70, 16, 46
    T = 12 + (18 if c.title else 0) + (18 if legend_row else 0)
    W, H = c.width, c.height
    pw, ph = W - L - R, H - T - B
    xs = [v for s in c.series for v in s.x if _finite(v)] + [x for x, _ in c.marks]
    ys = [v for s in c.series for v in s.y if _finite(v)] + [y for y, _ in c.hlines]
    if not xs or not ys:
        return ""
    ymin, ymax = min(ys), max(ys)
    if c.zero and ymin > 0 and ymin < 0.3 * ymax:
        ymin = 0.0
    xt, yt = nice_ticks(min(xs), max(xs)), nice_ticks(ymin, ymax)
    x0, x1, y0, y1 = xt[0], xt[-1], yt[0], yt[-1]

    def X(v: float) -> float:
        return L + (v - x0) / ((x1 - x0) or 1.0) * pw

    def Y(v: float) -> float:
        return T + ph - (v - y0) / ((y1 - y0) or 1.0) * ph

    out = [f'<svg class="chart" viewBox="0 0 {W} {H}" role="img" '
           f'aria-label="{e(role_label or c.title or c.ylabel)}" '
           f'xmlns="http://www.w3.org/2000/svg" font-family="sans-serif" font-size="11">']
    if c.title:
        out.append(f'<text x="{L}" y="16" font-weight="bold" font-size="12">{e(c.title)}</text>')
    for v in yt:
        out.append(f'<line x1="{L}" x2="{L + pw}" y1="{Y(v):.1f}" y2="{Y(v):.1f}" '
                   f'stroke="#e4e4e4"/><text x="{L - 5}" y="{Y(v) + 4:.1f}" '
                   f'text-anchor="end">{e(tick_text(v, yt))}</text>')
    for v in xt:
        out.append(f'<line x1="{X(v):.1f}" x2="{X(v):.1f}" y1="{T}" y2="{T + ph}" '
                   f'stroke="#f0f0f0"/><text x="{X(v):.1f}" y="{T + ph + 15}" '
                   f'text-anchor="middle">{e(tick_text(v, xt))}</text>')
    out.append(f'<rect x="{L}" y="{T}" width="{pw}" height="{ph}" fill="none" '
               f'stroke="#888"/>')
    if c.zero and y0 < 0 < y1:
        out.append(f'<line x1="{L}" x2="{L + pw}" y1="{Y(0):.1f}" y2="{Y(0):.1f}" '
                   f'stroke="#888"/>')
    out.append(f'<text x="{L + pw / 2:.1f}" y="{H - 8}" text-anchor="middle">'
               f'{e(c.xlabel)}</text>')
    out.append(f'<text transform="translate(14 {T + ph / 2:.1f}) rotate(-90)" '
               f'text-anchor="middle">{e(c.ylabel)}</text>')
    for x, text in c.marks:       # the label along its line, reading upwards
        out.append(f'<line x1="{X(x):.1f}" x2="{X(x):.1f}" y1="{T}" y2="{T + ph}" '
                   f'stroke="#b22222" stroke-dasharray="4 3"/><text transform="translate('
                   f'{X(x) - 4:.1f} {T + 4}) rotate(-90)" text-anchor="end" fill="#b22222" '
                   f'font-size="10" paint-order="stroke" stroke="#fff" stroke-width="3">'
                   f'{e(text)}</text>')
    for y, text in c.hlines:
        out.append(f'<line x1="{L}" x2="{L + pw}" y1="{Y(y):.1f}" y2="{Y(y):.1f}" '
                   f'stroke="#b22222" stroke-dasharray="4 3"/><text x="{L + pw - 3}" '
                   f'y="{Y(y) - 3:.1f}" text-anchor="end" fill="#b22222">{e(text)}</text>')
    legend = []
    for i, s in enumerate(c.series):
        color = s.color or PALETTE[i % len(PALETTE)]
        pts = [(X(a), Y(b)) for a, b in zip(s.x, s.y) if _finite(a) and _finite(b)]
        if s.line and len(pts) > 1:
            segs, cur = [], []
            for a, b in zip(s.x, s.y):      # a gap (None) breaks the line
                if _finite(a) and _finite(b):
                    cur.append(f"{X(a):.1f},{Y(b):.1f}")
                elif cur:
                    segs.append(cur)
                    cur = []
            if cur:
                segs.append(cur)
            dash = f' stroke-dasharray="{s.dash}"' if s.dash else ""
            for seg in segs:
                out.append(f'<polyline fill="none" stroke="{color}" stroke-width="1.6"{dash} '
                           f'points="{" ".join(seg)}"/>')
        if s.marker:
            for px, py in pts:
                out.append(f'<circle cx="{px:.1f}" cy="{py:.1f}" r="3.2" fill="{color}"/>')
        for (px, py), text in zip(pts, s.point_labels):
            out.append(f'<text x="{px + 5:.1f}" y="{py - 5:.1f}" font-size="10" '
                       f'fill="{color}">{e(text)}</text>')
        if s.label:
            legend.append((s.label, color, s.dash, s.line))
    if legend_row:                # one row above the frame, never over the data
        lx, ly = L, T - 8
        for label, color, dash, line in legend:
            if lx + 30 + 6.5 * len(label) > W - R:
                break                  # no room left in the row: the caption explains
            d = f' stroke-dasharray="{dash}"' if dash else ""
            out.append(f'<line x1="{lx}" x2="{lx + 18}" y1="{ly - 4}" y2="{ly - 4}" '
                       f'stroke="{color}" stroke-width="{1.6 if line else 6}"{d}/>'
                       f'<text x="{lx + 22}" y="{ly}">{e(label)}</text>')
            lx += 40 + 6.5 * len(label)
    out.append("</svg>")
    return "".join(out)


_VIEWBOX = re.compile(r'viewBox="([-\d.e]+) ([-\d.e]+) ([-\d.e]+) ([-\d.e]+)"')


def stack_svg(svgs: list[str], captions: list[str], width: int = 640) -> str:
    """Several ``<svg>`` elements one below the other in one SVG document, each scaled to
    ``width`` and followed by its caption (``--plot FILE.svg`` of the report's pictures)."""
    parts, y = [], 0.0
    for svg, caption in zip(svgs, captions):
        m = _VIEWBOX.search(svg)
        if m is None:
            continue
        w, h = float(m.group(3)), float(m.group(4))
        hh = width * h / w
        inner = svg.replace("<svg ", f'<svg x="0" y="{y:.1f}" width="{width}" '
                            f'height="{hh:.1f}" ', 1)
        parts.append(inner)
        y += hh + 6
        parts.append(f'<text x="0" y="{y + 10:.1f}" font-family="sans-serif" font-size="11" '
                     f'fill="#555">{e(caption)}</text>')
        y += 24
    return (f'<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="http://www.w3.org/2000/svg" '
            f'width="{width}" height="{y:.0f}" viewBox="0 0 {width} {y:.0f}">'
            + "".join(parts) + "</svg>\n")
