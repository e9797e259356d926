"""Design checks of the ring-gear rim: each says what is wrong and what to change.

Limits (sources in each check): required probability of non-failure (a spec input, 90 %
by default, a design choice); σ_-1eq <= σ_-1D; |σ_m| + σ_a < σ_u (domain of the limiting
amplitude diagrams) and σ_max < σ_y ([Gutyria2017]); warnings from design practice: σ_-1/σ_u within
0.35-0.6, K_c within 1-2, Y_F within 3-4.6, σ_max <= 0.8σ_y,
coefficients of variation within 0.02-0.2, Rz >= 0.32 µm; thin rim by ISO 6336-3 Y_B and
AGMA K_B; assembly and neighbouring conditions of the planets; resonance bands outside
the operating speed range.
"""

from __future__ import annotations

from geardesign.core.result import Check, check
from geardesign.epicycle_rim import sources as S

ENDURANCE_RATIO = (0.35, 0.6)
LOAD_SHARING = (1.0, 2.0)
FORM_FACTOR = (3.0, 4.6)
YIELD_MARGIN = 0.8
SCATTER_RANGE = (0.02, 0.2)
RZ_MIN = 0.32


def _f(x: float, d: int = 2) -> str:
    return f"{x:.{d}f}"


def probability_check(P: float, P_req: float, case: str, advice: str) -> Check:
    return check(
        "PROBABILITY", P >= P_req, "error",
        f"probability of non-failure P = {_f(P * 100, 1)} % < required {_f(P_req * 100, 1)} % "
        f"({case}); {advice}",
        f"probability of non-failure P = {_f(P * 100, 1)} % >= required "
        f"{_f(P_req * 100, 1)} % ({case})", P * 100.0, P_req * 100.0, S.GOST25504)


def endurance_check(sigma_eq: float, sigma_m1D: float, case: str, advice: str) -> Check:
    return check(
        "ENDURANCE_LIMIT", sigma_eq <= sigma_m1D, "error",
        f"equivalent amplitude σ_-1eq = {_f(sigma_eq)} MPa exceeds the median endurance limit "
        f"of the rim σ_-1D = {_f(sigma_m1D)} MPa ({case}): the median life is finite "
        f"(P < 50 %); {advice}",
        f"equivalent amplitude σ_-1eq = {_f(sigma_eq)} MPa <= σ_-1D = {_f(sigma_m1D)} MPa "
        f"({case})", sigma_eq, sigma_m1D, S.A)


def domain_check(worst: float, sigma_u: float, case: str) -> Check:
    return check(
        "MEAN_STRESS_DOMAIN", worst < sigma_u, "error",
        f"|σ_m| + σ_a = {_f(worst)} MPa >= σ_u = {_f(sigma_u)} MPa ({case}): outside the "
        f"limiting-amplitude diagram, the fatigue result is not valid; reduce the load or "
        f"use a stronger steel",
        f"|σ_m| + σ_a = {_f(worst)} MPa < σ_u = {_f(sigma_u)} MPa (inside the limiting-"
        f"amplitude diagram)", worst, sigma_u, S.A)


def yield_checks(s_max: float, sigma_y: float, case: str) -> list[Check]:
    out = [check(
        "STATIC_YIELD", s_max < sigma_y, "error",
        f"peak stress σ_max = {_f(s_max)} MPa >= σ_y = {_f(sigma_y)} MPa ({case}): the fillet "
        f"yields, the fatigue result is not valid; reduce the load or use a stronger steel",
        f"peak stress σ_max = {_f(s_max)} MPa < σ_y = {_f(sigma_y)} MPa", s_max, sigma_y, S.A)]
    if s_max < sigma_y:
        lim = YIELD_MARGIN * sigma_y
        out.append(check(
            "YIELD_MARGIN", s_max <= lim, "warning",
            f"peak stress σ_max = {_f(s_max)} MPa > {YIELD_MARGIN}·σ_y = {_f(lim)} MPa "
            f"({case}): close to static yielding; check the peak loads",
            f"peak stress σ_max = {_f(s_max)} MPa <= {YIELD_MARGIN}·σ_y", s_max, lim,
            S.PRACTICE))
    return out


def range_warning(code: str, value: float, lo: float, hi: float, what: str, advice: str,
                  source: str) -> Check:
    ok = lo <= value <= hi
    return check(code, ok, "warning",
                 f"{what} = {value:.4g} outside {lo:g}…{hi:g}: {advice}",
                 f"{what} = {value:.4g} within {lo:g}…{hi:g}", value, hi if value > hi else lo,
                 source)


