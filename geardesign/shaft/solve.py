"""The shaft analysis on plain data: steps, loads, supports, material -> :class:`ShaftResult`.

This is the API other calculators call (e.g. a drive placing its gears on a shaft): no spec,
no report rows.  Lengths mm, forces N, torques and couples N·m, stresses MPa, speeds min⁻¹.

Axes: x along the shaft from its left end; y and z the two bending planes.  A load's Fy, Fz
bend the shaft in the x–y and x–z planes; ``moment_y``/``moment_z`` are couples in those
planes (e.g. F_a·d/2 of a helical gear), positive when they turn the slope dw/dx up.
"""

from __future__ import annotations

import math
from bisect import bisect_left
from itertools import accumulate

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.shaft import beam
from geardesign.shaft import strength as ST
from geardesign.shaft.din743 import part2 as P2
from geardesign.shaft.din743 import rating as DR
from geardesign.spur.geometry import STEEL_DENSITY

ARCMIN = math.pi / (180.0 * 60.0)
EI_RATIO_SINGULAR = 1e-12      # smallest / largest EI of the steps below which K is singular


@dataclass(frozen=True)
class Step:
    length: float
    diameter: float
    bore: float = 0.0
    fillet: float = 1.0              # fillet radius at the right end, mm
    keyway: bool = False
    keyway_cutter: str = "end_mill"
    press_fit: bool = False
    groove_K_sigma: float | None = None   # groove at the right end: effective factors
    groove_K_tau: float | None = None
    Rz: float | None = None          # roughness, µm (None: the shaft's)
    # DIN 743 notches by geometry (mm): a groove at the right end, cut into this step —
    # round (depth and radius) or rectangular (with its width) — and a cross-bore
    groove_depth: float | None = None
    groove_radius: float | None = None
    groove_width: float | None = None
    cross_bore: float | None = None
    cross_bore_at: float | None = None   # from the step's left end (None: the middle)
    groove_shape: str | None = None      # "round", "rectangular", "V" (None: by the width)

    @property
    def groove_kind(self) -> str:
        """The groove's shape: ``groove_shape``, else rectangular with a width, else round."""
        if self.groove_shape:
            return self.groove_shape
        return "rectangular" if self.groove_width is not None else "round"

    @property
    def cross_bore_x(self) -> float:
        """Position of the cross-bore from the step's left end [mm]."""
        return self.length / 2.0 if self.cross_bore_at is None else self.cross_bore_at


@dataclass(frozen=True)
class Load:
    position: float
    Fy: float = 0.0
    Fz: float = 0.0
    Fx: float = 0.0
    torque: float = 0.0              # N·m, input positive, output negative
    moment_y: float = 0.0            # N·m
    moment_z: float = 0.0            # N·m
    mass: float = 0.0                # kg (critical speed)
    name: str = ""
    module: float | None = None      # mm: gear seat deflection limit 0.01·m


@dataclass(frozen=True)
class Support:
    position: float
    stiffness: float | None = None   # radial, N/mm; None = rigid
    type: str = "other"
    axial: bool = False
    name: str = ""


@dataclass(frozen=True)
class Material:
    sigma_B: float
    sigma_T: float
    sigma_m1: float
    tau_m1: float
    psi_sigma: float
    psi_tau: float
    E: float = 2.06e5
    density: float = STEEL_DENSITY   # kg/m³
    alloy: bool = False
    din: DR.Material | None = None   # the DIN 743 steel at its blank size (method DIN743)


@dataclass(frozen=True)
class Options:
    speed: float = 0.0               # min⁻¹
    peak_factor: float = 2.0         # peak / nominal load (static check)
    torsion_cycle: str = "pulsating"
    Rz: float = 6.3                  # µm
    K_V: float = 1.0                 # surface hardening factor
    method: str = "GOST"             # "GOST" or "DIN743"
    load_case: int = 2               # DIN 743-1 load case
    hard_surface: bool = False       # DIN 743 hard surface layer


@dataclass(frozen=True)
class SectionResult:
    x: float
    label: str
    d: float
    bore: float
    M: float          # resultant bending moment, N·m
    T: float          # torque, N·m
    N: float          # axial force, N (tension positive)
    sigma_a: float
    sigma_m: float
    tau_a: float
    tau_m: float
    sigma_v_peak: float
    S_static: float
    concentrator: str
    ratio_sigma: float      # K_σ/K_dσ used
    ratio_tau: float
    K_F_sigma: float
    K_sigma_D: float
    K_tau_D: float
    S_sigma: float
    S_tau: float
    S: float
    outside_table: bool = False
    fillet_K_sigma: float | None = None   # shoulder with a fillet at this section
    fillet_t: float | None = None
    fillet_r: float | None = None
    keyway_cutter: str = ""
    din: DR.Rating | None = None          # method DIN743: every factor of the section


