"""``kind = "bearing"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module resolves the spec (catalogue or given ratings, load case or spectrum, the
edition's factors), calls :func:`.assess.assess` and maps the assessment to report rows and
checks.  Rules that involve several keys raise :class:`InputError`.
"""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.bearing import catalogue as CAT
from geardesign.bearing import life as L
from geardesign.bearing import pair as PR
from geardesign.bearing import sources as S
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Assessment, Bearing, Block, Conditions, assess
from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.result import Check, Result, check
from geardesign.core.spec import ValidatedSpec

SHARE_TOL = 1e-6
GOST = "gost18855_94"


def _f(x: float, digits: int = 4) -> str:
    return f"{x:.{digits}g}"


def _h(x: float) -> str:
    return f"{x:,.0f}".replace(",", " ") if math.isfinite(x) else "∞"


def _kn(x: float) -> str:
    return f"{x / 1000:.3g} kN"


def _type_words(kind: str) -> str:
    return kind.replace("_", " ")


# ----------------------------------------------------------------------------- bearing


def _catalogue_row(b: dict, info: dict | None = None):
    """The catalogue row of ``bearing.designation`` (with ``bearing.maker``), read as
    :func:`.catalogue.read` reads a written designation (maker's prefix, seal and shield
    suffixes; ``info["reading"]`` says which variant was read as which row); an input
    error naming the designation when the catalogue has none or several."""
    try:
        reading = CAT.read(b["designation"], b["maker"])
    except ValueError as exc:    # an ambiguous designation, or two makers named
        raise InputError.at("bearing.designation", b["designation"], str(exc)) from None
    row = reading.row
    if info is not None:
        info["reading"] = reading.note
    if row is None:
        other = CAT.read(b["designation"]).row if b["maker"] is not None else None
        if other is not None:
            raise InputError.at("bearing.designation", b["designation"],
                                f"not in the {b['maker']} tables of the built-in catalogue; "
                                f"{other.maker} lists it: remove bearing.maker or set it to "
                                f"\"{other.maker}\"")
        close = CAT.close_matches(b["designation"])
        hint = (" (did you mean " + ", ".join(f'"{c}"' for c in close) + "?)") if close else ""
        raise InputError.at(
            "bearing.designation", b["designation"],
            f"not in the built-in catalogue{hint}; it holds deep groove 60/62/63/64, angular "
            f"contact 72 B/73 B, cylindrical roller NU/NJ/NUP 2/3/22/23, tapered roller "
            f"302/303/313/322/323, spherical roller 222/223/230/231 and thrust ball 511/512 "
            f"(`geardesign bearings` lists them); or give bearing.type, C_r and C_0r instead")
    return row


def resolve_bearing(spec: ValidatedSpec) -> tuple[Bearing, dict]:
    """The bearing of a spec: catalogue row and/or given values (given values override);
    returns the :class:`Bearing` and facts for the report (source, d, D, geometry, ...)."""
    b = spec.data["bearing"]
    info: dict = {"source": "given", "note": "", "geometry": None, "catalogue": None}
    row = None
    if b["maker"] is not None and b["maker"].upper() not in {m.upper() for m in CAT.makers()}:
        raise InputError.at("bearing.maker", b["maker"], "not in the built-in catalogue; known: "
                            + ", ".join(f'"{m}"' for m in CAT.makers()))
    if b["designation"] is not None:
        row = _catalogue_row(b, info)
        if b["type"] is not None and b["type"] != row.type:
            raise InputError.at("bearing.type", b["type"],
                                f"contradicts the catalogue: {row.designation} is a "
                                f"{_type_words(row.type)} bearing; remove bearing.type")
        info.update(source=row.cite, note=row.note, catalogue=row)
    kind = b["type"] if b["type"] is not None else (row.type if row else None)
    if kind is None:
        raise InputError(Problem("bearing.type", "missing; required without bearing.designation: "
                                 "one of " + ", ".join(f'"{t}"' for t in T.TYPES)))

    def pick(key: str, cat_value):
        return b[key] if b[key] is not None else cat_value

    d = pick("d", row.d if row else None)
    D = pick("D", row.D if row else None)
    D_pw = b["D_pw"] if b["D_pw"] is not None else (0.5 * (d + D) if d and D else None)
    if d is not None and D is not None and D <= d:
        raise InputError.at("bearing.D", D, f"must be larger than the bore d = {_f(d)} mm")
    alpha = b["contact_angle"]
    if alpha is None and row is not None and row.alpha is not None:
        alpha = row.alpha
    if alpha is not None and kind in ("deep_groove_ball", "cylindrical_roller") and alpha != 0:
        raise InputError.at("bearing.contact_angle", alpha,
                            f"does not apply to a {_type_words(kind)} bearing (α = 0); remove it "
                            f"or choose type \"angular_contact_ball\"")
    if kind in T.THRUST_TYPES and alpha is None:
        alpha = 90.0
    if kind in ("deep_groove_ball", "cylindrical_roller"):
        alpha = 0.0 if kind == "cylindrical_roller" else None
    e = pick("e", row.e if row else None)
    if alpha is not None and b["e"] is not None and kind in (
            "tapered_roller", "spherical_roller", "self_aligning_ball"):
        raise InputError.at("bearing.e", b["e"], "give either contact_angle or e, not both")
    if b["contact_angle"] is not None and b["e"] is None:
        e = None          # a given angle overrides the catalogue e
    C_r = b["C_r"] if b["C_r"] is not None else (row.C_r if row else None)
    if C_r is not None:
        info["rating"] = "given" if b["C_r"] is not None else "catalogue"
    else:
        geo = [b[k] for k in ("Z", "D_w")]
        if None in geo or D_pw is None or kind in T.THRUST_TYPES:
            raise InputError(Problem(
                "bearing.C_r", "missing; give C_r (N), a catalogue designation, or the geometry "
                "Z, D_w and D_pw (or d and D) of a radial bearing"))
        try:
            g = L.dynamic_rating(kind, b["Z"], b["D_w"], D_pw, alpha or 0.0, b["rows"], b["L_we"])
        except L.BearingError as exc:
            raise InputError.at(exc.key, b.get(exc.key.split(".")[1]), str(exc)) from None
        C_r = g.C_r
        info.update(rating="geometry (ISO 281)", geometry=g)
    C_0r = pick("C_0r", row.C_0r if row else None)
    C_u = pick("C_u", row.C_u if row else None)
    rows = b["rows"]
    if row is not None and row.type == "spherical_roller" and "bearing.rows" in spec.assumed:
        rows = 2                        # a spherical roller bearing has two rows
    own_angle = b["contact_angle"] is not None or b["e"] is not None
    Y1 = row.Y1 if row is not None and not own_angle else None
    Y0 = row.Y0 if row is not None and not own_angle else None
    f0 = b["f0"] if b["f0"] is not None else (row.f0 if row else None)
    bearing = Bearing(kind, rows, alpha, e, pick("Y", row.Y if row else None), C_r, C_0r,
                      C_u, False, f0, D_pw, row.designation if row else "", Y1, Y0)
    info.update(d=d, D=D, B=row.B if row else None, lubricant=b["lubricant"])
    return bearing, info


