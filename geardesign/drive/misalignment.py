"""Mesh misalignment of a spur stage ([ISO6336-1] 7.6: f_sh is the equivalent misalignment in
the plane of action caused by the deformation of the shafts): the slopes of the pinion and
the wheel shaft at their gears, θ = (dw_x/dz, dw_y/dz), give the relative slope
Δθ = θ_pinion − θ_wheel; its component along the line of action in the transverse plane
(the direction n of the transverse mesh force, along which the flanks approach each other,
as F_β is measured) times the face width is

.. math:: f_{sh} = |Δθ · n| \\, b \\quad [µm].

To it adds the twist of the gear bodies under the torque that passes them
(:func:`face_twist`: the part of f_sh that the standard's own formula carries in its torsion
term, [ISO6336-1] 7.6.3); the sum of the signed parts is f_sh.

It is passed to the stage's ISO 6336 rating as ``iso.f_sh``; K_Hβ then follows by method C
([ISO6336-1] 7.6.1, :mod:`geardesign.spur.strength.iso6336.part1`).
"""

from __future__ import annotations

import copy
import math

from geardesign.core.errors import InputError
from geardesign.core.registry import load_data
from geardesign.core.result import check
from geardesign.drive.shaft_analysis import TOL, ShaftRun
from geardesign.drive.shafts import gear_force

ISO_METHOD = "ISO 6336:2019"
F_SH_MAX = 1000.0     # µm, the largest iso.f_sh of the spur spec


POISSON = 0.3    # steel


def face_twist(T_left: float, T_right: float, b: float, d: float, r_b: float,
               E: float) -> float:
    """Separation of the mating flanks at the +z end of the face minus the −z end that the
    twist of a gear body gives [µm].

    .. math:: δ_{tw} = -\\operatorname{sgn}(T_R - T_L) \\, r_b
              \\frac{(T_L + T_R)/2 \\cdot b}{G \\, J_p},\\qquad J_p = \\frac{π d^4}{32},
              \\quad G = \\frac{E}{2(1 + ν)}

    Saint-Venant torsion of a solid round body ([Roark] table 10.1 case 1: θ = T·l/(G·J)):
    the torque along the shaft (signed in the sense of rotation, the torque of everything
    left of the section: T_L just left of the face, T_R = T_L + T_g just right of it, T_g
    the gear's own torque, + into the shaft, − out of it) falls or rises linearly across the
    face width as the tooth load takes it off uniformly, so the section at the +z end turns
    against the −z end by ∫T/(G·J)·dz = (T_L + T_R)/2·b/(G·J).  Turning a section in the
    sense of the mesh torque on the gear (sgn T_g) moves its flank along the line of action
    away from the mate by r_b per radian.  ``T_left``, ``T_right`` [N·m], ``b``, ``d`` (the
    body's diameter: the working pitch diameter, as d1 in the torsion term of [ISO6336-1]
    eq. (58)), ``r_b`` (base radius) [mm], ``E`` [MPa], ν = 0.3.  A torque that enters at
    the −z end (T_L = T, T_R = 0, T_g = −T) gives δ = +r_b·T·b/(2GJ): the flanks close up at
    the end where the torque enters, as load distribution measurements show.

    >>> round(face_twist(1000.0, 0.0, 60.0, 60.0, 28.19, 2.06e5), 3)
    8.389
    """
    T_g = T_right - T_left
    if T_g == 0.0:
        return 0.0
    G = E / (2.0 * (1.0 + POISSON))
    J = math.pi * d ** 4 / 32.0
    return -math.copysign(1.0, T_g) * r_b * 0.5 * (T_left + T_right) * 1e3 * b / (G * J) * 1e3


def _twist(run: ShaftRun, n: int, b: float) -> float:
    """:func:`face_twist` of the n-th gear of ``run`` (its torque path from the shaft's
    loads)."""
    g = run.gears[n]
    z = g.load.z - run.start
    T_left = sum(ld.torque for ld in run.loads if ld.position < z - TOL)
    T_right = T_left + g.torque
    F_t, F_r = g.load.F_t, g.load.F_r
    r_b = g.load.r * abs(F_t) / math.hypot(F_t, F_r) if F_t or F_r else g.load.r
    return face_twist(T_left, T_right, b, 2.0 * g.load.r, r_b, run.E)


