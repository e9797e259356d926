"""The calculators by ``kind``, known without importing any of them: the subpackages of
``geardesign`` (:data:`KINDS`) and their catalogue (:func:`catalog`, read from
:data:`CATALOG`).  ``geardesign list``, ``template`` and an unknown kind's message need
no more; :mod:`geardesign.core.registry` runs specs through them."""

from __future__ import annotations

import importlib
import os
from pathlib import Path

NOT_CALCULATORS = {"core", "fatigue", "gears", "materials", "rendering", "rexs"}
"""Subpackages of ``geardesign`` that are shared code, not calculators (``rexs``: the
exchange commands import and export)."""

ORDER = ("spur", "bearing", "worm", "planetary", "novikov", "epicycle_rim", "pzdn", "drive")
"""Listing order of the calculators; others follow alphabetically."""


def _discover() -> dict[str, str]:
    """The subpackages of ``geardesign`` (folders with an ``__init__.py``, as
    :func:`pkgutil.iter_modules` finds them) that are calculators."""
    import geardesign

    names = sorted({e.name for root in geardesign.__path__ for e in os.scandir(root)
                    if e.is_dir() and "." not in e.name and not e.name.startswith("_")
                    and e.name not in NOT_CALCULATORS
                    and os.path.isfile(os.path.join(e.path, "__init__.py"))})
    names.sort(key=lambda n: (ORDER.index(n) if n in ORDER else len(ORDER), n))
    return {n: f"geardesign.{n}" for n in names}


KINDS: dict[str, str] = _discover()


def known_kinds() -> list[str]:
    return list(KINDS)


def get(kind: str):
    """The calculator of ``kind`` (:class:`geardesign.core.registry.Calculator`), built by
    importing its package."""
    return importlib.import_module(KINDS[kind]).CALCULATOR


CATALOG = Path(__file__).with_name("calculators.json")
"""kind, summary and methods of every calculator, written once from the calculators
(:func:`write_catalog`, ``python -m geardesign.core.registry``) so that ``geardesign list``
imports none of them (numpy, scipy); tests/test_startup.py checks that it matches."""


def catalog() -> list[tuple[str, str, tuple[str, ...]]]:
    """``(kind, summary, methods)`` of every calculator in :data:`KINDS` order: from
    :data:`CATALOG`, and by importing the calculator for a kind the file does not list."""
    import json

    try:
        stored = {k: (s, tuple(m)) for k, s, m in json.loads(CATALOG.read_text("utf-8"))}
    except (OSError, ValueError):
        stored = {}
    rows = []
    for kind in KINDS:
        if kind not in stored:
            calc = get(kind)
            stored[kind] = (calc.summary, tuple(calc.methods))
        rows.append((kind, *stored[kind]))
    return rows


def schema(kind: str):
    """The spec schema of ``kind``: ``geardesign.<kind>.spec.SCHEMA``, which its calculator
    uses (a test checks), imported without the calculation (``geardesign template``)."""
    return importlib.import_module(f"{KINDS[kind]}.spec").SCHEMA
