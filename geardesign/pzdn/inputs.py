"""The ``pzdn`` spec read into typed, frozen inputs.

Every rule across keys that the schema cannot state is checked here and raises a one-line
:class:`~geardesign.core.errors.InputError`; the tables are independent stages (each
``[[spring]]`` (:mod:`.spring_inputs`), ``[coupling_gear]`` and each of its materials,
``[startup]`` (:mod:`.startup_inputs`), ``[regression]``), so that a spec with several
independent mistakes gets every line in one run (:class:`Problems`).  Defaults that depend
on other keys are written into the spec's echo, which leaves out the spring keys not given.
"""

from __future__ import annotations

import copy

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.pzdn import sources as S
from geardesign.pzdn.spring_inputs import Spring, fmt, spring
from geardesign.pzdn.startup_inputs import Startup, check_bounds, startup

TABLES = ("spring", "coupling_gear", "startup", "regression")


@dataclass(frozen=True)
class Motor:
    """The [motor] table (the wind-up of method A)."""

    speed: float                 # [min⁻¹]
    nominal_torque: float | None  # [N·m]
    power: float | None          # [kW]
    breakaway_time: float        # [s]
    windup_factor: float


@dataclass(frozen=True)
class Coupling:
    """The coupling gear: its table as given (the spur spec is built from it) and the
    resolved materials of the pinion and the wheel."""

    table: dict
    materials: tuple


@dataclass(frozen=True)
class Regression:
    C: float                     # link stiffness C12 [N·m/rad]
    how: str                     # its source
    T_ref_12: float
    T_ref_23: float
    pzdn_stiffness: float | None
    drive_stiffness: float | None
    sweep: tuple[float, ...]


@dataclass(frozen=True)
class Inputs:
    springs: tuple[Spring, ...]
    motor: Motor | None
    coupling: Coupling | None
    startup: Startup | None
    regression: Regression | None


def _tables(d: dict) -> None:
    if not [t for t in TABLES if d.get(t) is not None]:
        raise InputError(Problem("", "nothing to compute: give [[spring]] tables, "
                                 "[coupling_gear], [startup] or [regression]"))
    if d["motor"] is not None and d["spring"] is None:
        raise InputError(Problem("motor", "applies only with [[spring]] tables (the wind-up "
                                 "angle of method A); remove it or add the springs"))


def _names(springs: list) -> None:
    seen: dict = {}
    problems = []
    for j, sp in enumerate(springs):
        if sp["name"] is not None and sp["name"] in seen:
            problems.append(Problem(f"spring[{j}].name", f"spring[{seen[sp['name']]}] has the "
                                    f"same name; give each spring its own name", sp["name"]))
        seen.setdefault(sp["name"], j)
    if problems:
        raise InputError(problems)


def _peak(g: dict) -> None:
    if g["peak_torque"] is not None and g["peak_torque"] < g["torque"]:
        raise InputError.at("coupling_gear.peak_torque", g["peak_torque"],
                            f"smaller than the working torque {fmt(g['torque'])} N·m; give "
                            f"the largest short-time torque")


def _material(g: dict, who: str):
    from geardesign.materials.gear_steel import resolve

    return resolve(dict(g[who], root_ground=False, roughness_Ra=1.25),
                   f"coupling_gear.{who}")


def _coupling(g: dict, problems: Problems) -> Coupling | None:
    peak = problems.stage(_peak, g)
    mats = tuple(problems.stage(_material, g, who) for who in ("pinion", "wheel"))
    if peak is Problems.FAILED or any(m is Problems.FAILED for m in mats):
        return None
    return Coupling(copy.deepcopy(g), mats)


def _regression(rg: dict) -> Regression:
    from geardesign.pzdn.startup import series

    if rg["C12"] is not None:
        if rg["pzdn_stiffness"] is not None or rg["drive_stiffness"] is not None:
            raise InputError.at("regression.C12", rg["C12"], "give C12, or pzdn_stiffness (with "
                                "drive_stiffness), not both")
        C, how = rg["C12"], "spec"
    elif rg["pzdn_stiffness"] is not None:
        C = (series(rg["pzdn_stiffness"], rg["drive_stiffness"])
             if rg["drive_stiffness"] is not None else rg["pzdn_stiffness"])
        how = S.SERIES if rg["drive_stiffness"] is not None else "spec"
    else:
        raise InputError(Problem("regression.pzdn_stiffness", "missing; give the PZDN "
                                 "stiffness pzdn_stiffness (and drive_stiffness in series), "
                                 "or the link stiffness C12"))
    return Regression(C, how, rg["T_ref_12"], rg["T_ref_23"], rg["pzdn_stiffness"],
                      rg["drive_stiffness"], tuple(rg["sweep"] or ()))


def _bounds(si: Startup, springs: tuple[Spring, ...]) -> None:
    from geardesign.pzdn.spring import design

    finger = {s.name: design(s.inp).C_finger for s in springs if s.name in si.spring_names}
    check_bounds(si, finger)


def _stages(spec: ValidatedSpec, problems: Problems) -> Inputs | None:
    d = spec.data
    top = problems.stage(_tables, d)
    springs = []
    if d["spring"] is not None:
        problems.stage(_names, d["spring"])
        springs = [problems.stage(spring, spec, j, sp, d["motor"])
                   for j, sp in enumerate(d["spring"])]
    names = list(dict.fromkeys(sp["name"] or f"spring {j + 1}"
                               for j, sp in enumerate(d["spring"] or ())))
    coupling = (_coupling(d["coupling_gear"], problems) if d["coupling_gear"] is not None
                else None)
    si = (problems.stage(startup, spec, d["startup"], names) if d["startup"] is not None
          else None)
    rg = (problems.stage(_regression, d["regression"]) if d["regression"] is not None
          else None)
    springs_ok = not any(s is Problems.FAILED for s in springs)
    if si is not None and si is not Problems.FAILED and springs_ok:
        problems.stage(_bounds, si, tuple(springs))
    if problems.found or any(x is Problems.FAILED for x in (top, si, rg)) or not springs_ok:
        return None
    mo = d["motor"]
    motor = (Motor(mo["speed"], mo["nominal_torque"], mo["power"], mo["breakaway_time"],
                   mo["windup_factor"]) if mo is not None else None)
    return Inputs(tuple(springs), motor, coupling, si, rg)


def _restore_echo_keys(spec: ValidatedSpec) -> None:
    """Put back the keys that a first :func:`read` left out of the echo (springs' keys not
    given, the start-up defaults the closed form does not use), with their schema defaults:
    the advice re-reads a copy of a spec already read."""
    from geardesign.core.schema import REQUIRED, Field
    from geardesign.pzdn.spec import SPRING, STARTUP

    tables = list(spec.data.get("spring") or ()), [spec.data.get("startup")]
    for schema, items in zip((SPRING, STARTUP), tables):
        for item in items:
            if item is None:
                continue
            for f in schema.fields:
                if isinstance(f, Field) and f.default is not REQUIRED:
                    item.setdefault(f.key, f.default)


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated spec; every independent input problem in one
    :class:`InputError`."""
    _restore_echo_keys(spec)
    problems = Problems()
    inputs = _stages(spec, problems)
    problems.raise_all()
    assert inputs is not None
    for sp in spec.data["spring"] or ():   # the echo leaves out keys not given (as for tables)
        for k in [k for k, v in sp.items() if v is None]:
            del sp[k]
    return inputs


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """:func:`read`'s input stages on a spec whose schema problems are reported."""
    _stages(spec, problems)
