"""The fatigue inputs of the rim ([fillet], [material], [load], [[stage]], [fatigue]) read
into typed, frozen records; each group of rules is a stage of its own, so that independent
mistakes are reported together (:class:`Problems`).  ``ring`` is the
:class:`~geardesign.epicycle_rim.inputs.Ring` record."""

from __future__ import annotations

import math
import re

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass
from geardesign.core.spec import Field, ValidatedSpec
from geardesign.epicycle_rim import endurance as E
from geardesign.epicycle_rim import stress as ST
from geardesign.epicycle_rim.spec import FATIGUE
from geardesign.epicycle_rim.tables import mode_K_FE
from geardesign.fatigue import gost25504 as g25
from geardesign.fatigue import probability as FP

_NAME = re.compile(r"^[a-z][a-z0-9_]*$")


def fmt(x: float) -> str:
    """A number for a message: at most four decimals, no trailing zeros."""
    return f"{x:.4f}".rstrip("0").rstrip(".")


def assume(spec: ValidatedSpec, table: str, key: str, value) -> None:
    """Write a default that depends on other keys into the spec's echo."""
    spec.data[table][key] = value
    spec.assumed.append(f"{table}.{key}")


@dataclass(frozen=True)
class Material:
    sigma_u: float
    sigma_y: float
    sigma_m1: float
    source: str
    specimen_diameter: float     # d0 [mm]
    blank_size: float            # δ3 [mm]
    scatter: float               # v_σ-1
    anisotropy_factor: float | None


@dataclass(frozen=True)
class Fillet:
    root_chord: float            # S [mm]
    radius: float                # ρ [mm]
    radius_tolerance: float      # Δρ [mm]
    roughness: float             # Rz [µm]
    hardening_factor: float      # K_V


@dataclass(frozen=True)
class Load:
    bending_stress: float | None     # σ_F [MPa], when given
    form_factor: float | None        # Y_F
    sigma_Fn: float                  # nominal bending stress [MPa]
    load_sharing: float              # K_c
    hoop_loaded: float               # [MPa]
    hoop_between: float              # [MPa]
    estimate: ST.HoopEstimate | None  # the thin-ring estimate, when used


@dataclass(frozen=True)
class Stage:
    name: str
    tension_fillet: str
    mu_F: float
    how: str
    share: float | None


@dataclass(frozen=True)
class Options:
    """The [fatigue] table (defaults resolved)."""

    mean_stress_model: str
    stress_concentration: float | None
    stress_gradient: float | None
    concentrator_depth: float | None
    stressed_perimeter: float
    knee_cycles: float
    slgn_alpha: float
    slgn_beta: float
    probabilities: tuple[float, ...]     # [%]
    scatter_total: float | None
    stress_scatter: float
    required_probability: float          # [%]


@dataclass(frozen=True)
class Fatigue:
    material: Material
    fillet: Fillet
    load: Load
    stages: tuple[Stage, ...]
    options: Options


def _fillet(spec: ValidatedSpec) -> Fillet:
    fl = spec.data["fillet"]
    if fl["radius"] >= 0.5 * fl["root_chord"]:
        raise InputError(Problem("fillet.radius", f"must be less than half the root chord "
                                 f"S/2 = {fmt(0.5 * fl['root_chord'])} mm", fl["radius"]))
    return Fillet(fl["root_chord"], fl["radius"], fl["radius_tolerance"], fl["roughness"],
                  fl["hardening_factor"])


def _material(spec: ValidatedSpec) -> Material:
    from geardesign.materials.fatigue_steel import grade

    m = spec.data["material"]
    source = "given"
    if m["grade"] is not None:
        lib = grade(m["grade"])
        source = f"{m['grade']}: {lib['source']}"
        for key in ("sigma_u", "sigma_y", "sigma_m1"):
            if m[key] is None:
                assume(spec, "material", key, lib[key])
    for key, what in (("sigma_u", "ultimate strength"), ("sigma_y", "yield strength"),
                      ("sigma_m1", "endurance limit")):
        if m[key] is None:
            raise InputError(Problem(f"material.{key}", f"missing: give the {what} or a "
                                     f"material.grade"))
    found = [Problem(f"material.{key}", f"must be below sigma_u = {fmt(m['sigma_u'])} MPa",
                     m[key]) for key in ("sigma_y", "sigma_m1") if m[key] >= m["sigma_u"]]
    if g25.sensitivity_nu(m["sigma_u"]) <= 0.0:
        found.append(Problem("material.sigma_u", "must be < 1475 MPa: the sensitivity "
                             "ν_σ = 0.211 − 0.000143·σ_u of GOST 25.504-82 is <= 0 above",
                             m["sigma_u"]))
    if found:
        raise InputError(found)
    return Material(m["sigma_u"], m["sigma_y"], m["sigma_m1"], source, m["specimen_diameter"],
                    m["blank_size"], m["scatter"], m["anisotropy_factor"])


