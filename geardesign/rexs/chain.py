"""A REXS chain of cylindrical stages as a ``drive`` spec (TOML text) that ``geardesign run``
computes (the entry point: :func:`geardesign.rexs.importer.import_model`).

What is read, attribute by attribute, is in docs/rexs.md.  Each value written names its
source in a TOML comment: the component id, its type and the REXS attribute (and the load
case).  What the model has and the drive does not compute is listed in one place at the
top of the spec, "Not imported": every component type of the model is either read
(:data:`READ_TYPES`) or named there with its components.
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.rexs.common import custom, src
from geardesign.rexs.model import Attribute, Component, Model, ModelError, convert, number

READ_TYPES = frozenset({
    "gear_unit", "shaft", "shaft_section", "cylindrical_gear", "cylindrical_stage",
    "cylindrical_gear_flank", "flank_geometry", "rolling_bearing_with_catalog_geometry",
    "concept_bearing", "external_load", "lubricant", "material", "gear_casing",
})
"""Component types whose attributes the import reads (a gear casing only as the outer part
of a bearing; a material is named, not used: see :data:`DEFAULT_MATERIAL`)."""

DEFAULT_MATERIAL = {"grade": "18CrNiMo7-6", "treatment": "carburized", "hardness_HRC": 58.0}
"""The gear steel written when the model's material names no grade of the library (REXS
1.x materials state E, ν, density, strength; the strength calculation needs the grade and
its heat treatment): a case-hardened gear steel, ISO 6336-5 MQ."""
DEFAULT_LIFE_HOURS = 20000.0
"""Required life when the gear unit states no ``operating_time``."""

BEARING_TYPES = {
    "radial_grooved_ball_bearing": "deep_groove_ball",
    "angular_contact_ball_bearing": "angular_contact_ball",
    "radial_self_aligning_ball_bearing": "self_aligning_ball",
    "self_aligning_ball_bearing": "self_aligning_ball",
    "radial_roller_bearing": "cylindrical_roller",
    "cylindrical_roller_bearing": "cylindrical_roller",
    "radial_tapered_roller_bearing": "tapered_roller",
    "radial_self_aligning_roller_bearing": "spherical_roller",
    "axial_grooved_ball_bearing": "thrust_ball",
    "axial_roller_bearing": "thrust_roller",
}
"""REXS ``bearing_type`` → the bearing calculator's ``type``."""


def fmt(x: float) -> str:
    """A number as TOML: integers without noise, others to 10 significant digits."""
    if float(x).is_integer() and abs(x) < 1e15:
        return f"{x:.1f}"
    return f"{x:.10g}"


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


def _load_case(r: "_Reader") -> tuple:
    """(T_in [N·m], load case number or None, the torque's external_load, the load case's
    attributes, (speed, shaft, source), the torque's shaft): the load case of the largest
    input torque and the speed of a shaft."""
    m = r.m
    loads = m.of_type("external_load")
    shafts = {c.id: c for c in m.of_type("shaft")}
    cases = m.load_cases or [{}]
    best = None
    for k, case in enumerate(cases, 1):
        for ld in loads:
            at = r.merged(ld, case)
            if at.get("torque_around_u_axis") is None:
                continue
            defines = at.get("defines_torque")
            if defines is not None and str(defines.value).lower() == "false":
                continue
            T = abs(convert(at["torque_around_u_axis"], "N m", f"component {ld.id} (external_load)"))
            if T > 0 and (best is None or T > best[0]):
                best = (T, k if m.load_cases else None, ld, case)
    if best is None:
        raise ModelError("the model states no torque (torque_around_u_axis of an external_load "
                         "that defines the torque): the drive needs the load")
    T_in, case_no, torque_load, case = best
    load_shaft = None
    for rel in m.relations:
        if rel.type == "assembly" and rel.role("part") == torque_load.id:
            load_shaft = r.comp(rel.role("assembly") or "", rel)
    if load_shaft is None or load_shaft.type != "shaft":
        raise ModelError(f"external_load {torque_load.id} is on no shaft (no assembly relation)")

    # speed: the shaft that defines it
    speed = None
    for sh in shafts.values():
        at = r.merged(sh, case)
        if "rotational_speed" in at:
            n = abs(convert(at["rotational_speed"], "1 / min", f"component {sh.id} (shaft)"))
            if n > 0:
                speed = (n, sh, src(sh, "rotational_speed", case_no if sh.id in case else None))
                break
    if speed is None:
        raise ModelError("the model states no shaft speed (rotational_speed of a shaft)")
    return T_in, case_no, torque_load, case, speed, load_shaft


