"""From a validated spec to the plain data of :mod:`.solve`; every rule across keys raises
:class:`~geardesign.core.errors.InputError` (one line: key, value, what is allowed).
Independent rules are collected (:class:`~geardesign.core.errors.Problems`): a spec with
mistakes in several steps, loads or supports and in the material gets every line in one
run; a rule that needs a wrong value is left out."""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem, Problems, Unusable
from geardesign.core.spec import ValidatedSpec
from geardesign.shaft.din743 import tables as din_tables
from geardesign.shaft.material_inputs import material, method, resolve_defaults
from geardesign.shaft.records import Inputs, Load, Options, Step, Support

DIN_STEP = ("groove_depth", "groove_radius", "groove_width", "groove_shape", "cross_bore",
            "cross_bore_at")
"""Step keys of the DIN 743 method: notches by their geometry ([DIN743-2])."""


def read_steps(spec: ValidatedSpec) -> list[Step]:
    """The steps; every step's rules (:data:`STEP_RULES`) are checked, each independently."""
    rows = spec.data["step"]
    problems = Problems()
    how = problems.stage(method, spec)
    din = None if how is Problems.FAILED else how == "DIN743"
    x: float | None = 0.0
    for i, s in enumerate(rows):
        for rule in STEP_RULES:
            problems.stage(rule, i, s, x, len(rows), din)
        x = x + s["length"] if x is not None and isinstance(s["length"], (int, float)) else None
    problems.raise_all()
    return [Step(s["length"], s["diameter"], s["bore"], s["fillet"], s["keyway"],
                 s["keyway_cutter"], s["press_fit"], s["groove_K_sigma"], s["groove_K_tau"],
                 s["Rz"], s["groove_depth"], s["groove_radius"], s["groove_width"],
                 s["cross_bore"], s["cross_bore_at"], s["groove_shape"]) for s in rows]


def _start(i: int, s: dict, x: float | None, n: int, din: bool) -> None:
    """``start``, when given, is where the steps before end (``x``; None: unknown)."""
    if s["start"] is not None and x is not None and abs(s["start"] - x) > 1e-6 * max(1.0, x):
        what = "overlaps" if s["start"] < x else "leaves a gap after"
        prev = f"step[{i - 1}], which ends at {x:g} mm" if i else "the left end at 0 mm"
        raise InputError.at(f"step[{i}].start", s["start"],
                            f"{what} {prev}; steps follow each other without gaps: give "
                            f"start = {x:g} or leave it out")


def _bore(i: int, s: dict, x, n: int, din: bool) -> None:
    if s["bore"] >= s["diameter"]:
        raise InputError.at(f"step[{i}].bore", s["bore"],
                            f"must be smaller than the diameter {s['diameter']:g} mm")


def _groove_factors(i: int, s: dict, x, n: int, din: bool) -> None:
    """A groove by its factors: K_τ needs K_σ; no groove at the shaft's right end."""
    if s["groove_K_tau"] is not None and s["groove_K_sigma"] is None:
        raise InputError.at(f"step[{i}].groove_K_tau", s["groove_K_tau"],
                            "needs groove_K_sigma (the groove's factor in bending)")
    if s["groove_K_sigma"] is not None and i == n - 1:
        raise InputError.at(f"step[{i}].groove_K_sigma", s["groove_K_sigma"],
                            "a groove sits at the right end of its step, and the last step "
                            "ends with the shaft: give it on the step to the left of the "
                            "groove's shoulder")


def _keyway_cutter(i: int, s: dict, x, n: int, din: bool | None) -> None:
    if din is None:
        raise Unusable()     # the method is wrong: reported by the schema
    if s["keyway"] and s["keyway_cutter"] != "end_mill" and din:
        raise InputError.at(f"step[{i}].keyway_cutter", s["keyway_cutter"],
                            "DIN 743-2 gives the notch factor of a key seat cut by an end "
                            "mill only: no data for a disc cutter (use end_mill, or "
                            "method GOST)")


def _din_keys(i: int, s: dict, x, n: int, din: bool) -> None:
    """The DIN 743 notches by geometry: their domains (DIN743), or none of their keys
    (GOST, every one given reported)."""
    if din is None:
        raise Unusable()     # the method is wrong: reported by the schema
    if din:
        problems = Problems()
        problems.stage(_din_notches, i, s, n)
        problems.stage(_cross_bore, f"step[{i}]", s)
        problems.raise_all()
        return
    problems = Problems()
    for key in DIN_STEP:
        if s.get(key) is not None:
            what = "cross-bore" if key.startswith("cross") else "groove"
            hint = (": give the groove's factors groove_K_sigma/groove_K_tau"
                    if what == "groove" else "")
            problems.at(f"step[{i}].{key}", s[key],
                        f'a DIN 743 key, used only by [shaft] method = "DIN743" (this spec '
                        f'rates by GOST, whose tables have no factors of a {what} by its '
                        f'geometry{hint})')
    problems.raise_all()


