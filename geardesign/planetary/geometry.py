"""Geometry of every mesh of a planetary train: the external sun–planet mesh by
:func:`geardesign.gears.geometry.pair_geometry` (GOST 16532-70), the internal planet–ring
meshes by :func:`geardesign.gears.internal.internal_pair_geometry` (GOST 19274-73), the
shifts that make the meshes coaxial, and the mesh quality indices of Matusevich et al.

Pure functions; lengths mm, angles rad.  Ring shifts are in the GOST 19274-73 sign
(:mod:`geardesign.gears.internal`).

References
----------
GOST 16532-70, GOST 19274-73; Matusevich, Paravan, Shekhov, Avramov, "Optimal design of
planetary mechanisms of type 3K", Bulletin of NTU "KhPI" 2017 No. 25 ([Matusevich2017]), eqs. (2),
(5), (15)-(28) (coaxiality with shifts), (31)-(37) (quality
indices); [Matusevich2017]; [GOST19274].
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.planetary.kinematics import Train
from geardesign.gears import geometry as G
from geardesign.gears import internal as I
from geardesign.spur.kinematics import Sliding, balanced_shift_split, sliding_at_ends


@dataclass(frozen=True)
class MeshSpec:
    """One mesh of the train: its name, pinion and wheel members, and its module/face."""

    name: str           # "sun_planet", "planet_ring", "planet2_ring", "planet_ring2", ...
    pinion: str         # "sun", "planet" or "planet2"
    wheel: str          # "planet", "ring" or "ring2"
    internal: bool
    second: bool        # belongs to the second crown (module2, face_width2)


def meshes_of(train: Train) -> tuple[MeshSpec, ...]:
    """The meshes of a scheme: 2K-H sun–planet + planet–ring; stepped sun–planet +
    planet2–ring; 3K sun–planet + planet–ring + planet(2)–ring2."""
    out = [MeshSpec("sun_planet", "sun", "planet", False, False)]
    if train.scheme == "2K-H":
        out.append(MeshSpec("planet_ring", "planet", "ring", True, False))
    elif train.scheme == "2K-H-stepped":
        out.append(MeshSpec("planet2_ring", "planet2", "ring", True, True))
    else:
        out.append(MeshSpec("planet_ring", "planet", "ring", True, False))
        crown = "planet2" if train.planet2 is not None else "planet"
        out.append(MeshSpec(f"{crown}_ring2", crown, "ring2", True, crown == "planet2"))
    return tuple(out)


def gear_teeth(train: Train, member: str) -> int:
    return {"sun": train.sun, "planet": train.planet, "planet2": train.planet2,
            "ring": train.ring, "ring2": train.ring2}[member]


@dataclass(frozen=True)
class Layout:
    """Everything the mesh geometry needs besides the shifts."""

    train: Train
    m: float                 # normal module of the sun–planet(–ring) meshes
    m2: float                # normal module of the second crown's mesh
    beta: float
    b_w: float
    b_w2: float
    rack: G.BasicRack
    ring_rack: G.BasicRack
    k2: float = 0.0
    cutter: I.ShaperCutter | None = None

    def module(self, mesh: MeshSpec) -> float:
        return self.m2 if mesh.second else self.m

    def face(self, mesh: MeshSpec) -> float:
        return self.b_w2 if mesh.second else self.b_w


def reference_center_distance(lay: Layout, mesh: MeshSpec) -> float:
    """a = m_t (z2 ± z1)/2 of a mesh (+ external, − internal)."""
    z1, z2 = gear_teeth(lay.train, mesh.pinion), gear_teeth(lay.train, mesh.wheel)
    m_t = lay.module(mesh) / math.cos(lay.beta)
    return 0.5 * m_t * ((z2 - z1) if mesh.internal else (z1 + z2))


def center_distance_from_angle(lay: Layout, alpha_tw: float) -> float:
    """a_w of the sun–planet mesh for a working angle (paper (b) eq. (16)):
    a_w = a cos α_t / cos α_tw."""
    alpha_t, _ = G.transverse_angles(lay.rack.alpha_n, lay.beta)
    return reference_center_distance(lay, meshes_of(lay.train)[0]) * math.cos(alpha_t) / \
        math.cos(alpha_tw)


def shift_sum_for(lay: Layout, mesh: MeshSpec, a_w: float) -> float:
    """x_Σ (external) or x2 − x1 (internal) that puts a mesh at centre distance a_w:
    coaxiality, paper (b) eqs. (15), (17)-(22).  Raises GeometryError
    ``CENTER_DISTANCE_TOO_SMALL`` if a_w is below (d_b2 ± d_b1)/2."""
    z1, z2 = gear_teeth(lay.train, mesh.pinion), gear_teeth(lay.train, mesh.wheel)
    m = lay.module(mesh)
    if mesh.internal:
        return I.shift_difference_for_center_distance(a_w, m, z1, z2, lay.rack.alpha_n,
                                                      lay.beta)[0]
    return G.shift_sum_for_center_distance(a_w, m, z1, z2, lay.rack.alpha_n, lay.beta)[0]


def coaxial_shifts(lay: Layout, a_w: float, x_sun: float | None,
                   x_planet2: float | None) -> tuple[dict, str]:
    """Shifts of every gear that make all meshes run at the centre distance a_w.

    x_Σ of the sun–planet mesh and x2 − x1 of each planet–ring mesh follow from a_w
    (paper (b) eqs. (15), (21), (22)); the sun takes ``x_sun`` (or, if ``None``, the
    split of equal specific sliding at both roots of the sun–planet mesh,
    :func:`geardesign.spur.kinematics.balanced_shift_split`), the planet x_Σ − x_sun
    (eq. (26)), each ring its planet crown's shift plus the difference (eqs. (25), (28));
    a second planet crown takes ``x_planet2`` (0 if ``None``).

    Returns ``(shifts by member, how the sun's shift was chosen)``.
    """
    train = lay.train
    meshes = meshes_of(train)
    sp = meshes[0]
    x_sum = shift_sum_for(lay, sp, a_w)
    how = "given"
    if x_sun is None:
        base = G.PairInput(lay.m, train.sun, train.planet, 0.0, 0.0, lay.beta, lay.b_w, lay.rack)
        x_sun = balanced_shift_split(base, x_sum)
        how = "equal specific sliding of the sun–planet mesh"
    x = {"sun": x_sun, "planet": x_sum - x_sun}
    if train.planet2 is not None:
        x["planet2"] = 0.0 if x_planet2 is None else x_planet2
    for mesh in meshes[1:]:
        x[mesh.wheel] = x[mesh.pinion] + shift_sum_for(lay, mesh, a_w)
    return x, how


@dataclass(frozen=True)
class Mesh:
    """A computed mesh: geometry (spur PairGeometry or InternalPairGeometry) and sliding."""

    spec: MeshSpec
    geom: object
    sliding: Sliding

    @property
    def name(self) -> str:
        return self.spec.name


def mesh_geometry(lay: Layout, shifts: dict) -> list[Mesh]:
    """Geometry of every mesh for the given shifts.  The planet of a sun–planet mesh keeps
    its tip diameter (with the tip shortening Δy of that external mesh) in its ring mesh,
    as a real planet has one tip circle (KISSsoft does the same).

    Raises GeometryError (codes of :func:`geardesign.gears.geometry.pair_geometry` and
    :func:`geardesign.gears.internal.internal_pair_geometry`) with ``mesh`` set on it."""
    train = lay.train
    out: list[Mesh] = []
    planet_geometry = {}
    for mesh in meshes_of(train):
        z1, z2 = gear_teeth(train, mesh.pinion), gear_teeth(train, mesh.wheel)
        m, b = lay.module(mesh), lay.face(mesh)
        x1, x2 = shifts[mesh.pinion], shifts[mesh.wheel]
        try:
            if mesh.internal:
                g = I.internal_pair_geometry(I.InternalPairInput(
                    m, z1, z2, x1, x2, lay.beta, b, lay.rack, lay.ring_rack, lay.k2,
                    pinion=planet_geometry.get(mesh.pinion), cutter=lay.cutter))
            else:
                g = G.pair_geometry(G.PairInput(m, z1, z2, x1, x2, lay.beta, b, lay.rack))
                planet_geometry[mesh.wheel] = g.g2
        except G.GeometryError as exc:
            exc.mesh = mesh
            raise
        out.append(Mesh(mesh, g, sliding_at_ends(g)))
    return out


# ----------------------------------------------------------------------------- quality


def specific_pressure(z1: int, z2: int, alpha_t: float, alpha_tw: float,
                      internal: bool) -> float:
    """Specific-pressure coefficient of a mesh: the module over the reduced radius of
    curvature at the pitch point,

    .. math:: η = \\frac{m}{ρ_{red}} = \\frac{2 (z_2 \\pm z_1)}{z_1 z_2 \\cos α_t \\tan α_{tw}}

    "+" external, "−" internal.  Matusevich et al. 2017, eq. (34) ([Matusevich2017];
    e.g. 0.567 for their sun–planet mesh 12/46 at α_tw = 21.525°).

    Example: the sun–planet mesh 12/46 of [Matusevich2017] (α_t = 20°, α_tw = 21.525°):

    >>> import math
    >>> round(specific_pressure(12, 46, math.radians(20.0), math.radians(21.525), False), 3)
    0.567
    """
    s = -1.0 if internal else 1.0
    return 2.0 * (z2 + s * z1) / (z1 * z2 * math.cos(alpha_t) * math.tan(alpha_tw))


def sliding_balance(theta_p: float, theta_q: float) -> float:
    """Imbalance of the specific sliding at the two roots, Δϑ = |ϑ_p| − |ϑ_q|
    (Matusevich et al. 2017, eq. (37)): 0 means equal wear of both roots."""
    return abs(theta_p) - abs(theta_q)
