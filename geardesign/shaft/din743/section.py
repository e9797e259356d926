"""One section of a shaft rated by DIN 743 ([DIN743-1], [DIN743-2], [DIN743-3]): every
notch of the section rated in full by :func:`geardesign.shaft.din743.rating.rate`, the
lowest safety counting."""

from __future__ import annotations

import math

from geardesign.shaft import strength as ST
from geardesign.shaft.din743 import part2 as P2
from geardesign.shaft.din743 import rating as DR
from geardesign.shaft.places import boundary_at, step_at, torsion
from geardesign.shaft.records import Material, Options, SectionRecord, Step


def rate_section(xs: float, label: str, M: float, T: float, N: float,
                 bounds: list[float], steps: list[Step], mat: Material,
                 opt: Options) -> SectionRecord:
    """Stresses and safeties at x = xs by DIN 743 ([DIN743-1], [DIN743-2], [DIN743-3]).

    The notches of the section are those of the GOST method (a shoulder with its fillet, a
    groove of given β, the press fit of the smaller step at a step boundary; a key seat or a
    press fit elsewhere) and the notches by geometry of DIN 743-2: a round or rectangular
    groove at the right end of the left step (rated at its root diameter D − 2t), a
    cross-bore (rated on the net section); each is rated in full with its own nominal
    stresses; the one of the lowest fatigue safety counts (its static safety likewise the
    lowest).  Rotating shaft: the bending stress is a
    reversed amplitude (σ_bm = 0); the axial stress |N|/A a constant mean (σ_zda = 0); the
    torsion by ``torsion_cycle``; the peaks are K_p times the nominal stresses."""
    din = mat.din
    tol = 1e-9 * max(1.0, bounds[-1])
    boundary = boundary_at(bounds, len(steps), xs)
    notches: list[tuple] = []        # (notch, d, bore, net section or None, step for R_z)
    fillet = (None, None, None)
    if boundary is not None:
        left, right = steps[boundary - 1], steps[boundary]
        st = left if left.diameter <= right.diameter else right
        D = max(left.diameter, right.diameter)
        t = (D - st.diameter) / 2.0
        if t > 0:
            n = DR.shoulder(st.diameter, D, left.fillet, din, opt.hard_surface)
            notches.append((n, st.diameter, st.bore, None, st))
            fillet = (n.alpha_b, t, left.fillet)
        if left.groove_K_sigma is not None:
            notches.append((DR.given(left.groove_K_sigma,
                                     left.groove_K_tau or left.groove_K_sigma),
                            st.diameter, st.bore, None, st))
        if left.groove_depth is not None:
            # the groove is cut into the left step at its right end: the section is its root
            dg = left.diameter - 2.0 * left.groove_depth
            if left.groove_kind == "round":
                n = DR.round_groove(left.diameter, left.groove_depth, left.groove_radius, din,
                                    opt.hard_surface)
            elif left.groove_kind == "V":
                n = DR.v_notch(left.diameter, left.groove_depth, din)
            else:
                n = DR.ring_groove(left.diameter, left.groove_depth, left.groove_width,
                                   left.groove_radius, din)
            notches.append((n, dg, left.bore, None, left))
        if st.press_fit:
            notches.append((DR.measured("press_fit", st.diameter, din), st.diameter, st.bore,
                            None, st))
    else:
        k = step_at(bounds, xs)
        st = steps[k]
        if st.cross_bore and abs(bounds[k] + st.cross_bore_x - xs) <= tol:
            notches.append((DR.cross_bore(st.diameter, st.cross_bore, din, opt.hard_surface),
                            st.diameter, st.bore,
                            P2.cross_bore_section(st.diameter, st.cross_bore), st))
    if boundary is None or not notches:
        if st.keyway:
            notches.append((DR.measured("key", st.diameter, din), st.diameter, st.bore, None,
                            st))
        if st.press_fit:
            notches.append((DR.measured("press_fit", st.diameter, din), st.diameter, st.bore,
                            None, st))
    if not notches:
        notches.append((DR.smooth(), st.diameter, st.bore, None, st))
    kp = opt.peak_factor
    rated = []
    for n, d, bore, net, where in notches:
        rz = where.Rz if where.Rz is not None else opt.Rz
        A, W, Wp = net if net is not None else ST.section_moduli(d, bore)
        sigma_b, sigma_n, tau = M / W, abs(N) / A, T / Wp
        tau_a, tau_m = torsion(tau, opt.torsion_cycle)
        stresses = DR.Stresses(zdm=sigma_n, zdmax=kp * sigma_n, ba=sigma_b, bmax=kp * sigma_b,
                               ta=tau_a, tm=tau_m, tmax=kp * tau)
        r = DR.rate(n, din, d, stresses, rz, opt.K_V, opt.hard_surface, bore > 0,
                    opt.load_case)
        rated.append((r, d, bore, sigma_b, sigma_n, tau, tau_a, tau_m))
    r, d, bore, sigma_b, sigma_n, tau, tau_a, tau_m = min(
        rated, key=lambda x: (x[0].S, x[0].S_static))
    S_static = min(x[0].S_static for x in rated)
    outside = not all(x[0].notch.in_range for x in rated)   # any formula beyond its range
    S_sigma = r.sigma_ADK / sigma_b if sigma_b > 0 else math.inf
    S_tau = r.tau_ADK / tau_a if tau_a > 0 else math.inf
    sv = kp * ST.von_mises(sigma_b + sigma_n, tau)
    name = {"shoulder": "fillet"}.get(r.notch.kind, r.notch.kind)
    if r.notch.kind != "shoulder":
        fillet = (None, None, None)
    return SectionRecord(
        xs, label, d, bore, M / 1e3, T / 1e3, N, sigma_b, sigma_n, tau_a, tau_m, sv,
        S_static, name, r.notch.beta_b / r.K_2, r.notch.beta_t / r.K_2, r.K_F_sigma,
        r.K_sigma, r.K_tau, S_sigma, S_tau, r.S, outside, *fillet,
        st.keyway_cutter if st.keyway else "", r)