@dataclass(frozen=True)
class PointResult:
    x: float
    name: str
    w_y: float
    w_z: float
    w: float          # mm
    slope: float      # rad, resultant
    R_y: float = 0.0  # support reaction on the shaft, N
    R_z: float = 0.0
    R_x: float = 0.0
    slope_y: float = 0.0   # rad, dw_y/dx (x–y plane)
    slope_z: float = 0.0   # rad, dw_z/dx (x–z plane)


@dataclass(frozen=True)
class ShaftResult:
    length: float
    mass: float
    x: list
    M_y: list
    M_z: list
    M: list
    V_y: list
    V_z: list
    T: list
    N: list
    w_y: list
    w_z: list
    w: list
    slope: list
    supports: list
    loads: list
    sections: list
    omega_cr: float
    n_cr: float
    critical: SectionResult | None
    critical_static: SectionResult | None


def _clean(*planes: beam.PlaneSolution) -> None:
    """Set round-off (below 1e-9 of the largest moment) to zero, so that a section without
    bending reports no bending rather than a stress of 1e-11 MPa."""
    big = max([abs(v) for p in planes for a in (p.M_left, p.M_right) for v in a] + [0.0])
    tiny = 1e-9 * max(big, 1e-300)
    for p in planes:
        for a in (p.M_left, p.M_right, p.V_right):
            a[:] = [0.0 if abs(v) < tiny else v for v in a]


def node_positions(steps: list[Step], loads: list[Load], supports: list[Support],
                   refine: int = 80) -> tuple[list[float], list[float]]:
    """Nodes: every step boundary, load and support, and enough points between them that
    no element is longer than L/refine (for the mass matrix and smooth diagrams)."""
    bounds = [0.0]
    for s in steps:
        bounds.append(bounds[-1] + s.length)
    L = bounds[-1]
    bores = [bounds[i] + s.cross_bore_x for i, s in enumerate(steps) if s.cross_bore]
    # points closer than 1e-3·L are one node (a load a hair beside a shoulder sits on it;
    # an element 10⁴ times shorter than its neighbours would spoil the conditioning)
    key: list[float] = []
    for v in sorted([*bounds, *(ld.position for ld in loads), *(sp.position for sp in supports),
                     *bores]):
        if not key or v - key[-1] > 1e-3 * L:
            key.append(v)
    key[-1] = L
    h = L / refine
    xs: list[float] = []
    for a, b in zip(key[:-1], key[1:]):
        k = max(1, math.ceil((b - a) / h - 1e-9))
        xs.extend(a + (b - a) * i / k for i in range(k))
    xs.append(key[-1])
    return xs, bounds


def _index(x: list[float], v: float) -> int:
    """The node nearest to ``v`` (the first of equals; ``x`` increasing)."""
    i = bisect_left(x, v)
    if i == 0:
        return 0
    if i == len(x) or abs(x[i - 1] - v) <= abs(x[i] - v):
        return i - 1
    return i


def _step_at(bounds: list[float], xm: float) -> int:
    for i in range(len(bounds) - 1):
        if xm <= bounds[i + 1]:
            return i
    return len(bounds) - 2


def _singular(steps: list[Step], supports: list[Support], EI: list[float],
              el_step: list[int]) -> InputError:
    """The beam model cannot be solved (its stiffness matrix is singular): the error names
    what the user gave that causes it.  Springs given as support stiffness that are soft
    against the shaft; else the slenderest step, whose bending stiffness is negligible
    against the others' (a diameter in metres among millimetres)."""
    springs = [(k, s.stiffness) for k, s in enumerate(supports) if s.stiffness is not None]
    weakest = min(range(len(EI)), key=EI.__getitem__)
    k = el_step[weakest]
    if springs:
        k_s, value = min(springs, key=lambda t: t[1])
        return InputError(Problem(
            f"support[{k_s}].stiffness", f"the supports are too soft for this shaft (its "
            f"stiffness matrix is singular): give stiffer supports or leave out stiffness "
            f"(rigid); check also step[{k}].diameter = {steps[k].diameter:g} mm", value))
    return InputError(Problem(
        f"step[{k}].diameter", f"the shaft cannot be solved as a beam (its stiffness matrix is "
        f"singular): this step's bending stiffness EI = {EI[weakest]:.3g} N·mm² is "
        f"{EI[weakest] / max(EI):.1e} of the stiffest step's; diameters are in mm "
        f"(in metres {steps[k].diameter:g} would be {steps[k].diameter * 1e3:g} mm)",
        steps[k].diameter))


