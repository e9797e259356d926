"""The report of a finished sweep: counts, rejections by check, the ranked variants and the
Pareto front (each reported variant re-checked by the whole calculator) and the sweep's own
checks."""

from __future__ import annotations

from geardesign.spur.sweep_input import FIXED_KEYS, FULL_CHECKS, MATERIAL_COLUMNS, OBJECTIVES, \
    Sweep, rating_method
from geardesign.spur.sweep_rank import range_edges
from geardesign.spur.sweep_recheck import full_check

def sweep_result(data: dict, sw: Sweep, summary: dict, source: str = ""):
    """The :class:`~geardesign.core.result.Result` of a finished sweep: counts, the ranked
    variants, the Pareto front, and a check that a feasible variant exists (with the checks
    that rejected the most candidates as advice)."""
    from geardesign.core.result import DataTable, Result, Row, check

    inputs = {"sweep": {d.key: {"values": len(d.values), "from": d.low, "to": d.high}
                        for d in sw.dims},
              "samples": sw.samples, "seed": sw.seed, "objectives": list(sw.objectives),
              "ratio": list(sw.ratio) if sw.ratio else None,
              "center_distance_range": list(sw.center_distance_range)
              if sw.center_distance_range else None,
              "psi_bd": list(sw.psi_bd), "psi_ba": list(sw.psi_ba),
              "min_margin": sw.min_margin, "friction": sw.friction, "top": sw.top,
              "base": {k: v for k, v in data.items() if k not in ("kind", "title")}}
    rows = [Row(f"sweep.{d.key}", "; ".join(_material_label(t) for t in d.choices)
                if d.choices else f"{len(d.values)} values, {d.low:g} … {d.high:g}", None,
                d.key, "varied key") for d in sw.dims]
    res = Result("sweep", data.get("title"), ["GOST 16532-70", rating_method(data)], inputs,
                 rows, source=source)
    c = summary["counts"]
    sec = res.section("counts", "Candidates")
    sec.add("evaluated", c["evaluated"], "-", "N", "candidates evaluated ("
            + (f"Sobol sample, seed = {sw.seed}" if sw.samples else "full grid") + ")")
    sec.add("valid", c["valid"], "-", "N_valid", "candidates that form a gear pair")
    sec.add("passed", c["passed"], "-", "N_pass", "candidates that pass every error check")
    sec.add("feasible", c["feasible"], "-", "N_feas", "passing candidates within the "
            "constraints (ratio, centre distance, ψ_bd and ψ_ba windows, margin)")
    fails = res.section("rejections", "Candidates rejected, by check")
    for code, n in sorted(summary["fails"].items(), key=lambda kv: (-kv[1], kv[0])):
        if n:
            fails.add(code, n, "-", code, f"valid candidates failing {code}")
    cols = [("rank", "rank", "-"), ("index", "candidate", "-"), ("m_n", "m_n", "mm"),
            ("z1", "z1", "-"), ("z2", "z2", "-"), ("x1", "x1", "-"), ("x2", "x2", "-"),
            ("helix_angle", "β", "deg"), ("b_w", "b_w", "mm"), ("psi_bd", "ψ_bd", "-"),
            ("u", "u", "-"),
            ("a_w", "a_w", "mm"), ("S_H1", "S_H1", "-"), ("S_F1", "S_F1", "-"),
            ("S_F2", "S_F2", "-"), ("margin", "margin", "-"), ("mass", "mass", "kg")]
    for name in sw.objectives:
        col, _, unit, _ = OBJECTIVES[name]
        if col not in [c[0] for c in cols]:
            cols.append((col, col, unit))
    cols.append(("full_check", "full check", None))
    mdims = [d for d in sw.dims if d.choices]
    for i, d in enumerate(mdims):
        cols.insert(2 + i, (MATERIAL_COLUMNS[d.key], d.key.split(".")[1], None))
    for d in sw.dims:
        if d.key in FIXED_KEYS:
            name = d.key.split(".", 1)[1]
            cols.insert(2, (name, name.replace("_", " "), "-"))
    verified: dict = {}
    bases: dict = {}     # the typed inputs of each combination of fixed data
    for key, title, block in (("ranked", f"Ranked variants (by {', '.join(sw.objectives)})",
                               summary["head"]),
                              ("pareto", "Pareto front of " + " and ".join(sw.objectives[:2]),
                               summary["front"])):
        t = DataTable(key, title, cols)
        if block is not None:
            for i in range(len(block["index"])):
                r = {k: float(block[k][i]) for k in block if k in dict((c[0], 1) for c in cols)}
                r["rank"] = i + 1
                r["index"] = int(block["index"][i])
                for d in mdims:
                    r[MATERIAL_COLUMNS[d.key]] = _material_label(
                        d.choices[int(block[MATERIAL_COLUMNS[d.key]][i])])
                r["z1"], r["z2"] = int(r["z1"]), int(r["z2"])
                for d in sw.dims:
                    if d.key in FIXED_KEYS:
                        name = d.key.split(".", 1)[1]
                        r[name] = int(r[name])
                if r["index"] not in verified and i < FULL_CHECKS:
                    verified[r["index"]] = full_check(data, sw, r["index"], bases)
                r["full_check"] = verified.get(r["index"], "not run")
                t.rows.append(r)
        res.tables.append(t)
    failing = sorted(i for i, v in verified.items() if v != "pass")
    if failing:
        res.checks.append(check(
            "SWEEP_FULL_CHECK", False, "warning",
            f"{len(failing)} reported variant(s) fail checks the kernel does not make (column "
            f"full check; e.g. the peak-torque checks): candidates "
            f"{', '.join(map(str, failing[:10]))}; take a variant that passes, or rate one with "
            f"--emit-spec and geardesign run for its full report", "", len(failing), 0,
            "sweep"))
    edge = range_edges(sw, summary["head"])
    if edge:
        res.checks.append(check(
            "SWEEP_RANGE_EDGE", False, "warning",
            f"the first ranked variant sits on the boundary of a varied range: "
            f"{'; '.join(edge)}: a better variant may lie beyond it; widen that range (or "
            f"fix the key if the boundary is a limit of the design)", "", len(edge), 0,
            "sweep"))
    top = sorted(((n, k) for k, n in summary["fails"].items() if n), reverse=True)[:3]
    why = ", ".join(f"{k} ({n})" for n, k in top)
    res.checks.append(check(
        "SWEEP_FEASIBLE", c["feasible"] > 0, "error",
        f"no variant of the {c['evaluated']} candidates is feasible"
        + (f"; the checks that rejected the most: {why}" if why else "")
        + ": widen the ranges (larger modules or face widths, other tooth counts), relax the "
          "constraints (ratio window, centre distance range, psi_bd and psi_ba windows, "
          "min_margin) or use stronger "
          "materials",
        f"{c['feasible']} of {c['evaluated']} candidates are feasible", c["feasible"], 1,
        "sweep"))
    return res


def _material_label(t: dict) -> str:
    """A material table in a few words: grade, treatment and hardness."""
    parts = [str(t.get("grade", "")), str(t.get("treatment", ""))]
    for k, unit in (("hardness_HB", "HB"), ("hardness_HRC", "HRC"), ("hardness_HV", "HV")):
        if k in t:
            parts.append(f"{t[k]:g} {unit}")
    return " ".join(p for p in parts if p)