# ----------------------------------------------------------------------------- loads


def resolve_blocks(spec: ValidatedSpec) -> list[Block]:
    ld = spec.data["load"]
    blocks = ld["spectrum"]
    if blocks is not None:
        for key in ("F_r", "F_a", "speed", "regime"):
            if ld[key] is not None:
                raise InputError.at(f"load.{key}", ld[key],
                                    "give either a single load case or [[load.spectrum]] blocks, "
                                    "not both; remove it")
        total = sum(x["time_share"] for x in blocks)
        if abs(total - 1.0) > SHARE_TOL:
            raise InputError(Problem("load.spectrum", f"time shares add up to {total:.6g}; they "
                                     f"must add up to 1", [x["time_share"] for x in blocks]))
        out = [Block(x["F_r"], x["F_a"], x["speed"], x["time_share"]) for x in blocks]
        for i, blk in enumerate(out):
            if blk.F_r == 0 and blk.F_a == 0:
                raise InputError(Problem(f"load.spectrum[{i}]", "F_r = F_a = 0: a block needs a "
                                                                "load; remove the block or give one"))
        return out
    if ld["F_r"] is None:
        raise InputError(Problem("load.F_r", "missing; required: a number >= 0 (N) (radial "
                                             "load), or [[load.spectrum]] blocks"))
    if ld["speed"] is None:
        raise InputError(Problem("load.speed", "missing; required: a number > 0 (min^-1) (speed "
                                               "of the rotating ring)"))
    if ld["F_a"] is None:
        ld["F_a"] = 0.0
        spec.assumed.append("load.F_a")
    if ld["F_r"] == 0 and ld["F_a"] == 0:
        raise InputError.at("load.F_r", 0.0, "F_r = F_a = 0: give the radial or the axial load")
    return [Block(ld["F_r"], ld["F_a"], ld["speed"], 1.0)]


# ----------------------------------------------------------------------------- conditions


def resolve_conditions(spec: ValidatedSpec, bearing: Bearing, blocks: list,
                       checks: list) -> Conditions:
    data = spec.data
    method = data["method"]
    fac, lub, req, ld = data["factors"], data["lubrication"], data["requirements"], data["load"]
    gost = method == GOST
    ignored = []
    a23 = None
    if gost:
        if fac["a23"] is not None:
            a23 = fac["a23"]
        else:
            if bearing.kind not in T.A23:
                raise InputError(Problem("factors.a23", f"missing; required for a "
                                         f"{_type_words(bearing.kind)} bearing (no textbook a23): "
                                         f"a number > 0"))
            if fac["conditions"] is None:
                fac["conditions"] = "usual"
                spec.assumed.append("factors.conditions")
            a23 = L.a23_default(bearing.kind, fac["conditions"])
        if req["reliability"] > T.A1_GOST94[-1][0]:
            raise InputError.at("requirements.reliability", req["reliability"],
                                "GOST 18855-94 tabulates a1 only up to 99 %; use method = "
                                "\"iso281_2007\" for up to 99.95 %")
        if lub is not None:
            ignored.append("[lubrication] (a_ISO belongs to ISO 281:2007)")
    else:
        if fac["a23"] is not None or fac["conditions"] is not None:
            ignored.append("factors.a23/conditions (GOST 18855-94 only)")
        if ld["rotating_ring"] == "outer":
            ignored.append("load.rotating_ring (ISO 281 has no rotation factor V)")
    if ignored:
        checks.append(check("IGNORED_INPUTS", False, "warning",
                            f"not used by method = \"{method}\": " + "; ".join(ignored),
                            "", source=S.method_source(method)))
    V = T.V_OUTER if (gost and ld["rotating_ring"] == "outer"
                      and bearing.kind != "self_aligning_ball") else 1.0
    K_t = L.k_t(fac["temperature"])
    viscosity = e_C = None
    ep = False
    nu1 = kappa = None
    oil: dict = {}
    if not gost and lub is not None:
        viscosity, nu1, kappa, oil = resolve_viscosity(lub, spec)
        ep = lub["ep_additives"]
        if bearing.D_pw is None and nu1 is None and kappa is None:
            raise InputError(Problem("bearing.D_pw", "missing; required for ν1 of a_ISO: give "
                                                     "D_pw, or d and D (mm)"))
        if lub["e_C"] is not None:
            e_C = lub["e_C"]
        elif lub["contamination"] is not None:
            e_C = L.e_c_guide(lub["contamination"], bearing.D_pw)
        else:
            raise InputError(Problem("lubrication.contamination", "missing; give contamination "
                                     "(one of " + ", ".join(f'"{k}"' for k in T.E_C_GUIDE) +
                                     ") or e_C"))
    K_E = T.K_E[ld["regime"]] if ld["regime"] is not None else None
    return Conditions(
        method=method, reliability=req["reliability"], V=V, K_b=fac["K_b"], K_t=K_t, a23=a23,
        viscosity=viscosity, nu1=nu1, kappa=kappa, oil=oil, e_C=e_C, ep_additives=ep, K_E=K_E,
        life_required=req["life"],
        s0_min=req["s0_min"], F_r0=ld["F_r0"], F_a0=ld["F_a0"],
        system_lives=tuple(req["system_lives"] or ()), weibull_slope=req["weibull_slope"])


