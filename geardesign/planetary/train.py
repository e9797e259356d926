"""The train of a planetary spec: tooth numbers and sign conventions, the layout (modules,
helix, face widths, basic racks, the shaper cutter) and the operation (fixed, input, output
and control members); a rule across keys is a one-line :class:`InputError`."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.planetary import geometry as PG
from geardesign.planetary import kinematics as K
from geardesign.gears import geometry as G
from geardesign.gears import internal as I

MIN_RING_EXCESS = I.MIN_TEETH_DIFFERENCE  # ring teeth over its planet crown's, at least


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