STEP_RULES = (_start, _bore, _groove_factors, _keyway_cutter, _din_keys)
"""The rules of one step, each ``(i, step, x, n_steps, din)``, checked independently
(``din`` None: the method is wrong, and the rules of a method are left out)."""


def _din_notches(i: int, s: dict, n_steps: int) -> None:
    """The validity domains of a step's DIN 743 notches by geometry (one line each)."""
    at = f"step[{i}]"
    D, bore, L = s["diameter"], s["bore"], s["length"]
    t, r, m = s["groove_depth"], s["groove_radius"], s["groove_width"]
    shape = s["groove_shape"] or ("rectangular" if m is not None else "round")
    for key in ("groove_width", "groove_radius", "groove_shape"):
        if s[key] is not None and t is None:
            raise InputError.at(f"{at}.{key}", s[key],
                                "needs groove_depth (the depth of the groove at the step's "
                                "right end)")
    if t is not None:
        if s["groove_K_sigma"] is not None:
            raise InputError.at(f"{at}.groove_depth", t,
                                "give the groove by its factors (groove_K_sigma) or by its "
                                "geometry (groove_depth), not both")
        if i == n_steps - 1:
            raise InputError.at(f"{at}.groove_depth", t,
                                "a groove sits at the right end of its step, and the last "
                                "step ends with the shaft: give it on the step to the left of "
                                "the groove's shoulder")
        if shape == "V":
            for key in ("groove_radius", "groove_width"):
                if s[key] is not None:
                    raise InputError.at(f"{at}.{key}", s[key],
                                        'a V-notch (groove_shape = "V") is given by its depth '
                                        'alone (DIN 743-2: a sharp notch of the test specimen): '
                                        'leave it out')
            c = din_tables()["v_notch"]
            lo, hi = c["t_d_min"] * D / (1 + 2 * c["t_d_min"]), \
                c["t_d_max"] * D / (1 + 2 * c["t_d_max"])
            if not lo <= t <= hi or 2.0 * t >= D - bore:
                raise InputError.at(f"{at}.groove_depth", t,
                                    f"a V-notch of DIN 743-2 holds for {c['t_d_min']:g} <= t/d "
                                    f"<= {c['t_d_max']:g} (d = diameter − 2t the root): t "
                                    f"from {lo:.3g} to {hi:.3g} mm, the root outside the bore")
            return
        if shape == "rectangular" and m is None:
            raise InputError(Problem(
                f"{at}.groove_width",
                'missing; groove_shape = "rectangular" needs the width of the groove'))
        if shape == "round" and m is not None:
            raise InputError.at(f"{at}.groove_width", m,
                                'a round groove has no width: leave it out, or give '
                                'groove_shape = "rectangular"')
        if r is None:
            raise InputError(Problem(
                f"{at}.groove_radius",
                "missing; a groove (groove_depth) needs its radius: the radius of a round "
                "groove, or the root radius of a rectangular groove (with groove_width)"))
        if 2.0 * t >= D - bore:
            raise InputError.at(f"{at}.groove_depth", t,
                                f"must be less than (diameter − bore)/2 = {(D - bore) / 2:g} "
                                f"mm: the groove root must stay outside the bore")
        if t > D / 4.0:
            raise InputError.at(f"{at}.groove_depth", t,
                                f"at most diameter/4 = {D / 4:g} mm (a groove root below half "
                                f"the step's diameter is no groove)")
        if shape == "round":
            if r <= 0:
                raise InputError.at(f"{at}.groove_radius", r,
                                    "must be above 0 for a round groove (a sharp groove is a "
                                    "rectangular one: give groove_width)")
            w = 2.0 * math.sqrt(2.0 * r * t - t * t) if r > t else 2.0 * r
            if w > L:
                raise InputError.at(f"{at}.groove_radius", r,
                                    f"the round groove is {w:.3g} mm wide at the surface, more "
                                    f"than the step's length {L:g} mm")
        else:
            if r > t or r > m / 2.0:
                raise InputError.at(f"{at}.groove_radius", r,
                                    f"the root radius of a rectangular groove is at most its "
                                    f"depth {t:g} mm and half its width {m / 2:g} mm")
            if m > L:
                raise InputError.at(f"{at}.groove_width", m,
                                    f"more than the step's length {L:g} mm")