def resolve_viscosity(lub: dict, spec: ValidatedSpec) -> tuple:
    """(ν at the operating temperature or None, given ν1 or None, given κ or None, the oil's
    data for the report) of [lubrication]."""
    from geardesign.materials import lubricants as OIL

    routes = [k for k in ("viscosity", "oil", "nu40") if lub[k] is not None]
    if len(routes) > 1:
        raise InputError.at(f"lubrication.{routes[1]}", lub[routes[1]],
                            f"give one of lubrication.viscosity, oil or nu40, not "
                            f"{' and '.join(routes)}")
    if lub["kappa"] is not None and lub["nu1"] is not None:
        raise InputError.at("lubrication.nu1", lub["nu1"], "give kappa or nu1, not both")
    if not routes and lub["kappa"] is None:
        raise InputError(Problem("lubrication.viscosity", "missing; give the viscosity at the "
                                 "operating temperature (mm^2/s), or oil and temperature, or "
                                 "nu40 (and nu100) and temperature, or kappa"))
    oil_info: dict = {}
    viscosity = lub["viscosity"]
    if lub["oil"] is not None or lub["nu40"] is not None:
        if lub["temperature"] is None:
            key = "oil" if lub["oil"] is not None else "nu40"
            raise InputError(Problem("lubrication.temperature", f"missing; required with "
                                     f"lubrication.{key}: the operating temperature (°C)"))
        VI = lub["viscosity_index"]
        if lub["oil"] is not None:
            oil = OIL.find(lub["oil"])
            if oil is None:
                close = OIL.close_matches(lub["oil"])
                hint = (" (did you mean " + ", ".join(f'"{c}"' for c in close) + "?)"
                        if close else "")
                raise InputError.at("lubrication.oil", lub["oil"],
                                    f"not an ISO VG grade{hint}; grades: "
                                    + ", ".join(o.grade for o in OIL.grades()))
            nu40 = oil.nu40
            if VI is None and lub["nu100"] is None:
                VI = lub["viscosity_index"] = oil.VI
                spec.assumed.append("lubrication.viscosity_index")
            oil_info.update(oil=oil.grade, oil_source=oil.cite)
        else:
            nu40 = lub["nu40"]
        try:
            if lub["nu100"] is not None:
                if lub["viscosity_index"] is not None:
                    raise InputError.at("lubrication.viscosity_index", VI,
                                        "give nu100 or viscosity_index, not both")
                nu100 = lub["nu100"]
                if nu100 >= nu40:
                    raise InputError.at("lubrication.nu100", nu100,
                                        f"must be below nu40 = {nu40:g} mm^2/s")
                VI = OIL.viscosity_index(nu40, nu100)
            else:
                if VI is None:
                    raise InputError(Problem("lubrication.nu100", "missing; give nu100 or "
                                             "viscosity_index with nu40"))
                nu100 = OIL.nu100_from_vi(nu40, VI)
            viscosity = OIL.viscosity_at(lub["temperature"], nu40, nu100)
        except OIL.OilError as exc:
            raise InputError(Problem("lubrication", str(exc))) from None
        oil_info.update(nu40=nu40, nu100=nu100, VI=VI, t=lub["temperature"])
    return viscosity, lub["nu1"], lub["kappa"], oil_info


def _with_c_u(bearing: Bearing, cond: Conditions) -> Bearing:
    """Fill in an estimated C_u when a_ISO needs it."""
    if not cond.lubricated or bearing.C_u is not None:
        return bearing
    if bearing.C_0r is None:
        raise InputError(Problem("bearing.C_u", "missing; required for a_ISO: give C_u (N), or "
                                                "C_0r from which it is estimated"))
    return replace(bearing, C_u=L.c_u_estimate(bearing.kind, bearing.C_0r, bearing.D_pw),
                   C_u_estimated=True)


