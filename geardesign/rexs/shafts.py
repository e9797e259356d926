"""The shafts of a REXS model as [[shaft]] tables of the drive spec: bearings, gears, steps,
external loads."""

from __future__ import annotations

import math

from geardesign.rexs.bearings import _bearing_support
from geardesign.rexs.common import custom, src
from geardesign.rexs.model import Component, ModelError
from geardesign.rexs.reader import _Reader
from geardesign.rexs.writer import Writer

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