def _head(r: "_Reader", label: str, T_in: float, case_no, torque_load: Component,
          speed: tuple) -> tuple["Writer", list[str]]:
    """The drive spec's heading comments, [motor], [load] and the drive's other tables
    (from the load case and the gear unit's custom attributes)."""
    m = r.m
    out = Writer()
    head = [f"# Imported from {label}: REXS {m.version} ({m.fmt.upper()}), written by "
            f"{m.application} {m.application_version} on {m.date}.".rstrip(),
            "# Every value names its REXS source: component id, type and attribute.",
            f"# Load case: {case_no if case_no else 'the model'} (the largest input torque).",
            ]
    out.lines.append("kind = \"drive\"")
    gu = gu_of(m)
    out.lines.append(f"title = {_q(gu.name if gu is not None and gu.name else label)}")
    out.blank()
    extra = custom(gu) if gu is not None else {}
    motor = {k[len("motor__"):]: v for k, v in extra.items() if k.startswith("motor__")}
    load = {k[len("load__"):]: v for k, v in extra.items() if k.startswith("load__")}
    tables = {k: v for k, v in extra.items() if "__" in k
              and k.split("__", 1)[0] not in ("motor", "load")}
    out.table("motor")
    if "power" in motor or "torque" in motor:
        out.comment(f"input torque {fmt(T_in)} N·m stated ({src(torque_load, 'torque_around_u_axis', case_no)})")
    else:
        out.kv("torque", T_in, src(torque_load, "torque_around_u_axis", case_no))
    if "speed" not in motor:
        out.kv("speed", speed[0], speed[2])
    for k, (v, s_) in motor.items():
        out.kv(k, v, s_)
    out.blank()
    out.table("load")
    life, life_src = (None, None)
    if gu is not None:
        life, life_src = r.value(gu, "operating_time", "h")
    if "life_hours" not in load:
        out.kv("life_hours", life or DEFAULT_LIFE_HOURS,
               life_src or "assumed: the gear unit states no operating_time")
    for k, (v, s_) in load.items():
        out.kv(k, v, s_)
    others = [k for k in range(1, len(m.load_cases) + 1) if k != case_no]
    if r.spectrum:
        head.append(f"# Load cases 1–{len(m.load_cases)}: the stages' load spectrum.")
    elif others:
        head.append(f"# Load cases {', '.join(map(str, others))} are not rated (one load case "
                    f"per drive spec).")
    out.blank()
    if tables:      # the drive's other tables ([split], [thermal], ...) as exported
        from geardesign.rexs.stages import nest, write_tables

        write_tables(out, "", nest({k.replace("__", "."): v for k, v in tables.items()}))
        out.blank()
    return out, head


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