def rim_thickness_check(ratio_m: float, Y_B: float, m_B: float, K_B: float) -> Check:
    ok = Y_B == 1.0 and K_B == 1.0
    yb = "outside its range (δ/m <= 1.75)" if Y_B != Y_B else f"{Y_B:.3f}"
    return check(
        "RIM_THICKNESS", ok, "warning",
        f"thin rim: δ/m = {ratio_m:.2f} (ISO 6336-3 Y_B = {yb}; 1 needs δ/m >= 3.5) and "
        f"backup ratio m_B = δ/h = {m_B:.2f} (AGMA K_B = {K_B:.3f}; 1 needs m_B >= 1.2): the "
        f"rim bends under the mesh loads and cracks may cross it; the rim fatigue analysis "
        f"applies, or thicken the rim",
        f"rim thick enough for the tooth: δ/m = {ratio_m:.2f} >= 3.5 and m_B = {m_B:.2f} >= 1.2",
        m_B, 1.2, S.ISO6336_3)


def hoop_estimate_warning(loaded: float, between: float) -> Check:
    return check(
        "HOOP_ESTIMATE", False, "warning",
        f"rim hoop stresses estimated as a free thin ring ({loaded:.1f} / {between:.1f} MPa): "
        f"the estimate ignores the teeth, the tangential forces and the supports and can be "
        f"twice the finite-element values; give load.hoop_stress_loaded and "
        f"hoop_stress_between from an FE analysis",
        "", loaded, None, S.ROARK)


def assembly_check(indices: list[float], nearest: list[float], step: float) -> Check:
    bad = [i for i, x in enumerate(indices) if abs(x - round(x)) > 1e-6]
    shown = ", ".join(f"{a:.4f}°" for a in nearest)
    return check(
        "ASSEMBLY", not bad, "error",
        "identical planets cannot be assembled at these angles: (z_s + z_r)·θ/360° = "
        + ", ".join(f"{indices[i]:.4f}" for i in bad)
        + f" for planet(s) {', '.join(str(i + 1) for i in bad)} must be integers; use "
        f"multiples of {step:.4f}°, e.g. {shown}",
        f"planets assemble: (z_s + z_r)·θ/360° integer for every planet (step {step:.4f}°)",
        max((abs(x - round(x)) for x in indices), default=0.0), 0.0, S.ASSEMBLY)


def spacing_check(min_gap: float, limit: float) -> Check:
    return check(
        "PLANET_SPACING", min_gap > limit, "error",
        f"neighbouring planets overlap: smallest spacing {min_gap:.3f}° <= {limit:.3f}° "
        f"needed by their tip circles; spread the planets or use fewer or smaller planets",
        f"neighbouring planets clear: smallest spacing {min_gap:.3f}° > {limit:.3f}°",
        min_gap, limit, S.ASSEMBLY)


def coaxiality_warning(delta: int) -> Check:
    return check(
        "COAXIALITY", delta == 0, "warning",
        f"z_r − z_s − 2·z_p = {delta}: the sun-planet and ring-planet centre distances are "
        f"equal only with suitable profile shifts; check them",
        "z_r = z_s + 2·z_p: coaxial without profile shifts", float(delta), 0.0, S.KINEMATICS)


def resonance_check(hits: list[str], n_hits: int, speed_range: list[float]) -> Check:
    shown = "; ".join(hits[:4]) + (f"; and {n_hits - 4} more" if n_hits > 4 else "")
    return check(
        "RESONANCE_SPEED", n_hits == 0, "error",
        f"parametric resonance inside the operating range {speed_range[0]:g}…"
        f"{speed_range[1]:g} km/h: {shown}; move the natural frequencies (stiffer or lighter "
        f"rim), reduce the stiffness pulsation by the planet phasing, or add damping",
        f"no parametric-resonance band inside {speed_range[0]:g}…{speed_range[1]:g} km/h",
        float(n_hits), 0.0, S.B)


def phase_model_warning(mu_paper: float, mu_actual: float, h_actual: int) -> Check:
    return check(
        "PHASE_MODEL", False, "warning",
        f"mesh phases by paper B's model (equally spaced planets in phase): μ = {mu_paper:.4f}; "
        f"the tooth count gives μ = {mu_actual:.4f} with the dominant harmonic h = {h_actual}; "
        f'use resonance.phase_model = "actual" for design',
        "", mu_paper, mu_actual, S.PHASING)


def floquet_check_result(dev: float, tol: float) -> Check:
    return check(
        "FLOQUET", dev <= tol, "warning",
        f"numerical Floquet boundaries differ from the characteristic values by {dev:.3g} "
        f"in a (> {tol:g}); report this case",
        f"numerical Floquet boundaries agree with the characteristic values (max |Δa| = "
        f"{dev:.2g})", dev, tol, S.FLOQUET)
