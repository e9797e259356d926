"""The ISO 6336 rating record: :class:`IsoRating`, frozen, made of frozen section records
(materials, load factors, pitting, bending, scuffing, static, spectrum), each value a field
that carries its report metadata (unit, symbol, name, source) as the GOST 21354 record's
fields do (:func:`geardesign.spur.strength.common.q`).  The report rows come from that
metadata through the one :func:`geardesign.spur.strength.common.rows` of both methods; the
values by key through :func:`geardesign.spur.strength.common.values`.

Which values an ISO rating holds depends on its inputs (a helical pair, an internal gear,
a peak torque, a spectrum, scuffing inputs, given factors), and several names read the
inputs (ν40, R_z, the resonance range): :class:`Writer` collects each value with its
metadata as :func:`geardesign.spur.strength.iso6336.rating.rate` computes it, and
:meth:`Writer.record` freezes them into section records whose class is made once per
layout of keys, units and symbols (the names and sources held by the record).
"""

from __future__ import annotations

import dataclasses
import functools

from geardesign.core.records import dataclass
from geardesign.spur.strength.common import Record, q

SECTIONS = {"iso6336_materials": "ISO 6336: materials", "iso6336_factors": "ISO 6336: load factors",
            "iso6336_contact": "ISO 6336: pitting", "iso6336_bending": "ISO 6336: tooth bending",
            "iso6336_static": "ISO 6336: static (peak torque)",
            "iso6336_scuffing": "ISO/TS 6336-21: scuffing (integral temperature)",
            "iso6336_spectrum": "ISO 6336: load spectrum (Miner)"}
"""Report sections of an ISO 6336 rating (key → title), in report order."""

_PART = {sec: sec.removeprefix("iso6336_") for sec in SECTIONS}


@dataclass(frozen=True, kw_only=True)
class IsoRating(Record):
    """An ISO 6336:2019 rating: one frozen section record per report section (``None``
    when the rating has none: scuffing without its inputs, static without a peak torque,
    spectrum without load blocks).  :attr:`v` its values by key, :attr:`rows` its rows."""

    materials: object = None
    factors: object = None
    contact: object = None
    bending: object = None
    scuffing: object = None
    static: object = None
    spectrum: object = None
    order: tuple = ()
    """The keys in the order the rating computed them (the order of the rows and values;
    a pitting factor, Z_ε, is computed among the load factors)."""


def _name(key: str):
    return lambda c: c["row_names"][key]


def _source(key: str):
    return lambda c: c["row_sources"][key]


@functools.lru_cache(maxsize=512)
def _section_class(section: str, layout: tuple) -> type:
    """The frozen record class of ``section`` holding the fields of ``layout`` (``(key,
    unit, symbol, row)`` per value), made once per layout."""
    fields = [(key, object, q(unit, symbol, _name(key), _source(key), row=row))
              for key, unit, symbol, row in layout]
    fields += [("row_names", dict), ("row_sources", dict)]
    return dataclasses.make_dataclass(f"Iso_{_PART[section]}", fields, frozen=True,
                                      kw_only=True, namespace={"SECTION": section})


class Writer:
    """Values of a rating being computed, with their metadata and the ``[iso_factors]``
    overrides of the designer."""

    def __init__(self, overrides: dict):
        self.o = overrides
        self.v: dict = {}
        self._meta: dict = {sec: [] for sec in SECTIONS}

    def put(self, sec, key, value, unit, symbol, name, source, *, row: bool = True):
        """Record ``value`` under ``key`` in section ``sec`` (``row=False``: a value the
        checks read that the report does not show); return it."""
        self._meta[sec].append((key, unit, symbol, name, source, row))
        self.v[key] = value
        return value

    def factor(self, sec, key, computed, unit, symbol, name, source):
        """A factor the designer may give under ``[iso_factors]`` (name "… (given)", source
        "spec"); else ``computed`` (a value or a function of none)."""
        if self.o.get(key) is not None:
            return self.put(sec, key, float(self.o[key]), unit, symbol, name + " (given)", "spec")
        value = computed() if callable(computed) else computed
        return self.put(sec, key, value, unit, symbol, name, source)

    def record(self) -> IsoRating:
        """The frozen rating record of the values written."""
        parts = {}
        for sec, items in self._meta.items():
            if not items:
                continue
            cls = _section_class(sec, tuple((k, u, s, r) for k, u, s, _, _, r in items))
            parts[_PART[sec]] = cls(**{k: self.v[k] for k, *_ in items},
                                    row_names={k: n for k, _, _, n, _, _ in items},
                                    row_sources={k: src for k, _, _, _, src, _ in items})
        return IsoRating(**parts, order=tuple(self.v))
