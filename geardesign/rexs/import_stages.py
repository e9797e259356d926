"""Import of REXS models with planetary or worm stages (docs/rexs.md, "Planetary and worm
stages"): one planetary or worm stage becomes a ``planetary`` or ``worm`` spec; a drive
exported by geardesign (its stages numbered by ``custom_geardesign__drive__order``) becomes
the drive spec again, with inline stages of kind spur, planetary and worm.

The stage's spec keys come from the standard attributes listed in
:data:`geardesign.rexs.stages.PLANETARY_KEYS` / :data:`~geardesign.rexs.stages.WORM_KEYS` and,
in a model written by geardesign, from its custom attributes (what REXS has no attribute
for).  A model of another program is read from the standard attributes alone.
"""

from __future__ import annotations

from geardesign.rexs import bevel as BV
from geardesign.rexs import stages as ST
from geardesign.rexs.chain import _assemble
from geardesign.rexs.common import custom, src
from geardesign.rexs.cylindrical import _lubricant, _stage
from geardesign.rexs.foreign import _rest, members, planetary, stated, worm
from geardesign.rexs.load_case import _head, _load_case
from geardesign.rexs.model import Component, ModelError, convert, number
from geardesign.rexs.reader import Imported, _Reader, gu_of
from geardesign.rexs.shafts import _shafts
from geardesign.rexs.writer import Writer

KIND_OF = {"planetary_stage": "planetary", "worm_stage": "worm", "bevel_stage": "bevel"}
"""REXS stage component type → spec (and drive stage) kind."""
STAGE_OF = {v: k for k, v in KIND_OF.items()} | {"spur": "cylindrical_stage"}


def _members(r: _Reader, st: Component, kind: str) -> dict:
    return BV.members(r, st) if kind == "bevel" else members(r, st, kind)


def _stated(r: _Reader, st: Component, kind: str) -> dict:
    return BV.stated(r, st) if kind == "bevel" else stated(r, st, kind)


def import_other(r: _Reader, label: str) -> Imported:
    """A model with planetary or worm stages as a spec (one line when it cannot be)."""
    m = r.m
    gu = gu_of(m)
    ordered = [c for c in m.of_type("cylindrical_stage", *KIND_OF)
               if f"{ST.CUSTOM}drive__order" in c.attributes]
    if ordered:
        return _drive(r, label, ordered)
    units = m.of_type(*KIND_OF)
    inner = {rel.role("part") for rel in m.relations if rel.type == "assembly"
             and rel.role("assembly") in {u.id for u in units}}
    outer = [c for c in m.of_type("cylindrical_stage") if c.id not in inner]
    if len(units) != 1 or outer:    # a chain of another program's stages: a drive spec
        from geardesign.rexs.foreign_chain import import_foreign_chain

        return import_foreign_chain(r, label, units + outer)
    st = units[0]
    kind = KIND_OF[st.type]
    out, head = Writer(), _heading(m, label)
    T_in, case_no, torque_load, case, speed, load_shaft = _load_case(r)
    head.append(f"# Load case: {case_no if case_no else 'the model'} (the largest torque).")
    out.kv("kind", kind, None)
    out.kv("title", gu.name if gu is not None and gu.name else label,
           "gear_unit name" if gu is not None and gu.name else None)
    out.blank()
    life = r.value(gu, "operating_time", "h") if gu is not None else (None, None)
    read = {"planetary": planetary, "worm": worm, "bevel": BV.read_foreign}[kind]
    found = [read(r, out, st, T_in, torque_load, case_no, load_shaft, speed, life)]
    _lubricant(r, out)
    _rest(r, kind)
    return _assemble(r, head, out, found)


def _heading(m, label: str) -> list[str]:
    return [f"# Imported from {label}: REXS {m.version} ({m.fmt.upper()}), written by "
            f"{m.application} {m.application_version} on {m.date}.".rstrip(),
            "# Every value names its REXS source: component id, type and attribute."]


def restore_spec(r: _Reader, label: str, kind: str) -> Imported:
    """A spur, planetary or worm spec exported by geardesign (the gear unit's
    ``custom_geardesign__source_kind``), restored from its stage component."""
    ctype = STAGE_OF[kind]
    found = r.m.of_type(ctype)
    if len(found) != 1:
        raise ModelError(f"a {kind} spec exported by geardesign has one {ctype}; this model "
                         f"has {len(found)}")
    st = found[0]
    out = Writer()
    out.kv("kind", kind, None)
    tree = _restore(r, st, kind)
    tree.pop("kind", None)
    ST.write_tables(out, "", tree)
    out.blank()
    if kind == "spur":
        r.read.update({"material", "cylindrical_gear_flank"})
        r.used_materials.update(c.id for c in r.m.of_type("material"))
    _lubricant(r, out)
    _rest(r, kind)
    return _assemble(r, _heading(r.m, label), out, [_stated(r, st, kind)])


