"""Strength rating of external cylindrical gear pairs.

A method is a module with ``rate(geometry, materials, duty, setting)``; the spec's
``options.method`` selects one from :data:`METHODS` (``options.methods`` several).
GOST 21354-87 is the package :mod:`.gost21354` (``rate()`` returns the record
:class:`.gost21354.rating.GostRating`, reported by :func:`.common.rows`); ISO 6336:2019
method B is the package :mod:`.iso6336`.  Both are judged by :func:`.verdict.verdict`.
"""

from __future__ import annotations

import importlib

METHODS = {
    "GOST 21354-87": "geardesign.spur.strength.gost21354.rating",
    "ISO 6336:2019": "geardesign.spur.strength.iso6336.rating",
}


def method(name: str):
    """The rating module of a method."""
    return importlib.import_module(METHODS[name])