def _material(r: "_Reader", gear: Component) -> dict[str, tuple] | None:
    """The [material] table of a gear from the material its ``reference`` relation names,
    when that names a grade of the library; else None."""
    from geardesign.materials import gear_steel

    mat = None
    for rel in r.m.relations:
        if rel.type == "reference" and rel.role("origin") == gear.id:
            c = r.comp(rel.role("referenced") or "", rel)
            if c.type == "material":
                mat = c
    if mat is None:
        return None
    name = r.text(mat, "material_designation") or ""
    out = {}
    if name:        # a grade of the library; none named: the treatment and hardness alone
        grade = gear_steel.normalize_grade(name)
        if grade not in gear_steel.grades():
            grade = gear_steel.equivalent_of(name)
        if not grade:
            return None
        out["grade"] = (name.strip(), src(mat, "material_designation"))
    kind = r.text(mat, "heat_treated_material_type_iso_6336_2006")
    hard = {}
    for key, aid, unit in (("hardness_HB", "surface_hardness_brinell", "HB"),
                           ("hardness_HRC", "surface_hardness_rockwell", "HRC"),
                           ("hardness_HV", "surface_hardness_vickers", "HV"),
                           ("core_HRC", "core_hardness_rockwell", "HRC")):
        a = mat.attributes.get(aid)
        if a is not None:
            hard[key] = (number(a, f"component {mat.id} (material)"), src(mat, aid))
    treat = {"normalized_wrought_low_carbon_steel": "normalized",
             "flame_or_induction_hardened_steel": "induction",
             "case_hardened_wrought_steel": "carburized",
             "nitrided_steel": "nitrided",
             "through_hardened_wrought_steel": "improved" if "hardness_HB" in hard
             else "through_hardened"}.get(kind or "")
    if treat is None or not (name or hard):
        return None
    out["treatment"] = (treat, src(mat, "heat_treated_material_type_iso_6336_2006"))
    out.update(hard)
    for k, (v, s_) in custom(mat).items():
        out.setdefault(k, (v, s_))
    for k, aid in (("E", "elastic_modulus"), ("nu", "poisson_ratio")):
        a = mat.attributes.get(aid)
        if a is not None and k not in out:
            out[k] = (convert(a, "MPa" if k == "E" else "", f"component {mat.id} (material)"),
                      src(mat, aid))
    r.read.add("material")
    r.used_materials.add(mat.id)
    return out


def gu_of(m: Model) -> Component | None:
    units = m.of_type("gear_unit")
    return units[0] if units else None


FRACTIONS = ("operating_time_fraction", "load_duration_fraction")
"""The gear unit's share of the operating time of a load case [%] (REXS 1.5 name, and the
name of 1.0–1.4)."""


def _spectrum(r: "_Reader", gu, load: Component, shaft: Component, T_max: float,
              n_max: float) -> list[dict]:
    """The load cases as [[stage.load.spectrum]] blocks (torque and speed over those of the
    largest torque, the time share), when there are two or more and each states its
    share; else []."""
    cases = r.m.load_cases
    if len(cases) < 2 or gu is None:
        return []
    blocks = []
    for k, case in enumerate(cases, 1):
        g = r.merged(gu, case)
        frac = next((g[f] for f in FRACTIONS if f in g), None)
        ld, sh = r.merged(load, case), r.merged(shaft, case)
        if frac is None or "torque_around_u_axis" not in ld or "rotational_speed" not in sh:
            return []
        share = convert(frac, "%", f"component {gu.id} (gear_unit)") / 100.0
        T = abs(convert(ld["torque_around_u_axis"], "N m", f"component {load.id}"))
        n = abs(convert(sh["rotational_speed"], "1 / min", f"component {shaft.id}"))
        if share <= 0 or T <= 0 or n <= 0:
            continue
        blocks.append({"torque_ratio": (T / T_max, f"load case {k}: T / {fmt(T_max)} N·m"),
                       "time_share": (share, src(gu, frac.id, k) + " / 100"),
                       "speed_ratio": (n / n_max, f"load case {k}: n / {fmt(n_max)} min^-1")})
    total = sum(b["time_share"][0] for b in blocks)
    if len(blocks) < 2 or abs(total - 1.0) > 1e-6:
        return []
    return blocks


def _q(s: str) -> str:
    import json

    return json.dumps(str(s), ensure_ascii=False)


class Writer:
    def __init__(self):
        self.lines: list[str] = []

    def table(self, name: str, array: bool = False, note: str | None = None) -> None:
        h = f"[[{name}]]" if array else f"[{name}]"
        self.lines.append(h + (f"  # {note}" if note else ""))

    def kv(self, key: str, value, source: str | None) -> None:
        if isinstance(value, bool):
            v = "true" if value else "false"
        elif isinstance(value, int):
            v = str(value)
        elif isinstance(value, float):
            v = fmt(value)
        elif isinstance(value, list):
            v = "[" + ", ".join(_q(x) if isinstance(x, str) else
                                "true" if x is True else "false" if x is False else
                                str(x) if isinstance(x, int) else fmt(x)
                                for x in value) + "]"
        else:
            v = _q(value)
        self.lines.append(f"{key} = {v}" + (f"  # {source}" if source else ""))

    def comment(self, text: str) -> None:
        self.lines.append(f"# {text}")

    def blank(self) -> None:
        self.lines.append("")


