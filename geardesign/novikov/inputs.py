"""The spec of a Novikov pair read into typed inputs (mm, rad, N·m, µm, HB): every rule
across keys that the schema cannot state is checked here, and every independent problem of
a spec is reported in the same round (:class:`~geardesign.core.errors.Problems`)."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.novikov.geometry import (
    GeometryError,
    NovikovPair,
    engaged_teeth,
    helix_for_center_distance,
    pair_geometry,
    phase_points,
    table1_points,
)
from geardesign.novikov.rack import STANDARD, NovikovRack, standard_rack

SHIFT_SUM_TOL = 1e-9
RACK_KEYS = ("profile_angle", "lk_star", "eps_q", "addendum_coef", "dedendum_coef")
EPS_BETA_MAX = 8.0
"""Scope of the phase analysis: Korotkin's Table 1 lists tooth pairs up to ε_β ≈ 5; beyond
ε_β = 8 the loop would also be slow (the work grows with ε_β²·f_z)."""


def fmt(x: float) -> str:
    """A number for a message: four decimals at most, no trailing zeros."""
    return f"{x:.4f}".rstrip("0").rstrip(".")


@dataclass(frozen=True)
class Material:
    """One gear's steel: hardness [HB] and the endurance limits given in the spec [MPa]
    (``None``: from the hardness, GOST 21354-87)."""

    hardness: float
    sigma_Hlim: float | None
    sigma_Flim: float | None


@dataclass(frozen=True)
class Inputs:
    """A Novikov pair, its accuracy, duty and phase-analysis settings."""

    pair: NovikovPair
    how: str                          # how β was obtained ("given", "from the centre distance")
    # accuracy and the error model
    error_model: str
    grade_smoothness: int
    grade_contact: int
    risk: float
    misalignment: float               # [rad]
    end_relief: float                 # [mm]
    pitch_errors: dict                # tooth pair -> gap [µm] (explicit model)
    lead_error: float                 # [µm] (explicit model)
    # duty
    torque2: float                    # [N·m]
    application_factor: float
    speed1: float | None              # [min⁻¹]
    life: float | None                # [h]
    reversing: bool
    # phase analysis
    phases: int
    mesh_stiffness: float             # [N/(mm·µm)]
    point_stiffness: float | None     # [N/µm]
    pinion: Material
    wheel: Material


def rack_from_spec(spec: ValidatedSpec) -> NovikovRack:
    """The basic rack: GOST 15023-76 from ``racks.toml``, or a custom rack whose five
    constants must all be given."""
    r = spec.data["rack"]
    if r["name"] == STANDARD:
        given = [key for key in RACK_KEYS if r[key] is not None]
        if given:
            raise InputError([Problem(
                f"rack.{key}", f'applies only to rack.name = "custom" (the {STANDARD} values '
                f'are data); remove it or set rack.name = "custom"', r[key]) for key in given])
        return standard_rack()
    missing = [k for k in RACK_KEYS if r[k] is None]
    if missing:
        raise InputError([Problem(f"rack.{k}", 'missing; required for rack.name = "custom"')
                          for k in missing])
    return NovikovRack("custom", math.radians(r["profile_angle"]), r["lk_star"], r["eps_q"],
                       r["addendum_coef"], r["dedendum_coef"], verified=False)


def helix_from_spec(spec: ValidatedSpec) -> tuple[float, str]:
    """The helix angle [rad], given or following from the centre distance, and how."""
    g = spec.data["gear"]
    m, z1, z2 = g["module"], g["z1"], g["z2"]
    beta_deg, a_w = g["helix_angle"], g["center_distance"]
    if beta_deg is None and a_w is None:
        raise InputError(Problem("gear.helix_angle", "missing; required: give gear.helix_angle "
                                 "or gear.center_distance (β then follows from it)"))
    if beta_deg is not None and a_w is not None:
        raise InputError.at("gear.center_distance", a_w,
                            "give either gear.helix_angle or gear.center_distance, not both")
    if a_w is None:
        return math.radians(beta_deg), "given"
    a0 = 0.5 * m * (z1 + z2)
    a45 = a0 / math.cos(math.radians(45.0))
    try:
        beta = helix_for_center_distance(a_w, m, z1, z2)
    except GeometryError:
        beta = None
    if beta is None or beta >= math.radians(45.0):
        raise InputError.at(
            "gear.center_distance", a_w,
            f"gives no helix angle in 0…45°: must be > m(z1 + z2)/2 = {fmt(a0)} mm and "
            f"< m(z1 + z2)/(2cos 45°) = {fmt(a45)} mm")
    return beta, "from the centre distance"


def shift_sum(spec: ValidatedSpec) -> None:
    """x1 + x2 = 0: a Novikov pair works at the standard centre distance."""
    g = spec.data["gear"]
    if abs(g["x1"] + g["x2"]) > SHIFT_SUM_TOL:
        raise InputError(Problem(
            "gear.x1 + gear.x2", f"must be 0: a Novikov pair works at the standard centre "
            f"distance m(z1 + z2)/(2cos β); use x2 = {-g['x1']:g}", g["x1"] + g["x2"]))


def pair_from_spec(spec: ValidatedSpec, rack: NovikovRack) -> tuple[NovikovPair, str]:
    """The pair of a spec; the helix angle is given or follows from the centre distance."""
    shift_sum(spec)
    beta, how = helix_from_spec(spec)
    return _pair(spec, rack, beta), how


def _pair(spec: ValidatedSpec, rack: NovikovRack, beta: float) -> NovikovPair:
    g = spec.data["gear"]
    return NovikovPair(g["module"], g["z1"], g["z2"], beta, g["face_width"], g["x1"], g["x2"],
                       rack)


def engaged(spec: ValidatedSpec, pair: NovikovPair) -> list[int]:
    """The tooth pairs in engagement over one axial pitch; the face width must keep ε_β
    within the scope of the phase analysis (:data:`EPS_BETA_MAX`)."""
    g = pair_geometry(pair)
    if g.eps_beta > EPS_BETA_MAX:
        b_max = EPS_BETA_MAX * g.p_x
        raise InputError.at(
            "gear.face_width", pair.b_w,
            f"gives ε_β = {g.eps_beta:.4f} > {EPS_BETA_MAX:g}, beyond the scope of the phase "
            f"analysis (Korotkin's Table 1 covers ε_β up to about 5); make the face width at "
            f"most {math.floor(b_max * 100) / 100:.2f} mm or reduce the helix angle")
    points = table1_points(g.eps_beta, pair.rack.eps_q)
    return engaged_teeth(phase_points(points, g.eps_beta, spec.data["analysis"]["phases"]))


def explicit_only(spec: ValidatedSpec) -> None:
    """The gaps and lead of ``error_model = "explicit"`` are not given with another model."""
    acc = spec.data["accuracy"]
    if acc["error_model"] == "explicit":
        return
    given = [key for key in ("pitch_errors", "lead_error") if acc[key] is not None]
    if given:
        raise InputError([Problem(
            f"accuracy.{key}", f'applies only with accuracy.error_model = "explicit"; remove '
            f'it or set error_model = "explicit"', acc[key]) for key in given])


def explicit_errors(spec: ValidatedSpec, teeth: list[int]) -> tuple[dict[int, float], float]:
    """Per-tooth gaps and lead of ``error_model = "explicit"`` (one gap per tooth pair in
    engagement); an absent lead error is assumed 0."""
    acc = spec.data["accuracy"]
    if acc["error_model"] != "explicit":
        return {}, 0.0
    n = len(teeth)
    pe = acc["pitch_errors"]
    if pe is None:
        raise InputError(Problem(
            "accuracy.pitch_errors", f'missing; required with accuracy.error_model = "explicit": '
            f"{n} values in µm, one per tooth pair in engagement (pairs {teeth[0]}…{teeth[-1]} "
            f"of Korotkin's Table 1)"))
    if len(pe) != n:
        raise InputError.at(
            "accuracy.pitch_errors", pe,
            f"needs {n} values, one per tooth pair in engagement (pairs {teeth[0]}…{teeth[-1]} "
            f"of Korotkin's Table 1), got {len(pe)}")
    if acc["lead_error"] is None:
        acc["lead_error"] = 0.0
        spec.assumed.append("accuracy.lead_error")
    return dict(zip(teeth, pe)), acc["lead_error"]


def life_needs_speed(spec: ValidatedSpec) -> None:
    """The number of cycles 60·n1·L_h needs the speed with the life."""
    load = spec.data["load"]
    if load["life"] is not None and load["speed1"] is None:
        raise InputError.at("load.life", load["life"],
                            "needs load.speed1 (the number of cycles is 60·n1·L_h); give "
                            "speed1 or remove life")


def _stages(spec: ValidatedSpec, problems: Problems):
    """The independent stages of input checks, each stage's problems collected: the rack,
    the shifts, the helix angle, the explicit model's keys, the duty; then, on a pair that
    could be built, the face width (ε_β) and the explicit gaps."""
    rack = problems.stage(rack_from_spec, spec)
    problems.stage(shift_sum, spec)
    helix = problems.stage(helix_from_spec, spec)
    only = problems.stage(explicit_only, spec)
    problems.stage(life_needs_speed, spec)
    if rack is Problems.FAILED or helix is Problems.FAILED:
        return None
    pair = problems.stage(_pair, spec, rack, helix[0])
    if pair is Problems.FAILED:
        return None
    teeth = problems.stage(engaged, spec, pair)
    if teeth is Problems.FAILED or only is Problems.FAILED:
        return None
    errors = problems.stage(explicit_errors, spec, teeth)
    if errors is Problems.FAILED:
        return None
    return pair, helix[1], errors


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The input stages on a spec whose schema problems are reported."""
    _stages(spec, problems)


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated spec; every independent problem in one
    :class:`InputError`."""
    problems = Problems()
    found = _stages(spec, problems)
    problems.raise_all()
    pair, how, (pitch_errors, lead_error) = found
    d = spec.data
    acc, load, ana, mat = d["accuracy"], d["load"], d["analysis"], d["material"]
    materials = [Material(mat[w]["hardness"], mat[w]["sigma_Hlim"], mat[w]["sigma_Flim"])
                 for w in ("pinion", "wheel")]
    return Inputs(
        pair, how, acc["error_model"], acc["grade_smoothness"], acc["grade_contact"],
        acc["risk"], math.radians(acc["misalignment"]), acc["end_relief"], pitch_errors,
        lead_error, load["torque2"], load["application_factor"], load["speed1"],
        load["life"], bool(load["reversing"]), ana["phases"], ana["mesh_stiffness"],
        ana["point_stiffness"], *materials)
