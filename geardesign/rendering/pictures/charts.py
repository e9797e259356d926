"""The charts of a result: the shaft's shear force, bending moment, torque and
deflection; the sweep's ranked variants and Pareto front; the curves of pzdn, geneva,
novikov, ball clutch and the epicycle rim's stability chart."""

from __future__ import annotations

from geardesign.rendering.pictures.base import Figure, rows, table, value
from geardesign.rendering.svg import PALETTE, Chart, Series, chart_svg
from geardesign.rendering.typeset import unit_text


def shaft_figures(res) -> dict:
    d = rows(res, "diagrams")
    if "x" not in d or not isinstance(d["x"].value, list):
        return {}
    x = d["x"].value
    strength = rows(res, "strength")
    marks = []
    for key, label in (("x_critical", "critical (fatigue)"),):
        row = strength.get(key)
        if row is not None and isinstance(row.value, (int, float)):
            name = strength.get("critical_section")
            marks.append((row.value, f"{label}: {name.value}" if name else label))
    sections = table(res, "sections")
    if sections is not None and "S_static" in strength:
        worst = min((r for r in sections.rows if isinstance(r.get("S_static"), (int, float))),
                    key=lambda r: r["S_static"], default=None)
        if worst is not None and isinstance(worst.get("x"), (int, float)):
            marks.append((worst["x"], f"critical (static): {worst.get('label', '')}"))

    def series(keys):
        out = []
        for i, k in enumerate(keys):
            if k in d and isinstance(d[k].value, list) and len(d[k].value) == len(x):
                out.append(Series(d[k].symbol or k, x, d[k].value, PALETTE[i]))
        return out

    def unit(keys):
        return next((unit_text(d[k].unit) for k in keys if k in d), "")

    charts = []
    for title, keys, ylabel in (
            ("Shear force", ("V_y", "V_z"), "V"), ("Bending moment and torque",
                                                  ("M_y", "M_z", "M", "T"), "M, T"),
            ("Deflection", ("w_y", "w_z", "w"), "w")):
        ss = series(keys)
        if ss:
            charts.append(Chart("position along the shaft x, mm", f"{ylabel}, {unit(keys)}",
                                ss, title=title, marks=marks, height=220))
    figs = [Figure(c.title + " along the shaft" + (", critical sections marked" if marks
                                                    else ""), chart_svg(c)) for c in charts]
    return {"diagrams": [f for f in figs if f.svg]}


def sweep_figures(res) -> dict:
    ranked, front = table(res, "ranked"), table(res, "pareto")
    objectives = list(((res.inputs or {}).get("sweep") or {}).get("objectives") or [])
    if ranked is None or not ranked.rows:
        return {}
    names = objectives[:2] if len(objectives) > 1 else (objectives or ["mass"])[:1] + ["margin"]
    cols = {k: (h, u) for k, h, u in ranked.columns}
    if not all(n in cols for n in names):
        return {}

    def axis(n):
        head, unit = cols[n]
        u = unit_text(unit)
        return f"{head}, {u}" if u else head

    def pts(rows):
        ok = [r for r in rows if value(r, names[0]) is not None and value(r, names[1]) is not None]
        ok.sort(key=lambda r: r[names[0]])
        return ([r[names[0]] for r in ok], [r[names[1]] for r in ok],
                [f"#{r.get('rank')}" for r in ok])

    x, y, lab = pts(ranked.rows)
    series = [Series("ranked variants (#rank)", x, y, PALETTE[0], marker=True, line=False,
                     point_labels=lab)]
    if front is not None and front.rows:
        fx, fy, _ = pts(front.rows)
        series.append(Series("Pareto front", fx, fy, PALETTE[1], marker=True))
    c = Chart(axis(names[0]), axis(names[1]), series, zero=False, height=320)
    return {"": [Figure(f"Ranked variants and the Pareto front of {names[0]} and "
                              f"{names[1]}", chart_svg(c))]}


