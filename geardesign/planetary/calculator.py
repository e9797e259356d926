"""``kind = "planetary"``: from a validated spec to a :class:`~geardesign.core.result.Result`.

This module maps spec keys to the pure functions of :mod:`.kinematics`, :mod:`.assembly`,
:mod:`.geometry`, :mod:`.efficiency`, :mod:`.strength` and :mod:`.synthesis`, and their
results to report rows and checks.  Rules that involve several keys raise
:class:`~geardesign.core.errors.InputError` naming the key and saying what is allowed.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.result import Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.planetary import assembly as A
from geardesign.planetary import checks as C
from geardesign.planetary import efficiency as E
from geardesign.planetary import geometry as PG
from geardesign.planetary import kinematics as K
from geardesign.planetary import sources as S
from geardesign.spur import geometry as G
from geardesign.spur import internal as I
from geardesign.spur.kinematics import velocities

X_AGREE = 1e-3     # |given shift − shift from a_w| accepted when both are given
MIN_RING_EXCESS = I.MIN_TEETH_DIFFERENCE  # ring teeth over its planet crown's, at least


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


# ----------------------------------------------------------------------------- the train


def train_from_teeth(d: dict) -> tuple[K.Train, dict]:
    """The train of an analysis spec, and the sign convention of each ring (+1 GOST, −1
    ISO).  Rules across keys are input errors."""
    t, tr = d["teeth"], d["train"]
    scheme = tr["scheme"]
    conv = {}
    for key in ("ring", "ring2"):
        v = t[key]
        if v is not None:
            if v == 0:
                raise InputError.at(f"teeth.{key}", v, "must not be 0: give the ring's number of "
                                    "teeth (negative for the ISO 21771 convention)")
            conv[key] = 1 if v > 0 else -1
    if "ring2" in conv and conv["ring2"] != conv["ring"]:
        raise InputError.at("teeth.ring2", t["ring2"], "uses the other sign convention than "
                            f"teeth.ring = {t['ring']}; write both rings positive (GOST 19274-73) "
                            f"or both negative (ISO 21771)")
    if scheme == "2K-H":
        for key in ("planet2", "ring2"):
            if t[key] is not None:
                raise InputError.at(f"teeth.{key}", t[key], "applies only to the schemes "
                                    "\"2K-H-stepped\" and \"3K\"; remove it or set train.scheme")
    if scheme == "2K-H-stepped":
        if t["planet2"] is None:
            raise InputError(Problem("teeth.planet2", "missing; required for train.scheme = "
                                     "\"2K-H-stepped\": the teeth of the planet crown meshing "
                                     "the ring"))
        if t["ring2"] is not None:
            raise InputError.at("teeth.ring2", t["ring2"], "applies only to train.scheme = "
                                "\"3K\"; remove it")
    if scheme == "3K" and t["ring2"] is None:
        raise InputError(Problem("teeth.ring2", "missing; required for train.scheme = \"3K\": "
                                 "the teeth of the second (output) ring"))
    train = K.Train(scheme, t["sun"], t["planet"], abs(t["ring"]), tr["planets"], t["planet2"],
                    None if t["ring2"] is None else abs(t["ring2"]))
    for key in ("ring", "ring2") if scheme == "3K" else ("ring",):
        z, crown = train.teeth(key), train.crown(key)
        cname = "planet2" if crown == train.planet2 and (
            scheme == "2K-H-stepped" or key == "ring2") and train.planet2 is not None else "planet"
        if z - crown < MIN_RING_EXCESS:
            raise InputError.at(f"teeth.{key}", t[key],
                                f"the ring needs at least {MIN_RING_EXCESS} teeth more than the "
                                f"planet crown it meshes (teeth.{cname} = {crown}): with fewer the "
                                f"internal pair cannot run (tip interference); use |z| >= "
                                f"{crown + MIN_RING_EXCESS}")
    if scheme == "3K" and train.ring2 * train.crown("ring") == train.ring * train.crown("ring2"):
        raise InputError.at("teeth.ring2", t["ring2"],
                            "makes the ratio infinite (z_b z_f = z_g z_e: the output ring would "
                            "stand still); change the second ring's or the planet's teeth")
    return train, conv


def _layout(d: dict, train: K.Train) -> PG.Layout:
    tr, r, ring = d["train"], d["rack"], d["ring"]
    has_crown2 = train.planet2 is not None
    for key in ("module2", "face_width2"):
        if tr[key] is not None and not has_crown2:
            raise InputError.at(f"train.{key}", tr[key],
                                "applies only to a planet with a second crown (teeth.planet2); "
                                "remove it")
    alpha_n = math.radians(tr["pressure_angle"])
    rack = G.BasicRack(alpha_n, r["addendum_coef"], r["clearance_coef"], r["root_radius_coef"])
    rho_ring = ring["root_radius_coef"] if ring["root_radius_coef"] is not None else \
        r["root_radius_coef"]
    ring_rack = G.BasicRack(alpha_n, r["addendum_coef"], r["clearance_coef"], rho_ring)
    cutter = None
    if d["cutter"] is not None:
        c = d["cutter"]
        rings = [train.teeth(k) for k in (("ring", "ring2") if train.ring2 else ("ring",))]
        if c["teeth"] + MIN_RING_EXCESS > min(rings):
            raise InputError.at("cutter.teeth", c["teeth"],
                                f"a shaper cuts an internal gear only with fewer teeth: at most "
                                f"{min(rings) - MIN_RING_EXCESS} for the {min(rings)}-tooth ring "
                                f"(the same rule as for a planet meshing the ring)")
        cutter = I.ShaperCutter(c["teeth"], c["shift"], c["tip_radius_coef"])
    m = tr["module"]
    return PG.Layout(train, m, tr["module2"] or m, math.radians(tr["helix_angle"]),
                     tr["face_width"], tr["face_width2"] or tr["face_width"], rack, ring_rack,
                     ring["tip_shortening"], cutter)


def _check_operation(train: K.Train, op: dict) -> None:
    members = train.members
    fixed, inp, out = op["fixed"], op["input"], op["output"]
    for key in ("fixed", "input", "output", "control"):
        v = op[key]
        if v is not None and v != "none" and v not in members:
            raise InputError.at(f"operation.{key}", v,
                                f"train.scheme \"{train.scheme}\" has no such member; use one of "
                                + ", ".join(f'"{x}"' for x in members))
    if train.scheme == "3K":
        for key in ("fixed", "input", "output", "control"):
            if op[key] == "carrier":
                raise InputError.at(f"operation.{key}", "carrier",
                                    "the carrier of a 3K train runs free and carries no torque; "
                                    "use the sun, ring or ring2")
        if fixed == "none":
            raise InputError.at("operation.fixed", "none", "a 3K train needs a fixed member "
                                "(usually the ring)")
    if inp == out:
        raise InputError.at("operation.output", out, "is the input member too; the output must "
                            "be another member")
    if fixed in (inp, out):
        role = "input" if fixed == inp else "output"
        raise InputError.at("operation.fixed", fixed, f"is also the {role} member; a fixed "
                            "member cannot turn")
    if op["torque"] is not None and op["power"] is not None:
        raise InputError.at("operation.power", op["power"], "give torque or power, not both")
    if op["speed"] is not None and op["speed"] == 0.0:
        raise InputError.at("operation.speed", 0.0, "must not be 0: the input must turn")
    if op["power"] is not None and op["speed"] is None:
        raise InputError(Problem("operation.speed", "missing; required with operation.power "
                                 "(the torque follows from power and speed)"))
    if fixed == "none":
        if op["control"] is None or op["control_speed"] is None:
            missing = "control" if op["control"] is None else "control_speed"
            raise InputError(Problem(f"operation.{missing}", "missing; required with "
                                     "operation.fixed = \"none\": a differential needs a second "
                                     "member with an imposed speed (control and control_speed)"))
        if op["control"] in (inp, out):
            raise InputError.at("operation.control", op["control"], "must differ from the input "
                                "and output members")
        if op["speed"] is None:
            raise InputError(Problem("operation.speed", "missing; required with operation.fixed "
                                     "= \"none\": the input speed"))
    else:
        for key in ("control", "control_speed"):
            if op[key] is not None:
                raise InputError.at(f"operation.{key}", op[key], "applies only with "
                                    "operation.fixed = \"none\"; remove it")


# ----------------------------------------------------------------------------- shifts


def _user_to_gost(value: float | None, conv: int) -> float | None:
    return None if value is None else (value if conv > 0 else I.x_from_iso(value))


def _gost_to_user(value: float, conv: int) -> float:
    return value if conv > 0 else I.x_to_iso(value)


def resolve_shifts(d: dict, spec: ValidatedSpec, lay: PG.Layout, conv: dict
                   ) -> tuple[dict, str, float | None]:
    """The shifts (GOST sign) of every gear, how they were obtained, and the target a_w.

    Without train.center_distance or train.working_angle the shifts are as given (0 when
    absent, echoed as assumed); with either, they follow from a_w by coaxiality."""
    tr, sh = d["train"], d["shift"]
    train = lay.train
    a_given, ang = tr["center_distance"], tr["working_angle"]
    if a_given is not None and ang is not None:
        raise InputError.at("train.working_angle", ang, "give center_distance or working_angle, "
                            "not both")
    gears = ["sun", "planet", "ring"] + (["planet2"] if train.planet2 is not None else []) + \
        (["ring2"] if train.scheme == "3K" else [])
    for key in ("planet2", "ring2"):
        if sh[key] is not None and key not in gears:
            raise InputError.at(f"shift.{key}", sh[key], "there is no such gear in this train; "
                                "remove it")
    given = {g: (_user_to_gost(sh[g], conv.get(g, 1)) if g.startswith("ring") else sh[g])
             for g in gears}
    if a_given is None and ang is None:
        for g in gears:
            if sh[g] is None:
                sh[g] = 0.0
                given[g] = 0.0
                spec.assumed.append(f"shift.{g}")
        return given, "given", None
    if ang is not None:
        a_w = PG.center_distance_from_angle(lay, math.radians(ang))
        where, value = "train.working_angle", ang
    else:
        a_w, where, value = a_given, "train.center_distance", a_given
    try:
        shifts, how = PG.coaxial_shifts(lay, a_w, given["sun"], given.get("planet2"))
    except G.GeometryError as exc:
        if exc.code == "NO_BALANCED_SPLIT":
            raise InputError.at(where, value, "no split of the sun–planet shift sum balances the "
                                "specific sliding with a valid geometry; give shift.sun") from None
        mesh = _mesh_for_limit(lay, a_w)
        raise InputError.at(where, value, f"smaller than possible: the {mesh} mesh needs a_w > "
                            f"{_fmt(exc.limit)} mm, where its base circles touch") from None
    far = [g for g in gears if not _x_range(g)[0] <= shifts[g] <= _x_range(g)[1]]
    if far:
        a_ref = PG.reference_center_distance(lay, PG.meshes_of(lay.train)[0])
        lo, hi = _x_range(far[0])
        raise InputError.at(where, value, f"the teeth cannot reach it: it needs shift.{far[0]} "
                            f"= {shifts[far[0]]:.2f}, outside {lo:g}…{hi:g}; the "
                            f"reference centre distance of the sun–planet mesh is "
                            f"{_fmt(a_ref)} mm (check the module)")
    for g in gears:
        if given[g] is not None and abs(given[g] - shifts[g]) > X_AGREE:
            shown = _gost_to_user(shifts[g], conv.get(g, 1)) if g.startswith("ring") else \
                shifts[g]
            raise InputError.at(f"shift.{g}", sh[g],
                                f"does not match {where} = {_fmt(value)}, which needs "
                                f"shift.{g} = {shown:.4f}; leave it out and it follows")
    return shifts, how, a_w


def _x_range(member: str) -> tuple[float, float]:
    """Shift coefficients a centre distance may call for: the domain of the shift key."""
    return (-3.0, 3.0) if member.startswith("ring") else (-1.5, 3.0)


def _mesh_for_limit(lay: PG.Layout, a_w: float) -> str:
    for mesh in PG.meshes_of(lay.train):
        try:
            PG.shift_sum_for(lay, mesh, a_w)
        except G.GeometryError:
            return C.MESH_NAMES.get(mesh.name, mesh.name)
    return "sun–planet"


def shift_origin(d: dict) -> tuple[str, object] | None:
    """The input the shifts were derived from (key, value), or ``None`` when they are the
    spec's own (given, or 0 by default): an error about a derived shift names that input."""
    if d.get("synthesis") is not None:
        return "synthesis", Problem.NO_VALUE
    tr = d["train"]
    for key in ("center_distance", "working_angle"):
        if tr[key] is not None:
            return f"train.{key}", tr[key]
    return None


