"""Strength of every mesh of a planetary train to GOST 21354-87, by the spur rating
(:func:`geardesign.spur.strength.rating.rate`), and the planet bearing load.

Each mesh is rated as a pair of one planet: the torque of its smaller gear is the share
of one planet times the load-sharing factor K_γ, the speeds are relative to the carrier,
and the cycle counts use n_w meshes per revolution for a central gear, one for a planet.
A planet tooth that meshes a sun and a ring is loaded on both flanks: its bending
allowable takes the reversed-load factor Y_A with T_rev/T = 1.

References
----------
GOST 21354-87 (through the spur rating); Kudryavtsev, "Planetary gears. Handbook"
(per-planet force F_t = 2000 T_a K_γ/(n_w d_a), relative speeds, cycle counts, the
planet's alternating bending); [GOST21354].
"""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.core.records import dataclass
from geardesign.planetary.geometry import Mesh
from geardesign.planetary.kinematics import Speeds, Train
from geardesign.gears import geometry as G
from geardesign.spur.strength.rating import Duty, Life, Setting


@dataclass(frozen=True)
class MeshDuty:
    """What the rating of one mesh needs: the pair in rating order (the smaller gear
    first for an external mesh), torque and speed of its first gear."""

    geom: object
    members: tuple[str, str]     # members in rating order
    T1: float                    # torque of the first gear for one planet × K_γ, N·m
    n1: float                    # speed of the first gear relative to the carrier, min⁻¹
    c: tuple[int, int]           # meshes per revolution (central gear n_w, planet 1)
    reverse: tuple[float, float]  # T_rev/T per gear
    F_t: float                   # tangential force at the reference circle, one planet, N


def _member_torque_force(T_member: float, d_member: float, planets: int, K_gamma: float
                         ) -> float:
    """F_t = 2000 |T_X| K_γ/(n_w d_X): the force on one planet at the reference circle
    of central member X (Kudryavtsev; [GOST21354])."""
    return 2000.0 * abs(T_member) * K_gamma / (planets * d_member)


def mesh_duties(train: Train, meshes: list[Mesh], s: Speeds, T_ideal: dict,
                K_gamma: float, both_flanks: dict) -> list[MeshDuty]:
    """Rating data of each mesh from the ideal (lossless) member torques ``T_ideal``.

    ``both_flanks``: planet crown -> True if it meshes two members on opposite flanks."""
    out = []
    for mesh in meshes:
        g = mesh.geom
        spec = mesh.spec
        central = spec.pinion if spec.pinion == "sun" else spec.wheel
        d_central = g.g1.d if central == spec.pinion else g.g2.d
        F_t = _member_torque_force(T_ideal[central], d_central, train.planets, K_gamma)
        crown = spec.wheel if central == spec.pinion else spec.pinion
        n_rel_planet = abs(s.n_planet_rel)
        n_rel_central = abs(s.rel(central))
        rev_planet = 1.0 if both_flanks.get(crown, False) else 0.0
        if spec.internal:
            members = (crown, central)
            geom = g
            n1, c = n_rel_planet, (1, train.planets)
            reverse = (rev_planet, 0.0)
        elif g.inp.z1 <= g.inp.z2:
            members = (central, crown)
            geom = g
            n1, c = n_rel_central, (train.planets, 1)
            reverse = (0.0, rev_planet)
        else:   # a sun larger than its planet: rate with the planet as the pinion
            p = g.inp
            geom = G.pair_geometry(replace(p, z1=p.z2, z2=p.z1, x1=p.x2, x2=p.x1))
            members = (crown, central)
            n1, c = n_rel_planet, (1, train.planets)
            reverse = (rev_planet, 0.0)
        T1 = F_t * geom.g1.d / 2000.0
        out.append(MeshDuty(geom, members, T1, n1, c, reverse, F_t))
    return out


def shared_meshes(train: Train, members: tuple[str, str]) -> tuple[int, int]:
    """How many meshes of its kind each gear of a rated mesh carries, for the reduced mass
    of K_v: the sun meshes every planet at once (n_w), a planet crown one sun, a ring is
    rigid.  [ISO6336-1] 6.5.9 (planetary gears): m_red = m_P m_S/(n_P m_P + m_S) for the
    sun–planet mesh, m_red = m_P for the planet–ring mesh
    (:func:`geardesign.spur.strength.iso6336.part1.reduced_mass`)."""
    return tuple(train.planets if m == "sun" else 1 for m in members)


def rate_mesh(rate, md: MeshDuty, mats: tuple, K_A: float, life_hours: float,
              regime: str | None, blocks: tuple, T_peak_ratio: float | None,
              setting: Setting):
    """Rate one mesh with the spur ``rate`` function of the chosen method."""
    life = Life(life_hours, md.c, regime, blocks)
    T_peak = md.T1 * T_peak_ratio if T_peak_ratio is not None else None
    duty = Duty(md.T1, max(md.n1, 1e-9), K_A, T_peak, 0.0, life, md.reverse)
    return rate(md.geom, mats, duty, setting)


@dataclass(frozen=True)
class BearingLoad:
    F_r: float       # radial load on one planet bearing, N
    F_t: float       # tangential component (carrier direction), N
    F_n: float       # component along the planet's radius, N
    n: float         # speed of the planet relative to the carrier, min⁻¹


def planet_bearing_load(train: Train, meshes: list[Mesh], T_ideal: dict, K_gamma: float,
                        n_planet_rel: float) -> BearingLoad:
    """Load of one planet's bearing: the vector sum of the mesh forces on the planet.

    In the carrier frame, with the sun at −x and the rings at +x of the planet centre,
    mesh X puts on the planet the tangential force F_y = ±T^X/r_w (T^X = ρ_X T_X/n_w the
    torque about the planet axis, r_w the planet's working pitch radius in that mesh;
    − for the sun side, + for the rings) and the radial force |F_y| tan α_tw pushing the
    planet away from the mating teeth (+x from the sun, −x from a ring):

    .. math:: F = \\sqrt{(\\textstyle\\sum F_y)^2 + (\\sum F_x)^2}

    For a 2K-H train without shifts F = 2F_t.  References: statics of the planet
    ([Kudryavtsev]: bearing load 2F_t at the relative speed).
    """
    Fx = Fy = 0.0
    for mesh in meshes:
        spec, g = mesh.spec, mesh.geom
        central = spec.pinion if spec.pinion == "sun" else spec.wheel
        crown_geom = g.g2 if central == spec.pinion else g.g1
        T_planet = train.rho(central) * T_ideal[central] * K_gamma / train.planets
        r_w = 0.5 * crown_geom.d_w / 1000.0
        side = -1.0 if central == "sun" else 1.0
        F_y = side * T_planet / r_w
        Fy += F_y
        Fx += (1.0 if central == "sun" else -1.0) * abs(F_y) * math.tan(g.alpha_tw)
    return BearingLoad(math.hypot(Fx, Fy), Fy, Fx, abs(n_planet_rel))