def _chain(r: _Reader, stages, start) -> list:
    """The stages in power-flow order from the shaft ``start``: each stage's driving gear
    is on the shaft the previous one drove.  A cycle or a branch is one line."""
    left = list(stages)
    chain, shaft, seen = [], start, {start.id}
    while left:
        nxt = [(st, a, b) for st, a, b in left
               if r.shaft_of(a) is shaft or r.shaft_of(b) is shaft]
        if not nxt:
            break
        if len(nxt) > 1:
            raise ModelError(f"shaft {shaft.id} \"{shaft.name}\" drives {len(nxt)} stages "
                             f"({', '.join(s.id for s, _, _ in nxt)}): the drive computes one "
                             f"chain of stages, not a split power path")
        st, a, b = nxt[0]
        if r.shaft_of(a) is not shaft:
            a, b = b, a
        left.remove(nxt[0])
        shaft = r.shaft_of(b)
        if shaft.id in seen:
            raise ModelError(f"the stages form a cycle: stage {st.id} leads back to shaft "
                             f"{shaft.id}")
        seen.add(shaft.id)
        chain.append((st, a, b))
    if not chain:
        raise ModelError(f"no stage has a gear on shaft {start.id}, where the torque enters")
    return chain


def _flank(r: _Reader, gear: Component) -> tuple[Component | None, Component | None]:
    for rel in r.m.relations:
        if rel.type == "flank" and rel.role("gear") == gear.id:
            left, right = rel.role("left"), rel.role("right")
            return (r.comp(left, rel) if left else None, r.comp(right, rel) if right else None)
    return None, None


