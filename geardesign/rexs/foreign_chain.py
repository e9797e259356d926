"""A chain of stages of another program's model with planetary, worm or bevel stages as a
``drive`` spec (docs/rexs.md, "Chains with planetary, worm and bevel stages").

The stages are ordered along the power flow from the shaft that carries the input torque
(and the speed): each stage is entered on the shaft the previous one drove.  A cylindrical,
worm or bevel stage is entered by the gear on that shaft (a worm or bevel stage by its worm
or pinion, ``gear_1``: the drive's worm and bevel stages reduce) and leaves by the other; a
planetary stage is entered by the member (sun, ring, carrier) on that shaft and leaves by
the member whose shaft the next stage is on (the last stage: the member whose shaft carries
the other torque-transmitting ``external_load``), the third member is held.  Every stage is
read as its single-stage import reads it (:mod:`geardesign.rexs.foreign`,
:mod:`geardesign.rexs.bevel`, :func:`geardesign.rexs.cylindrical._stage`) into an inline
``[[stage]]``; the torque and speed a stage table states are those the drive sets.
"""

from __future__ import annotations

from geardesign.rexs import bevel as BV
from geardesign.rexs.chain import _assemble
from geardesign.rexs.cylindrical import _lubricant, _stage
from geardesign.rexs.foreign import _rest, members, planetary, worm
from geardesign.rexs.load_case import _head, _load_case
from geardesign.rexs.model import Component, ModelError
from geardesign.rexs.reader import Imported, _Reader
from geardesign.rexs.shafts import _shafts
from geardesign.rexs.writer import Writer


class _StageWriter(Writer):
    """Writes a stage spec's tables as the tables of the current ``[[stage]]``; the
    planetary spec's [efficiency] is left out (``efficiency`` of a drive's stage is the
    stage's efficiency, which the drive otherwise takes from the stage's calculator)."""

    SKIP = ("efficiency",)

    def __init__(self, out: Writer):
        super().__init__()
        self.lines = out.lines
        self.mute = False

    def table(self, name: str, array: bool = False, note: str | None = None) -> None:
        self.mute = name in self.SKIP
        if not self.mute:
            super().table(f"stage.{name}", array, note)

    def kv(self, key: str, value, source: str | None) -> None:
        if not self.mute:
            super().kv(key, value, source)


def _ports(r: _Reader, st: Component) -> dict[str, Component]:
    """Member → shaft of a stage: gear_1/gear_2 of a two-gear stage; sun, ring, carrier
    of a planetary stage."""
    if st.type == "planetary_stage":
        mem = members(r, st, "planetary")
        out = {"sun": r.shaft_of(mem["sun"]), "ring": r.shaft_of(mem["ring"])}
        for rel in r.m.related("planet_carrier_shaft", planetary_stage=st.id):
            out.setdefault("carrier", r.comp(rel.role("shaft") or "", rel))
        return {k: v for k, v in out.items() if v is not None}
    if st.type == "cylindrical_stage":
        rel = r.m.related("stage", stage=st.id)
        if not rel:
            raise ModelError(f"cylindrical_stage {st.id} has no stage relation")
        gears = [r.comp(rel[0].role(x) or "", rel[0]) for x in ("gear_1", "gear_2")]
    else:
        mem = BV.members(r, st) if st.type == "bevel_stage" else members(r, st, "worm")
        gears = [mem["pinion"], mem["wheel"]] if st.type == "bevel_stage" else \
            [mem["worm"], mem["wheel"]]
    out = {}
    for role, g in zip(("gear_1", "gear_2"), gears):
        sh = r.shaft_of(g)
        if sh is None:
            raise ModelError(f"{g.type} {g.id} \"{g.name}\" of stage {st.id} is on no shaft "
                             f"(no assembly relation shaft → gear)")
        out[role] = sh
    return out


