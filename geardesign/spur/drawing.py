"""From the calculation to the gear drawing: the tolerances and the backlash range of the
pair, the test dimensions of each gear with their limits, and the drawing data table
(GOST 2.403-75 / ISO 1340 parameter table).

The values are computed by :mod:`geardesign.spur.drawing_data` (:func:`accuracy_of`,
:func:`tests_of`: every input rule, typed records); here :func:`add_drawing` writes their
rows, the data table and the checks.
"""

from __future__ import annotations

import math

from geardesign.core.result import DataTable, Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.gears.geometry import PairGeometry
from geardesign.spur.drawing_data import (
    SRC_BACKLASH,
    SRC_BACKLASH_INT,
    SRC_GOST,
    SRC_MEAS,
    Accuracy,
    accuracy_of,
    inner,
    is_internal,
    tests_of,
    who,
)
from geardesign.spur.tolerances import gost1643, iso1328


# ----------------------------------------------------------------------------- report


def _pair(sec, key, values, unit, symbol, name, source, names=("pinion", "wheel")):
    for i, v in enumerate(values):
        sec.add(f"{key}{i + 1}", v, unit, f"{symbol}{i + 1}", f"{name}, {names[i]}", source)


def _accuracy_rows(res: Result, acc: Accuracy, g) -> None:
    names = (who(0, g), who(1, g))
    internal = is_internal(g)
    src_bl = SRC_BACKLASH_INT if internal else SRC_BACKLASH
    close = "a_w + f_a" if internal else "a_w − f_a"
    open_ = "a_w − f_a" if internal else "a_w + f_a"
    src = SRC_GOST if acc.standard == gost1643.STANDARD else acc.standard
    sec = res.section("accuracy", "Accuracy, tooth thickness allowances and backlash")
    sec.add("designation", acc.designation, None, "", "accuracy on the drawing", src)
    if acc.mating is not None:
        sec.add("mating", acc.mating, None, "", "type of mating", SRC_GOST)
    if acc.fa_class is not None:
        sec.add("fa_class", acc.fa_class, None, "", "class of centre-distance deviation",
                SRC_GOST)
    if acc.flank is not None:
        for attr, sym, name in (("f_pT", "f_pT", "single pitch tolerance"),
                                ("F_pT", "F_pT", "cumulative pitch tolerance"),
                                ("F_alphaT", "F_αT", "total profile tolerance"),
                                ("f_falphaT", "f_fαT", "profile form tolerance"),
                                ("f_HalphaT", "f_HαT", "profile slope tolerance"),
                                ("F_betaT", "F_βT", "total helix tolerance"),
                                ("f_fbetaT", "f_fβT", "helix form tolerance"),
                                ("f_HbetaT", "f_HβT", "helix slope tolerance"),
                                ("F_rT", "F_rT", "runout tolerance")):
            _pair(sec, attr, tuple(getattr(f, attr) for f in acc.flank), "µm", sym, name,
                  iso1328.source(attr, acc.standard), names)
    sec.add("jn_min_required", acc.jn_required, "µm", "j_n min", "required least normal backlash",
            acc.jn_source)
    sec.add("fa", acc.fa, "µm", "±f_a", "limit deviation of the centre distance",
            SRC_GOST + " (½ IT of a_w)" if acc.fa_class else "spec")
    how = "balance of j_n min" if acc.upper_assumed else "spec"
    if acc.E_Hs is not None:
        _pair(sec, "E_Hs", acc.E_Hs, "µm", "−E_Hs",
              "least additional rack shift" + (" (from the backlash balance)"
                                               if acc.upper_assumed else "")
              + (" (internal gear: into its rim, away from the axis)" if internal else ""),
              SRC_GOST, names)
        _pair(sec, "T_H", acc.T_H, "µm", "T_H", "tolerance on the additional rack shift", "spec",
              names)
    _pair(sec, "E_sns", acc.upper, "µm", "E_sns", "upper tooth thickness allowance (normal)",
          f"{src_bl}; {how}", names)
    _pair(sec, "E_sni", acc.lower, "µm", "E_sni", "lower tooth thickness allowance (normal)",
          src_bl, names)
    if internal:   # the internal gear's space width: the same allowances, opposite sign
        sec.add("E_ens2", -acc.upper[1], "µm", "E_ens2", "least space width allowance "
                "(normal), internal gear: −E_sns2", src_bl)
        sec.add("E_eni2", -acc.lower[1], "µm", "E_eni2", "largest space width allowance "
                "(normal), internal gear: −E_sni2", src_bl)
    b = acc.backlash
    sec.add("jn_min", b.jn_min, "µm", "j_n min", f"least normal backlash at 20 °C, {close}",
            src_bl)
    sec.add("jn_max", b.jn_max, "µm", "j_n max", f"largest normal backlash at 20 °C, {open_}",
            src_bl)
    if acc.thermal is not None:
        sec.add("j_thermal", b.j_thermal, "µm", "j_θ",
                "backlash change at operating temperature (housing and gears)", src_bl)
        sec.add("jn_min_hot", b.jn_min_hot, "µm", "j_n min,θ",
                "least normal backlash at operating temperature", src_bl)
        sec.add("jn_max_hot", b.jn_max_hot, "µm", "j_n max,θ",
                "largest normal backlash at operating temperature", src_bl)