def _stage(r: _Reader, out: Writer, i: int, st: Component, a: Component, b: Component) -> dict:
    out.table("stage", array=True)
    out.kv("name", st.name or f"stage {st.id}", f"component {st.id} ({st.type}) name")
    out.kv("kind", "spur", "a cylindrical stage")
    extra = {k: v for k, v in custom(st).items() if not k.startswith("drive__")}
    if "drive__efficiency" in custom(st):
        out.kv("efficiency", *custom(st)["drive__efficiency"])
    out.table("stage.gear")
    mn, s_mn = r.value(a, "normal_module", "mm")
    mn2, _ = r.value(b, "normal_module", "mm")
    if mn is None:
        raise ModelError(f"cylindrical_gear {a.id} states no normal_module")
    if mn2 is not None and abs(mn2 - mn) > 1e-9 * mn:
        raise ModelError(f"stage {st.id}: the gears' normal modules differ ({mn}, {mn2} mm)")
    out.kv("module", mn, s_mn)
    z = []
    for g in (a, b):
        t = g.attributes.get("number_of_teeth")
        if t is None:
            raise ModelError(f"cylindrical_gear {g.id} states no number_of_teeth")
        zz = number(t, f"component {g.id} (cylindrical_gear)")
        if not zz.is_integer():
            raise ModelError(f"cylindrical_gear {g.id}: number_of_teeth = {t.value} is not "
                             f"a whole number")
        z.append(int(zz))
    internal = z[1] < 0 or z[0] < 0
    out.kv("z1", abs(z[0]), src(a, "number_of_teeth"))
    out.kv("z2", abs(z[1]), src(b, "number_of_teeth"))
    beta, s_beta = r.value(a, "helix_angle_reference_diameter", "deg", 0.0)
    out.kv("helix_angle", abs(beta), (s_beta + " (its magnitude; the hand is the sign)")
           if s_beta else "none stated: spur")
    widths = [(r.value(g, "face_width", "mm"), g) for g in (a, b)]
    common, s_common = r.value(st, "common_face_width", "mm")
    if common is not None:
        out.kv("face_width", common, s_common)
    else:
        given = [(w, g) for (w, _), g in widths if w is not None]
        if not given:
            raise ModelError(f"stage {st.id}: no face_width of its gears")
        w, g = min(given, key=lambda x: x[0])
        out.kv("face_width", w, src(g, "face_width") + " (the narrower gear: the working "
                                                        "face width)")
    xs, alpha = [], None
    for g in (a, b):
        left, right = _flank(r, g)
        f = left or right
        x = None
        if f is not None:
            x, s_x = r.value(f, "addendum_modification_coefficient", "")
            al, s_al = r.value(f, "normal_pressure_angle", "deg")
            if al is not None and alpha is None:
                alpha = (al, s_al)
            if right is not None and left is not None:
                x_r, _ = r.value(right, "addendum_modification_coefficient", "")
                if x is not None and x_r is not None and abs(x_r - x) > 1e-9:
                    r.skip(right, f"right flank shift {x_r} differs from the left flank's {x}: "
                                  f"the left one is used")
            if x is not None:
                r.read.add(f.type)
                xs.append((x, s_x))
                continue
        xs.append((None, None))
    if alpha is not None:
        out.kv("pressure_angle", alpha[0], alpha[1])
    a_w, s_aw = r.value(st, "center_distance", "mm")
    if xs[0][0] is not None and xs[1][0] is not None:
        out.kv("x1", xs[0][0], xs[0][1])
        out.kv("x2", xs[1][0], xs[1][1])
        if a_w is not None:
            out.comment(f"center_distance = {fmt(a_w)} mm stated ({s_aw}): follows from "
                        f"x1 + x2, compared in the report of the import")
    elif a_w is not None:
        out.kv("center_distance", a_w, s_aw)
        if xs[0][0] is not None:
            out.kv("x1", xs[0][0], xs[0][1])
    if internal:
        out.kv("internal", True, "a negative number_of_teeth: an internal gear")
    gear_keys = {k.split("__", 1)[1]: v for k, v in extra.items() if k.startswith("gear__")}
    for k, (v, s_) in gear_keys.items():
        out.kv(k, v, s_)
    if "bearing_scheme" not in gear_keys:
        out.kv("bearing_scheme", 5, "assumed: GOST 21354-87 chart 5 (REXS has no such attribute)")
    tips = {}
    for key, g in (("d_a1", a), ("d_a2", b)):
        da, s_da = r.value(g, "tip_diameter", "mm")
        if da is not None:
            tips[key] = (da, s_da)
            out.comment(f"{key} = {fmt(da)} mm stated ({s_da})")
    for key, g in (("d1", a), ("d2", b)):
        d, s_d = r.value(g, "reference_circle_diameter", "mm")
        if d is not None:
            tips[key] = (d, s_d)
    if a_w is not None:
        tips["a_w"] = (a_w, s_aw)
    ratio, s_u = r.value(st, "gear_ratio", "")
    if ratio is not None:
        tips["u"] = (ratio, s_u)
    tables: dict[str, dict] = {}
    for k, v in extra.items():
        if not k.startswith("gear__") and "__" in k:
            t, key = k.rsplit("__", 1)
            tables.setdefault(t.replace("__", "."), {})[key] = v
    ka, s_ka = r.value(st, "application_factor_iso_6336_2006", "")
    if ka is not None:
        tables.setdefault("load", {})["application_factor"] = (ka, s_ka)
    for t, keys in tables.items():
        out.table(f"stage.{t}")
        for k, (v, s_) in keys.items():
            out.kv(k, v, s_)
    for block in r.spectrum:
        out.table("stage.load.spectrum", array=True)
        for k, (v, s_) in block.items():
            out.kv(k, v, s_)
    for side, g in (("pinion", a), ("wheel", b)):
        out.table(f"stage.material.{side}")
        mat = _material(r, g)
        if mat is None:
            for k, v in DEFAULT_MATERIAL.items():
                out.kv(k, v, "assumed: the model names no material of the library"
                       if k == "grade" else "assumed with the grade")
        else:
            for k, (v, s_) in mat.items():
                out.kv(k, v, s_)
    out.blank()
    return {"stage": i, "component": st.id, "stated": tips,
            "x": [x for x, _ in xs], "internal": internal}