def _check_inputs_fit(bearing: Bearing, blocks: list) -> None:
    if bearing.kind in T.THRUST_TYPES and (bearing.alpha or 90.0) >= 90.0:
        for i, blk in enumerate(blocks):
            if blk.F_r > 0:
                key = "load.F_r" if len(blocks) == 1 else f"load.spectrum[{i}].F_r"
                raise InputError.at(key, blk.F_r, "a thrust bearing with α = 90° carries no radial "
                                                  "load; use 0, or a radial or angular bearing")


def run_assessment(bearing: Bearing, blocks: list, cond: Conditions,
                   spec: ValidatedSpec) -> Assessment:
    try:
        return assess(bearing, blocks, cond)
    except L.BearingError as exc:
        section, _, name = exc.key.partition(".")
        value = spec.data.get(section, {}).get(name) if isinstance(spec.data.get(section),
                                                                  dict) else None
        raise InputError(Problem(exc.key, str(exc), value) if value is not None
                         else Problem(exc.key, str(exc))) from None


# ----------------------------------------------------------------------------- report


def add_rows(res: Result, a: Assessment, info: dict) -> None:
    b, c = a.bearing, a.cond
    gost = c.method == GOST
    src = S.method_source(c.method)

    s = res.section("bearing", "Bearing")
    s.add("designation", info["catalogue"].name if info.get("catalogue") else "—", None,
          "", "catalogue designation (ISO, GOST)", S.CATALOGUE)
    s.add("type", b.kind, None, "", "bearing type", "")
    s.add("rating_source", info.get("rating", "given"), None, "", "where C_r comes from", "")
    if info.get("catalogue"):
        s.add("data_source", info["source"], None, "", "catalogue data source", S.CATALOGUE)
        if info.get("B") is not None:
            s.add("d", info["d"], "mm", "d", "bore diameter", S.CATALOGUE)
            s.add("D", info["D"], "mm", "D", "outside diameter", S.CATALOGUE)
            s.add("B", info["B"], "mm", "B", "width (total width T for tapered roller bearings)",
                  S.CATALOGUE)
    g = info.get("geometry")
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


def _suggestion(a: Assessment, info: dict, blocks: list, cond: Conditions) -> str:
    """The smallest catalogue bearing of the same type and bore that passes, as words."""
    d = info.get("d")
    if d is None:
        return ""
    for row in CAT.candidates(a.bearing.kind, d):
        if row.C_r <= a.bearing.C_r:
            continue
        try:
            cand = _with_c_u(_catalogue_bearing(row, a.bearing), cond)
            x = assess(cand, blocks, cond)
        except (L.BearingError, InputError):
            continue
        if x.passes:
            return f"; the catalogue {row.name} would give {_h(x.life_h)} h"
    return ""


def units_checks(a: Assessment, spec: ValidatedSpec) -> list[Check]:
    """``UNITS_LOAD`` when the life is beyond ``LIFE_UNITS_MAX`` and the load P below the
    requisite minimum load (0.01·C_r ball, 0.02·C_r roller bearings, [SKFMinLoad]): the
    life equation does not hold there ("other failure mechanisms than fatigue are
    determining"), and a load in N given where kN was meant lands there.  The fraction is
    P over the minimum load, scaled to :data:`geardesign.core.units_guard.LIGHT_LOAD_FRACTION`."""
    from geardesign.core.units_guard import LIGHT_LOAD_FRACTION, given, light_load

    if not a.life_h > T.LIFE_UNITS_MAX:
        return []
    kind = "ball" if a.p == 3.0 else "roller"
    P_min = T.MIN_LOAD_RATIO[kind] * a.bearing.C_r
    what = (f"P = {_f(a.P, 3)} N is {_f(100 * a.P / a.bearing.C_r, 2)} % of C_r = "
            f"{_kn(a.bearing.C_r)}, below the minimum load "
            f"{_f(T.MIN_LOAD_RATIO[kind], 2)}·C_r = {_f(P_min, 3)} N of a {kind} bearing, where "
            f"the elements skid and the life equation no longer holds; {a.life_name} = "
            f"{_h(a.life_h)} h")
    load = spec.data.get("load") or {}
    inputs = given(load, {"F_r": "N", "F_a": "N"}, "load")
    for i, blk in enumerate(load.get("spectrum") or []):
        inputs += given(blk, {"F_r": "N", "F_a": "N"}, f"load.spectrum[{i}]")
    return light_load("UNITS_LOAD", LIGHT_LOAD_FRACTION * a.P / P_min, what, inputs[:2],
                      "[SKFMinLoad]")