def _limit_rows(sec, key: str, sym: str, name: str, limits, who: str) -> None:
    """The upper and lower limit rows of one test dimension (none without [accuracy])."""
    if limits:
        for j, (side, word) in enumerate((("upper", "max"), ("lower", "min"))):
            sec.add(f"{key}_{side}", limits[j], "mm", f"{sym} {word}",
                    f"{name}, {side} limit, {who}", SRC_MEAS)


def _test_rows(res: Result, tests: tuple, g) -> None:
    sec = res.section("test_dimensions", "Test dimensions")
    for i, t in enumerate(tests):
        n, name, ins = i + 1, who(i, g), inner(g, i)
        sec.add(f"k{n}", t.k, "-", f"k{n}", ("spaces" if ins else "teeth") + f" spanned, {name}",
                SRC_MEAS)
        sec.add(f"W{n}", t.W, "mm", f"W{n}", f"span over k {'spaces' if ins else 'teeth'}, {name}"
                + (" (internal calliper with ball or disc anvils: a standard disc micrometer "
                   "does not reach into an internal gear)" if ins else ""), SRC_MEAS)
        sec.add(f"d_W{n}", t.d_W, "mm", f"d_W{n}", f"diameter where the calliper touches, {name}",
                SRC_MEAS)
        _limit_rows(sec, f"W{n}", f"W{n}", "span", t.W_limits, name)
        sec.add(f"D{n}", t.D, "mm", f"D{n}", f"ball/pin diameter, {name}"
                + (" (chosen: contact near d + 2x·m_n)" if t.D_chosen else ""), SRC_MEAS)
        sec.add(f"M{n}", t.M, "mm", f"M{n}", f"dimension {'between' if ins else 'over'} two "
                f"balls, {name}", SRC_MEAS)
        sec.add(f"d_M_contact{n}", t.d_M_contact, "mm", f"d_c{n}",
                f"diameter where the ball touches the flanks, {name}", SRC_MEAS)
        _limit_rows(sec, f"M{n}", f"M{n}", "over balls", t.M_limits, name)
        sec.add(f"M_r{n}", t.M_r, "mm", f"M_r{n}", f"radial single-ball dimension (axis to the "
                f"{'near' if ins else 'far'} point of the ball), {name}", SRC_MEAS)
        _limit_rows(sec, f"M_r{n}", f"M_r{n}", "radial single-ball dimension", t.M_r_limits,
                    name)
        sec.add(f"s_chord{n}", t.s_c, "mm", f"s̄{n}", f"chordal tooth thickness (normal), {name}"
                + (" (of its teeth; a tooth calliper reaches them only in a large ring)"
                   if ins else ""), SRC_MEAS)
        sec.add(f"h_chord{n}", t.h_c, "mm", f"h̄{n}", f"chordal height from the tip, {name}",
                SRC_MEAS)
        _limit_rows(sec, f"s_chord{n}", f"s̄{n}", "chordal thickness", t.s_c_limits, name)
        sec.add(f"s_const{n}", t.s_cc, "mm", f"s̄_c{n}", f"constant chord, {name}", SRC_MEAS)
        sec.add(f"h_const{n}", t.h_cc, "mm", f"h̄_c{n}", f"constant chord height from the tip, "
                f"{name}", SRC_MEAS)
        _limit_rows(sec, f"s_const{n}", f"s̄_c{n}", "constant chord", t.s_cc_limits, name)


COLUMNS = [("parameter", "parameter", None), ("symbol", "symbol", None), ("unit", "unit", None),
           ("pinion", "pinion", None), ("pinion_es", "pinion upper dev.", None),
           ("pinion_ei", "pinion lower dev.", None), ("wheel", "wheel", None),
           ("wheel_es", "wheel upper dev.", None), ("wheel_ei", "wheel lower dev.", None)]