def _shift_error(key: str, value: float, message: str, given: set,
                 origin: tuple[str, object] | None) -> InputError:
    """An error about ``key`` (``shift.ring``, or ``shift.sun + shift.planet``): on that key
    when the user gave the shifts it reads; else on the input they were derived from,
    saying so."""
    members = [k.strip().removeprefix("shift.") for k in key.split("+")]
    if origin is None or all(m in given for m in members):
        return InputError.at(key, value, message)
    where, what = origin
    source = "the synthesis" if where == "synthesis" else f"{where} by coaxiality"
    return InputError(Problem(where, f"gives {key} = {value:.4f} (derived from {source} and "
                              f"the teeth): {message}", what))


def _geometry(lay: PG.Layout, shifts: dict, conv: dict, given: set = frozenset(),
              origin: tuple[str, object] | None = None):
    """The meshes of the train; an impossible one is an input error on the shift the user
    gave, or on the input a derived shift follows from (``origin``: :func:`shift_origin`;
    ``given``: the shifts the spec states)."""
    try:
        return PG.mesh_geometry(lay, shifts)
    except G.GeometryError as exc:
        mesh = getattr(exc, "mesh", None)
        mn = C.MESH_NAMES.get(mesh.name, mesh.name) if mesh else "a"
        if exc.code == "INV_ALPHA_TW" and mesh is not None and mesh.internal:
            ring, crown = mesh.wheel, mesh.pinion
            raise _shift_error(
                f"shift.{ring}", _gost_to_user(shifts[ring], conv.get(ring, 1)),
                f"too negative for the {mn} mesh: {exc}, no working pressure angle exists; "
                f"x_{ring} − x_{crown} (GOST sign) must be > {exc.limit:.4f}", given,
                origin) from None
        if exc.code == "INV_ALPHA_TW":
            raise _shift_error(
                "shift.sun + shift.planet", shifts["sun"] + shifts["planet"],
                f"too negative for the {mn} mesh: {exc}, no working pressure angle exists; "
                f"x_sun + x_planet must be > {exc.limit:.4f}", given, origin) from None
        if exc.code == "RING_TIP_INSIDE_BASE":
            ring = mesh.wheel
            iso = conv.get(ring, 1) < 0
            raise _shift_error(f"shift.{ring}", _gost_to_user(shifts[ring], conv.get(ring, 1)),
                               f"the tip circle of the {ring} (d_a = {exc.value:.4f} mm) lies "
                               f"inside its base circle (d_b = {exc.limit:.4f} mm): no involute "
                               f"at the ring's tips; {'reduce' if iso else 'increase'} "
                               f"shift.{ring} ({'ISO' if iso else 'GOST'} sign) or increase "
                               f"ring.tip_shortening", given, origin) from None
        if exc.code == "CUTTER_TIP":
            raise InputError.at("cutter.teeth", lay.cutter.z0, f"{exc}; use another cutter") \
                from None
        i = 1 if exc.code.endswith("_1") else 2
        member = (mesh.pinion if i == 1 else mesh.wheel) if mesh else "sun"
        raise _shift_error(f"shift.{member}", shifts.get(member),
                           f"the tip circle of the {member} (d_a = {exc.value:.4f} mm) lies "
                           f"inside its base circle (d_b = {exc.limit:.4f} mm): no involute "
                           f"flank; increase shift.{member} or teeth.{member}", given,
                           origin) from None