def analyse(steps: list[Step], loads: list[Load], supports: list[Support],
            material: Material, options: Options = Options()) -> ShaftResult:
    """Beam model, diagrams, critical speed, static and fatigue safety of every section."""
    x, bounds = node_positions(steps, loads, supports)
    n = len(x)
    el_step = [_step_at(bounds, 0.5 * (x[e] + x[e + 1])) for e in range(n - 1)]
    d = [steps[i].diameter for i in el_step]
    d0 = [steps[i].bore for i in el_step]
    EI = [material.E * (math.pi / 64.0 * (a ** 4 - b ** 4)) for a, b in zip(d, d0)]
    rho = material.density * 1e-9               # kg/mm³
    el_mass = [rho * (math.pi / 4.0 * (a ** 2 - b ** 2)) * (x[e + 1] - x[e])
               for e, (a, b) in enumerate(zip(d, d0))]

    Fy, Fz = [0.0] * n, [0.0] * n
    Cy, Cz = [0.0] * n, [0.0] * n
    Tn, Fxn, mpt = [0.0] * n, [0.0] * n, [0.0] * n
    for ld in loads:
        i = _index(x, ld.position)
        Fy[i] += ld.Fy
        Fz[i] += ld.Fz
        Cy[i] += ld.moment_y * 1e3
        Cz[i] += ld.moment_z * 1e3
        Tn[i] += ld.torque
        Fxn[i] += ld.Fx
        mpt[i] += ld.mass
    sup = [(_index(x, s.position), s.stiffness) for s in supports]
    if min(EI) <= EI_RATIO_SINGULAR * max(EI):
        # a step 10⁻¹² as stiff as another: the stiffness matrix is singular to working
        # precision (its pivots are rounding), whatever the factorisation's luck
        raise _singular(steps, supports, EI, el_step)
    try:
        (py, pz), omega = beam.solve(x, EI, el_mass, mpt, [(Fy, Cy), (Fz, Cz)], sup)
    except beam.NotPositiveDefinite:
        raise _singular(steps, supports, EI, el_step) from None

    # axial reaction at the support that takes it; internal torque and axial force
    axial_idx = next((k for k, s in enumerate(supports) if s.axial), 0)
    Rx = -math.fsum(Fxn)
    Fx_all = list(Fxn)
    Fx_all[sup[axial_idx][0]] += Rx
    N_int = [-v for v in accumulate(Fx_all)]       # just right of each node
    T_int = list(accumulate(Tn))

    _clean(py, pz)
    M_y, M_z = [v / 1e3 for v in py.M_right], [v / 1e3 for v in pz.M_right]
    M_y[-1], M_z[-1] = py.M_left[-1] / 1e3, pz.M_left[-1] / 1e3
    M_res = [math.hypot(a, b) for a, b in zip(M_y, M_z)]
    slope = [math.hypot(a, b) for a, b in zip(py.theta, pz.theta)]
    w = [math.hypot(a, b) for a, b in zip(py.w, pz.w)]

    n_cr = omega * 30.0 / math.pi

    sup_res = []
    for k, s in enumerate(supports):
        i = sup[k][0]
        sup_res.append(PointResult(s.position, s.name or f"support {k + 1}", py.w[i], pz.w[i],
                                   w[i], slope[i], py.reactions[k], pz.reactions[k],
                                   Rx if k == axial_idx else 0.0, float(py.theta[i]),
                                   float(pz.theta[i])))
    load_res = []
    for k, ld in enumerate(loads):
        i = _index(x, ld.position)
        load_res.append(PointResult(ld.position, ld.name or f"load {k + 1}", py.w[i], pz.w[i],
                                    w[i], slope[i], slope_y=float(py.theta[i]),
                                    slope_z=float(pz.theta[i])))

    # ---------------------------------------------------------------- sections
    sections = []
    points: dict[float, list[str]] = {}
    for i in range(1, len(steps)):
        points.setdefault(round(bounds[i], 9), []).append(f"step {i}|{i + 1}")
    for k, ld in enumerate(loads):
        points.setdefault(round(ld.position, 9), []).append(ld.name or f"load {k + 1}")
    for k, s in enumerate(supports):
        points.setdefault(round(s.position, 9), []).append(s.name or f"support {k + 1}")
    for k, s in enumerate(steps):
        if s.cross_bore:
            points.setdefault(round(bounds[k] + s.cross_bore_x, 9), []).append(
                f"cross-bore in step {k + 1}")
    for xs in sorted(points):
        i = _index(x, xs)
        M = max(math.hypot(py.M_left[i], pz.M_left[i]), math.hypot(py.M_right[i], pz.M_right[i]))
        T = max(abs(T_int[i]), abs(T_int[i - 1]) if i > 0 else 0.0) * 1e3
        N = N_int[i] if abs(N_int[i]) >= abs(N_int[i - 1] if i > 0 else 0.0) else N_int[i - 1]
        sections.append(_section(xs, " / ".join(points[xs]), float(M), float(T), float(N),
                                 bounds, steps,
                                 material, options))
    critical = min(sections, key=lambda s: s.S) if sections else None
    critical_static = min(sections, key=lambda s: s.S_static) if sections else None
    return ShaftResult(
        bounds[-1], math.fsum(el_mass), list(x), M_y, M_z,
        M_res, list(py.V_right), list(pz.V_right), T_int,
        N_int, list(py.w), list(pz.w), w, slope,
        sup_res, load_res, sections, omega, n_cr, critical, critical_static)