def drawing_table(g: PairGeometry, acc: Accuracy | None, tests: tuple, hand: str | None,
                  rack_name: str) -> DataTable:
    """The parameter table of each gear's drawing (GOST 2.403-75 / ISO 1340): one row per
    parameter, a column per gear with the upper and lower deviations of the test dimensions.
    An internal gear (the wheel column of an internal pair) has its span over spaces and the
    dimension between balls; the shift is in the GOST 19274-73 sign, named."""
    p = g.inp
    rows = []
    internal = is_internal(g)

    def row(name, sym, unit, v1, v2, dev1=(None, None), dev2=(None, None)):
        rows.append({"parameter": name, "symbol": sym, "unit": unit, "pinion": v1,
                     "pinion_es": dev1[0], "pinion_ei": dev1[1], "wheel": v2,
                     "wheel_es": dev2[0], "wheel_ei": dev2[1]})

    beta = math.degrees(p.beta)
    row("normal module", "m_n", "mm", p.m_n, p.m_n)
    row("number of teeth", "z", "-", p.z1, p.z2)
    if internal:
        row("toothing", "", "", "external", "internal")
    row("basic rack", "", "", rack_name, rack_name)
    row("profile shift coefficient" + (" (internal gear: GOST 19274-73 sign, + away from "
                                       "the axis)" if internal else ""), "x", "-", p.x1, p.x2)
    row("helix angle", "β", "deg", beta, beta)
    if beta > 0:
        h1 = hand or "right"
        row("hand of helix", "", "", h1, "left" if h1 == "right" else "right")
    if acc is not None:
        row("accuracy", "", "", acc.designation, acc.designation)
    d = [(None, None)] * 2
    for attr, lim, name, sym in (("W", "W_limits", "span over k teeth"
                                  + (" (internal gear: k spaces)" if internal else ""), "W"),
                                 ("M", "M_limits", "dimension over balls"
                                  + (" (internal gear: between)" if internal else ""), "M"),
                                 ("M_r", "M_r_limits", "radial single-ball dimension", "M_r"),
                                 ("s_c", "s_c_limits", "chordal tooth thickness", "s̄")):
        if acc is not None:
            d = [tuple(getattr(t, lim)[j] - getattr(t, attr) for j in (0, 1)) for t in tests]
        if attr == "W":
            row("teeth spanned", "k", "-", tests[0].k, tests[1].k)
        if attr == "M":
            row("ball diameter", "D", "mm", tests[0].D, tests[1].D)
        row(name, sym, "mm", getattr(tests[0], attr), getattr(tests[1], attr), d[0], d[1])
        if attr == "s_c":
            row("chordal height", "h̄", "mm", tests[0].h_c, tests[1].h_c)
    row("reference diameter", "d", "mm", g.g1.d, g.g2.d)
    row("tip diameter", "d_a", "mm", g.g1.d_a, g.g2.d_a)
    row("root diameter", "d_f", "mm", g.g1.d_f, g.g2.d_f)
    row("mating gear: number of teeth", "z", "-", p.z2, p.z1)
    fa = None if acc is None else acc.fa * 1e-3
    row("centre distance", "a_w", "mm", g.a_w, g.a_w, (fa, -fa if fa else None),
        (fa, -fa if fa else None))
    return DataTable("drawing", "Drawing data table (GOST 2.403-75 / ISO 1340)", COLUMNS, rows)


def add_drawing(res: Result, g: PairGeometry, spec: ValidatedSpec) -> None:
    """Accuracy, backlash, test dimensions and the drawing data table of the pair."""
    acc = accuracy_of(g, spec) if spec.data.get("accuracy") is not None else None
    tests = tests_of(g, spec, acc)
    if acc is not None:
        _accuracy_rows(res, acc, g)
        res.methods.append(acc.standard)
    _test_rows(res, tests, g)
    r = g.inp.rack
    rack = ("GOST 13755-81" if (abs(math.degrees(r.alpha_n) - 20.0) < 1e-9 and r.h_a == 1.0
                                and r.c == 0.25 and abs(r.rho_f - 0.38) < 1e-12)
            else f"α = {math.degrees(r.alpha_n):g}°, h_a* = {r.h_a:g}, c* = {r.c:g}, "
                 f"ρ_f* = {r.rho_f:g}")
    hand = (spec.data.get("drawing") or {}).get("helix_hand")
    res.tables.append(drawing_table(g, acc, tests, hand, rack))
    if acc is not None:
        b = acc.backlash
        least = min(b.jn_min, b.jn_min_hot)
        internal = is_internal(g)
        src_bl = SRC_BACKLASH_INT if internal else SRC_BACKLASH
        res.checks.append(check(
            "BACKLASH_JAM", least >= 0.0, "error",
            f"the least normal backlash is {least:.1f} µm (centre distance at "
            f"{'a_w + f_a' if internal else 'a_w − f_a'}"
            f"{', at operating temperature' if b.jn_min_hot < b.jn_min else ''}): the teeth "
            f"jam; thin the teeth (larger E_Hs / more negative A_sne), a wider centre-distance "
            f"class or a larger a_w tolerance {'downward' if internal else 'upward'}",
            f"the least normal backlash {least:.1f} µm keeps the teeth free", least, 0.0,
            src_bl))
        res.checks.append(check(
            "BACKLASH_GUARANTEED", least >= acc.jn_required - 1e-6, "warning",
            f"the least normal backlash {least:.1f} µm is below the required j_n min = "
            f"{acc.jn_required:.1f} µm: increase the upper thickness allowances by "
            f"{(acc.jn_required - least) / (2 * math.cos(g.inp.rack.alpha_n)):.1f} µm each",
            f"the least normal backlash {least:.1f} µm meets j_n min = {acc.jn_required:.1f} µm",
            least, acc.jn_required, src_bl))
