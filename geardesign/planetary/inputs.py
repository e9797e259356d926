"""The spec of a planetary train read into typed inputs: the train, its layout, the shifts
and the meshes they give (synthesised or as given), the operation, the materials of the
strength rating.  Every rule across keys that the schema cannot state raises a one-line
:class:`InputError` here; the independent stages of a spec are reported in one round
(:class:`Problems`)."""

from __future__ import annotations

import math
from types import MappingProxyType
from typing import Mapping

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.gears import losses as E
from geardesign.planetary import geometry as PG
from geardesign.planetary import kinematics as K
from geardesign.planetary import sources as S
from geardesign.planetary.shifts import _geometry, resolve_shifts, shift_origin
from geardesign.planetary.train import (
    _check_operation,
    _layout,
    train_from_teeth,
)

def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


@dataclass(frozen=True)
class Inputs:
    """A planetary train ready to solve.  ``data`` is the validated spec, read-only, for
    the tables read as they are (operation, limits, efficiency, frequencies, strength and
    the ISO 6336 inputs prepared by :func:`geardesign.planetary.iso_inputs.prepare`)."""

    train: K.Train
    conv: Mapping[str, int]          # sign convention of each ring (+1 GOST, −1 ISO)
    lay: PG.Layout
    shifts: Mapping[str, float]      # GOST sign
    how: str                         # how the shifts were obtained
    synthesis: tuple | None          # report rows of the synthesis mode
    meshes: tuple[PG.Mesh, ...]
    mats: Mapping | None             # materials of the strength rating by member
    data: Mapping

    @property
    def op(self) -> Mapping:
        return self.data["operation"]


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


def _material_table(d: dict, member: str) -> dict:
    """The [material.X] table of a member (planet2 and ring2 fall back to the planet's
    and the ring's)."""
    mat = d["material"]
    if mat.get(member) is None:
        member = {"planet2": "planet", "ring2": "ring"}[member]
    return mat[member]


def _undercut_free(lay) -> int:
    """The fewest teeth the layout's rack cuts without undercut and without a shift:
    z ≥ 2(h_l* − h_a*)·cos β / sin² α_t ([GOST16532]; :func:`geardesign.gears.geometry.
    undercut_shift_limit` = 0), 18 for the GOST 13755-81 rack of a spur gear."""
    import math

    from geardesign.gears.geometry import undercut_shift_limit

    alpha_t = math.atan(math.tan(lay.rack.alpha_n) / math.cos(lay.beta))
    z = 5
    while undercut_shift_limit(z, alpha_t, lay.beta, lay.rack) > 0.0 and z < 200:
        z += 1
    return z


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
        fewest = _undercut_free(lay)
        if n_cand and min(sy["sun_min"], sy["planet_min"]) < fewest and SY.search(
                scheme, tr["planets"], op["fixed"], op["input"], op["output"], sy["ratio"],
                sy["tolerance"], max(sy["sun_min"], fewest), max(sy["planet_min"], fewest),
                sy["ring_max"], sy["sum_deviation"], lay, lim["neighbour_gap"],
                lim["tip_thickness"], lim["specific_sliding"], 1)[0]:
            # the smallest tooth numbers rank first and fail (undercut): the search's
            # budget goes to them; without them it finds a train (tried, not guessed)
            raise InputError.at("synthesis.ratio", sy["ratio"],
                                f"{why}: the smallest tooth numbers rank first and fail; "
                                f"raise synthesis.sun_min and synthesis.planet_min to {fewest} "
                                f"(no undercut without a shift), which finds a train")
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


def input_torque(op: Mapping) -> float | None:
    """The input torque [N·m]: given, or 30000·P/(π·|n|) from the power [kW] and speed."""
    T_in = op["torque"]
    if T_in is None and op["power"] is not None:
        T_in = 30000.0 * op["power"] / (math.pi * abs(op["speed"]))
    return T_in


def speeds(train: K.Train, op: Mapping, unit: bool = False) -> K.Speeds:
    """The members' speeds (Willis); ``unit``: at an input speed of 1 min⁻¹."""
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


