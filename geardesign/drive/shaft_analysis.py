"""Shafts of a drive analysed by the shaft calculator, their hubs by the connection
calculator, and the mesh misalignment of the spur stages from the shafts' slopes.

A ``[[shaft]]`` with ``[[shaft.step]]`` is handed to :mod:`geardesign.shaft` with the loads
the drive already has: the mesh forces of its gears in two planes, the helical gear's axial
force and its couple F_a·r, the torques along the torque path (into the shaft +, out −; the
motor's torque enters and the output torque leaves at the coupling), supports at the
bearings (type from the bearing calculator) and the shaft's speed.  Axes: the drive's
(x, y, z = shaft axis) are the shaft calculator's (y, z, x) (docs/shaft.md, "API for other
calculators"); positions are shifted by the shaft's ``start``.

Mesh misalignment of a spur stage ([ISO6336-1] 7.6: f_sh is the equivalent misalignment in
the plane of action caused by the deformation of the shafts): the slopes of the pinion and
the wheel shaft at their gears, θ = (dw_x/dz, dw_y/dz), give the relative slope
Δθ = θ_pinion − θ_wheel; its component along the line of action in the transverse plane
(the direction n of the transverse mesh force, along which the flanks approach each other,
as F_β is measured) times the face width is

.. math:: f_{sh} = |Δθ · n| \\, b \\quad [µm].

To it adds the twist of the gear bodies under the torque that passes them
(:func:`face_twist`: the part of f_sh that the standard's own formula carries in its torsion
term, [ISO6336-1] 7.6.3); the sum of the signed parts is f_sh.

It is passed to the stage's ISO 6336 rating as ``iso.f_sh``; K_Hβ then follows by method C
([ISO6336-1] 7.6.1, :mod:`geardesign.spur.strength.iso6336.part1`).
"""

from __future__ import annotations

import copy
import math
from dataclasses import field

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.registry import load_data
from geardesign.core.result import DataTable, Result, check
from geardesign.drive.shafts import GearLoad, external_loads, gear_force
from geardesign.shaft import calculator as SC
from geardesign.gears.geometry import disc_mass
from geardesign.shaft.records import ARCMIN, Load, Support
from geardesign.shaft.records import ShaftRecord as ShaftResult
from geardesign.shaft.solve import analyse
from geardesign.shaft.spec import BEARING_TYPES

