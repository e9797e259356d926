"""The first screen of the HTML report (:mod:`geardesign.rendering.html`): the governing
margins as bars (worst first, after the failed checks that have no ratio) and every failed
check and warning with its advice; and the document builder the sections extend
(:class:`Page`: its output and its unique element ids)."""

from __future__ import annotations

import re

from geardesign.core.result import Check, Result, fix_text
from geardesign.rendering.margins import Margin
from geardesign.rendering.typeset import e, symbol_html

FIRST_SCREEN_MARGINS = 8
"""Rows of the first screen's margins: the failed checks that have no ratio (at most six),
then the worst margins as bars (at least two); all margins are in "All margins"."""


class Ids:
    """Unique element ids from names (letters, digits, ``-``)."""

    def __init__(self) -> None:
        self.used: set[str] = set()

    def __call__(self, *parts: str) -> str:
        base = "-".join(re.sub(r"[^A-Za-z0-9]+", "-", str(p)).strip("-").lower()
                        for p in parts if p) or "s"
        out, n = base, 2
        while out in self.used:
            out, n = f"{base}-{n}", n + 1
        self.used.add(out)
        return out


def advice_html(c: Check) -> str:
    parts = []
    advice = getattr(c, "advice", "")
    if advice:
        parts.append(e(advice))
    if c.fix:
        parts.append("in the spec: " + e(fix_text(c.fix)))
    return "; ".join(parts)


def short(x: float) -> str:
    """A margin's value or limit, four significant digits."""
    if abs(x) >= 1e5:
        return f"{x:.3g}"
    return f"{x:.4g}"


class Page:
    """The document being built: its HTML pieces and element ids; the first screen."""
    def __init__(self) -> None:
        self.out: list[str] = []
        self.ids = Ids()

    def add(self, *html: str) -> None:
        self.out.extend(html)

    # ------------------------------------------------------------------ first screen

    def margin_bars(self, ms: list[Margin], all_id: str, failed: list[Check] = ()) -> None:
        self.add('<section class="margins" aria-label="governing margins">'
                 '<h2 id="{}">Governing margins</h2>'.format(self.ids("governing")))
        shown = {m.code for m in ms}
        extra = [c for c in failed if c.code not in shown][:FIRST_SCREEN_MARGINS - 2]
        for c in extra:            # a failed check without a ratio (a shift, a geometry)
            nums = (f"{short(c.value)} vs {short(c.limit)}"
                    if isinstance(c.value, (int, float)) and isinstance(c.limit, (int, float))
                    else "")
            self.add(f'<div class="bar-row" title="{e(c.message)}"><span class="lbl">'
                     f'<span class="code">{e(c.code)}</span></span><span class="bar failed">'
                     f'failed</span><span class="num">{e(nums)}</span></div>')
        if not ms:
            self.add('<p class="none">No safety factor or limit of this kind to compare.</p>'
                     "</section>")
            return
        top = 2.5
        room = max(2, FIRST_SCREEN_MARGINS - len(extra))
        for m in ms[:room]:
            width = max(0.0, min(m.ratio, top)) / top * 100
            cls = "bad" if (m.ratio < 1 or not m.passed) else ("low" if m.ratio < 1.1 else "")
            rel = "≥" if m.at_least else "≤"
            where = "" if m.section == "checks" else m.section
            label = (f'<span class="code">{e(m.label)}</span>' if m.section == "checks"
                     else symbol_html(m.label))
            self.add(f'<div class="bar-row" title="{e(m.name)}"><span class="lbl">{label}'
                     f'{" <small>" + e(where) + "</small>" if where else ""}</span>'
                     f'<span class="bar" role="img" aria-label="margin {m.ratio:.2f}">'
                     f'<span class="fill {cls}" style="width:{width:.1f}%"></span>'
                     f'<span class="one" style="left:{100 / top:.1f}%"></span></span>'
                     f'<span class="num">{e(short(m.value))} {rel} {e(short(m.limit))}'
                     f'</span></div>')
        more = len(ms) - room
        note = f"{more} more: " if more > 0 else ""
        self.add(f'<p class="none">Bar: value against its limit (line = 1); '
                 f'{note}<a href="#{all_id}">all margins</a>.</p></section>')

    def findings(self, r: Result, checks_id: str) -> None:
        self.add('<section class="findings" aria-label="failed checks and warnings">')
        for title, items in (("Failed checks", r.failed), ("Warnings", r.warnings)):
            self.add(f'<h2 id="{self.ids(title)}">{title} ({len(items)})</h2>')
            if not items:
                self.add('<p class="none">None.</p>')
                continue
            self.add("<ul>")
            for c in items:
                advice = advice_html(c)
                self.add(f'<li><a class="code" href="#{checks_id}-{e(c.code.lower())}">'
                         f'{e(c.code)}</a>: {e(c.message)}'
                         + (f'<br><span class="fix">Advice: {advice}</span>' if advice else "")
                         + "</li>")
            self.add("</ul>")
        self.add("</section>")
