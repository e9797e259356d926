"""The checks of an ISO 6336 rating: S_H ≥ S_Hmin and S_F ≥ S_Fmin per gear (of the
spectrum when one is rated), the static safety factors at the peak torque, scuffing
(:func:`.scuffing.scuffing_checks`) and the notes on the inputs' ranges; judged by the one
:func:`geardesign.spur.strength.verdict.verdict` of both methods."""

from __future__ import annotations

from geardesign.core.result import Check, check
from geardesign.spur.strength.advice import (
    advised_percent, face_width_beyond, face_width_fix, face_width_up)
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.strength.iso6336.record import S2, S3, S5, S1328, IsoRating
from geardesign.spur.strength.iso6336.scuffing import scuffing_checks
from geardesign.spur.strength.verdict import verdict
from geardesign.spur.tolerances import iso1328

WHO = ("pinion", "wheel")


def checks(v: dict, members: tuple[str, str] = WHO, spectrum: bool = False,
           peak: bool = False, internal: bool = False, clamped: tuple = (),
           found: dict | None = None) -> list[Check]:
    """Checks of an ISO 6336 rating ``v``: S_H ≥ S_Hmin and S_F ≥ S_Fmin per gear (of the
    spectrum when one is given), the static safety factors at the peak torque, and notes.

    The advice names the face width and the scale of the pair (centre distance, module and
    face width in proportion) that pass, when ``found`` carries them (``{"b": (b_w,
    b_pitting, b_bending), "k": (a_w, k_pitting, k_bending), "face_limit": the largest
    face width tried as a multiple of b_w}``, found by re-rating); else
    it follows the scaling of the formulas at the present load factors: σ_H ∝ 1/√b and
    ∝ a^(-3/2) at a fixed ratio b/a; σ_F ∝ 1/(b m_n)."""
    found = found or {}

    def by_rerating(kind: int) -> str | None:
        parts = []
        if "k" in found and found["k"][kind] is not None:
            a_w, k = found["k"][0], found["k"][kind]
            parts.append(f"increase the centre distance to at least {k * a_w:.1f} mm "
                         f"(+{100 * (k - 1):.0f} %, module and face width in proportion)")
        if "b" in found and found["b"][kind] is not None:
            b_w, b = found["b"][0], face_width_up(found["b"][kind])
            parts.append(f"the face width to at least {b:g} mm (+{100 * (b / b_w - 1):.0f} %: "
                         f"set gear.face_width = {b:g})")
        if not parts:
            return None
        text = " or ".join(parts) + " (found by re-rating)"
        if "b" in found and found["b"][kind] is None:
            text += "; " + face_width_beyond(found["b"][0], found["face_limit"])
        return text

    def face_fix(kind: int) -> tuple:
        b = found.get("b")
        return face_width_fix(b[0], b[kind]) if b else ()

    out: list[Check] = []
    judged = verdict(v)
    spec = " (load spectrum)" if spectrum else ""
    for kind, what, lim, ok, src, fixed in (
            ("H", "pitting", "σ_Hlim", judged.contact_ok, S2, 1),
            ("F", "tooth bending", "σ_Flim", judged.bending_ok, S3, 2)):
        need = v[f"S_{kind}min"]
        for k in (1, 2):
            who = members[k - 1]
            S = v[f"S_{kind}spec{k}" if spectrum else f"S_{kind}{k}"]
            r = need / S
            if kind == "H":
                advice = (by_rerating(1) or
                          f"increase the centre distance by {advised_percent(r ** (2 / 3) - 1)} "
                          f"(module and face width in proportion), or the face width by "
                          f"{advised_percent(r * r - 1)} (at the present load factors)")
            else:
                advice = (f"increase the module by {advised_percent(r - 1)} (same centre "
                          f"distance, fewer teeth), or "
                          + (by_rerating(2) or f"the face width by {advised_percent(r - 1)} "
                                               f"(at the present load factors)"))
            out.append(check(
                f"ISO_{'PITTING' if kind == 'H' else 'BENDING'}_{who.upper()}", ok[k - 1],
                "error",
                f"ISO 6336 {what}, {who}: S_{kind}{k} = {S:.2f} < S_{kind}min = {need:.2f}"
                f"{spec}: {advice}, or use a {who} material with {lim} at least "
                f"{v[f'sigma_{kind}lim{k}'] * r:.0f} MPa",
                f"ISO 6336 {what}, {who}: S_{kind}{k} = {S:.2f} >= {need:.2f}", S, need, src,
                face_fix(fixed)))
    S_Hmin, S_Fmin = v["S_Hmin"], v["S_Fmin"]
    if peak:
        for kind, sym, need, src in (("PITTING", "S_Hst", S_Hmin, S2), ("BENDING", "S_Fst", S_Fmin, S3)):
            for k in (1, 2):
                who, up = members[k - 1], members[k - 1].upper()
                S = v[f"{sym}{k}"]
                expo = 2.0 if kind == "PITTING" else 1.0
                out.append(check(
                    f"ISO_STATIC_{kind}_{up}", S >= need * (1 - 1e-12), "error",
                    f"ISO 6336 static {kind.lower()}, {who}: {sym}{k} = {S:.2f} < {need:.2f} at "
                    f"the peak torque: limit the peak torque to "
                    f"{v['T_peak'] * (S / need) ** expo:.0f} N·m (e.g. a slip coupling), or "
                    f"enlarge the gears",
                    f"ISO 6336 static {kind.lower()}, {who}: {sym}{k} = {S:.2f} >= {need:.2f}",
                    S, need, src))
    if "S_intS" in v:
        out.extend(scuffing_checks(v))
    if internal and v.get("form_internal", "rack") == "rack":
        out.append(check("ISO_INTERNAL_FORM_FACTOR", False, "info",
                         "ISO 6336: the internal gear's Y_F and Y_S are those of the rack it "
                         "tends to (conservative); give the shaper cutter that cuts it "
                         "(cutter teeth) for the standard's internal-gear method", "",
                         None, None, S3))
    for k in (1, 2):
        if f"tolerance_range{k}" in v:
            out.append(check(
                f"ISO_TOLERANCE_RANGE_{members[k - 1].upper()}", False, "warning",
                f"ISO 6336: the {members[k - 1]}'s flank tolerances (f_pb, f_fα, f_Hβ, F_β "
                f"of K_v, K_Hα, K_Hβ): {v[f'tolerance_range{k}']}; give the measured "
                f"deviations (iso.f_pb, iso.f_falpha, iso.F_beta, iso.f_ma) for a rating "
                f"within the standard", "", None, None,
                "[ISO1328-1-1995]" if v.get("tolerance_standard") == iso1328.STANDARD_1995
                else S1328))
    for k, (lo, hi, scale) in clamped:
        out.append(check(f"ISO_HARDNESS_RANGE_{members[k - 1].upper()}", False, "warning",
                         f"ISO 6336-5: the {members[k - 1]} hardness lies outside the material "
                         f"line's range {lo:g}…{hi:g} {scale}; σ_Hlim and σ_Flim were taken at "
                         f"the nearer end: give sigma_Hlim and sigma_Flim under [iso.{WHO[k - 1]}]",
                         "", None, None, S5))
    return out


def passes(v: dict, kind: str) -> bool:
    """Whether a rating ``v`` passes pitting (``"H"``) or bending (``"F"``) on both gears
    (:func:`geardesign.spur.strength.verdict.verdict`)."""
    judged = verdict(v)
    return bool(judged.contact_passes if kind == "H" else judged.bending_passes)


def rating_checks(rating: IsoRating, internal: bool = False, members=WHO,
                  found: dict | None = None) -> list[Check]:
    """:func:`checks` of a finished rating (what a calculator calls)."""
    v = rating.v
    clamped = []
    for k in (1, 2):
        line = T.MATERIAL_LINES[v[f"type{k}"]]
        if rating.materials.clamped[k - 1]:
            clamped.append((k, (*line["range"], line["scale"])))
    return checks(v, members, "S_Hspec1" in v, "S_Hst1" in v, internal, tuple(clamped), found)
