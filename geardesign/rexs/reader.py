"""What every reader of a REXS model shares: the model with its relations resolved, what
was read and what not (:class:`_Reader`), the import's result (:class:`Imported`) and the
values assumed where the model states none."""

from __future__ import annotations

from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.rexs.common import src
from geardesign.rexs.model import Attribute, Component, Model, ModelError, convert

DEFAULT_MATERIAL = {"grade": "18CrNiMo7-6", "treatment": "carburized", "hardness_HRC": 58.0}
"""The gear steel written when the model's material names no grade of the library (REXS
1.x materials state E, ν, density, strength; the strength calculation needs the grade and
its heat treatment): a case-hardened gear steel, ISO 6336-5 MQ."""
DEFAULT_LIFE_HOURS = 20000.0
"""Required life when the gear unit states no ``operating_time``."""


@dataclass
class Imported:
    """The spec text and what was read, for the report and the tests."""

    text: str
    read_types: set[str]
    not_imported: dict[str, list[str]]        # component type → "id name: why"
    stages: list[dict] = field(default_factory=list)   # stated geometry per stage
    notes: list[str] = field(default_factory=list)


class _Reader:
    def __init__(self, model: Model, label: str):
        self.m = model
        self.label = label
        self.not_imported: dict[str, list[str]] = {}
        self.read: set[str] = set()
        self.used_materials: set[str] = set()
        self.spectrum: list[dict] = []
        self.applied: set[str] = set()        # external loads written as [[shaft.load]]
        self.notes: list[str] = []            # what the drive spec cannot express
        self._check_relations()

    # ---------------------------------------------------------------- helpers

    def comp(self, cid: str, rel=None) -> Component:
        c = self.m.components.get(cid)
        if c is None:
            where = f"relation {rel.id} ({rel.type})" if rel is not None else "the model"
            raise ModelError(f"{where} refers to component {cid}, which the model does not have")
        return c

    def _check_relations(self) -> None:
        for r in self.m.relations:
            for ref in r.refs:
                self.comp(ref.id, r)

    def attr(self, c: Component, aid: str) -> Attribute | None:
        return c.attributes.get(aid)

    def value(self, c: Component, aid: str, unit: str, default=None, case: int | None = None):
        """(value in the tool's unit, source comment) of an attribute, or (default, None)."""
        a = c.attributes.get(aid)
        if a is None or a.value in (None, ""):
            return default, None
        return convert(a, unit, f"component {c.id} ({c.type})"), src(c, aid, case)

    def text(self, c: Component, aid: str) -> str | None:
        a = c.attributes.get(aid)
        return None if a is None or a.value in (None, "") else str(a.value)

    def skip(self, c: Component, why: str) -> None:
        self.not_imported.setdefault(c.type, []).append(f"{c.id} \"{c.name}\": {why}")

    def parts(self, assembly: str, hint: str) -> list[Component]:
        out = []
        for r in self.m.relations:
            if r.type in ("assembly", "ordered_assembly") and r.role("assembly") == assembly:
                pid = r.role("part")
                if pid is not None and self.comp(pid, r).type == hint:
                    out.append(self.comp(pid, r))
        return out

    def shaft_of(self, gear: Component) -> Component | None:
        for r in self.m.relations:
            if r.type == "assembly" and r.role("part") == gear.id:
                owner = self.comp(r.role("assembly") or "", r)
                if owner.type == "shaft":
                    return owner
        return None

    def merged(self, c: Component, case: dict | None) -> dict[str, Attribute]:
        out = dict(c.attributes)
        if case is not None:
            out.update(case.get(c.id, {}))
        return out


def gu_of(m: Model) -> Component | None:
    units = m.of_type("gear_unit")
    return units[0] if units else None