def life_checks(a: Assessment, info: dict, blocks: list, cond: Conditions) -> list[Check]:
    b, c = a.bearing, a.cond
    src = S.method_source(c.method)
    out: list[Check] = []
    if c.life_required is not None:
        hint = _suggestion(a, info, blocks, cond) if a.life_h < c.life_required else ""
        out.append(check(
            "LIFE", a.life_h >= c.life_required, "error",
            f"{a.life_name} = {_h(a.life_h)} h < required {_h(c.life_required)} h: use a bearing "
            f"with C_r >= {_kn(a.C_req)} (now {_kn(b.C_r)}){hint}, or reduce the load or the "
            f"required life",
            f"{a.life_name} = {_h(a.life_h)} h >= required {_h(c.life_required)} h",
            a.life_h, c.life_required, src))
    if a.s0 is not None:
        out.append(check(
            "STATIC_SAFETY", a.s0 >= c.s0_min, "error",
            f"s_0 = C_0r/P_0 = {_f(a.s0, 3)} < {_f(c.s0_min, 3)}: permanent deformation of the "
            f"raceways; use a bearing with C_0r >= {_kn(c.s0_min * a.static.P0)} or reduce the "
            f"peak load",
            f"s_0 = {_f(a.s0, 3)} >= {_f(c.s0_min, 3)}", a.s0, c.s0_min, S.ISO76))
    ratio = a.P / b.C_r
    out.append(check(
        "HIGH_LOAD", ratio <= T.HIGH_LOAD_RATIO, "warning",
        f"P = {_f(ratio, 3)}·C_r > 0.5·C_r: the life formula loses accuracy under so high a load "
        f"(ISO/TS 16281 or the manufacturer's method is advised); use a larger bearing",
        f"P = {_f(ratio, 3)}·C_r <= 0.5·C_r", ratio, T.HIGH_LOAD_RATIO, src))
    if b.C_0r is not None and a.P > b.C_0r:
        out.append(check(
            "LOAD_ABOVE_C0", False, "warning",
            f"P = {_kn(a.P)} exceeds C_0r = {_kn(b.C_0r)}: the rating life assumes no plastic "
            f"deformation; the calculated life is not valid, use a larger bearing",
            "", a.P, b.C_0r, src))
    for i, r in enumerate(a.blocks):
        where = "" if len(a.blocks) == 1 else f" (block {i + 1})"
        lf = r.factors
        if lf.clamped == "above":
            out.append(check(
                "AXIAL_TABLE", False, "warning",
                f"{lf.entry_name} = {_f(lf.entry, 3)}{where} is beyond the X/Y table: e and Y "
                f"of its last row are used; the axial load is too high for this bearing, use a "
                f"larger one or an angular contact bearing", "", lf.entry, None, src))
        elif lf.clamped == "below":
            out.append(check(
                "AXIAL_TABLE", False, "info",
                f"{lf.entry_name} = {_f(lf.entry, 3)}{where} is below the X/Y table: e and Y of "
                f"its first row are used", "", lf.entry, None, src))
        if b.kind == "cylindrical_roller" and r.block.F_a > 0:
            row = info.get("catalogue")
            design = row.designation.split()[0] if row is not None else ""
            if design == "NU":
                out.append(check(
                    "AXIAL_CAPACITY", False, "error",
                    f"F_a = {_kn(r.block.F_a)}{where} on {row.designation}: an NU bearing has "
                    f"no rib on the inner ring and carries no axial load; use NJ or NUP "
                    f"{row.designation[3:]} or take the axial load on another bearing", "",
                    r.block.F_a, 0.0, S.SKF + " p. 518"))
            elif design in ("NJ", "NUP"):
                rc = L.rib_capacity(b.C_0r, r.block.F_r, r.block.n, row.d, row.D, row.series,
                                    info.get("lubricant", "oil"))
                out.append(check(
                    "AXIAL_CAPACITY", r.block.F_a <= rc.limit, "error",
                    f"F_a = {_kn(r.block.F_a)}{where} > {_kn(rc.limit)}, the continuous axial "
                    f"load the ribs of {row.designation} carry (F_ap = {_kn(rc.F_ap)}, rib "
                    f"strength {_kn(rc.F_a_max)}); lower the speed or the axial load, or take "
                    f"it on a thrust or angular contact bearing",
                    f"F_a = {_kn(r.block.F_a)}{where} <= {_kn(rc.limit)} (rib capacity of "
                    f"{row.designation})", r.block.F_a, rc.limit, S.SKF + " p. 518"))
            out.append(check(
                "AXIAL_LOAD_IGNORED", False, "warning",
                f"F_a = {_kn(r.block.F_a)}{where} is not counted in the life of a cylindrical "
                f"roller bearing" + ("" if design in ("NU", "NJ", "NUP") else
                                     "; check the rib capacity (manufacturer) or take the "
                                     "axial load on another bearing"),
                "", r.block.F_a, None, src))
        if r.block.n < T.LOW_SPEED:
            out.append(check(
                "LOW_SPEED", False, "warning",
                f"n = {_f(r.block.n, 3)} min^-1{where} < {T.LOW_SPEED:g}: a rating life means "
                f"little at so low a speed; rely on the static safety s_0",
                "", r.block.n, T.LOW_SPEED, src))
        if r.a_iso is not None:
            if r.a_iso.kappa_clamped == "low":
                out.append(check(
                    "KAPPA_RANGE", False, "warning",
                    f"κ = {_f(r.kappa, 3)}{where} < 0.1: a_ISO is not defined; 0.1 was used. Use "
                    f"a more viscous oil or a lower temperature", "", r.kappa, T.KAPPA_MIN,
                    S.ISO2007))
            elif r.a_iso.kappa_clamped == "high":
                out.append(check(
                    "KAPPA_RANGE", False, "info",
                    f"κ = {_f(r.kappa, 3)}{where} > 4: κ = 4 was used (ISO 281)", "", r.kappa,
                    T.KAPPA_MAX, S.ISO2007))
            if r.a_iso.capped:
                out.append(check(
                    "A_ISO_LIMIT", False, "info",
                    f"a_ISO{where} limited to {r.a_iso.limit:g} (ISO 281"
                    f"{' EP-additive rule' if r.a_iso.ep_rule else ''})", "", r.a_iso.value,
                    r.a_iso.limit, S.ISO2007))
    if b.C_u_estimated:
        out.append(check(
            "C_U_ESTIMATED", False, "warning",
            f"C_u not given: estimated as {_kn(b.C_u)} from C_0r (ISO 281 approximation, "
            f"unverified); give the catalogue C_u (P_u) for a reliable a_ISO", "", b.C_u, None,
            S.ISO2007))
    return out