# ----------------------------------------------------------------------------- rows


def _rows_train(res: Result, train: K.Train, op: dict, conv: dict) -> None:
    sec = res.section("train", "Train")
    sec.add("scheme", train.scheme, None, "", "scheme", S.KUDRYAVTSEV)
    sec.add("ring_convention", "ISO 21771 (z < 0, x_ISO = −x_GOST)" if conv.get("ring", 1) < 0
            else "GOST 19274-73 (z > 0, x > 0 away from the axis)", None, "",
            "sign convention of the internal gears (as given)", S.G19274)
    if op["fixed"] != "none":
        sec.add("i", K.ratio(train, op["fixed"], op["input"], op["output"]), "-", "i",
                f"ratio n_{op['input']}/n_{op['output']} ({op['fixed']} fixed)", S.WILLIS)
        free = [m for m in train.members if m != op["fixed"] and
                not (train.scheme == "3K" and m == "carrier")]
        for a_ in free:
            for b_ in free:
                if a_ < b_:
                    sec.add(f"i_{a_}_{b_}", K.ratio(train, op["fixed"], a_, b_), "-",
                            f"i_{a_},{b_}", f"ratio n_{a_}/n_{b_} ({op['fixed']} fixed)",
                            S.WILLIS)
    for x, y in (("sun", "ring"), ("sun", "ring2"), ("ring2", "ring")):
        if x in train.central and y in train.central:
            sec.add(f"u_h_{x}_{y}", train.willis(x, y), "-", f"u^h_{x},{y}",
                    f"fixed-carrier (Willis) ratio (ω_{x} − ω_h)/(ω_{y} − ω_h)", S.WILLIS)
    if train.scheme == "3K" and op["fixed"] == "ring" and {op["input"], op["output"]} == \
            {"sun", "ring2"}:
        sec.add("U_b_a_e", K.ratio(train, "ring", "sun", "ring2"), "-", "U^b_ae",
                "3K ratio sun → ring2, ring fixed: (1 + z_b/z_a)/(1 − z_b z_f/(z_g z_e))",
                S.MATUSEVICH_1)


def _gear_rows(res: Result, gears: dict, conv: dict) -> None:
    sec = res.section("gears", "Gears")
    for member, g in gears.items():
        ring = member.startswith("ring")
        sec.add(f"z_{member}", g.z, "-", f"z_{member}", f"teeth, {member}", S.G16532)
        sec.add(f"x_{member}", g.x, "-", f"x_{member}",
                f"profile shift, {member}" + (" (GOST 19274-73 sign)" if ring else ""),
                S.G19274 if ring else S.G16532)
        if ring:
            sec.add(f"x_{member}_iso", I.x_to_iso(g.x), "-", f"x_{member},ISO",
                    f"profile shift, {member} (ISO 21771 sign)", S.G19274)
        src = S.G19274 if ring else S.G16532
        sec.add(f"d_{member}", g.d, "mm", f"d_{member}", f"reference diameter, {member}", src)
        sec.add(f"d_b_{member}", g.d_b, "mm", f"d_b,{member}", f"base diameter, {member}", src)
        sec.add(f"d_a_{member}", g.d_a, "mm", f"d_a,{member}",
                f"tip diameter, {member}" + (" (internal)" if ring else ""), src)
        sec.add(f"d_f_{member}", g.d_f, "mm", f"d_f,{member}", f"root diameter, {member}", src)
        sec.add(f"d_l_{member}", g.d_l, "mm", f"d_l,{member}", f"form circle diameter, {member}",
                src)
        sec.add(f"s_n_{member}", g.s_n, "mm", f"s_n,{member}",
                f"normal tooth thickness at the reference circle, {member}", src)
        sec.add(f"s_an_{member}", g.s_an, "mm", f"s_an,{member}",
                f"normal tooth thickness at the tip, {member}",
                S.MATUSEVICH + (" (36)" if ring else " (35)"))
        if not ring:
            sec.add(f"x_min_{member}", g.x_min, "-", f"x_min,{member}",
                    f"least shift without undercut, {member}", S.G16532)
        sec.add(f"k_{member}", g.k, "-", f"k_{member}",
                f"teeth (ring: spaces) spanned, {member}", S.G16532 if not ring else S.G19274)
        sec.add(f"W_{member}", g.W, "mm", f"W_{member}", f"base tangent length, {member}",
                S.G16532 if not ring else S.G19274)


def _mesh_rows(res: Result, mesh: PG.Mesh) -> None:
    g, sp = mesh.geom, mesh.spec
    p1, p2 = sp.pinion, sp.wheel
    mn = C.MESH_NAMES.get(mesh.name, mesh.name)
    src = S.G19274 if sp.internal else S.G16532
    sec = res.section(mesh.name, f"Mesh {mn}" + (" (internal)" if sp.internal else ""))
    sec.add("internal", sp.internal, None, "", "internal mesh", src)
    sec.add("u", g.u, "-", "u", f"tooth ratio z_{p2}/z_{p1}", src)
    sec.add("m_n", g.inp.m_n, "mm", "m_n", "normal module", src)
    if sp.internal:
        sec.add("x_diff", g.x_diff, "-", "x_d", f"shift difference x_{p2} − x_{p1} (GOST sign)",
                src)
    else:
        sec.add("x_sum", g.x_sum, "-", "x_Σ", f"shift sum x_{p1} + x_{p2}", src)
    sec.add("alpha_tw", g.alpha_tw, "rad", "α_tw", "working transverse pressure angle", src)
    sec.add("a", g.a, "mm", "a", "reference centre distance", src)
    sec.add("a_w", g.a_w, "mm", "a_w", "working centre distance", src)
    sec.add("y", g.y, "-", "y", "centre distance modification coefficient", src)
    sec.add("delta_y", g.dy, "-", "Δy", "x_Σ − y (applied to the tips of external meshes only)",
            src)
    sec.add(f"d_w_{p1}", g.g1.d_w, "mm", f"d_w,{p1}", f"working pitch diameter, {p1}", src)
    sec.add(f"d_w_{p2}", g.g2.d_w, "mm", f"d_w,{p2}", f"working pitch diameter, {p2}", src)
    sec.add(f"d_p_{p1}", g.g1.d_p, "mm", f"d_p,{p1}",
            f"lower point of active profile, {p1}", src)
    sec.add(f"d_p_{p2}", g.g2.d_p, "mm", f"d_p,{p2}",
            f"{'outer end' if sp.internal else 'lower point'} of active profile, {p2}", src)
    sec.add("g_w", g.g_w, "mm", "g_w", "N1N2 = a_w sin α_tw", src)
    sec.add("g_alpha", g.g_alpha, "mm", "g_α", "length of the active line of action", src)
    sec.add("p_bt", g.p_bt, "mm", "p_bt", "transverse base pitch", src)
    sec.add("eps_alpha", g.eps_alpha, "-", "ε_α", "transverse contact ratio",
            S.MATUSEVICH + " (31)")
    sec.add("eps_beta", g.eps_beta, "-", "ε_β", "overlap ratio", src)
    sec.add("c_12", g.c_12, "mm", f"c_{p1}", f"radial clearance, {p1} tip to {p2} root", src)
    sec.add("c_21", g.c_21, "mm", f"c_{p2}", f"radial clearance, {p2} tip to {p1} root", src)
    sl = mesh.sliding
    sec.add("theta_p", sl.theta1_A, "-", "ϑ_p",
            f"specific sliding at the {p1} root (meets the {p2} tip)", S.MATUSEVICH + " (32)")
    sec.add("theta_q", sl.theta2_E, "-", "ϑ_q",
            f"specific sliding at the {p2} root (meets the {p1} tip)", S.MATUSEVICH + " (33)")
    sec.add("theta_tip_p", sl.theta1_E, "-", f"ϑ_a,{p1}", f"specific sliding at the {p1} tip",
            S.SLIDING)
    sec.add("theta_tip_q", sl.theta2_A, "-", f"ϑ_a,{p2}", f"specific sliding at the {p2} tip",
            S.SLIDING)
    sec.add("delta_theta", PG.sliding_balance(sl.theta1_A, sl.theta2_E), "-", "Δϑ",
            "sliding imbalance |ϑ_p| − |ϑ_q|", S.MATUSEVICH + " (37)")
    sec.add("eta_p", PG.specific_pressure(g.inp.z1, g.inp.z2, g.alpha_t, g.alpha_tw,
                                          sp.internal), "-", "η",
            "specific-pressure coefficient m/ρ_red", S.MATUSEVICH + " (34)")
    if sp.internal:
        from geardesign.spur.calculator import internal_rows

        internal_rows(sec, g)


