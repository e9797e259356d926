"""Worm-wheel rim materials (tin bronzes, tin-free bronzes and brass, grey cast iron).

The data live in ``worm_wheel.toml`` beside this module; this module only reads them.
The material groups are those of the classical worm-wheel strength calculation
([Chernavsky]; [Dunaev]):

* group I: tin bronzes, for high sliding speeds (up to 25 m/s); allowable contact stress
  from the strength of the bronze (wear of the flanks);
* group II: tin-free (aluminium-iron) bronzes and brasses, v_s up to about 5 m/s;
  allowable contact stress limited by scuffing and falling with the sliding speed;
* group III: grey cast iron, v_s up to about 2 m/s.

The property values of the GOST grades are indicative textbook values quoted from memory
(Dunaev & Lelikov; Chernavsky); no located text confirmed them.  The EN 1982 grades
(CuSn12-C, CuSn12Ni2-C, CuZn25Al5Mn4Fe3-C) carry the minimum values of the standard as
printed by the data sheet named in their ``source``.  A spec may override each value.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from geardesign.core.records import dataclass

GROUPS = ("I", "II", "III")

TEXTBOOK_SOURCE = ("[Dunaev]; [Chernavsky] (indicative textbook values quoted from memory; "
                   "unverified)")
"""Source of the rows that name none (the GOST grades of the classical tables)."""

GROUP_V_S_MAX = {"I": 25.0, "II": 5.0, "III": 2.0}
"""Highest sliding speed [m/s] of each material group, used when a material is given by its
properties only (design practice validation rules: group I 25, II 5, III 2 m/s)."""


@dataclass(frozen=True)
class WheelMaterial:
    """A worm-wheel rim material.

    Parameters
    ----------
    name : library key (ASCII transliteration, e.g. ``BrO10N1F1_centrifugal``).
    description : grade and casting method in words.
    group : material group ``"I"``, ``"II"`` or ``"III"``.
    casting : ``sand``, ``chill`` or ``centrifugal``.
    sigma_B : tensile strength [MPa] (bronzes, brass), or None.
    sigma_T : yield strength [MPa] (bronzes, brass), or None.
    sigma_bu : bending strength [MPa] (grey cast iron), or None.
    v_s_max : highest sliding speed for this material [m/s].
    source : where the row's numbers were read.
    """

    name: str
    description: str
    group: str
    casting: str
    sigma_B: float | None
    sigma_T: float | None
    sigma_bu: float | None
    v_s_max: float
    source: str = TEXTBOOK_SOURCE


@lru_cache(maxsize=1)
def _library() -> dict[str, WheelMaterial]:
    from geardesign.core.data import toml_table

    data = toml_table(Path(__file__).with_name("worm_wheel.toml"))
    return {
        name: WheelMaterial(name, row["description"], row["group"], row["casting"],
                            row.get("sigma_B"), row.get("sigma_T"), row.get("sigma_bu"),
                            row["v_s_max"], row.get("source", TEXTBOOK_SOURCE))
        for name, row in data.items()
    }


def names() -> tuple[str, ...]:
    """Library keys, in file order."""
    return tuple(_library())


def get(name: str) -> WheelMaterial:
    """The library material ``name`` (KeyError if unknown)."""
    return _library()[name]
