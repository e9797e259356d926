"""Why GOST 21354-87 and ISO 6336:2019 rate the same pair differently.

Both methods compute σ_H = Z_E Z_H Z_ε √(F_t (u ± 1)/(b d1 u) · K_A K_v K_Hβ K_Hα) and
σ_HP from σ_Hlim and a life factor ([GOST21354]; [ISO6336-1], [ISO6336-2]); they differ in
how each factor is found. The check ``METHODS_DIFFER`` lists the factors of the two ratings
with the largest ratio between them and the inputs that drive each, so the designer can
decide which assumption is his (e.g. K_Hβ: the GOST chart by bearing arrangement and
ψ_bd, against ISO 6336-1 method C with f_ma = f_Hβ for gears without adjustment at
assembly, [ISO6336-1] 7.6.2.4).
"""

from __future__ import annotations

from geardesign.core.result import Check, check

GOST = "GOST 21354-87"
ISO = "ISO 6336:2019"

FACTORS = (
    ("K_Hβ", "K_Hbeta", "K_Hbeta", "kh_beta"),
    ("K_Fβ", "K_Fbeta", "K_Fbeta", "kh_beta"),
    ("K_v", "K_Hv", "K_v", "k_v"),
    ("K_Hα", "K_Halpha", "K_Halpha", "k_alpha"),
    ("K_Fα", "K_Falpha", "K_Falpha", "k_alpha"),
    ("Z_N (pinion)", "Z_N1", "Z_NT1", "life"),
    ("Z_N (wheel)", "Z_N2", "Z_NT2", "life"),
    ("σ_Hlim (pinion)", "sigma_Hlim1", "sigma_Hlim1", "material"),
    ("σ_Hlim (wheel)", "sigma_Hlim2", "sigma_Hlim2", "material"),
)
"""(symbol, key in the GOST record, key in the ISO record, what drives it)."""

DIFFER_RATIO = 1.05
"""Ratio between the methods' values from which a factor is named (5 %)."""

SHOWN = 3
"""How many factors the check names."""


def _drivers(kind: str, g: dict, i: dict, spec) -> str:
    """The inputs behind a factor in each method, with the keys a designer can set."""
    gear = spec.data["gear"] or {}
    iso = spec.data.get("iso") or {}
    grade = gear.get("accuracy_grade")
    if kind == "kh_beta":
        if iso.get("f_ma") is not None:
            fma = f"f_ma = {i['f_ma']:.3g} µm (iso.f_ma)"
        else:
            fma = (f"f_ma = f_Hβ = {i['f_ma']:.3g} µm of grade {grade} for gears without "
                   f"adjustment at assembly (give iso.f_ma for gears adjusted at assembly)")
        mod = iso.get("helix_modification") or "none"
        fsh = (f"f_sh = {i['f_sh']:.3g} µm "
               + ("(iso.f_sh)" if iso.get("f_sh") is not None
                  else "(give iso.shaft_span, iso.shaft_diameter, iso.shaft_K_prime or iso.f_sh "
                       "from the shaft data)"))
        return (f"ISO: {fma}, iso.helix_modification = \"{mod}\", {fsh}, at "
                f"{i['w']:.0f} N/mm; GOST: the chart of gear.bearing_scheme = "
                f"{gear.get('bearing_scheme')} at ψ_bd = {g['psi_bd']:.2f}")
    if kind == "k_v":
        return (f"gear.accuracy_grade = {grade}, the speed (v = {i['v']:.3g} m/s), "
                f"gear.tip_relief; ISO method B at {i['w']:.0f} N/mm")
    if kind == "k_alpha":
        fpb = (f" (f_pb: GOST {g['f_pb']:.3g} µm, ISO {i['f_pb']:.3g} µm)"
               if "f_pb" in g and "f_pb" in i else "")
        return f"gear.accuracy_grade = {grade}{fpb} and running-in"
    if kind == "life":
        return "load.life_hours and the load spectrum (each method's S-N curve and N_lim)"
    return "the material lines of each method (hardness, treatment, quality)"


ADVICE_APART = 1.25
"""Ratio between the two methods' advised values (face width, centre distance, σ_Hlim)
from which the check says why they are far apart (25 %)."""