ISO_METHOD = "ISO 6336:2019"
F_SH_MAX = 1000.0     # µm, the largest iso.f_sh of the spur spec
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
    for side in ("a", "b"):
        z = sh[f"bearing_{side}"]
        _inside(span, z, f"{key}.bearing_{side}", f"bearing {side.upper()}")
        d, _, des = _bearing_data(bearings[side])
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
        _, typ, _ = _bearing_data(bearings[side])
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
        r = analyse(m["steps"], m["loads"], m["supports"], m["material"], m["options"])
    except InputError as exc:       # the beam cannot be solved: its step or support named
        raise _named(exc, f"{key}.") from None
    result = SC.report(spec, m, r)
    run = ShaftRun(idx, key, sh["name"] or f"shaft {idx}", start, speed, rotation, gears, r,
                   result, loads=loads, E=m["material"].E)
    run.connections = [_connection(run, sh, j, c, m["material"], steps, span, K_A)
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


def _utilisation(res: Result) -> tuple[float | None, str]:
    """The largest utilisation of the error checks of a result (≤ 1 passes): value/limit
    for an upper bound, limit/value for a lower bound (a safety factor)."""
    worst, of = None, ""
    for c in res.checks:
        if c.severity != "error" or c.value is None or c.limit is None or not c.limit:
            continue
        upper = c.passed == (c.value <= c.limit)
        u = c.value / c.limit if upper else (c.limit / c.value if c.value else math.inf)
        if worst is None or u > worst:
            worst, of = u, c.code
    return worst, of


# ------------------------------------------------------------------ mesh misalignment


POISSON = 0.3    # steel


def face_twist(T_left: float, T_right: float, b: float, d: float, r_b: float,
               E: float) -> float:
    """Separation of the mating flanks at the +z end of the face minus the −z end that the
    twist of a gear body gives [µm].

    .. math:: δ_{tw} = -\\operatorname{sgn}(T_R - T_L) \\, r_b
              \\frac{(T_L + T_R)/2 \\cdot b}{G \\, J_p},\\qquad J_p = \\frac{π d^4}{32},
              \\quad G = \\frac{E}{2(1 + ν)}

    Saint-Venant torsion of a solid round body ([Roark] table 10.1 case 1: θ = T·l/(G·J)):
    the torque along the shaft (signed in the sense of rotation, the torque of everything
    left of the section: T_L just left of the face, T_R = T_L + T_g just right of it, T_g
    the gear's own torque, + into the shaft, − out of it) falls or rises linearly across the
    face width as the tooth load takes it off uniformly, so the section at the +z end turns
    against the −z end by ∫T/(G·J)·dz = (T_L + T_R)/2·b/(G·J).  Turning a section in the
    sense of the mesh torque on the gear (sgn T_g) moves its flank along the line of action
    away from the mate by r_b per radian.  ``T_left``, ``T_right`` [N·m], ``b``, ``d`` (the
    body's diameter: the working pitch diameter, as d1 in the torsion term of [ISO6336-1]
    eq. (58)), ``r_b`` (base radius) [mm], ``E`` [MPa], ν = 0.3.  A torque that enters at
    the −z end (T_L = T, T_R = 0, T_g = −T) gives δ = +r_b·T·b/(2GJ): the flanks close up at
    the end where the torque enters, as load distribution measurements show.

    >>> round(face_twist(1000.0, 0.0, 60.0, 60.0, 28.19, 2.06e5), 3)
    8.389
    """
    T_g = T_right - T_left
    if T_g == 0.0:
        return 0.0
    G = E / (2.0 * (1.0 + POISSON))
    J = math.pi * d ** 4 / 32.0
    return -math.copysign(1.0, T_g) * r_b * 0.5 * (T_left + T_right) * 1e3 * b / (G * J) * 1e3


def _twist(run: ShaftRun, n: int, b: float) -> float:
    """:func:`face_twist` of the n-th gear of ``run`` (its torque path from the shaft's
    loads)."""
    g = run.gears[n]
    z = g.load.z - run.start
    T_left = sum(ld.torque for ld in run.loads if ld.position < z - TOL)
    T_right = T_left + g.torque
    F_t, F_r = g.load.F_t, g.load.F_r
    r_b = g.load.r * abs(F_t) / math.hypot(F_t, F_r) if F_t or F_r else g.load.r
    return face_twist(T_left, T_right, b, 2.0 * g.load.r, r_b, run.E)


def misalignment(runs_by_shaft: dict, stage_runs: list) -> dict:
    """f_sh [µm] of every spur stage whose pinion and wheel shafts were analysed:
    ``{stage: dict(f_sh, b, dtheta, f_bend, f_twist)}`` (f_bend = Δθ·n·b and f_twist the
    twist of both gear bodies, signed: flank separation at the +z end minus the −z end;
    f_sh = |f_bend + f_twist|)."""
    out = {}
    for i, sr in enumerate(stage_runs, 1):
        if sr.kind != "spur":
            continue
        pin = runs_by_shaft.get(i)
        whl = runs_by_shaft.get(i + 1)
        if pin is None or whl is None:
            continue
        gp = next(((n, g) for n, g in enumerate(pin.gears) if g.stage == i and g.which == 0),
                  None)
        gw = next(((n, g) for n, g in enumerate(whl.gears) if g.stage == i and g.which == 1),
                  None)
        if gp is None or gw is None:
            continue
        tp, tw = pin.r.loads[gp[0]], whl.r.loads[gw[0]]
        (fx, fy, _), _ = gear_force(gp[1].load, pin.rotation)
        norm = math.hypot(fx, fy)
        if norm == 0.0:
            continue
        nx, ny = fx / norm, fy / norm
        d_n = (tp.slope_y - tw.slope_y) * nx + (tp.slope_z - tw.slope_z) * ny
        b = sr.inputs["gear"]["face_width"]
        f_bend = d_n * b * 1e3
        f_twist = _twist(pin, gp[0], b) + _twist(whl, gw[0], b)
        out[i] = dict(f_sh=abs(f_bend + f_twist), b=b, dtheta=d_n, f_bend=f_bend,
                      f_twist=f_twist)
    return out


def _rating(run, name: str) -> dict | None:
    """The values of a spur stage's rating by ``name`` (None when not rated by it)."""
    r = run.record.ratings.get(name)
    return None if r is None else r.v


def _iso_K_Hbeta(data: dict, sr, duty, where: str, f_sh: float) -> float:
    """K_Hβ of ISO 6336-1 method C of a stage rated to GOST, with ``f_sh`` (informative):
    the ISO rating record of the stage spec (with the drive's loads; validated as a GOST
    stage in the passes already), no report."""
    from geardesign.drive.spur_stage import _spur_loads
    from geardesign.spur.strength.iso6336.report import iso_rating

    d = _spur_loads(data, sr.T_in, sr.n_in, duty, where)
    iso = d.get("iso")
    if not isinstance(iso, dict):
        iso = d["iso"] = {}
    iso["f_sh"] = f_sh
    opts = d.setdefault("options", {})
    opts.pop("methods", None)
    opts["method"] = ISO_METHOD
    d["load"].pop("regime", None)        # the GOST regime: not read by the ISO rating
    _, spec = load_data(d, where)
    return iso_rating(spec).v["K_Hbeta"]


def rate_with_misalignment(mis: dict, stages: list, stage_runs: list, duty, run_spur) -> list:
    """Rate the spur stages with ``iso.f_sh`` from the shafts: an ISO 6336 stage is rerun
    with it (its result replaced), a GOST stage gets the K_Hβ of ISO 6336-1 method C next
    to its chart value (informative).  Rows of the K_Hβ table."""
    rows = []
    for i, m in mis.items():
        sr = stage_runs[i - 1]
        where, _, data, _ = stages[i - 1]
        iso_before = _rating(sr, ISO_METHOD)
        gost = _rating(sr, "GOST 21354-87")
        f_sh = min(m["f_sh"], F_SH_MAX)
        capped = f" (capped at {F_SH_MAX:g} µm)" if m["f_sh"] > F_SH_MAX else ""
        K_new, note = None, ""
        if iso_before is not None:
            d = copy.deepcopy(data)
            iso = d.get("iso")
            if not isinstance(iso, dict):
                iso = d["iso"] = {}
            iso["f_sh"] = f_sh
            new = run_spur(d, sr.T_in, sr.n_in, duty, sr.efficiency, where)
            K_new = _rating(new, ISO_METHOD)["K_Hbeta"]
            new.result.checks.append(check(
                "F_SH_FROM_SHAFTS", False, "info",
                f"the drive sets iso.f_sh = {f_sh:.3g} µm from the slopes of the analysed "
                f"shafts and the twist of the gears{capped} (the formula of ISO 6336-1 7.6.3 gives "
                f"{iso_before['f_sh']:.3g} µm)", "", f_sh, None, "drive"))
            sr.result, sr.record = new.result, new.record
            sr.margin, sr.margin_of = new.margin, new.margin_of
            rows.append(dict(stage=i, method="ISO 6336:2019", b=m["b"],
                             f_sh_formula=iso_before["f_sh"], f_bend=m["f_bend"],
                             f_twist=m["f_twist"], f_sh=m["f_sh"],
                             K_Hbeta_before=iso_before["K_Hbeta"], K_Hbeta_shafts=K_new,
                             note="stage rated with f_sh from the shafts" + capped))
        if gost is not None:
            if K_new is None:
                try:
                    K_new = _iso_K_Hbeta(data, sr, duty, where, f_sh)
                except InputError as exc:
                    note = f"ISO 6336 not applicable: {exc.problems[0].message}"
            rows.append(dict(stage=i, method="GOST 21354-87", b=m["b"], f_sh_formula=None,
                             f_bend=m["f_bend"], f_twist=m["f_twist"], f_sh=m["f_sh"], K_Hbeta_before=gost["K_Hbeta"],
                             K_Hbeta_shafts=K_new,
                             note=note or "informative: ISO 6336-1 method C with f_sh; the "
                                          "GOST rating keeps its chart value" + capped))
    return rows


# ------------------------------------------------------------------ report


def report(res: Result, shaft_runs: list, kh_rows: list, mis: dict) -> None:
    """Summary tables, nested reports and checks of the analysed shafts and connections."""
    res.methods.append("shaft calculator")
    if any(sr.connections for sr in shaft_runs):
        res.methods.append("connection calculator")
    rows, gear_rows, conn_rows = [], [], []
    for sr in shaft_runs:
        r = sr.r
        c, cs = r.critical, r.critical_static
        lim = sr.result.inputs["shaft"]
        A, B = r.supports
        rows.append(dict(shaft=sr.idx, name=sr.name, critical=c.label if c else None,
                         z_critical=c.x + sr.start if c else None, S=c.S if c else None,
                         S_min=lim["S_min"], S_static=cs.S_static if cs else None,
                         S_static_min=lim["S_static_min"], slope_A=A.slope / ARCMIN,
                         slope_B=B.slope / ARCMIN, n_cr=r.n_cr, n_cr_ratio=r.n_cr / sr.speed,
                         verdict=sr.result.verdict))
        for g, p in zip(sr.gears, r.loads):
            gear_rows.append(dict(shaft=sr.idx, stage=g.stage,
                                  member="input (pinion)" if g.which == 0 else "output (wheel)",
                                  z=g.load.z, w=p.w * 1e3, slope=p.slope / ARCMIN,
                                  slope_x=p.slope_y / ARCMIN, slope_y=p.slope_z / ARCMIN))
        for cn in sr.connections:
            u, of = _utilisation(cn["result"])
            conn_rows.append(dict(shaft=sr.idx, connection=cn["name"], type=cn["type"],
                                  z=cn["z"], d=cn["d"], T=cn["T"], K_A=cn["K_A"],
                                  utilisation=u, of=of, verdict=cn["result"].verdict))
    res.tables.append(DataTable("shafts", "Shafts: strength, bearing slopes, critical speed "
                                "(shaft calculator)", [
        ("shaft", "shaft", None), ("name", "name", None),
        ("critical", "critical section", None), ("z_critical", "z", "mm"),
        ("S", "S", "-"), ("S_min", "[S]", "-"), ("S_static", "S_T", "-"),
        ("S_static_min", "[S_T]", "-"), ("slope_A", "θ_A", "arcmin"),
        ("slope_B", "θ_B", "arcmin"), ("n_cr", "n_cr", "min^-1"),
        ("n_cr_ratio", "n_cr/n", "-"), ("verdict", "verdict", None)], rows))
    res.tables.append(DataTable("shaft_gears", "Shafts: deflection and slope at the gears", [
        ("shaft", "shaft", None), ("stage", "stage", None), ("member", "member", None),
        ("z", "z", "mm"), ("w", "w", "µm"), ("slope", "θ", "arcmin"),
        ("slope_x", "θ_x", "arcmin"), ("slope_y", "θ_y", "arcmin")], gear_rows))
    if conn_rows:
        res.tables.append(DataTable("connections", "Shaft-hub connections (connection "
                                    "calculator)", [
            ("shaft", "shaft", None), ("connection", "connection", None),
            ("type", "type", None), ("z", "z", "mm"), ("d", "d", "mm"), ("T", "T", "N·m"),
            ("K_A", "K_A", "-"), ("utilisation", "worst use", "-"), ("of", "of", None),
            ("verdict", "verdict", None)], conn_rows))
    if kh_rows:
        res.tables.append(DataTable("face_load", "K_Hβ: chart/standard formula vs from the "
                                    "shaft deflections", [
            ("stage", "stage", None), ("method", "rating", None), ("b", "b", "mm"),
            ("f_sh_formula", "f_sh formula", "µm"), ("f_bend", "bending", "µm"),
            ("f_twist", "twist", "µm"), ("f_sh", "f_sh shafts", "µm"),
            ("K_Hbeta_before", "K_Hβ chart/formula", "-"),
            ("K_Hbeta_shafts", "K_Hβ from shafts", "-"), ("note", "note", None)], kh_rows))
    for sr in shaft_runs:
        res.parts.append(("shaft_reports", f"{sr.name}: shaft analysis", sr.result))
        failed = sr.result.failed
        warn = [c.code for c in sr.result.warnings]
        c = sr.r.critical
        res.checks.append(check(
            f"SHAFT_{sr.idx}", not failed, "error",
            f"{sr.name} fails (positions x from the shaft's left end: z = x "
            f"{'+' if sr.start >= 0 else '−'} {abs(sr.start):g} mm): "
            + "; ".join(f"{x.code}: {x.message}" for x in failed),
            f"{sr.name}: fatigue S = {c.S:.2f} at {c.label}, n_cr/n = "
            f"{sr.r.n_cr / sr.speed:.1f}" + (f" (warnings: {', '.join(warn)})" if warn else ""),
            c.S if c and math.isfinite(c.S) else None,
            sr.result.inputs["shaft"]["S_min"], "shaft calculator"))
        for cn in sr.connections:
            res.parts.append(("connection_reports", f"{sr.name}, {cn['name']}", cn["result"]))
            failed = cn["result"].failed
            u, of = _utilisation(cn["result"])
            res.checks.append(check(
                f"CONNECTION_{sr.idx}_{cn['j'] + 1}", not failed, "error",
                f"{sr.name}, {cn['name']} (T = {cn['T']:.0f} N·m) fails: "
                + "; ".join(f"{x.code}: {x.message}" for x in failed),
                f"{sr.name}, {cn['name']} (T = {cn['T']:.0f} N·m): worst use "
                f"{u:.2f} ({of})" if u is not None else f"{sr.name}, {cn['name']} passes",
                u, 1.0, "connection calculator"))
    for i, m in mis.items():
        if m["f_sh"] > F_SH_MAX:
            res.checks.append(check(
                f"MISALIGNMENT_{i}", False, "warning",
                f"stage {i}: the shafts tilt the gears against each other by "
                f"{m['f_sh']:.0f} µm over the face width (more than {F_SH_MAX:g} µm, rated "
                f"with {F_SH_MAX:g}): stiffen the shafts or bring the bearings closer to "
                f"the gears", "", m["f_sh"], F_SH_MAX, "drive"))