def _loss_factor_inputs(d: dict, meshes) -> None:
    """The loss factor H_V holds for 1 <= ε_α <= 2 ([ISOTR14179-2], H_V of Ohlendorf)."""
    model = d["efficiency"]["model"]
    if model == "given":
        return
    for mesh in meshes:
        if not E.loss_factor_applies(mesh.geom.eps_alpha):
            lo, hi = E.EPS_ALPHA_RANGE
            raise InputError.at("efficiency.model", model, f"the loss factor H_V "
                                f"(Ohlendorf, ISO/TR 14179-2) holds for {lo:g} <= ε_α <= "
                                f"{hi:g}, and the {mesh.name.replace('_', '–')} mesh has ε_α = "
                                f"{mesh.geom.eps_alpha:.4g}: give model = \"given\" with the "
                                f"external and internal mesh efficiencies, or change the "
                                f"geometry")


def _frequency_inputs(d: dict) -> None:
    """The measured amplitudes and their baseline (with a speed: the frequencies)."""
    if d["operation"]["speed"] is None:
        return
    fq = d["frequencies"]
    amps, base = fq["amplitudes"], fq["baseline"]
    if base is not None and amps is None:
        raise InputError(Problem("frequencies.amplitudes", "missing; required with "
                                 "frequencies.baseline: the amplitudes measured now"))
    if amps is not None and base is not None:
        if len(base) != len(amps):
            raise InputError.at("frequencies.baseline", base,
                                f"has {len(base)} values, frequencies.amplitudes "
                                f"{len(amps)}; give the same harmonics")
        if K.discriminant(base) <= 0.0:
            raise InputError.at("frequencies.baseline", base, "all zero: the relative "
                                "growth needs a non-zero baseline")


def _peak_torque(d: dict) -> None:
    """The peak torque of the strength rating is at least the input torque."""
    st = d["strength"]
    if st is None or st.get("peak_torque") is None:
        return
    T_in = input_torque(d["operation"])
    if T_in is not None and st["peak_torque"] / abs(T_in) < 1.0:
        raise InputError.at("strength.peak_torque", st["peak_torque"],
                            f"smaller than the input torque {_fmt(abs(T_in))} N·m; give the "
                            f"largest short-time torque")


def _input_stages(spec: ValidatedSpec, problems: Problems) -> tuple:
    """The independent stages of input checks: the train and its meshes, the efficiency
    model's inputs, the strength inputs, the frequency inputs; on a train that could be
    built, the kinematics and the loss factor's scope.  Each stage's problems are
    collected."""
    geo = problems.stage(_train_and_meshes, spec)
    problems.stage(_efficiency_inputs, spec.data)
    strength = problems.stage(_strength_inputs, spec)
    problems.stage(_frequency_inputs, spec.data)
    if geo is not Problems.FAILED:
        train, meshes = geo[0], geo[6]
        problems.stage(speeds, train, spec.data["operation"],
                       unit=spec.data["operation"]["speed"] is None)
        problems.stage(_loss_factor_inputs, spec.data, meshes)
        if strength is not Problems.FAILED and strength is not None:
            problems.stage(_peak_torque, spec.data)
    return geo, strength


def precheck(spec: ValidatedSpec, problems: Problems) -> None:
    """The input stages on a spec whose schema problems are reported."""
    _input_stages(spec, problems)


def read(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of a validated spec; every independent problem in one
    :class:`InputError`.  The ISO 6336 inputs are prepared into the spec's data."""
    problems = Problems()
    geo, strength = _input_stages(spec, problems)
    problems.raise_all()
    train, conv, lay, shifts, how, notes, meshes = geo
    from geardesign.planetary.iso_inputs import prepare

    prepare(spec, train, meshes)
    return Inputs(train, MappingProxyType(dict(conv)), lay, MappingProxyType(dict(shifts)),
                  how, None if notes is None else tuple(notes), tuple(meshes),
                  None if strength is None else MappingProxyType(dict(strength)),
                  MappingProxyType(spec.data))
