"""The ISO 6336 rating of a spur spec as report sections and checks."""

from __future__ import annotations

from geardesign.spur.strength.iso6336 import rating as IR
from geardesign.spur.strength.iso6336.spec import ISO_NAME, gear_checks, iso_setting


def add_iso_strength(res, geom, spec, inputs) -> None:
    """Rate the pair of a spur spec to ISO 6336 (``inputs`` from the calculator's
    ``_strength_inputs``): rows under the sections ``iso6336_*``, checks, method name."""
    mats, duty, setting = inputs
    gear_checks(spec.data["iso"], geom)
    rating = IR.rate(geom, mats, duty, setting, iso_setting(spec))
    res.methods.append(ISO_NAME)
    for row in rating.rows:
        res.section(row.section, IR.SECTIONS[row.section]).add(
            row.key, row.value, row.unit, row.symbol, row.name, row.source)
    res.checks.extend(IR.rating_checks(rating, bool(getattr(geom, "internal", False))))
