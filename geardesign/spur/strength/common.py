"""What both strength methods share: the duty (torque, speed, life), the report row, and the
rating records with their report metadata.

A rating record is a frozen dataclass whose reported fields carry their row metadata
(:func:`q`: unit, symbol, name, source); a per-gear field holds a (pinion, wheel) pair.
:func:`rows` turns any record into the report rows and :func:`values` into the flat
``key → value`` record the checks and the tests read; neither computes anything.  The
same record holds numbers (the calculator) or numpy arrays of candidates (the sweep
kernel); rows are built only from numbers.
"""

from __future__ import annotations

import dataclasses
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.spur.loads import Block

WHO = ("pinion", "wheel")


@dataclass(frozen=True)
class Life:
    """Required life and loading history."""

    L_h: float
    c: tuple[int, int] = (1, 1)
    regime: str | None = "0"
    blocks: tuple[Block, ...] = ()


@dataclass(frozen=True)
class Duty:
    T1: float               # nominal (largest long-acting) pinion torque, N·m
    n1: float               # pinion speed, min^-1
    K_A: float = 1.0
    T_peak: float | None = None
    reverse_ratio: float = 0.0
    life: Life = field(default_factory=lambda: Life(1.0))
    reverse_ratios: tuple[float, float] | None = None
    """Reversed torque ratio per gear (pinion, wheel) when they differ, e.g. a planet
    loaded on both flanks (1.0) meshing a sun loaded on one (0.0); ``None``: both gears
    take ``reverse_ratio``."""

    def reverse(self, i: int) -> float:
        """The reversed torque ratio of gear ``i`` (0 pinion, 1 wheel)."""
        return self.reverse_ratio if self.reverse_ratios is None else self.reverse_ratios[i]


@dataclass(frozen=True)
class Value:
    """One report row of a rating."""

    section: str
    key: str
    value: float | str
    unit: str | None
    symbol: str
    name: str
    source: str


# ----------------------------------------------------------------------------- records


def q(unit: str | None, symbol: str, name, source, *, key: str | None = None,
      gear: bool = False, group: str | None = None, row: bool = True,
      section: str | None = None, default=dataclasses.MISSING):
    """A reported field of a rating record.

    ``unit`` (None for a text value), ``symbol`` and ``name`` are the row's (each text, a
    template or a function of the context as ``name``); ``source`` a
    reference (a key of ``docs/references.md``, "spec", "material").  ``name`` and
    ``source`` may hold ``{placeholders}`` filled from the record's fields (a per-gear field
    at the gear's index) and from ``k`` (1, 2) and ``who`` (pinion, wheel), or be a function
    of that context.  ``gear``: a (pinion, wheel) pair, one row per gear, key and symbol
    with ``{k}``; consecutive per-gear fields of one ``group`` are reported gear by gear.
    A field that is ``None`` gives no row; ``row=False``: a value the checks read (in
    :func:`values`) that the report does not show; ``section``: the report section of the
    row when not the record's (a value computed among others, reported where it is read)."""
    meta = {"unit": unit, "symbol": symbol, "name": name, "source": source,
            "key": key, "gear": gear, "group": group, "row": row, "section": section}
    return field(default=default, metadata={"report": meta})


def opt(unit, symbol, name, source, **kw):
    """A reported field that may be absent (``None``, no row)."""
    return q(unit, symbol, name, source, default=None, **kw)


class Record:
    """A rating record: :attr:`v` its values by report key (as :func:`values`), :attr:`rows`
    its report rows (as :func:`rows`)."""

    @property
    def v(self) -> dict:
        """The values by report key (:func:`values`): of a frozen record collected once
        (the rating, its checks, its report and a drive read them), each caller given its
        own copy."""
        params = getattr(type(self), "__dataclass_params__", None)
        if params is None or not params.frozen:
            return values(self)
        got = self.__dict__.get("_values")
        if got is None:
            got = values(self)
            object.__setattr__(self, "_values", got)
        return dict(got)

    @property
    def rows(self) -> list[Value]:
        return rows(self)


def _section_records(record):
    """``(section, record)`` of a rating made of section records (each with ``SECTION``),
    or of a single section record."""
    if hasattr(record, "SECTION"):
        yield record.SECTION, record
        return
    for f in dataclasses.fields(record):
        part = getattr(record, f.name)
        if part is not None and hasattr(part, "SECTION"):
            yield part.SECTION, part


