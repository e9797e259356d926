"""A worm pair solved from its typed inputs (:mod:`geardesign.worm.inputs`) into one
record: the geometry (:mod:`.geometry`) and the analysis of kinematics, strength, stiffness
and oil temperature (:func:`geardesign.worm.pair.analyse`).  Pure: no spec, no rows."""

from __future__ import annotations

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.worm.geometry import WormGeometryError, WormPairGeometry, WormPairInput, \
    pair_geometry
from geardesign.worm.inputs import Inputs
from geardesign.worm.pair import Analysis, analyse


@dataclass(frozen=True)
class Record:
    """A solved worm pair: its inputs and the analysis (``analysis.g`` the geometry)."""

    inputs: Inputs
    analysis: Analysis


def _solve(p: WormPairInput) -> WormPairGeometry:
    try:
        return pair_geometry(p)
    except WormGeometryError as exc:  # pragma: no cover - guarded by the input rules
        raise InputError(Problem("gear", str(exc))) from None




def efficiency(inp: Inputs) -> float:
    """The pair's overall efficiency η (bearings and churning included) at the worm speed
    of ``inp``: it does not depend on the torque (:func:`geardesign.worm.pair.efficiency`),
    so a drive finds the wheel torque of a given worm torque before it solves the pair."""
    from geardesign.worm.pair import efficiency as eff

    return eff(_solve(inp.pair), inp.op.n1, inp.wheel, inp.options)[3]


def solve(inp: Inputs) -> Record:
    """The record of a worm pair: geometry, then the whole analysis."""
    return Record(inp, analyse(_solve(inp.pair), inp.op, inp.wheel, inp.options))
