"""Shafts of a drive analysed by the shaft calculator and their hubs by the connection
calculator.

A ``[[shaft]]`` with ``[[shaft.step]]`` is handed to :mod:`geardesign.shaft` with the loads
the drive already has: the mesh forces of its gears in two planes, the helical gear's axial
force and its couple F_a·r, the torques along the torque path (into the shaft +, out −; the
motor's torque enters and the output torque leaves at the coupling), supports at the
bearings (type from the bearing calculator) and the shaft's speed.  Axes: the drive's
(x, y, z = shaft axis) are the shaft calculator's (y, z, x) (docs/shaft.md, "API for other
calculators"); positions are shifted by the shaft's ``start``.

The mesh misalignment of the spur stages from the shafts' slopes is
:mod:`.misalignment`, the drive's tables and checks of the shafts :mod:`.shaft_report`.
"""

from __future__ import annotations

from dataclasses import field

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.registry import load_data
from geardesign.core.result import Result
from geardesign.drive.shafts import GearLoad, external_loads, gear_force
from geardesign.shaft import calculator as SC
from geardesign.gears.geometry import disc_mass
from geardesign.shaft.records import Load, Support
from geardesign.shaft.records import ShaftRecord as ShaftResult
from geardesign.shaft.solve import solve
from geardesign.shaft.spec import BEARING_TYPES

TOL = 1e-6


@dataclass
class GearOnShaft:
    index: int            # in the shaft's [[shaft.gear]]
    stage: int
    which: int            # 0: input member (pinion) of the stage, 1: output member
    load: GearLoad
    torque: float         # N·m on the shaft (+ in, − out)


@dataclass
class ShaftRun:
    idx: int
    key: str
    name: str
    start: float
    speed: float
    rotation: int
    gears: list
    r: ShaftResult
    result: Result
    connections: list = field(default_factory=list)   # dicts
    loads: list = field(default_factory=list)         # the shaft calculator's Load records
    E: float = 2.06e5                                  # MPa, of the shaft steel


def _named(exc: InputError, prefix: str) -> InputError:
    return InputError([Problem(f"{prefix}{p.key}" if p.key else prefix.rstrip(".: "),
                               p.message, p.value) for p in exc.problems])


def _fmt(x: float) -> str:
    return f"{x:g}"


def _span(steps: list, start: float) -> list[tuple[float, float, int]]:
    out, z = [], start
    for i, s in enumerate(steps):
        out.append((z, z + s["length"], i))
        z += s["length"]
    return out


def _steps_at(span, z: float) -> list[int]:
    """Steps whose extent holds z (two at a shoulder)."""
    L = span[-1][1] - span[0][0]
    tol = 1e-9 * max(1.0, L)
    return [i for a, b, i in span if a - tol <= z <= b + tol]


def _inside(span, z: float, key: str, what: str) -> None:
    a, b = span[0][0], span[-1][1]
    if not _steps_at(span, z):
        raise InputError.at(key, z, f"{what} lies outside the shaft steps: must be within "
                            f"{_fmt(a)}…{_fmt(b)} mm (start + the step lengths)")


def _bearing_data(br: Result) -> tuple[float | None, str, str]:
    """Bore d, type and designation of a bearing calculator result."""
    from geardesign.drive.stages import sections

    b = sections(br).get("bearing", {})
    return b.get("d"), b.get("type") or "", b.get("designation") or ""


def _coupling(sh: dict, span) -> float:
    if sh["coupling"] is not None:
        return sh["coupling"]
    a, b = span[0][0], span[-1][1]
    lo, hi = sorted((sh["bearing_a"], sh["bearing_b"]))
    return a if lo - a > b - hi else b


def _no_round_off(*values: float) -> tuple[float, ...]:
    """Round-off (cos 90° = 6e-17) is no load: the spec refuses magnitudes below 1e-6."""
    return tuple(v if abs(v) >= 1e-6 else 0.0 for v in values)


