"""A REXS gear unit as a spec (TOML text) that ``geardesign run`` computes
(docs/rexs.md): a model ``geardesign export`` wrote comes back as its spec
(:func:`geardesign.rexs.import_stages.restore_spec`), one planetary or worm stage as a
``planetary``, ``worm`` or ``bevel`` spec and a geardesign drive with such stages as the drive
(:mod:`geardesign.rexs.import_stages`), a chain of cylindrical stages as a ``drive`` spec
(:mod:`geardesign.rexs.chain`)."""

from __future__ import annotations

from geardesign.rexs.chain import import_chain
from geardesign.rexs.common import custom
from geardesign.rexs.import_stages import import_other, restore_spec
from geardesign.rexs.model import Model
from geardesign.rexs.reader import Imported, _Reader, gu_of


def import_model(model: Model, label: str = "model") -> Imported:
    """The spec of ``model``; a model no spec can represent is one :class:`ModelError`
    line (what is missing, which component)."""
    r = _Reader(model, label)
    gu = gu_of(model)
    source = custom(gu).get("source_kind", (None,))[0] if gu is not None else None
    if source in ("spur", "planetary", "worm", "bevel"):     # a spec exported by geardesign
        return restore_spec(r, label, source)
    if model.of_type("planetary_stage", "worm_stage", "bevel_stage"):
        return import_other(r, label)
    return import_chain(r, label)
