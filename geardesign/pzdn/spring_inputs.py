"""One ``[[spring]]`` table read into a typed, frozen :class:`Spring`: the allowables, the
wire (d_min rounded up to the series when not given), the coil diameter and the method-A
wind-up angle; every rule across its keys raises a one-line :class:`InputError`.
Defaults that depend on other keys are written into the spec's echo."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.pzdn import spring as SP
from geardesign.pzdn import tables


def fmt(x: float, digits: int = 4) -> str:
    """A number for a message: at most ``digits`` decimals, no trailing zeros."""
    return f"{x:.{digits}f}".rstrip("0").rstrip(".")


def assume(spec: ValidatedSpec, table: dict, key: str, path: str, value) -> None:
    """Fill in a default the calculation chose and echo it as assumed."""
    table[key] = value
    if path not in spec.assumed:
        spec.assumed.append(path)


@dataclass(frozen=True)
class Spring:
    """A spring ready to be designed (:func:`geardesign.pzdn.spring.design`), with what
    the report says about where its values come from."""

    key: str                     # "spring[0]"
    number: int                  # 1-based
    name: str
    named: bool                  # the spec gave the name
    inp: SP.SpringInput
    tau_allow: float | None      # [τ] at d [MPa]
    tau_given: bool
    ratio_set: bool              # [σ]/[τ] given, or assumed with a given [τ]
    sigma_source: str
    steel: object | None         # library spring steel
    phi_kin: float | None        # motor-start wind-up [rad]
    phi_req: float | None        # required wind-up [rad]
    phi_leg_req: float | None    # leg share of it [rad]
    outer: bool                  # coil_diameter is the outer diameter
    d_in_series: bool
    E_assumed: bool
    d_given: bool
    design_angle: float | None   # given [deg]
    coils_given: bool
    pitch_assumed: bool
    index_and_diameter: bool     # both the index and the coil diameter given
    slot_arms: tuple[float, float] | None
    target_stiffness: float | None
    ends_fixed_axially: bool
    arbor_diameter: float | None


def _allowables(sp: dict, key: str, steel, spec: ValidatedSpec):
    """([σ] as a function of d, [τ] as a function of d or None, a word on the source)."""
    lim = tables.limits()
    if sp["sigma_allow"] is not None:
        if sp["sigma_over_tau"] is not None:
            raise InputError.at(f"{key}.sigma_over_tau", sp["sigma_over_tau"],
                                "give sigma_allow or sigma_over_tau (× tau_allow), not both")
        tau = sp["tau_allow"]
        return (lambda d: sp["sigma_allow"]), (lambda d: tau) if tau else None, "spec"
    if sp["tau_allow"] is not None:
        if sp["sigma_over_tau"] is None:
            assume(spec, sp, "sigma_over_tau", f"{key}.sigma_over_tau",
                   lim["sigma_over_tau_default"])
        r, tau = sp["sigma_over_tau"], sp["tau_allow"]
        return (lambda d: r * tau), (lambda d: tau), "[σ] = [σ]/[τ]·[τ] (thesis eq. (1))"
    if steel is not None:
        from geardesign.materials import spring_steel

        if sp["sigma_over_tau"] is not None:
            r = sp["sigma_over_tau"]
            return (lambda d: r * steel.allowable_shear(d)), steel.allowable_shear, \
                "[σ]/[τ] × library [τ]"
        return (lambda d: spring_steel.bending_allowable(steel, d)), steel.allowable_shear, \
            "library, [τ]/0.577 (Shigley §10-12)"
    raise InputError(Problem(f"{key}.sigma_allow", "missing; give the allowable bending "
                             "stress sigma_allow, or tau_allow (with sigma_over_tau, default "
                             "1.5), or a material from the library"))


def _wire(T: float, sp: dict, sigma_of, d_mean) -> tuple[float, bool]:
    """The wire diameter: given, or d_min with k(c) and [σ](d) (a fixed point) rounded up
    to the standard series."""
    if sp["wire_diameter"] is not None:
        return sp["wire_diameter"], True
    c_in = sp["index"]
    d = (32.0 * T / (math.pi * sigma_of(1.0))) ** (1.0 / 3.0)
    for _ in range(60):
        Dm = d_mean(d)
        c = c_in if c_in is not None else (Dm / d if Dm and Dm > d else 4.0)
        d = SP.min_wire_diameter(T, SP.curvature_factor(c, sp["curvature_factor"]),
                                 sigma_of(d))
    return SP.standard_wire(d, tables.wire_series())


def _arms(key: str, sp: dict, D: float) -> None:
    for arm_key in ("leg_arm", "leg2_arm"):
        arm = sp[arm_key]
        if arm is not None and arm <= D / 2.0:
            raise InputError.at(f"{key}.{arm_key}", arm,
                                f"must exceed the coil radius D/2 = {fmt(D / 2)} mm: the "
                                f"arm is measured from the spring axis to the load point")
    if sp["slot_arms"] is not None:
        lo, hi = sp["slot_arms"]
        if not lo < hi:
            raise InputError.at(f"{key}.slot_arms", sp["slot_arms"],
                                "give [least arm, largest arm] with least < largest")
        if lo <= D / 2.0:
            raise InputError.at(f"{key}.slot_arms", sp["slot_arms"],
                                f"the slot must lie outside the coil: least arm > D/2 = "
                                f"{fmt(D / 2)} mm")
        if sp["leg_arm"] is not None and not lo <= sp["leg_arm"] <= hi:
            raise InputError.at(f"{key}.leg_arm", sp["leg_arm"],
                                f"the finger must sit in its slot: {fmt(lo)} … {fmt(hi)} mm")


def _coil_given(key: str, sp: dict) -> None:
    if sp["index"] is None and sp["coil_diameter"] is None:
        raise InputError(Problem(f"{key}.coil_diameter", "missing; give the coil diameter "
                                 "or the spring index (index), or both"))


def _coils_given(key: str, sp: dict, motor: dict | None) -> None:
    if sp["coils"] is None and sp["design_angle"] is None and motor is None:
        raise InputError(Problem(f"{key}.coils", "missing; give the number of working coils, "
                                 "or [motor] (or design_angle) to compute it from the wind-up "
                                 "angle (method A)"))


def _diameter(key: str, sp: dict, d: float) -> float:
    """The mean coil diameter D for the wire d."""
    D_in, outer = sp["coil_diameter"], sp["diameter_basis"] == "outer"
    if D_in is None:
        return sp["index"] * d
    limit = 2.0 * d if outer else d
    if D_in <= limit:
        what = ("2·d", "an outer") if outer else ("the wire diameter d", "a mean")
        raise InputError.at(f"{key}.coil_diameter", D_in,
                            f"must exceed {what[0]} = {fmt(limit)} mm ({what[1]} coil "
                            f"diameter up to it leaves no bore); increase it or use a "
                            f"thinner wire")
    return D_in - d if outer else D_in


def _pitch(key: str, sp: dict, d: float) -> None:
    if sp["pitch"] is not None and sp["pitch"] < d:
        raise InputError.at(f"{key}.pitch", sp["pitch"],
                            f"smaller than the wire diameter d = {fmt(d)} mm: the coils "
                            f"would overlap; give pitch >= d (= d: close-wound)")


def spring(spec: ValidatedSpec, j: int, sp: dict, motor: dict | None) -> Spring:
    """The spring ``spring[j]`` (``motor``: the [motor] table, for method A).  Its rules
    are checked in independent groups (the allowables, the coil diameter given, the coils
    given; then the coil diameter, the pitch, the arms), so that each mistake of one
    spring is reported in the same round."""
    from geardesign.materials import spring_steel

    key = f"spring[{j}]"
    lim = tables.limits()
    name = sp["name"] or f"spring {j + 1}"
    steel = spring_steel.get(sp["material"]) if sp["material"] is not None else None
    E_assumed = sp["E"] is None
    if E_assumed:
        E = spring_steel.elastic_modulus(sp["material"]) if steel is not None else None
        assume(spec, sp, "E", f"{key}.E", E if E is not None else lim["E_default"])
    E = sp["E"]
    problems = Problems()
    allow = problems.stage(_allowables, sp, key, steel, spec)
    problems.stage(_coil_given, key, sp)
    problems.stage(_coils_given, key, sp, motor)
    if problems.found:
        problems.raise_all()
    sigma_of, tau_of, sigma_source = allow
    T = sp["torque"] * 1000.0
    c_in, D_in = sp["index"], sp["coil_diameter"]
    outer = sp["diameter_basis"] == "outer"

    def d_mean(d: float) -> float | None:
        if D_in is None:
            return None
        return D_in - d if outer else D_in

    d, in_series = _wire(T, sp, sigma_of, d_mean)
    D = problems.stage(_diameter, key, sp, d)
    problems.stage(_pitch, key, sp, d)
    if D is not Problems.FAILED:
        problems.stage(_arms, key, sp, D)
    problems.raise_all()
    sigma_allow = sigma_of(d)
    # method A: required wind-up angle
    J = SP.second_moment(d)
    L_leg = sum(SP.leg_length(a, D, sp["leg_model"]) for a in (sp["leg_arm"], sp["leg2_arm"])
                if a is not None)
    phi_kin = phi_req = phi_leg = None
    phi_design = math.radians(sp["design_angle"]) if sp["design_angle"] is not None else None
    if motor is not None:
        phi_kin = SP.kinematic_windup(motor["speed"],
                                      motor["breakaway_time"] * motor["windup_factor"])
        phi_leg = SP.twist(T, L_leg, E, J)
        phi_req = phi_kin + phi_leg
        if phi_design is None:
            phi_design = SP.design_angle(phi_req, lim["design_angle_step"])
    pitch_assumed = sp["pitch"] is None
    if pitch_assumed:
        assume(spec, sp, "pitch", f"{key}.pitch", d + lim["pitch_gap_default"])
    inp = SP.SpringInput(
        T=sp["torque"], E=E, sigma_allow=sigma_allow, d=d, c=c_in, D=D, i=sp["coils"],
        p=sp["pitch"], curvature=sp["curvature_factor"], leg_arm=sp["leg_arm"],
        leg2_arm=sp["leg2_arm"], leg_model=sp["leg_model"], phi_required=phi_req,
        phi_design=phi_design,
        phi_stop=math.radians(sp["stop_angle"]) if sp["stop_angle"] is not None else None)
    tau = tau_of(d) if tau_of is not None else None
    slot = sp["slot_arms"]
    return Spring(
        key, j + 1, name, sp["name"] is not None, inp, tau, sp["tau_allow"] is not None,
        sp["tau_allow"] is not None or sp["sigma_over_tau"] is not None, sigma_source, steel,
        phi_kin, phi_req, phi_leg, outer, in_series, E_assumed, sp["wire_diameter"] is not None,
        sp["design_angle"], sp["coils"] is not None, pitch_assumed,
        sp["index"] is not None and sp["coil_diameter"] is not None,
        None if slot is None else (slot[0], slot[1]), sp["target_stiffness"],
        bool(sp["ends_fixed_axially"]), sp["arbor_diameter"])
