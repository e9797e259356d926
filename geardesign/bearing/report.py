"""The report of a bearing calculation: the solved records (:mod:`geardesign.bearing.solve`)
turned into report rows and checks.  Computes nothing: every number comes from a record."""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.bearing import sources as S
from geardesign.bearing.assess import Assessment
from geardesign.bearing.checks import _h, _kn, common_checks, life_checks, units_checks
from geardesign.bearing.conditions import GOST
from geardesign.bearing.conditions import fmt as _f
from geardesign.bearing.conditions import type_words as _type_words
from geardesign.bearing.inputs import (
    CheckInputs,
    Facts,
    PairInputs,
    SelectInputs,
)
from geardesign.bearing.solve import PairSolution, Rated, Selection
from geardesign.core.result import Check, Result, check


def ignored_check(method: str, ignored: tuple[str, ...]) -> list[Check]:
    """``IGNORED_INPUTS`` when the spec gives inputs the method does not use."""
    if not ignored:
        return []
    return [check("IGNORED_INPUTS", False, "warning",
                  f"not used by method = \"{method}\": " + "; ".join(ignored),
                  "", source=S.method_source(method))]


def report_check(res: Result, inp: CheckInputs, r: Rated, data: dict) -> None:
    """Rows and checks of one bearing (``data``: the spec's tables the checks name)."""
    add_rows(res, r.a, r.facts)
    res.checks.extend(ignored_check(inp.cond.method, inp.ignored))
    res.checks.extend(life_checks(r))
    res.checks.extend(units_checks(r.a, data.get("load")))
    res.checks.extend(common_checks(data["factors"]["temperature"], r.facts))


def report_select(res: Result, inp: SelectInputs, s: Selection, data: dict) -> None:
    """Rows and checks of a catalogue selection."""
    kind, d = inp.kind, inp.d
    results, pick = s.candidates, s.candidates[s.chosen if s.chosen is not None else -1]
    last = results[-1]
    checks = ignored_check(inp.cond.method, inp.ignored)
    sel = res.section("selection", "Selection from the catalogue")
    sel.add("candidates", [r.designation for r, _, _ in results], None, "",
            "candidates, smallest first", S.CATALOGUE)
    sel.add("candidate_lives", [x.life_h for _, _, x in results], "h", "L_j",
            "adjusted life of each candidate", S.method_source(inp.cond.method))
    sel.add("candidate_s0", [x.s0 for _, _, x in results], "-", "s_0,j",
            "static safety of each candidate", S.ISO76)
    sel.add("selected", pick[0].name if s.chosen is not None else "none", None, "",
            "smallest bearing that meets the required life and static safety", S.CATALOGUE)
    if inp.replaced:
        given = ", ".join(f"{k} = {v if k == 'designation' else _kn(v)}"
                          for k, v in inp.replaced)
        checks.append(check(
            "SELECTION_REPLACES", False, "info",
            f"mode = \"select\" chooses the bearing: the given {given} "
            f"{'is' if len(inp.replaced) == 1 else 'are'} replaced by the selection (of "
            f"{_type_words(kind)} bearings with d = {_f(d)} mm)", "", None, None, S.CATALOGUE))
    checks.append(check(
        "SELECTION", s.chosen is not None, "error",
        f"no catalogue {_type_words(kind)} bearing with d = {_f(d)} mm reaches the requirements "
        f"(largest: {last[0].name}, {_h(last[2].life_h)} h, s_0 = "
        f"{_f(last[2].s0, 3) if last[2].s0 is not None else '—'}); C_r >= "
        f"{_kn(last[2].C_req)} is needed: use a larger bore, another type or two bearings",
        f"{pick[0].name} is the smallest {_type_words(kind)} bearing with d = {_f(d)} mm that "
        f"reaches {_h(inp.life_required)} h ({_h(pick[2].life_h)} h)", None, None,
        S.CATALOGUE))
    add_rows(res, s.pick.a, s.facts)
    # when nothing passes, SELECTION already names the life shortfall
    checks.extend(c for c in life_checks(s.pick) if s.chosen is not None or c.code != "LIFE")
    checks.extend(units_checks(s.pick.a, data.get("load")))
    checks.extend(common_checks(data["factors"]["temperature"], s.facts))
    res.checks.extend(checks)


