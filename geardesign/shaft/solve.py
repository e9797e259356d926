"""The shaft analysis on typed data: steps, loads, supports, material, options
(:mod:`geardesign.shaft.records`) -> :class:`~geardesign.shaft.records.ShaftRecord`.

This is the API other calculators call (e.g. a drive placing its gears on a shaft): no spec,
no report rows.  :func:`solve` takes the :class:`~geardesign.shaft.records.Inputs`;
:func:`analyse` the same parts one by one.  Each rated place is rated by the method's own
module (GOST 25.504-82: :mod:`geardesign.shaft.section_gost`; DIN 743:
:mod:`geardesign.shaft.din743.section`).  Lengths mm, forces N, torques and couples N·m, stresses MPa, speeds min⁻¹.

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
from geardesign.shaft import records as R
from geardesign.shaft.din743.section import rate_section as din743_section
from geardesign.shaft.places import step_at
from geardesign.shaft.records import Inputs, Load, Material, Options, Step, Support
from geardesign.shaft.section_gost import rate_section as gost_section

EI_RATIO_SINGULAR = 1e-12      # smallest / largest EI of the steps below which K is singular


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
            material: Material, options: Options = Options()) -> R.ShaftRecord:
    """Beam model, diagrams, critical speed, static and fatigue safety of every section."""
    x, bounds = node_positions(steps, loads, supports)
    n = len(x)
    el_step = [step_at(bounds, 0.5 * (x[e] + x[e + 1])) for e in range(n - 1)]
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
        sup_res.append(R.PointRecord(s.position, s.name or f"support {k + 1}", py.w[i], pz.w[i],
                                   w[i], slope[i], py.reactions[k], pz.reactions[k],
                                   Rx if k == axial_idx else 0.0, float(py.theta[i]),
                                   float(pz.theta[i])))
    load_res = []
    for k, ld in enumerate(loads):
        i = _index(x, ld.position)
        load_res.append(R.PointRecord(ld.position, ld.name or f"load {k + 1}", py.w[i], pz.w[i],
                                    w[i], slope[i], slope_y=float(py.theta[i]),
                                    slope_z=float(pz.theta[i])))

    # ---------------------------------------------------------------- rated places
    rate = din743_section if options.method == "DIN743" else gost_section
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
        sections.append(rate(xs, " / ".join(points[xs]), float(M), float(T), float(N),
                                 bounds, steps,
                                 material, options))
    critical = min(sections, key=lambda s: s.S) if sections else None
    critical_static = min(sections, key=lambda s: s.S_static) if sections else None
    return R.ShaftRecord(
        bounds[-1], math.fsum(el_mass), list(x), M_y, M_z,
        M_res, list(py.V_right), list(pz.V_right), T_int,
        N_int, list(py.w), list(pz.w), w, slope,
        sup_res, load_res, sections, omega, n_cr, critical, critical_static)


def solve(inputs: Inputs) -> R.ShaftRecord:
    """The shaft of ``inputs`` analysed (:func:`analyse`): beam model, diagrams, critical
    speed, static and fatigue safety of every rated place."""
    return analyse(list(inputs.steps), list(inputs.loads), list(inputs.supports),
                   inputs.material, inputs.options)