def _lubricant(r: _Reader, out: Writer) -> None:
    lubs = r.m.of_type("lubricant")
    if not lubs:
        return
    lub = lubs[0]
    nu40, s40 = r.value(lub, "viscosity_at_40_degree_celsius", "mm^2 / s")
    nu100, s100 = r.value(lub, "viscosity_at_100_degree_celsius", "mm^2 / s")
    rho, s_rho = r.value(lub, "density_at_15_degree_celsius", "kg / m^3")
    out.comment(f"lubricant: component {lub.id} \"{lub.name}\": ν40 = "
                f"{fmt(nu40) if nu40 else '?'} mm²/s ({s40}), ν100 = "
                f"{fmt(nu100) if nu100 else '?'} mm²/s, ρ15 = {fmt(rho) if rho else '?'} kg/m³:"
                f" the drive rates the losses only with [lubrication] and a housing, which "
                f"REXS does not describe; not applied")
    r.skip(lub, "the losses and the heat balance need the housing, which the model does not "
                "give")
    out.blank()


def _bearing_support(r: _Reader, br: Component) -> tuple[dict | None, str]:
    """The [bearing] table of one REXS bearing and its source, or (None, why not)."""
    from geardesign.bearing import catalogue

    if br.type == "concept_bearing":
        return None, "a concept bearing: no designation, no ratings"
    designation = r.text(br, "catalogue_designation") or r.text(br, "name")
    if designation:
        try:
            found = catalogue.read(designation).row
        except ValueError:
            found = None
        if found is not None:
            key = "catalogue_designation" if br.attributes.get("catalogue_designation") \
                else "name"
            return {"designation": (designation, src(br, key))}, ""
    kind = BEARING_TYPES.get(r.text(br, "bearing_type") or "")
    C, s_C = r.value(br, "dynamic_capacity", "N")
    C0, s_C0 = r.value(br, "static_capacity", "N")
    if kind and C and C0:
        note = f" (\"{designation}\" is not in the catalogue)" if designation else ""
        table = {"type": (kind, src(br, "bearing_type") + note), "C_r": (C, s_C),
                 "C_0r": (C0, s_C0)}
        d, s_d = r.value(br, "inner_diameter", "mm")
        D, s_D = r.value(br, "outer_diameter", "mm")
        if d and D:
            table.update(d=(d, s_d), D=(D, s_D))
        return table, ""
    return None, (f"\"{designation}\" is not in the catalogue and the model gives no ratings"
                  if designation else "no designation and no ratings")