def _restore(r: _Reader, st: Component, kind: str) -> dict:
    """The stage spec written by geardesign: its custom attributes, and the keys listed in
    ``from_rexs`` from their standard attributes."""
    flat = ST.restored(st)
    parts = _members(r, st, kind)
    if kind == "bevel":
        table = BV.key_table(str(flat.get("pair.module_at", ("outer",))[0]))
    else:
        table = {k: (member, aid, unit) for k, member, aid, unit in
                 {"planetary": ST.PLANETARY_KEYS, "worm": ST.WORM_KEYS,
                  "spur": ST.SPUR_KEYS}[kind]}
    for path in ST.from_rexs(st) or []:
        if path not in table:
            raise ModelError(f"component {st.id} ({st.type}): {ST.FROM_REXS} names {path!r}, "
                             f"which has no standard attribute")
        member, aid, unit = table[path]
        c = parts.get(member)
        if c is None or aid not in c.attributes:
            raise ModelError(f"component {st.id} ({st.type}): {path} should be read from "
                             f"{aid} of its {member}, which the model does not state")
        v = convert(c.attributes[aid], "" if unit == "none" else unit,
                    f"component {c.id} ({c.type})")
        if aid == "number_of_teeth":
            v = int(round(abs(v)))
        flat[path] = (v, src(c, aid))
    r.read.update({st.type} | {c.type for c in parts.values() if isinstance(c, Component)})
    if kind == "planetary":
        r.read.add("planet_carrier")
    if kind == "bevel":     # the limits it states are the spec's [material] keys
        r.read.add("bevel_stage_gear_data")
    return ST.nest(flat)


def _drive(r: _Reader, label: str, ordered: list[Component]) -> Imported:
    """A drive exported by geardesign with planetary or worm stages: its stages in the
    order of ``custom_geardesign__drive__order``, each restored (spur stages as any
    cylindrical stage, see :func:`geardesign.rexs.cylindrical._stage`)."""
    m = r.m
    key = f"{ST.CUSTOM}drive__order"
    ordered.sort(key=lambda c: number(c.attributes[key], f"component {c.id} ({c.type})"))
    T_in, case_no, torque_load, case, speed, load_shaft = _load_case(r)
    out, head = _head(r, label, T_in, case_no, torque_load, speed)
    geometry, chain = [], []
    for i, st in enumerate(ordered, 1):
        extra = custom(st)
        if st.type == "cylindrical_stage":
            rel = m.related("stage", stage=st.id)
            if not rel:
                raise ModelError(f"cylindrical_stage {st.id} has no stage relation")
            a = r.comp(rel[0].role("gear_1") or "", rel[0])
            b = r.comp(rel[0].role("gear_2") or "", rel[0])
            geometry.append(_stage(r, out, i, st, a, b))
            chain.append((st, a, b))
            continue
        kind = KIND_OF[st.type]
        if kind != "planetary":
            pair = list(_members(r, st, kind).values())
            chain.append((st, pair[1], pair[2]))     # the stage, gear_1, gear_2
        else:
            chain.append((st, None, None))
        out.table("stage", array=True)
        out.kv("name", st.name or f"stage {i}", f"component {st.id} ({st.type}) name")
        if "drive__efficiency" in extra:
            out.kv("efficiency", *extra["drive__efficiency"])
        tree = _restore(r, st, kind)
        ST.write_tables(out, "stage.", tree)
        out.blank()
        s = _stated(r, st, kind)
        s["stage"] = i
        geometry.append(s)
    r.read.update({"cylindrical_stage", "cylindrical_gear", "cylindrical_gear_flank",
                   "material"})
    _lubricant(r, out)
    if all(a is not None for _, a, _ in chain) and any(
            rel.type == "side" for rel in m.relations):
        # the drive's [[shaft]] tables: shaft 1 carries the first stage's gear_1, shaft k + 1
        # the gear_2 of stage k (as geardesign writes them)
        gears = [chain[0][1]] + [b for _, _, b in chain]
        order = [r.shaft_of(g) for g in gears]
        for g, sh in zip(gears, order):
            if sh is None:
                raise ModelError(f"{g.type} {g.id} \"{g.name}\" is on no shaft (no assembly "
                                 f"relation shaft → gear)")
        _shafts(r, out, order, chain)
    _rest(r, "drive")
    return _assemble(r, head, out, geometry)