def _members_gears(meshes: list[PG.Mesh]) -> dict:
    sp = meshes[0].geom
    gears = {"sun": sp.g1, "planet": sp.g2}
    for mesh in meshes[1:]:
        if mesh.spec.pinion not in gears:
            gears[mesh.spec.pinion] = mesh.geom.g1
        gears[mesh.spec.wheel] = mesh.geom.g2
    return gears


# ----------------------------------------------------------------------------- compute


def _train_and_meshes(spec: ValidatedSpec) -> tuple:
    """The train, its layout, shifts and meshes (synthesised or as given)."""
    d = spec.data
    notes = None
    if d["synthesis"] is not None:
        train, conv, lay, shifts, how, _, notes = _synthesis(spec)
    else:
        train, conv = train_from_teeth(d)
        lay = _layout(d, train)
        _check_operation(train, d["operation"])
        shifts, how, _ = resolve_shifts(d, spec, lay, conv)
    meshes = _geometry(lay, shifts, conv, {g for g, v in d["shift"].items() if v is not None
                                           and f"shift.{g}" not in spec.assumed},
                       shift_origin(d))
    return train, conv, lay, shifts, how, notes, meshes


def _efficiency_inputs(d: dict) -> None:
    eff = d["efficiency"]
    if eff["model"] == "given":
        missing = [Problem(f"efficiency.{key}", "missing; required with efficiency.model "
                                 f"= \"given\": the efficiency of one {key} mesh")
                         for key in ("external", "internal") if eff[key] is None]
        if missing:
            raise InputError(missing)


def _input_stages(spec: ValidatedSpec, problems: Problems) -> tuple:
    """The independent stages of input checks: the train and its meshes, the efficiency
    model's inputs, the strength inputs; each stage's problems are collected."""
    geo = problems.stage(_train_and_meshes, spec)
    problems.stage(_efficiency_inputs, spec.data)
    strength = problems.stage(_strength_inputs, spec)
    return geo, strength


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """:func:`compute`'s input stages on a spec whose schema problems are reported."""
    _input_stages(spec, problems)


def compute(spec: ValidatedSpec) -> Result:
    from geardesign.planetary import CALCULATOR

    d = spec.data
    op = d["operation"]
    problems = Problems()
    geo, strength = _input_stages(spec, problems)
    problems.raise_all()
    train, conv, lay, shifts, how, notes, meshes = geo
    from geardesign.planetary.iso_inputs import prepare

    prepare(spec, train, meshes)
    res = CALCULATOR.new_result(spec)
    if notes is not None:
        sec = res.section("synthesis", "Synthesis")
        for row in notes:
            sec.add(*row)

    _rows_train(res, train, op, conv)
    gears = _members_gears(meshes)
    _gear_rows(res, gears, conv)
    sec = res.section("train", "Train")
    sec.add("shift_source", how, None, "", "how the shifts were obtained", S.COAX)
    for mesh in meshes:
        _mesh_rows(res, mesh)

    checks = geometry_checks(res, d, train, meshes, lay, shifts, conv, gears)
    if d["synthesis"] is None:
        from geardesign.planetary.advice import reconcile

        checks = reconcile(spec, meshes, checks)
    if lay.cutter is None:
        checks.append(check("RING_FORM_CIRCLE", True, "info", "",
                            "the rings' form circles are those of the basic rack; give [cutter] "
                            "for a shaper-cut ring (a smaller form circle) and the cutting "
                            "interference check", None, None, S.G19274))

    # -- kinematics, efficiency, power
    checks += _kinematics_and_power(res, d, train, meshes, lay, strength)
    res.checks.extend(checks)
    return res


def geometry_checks(res: Result, d: dict, train: K.Train, meshes: list[PG.Mesh],
                    lay: PG.Layout, shifts: dict, conv: dict, gears: dict) -> list:
    """The assembly checks (with their rows in ``res``) and the geometry checks of every
    gear and mesh."""
    lim, tr = d["limits"], d["train"]
    checks = _assembly(res, d, train, meshes, lay, shifts, conv, gears)
    alpha_t = {x: meshes[0].geom.alpha_t for x in gears}
    second = {mesh.spec.pinion: mesh.spec.second for mesh in meshes} | \
        {mesh.spec.wheel: mesh.spec.second for mesh in meshes[1:]}
    modules = {x: lay.m2 if second.get(x, False) else lay.m for x in gears}
    checks += C.gear_checks(gears, lay.rack.h_straight, alpha_t, lay.beta, modules,
                            lim["tip_thickness"], tr["allow_undercut"])
    checks += C.mesh_checks(meshes, lim["specific_sliding"])
    return checks