def _catalogue_bearing(row, template: Bearing | None = None) -> Bearing:
    kind = row.type
    alpha = 90.0 if kind in T.THRUST_TYPES else row.alpha
    f0 = row.f0
    if f0 is None and template is not None and template.designation == "":
        f0 = template.f0
    return Bearing(kind, 2 if kind == "spherical_roller" else 1, alpha, row.e, row.Y, row.C_r,
                   row.C_0r, row.C_u, False, f0, 0.5 * (row.d + row.D), row.designation, row.Y1,
                   row.Y0)


def _common_checks(spec: ValidatedSpec, info: dict) -> list[Check]:
    out = []
    t = spec.data["factors"]["temperature"]
    if t is not None and t > T.HOT:
        out.append(check("TEMPERATURE", False, "warning",
                         f"t = {t:g} °C > {T.HOT:g} °C: the bearing steel needs dimensional "
                         f"stabilisation for this temperature (ask the manufacturer)", "", t,
                         T.HOT, S.RU_PRACTICE))
    if info.get("reading"):
        out.append(check("DESIGNATION_READ", True, "info", "", info["reading"], None, None,
                         S.CATALOGUE))
    if info.get("note"):
        out.append(check("CATALOGUE_DATA", False, "warning",
                         f"catalogue row {info['catalogue'].designation}: {info['note']}; check "
                         f"the value against the manufacturer's catalogue", "", None, None,
                         S.CATALOGUE))
    return out


# ----------------------------------------------------------------------------- modes


def _select(spec: ValidatedSpec, blocks: list, checks: list, new_result) -> Result:
    b = spec.data["bearing"]
    req = spec.data["requirements"]
    problems = Problems()
    if req["life"] is None:
        problems.add(Problem("requirements.life", "missing; required in mode = \"select\": "
                                                  "a number > 0 (h)"))
    # the selection replaces the designation and its ratings: a designation names the type
    # and bore to select in (`--select` on a check spec runs as written)
    row = problems.stage(_catalogue_row, b) if b["designation"] is not None else None
    if row is Problems.FAILED:
        row = None
    replaced = [k for k in ("designation", "C_r", "C_0r") if b[k] is not None]
    if row is not None:
        for key, value in (("type", row.type), ("d", row.d)):
            if b[key] is None:
                b[key] = value
            elif b[key] != value:
                problems.add(Problem(f"bearing.{key}", f"contradicts bearing.designation = "
                                     f"\"{b['designation']}\" ({_type_words(row.type)}, d = "
                                     f"{_f(row.d)} mm), which names the type and bore to select "
                                     f"in; remove one of them", b[key]))
    if b["type"] is None and b["designation"] is None:
        problems.add(Problem("bearing.type", "missing; required in mode = \"select\" (or a "
                             "bearing.designation naming type and bore): one of "
                             + ", ".join(f'"{k}"' for k in sorted({r.type for r in
                                                                   CAT.bearings()}))))
    if b["d"] is None and b["designation"] is None:
        problems.add(Problem("bearing.d", "missing; required in mode = \"select\" (or a "
                             "bearing.designation naming type and bore): the bore diameter of "
                             "the shaft seat (mm)"))
    problems.raise_all()
    kind, d = b["type"], b["d"]
    if not CAT.bores(kind):
        raise InputError.at("bearing.type", kind, "the catalogue holds no bearing of this type; "
                                                  "use \"deep_groove_ball\" or \"tapered_roller\"")
    series = b["series"]
    if series:
        known = CAT.series_of(kind)
        for s in series:
            if s not in known:
                raise InputError.at("bearing.series", series,
                                    f"series \"{s}\" of {_type_words(kind)} bearings is not in the "
                                    f"catalogue; known: " + ", ".join(f'"{k}"' for k in known))
    rows = CAT.candidates(kind, d, series)
    if not rows:
        all_bores = CAT.bores(kind)
        near = sorted(sorted(all_bores, key=lambda x: abs(x - d))[:2])
        raise InputError.at("bearing.d", d, f"no catalogue {_type_words(kind)} bearing has this "
                                            f"bore; nearest catalogue bores: "
                                            + ", ".join(_f(x) for x in near) + f" mm (of "
                                            f"{_f(all_bores[0])}…{_f(all_bores[-1])} mm)")
    results = []
    cond0 = None
    for row in rows:
        cand = _catalogue_bearing(row)
        if b["f0"] is not None:
            cand = replace(cand, f0=b["f0"])
        cond = resolve_conditions(spec, cand, blocks, []) if cond0 is None else cond0
        cond0 = cond
        cand = _with_c_u(cand, cond)
        results.append((row, cand, run_assessment(cand, blocks, cond, spec)))
    chosen = next((x for x in results if x[2].passes), None)
    last = results[-1]
    pick = chosen or last
    resolve_conditions(spec, pick[1], blocks, checks)      # method-mismatch warnings, once
    res = new_result(spec)
    sel = res.section("selection", "Selection from the catalogue")
    sel.add("candidates", [r.designation for r, _, _ in results], None, "",
            "candidates, smallest first", S.CATALOGUE)
    sel.add("candidate_lives", [x.life_h for _, _, x in results], "h", "L_j",
            "adjusted life of each candidate", S.method_source(spec.data["method"]))
    sel.add("candidate_s0", [x.s0 for _, _, x in results], "-", "s_0,j",
            "static safety of each candidate", S.ISO76)
    sel.add("selected", pick[0].name if chosen else "none", None, "", "smallest bearing that "
            "meets the required life and static safety", S.CATALOGUE)
    if replaced:
        given = ", ".join(f"{k} = {b[k] if k == 'designation' else _kn(b[k])}"
                          for k in replaced)
        checks.append(check(
            "SELECTION_REPLACES", False, "info",
            f"mode = \"select\" chooses the bearing: the given {given} "
            f"{'is' if len(replaced) == 1 else 'are'} replaced by the selection (of "
            f"{_type_words(kind)} bearings with d = {_f(d)} mm)", "", None, None, S.CATALOGUE))
    checks.append(check(
        "SELECTION", chosen is not None, "error",
        f"no catalogue {_type_words(kind)} bearing with d = {_f(d)} mm reaches the requirements "
        f"(largest: {last[0].name}, {_h(last[2].life_h)} h, s_0 = "
        f"{_f(last[2].s0, 3) if last[2].s0 is not None else '—'}); C_r >= "
        f"{_kn(last[2].C_req)} is needed: use a larger bore, another type or two bearings",
        f"{pick[0].name} is the smallest {_type_words(kind)} bearing with d = {_f(d)} mm that "
        f"reaches {_h(req['life'])} h ({_h(pick[2].life_h)} h)", None, None, S.CATALOGUE))
    info = {"catalogue": pick[0], "source": pick[0].cite, "note": pick[0].note,
            "rating": "catalogue", "d": pick[0].d, "D": pick[0].D, "B": pick[0].B}
    add_rows(res, pick[2], info)
    # when nothing passes, SELECTION already names the life shortfall
    checks.extend(c for c in life_checks(pick[2], {}, blocks, pick[2].cond)
                  if chosen is not None or c.code != "LIFE")
    checks.extend(units_checks(pick[2], spec))
    checks.extend(_common_checks(spec, info))
    return res


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.bearing import CALCULATOR

    blocks = resolve_blocks(spec)
    checks: list[Check] = []
    if spec.data["mode"] == "pair":
        res = _pair(spec, blocks, checks, CALCULATOR.new_result)
        res.checks.extend(checks)
        return res
    if spec.data["pair"] is not None:
        raise InputError(Problem("pair", "used only with mode = \"pair\"; remove [pair] or set "
                                         "mode = \"pair\""))
    if spec.data["mode"] == "select":
        res = _select(spec, blocks, checks, CALCULATOR.new_result)
        res.checks.extend(checks)
        return res
    bearing, info = resolve_bearing(spec)
    _check_inputs_fit(bearing, blocks)
    cond = resolve_conditions(spec, bearing, blocks, checks)
    bearing = _with_c_u(bearing, cond)
    a = run_assessment(bearing, blocks, cond, spec)
    res = CALCULATOR.new_result(spec)
    add_rows(res, a, info)
    res.checks.extend(checks)
    res.checks.extend(life_checks(a, info, blocks, cond))
    res.checks.extend(units_checks(a, spec))
    res.checks.extend(_common_checks(spec, info))
    return res