def _nominal_bending(load: dict) -> float:
    sF, YF, sFn = load["bending_stress"], load["form_factor"], load["nominal_bending_stress"]
    if sFn is not None:
        if sF is not None or YF is not None:
            raise InputError(Problem("load.nominal_bending_stress", "give either "
                                     "nominal_bending_stress or bending_stress with "
                                     "form_factor, not both", sFn))
        return sFn
    if sF is None or YF is None:
        key = "load.form_factor" if sF is not None else "load.bending_stress"
        raise InputError(Problem(key, "missing: give bending_stress with form_factor, or "
                                 "nominal_bending_stress"))
    return ST.nominal_bending_stress(sF, YF)


def _hoop(spec: ValidatedSpec) -> tuple[float, float, ST.HoopEstimate | None]:
    load, ring, pl = spec.data["load"], spec.data["ring"], spec.data["planets"]
    if load["hoop_source"] == "given":
        for key in ("hoop_stress_loaded", "hoop_stress_between"):
            if load[key] is None:
                raise InputError(Problem(f"load.{key}", 'missing: give both hoop stresses, '
                                         'or hoop_source = "thin_ring" with ring_torque'))
        if load["pressure_angle"] is not None:
            raise InputError(Problem("load.pressure_angle", 'applies only with hoop_source = '
                                     '"thin_ring"; remove it', load["pressure_angle"]))
        return load["hoop_stress_loaded"], load["hoop_stress_between"], None
    for key in ("hoop_stress_loaded", "hoop_stress_between"):
        if load[key] is not None:
            raise InputError(Problem(f"load.{key}", 'not used with hoop_source = "thin_ring" '
                                     '(the estimate replaces it); remove it', load[key]))
    if load["ring_torque"] is None:
        raise InputError(Problem("load.ring_torque", 'missing: hoop_source = "thin_ring" '
                                 'needs the ring torque'))
    if load["pressure_angle"] is None:
        assume(spec, "load", "pressure_angle", 20.0)
    h = ST.thin_ring_hoop_stress(load["ring_torque"], ring["module"], ring["z"], pl["count"],
                                 ring["face_width"], ring["rim_thickness"],
                                 math.radians(load["pressure_angle"]))
    return h.hoop_loaded, h.hoop_between, h


def _stage(i: int, s: dict, q_F: int) -> Stage:
    key = f"stage[{i}]"
    if not _NAME.match(s["name"]):
        raise InputError(Problem(f"{key}.name", "must be a lower-case name of letters, "
                                 "digits and _ starting with a letter (it names the "
                                 "result keys), e.g. \"ed_braking\"", s["name"]))
    given = [k for k in ("mu_F", "mode", "torque_levels") if s[k] is not None]
    if len(given) != 1:
        raise InputError(Problem(
            key, "give exactly one of mu_F, mode, or torque_levels with time_fractions"
            + (f" (given: {', '.join(given)})" if given else "")))
    if s["time_fractions"] is not None and s["torque_levels"] is None:
        raise InputError(Problem(f"{key}.time_fractions", "applies only with "
                                 "torque_levels", s["time_fractions"]))
    if s["mu_F"] is not None:
        mu, how = s["mu_F"], "given"
    elif s["mode"] is not None:
        mu = ST.mode_factor_from_table(mode_K_FE(s["mode"], q_F), q_F)
        how = f"GOST 21354-87 mode {s['mode']}"
    else:
        t = s["time_fractions"]
        if t is None or len(t) != len(s["torque_levels"]):
            raise InputError(Problem(f"{key}.time_fractions", f"must list one duration "
                                     f"per torque level ({len(s['torque_levels'])})", t)
                             if t is not None else
                             Problem(f"{key}.time_fractions", "missing: give the duration "
                                     "of each torque level"))
        mu = ST.loading_mode_factor(s["torque_levels"], t, q_F)
        how = "torque spectrum"
    return Stage(s["name"], s["tension_fillet"], mu, how, s["distance_share"])