def _shafts(r: _Reader, out: Writer, order: list, chain: list) -> None:
    blocks, why_not = [], []
    for idx, sh in enumerate(order, 1):
        lines = Writer()
        lines.table("shaft", array=True)
        lines.kv("index", idx, f"component {sh.id} (shaft): place on the chain from the input")
        lines.kv("name", sh.name or f"shaft {sh.id}", f"component {sh.id} (shaft) name")
        brs = []
        for rel in r.m.relations:
            if rel.type == "side" and rel.role("inner_part") == sh.id:
                br = r.comp(rel.role("assembly") or "", rel)
                u, s_u = r.value(br, "u_coordinate_on_shaft_inner_side", "mm")
                if u is None:
                    raise ModelError(f"bearing {br.id} states no u_coordinate_on_shaft_inner_side")
                brs.append((u, br, s_u))
        brs.sort(key=lambda x: x[0])
        if not brs and not r.parts(sh.id, "shaft_section"):
            # a bare shaft (no bearing, no section): not a [[shaft]] of the drive, which
            # analyses the shafts it is given and leaves the others out
            r.skip(sh, "no bearings and no sections: not a [[shaft]] of the drive")
            continue
        if len(brs) < 2:
            why_not.append(f"shaft {sh.id} has {len(brs)} bearing(s); the drive's shafts have two")
            continue
        for _, br, _ in brs:
            rel = next(x for x in r.m.relations if x.type == "side"
                       and x.role("assembly") == br.id and x.role("inner_part") == sh.id)
            outer = r.m.components.get(rel.role("outer_part") or "")
            if outer is not None and outer.type == "shaft":
                r.notes.append(
                    f"bearing {br.id} \"{br.name}\" sits between shaft {sh.id} and shaft "
                    f"{outer.id} (its outer part): the drive supports every shaft on the "
                    f"housing, so it is taken as a housing support of shaft {sh.id} and its "
                    f"reaction is not applied to shaft {outer.id}, nor their relative speed "
                    f"to its life")
        if len(brs) > 2:
            for _, br, _ in brs[1:-1]:
                r.skip(br, f"a third bearing on shaft {sh.id}: the drive's shaft is a beam on "
                           f"two supports (statically determinate); the outer two are used and "
                           f"this one's share of the load goes to them")
            brs = [brs[0], brs[-1]]
        lines.kv("bearing_a", brs[0][0], brs[0][2])
        lines.kv("bearing_b", brs[1][0], brs[1][2])
        shaft_extra = custom(sh)
        keys = shaft_extra.pop("key__json", None)
        sub = {k: v for k, v in shaft_extra.items() if "__" in k}
        shaft_extra = {k: v for k, v in shaft_extra.items() if "__" not in k}
        for k, (v, s_) in shaft_extra.items():
            lines.kv(k, v, s_)
        for side, (_, br, _) in zip("ab", brs if "fixed" not in shaft_extra else ()):
            ax = r.text(br, "axial_force_absorption")
            if ax == "both_directions":
                lines.kv("fixed", side, src(br, "axial_force_absorption") + " = both_directions")
                break
        secs = sorted(((r.value(s, "u_coordinate_on_shaft", "mm", 0.0)[0], s)
                       for s in r.parts(sh.id, "shaft_section")), key=lambda x: x[0])
        if secs:
            lines.kv("start", secs[0][0], src(secs[0][1], "u_coordinate_on_shaft"))
        gears = []
        for k, (st, a, b) in enumerate(chain, 1):
            for g, mate in ((a, b), (b, a)):
                if g is not None and r.shaft_of(g) is sh:
                    gears.append((k, g, mate))
        for k, g, mate in gears:
            lines.table("shaft.gear", array=True)
            lines.kv("stage", k, f"component {chain[k - 1][0].id} "
                                 f"({chain[k - 1][0].type}), gear {g.id}")
            u, s_u = r.value(g, "u_coordinate_on_shaft", "mm")
            if u is None:
                raise ModelError(f"{g.type} {g.id} states no u_coordinate_on_shaft")
            lines.kv("position", u, s_u)
            extra = custom(g)
            ang = extra.pop("mate_angle", None) or _mate_angle(r, g, mate)
            lines.kv("mate_angle", ang[0], ang[1])
            for kk, (v, s_) in extra.items():
                lines.kv(kk, v, s_)
        ok = True
        for side, (_, br, _) in zip("ab", brs):
            table, why = _bearing_support(r, br)
            if table is None:
                why_not.append(f"bearing {br.id} \"{br.name}\" on shaft {sh.id}: {why}")
                ok = False
                continue
            lines.table(f"shaft.support_{side}")
            for k, (v, s_) in table.items():
                lines.kv(k, v, s_)
        if secs:
            for u0, s in secs:
                L, s_L = r.value(s, "length", "mm")
                d1, s_d = r.value(s, "outer_diameter_begin", "mm")
                d2, _ = r.value(s, "outer_diameter_end", "mm", d1)
                bore, s_b = r.value(s, "inner_diameter_begin", "mm", 0.0)
                if L is None or d1 is None:
                    raise ModelError(f"shaft_section {s.id} states no length or "
                                     f"outer_diameter_begin")
                lines.table("shaft.step", array=True)
                lines.kv("length", L, s_L)
                lines.kv("diameter", min(d1, d2), s_d + ("" if d1 == d2 else
                                                        " (a cone: its smaller diameter)"))
                if bore:
                    lines.kv("bore", bore, s_b)
                for k, (v, s_) in custom(s).items():
                    lines.kv(k, v, s_)
            r.read.add("shaft_section")
        if sub:             # the shaft's own tables ([shaft.lubrication], ...) as exported
            from geardesign.rexs.stages import nest, write_tables

            write_tables(lines, "shaft.", nest({k.replace("__", "."): v
                                                for k, v in sub.items()}))
        _shaft_loads(r, lines, sh)
        if keys is not None:
            import json

            try:
                items = json.loads(str(keys[0]))
            except ValueError:
                raise ModelError(f"{keys[1]}: not JSON text") from None
            if not isinstance(items, list) or not all(isinstance(x, dict) for x in items):
                raise ModelError(f"{keys[1]}: not a list of tables")
            for item in items:
                lines.table("shaft.key", array=True, note=keys[1])
                for k, v in item.items():
                    lines.kv(k, v, None)
        lines.blank()
        if ok:
            blocks.append(lines.lines)
        else:
            blocks.append(["# " + ln if ln else ln for ln in lines.lines])
    complete = not why_not
    if not complete:
        out.comment("The shafts are not imported as [[shaft]] tables (their bearings cannot be "
                    "rated): " + "; ".join(why_not))
        out.comment("Their data, as read, follow commented out.")
        r.applied.clear()           # their [[shaft.load]] are not applied either
        for sh in order:
            r.skip(sh, "its shaft tables are commented out (bearings not rated)")
        for br in r.m.of_type("rolling_bearing_with_catalog_geometry", "concept_bearing"):
            if br.type not in r.not_imported or not any(
                    x.startswith(f"{br.id} ") for x in r.not_imported[br.type]):
                r.skip(br, "the shafts are not imported")
        for blk in blocks:
            out.lines.extend(blk if blk[0].startswith("#") else
                             ["# " + ln if ln else ln for ln in blk])
    else:
        r.read.update({"rolling_bearing_with_catalog_geometry", "gear_casing"})
        for blk in blocks:
            out.lines.extend(blk)
    if "gear_casing" not in r.read:
        for c in r.m.of_type("gear_casing"):
            r.skip(c, "the housing is not modelled")


