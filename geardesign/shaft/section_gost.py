"""One section of a shaft rated by GOST 25.504-82 as applied in the Russian machine-design
textbooks ([Dunaev]; [Ivanov]): the notch factors of :mod:`geardesign.shaft.strength`
(tables as data), the safety factors of the shared GOST 25.504 formulas
(:mod:`geardesign.fatigue.gost25504`)."""

from __future__ import annotations

import math

from geardesign.shaft import strength as ST
from geardesign.shaft.places import boundary_at, step_at, torsion
from geardesign.shaft.records import Material, Options, SectionRecord, Step


def rate_section(xs: float, label: str, M: float, T: float, N: float, bounds: list[float],
                 steps: list[Step], mat: Material, opt: Options) -> SectionRecord:
    """Stresses and safeties at x = xs by GOST 25.504-82 as the textbooks apply it
    ([Dunaev]; [GOST25504]): the notches of the section (a shoulder with its fillet, a
    groove of given K_σ, the press fit of the smaller step at a step boundary; a key seat or
    a press fit elsewhere), the most severe K_σ/K_dσ counting; σ_a = M/W (reversed
    bending), σ_m = |N|/A, τ by ``torsion_cycle``; the safety factors of
    :func:`geardesign.shaft.strength.fatigue_safety`; the static safety σ_T/σ_v at the peak
    load (von Mises).  M, T in N·mm, N in N."""
    sb = mat.sigma_B
    boundary = boundary_at(bounds, len(steps), xs)
    candidates = []          # (name, K_σ/K_dσ, K_τ/K_dτ)
    fillet = (None, None, None)
    outside = False
    if boundary is not None:
        left, right = steps[boundary - 1], steps[boundary]
        small = left if left.diameter <= right.diameter else right
        st = small
        D = max(left.diameter, right.diameter)
        t = (D - small.diameter) / 2.0
        Kd_s, Kd_t = ST.size_factors(small.diameter, mat.alloy)
        if t > 0:
            Ks, Kt, out = ST.fillet_factors(t, left.fillet, small.diameter, sb)
            outside = outside or out
            fillet = (Ks, t, left.fillet)
            candidates.append(("fillet", Ks / Kd_s, Kt / Kd_t))
        if left.groove_K_sigma is not None:
            candidates.append(("groove", left.groove_K_sigma / Kd_s,
                               (left.groove_K_tau or left.groove_K_sigma) / Kd_t))
        if small.press_fit:
            # a hub or bearing ring on the smaller step abuts the shoulder: the edge of the
            # fit is at this section ([Dunaev]: fillet and fit, the larger K/K_d counts)
            rs, rt = ST.press_fit_ratios(small.diameter, sb)
            candidates.append(("press fit", rs, rt))
        rz = st.Rz
    else:
        st = steps[step_at(bounds, xs)]
        Kd_s, Kd_t = ST.size_factors(st.diameter, mat.alloy)
        rz = st.Rz
    if boundary is None or not candidates:
        if st.keyway:
            Ks, Kt = ST.keyway_factors(sb, st.keyway_cutter)
            candidates.append(("keyway", Ks / Kd_s, Kt / Kd_t))
        if st.press_fit:
            rs, rt = ST.press_fit_ratios(st.diameter, sb)
            candidates.append(("press fit", rs, rt))
    if not candidates:
        candidates.append(("smooth", 1.0 / Kd_s, 1.0 / Kd_t))
    # several concentrators: the most severe counts ([Dunaev])
    name_s, ratio_s, _ = max(candidates, key=lambda c: c[1])
    ratio_t = max(c[2] for c in candidates)
    d, bore = st.diameter, st.bore
    A, W, Wp = ST.section_moduli(d, bore)
    sigma_b = M / W
    sigma_n = abs(N) / A
    tau = T / Wp
    tau_a, tau_m = torsion(tau, opt.torsion_cycle)
    K_Fs, K_Ft = ST.surface_factors(rz if rz is not None else opt.Rz, sb)
    fat = ST.fatigue_safety(sigma_b, sigma_n, tau_a, tau_m, ratio_s, ratio_t, K_Fs, K_Ft,
                            opt.K_V, mat.sigma_m1, mat.tau_m1, mat.psi_sigma, mat.psi_tau)
    sv = opt.peak_factor * ST.von_mises(sigma_b + sigma_n, tau)
    S_static = mat.sigma_T / sv if sv > 0 else math.inf
    return SectionRecord(
        xs, label, d, bore, M / 1e3, T / 1e3, N, sigma_b, sigma_n, tau_a, tau_m, sv,
        S_static, name_s, ratio_s, ratio_t, K_Fs, fat.K_sigma_D, fat.K_tau_D, fat.S_sigma,
        fat.S_tau, fat.S, outside, *fillet, st.keyway_cutter if st.keyway else "")
