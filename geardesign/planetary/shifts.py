"""The profile shifts of a planetary train from its spec: as given, or following from the
centre distance (or working angle) by coaxiality; the meshes they give, where an impossible
mesh is an input error on the shift the user gave or on the input a derived shift follows
from.  Internal gears' shifts in the user's sign convention (GOST 19274-73 or ISO 21771)."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.spec import ValidatedSpec
from geardesign.planetary import checks as C
from geardesign.planetary import geometry as PG
from geardesign.gears import geometry as G
from geardesign.gears import internal as I

X_AGREE = 1e-3     # |given shift − shift from a_w| accepted when both are given


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


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