def _section(xs: float, label: str, M: float, T: float, N: float, bounds: list[float],
             steps: list[Step], mat: Material, opt: Options) -> SectionResult:
    """Stresses and safeties at x = xs.  M, T in N·mm, N in N."""
    if opt.method == "DIN743":
        return _section_din743(xs, label, M, T, N, bounds, steps, mat, opt)
    sb = mat.sigma_B
    tol = 1e-9 * max(1.0, bounds[-1])
    boundary = next((i for i in range(1, len(steps)) if abs(bounds[i] - xs) <= tol), None)
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
        st = steps[_step_at(bounds, xs)]
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
    if opt.torsion_cycle == "pulsating":
        tau_a = tau_m = tau / 2.0
    elif opt.torsion_cycle == "reversed":
        tau_a, tau_m = tau, 0.0
    else:
        tau_a, tau_m = 0.0, tau
    K_Fs, K_Ft = ST.surface_factors(rz if rz is not None else opt.Rz, sb)
    fat = ST.fatigue_safety(sigma_b, sigma_n, tau_a, tau_m, ratio_s, ratio_t, K_Fs, K_Ft,
                            opt.K_V, mat.sigma_m1, mat.tau_m1, mat.psi_sigma, mat.psi_tau)
    sv = opt.peak_factor * ST.von_mises(sigma_b + sigma_n, tau)
    S_static = mat.sigma_T / sv if sv > 0 else math.inf
    return SectionResult(
        xs, label, d, bore, M / 1e3, T / 1e3, N, sigma_b, sigma_n, tau_a, tau_m, sv,
        S_static, name_s, ratio_s, ratio_t, K_Fs, fat.K_sigma_D, fat.K_tau_D, fat.S_sigma,
        fat.S_tau, fat.S, outside, *fillet, st.keyway_cutter if st.keyway else "")


def _torsion(tau: float, cycle: str) -> tuple[float, float]:
    """Amplitude and mean of the torsional stress by ``torsion_cycle``."""
    if cycle == "pulsating":
        return tau / 2.0, tau / 2.0
    if cycle == "reversed":
        return tau, 0.0
    return 0.0, tau


def _section_din743(xs: float, label: str, M: float, T: float, N: float,
                    bounds: list[float], steps: list[Step], mat: Material,
                    opt: Options) -> SectionResult:
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
    boundary = next((i for i in range(1, len(steps)) if abs(bounds[i] - xs) <= tol), None)
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
        k = _step_at(bounds, xs)
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
        tau_a, tau_m = _torsion(tau, opt.torsion_cycle)
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
    return SectionResult(
        xs, label, d, bore, M / 1e3, T / 1e3, N, sigma_b, sigma_n, tau_a, tau_m, sv,
        S_static, name, r.notch.beta_b / r.K_2, r.notch.beta_t / r.K_2, r.K_F_sigma,
        r.K_sigma, r.K_tau, S_sigma, S_tau, r.S, outside, *fillet,
        st.keyway_cutter if st.keyway else "", r)