def _largest(values: list) -> list:
    """An array of arrays (a value per contact point of each phase) as the largest of
    each inner array; a flat array as it is."""
    out = []
    for v in values:
        if isinstance(v, list):
            finite = [x for x in v if isinstance(x, (int, float))]
            out.append(max(finite) if finite else None)
        else:
            out.append(v)
    return out


def _curves(res, key: str, x: str, xlabel: str, groups, x_from: str = "") -> dict:
    """Charts of the arrays of section ``key`` over the array ``x`` (of section
    ``x_from``, else the same): ``groups`` of ``(title, keys, ylabel)``; a key that is
    missing or of another length is left out; an array of arrays is drawn as the largest
    value of each (:func:`_largest`)."""
    d = rows(res, key)
    dx = rows(res, x_from) if x_from else d
    if x not in dx or not isinstance(dx[x].value, list):
        return {}
    xs = dx[x].value
    unit_x = unit_text(dx[x].unit)
    figs = []
    for title, keys, ylabel in groups:
        ss = [Series(d[k].symbol or k, xs, _largest(d[k].value), PALETTE[i % len(PALETTE)])
              for i, k in enumerate(keys)
              if k in d and isinstance(d[k].value, list) and len(d[k].value) == len(xs)]
        if ss:
            u = unit_text(d[keys[0]].unit) if keys[0] in d else ""
            c = Chart(f"{xlabel}, {unit_x}" if unit_x else xlabel,
                      f"{ylabel}, {u}" if u else ylabel, ss, title=title, height=240)
            figs.append(Figure(title, chart_svg(c)))
    return {key: figs}


def pzdn_figures(res) -> dict:
    return _curves(res, "history", "t", "time t", (
        ("Start-up: torques in the springs", ("T12", "T13"), "T"),
        ("Start-up: speeds of the three masses", ("omega1", "omega2", "omega3"), "ω")))


def geneva_figures(res) -> dict:
    out = _curves(res, "motion_law", "phi", "crank angle φ", (
        ("Motion law of the wheel, relative to the crank",
         ("omega2_ratio", "eps2_ratio", "power_ratio"), "ratio"),))
    out.update(_curves(res, "load", "phi", "crank angle φ", (
        ("Crank torque during the indexing", ("M1",), "M_1"),
        ("Force on the slot", ("F",), "F")), x_from="motion_law"))
    return out


def novikov_figures(res) -> dict:
    return _curves(res, "phases", "phase", "contact phase", (
        ("Stresses over the phases of engagement (largest over the contact points)",
         ("sigma_H", "sigma_F"), "σ"),
        ("Tooth load over the phases of engagement (largest over the contact points)",
         ("F_ideal", "F_max"), "F")))


def ball_clutch_figures(res) -> dict:
    return _curves(res, "speed", "n_grid", "speed n", (
        ("Limit torque against speed", ("T_lim_curve",), "T_lim"),))


def epicycle_rim_figures(res) -> dict:
    d = rows(res, "resonance")
    if "chart_b" not in d:
        return {}
    q = d["chart_b"].value
    ss = []
    for n in range(8):           # a_n(q) solid, b_n(q) dashed, one colour per order
        for name, dash in ((f"chart_a{n}", ""), (f"chart_b{n}", "4 3")):
            if name in d and isinstance(d[name].value, list) and len(d[name].value) == len(q):
                ss.append(Series(f"order {n}" if not dash else "", q, d[name].value,
                                 PALETTE[n % len(PALETTE)], dash=dash))
    if "chart_line_a" in d:
        ss.append(Series("working line a = 2q/μ", q, d["chart_line_a"].value, "#000000",
                         dash="2 2"))
    c = Chart("q of Mathieu's equation", "characteristic value a", ss,
              title="Ince–Strutt stability chart", height=320, zero=False)
    return {"resonance": [Figure("Ince–Strutt chart of Mathieu's equation: characteristic "
                                 "values a_n(q) solid and b_n(q) dashed (unstable between "
                                 "them), and the working line of the rim", chart_svg(c))]}