def _shaft_loads(r: _Reader, lines: "Writer", sh: Component) -> None:
    """The external loads on ``sh`` that transmit no torque and state a force, as
    [[shaft.load]]: position ``u_coordinate_on_shaft``, axial force ``force_u_direction``,
    the radial force F = √(F_v² + F_w²) at the angle atan2(F_w, F_v) in the v–w plane
    (the drive's x–y plane, as for the mate angle)."""
    for ld in r.parts(sh.id, "external_load"):
        at = ld.attributes
        tt = at.get("transmits_torque")
        if tt is not None and str(tt.value).lower() == "true":
            continue
        f = {k: r.value(ld, k, "N", 0.0) for k in ("force_u_direction", "force_v_direction",
                                                   "force_w_direction")}
        if not any(v for v, _ in f.values()):
            continue
        u, s_u = r.value(ld, "u_coordinate_on_shaft", "mm")
        if u is None:
            continue
        Fv, Fw = f["force_v_direction"][0], f["force_w_direction"][0]
        lines.table("shaft.load", array=True)
        lines.kv("position", u, s_u)
        lines.kv("force", math.hypot(Fv, Fw), src(ld, "force_v_direction") + ", "
                 "force_w_direction: √(F_v² + F_w²)")
        lines.kv("angle", round(math.degrees(math.atan2(Fw, Fv)), 9),
                 "atan2(F_w, F_v), the v–w plane")
        if f["force_u_direction"][0]:
            lines.kv("axial", f["force_u_direction"][0], f["force_u_direction"][1])
        for k, (v, s_) in custom(ld).items():
            lines.kv(k, v, s_)
        r.applied.add(ld.id)


def _mate_angle(r: _Reader, g: Component, mate: Component) -> tuple[float, str]:
    """Direction from the gear's axis to its mate's in the plane normal to the axis, from
    the two gears' ``support_vector`` (global position); 0 when the model gives none."""
    def vec(c):
        a = c.attributes.get("support_vector")
        if a is None or not isinstance(a.value, list) or len(a.value) != 3:
            return None
        try:
            return [float(x) for x in a.value]
        except (TypeError, ValueError):
            return None

    p, q = vec(g), vec(mate)
    if p is None or q is None:
        return 0.0, "assumed 0: no support_vector of the gears"
    dy, dz = q[1] - p[1], q[2] - p[2]
    if math.hypot(dy, dz) == 0:
        return 0.0, "assumed 0: the gears' support_vector coincide across the axis"
    ang = math.degrees(math.atan2(dz, dy)) % 360.0
    return round(ang, 6), (f"from support_vector of components {g.id} and {mate.id} "
                           f"(v–w plane)")