ADVISED = (("face_width", "face width", "mm"), ("center_distance", "centre distance", "mm"),
           ("sigma_Hlim", "σ_Hlim", "MPa"))
"""The advised quantities compared: (key, name, unit)."""


def advised(method: str, face_width: float | None, center_distance: float | None,
            sigma_Hlim: float | None) -> dict:
    """What a method's failed contact/bending checks advise, for :func:`methods_differ`:
    the least passing face width, the centre distance of the scaled pair and the σ_Hlim
    that passes (each found by that method's own re-rating or scaling; ``None`` when it
    advises none)."""
    return {"method": method, "face_width": face_width, "center_distance": center_distance,
            "sigma_Hlim": sigma_Hlim}


def _advice_apart(g: dict, i: dict) -> list[str]:
    """The advised quantities whose values differ by more than :data:`ADVICE_APART`."""
    ag, ai = g.get("advice") or {}, i.get("advice") or {}
    out = []
    for key, name, unit in ADVISED:
        a, b = ag.get(key), ai.get(key)
        if a and b and max(a / b, b / a) > ADVICE_APART:
            out.append(f"{name} {_num(a)} {unit} by GOST against {_num(b)} {unit} by ISO "
                       f"(×{max(a / b, b / a):.2f})")
    return out


def _num(x: float) -> str:
    return f"{x:.0f}" if abs(x) >= 100.0 else f"{x:.3g}"


def _passes(v: dict, method: str) -> bool:
    from geardesign.spur.strength.verdict import verdict

    return bool(verdict(v).passes)


def methods_differ(rated: dict, spec) -> list[Check]:
    """``METHODS_DIFFER`` for a pair rated by both methods (``rated``: method → value
    record): the :data:`SHOWN` factors with the largest ratio between the methods (at least
    :data:`DIFFER_RATIO`) and their inputs; a warning when one method passes the pair and
    the other fails it, or when both fail it and their advice (face width, centre distance,
    σ_Hlim, :func:`advised`) is more than :data:`ADVICE_APART` apart (the check then names
    those values before the factors that drive them), else information."""
    g, i = rated[GOST], rated[ISO]
    rows = []
    for sym, kg, ki, kind in FACTORS:
        a, b = g.get(kg), i.get(ki)
        if not isinstance(a, float) or not isinstance(b, float) or a <= 0 or b <= 0:
            continue
        r = max(a / b, b / a)
        if r >= DIFFER_RATIO:
            rows.append((r, sym, a, b, kind))
    rows.sort(key=lambda x: -x[0])
    shown, kinds = [], set()
    for r, sym, a, b, kind in rows:   # one factor per cause (K_Fβ follows K_Hβ)
        if len(shown) == SHOWN or kind in kinds:
            continue
        kinds.add(kind)
        shown.append(f"{sym} {_num(a)} by GOST against {_num(b)} by ISO (×{r:.2f}): "
                      f"{_drivers(kind, g, i, spec)}")
    pg, pi = _passes(g, GOST), _passes(i, ISO)
    apart = [] if pg or pi else _advice_apart(g, i)
    if not shown:
        if not apart:
            return []
        shown = ["none of the factors compared differs by 5 % or more (the difference lies "
                 "in the methods' formulas: Z factors, life factors, the bending model)"]
    verdicts = ("" if pg == pi else
                f"{GOST} {'passes' if pg else 'fails'} and {ISO} {'passes' if pi else 'fails'} "
                f"the pair; ")
    far = ("both methods fail the pair and their advice is far apart (more than "
           f"{100 * (ADVICE_APART - 1):.0f} %): " + ", ".join(apart) + "; ") if apart else ""
    S = (f"S_H {min(g['S_H1'], g['S_H2']):.2f} (GOST) against {min(i['S_H1'], i['S_H2']):.2f} "
         f"(ISO)")
    return [check(
        "METHODS_DIFFER", False, "info" if pg == pi and not apart else "warning",
        f"{verdicts}{far}{S}; the methods differ most in " + "; ".join(shown)
        + ". Decide which assumption is yours and give it as an input",
        "", rows[0][0] if rows else 1.0, DIFFER_RATIO, "[GOST21354]; [ISO6336-1]")]
