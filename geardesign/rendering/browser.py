"""The system's Chromium, driven through Playwright: the PDF printer of the report and the
browser of its tests.

Playwright's own browser download is not needed: :func:`chromium_path` finds an installed
Chromium (``GEARDESIGN_CHROMIUM``, else ``chromium-headless-shell``, ``chromium``,
``chromium-browser``, ``google-chrome`` on ``PATH``, else a browser Playwright installed).
"""

from __future__ import annotations

import os
import shutil
from contextlib import contextmanager

CANDIDATES = ("chromium-headless-shell", "chromium", "chromium-browser", "google-chrome",
              "google-chrome-stable")
"""Browser commands looked for on ``PATH``, in order."""

ARGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
        "--disable-component-update", "--disable-sync", "--no-first-run"]
"""Chromium flags: no sandbox (a container runs as root), no GPU, no request of its own."""

INSTALL_HINT = ("pip install 'geardesign[report]' and a Chromium (Debian/Ubuntu: apt-get install "
                "chromium-headless-shell, or set GEARDESIGN_CHROMIUM to a Chrome/Chromium binary)")


class BrowserMissing(RuntimeError):
    """Playwright or a Chromium is not installed."""


def chromium_path() -> str | None:
    """The Chromium to launch, or None."""
    given = os.environ.get("GEARDESIGN_CHROMIUM")
    if given:
        return given if os.path.exists(given) else None
    for name in CANDIDATES:
        found = shutil.which(name)
        if found:
            return found
    return None


def missing() -> str | None:
    """Why no browser can be launched (one phrase), or None when one can."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "Playwright for Python is not installed"
    if chromium_path() is None:
        return "no Chromium or Chrome is installed"
    return None


@contextmanager
def browser():
    """A launched headless Chromium (closed on exit); :class:`BrowserMissing` otherwise."""
    why = missing()
    if why:
        raise BrowserMissing(why)
    from playwright.sync_api import sync_playwright

    from playwright.sync_api import Error

    with sync_playwright() as p:
        try:
            b = p.chromium.launch(executable_path=chromium_path(), args=ARGS, timeout=60_000)
        except Error as exc:        # not a Chromium, or one that cannot start here
            first = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
            raise BrowserMissing(f"{chromium_path()} did not start as Chromium ({first})") \
                from None
        try:
            yield b
        finally:
            b.close()
