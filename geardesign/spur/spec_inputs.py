"""The spec readers of a spur pair: pair geometry input (shifts resolved) and strength
inputs (materials, setting; the duty from :mod:`.spec_duty`) from a validated spec, every
rule across keys an input error naming the key.  :mod:`.inputs` puts them together into the typed
:class:`~geardesign.spur.inputs.Inputs`; :mod:`.design` sizes a pair with them.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.spec import ValidatedSpec
from geardesign.gears import internal as I
from geardesign.gears.geometry import (
    BasicRack,
    GeometryError,
    PairGeometry,
    PairInput,
    pair_geometry,
    shift_sum_for_center_distance,
)
from geardesign.spur.kinematics import balanced_shift_split
from geardesign.spur.spec_duty import _fmt, duty_from_spec

X_AGREE = 1e-3  # |x1 + x2 − x_Σ(a_w)| accepted when all three are given
X_SUM_RANGE = (-2.0, 4.0)  # x1 + x2 reachable with each shift in −1…2 (the spec's range)
X_DIFF_RANGE = (-3.0, 3.0)  # x2 − x1 reachable likewise (internal pairs)


def pair_input_from_spec(spec: ValidatedSpec) -> tuple[PairInput, str]:
    """Build the :class:`PairInput` of a spec, resolving the shifts.

    Without ``center_distance`` the shifts are x1, x2 (0 when absent, echoed as assumed).
    With it, x_Σ follows from a_w (GOST 16532-70, reverse task) and is split: x1 or x2
    given, or ``shift_split`` ("sliding": equal specific sliding at the roots, the default;
    "equal": x1 = x2).  Returns the input and a word for how the shifts were obtained.
    """
    g, r = spec.data["gear"], spec.data["rack"]
    rack = BasicRack(math.radians(g["pressure_angle"]), r["addendum_coef"], r["clearance_coef"],
                     r["root_radius_coef"])
    beta = math.radians(g["helix_angle"])
    m, z1, z2, b = g["module"], g["z1"], g["z2"], g["face_width"]
    a_w = g["center_distance"]
    x1, x2, split = g["x1"], g["x2"], g["shift_split"]

    if a_w is None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only with gear.center_distance; remove it or give "
                                "center_distance")
        for key in ("x1", "x2"):
            if g[key] is None:
                g[key] = 0.0
                spec.assumed.append(f"gear.{key}")
        return PairInput(m, z1, z2, g["x1"], g["x2"], beta, b, rack), "given"

    try:
        x_sum, _ = shift_sum_for_center_distance(a_w, m, z1, z2, rack.alpha_n, beta)
    except GeometryError as exc:
        a = 0.5 * m * (z1 + z2) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"smaller than possible: must exceed (d_b1 + d_b2)/2 = {_fmt(exc.limit)} mm, where "
            f"the base circles touch (x1 + x2 = 0 gives a_w = {_fmt(a)} mm)") from None
    if not X_SUM_RANGE[0] <= x_sum <= X_SUM_RANGE[1]:
        a = 0.5 * m * (z1 + z2) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs x1 + x2 = {x_sum:.3f}, outside what two shifts of −1…2 can give "
            f"({X_SUM_RANGE[0]:g}…{X_SUM_RANGE[1]:g}); choose a_w nearer to a = {_fmt(a)} mm")
    if x1 is not None and x2 is not None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only when x1 or x2 is left out; remove it")
        if abs(x1 + x2 - x_sum) > X_AGREE:
            raise InputError(Problem(
                "gear.x1 + gear.x2", f"does not match center_distance = {_fmt(a_w)} mm, which "
                f"needs x1 + x2 = {x_sum:.4f}; give x1 or x2 only and the other follows",
                x1 + x2))
        return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "x1 given, x2 = x_Σ − x1"
    if x1 is not None or x2 is not None:
        if split is not None:
            raise InputError.at("gear.shift_split", split,
                                "applies only when neither x1 nor x2 is given; remove it")
        if x1 is not None:
            return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "x1 given, x2 = x_Σ − x1"
        return PairInput(m, z1, z2, x_sum - x2, x2, beta, b, rack), "x2 given, x1 = x_Σ − x2"
    if split == "equal":
        return PairInput(m, z1, z2, x_sum / 2, x_sum / 2, beta, b, rack), "equal split"
    base = PairInput(m, z1, z2, 0.0, 0.0, beta, b, rack)
    try:
        x1 = balanced_shift_split(base, x_sum)
    except GeometryError:
        raise InputError.at(
            "gear.center_distance", a_w,
            f"no split of x1 + x2 = {x_sum:.4f} balances the specific sliding with a valid "
            f"geometry; give x1 (or x2) explicitly") from None
    return PairInput(m, z1, z2, x1, x_sum - x1, beta, b, rack), "equal specific sliding"


#: Keys of internal pairs only: their defaults are not echoed for an external pair.
INTERNAL_ONLY = ("gear.internal", "gear.cutter_shift", "gear.internal_tip_shortening")


def _given(spec: ValidatedSpec, path: str) -> bool:
    """Whether the spec gave ``path`` itself (not a default)."""
    table, key = path.split(".")
    return path not in spec.assumed and (spec.data.get(table) or {}).get(key) is not None


def internal_input_from_spec(spec: ValidatedSpec) -> tuple[I.InternalPairInput, str]:
    """The :class:`~geardesign.gears.internal.InternalPairInput` of a spec with
    ``gear.internal = true``, resolving the shifts (GOST 19274-73 sign).

    Without ``center_distance`` the shifts are x1, x2 (0 when absent, echoed as assumed).
    With it, x2 − x1 follows from a_w (:func:`~geardesign.gears.internal.
    shift_difference_for_center_distance`); x1 or x2 given, the other follows; neither, x1 = 0
    (assumed).  Rules across keys are input errors naming the key."""
    g, r = spec.data["gear"], spec.data["rack"]
    rack = BasicRack(math.radians(g["pressure_angle"]), r["addendum_coef"], r["clearance_coef"],
                     r["root_radius_coef"])
    beta = math.radians(g["helix_angle"])
    m, z1, z2, b = g["module"], g["z1"], g["z2"], g["face_width"]
    n_min = I.MIN_TEETH_DIFFERENCE
    if z2 - z1 < n_min:
        raise InputError.at("gear.z2", z2, f"an internal gear needs at least {n_min} teeth more "
                            f"than the pinion (gear.z1 = {z1}): with fewer the pair cannot run "
                            f"(tip interference); use z2 >= {z1 + n_min}")
    if _given(spec, "gear.tip_shortening"):
        raise InputError.at("gear.tip_shortening", g["tip_shortening"],
                            "applies to external pairs (the Δy shortening of GOST 16532-70); the "
                            "tip of an internal gear is set by gear.internal_tip_shortening")
    if g["shift_split"] is not None:
        raise InputError.at("gear.shift_split", g["shift_split"],
                            "applies to external pairs only; for an internal pair give x1 or "
                            "x2 and the other follows from center_distance")
    cutter = None
    z0 = g["cutter_teeth"]
    if z0 is not None:
        if z0 + n_min > z2:
            raise InputError.at("gear.cutter_teeth", z0,
                                f"a shaper cuts an internal gear only with fewer teeth: at most "
                                f"{z2 - n_min} for the {z2}-tooth internal gear (gear.z2; the "
                                f"same rule as for the pinion)")
        cutter = I.ShaperCutter(z0, g["cutter_shift"], g["cutter_tip_radius_coef"])
    else:
        for key in ("cutter_shift", "cutter_tip_radius_coef"):
            if _given(spec, f"gear.{key}"):
                raise InputError.at(f"gear.{key}", g[key],
                                    "applies only with gear.cutter_teeth (the shaper cutter); "
                                    f"give it or remove {key}")
    for path in ("gear.tip_shortening",) + (("gear.cutter_shift",) if cutter is None else ()):
        _drop_unused_defaults(spec, (path,))

    def make(x1: float, x2: float) -> I.InternalPairInput:
        return I.InternalPairInput(m, z1, z2, x1, x2, beta, b, rack,
                                   k2=g["internal_tip_shortening"], cutter=cutter)

    a_w, x1, x2 = g["center_distance"], g["x1"], g["x2"]
    if a_w is None:
        for key in ("x1", "x2"):
            if g[key] is None:
                g[key] = 0.0
                spec.assumed.append(f"gear.{key}")
        return make(g["x1"], g["x2"]), "given"
    try:
        x_diff, _ = I.shift_difference_for_center_distance(a_w, m, z1, z2, rack.alpha_n, beta)
    except GeometryError as exc:
        a = 0.5 * m * (z2 - z1) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"smaller than possible for an internal pair: must exceed (d_b2 − d_b1)/2 = "
            f"{_fmt(exc.limit)} mm, where the base circles touch (x2 − x1 = 0 gives a_w = "
            f"{_fmt(a)} mm)") from None
    lo, hi = X_DIFF_RANGE
    if not lo <= x_diff <= hi:
        a = 0.5 * m * (z2 - z1) / math.cos(beta)
        raise InputError.at(
            "gear.center_distance", a_w,
            f"needs x2 − x1 = {x_diff:.3f}, outside what two shifts of −1…2 can give "
            f"({lo:g}…{hi:g}); choose a_w nearer to a = {_fmt(a)} mm")
    if x1 is not None and x2 is not None:
        if abs(x2 - x1 - x_diff) > X_AGREE:
            raise InputError(Problem(
                "gear.x2 − gear.x1", f"does not match center_distance = {_fmt(a_w)} mm, which "
                f"needs x2 − x1 = {x_diff:.4f} (internal pair); give x1 or x2 only and the "
                f"other follows", x2 - x1))
        return make(x1, x1 + x_diff), "x1 given, x2 = x1 + x_d"
    if x2 is not None:
        return make(x2 - x_diff, x2), "x2 given, x1 = x2 − x_d"
    if x1 is None:
        g["x1"] = 0.0
        spec.assumed.append("gear.x1")
    return make(g["x1"], g["x1"] + x_diff), "x1 given, x2 = x1 + x_d"


def _solve_internal(spec: ValidatedSpec) -> tuple[I.InternalPairGeometry, str]:
    p, how = internal_input_from_spec(spec)
    try:
        return I.internal_pair_geometry(p), how
    except GeometryError as exc:
        if exc.code == "INV_ALPHA_TW":
            raise InputError(Problem(
                "gear.x2 − gear.x1",
                f"too negative for an internal pair: {exc}, no working pressure angle exists; "
                f"x2 − x1 (GOST 19274-73 sign) must be > {exc.limit:.4f}", p.x2 - p.x1)) \
                from None
        if exc.code == "RING_TIP_INSIDE_BASE":
            raise InputError.at(
                "gear.x2", p.x2,
                f"the tip circle of the internal gear (d_a2 = {exc.value:.4f} mm) lies inside "
                f"its base circle (d_b2 = {exc.limit:.4f} mm): no involute at its tips; "
                f"increase x2 (GOST 19274-73 sign) or gear.internal_tip_shortening") from None
        if exc.code == "CUTTER_TIP":
            raise InputError.at("gear.cutter_teeth", p.cutter.z0,
                                f"{exc}; use another cutter") from None
        raise InputError.at(
            "gear.x1", p.x1,
            f"the tip circle of the pinion (d_a = {exc.value:.4f} mm) lies inside its base "
            f"circle (d_b = {exc.limit:.4f} mm): no involute flank; increase x1 or z1") \
            from None


def solve_geometry(spec: ValidatedSpec) -> tuple[PairGeometry, str]:
    """Pair geometry of a spec; impossible geometry becomes a one-line input error.  An
    internal pair (``gear.internal``) gives an
    :class:`~geardesign.gears.internal.InternalPairGeometry`."""
    gear = spec.data["gear"]
    if gear.get("internal"):
        return _solve_internal(spec)
    for path in INTERNAL_ONLY[1:]:
        if _given(spec, path):
            raise InputError.at(path, gear[path.split(".")[1]],
                                "applies to internal pairs only; set gear.internal = true or "
                                "remove it")
    for key in ("cutter_teeth", "cutter_tip_radius_coef"):
        if gear.get(key) is not None:
            raise InputError.at(f"gear.{key}", gear[key], "applies to internal pairs only; set "
                                "gear.internal = true or remove it")
    _drop_unused_defaults(spec, INTERNAL_ONLY)
    p, how = pair_input_from_spec(spec)
    if not spec.data["gear"].get("tip_shortening", True):
        from dataclasses import replace

        p = replace(p, tip_shortening=False)
    try:
        return pair_geometry(p), how
    except GeometryError as exc:
        if exc.code == "INV_ALPHA_TW":
            raise InputError(Problem(
                "gear.x1 + gear.x2",
                f"too negative: {exc}, no working pressure angle exists; x1 + x2 must be "
                f"> {exc.limit:.4f}", p.x1 + p.x2)) from None
        i = 1 if exc.code.endswith("_1") else 2
        x = p.x1 if i == 1 else p.x2
        key = f"gear.x{i}" if how == "given" or f"x{i} given" in how else "gear.center_distance"
        value = x if key.endswith(f"x{i}") else spec.data["gear"]["center_distance"]
        raise InputError.at(
            key, value,
            f"the tip circle of gear {i} (d_a = {exc.value:.4f} mm) lies inside its base circle "
            f"(d_b = {exc.limit:.4f} mm): no involute flank; increase x{i} or z{i}") from None


def _strength_inputs(spec: ValidatedSpec, gear: dict):
    """Materials, duty and setting of the strength calculation, or ``None`` for a
    geometry-only spec.  Missing pieces are input errors naming the key; every
    independent one is reported in the same round (:class:`Problems`)."""
    from geardesign.materials.gear_steel import resolve
    from geardesign.spur.strength.rating import Setting

    d = spec.data
    load, mat = d["load"], d["material"]
    torque_given = load is not None and (load["torque1"] is not None or load["power"] is not None)
    if mat is None:
        if torque_given:
            raise InputError(Problem("material", "missing table [material.pinion] and "
                                     "[material.wheel]: required with load.torque1 or load.power "
                                     "for the strength calculation"))
        return None
    from geardesign.spur.strength.iso6336.spec import ISO_NAME, chosen

    problems = Problems()
    # the GOST 21354-87 chart of K_Hβ: the GOST rating and the design mode's sizing read it,
    # the ISO 6336 rating does not (K_Hβ by method C from f_sh and f_ma)
    if gear["bearing_scheme"] is None and (d["design"] is not None
                                           or chosen(d["options"]) != [ISO_NAME]):
        where = "design" if d["design"] is not None else "gear"
        why = ("the design mode sizes the pair with the GOST 21354-87 K_Hβ" if d["design"]
               is not None else "the GOST 21354-87 rating")
        problems.add(Problem(f"{where}.bearing_scheme", f"missing; required for {why}: "
                             "1…7 as in the GOST 21354-87 chart (see geardesign template "
                             "spur)"))
    duty = problems.stage(duty_from_spec, spec, load, torque_given)
    mats = tuple(problems.stage(lambda who=who: resolve(mat[who], f"material.{who}"))
                 for who in ("pinion", "wheel"))
    problems.raise_all()
    setting = Setting(gear["accuracy_grade"], gear["tip_relief"], gear["bearing_scheme"],
                      (mat["pinion"]["roughness_Ra"], mat["wheel"]["roughness_Ra"]),
                      dict(d["factors"] or {}), d["options"]["contact_model"],
                      d["options"]["crowning"])
    from geardesign.spur.strength.iso6336.spec import prepare

    prepare(spec)
    return mats, duty, setting


#: Defaults that only the strength calculation uses: not echoed for a geometry-only spec.
STRENGTH_ONLY = ("gear.accuracy_grade", "gear.tip_relief", "load.application_factor",
                 "load.meshes_pinion", "load.meshes_wheel", "load.reverse_torque_ratio",
                 "options.method", "options.contact_model")


def _drop_unused_defaults(spec: ValidatedSpec, paths: tuple[str, ...]) -> None:
    """Remove assumed defaults that the calculation did not use from the inputs echo."""
    for path in paths:
        if path in spec.assumed:
            spec.assumed.remove(path)
            table, key = path.split(".")
            if spec.data.get(table) is not None:
                spec.data[table].pop(key, None)


def _contact_ratio_domain(geom, spec: ValidatedSpec, gear: dict) -> None:
    """Refuse a pair whose tip circles do not overlap on the line of action: ε_α <= 0 is
    outside the domain of every formula that uses it (Z_ε, Y_ε, K_Hα of GOST 21354-87 and
    ISO 6336 take ε_α > 0; ε_α = g_α/p_bt of GOST 16532-70 table 1 item 4 is a length ratio).
    The input to change is the tooth height (``rack.addendum_coef``) or the shifts."""
    if geom.eps_alpha > 0.0:
        return
    rack = spec.data.get("rack") or {}
    shifts = ", ".join(f"gear.{k} = {gear[k]:.3g}" for k in ("x1", "x2")
                       if isinstance(gear.get(k), (int, float)))
    raise InputError.at(
        "rack.addendum_coef", rack.get("addendum_coef", 1.0),
        f"gives with {shifts or 'the shifts'} a transverse contact ratio ε_α = "
        f"{geom.eps_alpha:.3f} <= 0: the tip circles do not overlap on the line of action; "
        "increase rack.addendum_coef (tooth height) or reduce the profile shifts")