def report_pair(res: Result, inp: PairInputs, p: PairSolution, data: dict) -> None:
    """Rows and checks of a pair: induced axial loads, bearing A, bearing B."""
    xa, xb = p.A.a, p.B.a
    s = res.section("pair", "Pair: induced axial loads")
    s.add("arrangement", inp.arrangement.replace("_", "-"), None, "", "arrangement", "given")
    s.add("F_rA", inp.block.F_r, "N", "F_rA", "radial load on bearing A", "given")
    s.add("F_rB", inp.F_rB, "N", "F_rB", "radial load on bearing B", "given")
    s.add("K_a", abs(inp.F_a), "N", "K_a", "external axial load on the shaft", "given")
    s.add("K_a_carrier", p.carrier, None, "", "bearing that carries K_a", S.PAIR)
    name = "k·F_r/Y" if inp.A.kind == "tapered_roller" else "R·F_r"
    s.add("F_iA", p.F_iA, "N", "F_iA", f"induced axial force of A ({name})", S.PAIR)
    s.add("F_iB", p.F_iB, "N", "F_iB", f"induced axial force of B ({name})", S.PAIR)
    s.add("F_aA", p.F_aA, "N", "F_aA", "axial load on bearing A", S.PAIR)
    s.add("F_aB", p.F_aB, "N", "F_aB", "axial load on bearing B", S.PAIR)
    s.add("case", p.case, None, "", "governing case", S.PAIR)
    add_rows(res, xa, p.A.facts)
    _add_b_rows(res, xb, p.B.facts)
    checks = ignored_check(inp.cond.method, inp.ignored)
    checks.extend(life_checks(p.A))
    checks.extend(units_checks(xa if xa.P <= xb.P else xb, data.get("load")))
    checks.extend(replace(c, message="bearing B: " + c.message) for c in life_checks(p.B))
    checks.extend(common_checks(data["factors"]["temperature"], p.A.facts))
    res.checks.extend(checks)


def report(res: Result, inp, sol, data: dict) -> None:
    """Rows and checks of any bearing record into ``res``."""
    if isinstance(sol, Selection):
        report_select(res, inp, sol, data)
    elif isinstance(sol, PairSolution):
        report_pair(res, inp, sol, data)
    else:
        report_check(res, inp, sol, data)