def _assembly(res: Result, d: dict, train: K.Train, meshes: list[PG.Mesh], lay: PG.Layout,
              shifts: dict, conv: dict, gears: dict) -> list:
    """Coaxiality, spacing, neighbours and phasing: rows and checks."""
    lim, tr = d["limits"], d["train"]
    checks = []
    # -- coaxiality
    a_ref = meshes[0].geom.a_w
    needed, sign_note = {}, {}
    for mesh in meshes[1:]:
        ring = mesh.spec.wheel
        try:
            xd = PG.shift_sum_for(lay, mesh.spec, a_ref)
            needed[ring] = _gost_to_user(shifts[mesh.spec.pinion] + xd, conv.get(ring, 1))
        except G.GeometryError:
            needed[ring] = math.nan
        sign_note[ring] = "ISO 21771 sign" if conv.get(ring, 1) < 0 else "GOST 19274-73 sign"
    asec = res.section("assembly", "Assembly conditions")
    for mesh in meshes:
        asec.add(f"a_w_{mesh.name}", mesh.geom.a_w, "mm", f"a_w,{mesh.name}",
                 f"working centre distance of the {C.MESH_NAMES.get(mesh.name)} mesh", S.COAX)
    asec.add("coaxiality_residual", max(abs(m.geom.a_w - a_ref) for m in meshes), "mm", "Δa_w",
             "largest difference of the meshes' centre distances", S.COAX)
    m = lay.m
    checks += C.coaxiality_checks(meshes, lim["coaxiality"] * m, needed, sign_note)

    # -- spacing, neighbours, phasing
    spc = A.spacing(train)
    uneven = tr["spacing"] == "uneven"
    angles = spc.angles
    crowns = [gears["planet"].d_a] + ([gears["planet2"].d_a] if "planet2" in gears else [])
    d_a_max = max(crowns)
    clearance = A.neighbour_clearance(a_ref, d_a_max, math.radians(spc.min_angle
                                                                    if uneven else
                                                                    360.0 / train.planets))
    n_max = A.max_planets(a_ref, d_a_max, lim["neighbour_gap"] * m)
    for x, n in spc.N.items():
        asec.add(f"N_{x}", n, "-", f"N_{x}", f"admissible planet positions per turn ({x} against "
                 "the ring)", S.ASSEMBLY)
    asec.add("equal_spacing", spc.equal_ok, None, "", f"{train.planets} planets can be equally "
             "spaced", S.ASSEMBLY)
    if spc.equal_ok or uneven:
        asec.add("planet_angles", angles, "deg", "θ_i", "angles of the planets", S.ASSEMBLY)
    if train.planets > 1:
        asec.add("neighbour_clearance", clearance, "mm", "c_n",
                 "gap between the tips of neighbouring planets", S.KUDRYAVTSEV)
    asec.add("planets_max", n_max, "-", "n_w,max",
             f"most equally spaced planets with a gap of {lim['neighbour_gap']:g}·m", S.KUDRYAVTSEV)
    ph = A.phasing(train, angles)
    asec.add("phase_sun", ph.sun, "-", "γ_s", "sun-mesh phase of each planet (mesh cycles)",
             S.PHASING)
    asec.add("phase_ring", ph.ring, "-", "γ_r", "ring-mesh phase of each planet (mesh cycles)",
             S.PHASING)
    asec.add("phasing", ph.kind, None, "", "mesh phasing of the planets", S.PHASING)
    checks.append(C.assembly_check(train, spc, uneven, _assembly_advice(train)))
    checks += C.neighbour_checks(clearance, lim["neighbour_gap"], m, n_max, train.planets)
    checks.append(check("PHASING", True, "info", "", f"planet meshes are {ph.kind}"
                        + (" (sun teeth a multiple of the planets: mesh forces add up; a "
                           "sequential phasing cancels part of the mesh excitation)"
                           if ph.kind == "in phase" else ""), None, None, S.PHASING))

    return checks


def _assembly_advice(train: K.Train) -> str:
    k = train.planets
    zb = train.ring
    for step in range(1, k):
        for cand in (zb - step, zb + step):
            t2 = K.Train(train.scheme, train.sun, train.planet, cand, k, train.planet2,
                         train.ring2)
            if cand - train.crown("ring") >= MIN_RING_EXCESS and A.spacing(t2).equal_ok:
                return (f"change the ring to {cand} teeth (and make the meshes coaxial with "
                        f"shifts, train.center_distance)")
    return "change the sun or ring teeth"


def _speeds(train: K.Train, op: dict, unit: bool = False) -> K.Speeds:
    n_in = op["speed"] if op["speed"] is not None and not unit else 1.0
    if op["fixed"] == "none":
        cond = {op["input"]: n_in, op["control"]: op["control_speed"]}
    else:
        cond = {op["fixed"]: 0.0, op["input"]: n_in}
    try:
        return K.speeds(train, cond)
    except K.KinematicsError as exc:
        raise InputError.at("operation.control", op["control"], f"{exc}; choose another "
                            "control member") from None


def _mesh_efficiencies(d: dict, train: K.Train, meshes: list[PG.Mesh]) -> tuple[dict, dict]:
    eff = d["efficiency"]
    by_member, hv = {}, {}
    for mesh in meshes:
        central = "sun" if mesh.spec.pinion == "sun" else mesh.spec.wheel
        H = E.mesh_loss_factor(mesh.geom)
        hv[mesh.name] = H
        if eff["model"] != "given" and not E.loss_factor_applies(mesh.geom.eps_alpha):
            lo, hi = E.EPS_ALPHA_RANGE
            raise InputError.at("efficiency.model", eff["model"], f"the loss factor H_V "
                                f"(Ohlendorf, ISO/TR 14179-2) holds for {lo:g} <= ε_α <= "
                                f"{hi:g}, and the {mesh.name.replace('_', '–')} mesh has ε_α = "
                                f"{mesh.geom.eps_alpha:.4g}: give model = \"given\" with the "
                                f"external and internal mesh efficiencies, or change the "
                                f"geometry")
        if eff["model"] == "given":
            eta = eff["internal"] if mesh.spec.internal else eff["external"]
        else:
            eta = 1.0 - eff["friction"] * H
        by_member[central] = eta
    return by_member, hv


