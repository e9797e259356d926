"""The ``epicycle_rim`` spec read into typed, frozen inputs (MPa, mm, deg, Hz).

Every rule across keys that the schema cannot state is checked here and raises a one-line
:class:`~geardesign.core.errors.InputError`; independent groups of rules (the ring and its
planets, the vehicle, the material, the bending stress, the hoop stresses, the stages, the
fatigue options, the resonance inputs) are checked in separate stages, so that a spec with
several independent mistakes gets every line in one run (:class:`Problems`); the fatigue inputs are read by :mod:`.fatigue_inputs`.  Defaults
that depend on other keys are written into the spec's echo (``spec.assumed``).
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems, Unusable
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.epicycle_rim import mesh
from geardesign.epicycle_rim.fatigue_inputs import Fatigue, assume, fatigue
from geardesign.epicycle_rim.spec import FATIGUE_TABLES


# ----------------------------------------------------------------------------- records


@dataclass(frozen=True)
class Ring:
    module: float            # m [mm]
    z: int
    face_width: float        # b [mm]
    rim_thickness: float     # δ [mm]
    tooth_height: float      # h [mm]


@dataclass(frozen=True)
class Planets:
    count: int
    z_sun: int | None
    z_planet: int | None
    x_sun: float
    x_planet: float
    contact_ratio: float | None
    angles: tuple[float, ...]    # planet axes on the carrier [deg]


@dataclass(frozen=True)
class Vehicle:
    wheel_radius: float                          # [mm]
    carrier_ratio: float
    speed_range: tuple[float, float] | None      # [km/h]


@dataclass(frozen=True)
class Resonance:
    natural_frequencies: tuple[float, ...]       # k0 [Hz]
    orders: tuple[int, ...]                      # sorted, distinct
    phase_model: str
    depth: str
    stiffness_model: str
    harmonics: int
    floquet_check: bool
    chart_b_max: float | None                    # None: from the instability regions
    chart_points: int


@dataclass(frozen=True)
class Inputs:
    ring: Ring
    planets: Planets
    fatigue: Fatigue | None
    resonance: Resonance | None
    vehicle: Vehicle | None


# ----------------------------------------------------------------------------- rules


def _tables(spec: ValidatedSpec) -> tuple[bool, bool]:
    d = spec.data
    given = [t for t in FATIGUE_TABLES if d.get(t) is not None]
    fatigue = bool(given)
    if fatigue:
        for t in FATIGUE_TABLES:
            if d.get(t) is None:
                what = "[[stage]] tables" if t == "stage" else f"table [{t}]"
                raise InputError(Problem(
                    t, f"missing {what}: the fatigue analysis (started by "
                    f"[{given[0]}]) needs [fillet], [material], [load] and [[stage]]"))
    elif d.get("fatigue") is not None:
        raise InputError(Problem(
            "fatigue", "applies to the fatigue analysis, which needs [fillet], [material], "
            "[load] and [[stage]]; remove [fatigue] or add them"))
    resonance = d.get("resonance") is not None
    if not fatigue and not resonance:
        raise InputError(Problem(
            "", "nothing to compute: give the fatigue tables ([fillet], [material], [load], "
            "[[stage]]) or [resonance], or both"))
    return fatigue, resonance


def _ring(spec: ValidatedSpec) -> Ring:
    ring = spec.data["ring"]
    if ring["tooth_height"] is None:
        assume(spec, "ring", "tooth_height", 2.25 * ring["module"])
    return Ring(ring["module"], ring["z"], ring["face_width"], ring["rim_thickness"],
                ring["tooth_height"])


def _coaxial(ring: dict, pl: dict) -> None:
    if (pl["z_sun"] is None) != (pl["z_planet"] is None):
        key = "planets.z_planet" if pl["z_planet"] is None else "planets.z_sun"
        raise InputError(Problem(key, "missing: give both z_sun and z_planet (or neither)"))
    if pl["z_sun"] is not None:
        delta = ring["z"] - pl["z_sun"] - 2 * pl["z_planet"]
        if abs(delta) > 2:
            raise InputError(Problem(
                "ring.z", f"does not fit the planets: z_sun + 2·z_planet = "
                f"{pl['z_sun'] + 2 * pl['z_planet']} (coaxial trains need z_r = z_s + 2·z_p, "
                f"±2 with profile shifts)", ring["z"]))


def _angles(ring: dict, pl: dict) -> list[float]:
    """The planet angles [deg] (given, from the shifts, or equally spaced)."""
    n = pl["count"]
    if pl["angles"] is not None and pl["shifts"] is not None:
        raise InputError(Problem("planets.shifts", "give planets.angles or planets.shifts, "
                                 "not both", pl["shifts"]))
    if pl["angles"] is not None:
        if len(pl["angles"]) != n:
            raise InputError(Problem("planets.angles", f"must list {n} angles (planets.count "
                                     f"= {n})", pl["angles"]))
        return list(pl["angles"])
    if pl["shifts"] is not None:
        k = pl["shifts"]
        if len(k) != n:
            raise InputError(Problem("planets.shifts", f"must list {n} shifts (planets.count "
                                     f"= {n})", k))
        if abs(sum(k)) > 1e-9:
            raise InputError(Problem("planets.shifts", f"must sum to 0 (the spacings add up "
                                     f"to 360°); the sum is {sum(k):.6g}", k))
        return mesh.angles_from_shifts(n, k, ring["z"])
    return [360.0 * i / n for i in range(n)]


def _planets(spec: ValidatedSpec) -> Planets:
    ring, pl = spec.data["ring"], spec.data["planets"]
    problems = Problems()
    problems.stage(_coaxial, ring, pl)
    angles = problems.stage(_angles, ring, pl)
    problems.raise_all()
    if angles is Problems.FAILED:    # uses a value reported by the schema
        raise Unusable()
    return Planets(pl["count"], pl["z_sun"], pl["z_planet"], pl["x_sun"], pl["x_planet"],
                   pl["contact_ratio"], tuple(angles))


def sun_planet_pair(ring: Ring, pl: Planets):
    """The sun-planet pair of the spacing check (GOST 13755 rack, α = 20°); an input error
    names the shifts when the pair cannot be built."""
    from geardesign.gears.geometry import BasicRack, GeometryError, PairInput, pair_geometry

    try:
        return pair_geometry(PairInput(ring.module, pl.z_sun, pl.z_planet, pl.x_sun,
                                       pl.x_planet, 0.0, ring.face_width,
                                       BasicRack(math.radians(20.0))))
    except GeometryError as exc:
        raise InputError(Problem("planets.x_planet", f"no sun-planet pair with these shifts "
                                 f"({exc}); check x_sun and x_planet", pl.x_planet)) from None


def _vehicle(spec: ValidatedSpec) -> Vehicle | None:
    v = spec.data.get("vehicle")
    if v is None:
        return None
    rng = v["speed_range"]
    if rng is not None:
        lo, hi = rng
        if not lo < hi:
            raise InputError(Problem("vehicle.speed_range", "must be [lowest, highest] with "
                                     "lowest < highest", rng))
    return Vehicle(v["wheel_radius"], v["carrier_ratio"],
                   None if rng is None else (rng[0], rng[1]))


def _resonance(spec: ValidatedSpec) -> Resonance:
    if spec.data["planets"]["contact_ratio"] is None:
        raise InputError(Problem("planets.contact_ratio", "missing: [resonance] needs the "
                                 "transverse contact ratio of the ring-planet mesh"))
    rz = spec.data["resonance"]
    return Resonance(tuple(rz["natural_frequencies"]), tuple(sorted(set(rz["orders"]))),
                     rz["phase_model"], rz["depth"], rz["stiffness_model"], rz["harmonics"],
                     rz["floquet_check"], rz["chart_b_max"], rz["chart_points"])


def _stages_of(spec: ValidatedSpec, problems: Problems) -> Inputs | None:
    tables = problems.stage(_tables, spec)
    ring = problems.stage(_ring, spec)
    planets = problems.stage(_planets, spec)
    vehicle = problems.stage(_vehicle, spec)
    if ring is not Problems.FAILED and planets is not Problems.FAILED and planets.z_sun:
        problems.stage(sun_planet_pair, ring, planets)
    if tables is Problems.FAILED:
        return None
    has_fatigue, resonance = tables
    fat = fatigue(spec, ring, problems) if has_fatigue else None
    res = problems.stage(_resonance, spec) if resonance else None
    if any(x is Problems.FAILED for x in (ring, planets, vehicle, res)) or (has_fatigue and fat is None):
        return None
    return Inputs(ring, planets, fat, res, vehicle)


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated spec; every independent input problem in one
    :class:`InputError`."""
    problems = Problems()
    inputs = _stages_of(spec, problems)
    problems.raise_all()
    assert inputs is not None
    return inputs


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """:func:`read`'s input stages on a spec whose schema problems are reported."""
    _stages_of(spec, problems)
