"""The load case of a REXS model: the input torque and speed, the load spectrum of several
load cases, and the drive spec's [motor] and [load] tables written from them."""

from __future__ import annotations

from geardesign.rexs.common import custom, src
from geardesign.rexs.model import Component, ModelError, convert
from geardesign.rexs.reader import DEFAULT_LIFE_HOURS, _Reader, gu_of
from geardesign.rexs.writer import Writer, _q, fmt

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
