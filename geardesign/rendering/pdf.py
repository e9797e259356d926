"""The PDF report: the HTML report (:mod:`geardesign.rendering.html`) printed by Chromium.

Chromium's print-to-PDF (through Playwright, :mod:`geardesign.rendering.browser`) is the
printer because the same browser already renders and tests the HTML: the PDF is exactly
the page the browser tests looked at, with the print style sheet (A4, table heads
repeated on each page, rows, figures and the bars never split, headings kept with what
follows) and inline SVG kept as vectors.  WeasyPrint would be a second layout engine
with its own CSS subset (no CSS grid of the first screen) and its own native
dependencies (Pango).  The header of each page carries the report's title, the footer
the page number and count.
"""

from __future__ import annotations

from geardesign.rendering.browser import INSTALL_HINT, BrowserMissing, browser, missing
from geardesign.rendering.typeset import e

__all__ = ["INSTALL_HINT", "BrowserMissing", "missing", "html_to_pdf"]

HEADER = ('<div style="font-size:8px;width:100%;padding:0 12mm;color:#555;'
          'font-family:sans-serif;display:flex;justify-content:space-between">'
          '<span>{title}</span><span>geardesign</span></div>')
FOOTER = ('<div style="font-size:8px;width:100%;padding:0 12mm;color:#555;'
          'font-family:sans-serif;text-align:right">page <span class="pageNumber"></span> '
          'of <span class="totalPages"></span></div>')


def html_to_pdf(html: str, title: str) -> bytes:
    """The PDF of ``html`` (a self-contained document: nothing is fetched), A4."""
    with browser() as b:
        page = b.new_page()
        page.route("**/*", lambda route: route.abort())     # self-contained: no request
        page.set_content(html, wait_until="load")
        page.emulate_media(media="print")
        return page.pdf(format="A4", print_background=True, display_header_footer=True,
                        header_template=HEADER.format(title=e(title)),
                        footer_template=FOOTER,
                        margin={"top": "16mm", "bottom": "14mm", "left": "12mm",
                                "right": "12mm"})