def _stages(spec: ValidatedSpec) -> tuple[Stage, ...]:
    """Each stage is checked on its own (one line per wrong stage); the names must differ
    and the distance shares must not exceed 1."""
    q_F = spec.data["load"]["fatigue_exponent"]
    problems, out, names = Problems(), [], set()
    for i, s in enumerate(spec.data["stage"]):
        if s["name"] in names:
            problems.add(Problem(f"stage[{i}].name", "used twice; stage names must differ",
                                 s["name"]))
            continue
        names.add(s["name"])
        out.append(problems.stage(_stage, i, s, q_F))
    problems.raise_all()
    shares = [s.share for s in out if s.share is not None]
    if sum(shares) > 1.0 + 1e-9:
        raise InputError(Problem("stage.distance_share", f"the shares sum to "
                                 f"{sum(shares):.4g}; they must not exceed 1", shares))
    return tuple(out)


def _options(spec: ValidatedSpec) -> Options:
    if spec.data.get("fatigue") is None:
        spec.data["fatigue"] = {}
        for f in FATIGUE.fields:
            if isinstance(f, Field):
                spec.data["fatigue"][f.key] = f.default
                if f.default is not None:
                    spec.assumed.append(f"fatigue.{f.key}")
    fo = spec.data["fatigue"]
    if fo["stress_gradient"] is None and fo["concentrator_depth"] is None:
        raise InputError(Problem("fatigue.concentrator_depth", "missing: give the depth of "
                                 "the concentrator t, or the stress_gradient G directly"))
    if fo["stress_gradient"] is not None and fo["concentrator_depth"] is not None:
        raise InputError(Problem("fatigue.concentrator_depth", "not used when "
                                 "stress_gradient is given; remove one of them",
                                 fo["concentrator_depth"]))
    if fo["stressed_perimeter"] is None:
        assume(spec, "fatigue", "stressed_perimeter", 2.0 * spec.data["ring"]["face_width"])
    return Options(fo["mean_stress_model"], fo["stress_concentration"], fo["stress_gradient"],
                   fo["concentrator_depth"], fo["stressed_perimeter"], fo["knee_cycles"],
                   fo["slgn_alpha"], fo["slgn_beta"], tuple(fo["probabilities"]),
                   fo["scatter_total"], fo["stress_scatter"], fo["required_probability"])


def part_endurance(ring, f: Fatigue, rho: float | None = None) -> E.PartEndurance:
    """The part endurance limit of the rim for these inputs (``rho``: another fillet
    radius, for the advice)."""
    m, fl, o = f.material, f.fillet, f.options
    return E.part_endurance(
        sigma_u=m.sigma_u, sigma_m1=m.sigma_m1, d0=m.specimen_diameter,
        blank_size=m.blank_size, root_chord=fl.root_chord,
        fillet_radius=fl.radius if rho is None else rho,
        radius_tol=fl.radius_tolerance, rim_thickness=ring.rim_thickness,
        perimeter=o.stressed_perimeter, Rz=fl.roughness, K_V=fl.hardening_factor,
        v_material=m.scatter, alpha=o.stress_concentration,
        gradient=o.stress_gradient, depth=o.concentrator_depth,
        K_A=m.anisotropy_factor, v_override=o.scatter_total)


def _probabilities(ring, f: Fatigue) -> None:
    """Each probability must leave a positive quantile σ_-1D(P) = σ_-1D·(1 − z_P·v)."""
    v = part_endurance(ring, f).v
    o = f.options
    probs = [p / 100.0 for p in o.probabilities]
    for P in probs + [o.required_probability / 100.0]:
        if 1.0 - FP.normal_quantile(P) * v <= 0.0:
            given = P in probs
            pmax = 100.0 * FP.normal_cdf(1.0 / v)
            raise InputError(Problem(
                "fatigue.probabilities" if given else "fatigue.required_probability",
                f"P = {P * 100:g} % makes σ_-1D(P) = σ_-1D·(1 − z_P·v) <= 0 with v = "
                f"{v:.4g}; use P < {pmax:.2f} %",
                list(o.probabilities) if given else o.required_probability))


def fatigue(spec: ValidatedSpec, ring, problems: Problems) -> Fatigue | None:
    d = spec.data
    fillet = problems.stage(_fillet, spec)
    material = problems.stage(_material, spec)
    sFn = problems.stage(_nominal_bending, d["load"])
    hoop = problems.stage(_hoop, spec)
    stages = problems.stage(_stages, spec)
    options = problems.stage(_options, spec)
    parts = (ring, fillet, material, sFn, hoop, stages, options)
    if any(p is Problems.FAILED for p in parts):
        return None
    ld = d["load"]
    load = Load(ld["bending_stress"], ld["form_factor"], sFn, ld["load_sharing"], *hoop)
    f = Fatigue(material, fillet, load, stages, options)
    return f if problems.stage(_probabilities, ring, f) is not Problems.FAILED else None
