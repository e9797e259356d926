"""inputs -> record: the bevel pair solved once (pure, no report rows)."""

from __future__ import annotations

from geardesign.bevel import forces as shaft_forces
from geardesign.bevel import geometry, gost_route, rating
from geardesign.bevel.inputs import Inputs
from geardesign.core.records import dataclass


@dataclass(frozen=True)
class Solution:
    """The pair's typed record: geometry, forces and the ratings asked for."""

    inputs: Inputs
    geometry: geometry.Geometry
    forces: shaft_forces.Forces
    iso: rating.IsoRating | None
    gost: gost_route.GostRating | None


def ratable(g: geometry.Geometry) -> bool:
    """Whether the pair meshes as computed, so that a strength rating means something: a
    transverse contact ratio of at least 1, no undercut and no pointed tip on either
    member's virtual gear (the tooth form of [ISO6336-3] method B needs a real fillet)."""
    return g.eps_va >= 1.0 and all(m.x >= m.x_min - 1e-9 and m.s_am > 0.0
                                   for m in g.members)


def solve(inp: Inputs) -> Solution:
    """Geometry, forces and the strength ratings of ``inp.rating.method`` (none for a pair
    that is not :func:`ratable`)."""
    g = geometry.pair_geometry(inp.pair)
    f = shaft_forces.forces(inp, g)
    rate = ratable(g)
    return Solution(inp, g, f,
                    rating.iso_rating(inp, g, f) if rate and inp.rating.iso else None,
                    gost_route.gost_rating(inp, g, f) if rate and inp.rating.gost else None)
