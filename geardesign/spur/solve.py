"""A spur pair solved: :func:`solve` takes :class:`~geardesign.spur.inputs.Inputs` and
returns a :class:`Record` (geometry, sliding, velocities, the ratings of every method), no
report rows.  This is the interface other calculators and scripts call (a drive's stage,
a study over variants); :func:`geardesign.spur.report.report` writes the report.

Units: lengths mm, angles rad, forces N, torques N·m, stresses MPa, speeds min⁻¹.
References: [GOST16532] (external pairs), [GOST19274] (internal pairs), [GOST21354] and
[ISO6336-1] … [ISO6336-6] (ratings).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import field
from typing import Any, Mapping

from geardesign.core.records import dataclass
from geardesign.gears.geometry import PairGeometry, pair_geometry
from geardesign.spur.kinematics import Sliding, Velocities, sliding_at_ends, velocities

GOST = "GOST 21354-87"
ISO = "ISO 6336:2019"


def ratable(g) -> bool:
    """Whether a pair (an internal pair in particular) has the geometry a strength rating
    needs: a continuous transverse mesh (ε_α >= 1, which the contact-ratio factors of both
    methods presume), both active limits before the tangency points and teeth that are not
    pointed."""
    return (g.eps_alpha >= 1.0 and g.g1.rho_p > 0.0 and g.g2.rho_p > 0.0
            and g.g1.s_an > 0.0 and g.g2.s_an > 0.0)


@dataclass(frozen=True)
class Record:
    """A solved spur pair.

    ``geometry``: :class:`~geardesign.gears.geometry.PairGeometry` (or the internal pair's);
    ``sliding``: specific sliding at the ends of action; ``velocities``: with a speed;
    ``ratings``: method name -> that method's rating (``.v``: factors, stresses, safety
    factors by symbol); ``forces``: the mesh forces' rating when GOST 21354-87 is not
    among the methods; ``rated``: False when strength inputs were given but the pair
    cannot be rated (see :func:`ratable`).
    """

    inputs: Any
    geometry: PairGeometry
    sliding: Sliding
    velocities: Velocities | None = None
    ratings: Mapping[str, Any] = field(default_factory=dict)
    forces: Any = None
    rated: bool = True

    # ------------------------------------------------------------- typed reading
    @property
    def values(self) -> dict:
        """Every rating's values by symbol, the first method's winning a shared key
        (``S_H1``, ``F_t``, ...), the mesh forces included."""
        out: dict = {}
        for r in reversed(list(self.ratings.values())):
            out.update(r.v)
        if self.forces is not None:
            out.update(self.forces.v)
        return out

    def margins(self) -> dict:
        """Safety margins S/S_min of every rating: GOST 21354-87 ``S_H1`` …, ISO 6336
        ``ISO S_H1`` …; empty when not rated."""
        out = {}
        for name, r in self.ratings.items():
            v, prefix = r.v, ("ISO " if name == ISO else "")
            for k in ("S_H1", "S_H2", "S_F1", "S_F2"):
                need = v.get(f"{k}_min", v.get(f"{k[:3]}min"))
                if v.get(k) is not None and need:
                    out[prefix + k] = v[k] / need
        return out

    # ------------------------------------------------------------- conversions
    def asdict(self) -> dict:
        """The record as plain, JSON-safe data: geometry, sliding, velocities and every
        rating's values (non-finite numbers as None)."""
        return _plain({"inputs": _inputs_dict(self.inputs), "geometry": self.geometry,
                       "sliding": self.sliding, "velocities": self.velocities,
                       "ratings": {k: r.v for k, r in self.ratings.items()},
                       "forces": None if self.forces is None else self.forces.v,
                       "rated": self.rated})

    def flat(self) -> dict:
        """One flat dict of the pair's main figures (a row of a table of variants):
        inputs, geometry scalars, each gear's figures numbered (``d_a1``, ``d_a2``), then
        the ratings' values prefixed by method (``GOST.S_H1``, ``ISO.S_F2``)."""
        p, g = self.inputs.pair, self.geometry
        row = {k: v for k, v in _plain(dataclasses.asdict(p)).items()
               if not isinstance(v, (dict, list))}
        row.update({k: v for k, v in _plain({f.name: getattr(g, f.name)
                                             for f in dataclasses.fields(g)}).items()
                    if not isinstance(v, (dict, list))})
        for i, gear in enumerate(g.gears, 1):     # a gear's figures with its number
            row.update({f"{f.name}{i}": v for f in dataclasses.fields(gear)
                        if isinstance(v := _plain(getattr(gear, f.name)), (int, float))})
        for name, r in self.ratings.items():
            tag = "ISO" if name == ISO else "GOST"
            row.update({f"{tag}.{k}": v for k, v in _plain(r.v).items()
                        if not isinstance(v, (dict, list))})
        return row

    def rows(self) -> list[dict]:
        """Pandas-friendly rows: one flat dict per quantity (``section``, ``key``,
        ``value``, ``unit``, ``symbol``, ``name``, ``source``): the geometry's scalars
        (section ``geometry``, gear quantities with the suffix 1 or 2), then every
        rating's rows (section prefixed by ``iso6336_`` for ISO 6336, as in the report)."""
        out = []
        g = self.geometry
        for f in dataclasses.fields(g):
            value = getattr(g, f.name)
            if f.name == "gears" or dataclasses.is_dataclass(value):
                continue
            out.append(dict(section="geometry", key=f.name, value=_plain(value), unit=None,
                            symbol=f.name, name="", source=""))
        for i, gear in enumerate(g.gears, 1):
            for f in dataclasses.fields(gear):
                value = getattr(gear, f.name)
                if isinstance(value, (int, float)) and not isinstance(value, bool):
                    out.append(dict(section="geometry", key=f"{f.name}{i}",
                                    value=_plain(value), unit=None, symbol=f"{f.name}{i}",
                                    name="", source=""))
        ratings = list(self.ratings.values()) + ([self.forces] if self.forces else [])
        for r in ratings:
            out += [dict(section=x.section, key=x.key, value=_plain(x.value), unit=x.unit,
                         symbol=x.symbol, name=x.name, source=x.source) for x in r.rows]
        return out


