"""The checks of one rated bearing (:class:`geardesign.bearing.solve.Rated`): life, static
safety, load range, axial load and rib capacity, speed, κ and a_ISO range, estimated C_u,
temperature, the catalogue data, and a load in the wrong unit."""

from __future__ import annotations

import math

from geardesign.bearing import sources as S
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Assessment
from geardesign.bearing.conditions import fmt as _f
from geardesign.bearing.resolve import Facts
from geardesign.bearing.solve import Rated
from geardesign.core.result import Check, check


def _h(x: float) -> str:
    return f"{x:,.0f}".replace(",", " ") if math.isfinite(x) else "∞"


def _kn(x: float) -> str:
    return f"{x / 1000:.3g} kN"


def units_checks(a: Assessment, load: dict | None) -> list[Check]:
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
    load = load or {}
    inputs = given(load, {"F_r": "N", "F_a": "N"}, "load")
    for i, blk in enumerate(load.get("spectrum") or []):
        inputs += given(blk, {"F_r": "N", "F_a": "N"}, f"load.spectrum[{i}]")
    return light_load("UNITS_LOAD", LIGHT_LOAD_FRACTION * a.P / P_min, what, inputs[:2],
                      "[SKFMinLoad]")


def life_checks(rated: Rated) -> list[Check]:
    """The checks of one rated bearing: life, static safety, load range, axial load, speed,
    κ and a_ISO range, an estimated C_u."""
    a, info = rated.a, rated.facts
    b, c = a.bearing, a.cond
    src = S.method_source(c.method)
    out: list[Check] = []
    if c.life_required is not None:
        hint = (f"; the catalogue {rated.better[0].name} would give {_h(rated.better[1])} h"
                if rated.better is not None else "")
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
            row = info.catalogue
            design = row.designation.split()[0] if row is not None else ""
            if design == "NU":
                out.append(check(
                    "AXIAL_CAPACITY", False, "error",
                    f"F_a = {_kn(r.block.F_a)}{where} on {row.designation}: an NU bearing has "
                    f"no rib on the inner ring and carries no axial load; use NJ or NUP "
                    f"{row.designation[3:]} or take the axial load on another bearing", "",
                    r.block.F_a, 0.0, S.SKF + " p. 518"))
            elif design in ("NJ", "NUP"):
                rc = rated.ribs[i]
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


def common_checks(t: float | None, info: Facts) -> list[Check]:
    """Temperature, how a designation was read, a catalogue row's note."""
    out = []
    if t is not None and t > T.HOT:
        out.append(check("TEMPERATURE", False, "warning",
                         f"t = {t:g} °C > {T.HOT:g} °C: the bearing steel needs dimensional "
                         f"stabilisation for this temperature (ask the manufacturer)", "", t,
                         T.HOT, S.RU_PRACTICE))
    if info.reading:
        out.append(check("DESIGNATION_READ", True, "info", "", info.reading, None, None,
                         S.CATALOGUE))
    if info.note:
        out.append(check("CATALOGUE_DATA", False, "warning",
                         f"catalogue row {info.catalogue.designation}: {info.note}; check "
                         f"the value against the manufacturer's catalogue", "", None, None,
                         S.CATALOGUE))
    return out
