"""Strength rating of external cylindrical gear pairs.

A method is a module with ``rate(geometry, materials, duty, setting) -> Rating``; the
spec's ``options.method`` selects one from :data:`METHODS`.  GOST 21354-87 is
:mod:`.rating` (on the formulas of :mod:`.gost21354`); a second method (ISO 6336-2/-3
method B) would add its own formula and rating modules and one line here, without
touching the GOST code.
"""

from __future__ import annotations

import importlib

METHODS = {
    "GOST 21354-87": "geardesign.spur.strength.rating",
}


def method(name: str):
    """The rating module of a method."""
    return importlib.import_module(METHODS[name])