def _inputs_dict(inp) -> dict:
    out = {"pair": inp.pair, "how": inp.how, "methods": list(inp.methods),
           "speed1": inp.speed1}
    if inp.strength is not None:
        out["duty"] = inp.strength.duty
        out["materials"] = [m.label for m in inp.strength.mats]
    return out


def _plain(x):
    """JSON-safe plain data of dataclasses, tuples, dicts and numbers."""
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return {f.name: _plain(getattr(x, f.name)) for f in dataclasses.fields(x)}
    if isinstance(x, dict):
        return {str(k): _plain(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, bool) or x is None or isinstance(x, (int, str)):
        return x
    if isinstance(x, float):
        return x if math.isfinite(x) else None
    try:
        f = float(x)
    except (TypeError, ValueError):
        return str(x)
    return f if math.isfinite(f) else None


def geometry(pair) -> PairGeometry:
    """The geometry of a pair input: external ([GOST16532]) or internal ([GOST19274])."""
    from geardesign.gears import internal as I

    if isinstance(pair, I.InternalPairInput):
        return I.internal_pair_geometry(pair)
    return pair_geometry(pair)


def solve(inputs) -> Record:
    """Solve a spur pair: the geometry, the sliding, the velocities (with a speed) and the
    strength by every method of ``inputs.methods`` (with strength inputs and a pair that
    can be rated).  Raises :class:`~geardesign.core.errors.InputError` for an ISO 6336
    bore or rim outside the gear body."""
    if inputs.spec is None:         # built in Python: the domains a spec's keys have
        from geardesign.spur.domains import check_built

        check_built(inputs)
    g = inputs.geometry
    if g is None or g.inp is not inputs.pair:
        g = geometry(inputs.pair)
    sl = sliding_at_ends(g)
    vel = velocities(g, inputs.speed1) if inputs.speed1 is not None else None
    ratings: dict = {}
    forces = None
    rated = True
    st = inputs.strength
    if st is not None:
        internal = getattr(g, "internal", False)
        if (internal or ISO in inputs.methods) and not ratable(g):
            rated = False
        else:
            if GOST in inputs.methods:
                from geardesign.spur.strength import method

                ratings[GOST] = method(GOST).rate(g, st.mats, st.duty, st.setting)
            else:   # the mesh forces (shafts, bearings, a drive) whatever the method
                from geardesign.spur.strength.rating import forces as mesh_forces

                forces = mesh_forces(g, st.duty)
            if ISO in inputs.methods:
                from geardesign.spur.strength.iso6336 import rating as IR
                from geardesign.spur.strength.iso6336.spec import gear_checks

                if inputs.iso_table is not None:
                    gear_checks(inputs.iso_table, g)
                ratings[ISO] = IR.rate(g, st.mats, st.duty, st.setting, inputs.iso)
    if inputs.spec is None:
        _refuse_impossible(g, ratings)
    return Record(inputs, g, sl, vel, ratings, forces, rated)


def _refuse_impossible(g, ratings: dict) -> None:
    """Inputs built in Python (:meth:`~geardesign.spur.inputs.Inputs.replace`, a study)
    meet the rule the report's guard applies to a spec's result
    (:func:`geardesign.core.result.guard`): a contact ratio, a safety factor or a life
    below zero cannot be computed, and raises
    :class:`~geardesign.core.result.ResultDomainError` naming it, instead of a record whose
    margins are negative."""
    from geardesign.core.result import refuse_negative
    from geardesign.spur.strength.common import rows

    for key in ("eps_alpha", "eps_gamma"):
        refuse_negative(key, getattr(g, key, None), key, f"results.geometry.{key}")
    for record in ratings.values():
        for row in rows(record):
            refuse_negative(row.key, row.value, row.symbol or row.key,
                            f"results.{row.section}.{row.key}")


from geardesign.core.modules import callable_module  # noqa: E402

callable_module(__name__, "solve")   # spur.solve(inputs) as well as spur.solve.Record
