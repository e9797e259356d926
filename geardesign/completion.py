"""Shell completion of the command line's values (``geardesign --install-completion``):
each function takes the word typed so far and returns the values that start with it.  They
read the same lists the commands check their input against (one source of truth), and import
only what they list."""

from __future__ import annotations


def _starting(values, incomplete: str) -> list[str]:
    return [v for v in values if v.startswith(incomplete or "")]


def kinds(incomplete: str) -> list[str]:
    """Calculator kinds (``geardesign template KIND``, ``geardesign schema KIND``): the
    registry's list, which is also the list of templates."""
    from geardesign.core.registry import known_kinds

    return _starting(known_kinds(), incomplete)


def bearing_types(incomplete: str) -> list[str]:
    """Bearing types of the built-in catalogue (``geardesign bearings --type``)."""
    from geardesign.bearing.catalogue import types

    return _starting(types(), incomplete)


def bearing_makers(incomplete: str) -> list[str]:
    """Makers of the built-in catalogue (``geardesign bearings --maker``)."""
    from geardesign.bearing.catalogue import makers

    return _starting(makers(), incomplete)


def material_families(incomplete: str) -> list[str]:
    """Families of the material library (``geardesign materials --family``)."""
    from geardesign.materials.catalog import families

    return _starting(families(), incomplete)


def formats(incomplete: str) -> list[str]:
    """Report formats (``--format``)."""
    from geardesign.core.render import FORMATS

    return _starting(FORMATS, (incomplete or "").lower())


def vary_keys(incomplete: str) -> list[str]:
    """Keys a sweep may vary (``geardesign sweep --vary KEY=...``), each with its ``=``;
    after the ``=`` nothing is proposed (a range or a list of values follows)."""
    if "=" in (incomplete or ""):
        return []
    from geardesign.spur.sweep import MATERIAL_KEYS, VARIABLE

    return _starting([k + "=" for k in (*VARIABLE, *MATERIAL_KEYS)], incomplete)