# ----------------------------------------------------------------------------- pair

_PAIR_RATING_KEYS = ("C_r", "C_0r", "C_u", "e", "Y", "contact_angle", "d", "D")


def _bearing_b(spec: ValidatedSpec, a_info: dict, kind: str) -> tuple[Bearing, dict]:
    """Bearing B of a pair from [pair] (its designation, or its ratings, or bearing A's
    designation), resolved like [bearing]."""
    p = spec.data["pair"]
    a = spec.data["bearing"]
    b = {k: None for k in a}
    b.update(rows=1, series=None)
    given = {k: p[k] for k in _PAIR_RATING_KEYS if p[k] is not None}
    b.update(given)
    if p["designation"] is not None:
        b.update(designation=p["designation"], maker=p["maker"])
    elif not given and a["designation"] is not None:
        b.update(designation=a["designation"], maker=a["maker"])
    else:
        b["type"] = kind
    if b["designation"] is None:
        b["type"] = kind
    sub = ValidatedSpec(dict(spec.data, bearing=b), list(spec.assumed), spec.source,
                        spec.base_dir)
    try:
        bearing, info = resolve_bearing(sub)
    except InputError as exc:
        raise InputError([replace(pr, key=pr.key.replace("bearing.", "pair.", 1))
                          for pr in exc.problems]) from None
    if bearing.kind != kind:
        raise InputError.at("pair.designation", p["designation"],
                            f"bearing B must be a {_type_words(kind)} bearing like bearing A")
    return bearing, info


def _induced(b: Bearing, F_r: float, factor: float | None, key: str) -> float:
    if b.kind == "tapered_roller":
        Y = b.Y
        if Y is None:
            tan_a = (b.e / 1.5) if b.e is not None else (
                math.tan(math.radians(b.alpha)) if b.alpha else None)
            if not tan_a:
                raise InputError(Problem(f"{key}.Y", "missing; the induced axial force of a "
                                         "tapered roller bearing needs its catalogue Y or e"))
            Y = T.ROLLER_RADIAL[1]["Y_gt_cot"] / tan_a
        return PR.induced_tapered(F_r, Y, PR.K_TAPERED if factor is None else factor)
    if b.alpha is None:
        raise InputError(Problem(f"{key}.contact_angle", "missing; the induced axial force of "
                                 "an angular contact ball bearing needs its contact angle"))
    return PR.induced_angular(F_r, b.alpha, factor)


