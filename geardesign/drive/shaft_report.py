"""The drive's tables, nested reports and checks of its analysed shafts, their
shaft-hub connections and the mesh misalignment of the spur stages
(:mod:`.shaft_analysis`, :mod:`.misalignment`)."""

from __future__ import annotations

import math

from geardesign.core.result import DataTable, Result, check
from geardesign.drive.misalignment import F_SH_MAX
from geardesign.shaft.records import ARCMIN


def _utilisation(res: Result) -> tuple[float | None, str]:
    """The largest utilisation of the error checks of a result (≤ 1 passes): value/limit
    for an upper bound, limit/value for a lower bound (a safety factor)."""
    worst, of = None, ""
    for c in res.checks:
        if c.severity != "error" or c.value is None or c.limit is None or not c.limit:
            continue
        upper = c.passed == (c.value <= c.limit)
        u = c.value / c.limit if upper else (c.limit / c.value if c.value else math.inf)
        if worst is None or u > worst:
            worst, of = u, c.code
    return worst, of


def report(res: Result, shaft_runs: list, kh_rows: list, mis: dict) -> None:
    """Summary tables, nested reports and checks of the analysed shafts and connections."""
    res.methods.append("shaft calculator")
    if any(sr.connections for sr in shaft_runs):
        res.methods.append("connection calculator")
    rows, gear_rows, conn_rows = [], [], []
    for sr in shaft_runs:
        r = sr.r
        c, cs = r.critical, r.critical_static
        lim = sr.result.inputs["shaft"]
        A, B = r.supports
        rows.append(dict(shaft=sr.idx, name=sr.name, critical=c.label if c else None,
                         z_critical=c.x + sr.start if c else None, S=c.S if c else None,
                         S_min=lim["S_min"], S_static=cs.S_static if cs else None,
                         S_static_min=lim["S_static_min"], slope_A=A.slope / ARCMIN,
                         slope_B=B.slope / ARCMIN, n_cr=r.n_cr, n_cr_ratio=r.n_cr / sr.speed,
                         verdict=sr.result.verdict))
        for g, p in zip(sr.gears, r.loads):
            gear_rows.append(dict(shaft=sr.idx, stage=g.stage,
                                  member="input (pinion)" if g.which == 0 else "output (wheel)",
                                  z=g.load.z, w=p.w * 1e3, slope=p.slope / ARCMIN,
                                  slope_x=p.slope_y / ARCMIN, slope_y=p.slope_z / ARCMIN))
        for cn in sr.connections:
            u, of = _utilisation(cn["result"])
            conn_rows.append(dict(shaft=sr.idx, connection=cn["name"], type=cn["type"],
                                  z=cn["z"], d=cn["d"], T=cn["T"], K_A=cn["K_A"],
                                  utilisation=u, of=of, verdict=cn["result"].verdict))
    res.tables.append(DataTable("shafts", "Shafts: strength, bearing slopes, critical speed "
                                "(shaft calculator)", [
        ("shaft", "shaft", None), ("name", "name", None),
        ("critical", "critical section", None), ("z_critical", "z", "mm"),
        ("S", "S", "-"), ("S_min", "[S]", "-"), ("S_static", "S_T", "-"),
        ("S_static_min", "[S_T]", "-"), ("slope_A", "θ_A", "arcmin"),
        ("slope_B", "θ_B", "arcmin"), ("n_cr", "n_cr", "min^-1"),
        ("n_cr_ratio", "n_cr/n", "-"), ("verdict", "verdict", None)], rows))
    res.tables.append(DataTable("shaft_gears", "Shafts: deflection and slope at the gears", [
        ("shaft", "shaft", None), ("stage", "stage", None), ("member", "member", None),
        ("z", "z", "mm"), ("w", "w", "µm"), ("slope", "θ", "arcmin"),
        ("slope_x", "θ_x", "arcmin"), ("slope_y", "θ_y", "arcmin")], gear_rows))
    if conn_rows:
        res.tables.append(DataTable("connections", "Shaft-hub connections (connection "
                                    "calculator)", [
            ("shaft", "shaft", None), ("connection", "connection", None),
            ("type", "type", None), ("z", "z", "mm"), ("d", "d", "mm"), ("T", "T", "N·m"),
            ("K_A", "K_A", "-"), ("utilisation", "worst use", "-"), ("of", "of", None),
            ("verdict", "verdict", None)], conn_rows))
    if kh_rows:
        res.tables.append(DataTable("face_load", "K_Hβ: chart/standard formula vs from the "
                                    "shaft deflections", [
            ("stage", "stage", None), ("method", "rating", None), ("b", "b", "mm"),
            ("f_sh_formula", "f_sh formula", "µm"), ("f_bend", "bending", "µm"),
            ("f_twist", "twist", "µm"), ("f_sh", "f_sh shafts", "µm"),
            ("K_Hbeta_before", "K_Hβ chart/formula", "-"),
            ("K_Hbeta_shafts", "K_Hβ from shafts", "-"), ("note", "note", None)], kh_rows))
    for sr in shaft_runs:
        res.parts.append(("shaft_reports", f"{sr.name}: shaft analysis", sr.result))
        failed = sr.result.failed
        warn = [c.code for c in sr.result.warnings]
        c = sr.r.critical
        res.checks.append(check(
            f"SHAFT_{sr.idx}", not failed, "error",
            f"{sr.name} fails (positions x from the shaft's left end: z = x "
            f"{'+' if sr.start >= 0 else '−'} {abs(sr.start):g} mm): "
            + "; ".join(f"{x.code}: {x.message}" for x in failed),
            f"{sr.name}: fatigue S = {c.S:.2f} at {c.label}, n_cr/n = "
            f"{sr.r.n_cr / sr.speed:.1f}" + (f" (warnings: {', '.join(warn)})" if warn else ""),
            c.S if c and math.isfinite(c.S) else None,
            sr.result.inputs["shaft"]["S_min"], "shaft calculator"))
        for cn in sr.connections:
            res.parts.append(("connection_reports", f"{sr.name}, {cn['name']}", cn["result"]))
            failed = cn["result"].failed
            u, of = _utilisation(cn["result"])
            res.checks.append(check(
                f"CONNECTION_{sr.idx}_{cn['j'] + 1}", not failed, "error",
                f"{sr.name}, {cn['name']} (T = {cn['T']:.0f} N·m) fails: "
                + "; ".join(f"{x.code}: {x.message}" for x in failed),
                f"{sr.name}, {cn['name']} (T = {cn['T']:.0f} N·m): worst use "
                f"{u:.2f} ({of})" if u is not None else f"{sr.name}, {cn['name']} passes",
                u, 1.0, "connection calculator"))
    for i, m in mis.items():
        if m["f_sh"] > F_SH_MAX:
            res.checks.append(check(
                f"MISALIGNMENT_{i}", False, "warning",
                f"stage {i}: the shafts tilt the gears against each other by "
                f"{m['f_sh']:.0f} µm over the face width (more than {F_SH_MAX:g} µm, rated "
                f"with {F_SH_MAX:g}): stiffen the shafts or bring the bearings closer to "
                f"the gears", "", m["f_sh"], F_SH_MAX, "drive"))