def _cross_bore(at: str, s: dict) -> None:
    """The validity domain of a step's cross-bore."""
    D, bore, L = s["diameter"], s["bore"], s["length"]
    dL = s["cross_bore"]
    if s["cross_bore_at"] is not None and dL is None:
        raise InputError.at(f"{at}.cross_bore_at", s["cross_bore_at"],
                            "needs cross_bore (the diameter of the hole)")
    if dL is not None:
        if bore > 0:
            raise InputError.at(f"{at}.cross_bore", dL,
                                "DIN 743-2 rates a cross-bore through a solid shaft only "
                                "(this step has a bore)")
        lim = din_tables()["cross_bore"]["dL_d_max"]
        if dL > lim * D:
            raise InputError.at(f"{at}.cross_bore", dL,
                                f"at most {lim:g}·diameter = {lim * D:g} mm (the range of the "
                                f"cross-bore's factors taken here)")
        x = s["cross_bore_at"] if s["cross_bore_at"] is not None else L / 2.0
        if x < dL / 2.0 or x > L - dL / 2.0:
            if s["cross_bore_at"] is None:   # the default middle: the hole is too large
                raise InputError.at(f"{at}.cross_bore", dL,
                                    f"wider than the step's length {L:g} mm: the hole at its "
                                    f"middle (the default of cross_bore_at, not in the spec) "
                                    f"must lie within the step")
            raise InputError.at(f"{at}.cross_bore_at", x,
                                f"the hole must lie within the step: {dL / 2:g}…"
                                f"{L - dL / 2:g} mm from its left end")


def _on_shaft(key: str, position: float, length: float | None) -> None:
    """A load or support position must lie on the shaft (0 … the sum of the step lengths;
    ``length`` None: a step length is wrong, reported with the steps)."""
    if length is not None and position > length * (1 + 1e-12):
        raise InputError.at(key, position, f"outside the shaft: must be within 0…{length:g} mm "
                            f"(the sum of the step lengths)")


def read_loads(spec: ValidatedSpec, length: float | None) -> list[Load]:
    problems = Problems()
    out = []
    for i, ld in enumerate(spec.data["load"]):
        problems.stage(_on_shaft, f"load[{i}].position", ld["position"], length)
        out.append(Load(ld["position"], ld["Fy"], ld["Fz"], ld["Fx"], ld["torque"],
                        ld["moment_y"], ld["moment_z"], ld["mass"], ld["name"] or "",
                        ld["module"]))
    problems.stage(_balanced, out)
    problems.raise_all()
    return out


def _balanced(out: list[Load]) -> None:
    torques = [abs(ld.torque) for ld in out]
    total = sum(ld.torque for ld in out)
    if torques and abs(total) > 1e-3 * max(torques) + 1e-9:
        raise InputError(Problem(
            "load", f"the torques do not balance: their sum is {total:g} N·m; a shaft in "
                    f"steady rotation takes out what is put in: give the output torque(s) "
                    f"with the opposite sign so that the sum is 0"))


def read_supports(spec: ValidatedSpec, length: float | None) -> list[Support]:
    problems = Problems()
    out = []
    for i, s in enumerate(spec.data["support"]):
        problems.stage(_on_shaft, f"support[{i}].position", s["position"], length)
        out.append(Support(s["position"], s["stiffness"], s["type"], s["axial"],
                           s["name"] or ""))
    problems.stage(_two_positions, out, length)
    axial = [i for i, s in enumerate(out) if s.axial is True]
    if len(axial) > 1:
        problems.at(f"support[{axial[1]}].axial", True,
                    f"only one bearing takes the axial force (support[{axial[0]}] already "
                    f"does)")
    problems.raise_all()
    return out


def _two_positions(out: list[Support], length: float | None) -> None:
    xs = sorted(s.position for s in out)
    if xs[-1] - xs[0] <= 1e-3 * (length or 0.0):
        raise InputError(Problem(
            "support", "a free shaft needs at least two supports at different positions to "
                       "carry its loads; add a [[support]]"))


def read_options(spec: ValidatedSpec) -> Options:
    s = spec.data["shaft"]
    how = method(spec)
    if how != "DIN743":
        return Options(s["speed"], s["peak_factor"], s["torsion_cycle"], s["Rz"], s["K_V"])
    return Options(s["speed"], s["peak_factor"], s["torsion_cycle"], s["Rz"], s["K_V"], how,
                   s["din743_load_case"], s["din743_hard_surface"])


def model(spec: ValidatedSpec) -> Inputs:
    """The typed inputs of :func:`.solve.solve` read from the spec (every input rule): the
    method's defaults, the steps, the material, the loads and the supports are checked
    independently, and every problem is reported at once."""
    problems = Problems()
    problems.stage(resolve_defaults, spec)
    steps = problems.stage(read_steps, spec)
    rows = spec.data["step"]
    d_max = problems.stage(lambda: max(s["diameter"] for s in rows))
    how = problems.stage(method, spec)
    mat = (problems.stage(material, spec.data["material"], how, d_max)
           if how is not Problems.FAILED else Problems.FAILED)
    length = problems.stage(lambda: sum(s["length"] for s in rows))
    length = None if length is Problems.FAILED else length
    loads = problems.stage(read_loads, spec, length)
    supports = problems.stage(read_supports, spec, length)
    problems.raise_all()
    mat, origin = mat
    return Inputs(tuple(steps), tuple(loads), tuple(supports), mat, read_options(spec), origin)