def _order(r: _Reader, stages: list[Component], start: Component, torque_load) -> list:
    """(stage, input member, output member) in power-flow order from ``start``."""
    ports = {st.id: _ports(r, st) for st in stages}
    left, chain, shaft, seen = list(stages), [], start, {start.id}
    while left:
        nxt = [st for st in left if any(sh is shaft for sh in ports[st.id].values())]
        if not nxt:
            break
        if len(nxt) > 1:
            raise ModelError(f"shaft {shaft.id} \"{shaft.name}\" drives {len(nxt)} stages "
                             f"({', '.join(s.id for s in nxt)}): the drive computes one chain "
                             f"of stages, not a split power path")
        st = nxt[0]
        left.remove(st)
        p = ports[st.id]
        inp = next(k for k, sh in p.items() if sh is shaft)
        if st.type in ("worm_stage", "bevel_stage") and inp != "gear_1":
            raise ModelError(f"{st.type} {st.id} is driven by its wheel (gear_2): the drive's "
                             f"{st.type.split('_')[0]} stages are driven by the "
                             f"{'worm' if st.type == 'worm_stage' else 'pinion'}")
        if st.type != "planetary_stage":
            out = "gear_2" if inp == "gear_1" else "gear_1"
        else:
            on = {sh.id for s in left for sh in ports[s.id].values()}
            outs = [k for k, sh in p.items() if k != inp and sh.id in on]
            if not outs:
                outs = [k for k, sh in p.items() if k != inp and _driven(r, sh, torque_load)]
            if len(outs) != 1:
                raise ModelError(f"planetary_stage {st.id}: its output member is the one whose "
                                 f"shaft the next stage is on, or the one whose shaft carries "
                                 f"the other torque-transmitting external_load; found "
                                 f"{sorted(outs) or 'none'}")
            out = outs[0]
        shaft = p[out]
        if shaft.id in seen:
            raise ModelError(f"the stages form a cycle: stage {st.id} leads back to shaft "
                             f"{shaft.id}")
        seen.add(shaft.id)
        chain.append((st, inp, out))
    for st in left:
        r.skip(st, "not on the chain of stages from the input shaft")
    if not chain:
        raise ModelError(f"no stage has a gear on shaft {start.id}, where the torque enters")
    return chain


def _driven(r: _Reader, shaft: Component, torque_load) -> bool:
    for ld in r.m.of_type("external_load"):
        tt = ld.attributes.get("transmits_torque")
        if ld is torque_load or tt is None or str(tt.value).lower() != "true":
            continue
        if any(rel.type == "assembly" and rel.role("part") == ld.id
               and rel.role("assembly") == shaft.id for rel in r.m.relations):
            return True
    return False


def import_foreign_chain(r: _Reader, label: str, stages: list[Component]) -> Imported:
    """The chain of ``stages`` (cylindrical, planetary, worm, bevel) as a drive spec."""
    T_in, case_no, torque_load, case, speed, load_shaft = _load_case(r)
    if speed[1].id != load_shaft.id:
        raise ModelError(f"the speed is given on shaft {speed[1].id}, the torque on shaft "
                         f"{load_shaft.id}: the drive needs both at the input")
    chain = _order(r, stages, load_shaft, torque_load)
    out, head = _head(r, label, T_in, case_no, torque_load, speed)
    head.append("# The torque and speed in each stage's tables are set by the drive.")
    geometry, gears = [], []
    for i, (st, inp, outp) in enumerate(chain, 1):
        p = _ports(r, st)
        if st.type == "cylindrical_stage":
            rel = r.m.related("stage", stage=st.id)[0]
            a, b = (r.comp(rel.role(x) or "", rel) for x in (inp, outp))
            geometry.append(_stage(r, out, i, st, a, b))
            gears.append((st, a, b))
            continue
        kind = {"planetary_stage": "planetary", "worm_stage": "worm",
                "bevel_stage": "bevel"}[st.type]
        out.table("stage", array=True)
        out.kv("name", st.name or f"stage {i}", f"component {st.id} ({st.type}) name")
        out.kv("kind", kind, f"a {st.type}")
        w = _StageWriter(out)
        into = (p[inp], (speed[0], p[inp], speed[2]))
        if kind == "planetary":
            s = planetary(r, w, st, T_in, torque_load, case_no, into[0], into[1],
                          (None, None), output=outp)
            gears.append((st, None, None))
        elif kind == "worm":
            s = worm(r, w, st, T_in, torque_load, case_no, p["gear_2"], into[1], (None, None))
            mem = members(r, st, "worm")
            gears.append((st, mem["worm"], mem["wheel"]))
        else:
            s = BV.read_foreign(r, w, st, T_in, torque_load, case_no, into[0], into[1],
                                (None, None))
            mem = BV.members(r, st)
            gears.append((st, mem["pinion"], mem["wheel"]))
        s["stage"] = i
        geometry.append(s)
    r.read.update({"cylindrical_stage", "cylindrical_gear", "external_load", "shaft",
                   "gear_unit"})
    _lubricant(r, out)
    if all(a is not None for _, a, _ in gears):
        order = [r.shaft_of(gears[0][1])] + [r.shaft_of(b) for _, _, b in gears]
        _shafts(r, out, order, gears)
    _rest(r, "drive")
    return _assemble(r, head, out, geometry)
