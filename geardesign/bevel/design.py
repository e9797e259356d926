"""Design mode: a first bevel pair for the torque, the ratio and the materials, sized by
re-rating with the pair's own strength methods (no separate design formula).

Procedure: z1 as given (``design.z1``), z2 = round(u·z1); for each module of the first series
of [GOST9563] (:data:`geardesign.spur.strength.tables.MODULES_1`; the outer transverse module
m_te of straight teeth, the mean normal module m_nm of spiral teeth) from the smallest up,
the face width b = K_be·R_e (rounded down to 0.5 mm, :func:`face_width`) and the pair rated by
:func:`geardesign.bevel.solve.solve` with the spec's methods; the first pair whose every
pitting and bending safety reaches its minimum (and that meshes: no undercut, a contact
ratio, see :func:`~geardesign.bevel.solve.ratable`) is proposed, and the calculator then
reports it in full.  The stresses fall steadily with the module at a fixed K_be (the cone
grows with it), so the first passing module is the least one of the series.
"""

from __future__ import annotations

import dataclasses
import math

from geardesign.bevel import solve as SOLVE
from geardesign.bevel.geometry import modules
from geardesign.bevel.inputs import Inputs, Pair, pitch_angles
from geardesign.core.errors import InputError, Problem

FACE_STEP = 0.5
"""Face widths are proposed in steps of 0.5 mm (rounded down, so that b/R_e <= K_be)."""


@dataclasses.dataclass(frozen=True)
class Proposal:
    z1: int
    z2: int
    module: float
    face_width: float
    u_dev: float          # (z2/z1 − u)/u [%]
    tried: int            # modules rated


def passes(sol: SOLVE.Solution) -> bool:
    """Every rating asked for reaches its minimum safety factors."""
    rt = sol.inputs.rating
    ratings = [r for r in (sol.iso, sol.gost) if r is not None]
    return bool(ratings) and all(m.S_H >= rt.S_Hmin and m.S_F >= rt.S_Fmin
                                 for r in ratings for m in (r.pinion, r.wheel))


def face_width(pair: Pair, face_ratio: float) -> float:
    """The largest face width b <= K_be·R_e in steps of :data:`FACE_STEP` for the pair's
    module and teeth: R_e = m_te z1/(2 sin δ1) for an outer module, R_e = R_m + b/2 for a
    mean one (then b = K_be R_m/(1 − K_be/2)).  [ISO23509] §5.2."""
    R = modules(dataclasses.replace(pair, b=0.0), pitch_angles(pair.z1, pair.z2, pair.Sigma)[0])
    b = face_ratio * R[3] if pair.module_at == "outer" else (
        face_ratio * R[4] / (1.0 - 0.5 * face_ratio))
    return math.floor(b / FACE_STEP + 1e-9) * FACE_STEP


def propose(inp: Inputs, u: float, z1: int, face_ratio: float) -> tuple[Proposal, Inputs]:
    """The least first-series module that passes (see the module docstring) and the inputs
    with it; inputs whose ``pair`` carries placeholder module, teeth and face width."""
    from geardesign.spur.strength.tables import MODULES_1

    z2 = max(z1, round(u * z1))
    for k, m in enumerate(MODULES_1, 1):
        p = dataclasses.replace(inp.pair, m=m, z1=z1, z2=z2)
        b = face_width(p, face_ratio)
        if b <= 0.0:
            continue
        trial = dataclasses.replace(inp, pair=dataclasses.replace(p, b=b))
        if passes(SOLVE.solve(trial)):
            return Proposal(z1, z2, m, b, (z2 / z1 - u) / u * 100.0, k), trial
    raise InputError(Problem(
        "design", f"no module of the first series up to {MODULES_1[-1]:g} mm carries the "
        f"load with z1 = {z1}, K_be = {face_ratio:g}: use stronger materials, a smaller "
        f"torque or several stages"))
