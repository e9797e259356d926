"""Design checks of a worm pair.  Each check says what is wrong and what to change.

Limits (design practice validation rules,
[GOST19650]; [Chernavsky]): z1 in 1, 2, 4; z2 >= 26 (error), 28 ... 80 (warning); x within −0.5 ... +0.7
(warning); b2 <= 0.75/0.67·d_a1; b1 >= the GOST 19650-97 length; q >= 0.212·z2 (warning);
v_s <= the material's limit; σ_H <= [σ]_H, σ_F <= [σ]_F and their peak values;
f <= f_lim and t_oil <= t_lim (the allowed values, written [f] and [t] in the textbooks;
the report table would read "[f]" as markup); self-locking as required (dependable only
for γ_w below about 3.5°).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.core.result import Check, check
from geardesign.worm import sources as S
from geardesign.worm.design import (
    PREFERRED_SHIFT,
    STIFFNESS_Q_RATIO,
    is_standard_pair,
    round_up_center_distance,
)
from geardesign.worm.pair import Analysis, Options, WheelProps
from geardesign.worm import tables

Z2_MIN = 26
STARTS_MAX = 4
"""The most worm starts (GOST 2144-76: 1, 2, 4)."""
"""Fewer wheel teeth are undercut off the mid-plane and weak (Dunaev & Lelikov: 26 ... 28)."""
Z2_POWER = (28, 80)
"""Usual wheel tooth numbers of power drives ([Dunaev]; design practice)."""
SELF_LOCKING_RELIABLE = 3.5
"""Self-locking is dependable without vibration only for γ_w below about 3.5° ([Dunaev])."""


@dataclass(frozen=True)
class Advice:
    """``fix``: the spec changes, ``((key, value), ...)``, and ``text`` how the message says
    it; when no standard pair passes, ``fix`` is ``None`` and ``text`` a remark that follows
    the check's own advice."""

    fix: tuple | None
    text: str


def _deg(rad: float) -> float:
    return math.degrees(rad)


def _fmt(v: float, digits: int = 3) -> str:
    text = f"{v:.{digits}f}".rstrip("0").rstrip(".")
    return text if text not in ("-0", "") else "0"


def _series_text(values: list[float]) -> str:
    return ", ".join(_fmt(v) for v in values)


