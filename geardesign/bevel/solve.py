"""inputs -> record: the bevel pair solved once (pure, no report rows)."""

from __future__ import annotations

import dataclasses

from geardesign.bevel import factors, geometry, gost_route, peak, rating
from geardesign.bevel import forces as shaft_forces
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
    factors: factors.LoadFactors | None = None    # K_v, K_Hα as used (given or method B)
    iso_peak: peak.IsoPeak | None = None          # static checks at load.peak_torque
    gost_peak: peak.GostPeak | None = None


def ratable(g: geometry.Geometry) -> bool:
    """Whether the pair meshes as computed, so that a strength rating means something: a
    transverse contact ratio of at least 1, no undercut and no pointed tip on either
    member's virtual gear (the tooth form of [ISO6336-3] method B needs a real fillet)."""
    return g.eps_va >= 1.0 and all(m.x >= m.x_min - 1e-9 and m.s_am > 0.0
                                   for m in g.members)


def solve(inp: Inputs) -> Solution:
    """Geometry, forces and the strength ratings of ``inp.rating.method`` (none for a pair
    that is not :func:`ratable`), with K_v and K_Hα given or by [ISO10300-1] method B
    (:func:`geardesign.bevel.factors.load_factors`), and the static checks at the peak
    torque when one is given (:mod:`geardesign.bevel.peak`)."""
    g = geometry.pair_geometry(inp.pair)
    f = shaft_forces.forces(inp, g)
    if not ratable(g):
        return Solution(inp, g, f, None, None)
    lf = factors.load_factors(inp, g, f.F_mt, f.v_mt)
    used = dataclasses.replace(inp, load=dataclasses.replace(inp.load, K_v=lf.K_v,
                                                             K_alpha=lf.K_Halpha))
    iso = rating.iso_rating(used, g, f) if inp.rating.iso else None
    gost = gost_route.gost_rating(used, g, f) if inp.rating.gost else None
    peaked = inp.load.T_peak is not None
    return Solution(inp, g, f, iso, gost, lf,
                    peak.iso_peak(used, iso) if peaked and iso is not None else None,
                    peak.gost_peak(used, lf.K_Halpha, gost)
                    if peaked and gost is not None else None)
