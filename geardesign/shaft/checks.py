"""The checks of an analysed shaft: fatigue and static safety at the critical places (with
the diameter scale that passes, :mod:`geardesign.shaft.scaling`), deflection at the gear
seats, bearing slopes, the critical speed, the formulas' ranges of DIN 743 and the load
units guard."""

from __future__ import annotations

import math

from geardesign.core.result import check
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft import sources as S
from geardesign.shaft import strength as ST
from geardesign.shaft.records import ARCMIN, ShaftRecord
from geardesign.shaft.scaling import MAX_SCALE

def units_checks(r: ShaftRecord, spec: ValidatedSpec) -> list:
    """``UNITS_LOAD`` when the peak loads use less than 1 % of the static strength
    (1/S_T: the stresses are proportional to the loads), as loads typed in N and N·m where
    kN and kN·m were meant do (:mod:`geardesign.core.units_guard`); the hints name the
    largest loads given."""
    from geardesign.core.units_guard import given, light_load

    cs = r.critical_static
    if cs is None or not cs.S_static > 0.0 or not math.isfinite(cs.S_static):
        return []
    fraction = 1.0 / cs.S_static
    inputs = []
    for i, ld in enumerate(spec.data.get("load") or []):
        inputs += given(ld, {"Fy": "N", "Fz": "N", "Fx": "N", "torque": "N·m", "moment_y": "N·m",
                             "moment_z": "N·m"}, f"load[{i}]")
    inputs.sort(key=lambda x: -abs(x[1]))
    what = (f"the peak loads use {100 * fraction:.2g} % of the static strength (S_T = "
            f"{cs.S_static:.4g} at {cs.label})")
    return light_load("UNITS_LOAD", fraction, what, inputs[:2], S.VON_MISES)


def _din_range_checks(r: ShaftRecord, d_eff: float) -> list:
    """Warnings where DIN 743's formulas are used outside their range."""
    from geardesign.shaft.din743 import tables as din_tables

    out = []
    sh = din_tables()["shoulder"]
    if any(s.outside_table for s in r.sections):
        where = ", ".join(s.label for s in r.sections if s.outside_table)
        out.append(check(
            "FILLET_TABLE_RANGE", False, "warning",
            f"the shoulder or round groove at {where} lies outside the range of the DIN 743-2 "
            f"formula for α "
            f"(r/t >= {sh['r_t_min']:g}, d/D <= {sh['d_D_max']:g}): the formula is used "
            f"beyond it; enlarge the fillet or check α against a handbook",
            "", None, None, S.DIN_NOTCH))
    d_eff_max = din_tables()["K_1"]["d_eff_max"]
    if d_eff > d_eff_max:
        out.append(check(
            "FACTOR_TABLE_RANGE", False, "warning",
            f"the blank diameter d_eff = {d_eff:g} mm is above the {d_eff_max:g} mm of the "
            f"DIN 743 technological size factor K_1: its last value is used; give the "
            f"blank's own sigma_B and sigma_T", "", None, None, S.DIN_K1))
    return out


def _val(v: float) -> float | None:
    """A check value: None where the quantity is unbounded (an unloaded shaft has an
    infinite safety), so that the check passes without an infinite number."""
    return v if math.isfinite(v) else None


def _fmt(v: float) -> str:
    return "∞" if math.isinf(v) else f"{v:.2f}"


def _scale_advice(k: float | None, sec, what: str, notches: bool = False) -> str:
    """The advice to grow the shaft: every diameter (bores, fillet radii; with ``notches``
    the grooves' depth, radius and width and the cross-bores) times ``k``."""
    if k is None:
        return (f"even {MAX_SCALE:g} times the diameters do not reach {what}: use a stronger "
                f"steel or reduce the load")
    also = (" (the grooves' depth, radius and width and the cross-bores' diameter scale "
            "with them)" if notches else "")
    return (f"scale every step's diameter (and bore and fillet radius) by {k:.2f}, which "
            f"reaches {what} (analysed again){also}: at {sec.label} (x = {sec.x:g} mm) from "
            f"{sec.d:g} to {math.ceil(sec.d * k * 10.0 - 1e-9) / 10.0:g} mm; choose the "
            f"bearings and hubs for the new seats")


