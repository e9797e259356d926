"""Statics of a shaft on two bearings loaded by its gears (pure functions).

Coordinates: z along the shaft axis (bearing A at z_A, bearing B at z_B), x-y the
transverse plane.  A gear on the shaft meshes with a mate whose axis lies in the direction
``e = (cos θ, sin θ)`` from this shaft's axis (θ = ``mate_angle``); the contact point is at
``r·e`` (r the working pitch radius).  The mesh forces on this gear are

* radial  F_r, towards its own axis:            −F_r·e
* tangential F_t along t = (−sin θ, cos θ):      −s·F_t·t on a driving gear (it resists the
  shaft's rotation s = ±1), +s·F_t·t on a driven gear (it turns the shaft)
* axial   F_a along ±z (the sign is the designer's: it depends on the helix hands).

Bearings are simple radial supports; the axial force goes to the bearing named fixed.
Equilibrium (moments about A, ΣF = 0) gives the reactions in both planes:

.. math::
    R_{Bx} = -M_{Ay}/L,\\quad R_{By} = M_{Ax}/L,\\quad
    R_A = -\\sum F_{xy} - R_B,\\quad R_{z,fixed} = -\\sum F_z

with M_A = Σ (p − A) × F and L = z_B − z_A (statics of a beam on two supports).
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass


@dataclass(frozen=True)
class GearLoad:
    """The mesh forces on one gear (N) and where it sits on the shaft."""

    F_t: float
    F_r: float
    F_a: float
    r: float              # working pitch radius, mm
    z: float              # position of the gear mid-plane along the shaft, mm
    mate_angle: float     # rad
    driving: bool
    axial_sign: int = 1


@dataclass(frozen=True)
class Reactions:
    R_A: tuple[float, float]
    R_B: tuple[float, float]
    axial: float          # the axial reaction at the fixed bearing (magnitude)

    @property
    def F_rA(self) -> float:
        return math.hypot(*self.R_A)

    @property
    def F_rB(self) -> float:
        return math.hypot(*self.R_B)


def external_load(force: float, angle: float, z: float, axial: float = 0.0) -> GearLoad:
    """A point force on the shaft as a :class:`GearLoad` with no tangential force and no
    lever: ``force`` [N] in the direction θ = ``angle`` [rad] of the transverse plane,
    ``axial`` [N] along +z, at ``z`` [mm].  :func:`gear_force` then gives
    F = (force·cos θ, force·sin θ, axial) at (0, 0, z): the radial force of a gear is
    −F_r·e, so F_r = −force.

    >>> gear_force(external_load(100.0, 0.0, 5.0, -20.0), 1)
    ((100.0, 0.0, -20.0), (0.0, 0.0, 5.0))
    """
    return GearLoad(0.0, -force, abs(axial), 0.0, z, angle, driving=False,
                    axial_sign=-1 if axial < 0 else 1)


def external_loads(sh: dict) -> list[GearLoad]:
    """The ``[[shaft.load]]`` tables of a shaft spec (force [N], angle [deg], position [mm],
    axial [N]) as point loads (:func:`external_load`)."""
    return [external_load(ld["force"], math.radians(ld["angle"]), ld["position"], ld["axial"])
            for ld in sh.get("load") or []]


def gear_force(g: GearLoad, rotation: int) -> tuple[tuple[float, float, float], tuple[float, float, float]]:
    """Force vector on the gear and its point of application (x, y, z) in mm."""
    ex, ey = math.cos(g.mate_angle), math.sin(g.mate_angle)
    tx, ty = -ey, ex
    sign_t = (-rotation) if g.driving else rotation
    F = (-g.F_r * ex + sign_t * g.F_t * tx, -g.F_r * ey + sign_t * g.F_t * ty,
         g.axial_sign * g.F_a)
    p = (g.r * ex, g.r * ey, g.z)
    return F, p


def reactions(z_A: float, z_B: float, loads: list[GearLoad], rotation: int = 1) -> Reactions:
    """Bearing reactions of a shaft on two supports (see the module docstring)."""
    L = z_B - z_A
    Fx = Fy = Fz = Mx = My = 0.0
    for g in loads:
        (fx, fy, fz), (px, py, pz) = gear_force(g, rotation)
        dz = pz - z_A
        Fx, Fy, Fz = Fx + fx, Fy + fy, Fz + fz
        # M = (p − A) × F with p − A = (px, py, dz)
        Mx += py * fz - dz * fy
        My += dz * fx - px * fz
    RBx, RBy = -My / L, Mx / L
    return Reactions((-Fx - RBx, -Fy - RBy), (RBx, RBy), abs(Fz))