def shaft_run(k: int, sh: dict, gears: list[GearOnShaft], bearings: dict, speed: float,
              rotation: int, n_shafts: int, peak: float, stage_modules: dict,
              K_A: float = 1.0) -> ShaftRun:
    """Analyse shaft ``sh`` (the k-th [[shaft]]) with its gears; ``bearings`` maps "a"/"b"
    to the bearing calculator's result."""
    key = f"shaft[{k}]"
    idx = sh["index"]
    steps = sh["step"]
    start = sh["start"] if sh["start"] is not None else 0.0
    span = _span(steps, start)
    for j, g in enumerate(sh["gear"]):
        _inside(span, g["position"], f"{key}.gear[{j}].position", "the gear")
    seats = {side: _bearing_data(bearings[side]) for side in ("a", "b")}
    for side in ("a", "b"):
        z = sh[f"bearing_{side}"]
        _inside(span, z, f"{key}.bearing_{side}", f"bearing {side.upper()}")
        d, _, des = seats[side]
        if d is None:
            continue
        on = _steps_at(span, z)
        if not any(abs(steps[i]["diameter"] - d) <= TOL * d for i in on):
            i = on[0]
            raise InputError.at(
                f"{key}.step[{i}].diameter", steps[i]["diameter"],
                f"bearing {side.upper()} ({des}) at z = {_fmt(z)} mm sits on this step and its "
                f"bore is d = {_fmt(d)} mm: the bearing seat's diameter must equal the bore")
    loads = []
    for g in gears:
        (fx, fy, fz), (px, py, _) = gear_force(g.load, rotation)
        fx, fy, fz, px, py = _no_round_off(fx, fy, fz, px, py)
        mass = sh["gear"][g.index].get("mass")
        if mass is None:
            # a solid disc of the pitch diameter and the face width
            b = stage_modules.get(g.stage, (None, 0.0))[1]
            mass = disc_mass(2.0 * g.load.r, b)
        loads.append(Load(g.load.z - start, Fy=fx, Fz=fy, Fx=fz, torque=g.torque,
                          moment_y=-px * fz / 1e3 + 0.0, moment_z=-py * fz / 1e3 + 0.0,
                          mass=mass,
                          name=f"gear of stage {g.stage}",
                          module=stage_modules.get(g.stage, (None, 0.0))[0]))
    for j, (el, pl) in enumerate(zip(sh.get("load") or [], external_loads(sh))):
        _inside(span, el["position"], f"{key}.load[{j}].position", "the load")
        (fx, fy, fz), _ = gear_force(pl, rotation)
        fx, fy, fz = _no_round_off(fx, fy, fz)
        loads.append(Load(el["position"] - start, Fy=fx, Fz=fy, Fx=fz,
                          mass=el["mass"] or 0.0, name=el["name"] or f"load {j + 1}"))
    T_rest = -sum(g.torque for g in gears)
    if (idx == 1 or idx == n_shafts) and abs(T_rest) > 1e-9 * max(
            [abs(g.torque) for g in gears] + [1.0]):
        zc = _coupling(sh, span)
        _inside(span, zc, f"{key}.coupling", "the coupling")
        loads.append(Load(zc - start, torque=T_rest, name="coupling"))
    supports = []
    for side in ("a", "b"):
        _, typ, _ = seats[side]
        supports.append(Support(sh[f"bearing_{side}"] - start, sh.get(f"stiffness_{side}"),
                                typ if typ in BEARING_TYPES else "other",
                                axial=sh["fixed"] == side, name=side.upper()))
    strength = {k_: v for k_, v in (sh["strength"] or {}).items() if v is not None}
    strength.setdefault("peak_factor", peak)
    data = {"kind": "shaft", "title": sh["name"] or f"shaft {idx}",
            "shaft": {"speed": speed, **strength},
            "material": {k_: v for k_, v in (sh["material"] or {"grade": "45"}).items()
                         if v is not None},
            "step": [{k_: v for k_, v in s.items() if v is not None} for s in steps],
            "load": [{k_: v for k_, v in (("name", ld.name), ("position", ld.position),
                                          ("Fy", ld.Fy), ("Fz", ld.Fz), ("Fx", ld.Fx),
                                          ("torque", ld.torque), ("moment_y", ld.moment_y),
                                          ("moment_z", ld.moment_z), ("mass", ld.mass),
                                          ("module", ld.module)) if v is not None}
                     for ld in loads],
            "support": [{k_: v for k_, v in (("name", s.name), ("position", s.position),
                                             ("type", s.type), ("axial", s.axial),
                                             ("stiffness", s.stiffness)) if v is not None}
                        for s in supports]}
    try:
        _, spec = load_data(data, key)
        m = SC.model(spec)
    except InputError as exc:
        raise _named(exc, f"{key}.") from None
    try:
        r = solve(m)
    except InputError as exc:       # the beam cannot be solved: its step or support named
        raise _named(exc, f"{key}.") from None
    result = SC.report(spec, m, r)
    run = ShaftRun(idx, key, sh["name"] or f"shaft {idx}", start, speed, rotation, gears, r,
                   result, loads=loads, E=m.material.E)
    run.connections = [_connection(run, sh, j, c, m.material, steps, span, K_A)
                       for j, c in enumerate(sh["key"] or [])]
    return run