def add_rows(res: Result, a: Assessment, info: Facts) -> None:
    """The rows of one rated bearing: the bearing, its equivalent load, life and static load."""
    b, c = a.bearing, a.cond
    gost = c.method == GOST
    src = S.method_source(c.method)

    s = res.section("bearing", "Bearing")
    s.add("designation", info.catalogue.name if info.catalogue else "—", None,
          "", "catalogue designation (ISO, GOST)", S.CATALOGUE)
    s.add("type", b.kind, None, "", "bearing type", "")
    s.add("rating_source", info.rating, None, "", "where C_r comes from", "")
    if info.catalogue:
        s.add("data_source", info.source, None, "", "catalogue data source", S.CATALOGUE)
        if info.B is not None:
            s.add("d", info.d, "mm", "d", "bore diameter", S.CATALOGUE)
            s.add("D", info.D, "mm", "D", "outside diameter", S.CATALOGUE)
            s.add("B", info.B, "mm", "B", "width (total width T for tapered roller bearings)",
                  S.CATALOGUE)
    g = info.geometry
    if g is not None:
        s.add("gamma", g.gamma, "-", "γ", "D_w·cos α/D_pw", src)
        s.add("f_c", g.f_c, "-", "f_c", "geometry factor", src)
        s.add("b_m", g.b_m, "-", "b_m", "material and manufacturing factor", src)
    s.add("C_r", b.C_r, "N", "C_r", "basic dynamic load rating", src)
    if b.C_0r is not None:
        s.add("C_0r", b.C_0r, "N", "C_0r", "basic static load rating", S.ISO76)
    if b.C_u is not None and c.lubricated:
        s.add("C_u", b.C_u, "N", "C_u", "fatigue load limit" + (" (estimated from C_0r)"
                                                                if b.C_u_estimated else ""), S.ISO2007)
    if b.D_pw is not None:
        s.add("D_pw", b.D_pw, "mm", "D_pw", "pitch diameter", src)
    s.add("p", a.p, "-", "p", "life exponent (3 ball, 10/3 roller)", src)

    e = res.section("load", "Equivalent load")
    if len(a.blocks) == 1:
        r = a.blocks[0]
        lf = r.factors
        if lf.entry is not None:
            e.add("entry", lf.entry, "-", lf.entry_name, "entry of the X/Y table", src)
        if math.isfinite(lf.e):
            e.add("e", lf.e, "-", "e", "limit of F_a/(V·F_r)", src)
        if math.isfinite(lf.ratio):
            e.add("ratio", lf.ratio, "-", "F_a/(V·F_r)", "axial to radial load", src)
        e.add("X", lf.X, "-", "X", "radial load factor", src)
        e.add("Y", lf.Y, "-", "Y", "axial load factor", src)
        if lf.note:
            e.add("xy_note", lf.note, None, "", "how X, Y were found", src)
    else:
        e.add("P_blocks", [r.P for r in a.blocks], "N", "P_j", "equivalent load of each block", src)
        e.add("X_blocks", [r.factors.X for r in a.blocks], "-", "X_j", "radial factor of each block",
              src)
        e.add("Y_blocks", [r.factors.Y for r in a.blocks], "-", "Y_j", "axial factor of each block",
              src)
    if gost:
        e.add("V", c.V, "-", "V", "rotation factor", S.RU_PRACTICE)
    e.add("K_b", c.K_b, "-", "K_б", "dynamic (safety) factor", S.RU_PRACTICE)
    e.add("K_t", c.K_t, "-", "K_т", "temperature factor", S.RU_PRACTICE)
    if a.spectrum is not None:
        e.add("P_m", a.spectrum.P_m, "N", "P_m", "equivalent load of the spectrum", S.NTN + " (4.12)")
        e.add("n_m", a.spectrum.n_m, "min^-1", "n_m", "mean speed", S.NTN + " (4.12)")
        e.add("damage_share", a.spectrum.damage_share, "-", "D_j", "share of fatigue damage of "
              "each block", S.NTN + " (4.12)")
    if c.K_E is not None:
        e.add("K_E", c.K_E, "-", "K_E", "equivalence factor of the load regime", S.GOST21354_REGIMES)
    e.add("P", a.P, "N", "P", "equivalent dynamic load" + (" P_E = K_E·P" if c.K_E else ""), src)

    f = res.section("life", "Life")
    f.add("L10", a.L10, "10^6 rev", "L10", "basic rating life", src)
    f.add("L10h", a.L10h, "h", "L10h", "basic rating life in hours", src)
    f.add("a1", a.a1, "-", "a1", f"life adjustment factor for reliability ({c.reliability:g} %)", src)
    if gost:
        f.add("a23", a.a23, "-", "a23", "combined material and operating factor", S.RU_PRACTICE)
        f.add("L_sah", a.life_h, "h", "L_sah", "adjusted life a1·a23·L10h", S.GOST94)
    else:
        if c.lubricated:
            r0 = a.blocks[0]
            o = c.oil or {}
            if "oil" in o:
                f.add("oil", o["oil"], None, "", "lubricant, ISO VG grade (ν40 of ISO 3448)",
                      o["oil_source"])
                f.add("oil_source", f"library row {o['oil']}: {o['oil_source']}", None, "",
                      "data used, oil", "library")
            if "nu40" in o:
                f.add("nu40", o["nu40"], "mm^2/s", "ν40", "oil viscosity at 40 °C",
                      o.get("oil_source", "given"))
                f.add("nu100", o["nu100"], "mm^2/s", "ν100", "oil viscosity at 100 °C", S.D2270)
                f.add("VI", o["VI"], "-", "VI", "viscosity index", S.D2270)
                f.add("t_oil", o["t"], "°C", "t", "operating temperature", "given")
            if c.viscosity is not None:
                f.add("nu", c.viscosity, "mm^2/s", "ν", "viscosity at the operating temperature",
                      S.D341 if o else "given")
            given = " (given)" if c.nu1 is not None else ""
            if len(a.blocks) == 1:
                if r0.nu1 is not None:
                    f.add("nu1", r0.nu1, "mm^2/s", "ν1", "reference viscosity" + given,
                          S.ISO2007)
                f.add("kappa", r0.kappa, "-", "κ", "viscosity ratio ν/ν1" + (
                    " (given)" if c.kappa is not None else ""), S.ISO2007)
            else:
                if r0.nu1 is not None:
                    f.add("nu1", [r.nu1 for r in a.blocks], "mm^2/s", "ν1_j", "reference "
                          "viscosity of each block" + given, S.ISO2007)
                f.add("kappa", [r.kappa for r in a.blocks], "-", "κ_j", "viscosity ratio of each "
                      "block", S.ISO2007)
            f.add("e_C", c.e_C, "-", "e_C", "contamination factor", S.ISO2007)
            if len(a.blocks) == 1:
                f.add("eC_Cu_P", r0.a_iso.ratio, "-", "e_C·C_u/P", "contamination-load ratio",
                      S.ISO2007)
                f.add("a_ISO", r0.a_iso.value, "-", "a_ISO", "life modification factor", S.ISO2007)
            else:
                f.add("a_ISO", [r.a_iso.value for r in a.blocks], "-", "a_ISO,j",
                      "life modification factor of each block", S.ISO2007)
            name = "adjusted life a1·a_ISO·L10h" + (" (Palmgren–Miner over the blocks)"
                                                     if len(a.blocks) > 1 else "")
        else:
            name = "adjusted life a1·L10h (no [lubrication]: a_ISO not applied)"
        f.add("L_nmh", a.life_h, "h", "L_nmh", name, S.ISO2007)
    if c.life_required is not None:
        f.add("L_req", c.life_required, "h", "[L_h]", "required life", "")
        f.add("margin", a.margin, "-", "L/[L_h]", "life margin", "")
        f.add("C_req", a.C_req, "N", "C_req", "dynamic rating needed for the required life", src)
    if a.system_life is not None:
        f.add("weibull_slope", a.slope, "-", "e", "Weibull slope of the system life", S.LP)
        f.add("L_system", a.system_life, "h", "L_sys", "life of the system of bearings", S.LP)

    if a.static is not None:
        t = res.section("static", "Static load")
        t.add("X0", a.static.X0, "-", "X_0", "static radial factor", S.ISO76)
        t.add("Y0", a.static.Y0, "-", "Y_0", "static axial factor", S.ISO76)
        t.add("P0", a.static.P0, "N", "P_0", "equivalent static load", S.ISO76)
        t.add("s0", a.s0, "-", "s_0", "static safety factor C_0r/P_0", S.ISO76)


def _add_b_rows(res: Result, x: Assessment, info: Facts) -> None:
    src = S.method_source(x.cond.method)
    row = info.catalogue
    t = res.section("bearing_B", "Bearing B")
    t.add("designation", row.name if row else "—", None, "", "catalogue designation",
          info.source or S.CATALOGUE)
    t.add("C_r", x.bearing.C_r, "N", "C_rB", "basic dynamic load rating", src)
    lf = x.blocks[0].factors
    t.add("X", lf.X, "-", "X_B", "radial load factor", src)
    t.add("Y", lf.Y, "-", "Y_B", "axial load factor", src)
    t.add("P", x.P, "N", "P_B", "equivalent dynamic load", src)
    t.add("L10h", x.L10h, "h", "L10h,B", "basic rating life in hours", src)
    t.add("life_h", x.life_h, "h", x.life_name + ",B", "adjusted life", src)
    if x.s0 is not None:
        t.add("s0", x.s0, "-", "s_0B", "static safety factor C_0r/P_0", S.ISO76)


