"""Typed inputs of a spur pair: :class:`Inputs`, built from a validated spec by
:func:`from_spec` (every input rule, one round of problems) or directly in Python.

:func:`geardesign.spur.solve.solve` takes an :class:`Inputs` and returns the record of the
pair; :func:`geardesign.spur.report.report` turns the record into the report.  Units: mm,
radians (inside the pair input), N·m, min⁻¹, hours.
"""

from __future__ import annotations

import dataclasses
from dataclasses import field
from typing import Any, NamedTuple

from geardesign.core.errors import Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.gears.geometry import PairInput
from geardesign.spur.spec_inputs import (
    STRENGTH_ONLY,
    _contact_ratio_domain,
    _drop_unused_defaults,
    _strength_inputs,
    solve_geometry,
)

GOST = "GOST 21354-87"


class Strength(NamedTuple):
    """What the strength rating needs beyond the geometry: the two gears' materials
    (:class:`~geardesign.materials.gear_steel.GearMaterial`), the duty and the setting
    (:class:`~geardesign.spur.strength.rating.Duty`, :class:`~geardesign.spur.strength.rating.Setting`)."""

    mats: tuple
    duty: Any
    setting: Any


@dataclass(frozen=True)
class Design:
    """The design mode's proposal: rows of the proposal, the rated variants, ψ_ba."""

    notes: list
    variants: list
    psi_ba: float


@dataclass(frozen=True)
class Inputs:
    """Everything :func:`geardesign.spur.solve.solve` reads.

    ``pair``: :class:`~geardesign.gears.geometry.PairInput` (or an internal pair's
    :class:`~geardesign.gears.internal.InternalPairInput`); ``how``: how the shifts were
    obtained; ``strength``: :class:`Strength` or ``None`` (geometry only); ``methods``: the
    rating methods (GOST 21354-87, ISO 6336:2019); ``iso``: the ISO 6336 setting
    (:class:`~geardesign.spur.strength.iso6336.rating.IsoSetting`) when rated by ISO 6336,
    ``iso_table`` the ``[iso]`` table it came from (bore and rim checks); ``speed1``: the
    pinion speed [min⁻¹] (None: no kinematics); ``spec``: the validated spec these inputs
    were read from (the report echoes it), ``None`` when built in Python.
    """

    pair: PairInput
    how: str = "given"
    strength: Strength | None = None
    methods: tuple[str, ...] = (GOST,)
    iso: Any = None
    iso_table: dict | None = field(default=None, compare=False)
    speed1: float | None = None
    allow_undercut: bool = False
    design: Design | None = field(default=None, compare=False)
    spec: ValidatedSpec | None = field(default=None, compare=False, repr=False)
    geometry: Any = field(default=None, compare=False, repr=False)
    """The pair's geometry when already computed for ``pair`` (reading the spec checks it);
    :func:`~geardesign.spur.solve.solve` computes it otherwise."""

    def replace(self, **changes) -> "Inputs":
        """A copy with ``changes``: fields of these inputs, or of the pair input
        (``b_w``, ``m_n``, ``x1``, ...), or of the duty (``T1``, ``n1``, ``K_A``, ...;
        ``n1`` and ``speed1`` are one speed).  The copy keeps no spec (its report would echo
        values it no longer has).  Each changed value that a spec key holds is checked
        against that key's domain (:data:`geardesign.spur.domains.SPEC_KEYS`), as reading the spec checks it:
        :class:`~geardesign.core.errors.InputError` names the key, the value and what is
        allowed (a study never solves a face width of NaN or a K_A of 0.1)."""
        from geardesign.spur.domains import check_changes

        check_changes(changes)
        if self.strength is not None:   # the pinion speed is the duty's n1 as well
            if "speed1" in changes:
                changes.setdefault("n1", changes["speed1"])
            elif "n1" in changes:
                changes["speed1"] = changes["n1"]
        pair_fields = {f.name for f in dataclasses.fields(self.pair)}
        pair = {k: changes.pop(k) for k in list(changes) if k in pair_fields}
        mine = {k: changes.pop(k) for k in list(changes)
                if k in {f.name for f in dataclasses.fields(self)}}
        out = dataclasses.replace(self, spec=None, **{"geometry": None, **mine})
        if pair:
            out = dataclasses.replace(out, pair=dataclasses.replace(out.pair, **pair))
        if changes:
            if out.strength is None:
                raise TypeError(f"unknown input(s) {sorted(changes)} (no strength inputs)")
            duty = dataclasses.replace(out.strength.duty, **changes)
            out = dataclasses.replace(out, strength=out.strength._replace(duty=duty))
        return out


def from_spec(spec: ValidatedSpec) -> Inputs:
    """The :class:`Inputs` of a validated spur spec (``kind = "spur"``).  Fills the spec's
    defaults that the calculation uses (echoed as assumed) and drops those it does not;
    raises :class:`~geardesign.core.errors.InputError` with every problem of a round."""
    from geardesign.spur.solve import ratable
    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen, iso_setting, \
        unused_tables

    d = spec.data
    design = None
    if d["design"] is not None:
        from geardesign.spur.design import design_pair

        unused_tables(spec)
        geom, how, gear, notes, variants = design_pair(spec)
        strength = _strength_inputs(spec, gear)
        design = Design(notes, variants, d["design"]["psi_ba"])
    else:   # the geometry and the strength inputs are checked independently: one report
        gear = d["gear"]
        problems = Problems()
        problems.stage(unused_tables, spec)
        solved = problems.stage(solve_geometry, spec)
        strength = problems.stage(_strength_inputs, spec, gear)
        problems.raise_all()
        geom, how = solved
    _contact_ratio_domain(geom, spec, gear)
    if strength is None:
        _drop_unused_defaults(spec, STRENGTH_ONLY)
    if d.get("accuracy") is not None:
        from geardesign.spur.drawing_data import assume_expansion

        assume_expansion(spec)
    methods = tuple(chosen(d["options"])) if strength is not None else ()
    iso = None
    if strength is not None and ISO_NAME in methods and ratable(geom):
        iso = iso_setting(spec)
    load = d["load"]
    return Inputs(geom.inp, how, Strength(*strength) if strength is not None else None,
                  methods, iso, d.get("iso") if iso is not None else None,
                  load["speed1"] if load is not None else None, bool(gear["allow_undercut"]),
                  design, spec, geom)


def from_tables(**tables) -> Inputs:
    """The :class:`Inputs` of a spur spec given as tables (as in a TOML file):
    ``from_tables(gear={...}, material={...}, load={...})``; validated like a file."""
    from geardesign.core.registry import load_data

    _, spec = load_data({"kind": "spur", **tables}, "<python>", expect_kind="spur")
    return from_spec(spec)