def _kinematics_and_power(res: Result, d: dict, train: K.Train, meshes: list[PG.Mesh],
                          lay: PG.Layout, strength) -> list:
    op = d["operation"]
    out = []
    has_speed = op["speed"] is not None
    s = _speeds(train, op, unit=not has_speed)
    inp, outp, fixed = op["input"], op["output"], op["fixed"]
    two_dof = fixed == "none"
    ksec = res.section("kinematics", "Kinematics (Willis)")
    if has_speed:
        for mbr in train.members:
            ksec.add(f"n_{mbr}", s.n[mbr], "min^-1", f"n_{mbr}", f"speed of the {mbr}", S.WILLIS)
        ksec.add("n_planet", s.n_planet, "min^-1", "n_g", "absolute speed of the planet",
                 S.WILLIS)
        for mbr in train.central:
            ksec.add(f"n_{mbr}_rel", s.rel(mbr), "min^-1", f"n_{mbr}−n_h",
                     f"speed of the {mbr} relative to the carrier", S.WILLIS)
        ksec.add("n_planet_rel", s.n_planet_rel, "min^-1", "n_g−n_h",
                 "speed of the planet relative to the carrier (planet bearing speed)", S.WILLIS)
        if two_dof:
            ksec.add("i", s.n[inp] / s.n[outp] if s.n[outp] != 0 else math.nan, "-", "i",
                     f"ratio n_{inp}/n_{outp} at the imposed {op['control']} speed", S.WILLIS)
        for mesh in meshes:
            g = mesh.geom
            n1 = s.rel("sun") if mesh.spec.pinion == "sun" else s.n_planet_rel
            v = abs(math.pi * n1 / 30.0) * g.g1.d_w / 2000.0
            ksec.add(f"v_{mesh.name}", v, "m/s", f"v_{mesh.name}",
                     f"pitch-line velocity of the {C.MESH_NAMES.get(mesh.name)} mesh (relative "
                     "to the carrier)", S.SLIDING)
            sv = velocities(g, abs(n1))   # ω1 ± ω2: external or internal mesh
            vs = max(abs(sv.v_s_A), abs(sv.v_s_E))
            ksec.add(f"v_s_{mesh.name}", vs, "m/s", f"v_s,{mesh.name}",
                     f"largest sliding velocity of the {C.MESH_NAMES.get(mesh.name)} mesh",
                     S.SLIDING)

    # -- efficiency
    eta, hv = _mesh_efficiencies(d, train, meshes)
    esec = res.section("efficiency", "Efficiency and self-locking")
    for mesh in meshes:
        central = "sun" if mesh.spec.pinion == "sun" else mesh.spec.wheel
        mn = C.MESH_NAMES.get(mesh.name)
        if E.loss_factor_applies(mesh.geom.eps_alpha):   # else only a given efficiency
            esec.add(f"H_V_{mesh.name}", hv[mesh.name], "-", f"H_V,{mesh.name}",
                     f"tooth loss factor of the {mn} mesh", S.HV)
        esec.add(f"eta_{mesh.name}", eta[central], "-", f"η_{mesh.name}",
                 f"efficiency of the {mn} mesh", S.HV if d["efficiency"]["model"] == "niemann"
                 else "spec")
    for x, y in (("sun", "ring"), ("ring2", "ring")):
        if x in train.central and y in train.central:
            esec.add(f"eta_h_{x}_{y}", eta[x] * eta[y], "-", f"η^h_{x},{y}",
                     f"fixed-carrier efficiency of the chain {x} → {y}", S.TORQUE)
    loaded = train.loaded
    control = op["control"] if two_dof else None
    unknown = (outp, control) if two_dof else (fixed, outp)
    sign_in = 1.0 if s.n[inp] > 0 else -1.0
    f_fwd = E.flow(train, s, eta, inp, sign_in, unknown, driven=outp)
    driving = (inp, control) if two_dof else (inp,)
    if two_dof:
        eta_f = -sum(min(f_fwd.P[mb], 0.0) for mb in loaded) / \
            sum(max(f_fwd.P[mb], 0.0) for mb in loaded)
    else:
        eta_f = E.efficiency(f_fwd, (inp,), outp)
    esec.add("eta", eta_f, "-", "η", f"efficiency {inp} → {outp}"
             + (" (all outputs/all inputs)" if two_dof else ""), S.TORQUE)
    if two_dof:
        esec.add("eta_branch", E.efficiency(f_fwd, driving, outp), "-", "η_13",
                 f"branch efficiency −P_{outp}/(P_{inp} + P_{control}) with the {control} "
                 "controlled", S.MALASHCHENKO)
    # reverse
    sign_out = 1.0 if s.n[outp] > 0 else -1.0
    unknown_r = tuple(mb for mb in unknown if mb != outp) + (inp,)
    f_rev = E.flow(train, s, eta, outp, sign_out, unknown_r, driven=inp)
    eta_r = E.efficiency(f_rev, (outp, control) if two_dof else (outp,), inp)
    self_locking = (not f_rev.consistent) or not eta_r > 0.0
    esec.add("eta_reverse", eta_r, "-", "η'", f"reverse efficiency {outp} → {inp} (formal value; "
             "≤ 0 or no consistent power flow: self-locking)", S.TORQUE)
    esec.add("self_locking", self_locking, None, "", "the output cannot drive the input",
             S.TORQUE)
    out += C.efficiency_checks(f_fwd.consistent, eta_f, f_rev.consistent, eta_r,
                               d["efficiency"]["self_locking"],
                               d["efficiency"]["near_self_locking"])

    # -- torques and power flow
    T_in = op["torque"]
    if T_in is None and op["power"] is not None:
        T_in = 30000.0 * op["power"] / (math.pi * abs(op["speed"]))
    ideal = E.flow(train, s, {x: 1.0 for x in train.central}, inp, sign_in, unknown)
    if T_in is not None:
        f = E.flow(train, s, eta, inp, sign_in * T_in, unknown, driven=outp)
        psec = res.section("power", "Torques and power flow")
        for mbr in train.members:
            if mbr in loaded:
                psec.add(f"T_{mbr}", f.T[mbr], "N·m", f"T_{mbr}",
                         f"torque on the {mbr} (with mesh losses)", S.TORQUE)
        for mbr in train.members:
            if mbr in loaded:
                psec.add(f"T_{mbr}_ideal", ideal.T[mbr] * T_in, "N·m", f"T_{mbr},0",
                         f"torque on the {mbr} without losses", S.WILLIS)
        if has_speed:
            for mbr in train.members:
                if mbr in loaded:
                    psec.add(f"P_{mbr}", f.P[mbr], "kW", f"P_{mbr}",
                             f"power delivered by the {mbr} (> 0 input, < 0 output)", S.TORQUE)
            for mesh in meshes:
                central = "sun" if mesh.spec.pinion == "sun" else mesh.spec.wheel
                P_rel = abs(f.P_mesh[central])
                psec.add(f"P_mesh_{mesh.name}", P_rel, "kW", f"P_{mesh.name}",
                         f"rolling power of the {C.MESH_NAMES.get(mesh.name)} meshes (all "
                         "planets, carrier frame)", S.TORQUE)
                psec.add(f"P_loss_{mesh.name}", P_rel * (1.0 - eta[central]) /
                         (eta[central] if f.k[central] < 0 else 1.0), "kW",
                         f"P_V,{mesh.name}", "power lost in these meshes", S.HV)
            P_in = abs(f.P[inp])
            if P_in > 0.0:
                psec.add("circulating_ratio", max(abs(v) for v in f.P_mesh.values()) / P_in,
                         "-", "P_mesh/P_in", "largest rolling power over the input power "
                         "(circulating power when > 1)", S.KUDRYAVTSEV)
        from geardesign.planetary.strength import planet_bearing_load
        ideal_T = {x: ideal.T[x] * T_in for x in train.members}
        bl = planet_bearing_load(train, meshes, ideal_T, 1.0, s.n_planet_rel)
        bsec = res.section("planet_bearing", "Planet bearing")
        bsec.add("F_bearing", bl.F_r, "N", "F_r", "load on one planet bearing (vector sum of the "
                 "mesh forces, nominal torque, no K_γ)", S.KUDRYAVTSEV)
        bsec.add("F_bearing_t", bl.F_t, "N", "F_t", "its component along the carrier's motion",
                 S.KUDRYAVTSEV)
        bsec.add("F_bearing_r", bl.F_n, "N", "F_n", "its component along the carrier radius",
                 S.KUDRYAVTSEV)
        if has_speed:
            bsec.add("n_bearing", bl.n, "min^-1", "n", "speed of the planet on its bearing",
                     S.WILLIS)
        if strength is not None:
            out += _strength(res, d, train, meshes, s, ideal_T, strength)

    # -- frequencies
    if has_speed:
        _frequencies(res, d, train, s)
    return out