def _pair(spec: ValidatedSpec, blocks: list, checks: list, new_result) -> Result:
    p = spec.data["pair"]
    if p is None:
        raise InputError(Problem("pair", "missing; required in mode = \"pair\": bearing B's "
                                         "arrangement and radial load F_r"))
    if len(blocks) != 1:
        raise InputError(Problem("load.spectrum", "mode = \"pair\" takes a single load case "
                                 "(load.F_r, F_a, speed), not a spectrum"))
    A, info_a = resolve_bearing(spec)
    if A.kind not in PR.pair_types():
        raise InputError.at("bearing.type" if spec.data["bearing"]["type"] else
                            "bearing.designation", spec.data["bearing"]["type"] or
                            spec.data["bearing"]["designation"],
                            "a pair with induced axial loads is one of angular contact ball "
                            "or tapered roller bearings")
    B, info_b = _bearing_b(spec, info_a, A.kind)
    blk = blocks[0]
    F_rA, F_rB, F_a = blk.F_r, p["F_r"], blk.F_a
    ld = spec.data["load"]
    if "load.F_a" not in spec.assumed and ld["F_a"] is not None:
        F_a = ld["F_a"]
    k = p["induced_factor"]
    F_iA = _induced(A, F_rA, k, "bearing")
    F_iB = _induced(B, F_rB, k, "pair")
    who = PR.carrier(p["arrangement"], F_a)
    if who == "B":
        sol = PR.solve(F_iA, F_iB, abs(F_a))
        F_aA, F_aB = sol.F_aA, sol.F_aB
    else:
        sol = PR.solve(F_iB, F_iA, abs(F_a))
        F_aA, F_aB = sol.F_aB, sol.F_aA
    cond = resolve_conditions(spec, A, blocks, checks)
    A = _with_c_u(A, cond)
    B = _with_c_u(B, cond)
    bA = [Block(F_rA, F_aA, blk.n, 1.0)]
    bB = [Block(F_rB, F_aB, blk.n, 1.0)]
    cond_b = replace(cond, F_r0=None, F_a0=None)
    xa = run_assessment(A, bA, cond, spec)
    xb = run_assessment(B, bB, cond_b, spec)

    res = new_result(spec)
    s = res.section("pair", "Pair: induced axial loads")
    s.add("arrangement", p["arrangement"].replace("_", "-"), None, "", "arrangement", "given")
    s.add("F_rA", F_rA, "N", "F_rA", "radial load on bearing A", "given")
    s.add("F_rB", F_rB, "N", "F_rB", "radial load on bearing B", "given")
    s.add("K_a", abs(F_a), "N", "K_a", "external axial load on the shaft", "given")
    s.add("K_a_carrier", who, None, "", "bearing that carries K_a", S.PAIR)
    name = "k·F_r/Y" if A.kind == "tapered_roller" else "R·F_r"
    s.add("F_iA", F_iA, "N", "F_iA", f"induced axial force of A ({name})", S.PAIR)
    s.add("F_iB", F_iB, "N", "F_iB", f"induced axial force of B ({name})", S.PAIR)
    s.add("F_aA", F_aA, "N", "F_aA", "axial load on bearing A", S.PAIR)
    s.add("F_aB", F_aB, "N", "F_aB", "axial load on bearing B", S.PAIR)
    c, o = ("B", "A") if who == "B" else ("A", "B")       # carrier, other
    F_io = F_iA if o == "A" else F_iB
    F_ic = F_iB if c == "B" else F_iA
    case = (f"F_a{o} = F_i{o}, F_a{c} = F_i{o} + K_a" if F_io + abs(F_a) >= F_ic
            else f"F_a{c} = F_i{c}, F_a{o} = F_i{c} − K_a")
    s.add("case", case, None, "", "governing case", S.PAIR)
    add_rows(res, xa, info_a)
    _add_b_rows(res, xb, info_b)
    checks.extend(life_checks(xa, info_a, bA, cond))
    checks.extend(units_checks(xa if xa.P <= xb.P else xb, spec))
    checks.extend(replace(c, message="bearing B: " + c.message)
                  for c in life_checks(xb, info_b, bB, cond_b))
    checks.extend(_common_checks(spec, info_a))
    return res


def _add_b_rows(res: Result, x: Assessment, info: dict) -> None:
    src = S.method_source(x.cond.method)
    row = info.get("catalogue")
    t = res.section("bearing_B", "Bearing B")
    t.add("designation", row.name if row else "—", None, "", "catalogue designation",
          info.get("source") or S.CATALOGUE)
    t.add("C_r", x.bearing.C_r, "N", "C_rB", "basic dynamic load rating", src)
    lf = x.blocks[0].factors
    t.add("X", lf.X, "-", "X_B", "radial load factor", src)
    t.add("Y", lf.Y, "-", "Y_B", "axial load factor", src)
    t.add("P", x.P, "N", "P_B", "equivalent dynamic load", src)
    t.add("L10h", x.L10h, "h", "L10h,B", "basic rating life in hours", src)
    t.add("life_h", x.life_h, "h", x.life_name + ",B", "adjusted life", src)
    if x.s0 is not None:
        t.add("s0", x.s0, "-", "s_0B", "static safety factor C_0r/P_0", S.ISO76)