def misalignment(runs_by_shaft: dict, stage_runs: list) -> dict:
    """f_sh [µm] of every spur stage whose pinion and wheel shafts were analysed:
    ``{stage: dict(f_sh, b, dtheta, f_bend, f_twist)}`` (f_bend = Δθ·n·b and f_twist the
    twist of both gear bodies, signed: flank separation at the +z end minus the −z end;
    f_sh = |f_bend + f_twist|)."""
    out = {}
    for i, sr in enumerate(stage_runs, 1):
        if sr.kind != "spur":
            continue
        pin = runs_by_shaft.get(i)
        whl = runs_by_shaft.get(i + 1)
        if pin is None or whl is None:
            continue
        gp = next(((n, g) for n, g in enumerate(pin.gears) if g.stage == i and g.which == 0),
                  None)
        gw = next(((n, g) for n, g in enumerate(whl.gears) if g.stage == i and g.which == 1),
                  None)
        if gp is None or gw is None:
            continue
        tp, tw = pin.r.loads[gp[0]], whl.r.loads[gw[0]]
        (fx, fy, _), _ = gear_force(gp[1].load, pin.rotation)
        norm = math.hypot(fx, fy)
        if norm == 0.0:
            continue
        nx, ny = fx / norm, fy / norm
        d_n = (tp.slope_y - tw.slope_y) * nx + (tp.slope_z - tw.slope_z) * ny
        b = sr.inputs["gear"]["face_width"]
        f_bend = d_n * b * 1e3
        f_twist = _twist(pin, gp[0], b) + _twist(whl, gw[0], b)
        out[i] = dict(f_sh=abs(f_bend + f_twist), b=b, dtheta=d_n, f_bend=f_bend,
                      f_twist=f_twist)
    return out


def _rating(run, name: str) -> dict | None:
    """The values of a spur stage's rating by ``name`` (None when not rated by it)."""
    r = run.record.ratings.get(name)
    return None if r is None else r.v


def _iso_K_Hbeta(data: dict, sr, duty, where: str, f_sh: float) -> float:
    """K_Hβ of ISO 6336-1 method C of a stage rated to GOST, with ``f_sh`` (informative):
    the ISO rating record of the stage spec (with the drive's loads; validated as a GOST
    stage in the passes already), no report."""
    from geardesign.drive.spur_stage import _spur_loads
    from geardesign.spur.strength.iso6336.report import iso_rating

    d = _spur_loads(data, sr.T_in, sr.n_in, duty, where)
    iso = d.get("iso")
    if not isinstance(iso, dict):
        iso = d["iso"] = {}
    iso["f_sh"] = f_sh
    opts = d.setdefault("options", {})
    opts.pop("methods", None)
    opts["method"] = ISO_METHOD
    d["load"].pop("regime", None)        # the GOST regime: not read by the ISO rating
    _, spec = load_data(d, where)
    return iso_rating(spec).v["K_Hbeta"]


def rate_with_misalignment(mis: dict, stages: list, stage_runs: list, duty, run_spur) -> list:
    """Rate the spur stages with ``iso.f_sh`` from the shafts: an ISO 6336 stage is rerun
    with it (its result replaced), a GOST stage gets the K_Hβ of ISO 6336-1 method C next
    to its chart value (informative).  Rows of the K_Hβ table."""
    rows = []
    for i, m in mis.items():
        sr = stage_runs[i - 1]
        where, _, data, _ = stages[i - 1]
        iso_before = _rating(sr, ISO_METHOD)
        gost = _rating(sr, "GOST 21354-87")
        f_sh = min(m["f_sh"], F_SH_MAX)
        capped = f" (capped at {F_SH_MAX:g} µm)" if m["f_sh"] > F_SH_MAX else ""
        K_new, note = None, ""
        if iso_before is not None:
            d = copy.deepcopy(data)
            iso = d.get("iso")
            if not isinstance(iso, dict):
                iso = d["iso"] = {}
            iso["f_sh"] = f_sh
            new = run_spur(d, sr.T_in, sr.n_in, duty, sr.efficiency, where)
            K_new = _rating(new, ISO_METHOD)["K_Hbeta"]
            new.result.checks.append(check(
                "F_SH_FROM_SHAFTS", False, "info",
                f"the drive sets iso.f_sh = {f_sh:.3g} µm from the slopes of the analysed "
                f"shafts and the twist of the gears{capped} (the formula of ISO 6336-1 7.6.3 gives "
                f"{iso_before['f_sh']:.3g} µm)", "", f_sh, None, "drive"))
            sr.result, sr.record = new.result, new.record
            sr.margin, sr.margin_of = new.margin, new.margin_of
            rows.append(dict(stage=i, method="ISO 6336:2019", b=m["b"],
                             f_sh_formula=iso_before["f_sh"], f_bend=m["f_bend"],
                             f_twist=m["f_twist"], f_sh=m["f_sh"],
                             K_Hbeta_before=iso_before["K_Hbeta"], K_Hbeta_shafts=K_new,
                             note="stage rated with f_sh from the shafts" + capped))
        if gost is not None:
            if K_new is None:
                try:
                    K_new = _iso_K_Hbeta(data, sr, duty, where, f_sh)
                except InputError as exc:
                    note = f"ISO 6336 not applicable: {exc.problems[0].message}"
            rows.append(dict(stage=i, method="GOST 21354-87", b=m["b"], f_sh_formula=None,
                             f_bend=m["f_bend"], f_twist=m["f_twist"], f_sh=m["f_sh"], K_Hbeta_before=gost["K_Hbeta"],
                             K_Hbeta_shafts=K_new,
                             note=note or "informative: ISO 6336-1 method C with f_sh; the "
                                          "GOST rating keeps its chart value" + capped))
    return rows