def _runs(rec):
    """The reported fields of a section record in report order: runs of fields, a run
    being one field or the consecutive per-gear fields of one group."""
    run: list = []
    for f in dataclasses.fields(rec):
        meta = f.metadata.get("report")
        if meta is None:
            continue
        if run and meta["gear"] and meta["group"] is not None \
                and run[-1][1]["group"] == meta["group"]:
            run.append((f, meta))
            continue
        if run:
            yield run
        run = [(f, meta)]
    if run:
        yield run


def _key(f, meta, k: int | None) -> str:
    key = meta["key"] or (f.name + "{k}" if meta["gear"] else f.name)
    return key.format(k=k) if k is not None else key


_LAYOUT: dict = {}


def _layout(cls) -> list:
    """``(field, meta, gear index or None, field name, key)`` of every reported value of a
    section record class in report order (:func:`_runs`), computed once per class."""
    lay = _LAYOUT.get(cls)
    if lay is None:
        lay = []
        for run in _runs(cls):
            for i in ((0, 1) if run[0][1]["gear"] else (None,)):
                lay += [(f, meta, i, f.name, _key(f, meta, None if i is None else i + 1))
                        for f, meta in run]
        _LAYOUT[cls] = lay
    return lay


def _items(rec):
    """``(field, meta, gear index or None, key, value)`` of a section record in report
    order, the absent fields left out."""
    for f, meta, i, name, key in _layout(type(rec)):
        value = getattr(rec, name)
        if value is None:
            continue
        if i is not None:
            value = value[i]
            if value is None:
                continue
        yield f, meta, i, key, value


def values(record) -> dict:
    """The rating's values by report key (the keys of the rows), numbers or arrays."""
    return {key: value for _, rec in _section_records(record)
            for _, _, _, key, value in _items(rec)}


def _text(template, ctx: dict) -> str:
    if callable(template):
        return template(ctx)
    return template.format(**ctx) if "{" in template else template


def rows(record) -> list[Value]:
    """The report rows of a rating record, from its fields' metadata: key, value, unit,
    symbol, name and source per row, in field order, per-gear groups gear by gear (unit,
    symbol, name and source: text, ``{placeholder}`` templates or functions of the
    context, as :func:`q`).  A factor the designer gave (``record.given``) reads "(given)" with the source "spec"; a material
    value from the spec (``record.from_spec``) has the source "spec"."""
    given = getattr(record, "given", frozenset())
    from_spec = getattr(record, "from_spec", frozenset())
    out = []
    for section, rec in _section_records(record):
        base = {f.name: getattr(rec, f.name) for f in dataclasses.fields(rec)}
        per_gear: dict = {}        # the context of gear i, made once per section record
        for f, meta, i, key, value in _items(rec):
            if not meta.get("row", True):
                continue
            ctx = base
            if i is not None:
                ctx = per_gear.get(i)
                if ctx is None:
                    ctx = per_gear[i] = {n: (x[i] if isinstance(x, tuple) else x)
                                         for n, x in base.items()}
                    ctx.update(k=i + 1, who=WHO[i])
            name, source = _text(meta["name"], ctx), _text(meta["source"], ctx)
            if key in given:
                name, source = name + " (given)", "spec"
            elif key in from_spec:
                source = "spec"
            if isinstance(value, bool):
                value = "yes" if value else "no"
            unit = meta["unit"] if meta["unit"] is None else _text(meta["unit"], ctx)
            out.append(Value(meta["section"] or section, key, value, unit, _text(meta["symbol"], ctx), name,
                             source))
    return out


def add_rows(res, record, titles: dict) -> None:
    """The rows of ``record`` (:func:`rows`) added to the result ``res`` under their
    sections (``titles``: section key → title)."""
    for row in rows(record):
        res.section(row.section, titles[row.section]).add(
            row.key, row.value, row.unit, row.symbol, row.name, row.source)


# ----------------------------------------------------------------------------- given factors


class Given:
    """The designer's overrides of computed factors (``[factors]``, ``[iso_factors]``), and
    the keys of those used: a rating's ``given``, whose rows read "(given)" with the source
    "spec" (:func:`rows`).  ``cast`` converts a given value (ISO 6336: ``float``)."""

    def __init__(self, overrides: dict, cast=None):
        self.o = overrides
        self.cast = cast
        self.used: set[str] = set()

    def __call__(self, key: str, computed):
        """The given value of ``key``, else ``computed`` (a value or a function for one)."""
        v = self.o.get(key)
        if v is not None:
            self.used.add(key)
            return self.cast(v) if self.cast else v
        return computed() if callable(computed) else computed

    def pair(self, key: str, computed) -> tuple:
        """A per-gear factor: keys ``key1``, ``key2``; ``computed(i)``."""
        return tuple(self(f"{key}{i + 1}", lambda i=i: computed(i)) for i in range(2))