def shaft_checks(r: ShaftRecord, lim: dict, speed: float, loads, supports, origin, steps,
            mat_sigma_B: float, din: bool = False, d_eff: float = 0.0,
            scale: dict | None = None) -> list:
    out = []
    scale = scale or {}
    c = r.critical
    if c is not None:
        S_req = lim["S_min"]
        notches = any(st.groove_depth is not None or st.cross_bore is not None
                      for st in steps)
        advice = _scale_advice(scale.get("S"), c, f"[S] = {S_req:g}", notches)
        if c.fillet_r is not None and c.concentrator == "fillet":
            r_big = min(c.fillet_t / 2.0, 0.05 * c.d) if c.fillet_t else c.fillet_r
            if r_big > c.fillet_r:
                advice += (f", or enlarge the fillet radius from {c.fillet_r:g} to about "
                           f"{r_big:.1f} mm (t/r = 2)")
        elif c.concentrator == "keyway" and c.keyway_cutter == "end_mill":
            advice += ", or cut the keyway with a disc cutter"
        elif c.concentrator == "press fit":
            advice += ", or relieve the hub edge (groove, thinner hub end)"
        elif c.concentrator == "round groove":
            advice += ", or give the groove a larger radius"
        elif c.concentrator == "ring groove":
            advice += ", or give the groove a larger root radius"
        elif c.concentrator == "cross-bore":
            advice += ", or make the hole smaller"
        out.append(check(
            "FATIGUE", c.S >= S_req, "error",
            f"fatigue safety S = {_fmt(c.S)} < [S] = {S_req:g} at {c.label} (x = {c.x:g} mm, "
            f"{c.concentrator}): {advice}",
            f"fatigue safety S = {_fmt(c.S)} >= [S] = {S_req:g} (lowest at {c.label}, "
            f"x = {c.x:g} mm)", _val(c.S), S_req, S.DIN_FATIGUE if din else S.FATIGUE))
        cs = r.critical_static
        S_req = lim["S_static_min"]
        out.append(check(
            "STATIC_STRENGTH", cs.S_static >= S_req, "error",
            f"static safety at the peak load S_T = {_fmt(cs.S_static)} < [S_T] = {S_req:g} at "
            f"{cs.label} (x = {cs.x:g} mm): "
            f"{_scale_advice(scale.get('S_static'), cs, f'[S_T] = {S_req:g}', notches)}, "
            f"or use a steel of higher yield strength",
            f"static safety at the peak load S_T = {_fmt(cs.S_static)} >= [S_T] = {S_req:g} "
            f"(lowest at {cs.label})", _val(cs.S_static), S_req,
            S.DIN_STATIC if din else S.VON_MISES))
    margin = lim["critical_speed_margin"]
    ratio = r.n_cr / speed
    out.append(check(
        "CRITICAL_SPEED", ratio >= margin, "error",
        f"first bending critical speed n_cr = {r.n_cr:.0f} min^-1 is only {ratio:.2f} times "
        f"the speed {speed:g} min^-1 (at least {margin:g} required): stiffen the shaft "
        f"(larger diameters, shorter span, bearings closer to heavy parts)",
        f"first bending critical speed n_cr = {r.n_cr:.0f} min^-1 = {ratio:.1f}·n",
        _val(ratio), margin, S.PRACTICE))
    tilt = ST.tables()["tilt"]
    for sp, p in zip(supports, r.supports):
        if sp.type not in tilt:
            continue
        lo, hi, name = tilt[sp.type]["min"], tilt[sp.type]["max"], tilt[sp.type]["name"]
        a = p.slope / ARCMIN
        sev = "warning" if a <= hi else "error"
        out.append(check(
            "BEARING_TILT", a <= lo, sev,
            f"slope at bearing {p.name} (x = {p.x:g} mm) {a:.2f}′ exceeds "
            f"{'the permissible ' + format(hi, 'g') if a > hi else 'the lower limit ' + format(lo, 'g')}′ "
            f"of a {name} ({lo:g}…{hi:g}′): stiffen the shaft between the bearings or use a "
            f"bearing that tolerates tilt",
            f"slope at bearing {p.name} {a:.2f}′ <= {lo:g}′ ({name})", a, lo, S.TILT))
    for ld, p in zip(loads, r.loads):
        if ld.module is None:
            continue
        limit = 0.01 * ld.module
        out.append(check(
            "GEAR_DEFLECTION", p.w <= limit, "warning",
            f"deflection at {p.name} (x = {p.x:g} mm) {p.w * 1000:.1f} µm exceeds 0.01·m = "
            f"{limit * 1000:.1f} µm: stiffen the shaft or bring the bearings closer",
            f"deflection at {p.name} {p.w * 1000:.1f} µm <= 0.01·m = {limit * 1000:.1f} µm",
            p.w, limit, S.GEAR_SEAT))
    if din:
        out.extend(_din_range_checks(r, d_eff))
        return out
    if any(s.outside_table for s in r.sections):
        where = ", ".join(s.label for s in r.sections if s.outside_table)
        out.append(check(
            "FILLET_TABLE_RANGE", False, "warning",
            f"t/r or r/d of the fillet at {where} lies outside the table (t/r above 5 or r/d "
            f"below 0.01): the nearest row is used and may understate K_σ; enlarge the fillet",
            "", None, None, S.TABLES))
    big = [s for s in r.sections if s.d > ST.TABLE_D_MAX]
    high = ST.tables()["fillet"]["sigma_B"][-1]
    if big or mat_sigma_B > high:
        why = []
        if mat_sigma_B > high:
            why.append(f"σ_B = {mat_sigma_B:g} MPa is above the tables' {high:g} MPa "
                       f"(K_σ, K_τ grow with σ_B)")
        if big:
            why.append(f"d = {max(s.d for s in big):g} mm is above the tables' "
                       f"{ST.TABLE_D_MAX:g} mm (K_d falls, K_σ/K_d of a fit grows with d)")
        out.append(check(
            "FACTOR_TABLE_RANGE", False, "warning",
            "; ".join(why) + ": the last column is used and may understate the concentration; "
            "check the factors against a handbook for this size and strength", "",
            None, None, S.TABLES))
    if origin.get("blank"):
        d_max = max(s.diameter for s in steps)
        blank = origin["blank"]
        out.append(check(
            "BLANK_SIZE", d_max <= blank, "warning",
            f"the largest diameter {d_max:g} mm exceeds the blank size {blank:g} mm for which "
            f"the properties of steel {origin['grade']} at {origin['HB']:g} HB hold: give "
            f"the blank's own sigma_B and sigma_T",
            f"blank properties of steel {origin['grade']} hold up to {blank:g} mm",
            d_max, blank, S.MATERIAL) if blank > 0 else check(
            "BLANK_SIZE", True, "info", "", f"properties of steel {origin['grade']} hold for "
            f"any blank size", None, None, S.MATERIAL))
    return out