def pair_checks(a: Analysis, w: WheelProps, o: Options, self_locking: str,
                advice: Advice | None = None) -> list[Check]:
    """The checks of the analysed pair ``a``.  ``advice``: the standard pair found by
    re-rating (:func:`geardesign.worm.advice.standard_pair_advice`) that the failed checks
    of :data:`geardesign.worm.advice.RERATED` then advise, with it as their ``fix``."""
    def lever(default: str) -> str:
        if advice is None:
            return default
        return advice.text if advice.fix else default + advice.text

    fix = advice.fix if advice is not None and advice.fix else ()
    g = a.g
    p = g.inp
    out: list[Check] = []

    # -- standard parameters
    out.append(check(
        "WORM_STARTS", p.z1 != 3, "warning",
        "z1 = 3 is not a GOST 2144-76 number of starts (1, 2, 4): no standard hob; use "
        "z1 = 2 or 4",
        f"z1 = {p.z1} is a standard number of starts", p.z1, None, S.G2144))
    m_ok, q_ok, rec = is_standard_pair(p.m, p.q)
    if not m_ok:
        msg = (f"m = {_fmt(p.m)} mm is not a GOST 19672-74 module (first row "
               f"{_series_text(tables.series()['module_1'])} mm): no standard hob; use one of "
               f"these")
    elif not q_ok:
        msg = (f"q = {_fmt(p.q, 4)} is not a GOST 19672-74 diameter factor (first row "
               f"{_series_text(tables.series()['q_1'])}): no standard hob; use one of these")
    elif not rec:
        allowed = tables.recommended_q(p.m)
        msg = (f"(m, q) = ({_fmt(p.m)}, {_fmt(p.q)}) is not a recommended pair (GOST "
               f"19672-74 table as recalled); with m = {_fmt(p.m)} mm use q = "
               f"{_series_text(allowed) if allowed else 'a first-row value'}")
    else:
        msg = ""
    out.append(check(
        "STANDARD_PAIR", m_ok and q_ok and rec, "warning", msg,
        f"(m, q) = ({_fmt(p.m)}, {_fmt(p.q)}) is a standard pair", None, None, S.G19672))
    s = tables.series()
    rows = s["center_distance_1"] + s["center_distance_2"]
    a_ok = any(abs(g.a_w - v) < 1e-6 for v in rows)
    nxt = round_up_center_distance(g.a_w, "both")
    out.append(check(
        "STANDARD_CENTER_DISTANCE", a_ok, "warning",
        f"a_w = {_fmt(g.a_w)} mm is not a GOST 2144-76 centre distance"
        + (f" (next: {_fmt(nxt)} mm)" if nxt else "")
        + ": standard housings and hobs do not fit; use a standard a_w and let x follow",
        f"a_w = {_fmt(g.a_w)} mm is a GOST 2144-76 centre distance", g.a_w, None, S.G2144))

    # -- wheel shift and teeth
    lo, hi = PREFERRED_SHIFT
    out.append(check(
        "SHIFT_RANGE", lo - 1e-9 <= p.x <= hi + 1e-9, "warning",
        f"x = {_fmt(p.x, 4)} outside the preferred {lo:g} ... +{hi:g}: the wheel teeth "
        f"become {'pointed' if p.x > hi else 'weak at the root'}; change a_w, m or q to bring "
        f"x nearer 0",
        f"x = {_fmt(p.x, 4)} within {lo:g} ... +{hi:g}", p.x, hi if p.x > hi else lo, S.G19650))
    if p.z2 < Z2_MIN:
        u = p.z2 / p.z1
        ok, msg = False, (f"z2 = {p.z2} < {Z2_MIN}: the wheel teeth are undercut off the "
                          f"mid-plane and weak; use z2 >= {Z2_MIN} ({Z2_POWER[0]} or more for a "
                          f"power drive)")
        if u * STARTS_MAX < Z2_MIN:     # no number of starts gives the ratio with z2 >= 26
            msg += (f"; u = {_fmt(u, 3)} with at most {STARTS_MAX} starts gives z2 <= "
                    f"{math.floor(u * STARTS_MAX + 1e-9)}: a worm pair needs u >= "
                    f"{_fmt(Z2_MIN / STARTS_MAX, 3)}, use a cylindrical stage for this ratio")
    elif p.x < g.x_min - 1e-9:
        ok, msg = False, (f"wheel undercut in the mid-plane: x = {_fmt(p.x, 4)} < x_min = "
                          f"{_fmt(g.x_min, 4)}; "
                          + lever(f"increase x to at least {math.ceil(g.x_min * 1000) / 1000:.3f}"
                                  f" (a larger a_w or a smaller q)")
                          + ", or use more wheel teeth")
    else:
        ok, msg = True, ""
    out.append(check(
        "UNDERCUT_WHEEL", ok, "error", msg,
        f"wheel not undercut (z2 = {p.z2} >= {Z2_MIN}, x = {_fmt(p.x, 4)} >= x_min = "
        f"{_fmt(g.x_min, 4)})", p.x, g.x_min, S.G19650, fix))
    if p.z2 < Z2_POWER[0]:
        msg = (f"z2 = {p.z2} < {Z2_POWER[0]}: few wheel teeth for a power drive (undercut "
               f"risk off the mid-plane); use z2 >= {Z2_POWER[0]}")
    elif p.z2 > Z2_POWER[1]:
        msg = (f"z2 = {p.z2} > {Z2_POWER[1]}: the worm becomes long and flexible for a power "
               f"drive; use more starts, two stages, or check WORM_DEFLECTION closely")
    else:
        msg = ""
    out.append(check(
        "WHEEL_TEETH", not msg, "warning", msg,
        f"z2 = {p.z2} within {Z2_POWER[0]} ... {Z2_POWER[1]} for a power drive", p.z2, None,
        S.PRACTICE))
    out.append(check(
        "CONTACT_RATIO", g.eps_alpha >= 1.0, "error",
        f"ε_α ≈ {g.eps_alpha:.3f} < 1 in the wheel mid-plane: the mesh is not continuous; "
        + lever("reduce x") + ", or use more wheel teeth",
        f"ε_α ≈ {g.eps_alpha:.3f} >= 1 in the wheel mid-plane", g.eps_alpha, 1.0, S.G19650,
        fix))

    # -- proportions
    out.append(check(
        "FACE_WIDTH", g.b2 <= g.b2_max + 1e-9, "error",
        f"b2 = {_fmt(g.b2)} mm > {_fmt(g.b2_max / g.d_a1, 2)}·d_a1 = {_fmt(g.b2_max)} mm: the "
        f"rim ends overhang the worm threads and carry nothing; reduce face_width to at most "
        f"{math.floor(g.b2_max * 10) / 10:g} mm",
        f"b2 = {_fmt(g.b2)} mm <= {_fmt(g.b2_max / g.d_a1, 2)}·d_a1 = {_fmt(g.b2_max)} mm",
        g.b2, g.b2_max, S.G19650))
    out.append(check(
        "WORM_LENGTH", g.b1 >= g.b1_min - 1e-9, "error",
        f"worm thread length b1 = {_fmt(g.b1)} mm < {_fmt(g.b1_min)} mm required for "
        f"z2 = {p.z2}, x = {_fmt(p.x, 4)}"
        + (" (grinding allowance included)" if p.ground else "")
        + f"; increase worm_length to at least {math.ceil(g.b1_min):g} mm",
        f"worm thread length b1 = {_fmt(g.b1)} mm >= {_fmt(g.b1_min)} mm", g.b1, g.b1_min,
        S.G19650))
    q_min = STIFFNESS_Q_RATIO * p.z2
    out.append(check(
        "WORM_STIFFNESS_Q", p.q >= q_min - 1e-9, "warning",
        f"q = {_fmt(p.q, 4)} < 0.212·z2 = {_fmt(q_min)}: slender worm; use a larger q or "
        f"mind WORM_DEFLECTION",
        f"q = {_fmt(p.q, 4)} >= 0.212·z2 = {_fmt(q_min)}", p.q, q_min, S.DUNAEV))

    # -- sliding speed and self-locking
    out.append(check(
        "SLIDING_SPEED", a.s.v_s <= w.v_s_max + 1e-9, "error",
        f"v_s = {a.s.v_s:.2f} m/s > {_fmt(w.v_s_max)} m/s allowed for {w.name} (group "
        f"{w.group}): scuffing and wear; use a tin bronze for high sliding speeds (group I), "
        f"or lower the worm speed",
        f"v_s = {a.s.v_s:.2f} m/s <= {_fmt(w.v_s_max)} m/s allowed for {w.name}", a.s.v_s,
        w.v_s_max, S.TEXTBOOK))
    gw, rho = _deg(g.gamma_w), _deg(a.fr.rho)
    state = (f"self-locking (γ_w = {gw:.2f}° <= ρ' = {rho:.2f}°)" if a.self_locking
             else f"not self-locking (γ_w = {gw:.2f}° > ρ' = {rho:.2f}°)")
    if self_locking == "avoid":
        out.append(check(
            "SELF_LOCKING", not a.self_locking, "error",
            f"the pair is {state}: η = {a.eta:.3f} and the wheel cannot drive the worm; use "
            f"more starts or a smaller q so that γ_w > ρ', or set load.self_locking = "
            f"\"require\" if it is wanted",
            f"{state}, as wanted for a power drive", gw, rho, S.TEXTBOOK))
    elif self_locking == "require":
        out.append(check(
            "SELF_LOCKING", a.self_locking, "error",
            f"the pair is {state}: the load can drive the worm backwards; use z1 = 1 and a "
            f"larger q so that γ_w < ρ', or fit a brake",
            f"{state}, as required", gw, rho, S.TEXTBOOK))
        if a.self_locking:
            out.append(check(
                "SELF_LOCKING_RELIABILITY", gw <= SELF_LOCKING_RELIABLE, "warning",
                f"γ_w = {gw:.2f}° > {SELF_LOCKING_RELIABLE}°: self-locking is not dependable "
                f"under vibration or shocks; fit a brake or use γ_w < {SELF_LOCKING_RELIABLE}°",
                f"γ_w = {gw:.2f}° <= {SELF_LOCKING_RELIABLE}°: self-locking dependable without "
                f"strong vibration", gw, SELF_LOCKING_RELIABLE, S.TEXTBOOK))
    else:
        out.append(Check("SELF_LOCKING", "info", True, f"the pair is {state}", gw, rho,
                         S.TEXTBOOK))

    # -- strength of the wheel
    if a.sigma_HP <= 0.0:
        msg = (f"[σ]_H = {a.sigma_HP:.1f} MPa at v_s = {a.s.v_s:.2f} m/s: a group {w.group} "
               f"wheel cannot carry load at this sliding speed; use a bronze for higher "
               f"sliding speeds or lower the worm speed")
    else:
        nxt = round_up_center_distance(a.a_w_req) if a.a_w_req is not None else None
        msg = (f"σ_H = {a.sigma_H:.1f} MPa > [σ]_H = {a.sigma_HP:.1f} MPa: "
               + lever(f"increase the centre distance to at least {a.a_w_req:.1f} mm"
                       + (f" (GOST 2144-76: {_fmt(nxt)} mm)" if nxt else ""))
               + ", use a stronger wheel material, or harden and grind the worm")
    out.append(check(
        "CONTACT_STRESS", a.sigma_H <= a.sigma_HP, "error", msg,
        f"σ_H = {a.sigma_H:.1f} MPa <= [σ]_H = {a.sigma_HP:.1f} MPa", a.sigma_H, a.sigma_HP,
        S.CHERNAVSKY, fix))
    out.append(check(
        "CONTACT_STRESS_PEAK", a.sigma_Hmax <= a.allow.sigma_HP_max, "error",
        f"σ_Hmax = {a.sigma_Hmax:.1f} MPa > [σ]_Hmax = {a.allow.sigma_HP_max:.1f} MPa at the "
        f"peak torque {_fmt(a.T_peak)} N·m: the flanks yield; limit the peak torque (a "
        f"torque limiter), or " + lever("increase the centre distance"),
        f"σ_Hmax = {a.sigma_Hmax:.1f} MPa <= [σ]_Hmax = {a.allow.sigma_HP_max:.1f} MPa",
        a.sigma_Hmax, a.allow.sigma_HP_max, S.TEXTBOOK, fix))
    out.append(check(
        "BENDING_STRESS", a.sigma_F <= a.sigma_FP, "error",
        f"σ_F = {a.sigma_F:.1f} MPa > [σ]_F = {a.sigma_FP:.1f} MPa: the wheel teeth break; "
        + lever("increase the module (a larger a_w or a smaller q)")
        + ", or use a stronger wheel material",
        f"σ_F = {a.sigma_F:.1f} MPa <= [σ]_F = {a.sigma_FP:.1f} MPa", a.sigma_F, a.sigma_FP,
        S.DUNAEV, fix))
    out.append(check(
        "BENDING_STRESS_PEAK", a.sigma_Fmax <= a.allow.sigma_FP_max, "error",
        f"σ_Fmax = {a.sigma_Fmax:.1f} MPa > [σ]_Fmax = {a.allow.sigma_FP_max:.1f} MPa at the "
        f"peak torque {_fmt(a.T_peak)} N·m: limit the peak torque, or "
        + lever("increase the module"),
        f"σ_Fmax = {a.sigma_Fmax:.1f} MPa <= [σ]_Fmax = {a.allow.sigma_FP_max:.1f} MPa",
        a.sigma_Fmax, a.allow.sigma_FP_max, S.TEXTBOOK, fix))

    # -- worm stiffness
    out.append(check(
        "WORM_DEFLECTION", a.f <= a.f_lim, "error",
        f"worm deflection f = {a.f:.4f} mm > f_lim = {_fmt(o.deflection_limit, 4)}·m = "
        f"{a.f_lim:.4f} mm: the worm bends out of mesh; "
        + lever("increase q or the module")
        + f", or shorten the bearing span (l = {_fmt(a.span, 1)} mm)",
        f"worm deflection f = {a.f:.4f} mm <= f_lim = {a.f_lim:.4f} mm", a.f, a.f_lim, S.DUNAEV,
        fix))

    # -- thermal balance
    out.append(check(
        "OIL_TEMPERATURE", a.th.t_oil <= o.oil_limit, "error",
        f"oil temperature {a.th.t_oil:.1f} °C > t_lim = {_fmt(o.oil_limit)} °C: add cooling fins "
        f"(a larger thermal.housing_area)"
        + ("" if o.fan else ", a fan on the worm shaft (thermal.fan = true)")
        + ", a water coil, or " + lever("a larger centre distance"),
        f"oil temperature {a.th.t_oil:.1f} °C <= t_lim = {_fmt(o.oil_limit)} °C", a.th.t_oil,
        o.oil_limit, S.THERMAL, fix))
    return out
