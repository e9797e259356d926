"""inputs -> record: the bevel pair solved once (pure, no report rows)."""

from __future__ import annotations

from dataclasses import dataclass

from geardesign.bevel import geometry, rating
from geardesign.bevel.inputs import Inputs


@dataclass(frozen=True)
class Solution:
    """The pair's typed record: geometry, forces and the ratings asked for."""

    inputs: Inputs
    geometry: geometry.Geometry
    forces: rating.Forces
    iso: rating.IsoRating | None
    gost: rating.GostRating | None


def solve(inp: Inputs) -> Solution:
    """Geometry, forces and the strength ratings of ``inp.rating.method``."""
    g = geometry.pair_geometry(inp.pair)
    f = rating.forces(inp, g)
    return Solution(inp, g, f,
                    rating.iso_rating(inp, g, f) if inp.rating.iso else None,
                    rating.gost_rating(inp, g, f) if inp.rating.gost else None)
