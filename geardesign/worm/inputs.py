"""The spec of a worm pair read into typed inputs: the wheel material, the duty, the
options and the pair (given, ``mode = "check"``, or proposed, ``mode = "design"``).  Rules
across keys raise :class:`~geardesign.core.errors.InputError` naming the key and what is
allowed; independent stages are reported in one round (:class:`Problems`)."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.materials import worm_wheel
from geardesign.worm import design as D
from geardesign.worm import tables
from geardesign.worm.geometry import (
    WormPairInput,
    center_distance,
    shift_for_center_distance,
)
from geardesign.worm.kinematics import estimated_sliding_speed
from geardesign.worm.pair import Operation, Options, WheelProps
from geardesign.worm.spec import GEAR
from geardesign.worm.strength import (
    allowables,
    load_concentration_factor,
    required_center_distance,
    spectrum_factors,
)

X_AGREE = 1e-3       # |x − x(a_w)| accepted when both are given
RATIO_AGREE = 0.04   # |z2/z1 − u|/u accepted when all three are given
SHARE_AGREE = 1e-3   # |Σ t_i/t − 1|
_REQUIRED_IN_CHECK = tuple((k, GEAR.member(k)) for k in ("module", "diameter_factor", "z1", "z2"))


def _fmt(x: float, digits: int = 4) -> str:
    return f"{x:.{digits}f}".rstrip("0").rstrip(".")


def wheel_props(spec: ValidatedSpec) -> WheelProps:
    """The wheel material: library values, overridden by the values given."""
    w = spec.data["wheel"]
    name = w["material"]
    if name == "custom":
        if w["group"] is None:
            raise InputError(Problem("wheel.group", 'missing; required with material = "custom": '
                                     'one of "I", "II", "III" (material group)'))
        group, props, v_max = w["group"], {}, worm_wheel.GROUP_V_S_MAX[w["group"]]
        source = "given in the spec (material = \"custom\")"
    else:
        lib = worm_wheel.get(name)
        group = w["group"] or lib.group
        props = {"sigma_B": lib.sigma_B, "sigma_T": lib.sigma_T, "sigma_bu": lib.sigma_bu}
        v_max = lib.v_s_max
        source = f"library row {name}: {lib.source}"
    given = [key for key in ("group", "sigma_B", "sigma_T", "sigma_bu", "v_s_max", "sigma_HP",
                             "sigma_FP") if w[key] is not None]
    for key in ("sigma_B", "sigma_T", "sigma_bu"):
        if w[key] is not None:
            props[key] = w[key]
    if given and name != "custom":
        source += "; given in the spec: " + ", ".join(given)
    need = ("sigma_B", "sigma_T") if group in ("I", "II") else ("sigma_bu",)
    what = {"sigma_B": "tensile", "sigma_T": "yield", "sigma_bu": "bending"}
    problems = [Problem(f"wheel.{k}", f"missing; required for a group {group} wheel "
                        f"({what[k]} strength, MPa)")
                for k in need if props.get(k) is None]
    if problems:
        raise InputError(problems)
    sigma_H0 = spec.data["method"]["sigma_H0"]
    if sigma_H0 is not None and group == "I":
        raise InputError.at("method.sigma_H0", sigma_H0,
                            "applies only to group II and III wheels ([σ]_H = σ_H0 − k·v_s); "
                            "remove it for a group I (tin bronze) wheel")
    return WheelProps(name, group, props.get("sigma_B"), props.get("sigma_T"),
                      props.get("sigma_bu"), w["v_s_max"] if w["v_s_max"] is not None else v_max,
                      w["sigma_HP"], w["sigma_FP"], source, tuple(given))


def _peak_rule(T_peak: float | None, T2: float) -> None:
    """A given peak torque is not below the long-acting wheel torque ``T2``."""
    if T_peak is not None and T_peak < T2:
        raise InputError.at("load.peak_torque", T_peak,
                            f"smaller than load.torque2 = {_fmt(T2)} N·m; the peak "
                            f"must be >= the long-acting torque (or leave it out)")


def operation(spec: ValidatedSpec) -> Operation:
    ld = spec.data["load"]
    spectrum = ((1.0, 1.0),)
    if ld["spectrum"] is not None:
        spectrum = tuple((r["torque_ratio"], r["time_share"]) for r in ld["spectrum"])
        total = sum(s for _, s in spectrum)
        if abs(total - 1.0) > SHARE_AGREE:
            raise InputError(Problem("load.spectrum", f"the time shares add up to "
                                     f"{_fmt(total)}; they must add up to 1"))
    _peak_rule(ld["peak_torque"], ld["torque2"])
    return Operation(ld["torque2"], ld["speed1"], ld["peak_torque"], ld["life"], ld["reversing"],
                     spectrum)


def options(spec: ValidatedSpec) -> Options:
    d = spec.data
    fr, me, th, wo = d["friction"], d["method"], d["thermal"], d["worm"]
    if fr["coefficient"] is not None and fr["material_factor"] is not None:
        raise InputError.at("friction.material_factor", fr["material_factor"],
                            "applies only to the table's f'; remove it or remove "
                            "friction.coefficient")
    if th["fan_speed"] is not None and not th["fan"]:
        raise InputError.at("thermal.fan_speed", th["fan_speed"],
                            "applies only with thermal.fan = true; remove it or set fan = true")
    if th["oil_limit"] <= th["ambient"]:
        raise InputError.at("thermal.oil_limit", th["oil_limit"],
                            f"must be above thermal.ambient = {_fmt(th['ambient'])} °C")
    return Options(
        hardened=wo["surface"] == "hardened_ground", elastic_modulus=wo["elastic_modulus"],
        bearing_span=wo["bearing_span"], deflection_limit=wo["deflection_limit"],
        friction_level=fr["level"], friction_coefficient=fr["coefficient"],
        friction_factor=fr["material_factor"], bearing_efficiency=fr["bearing_efficiency"],
        profile_angle=math.radians(d["gear"]["profile_angle"]), cv_law=me["cv_law"],
        K_HL_max=me["K_HL_max"], sigma_H0=me["sigma_H0"], bending_formula=me["bending_formula"],
        dynamic_factor=me["dynamic_factor"], ambient=th["ambient"], oil_limit=th["oil_limit"],
        heat_transfer=th["heat_transfer"], housing_area=th["housing_area"],
        base_share=th["base_share"], fan=th["fan"], fan_speed=th["fan_speed"],
        fan_share=th["fan_share"])


def _pair_input(spec: ValidatedSpec, m: float, q: float, z1: int, z2: int, x: float,
                hardened: bool) -> WormPairInput:
    g, bw = spec.data["gear"], spec.data["basic_worm"]
    if q <= 2.0 * (bw["addendum_coef"] + bw["clearance_coef"]):
        raise InputError.at("gear.diameter_factor", q,
                            f"too small for the basic worm: the root diameter d_f1 = "
                            f"m·(q − 2(h_a* + c*)) must be > 0, so q > "
                            f"{_fmt(2.0 * (bw['addendum_coef'] + bw['clearance_coef']))}")
    return WormPairInput(m, q, z1, z2, x, g["worm_type"], math.radians(g["profile_angle"]),
                         bw["addendum_coef"], bw["clearance_coef"], bw["root_radius_coef"],
                         g["face_width"], g["worm_length"], hardened)


def _check_ratio(g: dict, z1: int, z2: int) -> None:
    u = g["ratio"]
    if u is not None and abs(z2 / z1 - u) / u > RATIO_AGREE:
        raise InputError(Problem("gear.ratio", f"does not match z2/z1 = {z2}/{z1} = "
                                 f"{_fmt(z2 / z1)} (more than 4 % apart); give z1 and z2 or "
                                 f"the ratio, or make them agree", u))


def check_mode_input(spec: ValidatedSpec, hardened: bool) -> tuple[WormPairInput, str]:
    """The pair of a ``mode = "check"`` spec, with the wheel shift resolved."""
    g = spec.data["gear"]
    missing = [(k, f.description, f.rule()) for k, f in _REQUIRED_IN_CHECK if g[k] is None]
    if missing:
        raise InputError([Problem(f"gear.{k}", f'missing; required with mode = "check": '
                                  f"{rule} ({desc})") for k, desc, rule in missing])
    m, q, z1, z2 = g["module"], g["diameter_factor"], g["z1"], g["z2"]
    _check_ratio(g, z1, z2)
    a_w, x = g["center_distance"], g["x"]
    if a_w is None:
        if x is None:
            g["x"] = 0.0
            spec.assumed.append("gear.x")
        return _pair_input(spec, m, q, z1, z2, g["x"], hardened), "given"
    x_a = shift_for_center_distance(a_w, m, q, z2)
    if x is not None:
        if abs(x - x_a) > X_AGREE:
            raise InputError(Problem(
                "gear.x", f"does not match center_distance = {_fmt(a_w)} mm, which needs "
                f"x = {x_a:.4f}; give x or center_distance, not both", x))
        return _pair_input(spec, m, q, z1, z2, x_a, hardened), "from center_distance"
    if abs(x_a) > 1.0:
        lo, hi = center_distance(m, q, z2, -1.0), center_distance(m, q, z2, 1.0)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs the wheel shift x = {x_a:.4f}, outside ±1 (GOST 19650-97); with m = "
            f"{_fmt(m)} mm, q = {_fmt(q)}, z2 = {z2} the centre distance must be "
            f"{_fmt(lo)} ... {_fmt(hi)} mm")
    return _pair_input(spec, m, q, z1, z2, x_a, hardened), "from center_distance"


@dataclass(frozen=True)
class DesignResult:
    z1: int
    z2: int
    z_source: str
    q0: float
    q_given: bool
    v_s_est: float
    sigma_HP: float
    K_HL: float | None
    C_v: float | None
    K: float
    K_beta: float
    theta: float
    a_w_req: float
    a_w: float
    rows: str
    m_calc: float
    proposal: D.Proposal


def design_mode_input(spec: ValidatedSpec, w: WheelProps, op: Operation,
                      o: Options) -> tuple[WormPairInput, DesignResult]:
    """Propose a_w, m, q, x for a ``mode = "design"`` spec (:mod:`.design`)."""
    g = spec.data["gear"]
    given = [k for k in ("module", "center_distance", "x") if g[k] is not None]
    if given:
        raise InputError([Problem(f"gear.{k}", 'is proposed by mode = "design"; remove it, or '
                                  'use mode = "check" to check a given pair', g[k])
                          for k in given])
    z1, z2, u = g["z1"], g["z2"], g["ratio"]
    if z1 is not None and z2 is not None:
        _check_ratio(g, z1, z2)
        how = "given"
    elif u is not None and z2 is None:
        z1 = z1 if z1 is not None else D.starts_for_ratio(u)
        z2 = round(u * z1)
        how = "from the ratio"
        if not 10 <= z2 <= 400:
            raise InputError(Problem("gear.ratio", f"gives z2 = round(u·z1) = {z2}, outside "
                                     f"10 ... 400; choose another ratio or z1", u))
    else:
        raise InputError(Problem("gear.ratio", 'missing; with mode = "design" give the ratio '
                                 "(z1 optional) or both z1 and z2"))
    q_given = g["diameter_factor"] is not None
    q0 = g["diameter_factor"] if q_given else D.default_q(z2)
    v_s = estimated_sliding_speed(op.n1, op.T2)
    sf = spectrum_factors(list(op.spectrum))
    N = 60.0 * op.n1 / (z2 / z1) * op.life
    al = allowables(w.group, o.hardened, v_s, sf.K_HE * N, sf.K_FE * N, op.reversing,
                    w.sigma_B, w.sigma_T, w.sigma_bu, o.cv_law, o.K_HL_max, o.sigma_H0)
    sigma_HP = w.sigma_HP if w.sigma_HP is not None else al.sigma_HP
    if sigma_HP <= 0.0:
        raise InputError.at(
            "wheel.material", w.name,
            f"[σ]_H = {sigma_HP:.1f} MPa at the estimated sliding speed {v_s:.2f} m/s: a group "
            f"{w.group} wheel cannot carry this drive; choose a group I bronze")
    theta = tables.theta(q0, z1)
    K_beta = load_concentration_factor(z2, theta, sf.X)
    K = K_beta * (o.dynamic_factor if o.dynamic_factor is not None else 1.0)
    a_req = required_center_distance(op.T2, K, q0, z2, sigma_HP)
    rows = (spec.data["design"] or {}).get("center_distance_rows", "first")
    a_w = D.round_up_center_distance(a_req, rows)
    if a_w is None:
        raise InputError.at("load.torque2", op.T2,
                            f"needs a centre distance of {a_req:.1f} mm ([σ]_H = "
                            f"{sigma_HP:.1f} MPa at the estimated sliding speed {v_s:.2f} m/s), "
                            f"beyond the GOST 2144-76 series (500 mm); use a stronger wheel "
                            f"material or split the drive")
    prop = D.choose_module(a_w, z2, q0, q_given)
    p = _pair_input(spec, prop.m, prop.q, z1, z2, prop.x, o.hardened)
    return p, DesignResult(z1, z2, how, q0, q_given, v_s, sigma_HP, al.K_HL, al.C_v, K, K_beta,
                           theta, a_req, a_w, rows, 2.0 * a_w / (q0 + z2), prop)


def _check_mode_inputs(spec: ValidatedSpec, o) -> None:
    """The pair of the check mode and how its shift was found (no [design] keys); ``None``
    when the options could not be read (their problem is reported)."""
    given = [k for k in spec.data["design"] or {} if f"design.{k}" not in spec.assumed]
    if given:
        raise InputError.at(f"design.{given[0]}", spec.data["design"][given[0]],
                            'applies only with mode = "design"; remove it or set mode = '
                            '"design"')
    return check_mode_input(spec, o.hardened) if o is not Problems.FAILED else None


@dataclass(frozen=True)
class Inputs:
    """Everything :func:`geardesign.worm.solve.solve` reads: the pair, how its shift was
    found (``"given"``, ``"from center_distance"``, ``"design"``), the duty, the wheel, the
    options, the design proposal (``mode = "design"``) and what the checks need: the
    self-locking requirement (``load.self_locking``) and whether gear.x was given."""

    pair: WormPairInput
    how: str
    op: Operation
    wheel: WheelProps
    options: Options
    design: DesignResult | None
    self_locking: str
    x_given: bool


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated worm spec; every independent problem in one
    :class:`InputError`."""
    problems = Problems()
    w, op, o = (problems.stage(f, spec) for f in (wheel_props, operation, options))
    if spec.data["mode"] == "design":
        problems.raise_all()    # the design needs the wheel, the duty and the options
        p, dres = design_mode_input(spec, w, op, o)
        how = "design"
    else:
        checked = problems.stage(_check_mode_inputs, spec, o)
        problems.raise_all()
        p, how = checked
        dres = None
    x_given = spec.data["gear"]["x"] is not None and "gear.x" not in spec.assumed
    return Inputs(p, how, op, w, o, dres, spec.data["load"]["self_locking"], x_given)


def with_torque2(inp: Inputs, T2: float) -> Inputs:
    """The inputs with the wheel torque ``T2`` [N·m] (the rules of :func:`operation` on
    the new duty: a given peak torque must not be below it)."""
    import dataclasses

    op = inp.op
    _peak_rule(op.T_peak, T2)
    return dataclasses.replace(inp, op=dataclasses.replace(op, T2=T2))
