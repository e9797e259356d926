"""A spur stage of a drive: the stage spec with the drive's load read into typed inputs
(:func:`geardesign.spur.inputs.from_spec`) and solved once per pass
(:func:`geardesign.spur.solve.solve`); ratio, margins and mesh forces come from the typed
record, and the stage's report (with the advice of its failed checks) is written only when
the drive's report asks for it, from the last pass."""

from __future__ import annotations

import copy

from geardesign.core.errors import InputError, Problem
from geardesign.core.registry import load_data
from geardesign.core.result import Result
from geardesign.core.spec import ValidatedSpec
from geardesign.drive.stages import (
    ETA_CYLINDRICAL,
    Duty,
    Member,
    StageRun,
    _named,
    _set_by_drive,
    _put,
    _table,
)


def _spur_loads(data: dict, T_in: float, n_in: float, duty: Duty, where: str) -> dict:
    """A copy of the spur stage spec with the drive's load in it."""
    d = copy.deepcopy(data)
    load = _table(d, "load", where)
    load["torque1"], load["speed1"] = T_in, n_in
    load.pop("power", None)
    _put(load, "life_hours", duty.L_h)
    _put(load, "application_factor", duty.K_A)
    if duty.peak_ratio is not None:
        _put(load, "peak_torque1", T_in * duty.peak_ratio)
    opts = d.get("options")
    if duty.method is not None:
        opts = d.setdefault("options", {})
        if isinstance(opts, dict) and not opts.get("method") and not opts.get("methods"):
            opts["method"] = duty.method
    from geardesign.spur.strength.iso6336.spec import ISO_NAME

    methods = (opts.get("methods") or [opts.get("method")]) if isinstance(opts, dict) else []
    if not load.get("spectrum") and methods != [ISO_NAME]:   # ISO 6336 has no GOST regime
        _put(load, "regime", duty.regime)
    return d


def _no_material(where: str) -> InputError:
    return InputError(Problem(f"{where}: material", "missing table [material.pinion] and "
                              "[material.wheel]: a drive rates every stage for strength"))


#: The loads the drive sets on a spur stage (:func:`_spur_loads`).
SPUR_LOADS = ("load.torque1", "load.speed1", "load.peak_torque1", "iso.f_sh",
              "iso.scuffing.oil_temperature")
"""With the misalignment the shafts give (``iso.f_sh``) and the oil at the sump
temperature of the heat balance (``iso.scuffing.oil_temperature``)."""


def _reloaded(inputs, d: dict):
    """The typed inputs of the spur spec ``d`` from those of the same spec with other
    loads (:mod:`geardesign.drive.reuse`): the loads checked by their schema fields, the
    duty read by the spur calculator's reader; ``None`` when a load is refused."""
    import dataclasses

    from geardesign.drive import reuse
    from geardesign.spur.spec import SCHEMA
    from geardesign.spur.spec_duty import duty_from_spec

    spec = reuse.reloaded(SCHEMA, inputs.spec, d, SPUR_LOADS)
    if spec is None or inputs.strength is None:
        return None
    # the reader fills defaults into its copies: the echo keeps those of the first read
    probe = ValidatedSpec(spec.data, list(spec.assumed))
    try:
        duty = duty_from_spec(probe, dict(spec.data["load"]), True)
    except InputError:
        return None
    changes = {}
    if inputs.iso is not None:      # the ISO 6336 setting read again: f_sh, the oil
        from geardesign.spur.strength.iso6336.spec import iso_setting

        try:
            changes = dict(iso=iso_setting(spec), iso_table=spec.data["iso"])
        except InputError:
            return None
    return dataclasses.replace(inputs, strength=inputs.strength._replace(duty=duty),
                               speed1=spec.data["load"]["speed1"], spec=spec, **changes)


def spur_inputs(data: dict, T_in: float, n_in: float, duty: Duty, where: str):
    """The typed inputs (:class:`geardesign.spur.inputs.Inputs`) of a spur stage with the
    drive's load: the stage spec validated once per run, a later pass with other loads
    reusing it (:mod:`geardesign.drive.reuse`); problems name the stage."""
    from geardesign.drive import reuse

    d = _spur_loads(data, T_in, n_in, duty, where)
    key = reuse.fingerprint("spur", where, d, SPUR_LOADS)
    if key in duty.memo:
        inputs = _reloaded(duty.memo[key], d)
        if inputs is not None:
            return inputs
    inputs = _read_spur(d, where)
    duty.memo[key] = inputs
    return inputs


def _read_spur(d: dict, where: str):
    """The stage spec ``d`` validated and read into typed inputs."""
    from geardesign.core.registry import _say_default
    from geardesign.spur.inputs import from_spec

    has_material = d.get("material") is not None
    try:
        _, spec = load_data(d, where)
    except InputError as exc:
        raise _named(exc, where) from None
    if not has_material:
        raise _no_material(where)
    try:
        return from_spec(spec)
    except InputError as exc:
        raise _named(InputError([_say_default(p, spec) for p in exc.problems]), where) \
            from None


def _spur_report(record, where: str, original: dict) -> Result:
    """The report of a solved spur stage as its calculator gives it
    (:func:`geardesign.spur.calculator.advised_report`), its problems named by the stage,
    with the loads the drive set."""
    from geardesign.spur.calculator import advised_report

    try:
        res = advised_report(record)
    except InputError as exc:
        raise _named(exc, where) from None
    _set_by_drive(res, record.inputs.spec.data, original)
    return res


