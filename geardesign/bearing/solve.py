"""Bearings rated from their typed inputs (:mod:`geardesign.bearing.inputs`) into frozen
records: one bearing, a catalogue selection, or a pair with induced axial loads.  Pure: no
spec, no report rows (those are :mod:`geardesign.bearing.report`'s).  Formulas in
:mod:`.life`, :mod:`.assess`, :mod:`.pair`; a formula outside its domain raises
:class:`~geardesign.bearing.life.BearingError`."""

from __future__ import annotations

import math
from dataclasses import replace

from geardesign.bearing import catalogue as CAT
from geardesign.bearing import life as L
from geardesign.bearing import rib as RB
from geardesign.bearing import pair as PR
from geardesign.bearing import tables as T
from geardesign.bearing.assess import Assessment, Bearing, Block, Conditions, assess
from geardesign.bearing.inputs import (
    CheckInputs,
    Facts,
    Inputs,
    PairInputs,
    SelectInputs,
    catalogue_bearing,
    with_c_u,
)
from geardesign.core.errors import InputError
from geardesign.core.records import dataclass


@dataclass(frozen=True)
class Rated:
    """One bearing rated: its assessment, the continuous axial capacity of the ribs of an
    NJ/NUP bearing per block (``None`` where it does not apply) and the smallest catalogue
    bearing of the same type and bore that passes (``None``: none, or not looked for)."""

    a: Assessment
    facts: Facts
    ribs: tuple[RB.RibCapacity | None, ...]
    better: tuple[CAT.CatalogueBearing, float] | None = None    # (row, its life [h])


@dataclass(frozen=True)
class Selection:
    """The catalogue candidates, smallest first, each rated; ``chosen`` the index of the
    first that passes (``None``: none does); ``pick`` the chosen or the largest."""

    candidates: tuple[tuple[CAT.CatalogueBearing, Bearing, Assessment], ...]
    chosen: int | None
    pick: Rated
    facts: Facts


@dataclass(frozen=True)
class PairSolution:
    """Induced axial loads of a pair ([SKF6000] pp. 415–416) and both bearings rated."""

    F_iA: float
    F_iB: float
    carrier: str                 # "A" or "B": the bearing that carries K_a
    F_aA: float
    F_aB: float
    case: str                    # the governing case, as a formula
    A: Rated
    B: Rated


def ribs(a: Assessment, facts: Facts) -> tuple:
    """The continuous axial capacity of the ribs ([SKF6000] p. 518) of a catalogue NJ/NUP
    cylindrical roller bearing at each block with an axial load."""
    row = facts.catalogue
    out = []
    for r in a.blocks:
        design = row.designation.split()[0] if row is not None else ""
        if a.bearing.kind == "cylindrical_roller" and r.block.F_a > 0 and design in ("NJ",
                                                                                   "NUP"):
            out.append(RB.rib_capacity(a.bearing.C_0r, r.block.F_r, r.block.n, row.d, row.D,
                                      row.series, facts.lubricant))
        else:
            out.append(None)
    return tuple(out)


def better(a: Assessment, facts: Facts, blocks, cond: Conditions):
    """The smallest catalogue bearing of the same type and bore with a higher C_r that
    passes, and its life; ``None`` without a bore or when none passes."""
    if facts.d is None:
        return None
    for row in CAT.candidates(a.bearing.kind, facts.d):
        if row.C_r <= a.bearing.C_r:
            continue
        try:
            x = assess(with_c_u(catalogue_bearing(row, a.bearing), cond), list(blocks), cond)
        except (L.BearingError, InputError):
            continue
        if x.passes:
            return row, x.life_h
    return None


def rate(bearing: Bearing, blocks, cond: Conditions, facts: Facts,
         suggest: bool = True) -> Rated:
    """One bearing rated ([ISO281], [GOST18855]); with ``suggest`` and a life below the
    required one, the catalogue bearing that would pass."""
    a = assess(bearing, list(blocks), cond)
    short = suggest and cond.life_required is not None and a.life_h < cond.life_required
    return Rated(a, facts, ribs(a, facts), better(a, facts, blocks, cond) if short else None)


def solve_check(inp: CheckInputs) -> Rated:
    return rate(inp.bearing, inp.blocks, inp.cond, inp.facts)


def solve_select(inp: SelectInputs) -> Selection:
    """Every candidate rated; the smallest that meets the life and static safety."""
    results = tuple((row, cand, assess(cand, list(inp.blocks), inp.cond))
                    for row, cand in inp.candidates)
    chosen = next((i for i, x in enumerate(results) if x[2].passes), None)
    row, cand, a = results[chosen if chosen is not None else -1]
    facts = Facts(source=row.cite, note=row.note, catalogue=row, rating="catalogue",
                  d=row.d, D=row.D, B=row.B)
    # the checks of the pick judge the bearing alone (no catalogue row: SELECTION names it)
    return Selection(results, chosen, Rated(a, Facts(), ribs(a, Facts())), facts)


def induced(b: Bearing, F_r: float, factor: float | None) -> float:
    """The induced axial force of a tapered roller (k·F_r/Y) or angular contact ball
    bearing (R·F_r) [N] ([SKF6000] pp. 415–416)."""
    if b.kind == "tapered_roller":
        Y = b.Y
        if Y is None:
            tan_a = (b.e / 1.5) if b.e is not None else math.tan(math.radians(b.alpha))
            Y = T.ROLLER_RADIAL[1]["Y_gt_cot"] / tan_a
        return PR.induced_tapered(F_r, Y, PR.K_TAPERED if factor is None else factor)
    return PR.induced_angular(F_r, b.alpha, factor)


def solve_pair(inp: PairInputs) -> PairSolution:
    """The axial loads of the pair from the induced forces and K_a; both bearings rated."""
    blk = inp.block
    F_rA, F_rB, F_a = blk.F_r, inp.F_rB, inp.F_a
    F_iA = induced(inp.A, F_rA, inp.induced_factor)
    F_iB = induced(inp.B, F_rB, inp.induced_factor)
    who = PR.carrier(inp.arrangement, F_a)
    if who == "B":
        sol = PR.solve(F_iA, F_iB, abs(F_a))
        F_aA, F_aB = sol.F_aA, sol.F_aB
    else:
        sol = PR.solve(F_iB, F_iA, abs(F_a))
        F_aA, F_aB = sol.F_aB, sol.F_aA
    c, o = ("B", "A") if who == "B" else ("A", "B")       # carrier, other
    F_io = F_iA if o == "A" else F_iB
    F_ic = F_iB if c == "B" else F_iA
    case = (f"F_a{o} = F_i{o}, F_a{c} = F_i{o} + K_a" if F_io + abs(F_a) >= F_ic
            else f"F_a{c} = F_i{c}, F_a{o} = F_i{c} − K_a")
    bA = (Block(F_rA, F_aA, blk.n, 1.0),)
    bB = (Block(F_rB, F_aB, blk.n, 1.0),)
    cond_b = replace(inp.cond, F_r0=None, F_a0=None)
    return PairSolution(F_iA, F_iB, who, F_aA, F_aB, case,
                        rate(inp.A, bA, inp.cond, inp.facts_a),
                        rate(inp.B, bB, cond_b, inp.facts_b))


def solve(inp: Inputs) -> Rated | Selection | PairSolution:
    """The record of a bearing calculation, by the kind of its inputs."""
    if isinstance(inp, SelectInputs):
        return solve_select(inp)
    if isinstance(inp, PairInputs):
        return solve_pair(inp)
    return solve_check(inp)
