"""A REXS chain of cylindrical stages as a ``drive`` spec (TOML text) that ``geardesign run``
computes (the entry point: :func:`geardesign.rexs.importer.import_model`).

What is read, attribute by attribute, is in docs/rexs.md.  Each value written names its
source in a TOML comment: the component id, its type and the REXS attribute (and the load
case).  What the model has and the drive does not compute is listed in one place at the
top of the spec, "Not imported": every component type of the model is either read
(:data:`READ_TYPES`) or named there with its components.
"""

from __future__ import annotations

from geardesign.rexs.cylindrical import _chain, _lubricant, _stage
from geardesign.rexs.load_case import _head, _load_case, _spectrum
from geardesign.rexs.model import ModelError, number
from geardesign.rexs.reader import DEFAULT_MATERIAL, Imported, _Reader, gu_of
from geardesign.rexs.shafts import _shafts
from geardesign.rexs.writer import Writer

READ_TYPES = frozenset({
    "gear_unit", "shaft", "shaft_section", "cylindrical_gear", "cylindrical_stage",
    "cylindrical_gear_flank", "flank_geometry", "rolling_bearing_with_catalog_geometry",
    "concept_bearing", "external_load", "lubricant", "material", "gear_casing",
})
"""Component types whose attributes the import reads (a gear casing only as the outer part
of a bearing; a material is named, not used: see :data:`DEFAULT_MATERIAL`)."""


def import_chain(r: "_Reader", label: str) -> Imported:
    """The drive spec of a chain of cylindrical stages; a model the drive cannot represent
    is one :class:`ModelError` line (what is missing, which component)."""
    m = r.m
    stages = []
    for st in m.of_type("cylindrical_stage"):
        rels = [x for x in m.relations if x.type == "stage" and x.role("stage") == st.id]
        if not rels:
            raise ModelError(f"cylindrical_stage {st.id} \"{st.name}\" has no stage relation "
                             f"naming its gears")
        g1, g2 = rels[0].role("gear_1"), rels[0].role("gear_2")
        if g1 is None or g2 is None:
            raise ModelError(f"stage relation {rels[0].id} of cylindrical_stage {st.id} does "
                             f"not name gear_1 and gear_2")
        a, b = r.comp(g1, rels[0]), r.comp(g2, rels[0])
        for g in (a, b):
            if g.type != "cylindrical_gear":
                raise ModelError(f"stage relation {rels[0].id}: {g.id} is a {g.type}, not a "
                                 f"cylindrical_gear")
            if r.shaft_of(g) is None:
                raise ModelError(f"cylindrical_gear {g.id} \"{g.name}\" of stage {st.id} is "
                                 f"on no shaft (no assembly relation shaft → gear)")
        stages.append((st, a, b))
    if not stages:
        raise ModelError("the model has no cylindrical stage: nothing a drive spec can hold "
                         f"(component types: {', '.join(sorted({c.type for c in m.components.values()}))})")

    T_in, case_no, torque_load, case, speed, load_shaft = _load_case(r)
    r.spectrum = _spectrum(r, gu_of(m), torque_load, speed[1], T_in, speed[0])

    # the chain of stages from the shaft that carries the torque
    chain = _chain(r, stages, load_shaft)
    order = [load_shaft] + [r.shaft_of(b) for _, _, b in chain]
    if speed[1] not in order:
        raise ModelError(f"the shaft {speed[1].id} whose speed is given is not on the chain of "
                         f"stages from shaft {load_shaft.id}")
    if speed[1].id != load_shaft.id:
        raise ModelError(f"the speed is given on shaft {speed[1].id}, the torque on shaft "
                         f"{load_shaft.id}: the drive needs both at the input")
    out, head = _head(r, label, T_in, case_no, torque_load, speed)
    stated = []
    for i, (st, a, b) in enumerate(chain, 1):
        stated.append(_stage(r, out, i, st, a, b))
    r.read.update({"cylindrical_stage", "cylindrical_gear", "external_load", "shaft",
                   "gear_unit"})
    for st, a, b in stages:
        if (st, a, b) not in chain:
            r.skip(st, "not on the chain of stages from the input shaft")

    _lubricant(r, out)
    for mat in m.of_type("material"):
        if mat.id not in r.used_materials:
            r.skip(mat, "names no grade of the library, or no heat treatment (gears rated "
                        f"as {DEFAULT_MATERIAL['grade']})")
    _shafts(r, out, order, chain)
    for c in m.components.values():
        if c.type not in READ_TYPES:
            r.skip(c, "not computed by the drive")
    for ld in m.of_type("external_load"):
        if ld is not torque_load and ld.id not in r.applied:
            at = r.merged(ld, case)
            forces = [k for k in ("force_u_direction", "force_v_direction", "force_w_direction")
                      if k in at and number(at[k], f"component {ld.id}") != 0]
            if forces:
                r.skip(ld, f"its forces ({', '.join(forces)}) are not applied")
    return _assemble(r, head, out, stated)


def _assemble(r: "_Reader", head: list[str], out: "Writer", stated: list) -> Imported:
    """The spec text: heading, the "Not imported" list, the tables."""
    m = r.m
    for note in r.notes:
        head.append(f"# Note: {note}.")
    head.append("# Not imported (component type: components):")
    if not r.not_imported:
        head.append("#   nothing")
    for t in sorted(r.not_imported):
        items = r.not_imported[t]
        head.append(f"#   {t}: " + "; ".join(items[:6])
                    + (f"; and {len(items) - 6} more" if len(items) > 6 else ""))
    text = "\n".join(head) + "\n" + "\n".join(out.lines).rstrip() + "\n"
    read_types = {c.type for c in m.components.values()
                  if c.type in READ_TYPES and c.type not in r.not_imported} | (
        {t for t in r.read if t in {c.type for c in m.components.values()}})
    return Imported(text, read_types, r.not_imported, stated, list(r.notes))