def _geometry_run(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
                  where: str, read: tuple | None = None) -> tuple:
    """``((typed inputs, geometry), run)`` of a spur stage from its geometry alone
    (:func:`probe_spur`, :func:`light_spur`): the ratio the geometry's, the efficiency the
    spec's or the handbook's (or the one the drive gives as ``eta``), no forces; ``read``:
    the stage's inputs and geometry of a pass before, else read here."""
    from geardesign.spur.solve import geometry

    if read is None:
        inputs = spur_inputs(data, T_in, n_in, duty, where)
        try:
            g = inputs.geometry if getattr(inputs, "geometry", None) is not None \
                and inputs.geometry.inp is inputs.pair else geometry(inputs.pair)
        except InputError as exc:
            raise _named(exc, where) from None
        read = (inputs, g)
    inputs, g = read
    u = g.u
    e, src = (eta, "spec") if eta is not None else (ETA_CYLINDRICAL, "assumed (handbook)")
    return read, StageRun("spur", u, e, src, T_in, n_in, T_in * u * e, n_in / u,
                          (Member(0.0, 0.0, 0.0, 0.0),) * 2, None, "", True,
                          spec=inputs.spec, geometry=g)


def probe_spur(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
               where: str) -> StageRun:
    """The ratio and efficiency of a spur stage for the drive's probe pass (the ratios that
    carry the machine's torque back to the motor): its typed inputs read as in
    :func:`run_spur` (the spec validated, kept for the rated pass) and its geometry, not
    its rating: the ratio is the geometry's, the efficiency the spec's or the handbook's,
    neither depends on the load.  The passes of the heat balance (:func:`light_spur`)
    reuse this reading."""
    read, run = _geometry_run(data, T_in, n_in, duty, eta, where)
    duty.memo[_light_key(data, where)] = read
    return run


def _light_key(data: dict, where: str) -> tuple:
    """The key of a spur stage's reading for the unrated passes in ``duty.memo``: the
    stage spec without the loads the drive sets."""
    from geardesign.drive import reuse

    return ("light",) + reuse.fingerprint("spur", where, data, SPUR_LOADS)


def light_spur(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
               where: str) -> StageRun:
    """A spur stage in a pass of the heat balance (:mod:`.lubrication`): what the losses
    and the bearings need, none of it from the rating: the ratio and the efficiency as in
    :func:`probe_spur`, the mesh forces from the geometry and the torque
    (:func:`geardesign.spur.loads.mesh_forces`, the forces the rating itself gives:
    [GOST21354] §2, [ISO6336-1] §5).  The typed inputs are those the probe pass read (or
    the first of these passes, without a probe pass), reused (``duty.memo``): their loads
    are checked again when the stage is rated; a pair that the calculator cannot rate is
    refused as there."""
    from geardesign.spur.loads import mesh_forces
    from geardesign.spur.solve import ISO, ratable

    # the stage as read (its loads checked) by the probe pass or the first of these
    # passes: the geometry and the values the losses take from the spec do not change
    key = _light_key(data, where)
    read, run = _geometry_run(data, T_in, n_in, duty, eta, where, duty.memo.get(key))
    duty.memo[key] = read
    inputs, g = read
    if inputs.strength is not None and (getattr(g, "internal", False)
                                        or ISO in inputs.methods) and not ratable(g):
        return run_spur(data, T_in, n_in, duty, eta, where)     # refused as there
    f = mesh_forces(g, T_in)
    run.members = (Member(f.F_t, f.F_r, f.F_a, g.g1.d_w / 2),
                   Member(f.F_t, f.F_r, f.F_a, g.g2.d_w / 2))
    return run


def run_spur(data: dict, T_in: float, n_in: float, duty: Duty, eta: float | None,
             where: str) -> StageRun:
    """A spur stage solved once (:func:`geardesign.spur.solve.solve`), its report written
    on demand."""
    from geardesign.spur import solve as SOLVE

    inputs = spur_inputs(data, T_in, n_in, duty, where)
    try:
        rec = SOLVE.solve(inputs)
    except InputError as exc:
        raise _named(exc, where) from None
    g = rec.geometry
    u = g.u
    e, src = (eta, "spec") if eta is not None else (ETA_CYLINDRICAL, "assumed (handbook)")
    margins = rec.margins()
    run = StageRun("spur", u, e, src, T_in, n_in, T_in * u * e, n_in / u,
                   (Member(0.0, 0.0, 0.0, 0.0),) * 2, None, "", True, rec,
                   lambda: _spur_report(rec, where, data), geometry=g)
    if not margins:
        # the spur calculator rates no strength for a pair that cannot mesh as computed
        # (ε_α < 1, a pointed tooth, ...): the drive has no margin and no mesh forces
        failed = [c for c in run.result.checks if not c.passed and c.severity == "error"
                  and c.code != "STRENGTH_NOT_RATED"]
        why = "; ".join(f"{c.code}: {c.message}" for c in failed[:2]) or "see its checks"
        raise InputError(Problem(
            f"{where}.gear", f"the stage's gears cannot mesh as given, so the drive cannot "
            f"rate it ({why})"))
    worst = min(margins, key=margins.get)
    if SOLVE.GOST in rec.ratings:           # the GOST record's forces section
        f = rec.ratings[SOLVE.GOST].forces
        F_t, F_r, F_a = f.F_t, f.F_r, f.F_a
    else:
        forces = rec.forces.v
        F_t, F_r, F_a = forces["F_t"], forces["F_r"], forces["F_a"]
    run.members = (Member(F_t, F_r, F_a, g.g1.d_w / 2), Member(F_t, F_r, F_a, g.g2.d_w / 2))
    run.margin, run.margin_of = margins[worst], worst
    return run
