"""The open spur gear of the PZDN coupling (KO-2 thesis §2.1, [Lopukhov] §2.1):
rated by the spur calculator, not by a second copy of the gear formulas.

The thesis sizes the mesh with a course-book procedure (module from the bending strength,
check of σ_F and σ_H).  The module estimate is the spur strength code's bending design
formula, and the check itself is the spur calculator's: the coupling table becomes typed
spur inputs (:func:`spur_inputs`, the spur input rules), :func:`geardesign.spur.solve.solve`
rates them once (geometry to GOST 16532-70, σ_H and σ_F to GOST 21354-87 or ISO 6336, the
thesis' load factors passed as overrides when given) and the pzdn report reads that record.
The torque of the coupling is shared by the planet meshes: the pinion torque per mesh is
T/n_w (torque on the pinion) or T/(n_w·u) (torque on the wheel); the thesis'
F_t = 2T/(n_w·d2) = 210.48 N is the second case.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.spur.strength.gost21354 import module_estimate as _gost_module_estimate


# The module estimate is the spur strength code's (GOST 21354-87 bending design formula):
# the thesis prints m = 2.086 mm for T = 48.6 N·m, K_Fβ = 1.37, Y_F2 = 3.612, ψ_bd = 0.4,
# z1 = 20, [σ]_F2 = 180 MPa; these inputs give 2.84 mm (tests/reference/pzdn).
module_estimate = _gost_module_estimate


def pinion_torque(T: float, on: str, planets: int, u: float) -> float:
    """Pinion torque of one mesh [N·m]: T/n_w when T acts on the pinion, T/(n_w·u) when on
    the wheel (load shared equally by the n_w planet meshes; thesis F_t = 2T/(n_w·d2),
    [Lopukhov] §2.1)."""
    return T / planets if on == "pinion" else T / (planets * u)


_MATERIAL_KEYS = ("grade", "treatment", "hardness_HB", "hardness_HRC", "blank", "sigma_T",
                  "sigma_Hlim", "sigma_Flim", "S_H", "S_F")
_FACTOR_KEYS = ("K_Hv", "K_Hbeta", "K_Fv", "K_Fbeta", "Y_FS1", "Y_FS2")


def spur_spec(g: dict, module: float, face_width: float, T1: float,
              T1_peak: float | None) -> dict:
    """The ``kind = "spur"`` spec of the coupling gear (a dict as from TOML)."""
    gear = {"module": module, "z1": g["z1"], "z2": g["z2"], "face_width": face_width,
            "x1": g["x1"], "x2": g["x2"], "accuracy_grade": g["accuracy_grade"],
            "bearing_scheme": g["bearing_scheme"]}
    load = {"speed1": g["speed"], "torque1": T1, "life_hours": g["life_hours"]}
    if T1_peak is not None:
        load["peak_torque1"] = T1_peak
    mats = {}
    for who in ("pinion", "wheel"):
        mats[who] = {k: v for k, v in g[who].items() if k in _MATERIAL_KEYS and v is not None}
    spec = {"kind": "spur", "title": "PZDN coupling gear", "gear": gear, "load": load,
            "material": mats, "options": {"method": g.get("method", "GOST 21354-87")}}
    factors = {k: v for k, v in (g.get("factors") or {}).items() if v is not None}
    if factors:
        spec["factors"] = factors
    return spec


def _pzdn_key(key: str) -> str:
    """Map a key path of the generated spur spec back to the pzdn spec; each part of a key
    joining several (``gear.x1 + gear.x2``) alike."""
    if " + " in key:
        return " + ".join(_pzdn_key(k) for k in key.split(" + "))
    for spur, ours in (("material.pinion.", "coupling_gear.pinion."),
                       ("material.wheel.", "coupling_gear.wheel."),
                       ("factors.", "coupling_gear.factors."), ("gear.", "coupling_gear."),
                       ("load.torque1", "coupling_gear.torque"),
                       ("load.peak_torque1", "coupling_gear.peak_torque"),
                       ("load.speed1", "coupling_gear.speed"),
                       ("options.method", "coupling_gear.method"), ("load.", "coupling_gear.")):
        if key.startswith(spur):
            return ours + key[len(spur):]
    return "coupling_gear" + (f" ({key})" if key else "")


def _at_pzdn_keys(exc: InputError) -> InputError:
    """The spur input problems of the coupling gear against the pzdn keys."""
    return InputError([Problem(_pzdn_key(p.key), p.message, p.value) for p in exc.problems])


def spur_inputs(spec: dict):
    """The typed spur inputs (:class:`geardesign.spur.inputs.Inputs`) of the coupling gear:
    the tables of :func:`spur_spec` validated and read by the spur calculator's own input
    rules (:func:`geardesign.spur.inputs.from_spec`); its input problems are reported
    against the pzdn keys."""
    from geardesign.core.registry import _say_default, load_data
    from geardesign.spur.inputs import from_spec

    try:
        _, vs = load_data(spec, "coupling gear", expect_kind="spur")
        try:
            return from_spec(vs)
        except InputError as exc:
            raise InputError([_say_default(p, vs) for p in exc.problems]) from None
    except InputError as exc:
        raise _at_pzdn_keys(exc) from None


def rate(inputs):
    """The coupling gear solved by :func:`geardesign.spur.solve.solve`: the typed record
    (geometry, the rating of the chosen method)."""
    from geardesign.core.registry import _say_default
    from geardesign.spur.solve import solve

    try:
        return solve(inputs)
    except InputError as exc:
        raise _at_pzdn_keys(InputError([_say_default(p, inputs.spec)
                                        for p in exc.problems])) from None


def spur_report(record):
    """The spur calculator's report of the coupling gear's record
    (:func:`geardesign.spur.calculator.advised_report`), nested in the pzdn report."""
    from geardesign.spur.calculator import advised_report

    try:
        return advised_report(record)
    except InputError as exc:
        raise _at_pzdn_keys(exc) from None


def weaker_gear(Y_F: tuple[float, float], sigma_FP: tuple[float, float]) -> int:
    """Index (0 pinion, 1 wheel) of the gear with the larger Y_F/[σ]_F (thesis: compare
    [σ]_F/Y_F, the smaller is weaker; [Lopukhov] §2.1)."""
    return 0 if Y_F[0] / sigma_FP[0] >= Y_F[1] / sigma_FP[1] else 1


def round_module(m: float, series: tuple[float, ...]) -> float:
    """The first module of the series >= m (GOST 9563-60, rounded up as in the thesis)."""
    for v in sorted(series):
        if v >= m - 1e-12:
            return v
    return math.ceil(m)