def _frequencies(res: Result, d: dict, train: K.Train, s: K.Speeds) -> None:
    fq = d["frequencies"]
    fr = K.frequencies(train, s)
    sec = res.section("frequencies", "Frequencies for diagnostics")
    for mbr in train.members:
        sec.add(f"f_{mbr}", fr.f[mbr], "Hz", f"f_{mbr}", f"rotation frequency of the {mbr}",
                S.BELAZ)
    for mbr, v in fr.f_rel.items():
        sec.add(f"f_{mbr}_rel", v, "Hz", f"f_{mbr},rel",
                f"rotation frequency of the {mbr} relative to the carrier", S.BELAZ)
    sec.add("f_mesh", fr.f_mesh, "Hz", "f_z", "mesh frequency z_a|f_a − f_h|", S.BELAZ)
    if fr.f_mesh2 is not None:
        sec.add("f_mesh2", fr.f_mesh2, "Hz", "f_z2", "mesh frequency of the second crown's mesh",
                S.BELAZ)
    sec.add("f_mesh_harmonics", [h * fr.f_mesh for h in range(1, fq["harmonics"] + 1)], "Hz",
            "h·f_z", "mesh harmonics", S.BELAZ)
    delta = fq["speed_fluctuation"]
    sec.add("f_mesh_band", [fr.f_mesh * (1 - delta), fr.f_mesh * (1 + delta)], "Hz",
            "f_z(1 ± δ)", "mesh frequency band for the admissible speed fluctuation", S.BELAZ)
    sec.add("planet_pass", fr.planet_pass, "Hz", "f_pp", "planet-pass frequency n_w|f_b − f_h|",
            S.BELAZ)
    for mbr, v in fr.fault.items():
        sec.add(f"f_fault_{mbr}", v, "Hz", f"f_d,{mbr}",
                f"local-fault frequency of the {mbr}", S.BELAZ)
    for mbr in ("sun", "planet", "ring"):
        sec.add(f"sidebands_{mbr}", K.sidebands(fr.f_mesh, fr.fault[mbr], fr.f_carrier,
                                                fq["harmonics"], fq["sideband_orders"]),
                "Hz", f"h f_z ± k f_d ± l f_h ({mbr})",
                f"sideband families around the mesh harmonics, {mbr} fault", S.BELAZ)
    amps, base = fq["amplitudes"], fq["baseline"]
    if base is not None and amps is None:
        raise InputError(Problem("frequencies.amplitudes", "missing; required with "
                                 "frequencies.baseline: the amplitudes measured now"))
    if amps is not None:
        Sd = K.discriminant(amps)
        sec.add("S_fz", Sd, "m/s^2", "S_fz", "discriminant: root sum of squares of the harmonic "
                "amplitudes", S.BELAZ + " (1)")
        if base is not None:
            if len(base) != len(amps):
                raise InputError.at("frequencies.baseline", base,
                                    f"has {len(base)} values, frequencies.amplitudes "
                                    f"{len(amps)}; give the same harmonics")
            S0 = K.discriminant(base)
            if S0 <= 0.0:
                raise InputError.at("frequencies.baseline", base, "all zero: the relative "
                                    "growth needs a non-zero baseline")
            sec.add("S_fz0", S0, "m/s^2", "S_fz0", "discriminant at the start of monitoring",
                    S.BELAZ + " (1)")
            sec.add("P_fz", K.relative_growth(Sd, S0), "-", "P_fz",
                    "relative growth of the discriminant", S.BELAZ + " (2)")


# ----------------------------------------------------------------------------- strength


def _strength_inputs(spec: ValidatedSpec):
    """The materials of the strength calculation (``None`` without [strength] and
    [material]); every missing piece is reported in one round."""
    d = spec.data
    st, mat, op = d["strength"], d["material"], d["operation"]
    torque = op["torque"] is not None or op["power"] is not None
    if st is None and mat is None:
        return None
    problems = Problems()
    if st is None:
        problems.add(Problem("strength", "missing table [strength] (life_hours, ...): "
                             "required with [material]"))
    if mat is None:
        problems.add(Problem("material", "missing table [material.sun], [material.planet], "
                             "[material.ring]: required with [strength]"))
    if not torque:
        problems.add(Problem("operation.torque", "missing; required with [strength]: the "
                             "input torque in N·m (or operation.power in kW)"))
    if op["speed"] is None:
        problems.add(Problem("operation.speed", "missing; required with [strength]: the "
                             "input speed"))
    from geardesign.materials.gear_steel import resolve

    mats = {}
    for key in ("sun", "planet", "ring", "planet2", "ring2"):
        if mat is not None and mat[key] is not None:
            mats[key] = problems.stage(lambda key=key: resolve(mat[key], f"material.{key}"))
    problems.raise_all()
    mats.setdefault("planet2", mats["planet"])
    mats.setdefault("ring2", mats["ring"])
    return mats


_RATING_SECTIONS = ("forces", "life", "factors", "contact", "bending", "static")


def _strength(res: Result, d: dict, train: K.Train, meshes: list[PG.Mesh], s: K.Speeds,
              T_ideal: dict, mats: dict) -> list:
    from geardesign.planetary.strength import mesh_duties, rate_mesh
    from geardesign.spur.checks import strength_checks
    from geardesign.spur.strength import method
    from geardesign.spur.strength.rating import Setting

    st, op = d["strength"], d["operation"]
    rate = method(st["method"]).rate
    out = []
    if st.get("scuffing") is not None and st["method"] != "ISO 6336:2019":
        from geardesign.core.result import check

        out.append(check("SCUFFING_NOT_RATED", False, "warning",
                         "[strength.scuffing] is not rated: scuffing is rated by ISO/TS 6336-21 "
                         "with the ISO 6336 rating; set strength.method = \"ISO 6336:2019\"",
                         "", None, None, "[ISO6336-21]"))
    res.methods.append(st["method"])
    # a crown meshing a sun and a ring is loaded on both flanks (alternating bending)
    both = {"planet": train.scheme != "2K-H-stepped", "planet2": False}
    iso = st["method"] == "ISO 6336:2019"
    # ISO 6336 takes K_γ as its own factor: the duties carry the nominal force
    duties = mesh_duties(train, meshes, s, T_ideal, 1.0 if iso else st["load_sharing"], both)
    T_in = abs(T_ideal[op["input"]])
    peak_ratio = st["peak_torque"] / T_in if st["peak_torque"] is not None else None
    if peak_ratio is not None and peak_ratio < 1.0:
        raise InputError.at("strength.peak_torque", st["peak_torque"],
                            f"smaller than the input torque {_fmt(T_in)} N·m; give the largest "
                            f"short-time torque")
    from geardesign.materials.gear_steel import data_used

    msec = res.section("materials", "Materials")
    for key, m in mats.items():
        if key in ("planet2",) and train.planet2 is None or key == "ring2" and \
                train.scheme != "3K":
            continue
        msec.add(f"material_{key}", m.label, None, f"mat_{key}", key,
                 "library" if not m.given else "library + spec")
        msec.add(f"material_{key}_source", data_used(m), None, f"src_{key}",
                 f"data used, {key}", "library" if m.grade else "spec")
        msec.add(f"HB_{key}", m.HB, "HB", f"HB_{key}", "surface hardness in HB (converted)",
                 "GOST 21354-87 (ZPCIL fit)")
    rated = []
    for mesh, md in zip(meshes, duties):
        if iso:
            from geardesign.spur.calculator import ratable

            if not ratable(mesh.geom):
                from geardesign.core.result import check

                out.append(check(
                    f"{mesh.name.upper()}_STRENGTH_NOT_RATED", False, "error",
                    f"{C.MESH_NAMES.get(mesh.name)}: the strength was not rated: this mesh "
                    f"cannot run as computed (ε_α < 1, a tip beyond the mate's tangency point "
                    f"or a pointed tooth; see the failed geometry checks); correct the "
                    f"geometry first", "", None, None, "[ISO6336-2]"))
                continue
        overrides = {}
        if mesh.spec.internal and st.get("ring_form_factor") is not None:
            overrides["Y_FS2"] = st.get("ring_form_factor")
        ra = tuple(_material_table(d, mb)["roughness_Ra"] for mb in md.members)
        # the GOST-only keys are left out of an ISO 6336 spec (iso_inputs.prepare)
        setting = Setting(st["accuracy_grade"], st.get("tip_relief", False),
                          st.get("bearing_scheme"), ra, overrides)
        pair = (mats[md.members[0]], mats[md.members[1]])
        mesh_rate = rate
        if iso:
            from geardesign.planetary.iso_inputs import mesh_rate_function

            mesh_rate = mesh_rate_function(rate, d, train, meshes, mesh, md)
        rating = rate_mesh(mesh_rate, md, pair, st["application_factor"], st["life_hours"],
                           st.get("regime"), (), peak_ratio, setting)
        mn = C.MESH_NAMES.get(mesh.name)
        sec = res.section(f"strength_{mesh.name}", f"Strength of the {mn} mesh "
                          f"({md.members[0]} = gear 1, {md.members[1]} = gear 2)")
        sec.add("gear1", md.members[0], None, "", "gear 1 of the rating", S.G21354)
        sec.add("gear2", md.members[1], None, "", "gear 2 of the rating", S.G21354)
        sec.add("F_t_planet", md.F_t, "N", "F_t", "tangential force on one planet at the "
                "reference circle" + (" (ISO 6336: nominal, K_γ a factor of its own)" if iso
                                      else ", with K_γ"), S.KUDRYAVTSEV)
        sec.add("n1_rel", md.n1, "min^-1", "n_1", "speed of gear 1 relative to the carrier",
                S.WILLIS)
        for row in rating.rows:
            sec.add(row.key, row.value, row.unit, row.symbol, _members_words(row.name, md.members),
                    row.source)
        if iso:
            from geardesign.spur.strength.iso6336.rating import rating_checks

            found = rating_checks(rating, bool(mesh.spec.internal))
        else:
            found = strength_checks(rating.v, pair, mesh.geom.inp.beta > 0.0,
                                    st["accuracy_grade"], peak_ratio is not None)
        for c in found:
            out.append(_rename(c, mesh.name, md.members))
        rated.append(rating.v)
    if rated:   # a load typed in a unit a thousand times too small: the lightest mesh
        from geardesign.core.units_guard import given
        from geardesign.spur.checks import contact_load_fraction, light_load_checks

        v = min(rated, key=lambda x: contact_load_fraction(x)[0])
        out.extend(light_load_checks(v, given(op, {"torque": "N·m", "power": "kW"},
                                              "operation")))
    return out