OWN_KEYS = ("type", "position", "hub_length", "name", "application_factor")


def _connection_problem(p: Problem, key: str, typ: str, filled: dict) -> Problem:
    """A problem of the connection spec the drive built, on the drive's own key: a value
    the drive filled in is named by the drive key it comes from (the step's diameter, the
    hub length, the shaft's material), the load by the shaft's loads it is derived from."""
    own = ", ".join(OWN_KEYS)
    sub = p.key.split(".", 1)[1] if p.key.startswith(typ + ".") else None
    if sub in filled:
        source = filled[sub]
        if source.endswith(("diameter", "hub_length")):
            return Problem(source, p.message, p.value)
        return Problem(f"{key}.{sub}", f"derived from {source}: {p.message}", p.value)
    if sub is not None:
        return Problem(f"{key}.{sub}", p.message + (f"; or the drive's {own}" if
                       p.message.startswith("unknown key") else ""), p.value)
    if p.key.startswith("load."):
        return Problem(f"{key}: {p.key}", f"derived from the shaft's loads (the torque "
                       f"through the connection): {p.message}", p.value)
    return Problem(f"{key}: {p.key}", p.message, p.value)


def _connection(run: ShaftRun, sh: dict, j: int, c: dict, material, steps, span,
                K_A: float) -> dict:
    key = f"{run.key}.key[{j}]"
    z = c["position"]
    _inside(span, z, f"{key}.position", "the hub")
    extra = {k: v for k, v in c.items() if k not in OWN_KEYS}
    L_hub = c["hub_length"]
    length = extra.get("length")
    if isinstance(length, (int, float)) and not isinstance(length, bool) and length > L_hub:
        what = {"key": "key", "spline": "engaged spline", "fit": "fit"}[c["type"]]
        raise InputError.at(f"{key}.length", length,
                            f"the {what} is longer than its hub (hub_length = "
                            f"{_fmt(L_hub)} mm): give length <= {_fmt(L_hub)}")
    r = run.r
    x = z - run.start
    i = min(range(len(r.x)), key=lambda n: abs(r.x[n] - x))
    T = max(abs(r.T[i]), abs(r.T[i - 1]) if i > 0 else 0.0)
    if T <= 0.0:
        raise InputError.at(f"{key}.position", z, "no torque passes the shaft here: put the "
                            "connection at a gear or at the coupling")
    n_step = _steps_at(span, z)[0]
    d = steps[n_step]["diameter"]
    typ = c["type"]
    table = dict(extra)
    # keys of the connection spec the drive fills in, by the drive key they come from
    step_d, hub = f"{run.key}.step[{n_step}].diameter", f"{key}.hub_length"
    filled = {"key": {"shaft_diameter": step_d, "hub_length": hub},
              "spline": {"length": hub},
              "fit": {"diameter": step_d, "length": hub,
                      "shaft_yield": f"{run.key}.material"}}[typ]
    filled = {k: v for k, v in filled.items() if k not in extra}
    if typ == "key":
        table.setdefault("shaft_diameter", d)
        table["hub_length"] = L_hub
    elif typ == "spline":
        table.setdefault("length", L_hub)
    else:
        table.setdefault("diameter", d)
        table.setdefault("length", L_hub)
        table.setdefault("shaft_yield", material.sigma_T)
    data = {"kind": "connection",
            "title": c["name"] or f"{run.name}, {typ} at z = {_fmt(z)} mm",
            "load": {"torque": T, "application_factor": c["application_factor"] or K_A},
            typ: table}
    try:
        calc, spec = load_data(data, key)
        res = calc.compute(spec)
    except InputError as exc:
        raise InputError([_connection_problem(p, key, typ, filled)
                          for p in exc.problems]) from None
    return dict(j=j, name=c["name"] or f"{typ} at z = {_fmt(z)} mm", type=typ, z=z, d=d, T=T,
                K_A=c["application_factor"] or K_A, result=res)
