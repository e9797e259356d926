"""A bevel stage of a drive (``kind = "bevel"``): the stage spec with the drive's load read
into typed inputs (:func:`geardesign.bevel.inputs.read`) and solved once per pass
(:func:`geardesign.bevel.solve.solve`); the ratio, the safety margins and the mesh forces
come from the typed record, the stage's report is written only when the drive's report asks
for it.

Right-angle arrangement.  The pinion and the wheel sit on shafts whose axes meet at the
shaft angle Σ; each shaft is analysed in its own frame (its axis z, the direction to the
mating gear's contact point ``mate_angle`` in its transverse plane), so the statics of
:mod:`.shafts` hold unchanged.  The axial force of a bevel member is signed by the bevel
calculator from the hand of spiral, the sense of rotation and the driving member
(:func:`geardesign.bevel.forces.thrust_sign`; + from the pitch apex toward the member's
back): on the shaft it acts along ``axial_sign``·F_a, with ``[[shaft.gear]] axial_sign`` the
direction of the member's back along the shaft (+1: the back faces bearing B).  The sense of
rotation of the wheel shaft keeps the pinion shaft's sign by convention (crossed axes have no
common sense, as for a worm stage)."""

from __future__ import annotations

import copy

from geardesign.core.errors import InputError, Problem
from geardesign.core.registry import load_data
from geardesign.core.result import Result
from geardesign.drive.stages import Duty, Member, StageRun, _named, _put, _set_by_drive, _table

ETA_BEVEL = 0.97
"""Efficiency of a closed bevel stage when the spec gives none, without bearing losses:
handbook 0.96–0.98 (Dunaev & Lelikov, table 1.1; verify)."""


def bevel_data(data: dict, T_in: float, n_in: float, duty: Duty, where: str) -> dict:
    """A copy of the bevel stage spec with the drive's load in it: the pinion torque and
    speed always, the application factor where the stage gives none, and the peak torque
    T_in·``motor.peak_ratio`` (the static checks, as for a spur stage) where the stage gives
    none."""
    d = copy.deepcopy(data)
    load = _table(d, "load", where)
    load["torque"], load["speed"] = T_in, n_in
    _put(load, "application_factor", duty.K_A)
    if duty.peak_ratio is not None:
        _put(load, "peak_torque", T_in * duty.peak_ratio)
    return d


def _report(spec, proposal, sol, where: str, original: dict) -> Result:
    """The stage's report as the bevel calculator writes it (with the proposal of its
    design mode), with the loads the drive set."""
    from geardesign.bevel import CALCULATOR
    from geardesign.bevel.report import design_rows, report
    from geardesign.core.result import guard

    res = CALCULATOR.new_result(spec)
    if proposal is not None:
        design_rows(res, proposal, sol)
    res = guard(report(res, sol, spec.data.get("load")))
    _set_by_drive(res, spec.data, original)
    return res


def margins(sol) -> dict[str, float]:
    """Safety margins S/S_min of every rating of a solved bevel pair, keyed
    ``"<method>.S_H1"`` …"""
    rt = sol.inputs.rating
    out = {}
    for name, r in (("ISO 10300", sol.iso), ("GOST 21354", sol.gost)):
        if r is None:
            continue
        for i, m in enumerate((r.pinion, r.wheel), 1):
            out[f"{name}.S_H{i}"] = m.S_H / rt.S_Hmin
            out[f"{name}.S_F{i}"] = m.S_F / rt.S_Fmin
    return out


def run_bevel(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
              where: str) -> StageRun:
    """A bevel stage solved once; its members carry the calculator's signed forces at the
    mean cone (radius d_m/2)."""
    from geardesign.bevel.calculator import solution

    d = bevel_data(data, T_in, n_in, duty, where)
    try:
        _, spec = load_data(d, where)
        proposal, sol = solution(spec.data)
    except InputError as exc:
        raise _named(exc, where) from None
    g, f = sol.geometry, sol.forces
    e, src = (eta, "spec") if eta is not None else (ETA_BEVEL, "assumed (handbook)")
    m = margins(sol)
    if not m:
        raise InputError(Problem(
            f"{where}.pair", "the stage's bevel pair cannot mesh as given (see the checks "
            "UNDERCUT, POINTED_TIP, CONTACT_RATIO of its report), so the drive cannot rate it"))
    worst = min(m, key=m.get)
    P, W = f.pinion, f.wheel
    members = (Member(P.F_t, P.F_r, P.F_a, g.pinion.d_m / 2.0),
               Member(W.F_t, W.F_r, W.F_a, g.wheel.d_m / 2.0))
    return StageRun("bevel", g.u, e, src, T_in, n_in, T_in * g.u * e, n_in / g.u, members,
                    m[worst], worst, False, None, lambda: _report(spec, proposal, sol, where, data))
