"""Design checks of a Novikov DLZ pair.  Each check says what is wrong and what to change.

Limits (constants below): contact continuity b_w ≥ (1 − δ)·p_x (Cyclogram 2017, error);
ε_β ≥ 1 + 0.2 and at least two points in contact at every instant (design practice, warnings); σ_H ≤
σ_HP, σ_F ≤ σ_FP (errors); β within 8…30°, b_w/d1 ≤ 1.5,
z1 ≥ 10 and z_v1 ≥ 12, HB1 − HB2 ≥ 20 (warnings, design practice); the fitted factors
inside their range ψ = 0.05…0.25 (warning when ψ was clamped).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.core.result import Check, check
from geardesign.novikov import sources as S
from geardesign.novikov.tables import PSI_RANGE

EPS_BETA_MARGIN = 0.2
"""ε_β should exceed 1 by this margin (1.1–1.2 is the usual practical minimum)."""
POINTS_MIN = 2
BETA_RANGE_DEG = (8.0, 30.0)
FACE_RATIO_MAX = 1.5
Z1_MIN = 10
ZV1_MIN = 12.0


def _mm(x: float) -> str:
    return f"{x:.1f}"


@dataclass(frozen=True)
class ContinuityData:
    b_w: float
    p_x: float
    eps_beta: float
    delta: float
    b_min_1: float      # least b_w for >= 1 point (continuity)
    b_min_2: float      # least b_w for >= 2 points
    n_min: int
    n_max: int
    beta_deg: float


def continuity_checks(c: ContinuityData) -> list[Check]:
    out = []
    ok = c.b_w >= c.b_min_1 * (1.0 - 1e-12)
    out.append(check(
        "CONTACT_CONTINUITY", ok, "error",
        f"contact interrupted: b_w = {_mm(c.b_w)} mm < b_w,min = (1 − δ)·p_x = "
        f"{_mm(c.b_min_1)} mm (δ = {c.delta:.4f}, p_x = {_mm(c.p_x)} mm): at times no point of "
        f"either line of action is in the face; increase the face width to at least "
        f"{math.ceil(c.b_min_1 * 10) / 10:.1f} mm (or the helix angle)",
        f"contact continuous: b_w = {_mm(c.b_w)} mm >= (1 − δ)·p_x = {_mm(c.b_min_1)} mm",
        c.b_w, c.b_min_1, S.CYCLOGRAM,
        (("gear.face_width", math.ceil(c.b_min_1 * 10) / 10),)))
    limit = 1.0 + EPS_BETA_MARGIN
    out.append(check(
        "OVERLAP_RATIO", c.eps_beta >= limit, "warning",
        f"ε_β = {c.eps_beta:.3f} < {limit:g}: little axial overlap; Novikov gears carry the "
        f"load only through the axial overlap; increase the face width to at least "
        f"{math.ceil(limit * c.p_x * 10) / 10:.1f} mm or the helix angle",
        f"ε_β = {c.eps_beta:.3f} >= {limit:g}", c.eps_beta, limit, S.PRACTICE,
        (("gear.face_width", math.ceil(limit * c.p_x * 10) / 10),)))
    out.append(check(
        "CONTACT_POINTS", c.n_min >= POINTS_MIN, "warning",
        f"at times only {c.n_min} point(s) of contact carry the whole load (n = "
        f"{c.n_min}…{c.n_max}); for at least {POINTS_MIN} points at every instant make "
        f"b_w >= {_mm(c.b_min_2)} mm",
        f"{c.n_min}…{c.n_max} points in contact at every instant", c.n_min, POINTS_MIN,
        S.CYCLOGRAM))
    lo, hi = BETA_RANGE_DEG
    out.append(check(
        "HELIX_ANGLE", lo <= c.beta_deg <= hi, "warning",
        f"β = {c.beta_deg:.3f}° outside the usual {lo:g}…{hi:g}° of Novikov gears: "
        + ("a small helix angle needs a wide face for the axial overlap"
           if c.beta_deg < lo else "a large helix angle gives large axial forces"),
        f"β = {c.beta_deg:.3f}° within {lo:g}…{hi:g}°", c.beta_deg, hi if c.beta_deg > hi else lo,
        S.PRACTICE))
    return out


def module_checks(m: float, series: tuple[tuple[float, ...], tuple[float, ...]],
                  scope: tuple[float, float] | None) -> list[Check]:
    out = []
    s1, s2 = series
    in1 = any(abs(m - v) < 1e-9 for v in s1)
    in2 = any(abs(m - v) < 1e-9 for v in s2)
    near = min(s1 + s2, key=lambda v: abs(v - m))
    out.append(check(
        "MODULE_SERIES", in1 or in2, "warning",
        f"m = {m:g} mm is not a preferred module of GOST 14186-69; use e.g. {near:g} mm",
        f"m = {m:g} mm is in the {'first' if in1 else 'second'} series of GOST 14186-69",
        m, near, S.MODULES))
    if scope is not None:
        lo, hi = scope
        out.append(check(
            "MODULE_RANGE", lo <= m <= hi, "warning",
            f"m = {m:g} mm outside {lo:g}…{hi:g} mm, the module range of GOST 15023-76: the rack "
            f"constants may not apply",
            f"m = {m:g} mm within {lo:g}…{hi:g} mm (GOST 15023-76)", m,
            hi if m > hi else lo, S.RACK))
    return out


def proportion_checks(z1: int, z_v1: float, b_w: float, d1: float, x1: float, x2: float,
                      HB1: float, HB2: float, diff_min: float) -> list[Check]:
    out = []
    ok = z1 >= Z1_MIN and z_v1 >= ZV1_MIN
    out.append(check(
        "PINION_TEETH", ok, "warning",
        f"small pinion (z1 = {z1}, z_v1 = {z_v1:.2f}; usual z1 >= {Z1_MIN}, z_v1 >= "
        f"{ZV1_MIN:g}): the tip may be pointed and the form factor is extrapolated; increase z1 "
        f"or reduce x1",
        f"z1 = {z1}, z_v1 = {z_v1:.2f}", z_v1, ZV1_MIN, S.PRACTICE))
    ratio = b_w / d1
    out.append(check(
        "FACE_WIDTH_RATIO", ratio <= FACE_RATIO_MAX, "warning",
        f"b_w/d1 = {ratio:.2f} > {FACE_RATIO_MAX:g}: the pair is sensitive to misalignment; "
        f"reduce the face width or increase the pinion diameter",
        f"b_w/d1 = {ratio:.2f} <= {FACE_RATIO_MAX:g}", ratio, FACE_RATIO_MAX, S.PRACTICE))
    pos = [f"x{i} = {x:g}" for i, x in ((1, x1), (2, x2)) if x > 0.0]
    out.append(check(
        "SHIFT_UNVERIFIED", not pos, "warning",
        f"{', '.join(pos)} > 0: the exponents of the Y_v formula for x > 0 are unreadable in the "
        f"source and placeholders are used; σ_F of that gear is unverified",
        "no positive shift (Y_v formula fully read)", max(x1, x2), 0.0, S.YV))
    out.append(check(
        "HARDNESS_DIFFERENCE", HB1 - HB2 >= diff_min, "warning",
        f"HB1 − HB2 = {HB1 - HB2:g} < {diff_min:g}: a harder pinion helps the run-in the method "
        f"assumes; make the pinion {diff_min:g}…50 HB harder than the wheel",
        f"HB1 − HB2 = {HB1 - HB2:g} >= {diff_min:g} (run-in)", HB1 - HB2, diff_min, S.PRACTICE))
    return out


def psi_check(clamped: int, evaluations: int, psi_min: float, psi_max: float,
              critical_clamped: list[str]) -> Check:
    lo, hi = PSI_RANGE
    ok = clamped == 0
    where = (f"; at the critical point of {', '.join(critical_clamped)}" if critical_clamped
             else "; not at the critical points")
    return check(
        "PSI_RANGE", ok, "warning",
        f"ψ = a/b_w outside {lo:g}…{hi:g} at {clamped} of {evaluations} loaded points "
        f"(ψ = {psi_min:.4f}…{psi_max:.4f}){where}: K_W, K_F, K_H, K_ψ were evaluated at "
        f"the clamped ψ, outside the range of Korotkin's fits",
        f"ψ = {psi_min:.4f}…{psi_max:.4f} within {lo:g}…{hi:g} at all {evaluations} loaded "
        f"points", float(clamped), 0.0, S.KOROTKIN)


def stress_check(code: str, sigma: float, allowable: float, what: str, where: str,
                 share: float, source: str) -> Check:
    ok = sigma <= allowable * (1.0 + 1e-12)
    advice = ("increase the face width or the module, use harder steel"
              + (f", improve the accuracy grades (deviations cause {share:.0%} of it)"
                 if share > 0.05 else "")
              + ", or reduce the torque")
    return check(
        code, ok, "error",
        f"{what} = {sigma:.1f} MPa > allowable {allowable:.1f} MPa ({where}); {advice}",
        f"{what} = {sigma:.1f} MPa <= allowable {allowable:.1f} MPa ({where})",
        sigma, allowable, source)