def _material_table(d: dict, member: str) -> dict:
    """The [material.X] table of a member (planet2 and ring2 fall back to the planet's
    and the ring's)."""
    mat = d["material"]
    if mat.get(member) is None:
        member = {"planet2": "planet", "ring2": "ring"}[member]
    return mat[member]


def _members_words(text: str, members: tuple[str, str]) -> str:
    """The spur rating's words "pinion" and "wheel" replaced by the members' names."""
    import re

    return re.sub(r"\bwheel\b", members[1], re.sub(r"\bpinion\b", members[0], text))


def _rename(c, mesh: str, members: tuple[str, str]):
    """A spur strength check for one mesh: the code carries the mesh, the words name the
    members instead of pinion and wheel."""
    from dataclasses import replace

    msg = _members_words(c.message, members).replace("load.peak_torque1",
                                                      "strength.peak_torque")
    code = c.code.replace("PINION", members[0].upper()).replace("WHEEL", members[1].upper())
    return replace(c, code=f"{mesh.upper()}_{code}", message=f"{C.MESH_NAMES.get(mesh)}: {msg}")


# ----------------------------------------------------------------------------- synthesis


def _synthesis(spec: ValidatedSpec):
    from geardesign.planetary import synthesis as SY

    d = spec.data
    sy, tr, op = d["synthesis"], d["train"], d["operation"]
    for key, v in d["shift"].items():
        if v is not None:
            raise InputError.at(f"shift.{key}", v, "the synthesis mode chooses the shifts; "
                                "remove [shift] (or use [teeth] to analyse a given train)")
    for key in ("center_distance", "working_angle", "module2", "face_width2"):
        if tr[key] is not None:
            raise InputError.at(f"train.{key}", tr[key], "does not apply to the synthesis mode; "
                                "remove it")
    scheme = tr["scheme"]
    if scheme == "2K-H-stepped":
        raise InputError.at("train.scheme", scheme, "the synthesis mode handles \"2K-H\" and "
                            "single-crown \"3K\" trains; give [teeth] for a stepped planet")
    probe = K.Train(scheme, 20, 20, 60, tr["planets"], None, 63 if scheme == "3K" else None)
    _check_operation(probe, op)
    if op["fixed"] == "none":
        raise InputError.at("operation.fixed", "none", "the synthesis mode needs a fixed member "
                            "(a ratio between two members)")
    lay = _layout(d, probe)
    lim = d["limits"]
    found, n_cand, n_eval = SY.search(
        scheme, tr["planets"], op["fixed"], op["input"], op["output"], sy["ratio"],
        sy["tolerance"], sy["sun_min"], sy["planet_min"], sy["ring_max"], sy["sum_deviation"],
        lay, lim["neighbour_gap"], lim["tip_thickness"], lim["specific_sliding"],
        sy["candidates"])
    if not found:
        why = ("no tooth numbers give this ratio within the tolerance with equal spacing"
               if n_cand == 0 else
               f"none of the {n_eval} best of {n_cand} tooth-number candidates passes the "
               f"geometric checks")
        raise InputError.at("synthesis.ratio", sy["ratio"],
                            f"{why}; widen synthesis.tolerance, raise synthesis.ring_max or "
                            f"synthesis.sum_deviation, lower synthesis.sun_min/planet_min, or "
                            f"change train.planets")
    best = found[0]
    train = best.train
    lay = PG.Layout(train, lay.m, lay.m2, lay.beta, lay.b_w, lay.b_w2, lay.rack, lay.ring_rack,
                    lay.k2, lay.cutter)
    conv = {"ring": 1, "ring2": 1}
    rows = [
        ("target_ratio", sy["ratio"], "-", "i*", "required ratio (magnitude)", "spec"),
        ("tooth_candidates", n_cand, "-", "", "tooth-number sets within the tolerance with "
         "equal spacing", S.SYNTHESIS),
        ("evaluated", n_eval, "-", "", "candidates whose geometry was checked", S.SYNTHESIS),
        ("found", len(found), "-", "", "candidates that pass every geometric check",
         S.SYNTHESIS),
        ("cand_sun", [c.train.sun for c in found], "-", "z_a", "sun teeth of the candidates",
         S.SYNTHESIS),
        ("cand_planet", [c.train.planet for c in found], "-", "z_g", "planet teeth",
         S.SYNTHESIS),
        ("cand_ring", [c.train.ring for c in found], "-", "z_b", "ring teeth", S.SYNTHESIS),
    ]
    if scheme == "3K":
        rows.append(("cand_ring2", [c.train.ring2 for c in found], "-", "z_e",
                     "second ring teeth", S.SYNTHESIS))
    rows += [
        ("cand_ratio", [c.ratio for c in found], "-", "i", "ratio of the candidates",
         S.SYNTHESIS),
        ("cand_error", [c.error for c in found], "%", "Δi", "ratio error", S.SYNTHESIS),
        ("cand_a_w", [c.a_w for c in found], "mm", "a_w", "centre distance", S.SYNTHESIS),
        ("cand_x_sun", [c.shifts["sun"] for c in found], "-", "x_a", "sun shift", S.SYNTHESIS),
        ("cand_d_ring", [c.d_ring for c in found], "mm", "d_f,b", "ring root diameter (size)",
         S.SYNTHESIS),
        ("chosen", f"z = {train.sun}/{train.planet}/{train.ring}"
         + (f"/{train.ring2}" if scheme == "3K" else "")
         + f", a_w = {best.a_w:.4f} mm", None, "", "candidate analysed below (the first)",
         S.SYNTHESIS),
    ]
    d["teeth"] = None
    return train, conv, lay, best.shifts, "synthesis: a_w of the largest reference centre " \
        "distance, sun–planet split of equal specific sliding", best.a_w, rows
