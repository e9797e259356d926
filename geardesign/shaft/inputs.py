"""From a validated spec to the plain data of :mod:`.solve`; every rule across keys raises
:class:`~geardesign.core.errors.InputError` (one line: key, value, what is allowed).
Independent rules are collected (:class:`~geardesign.core.errors.Problems`): a spec with
mistakes in several steps, loads or supports and in the material gets every line in one
run; a rule that needs a wrong value is left out."""

from __future__ import annotations

import difflib
import math

from geardesign.core.errors import InputError, Problem, Problems, Unusable
from geardesign.core.spec import ValidatedSpec
from geardesign.materials.gear_steel import normalize_grade
from geardesign.shaft import strength as ST
from geardesign.shaft.din743 import part3 as D3
from geardesign.shaft.din743 import rating as DR
from geardesign.shaft.din743 import tables as din_tables
from geardesign.shaft.solve import Load, Material, Options, Step, Support

GOST_ONLY = ("hardness_HB", "sigma_m1", "tau_m1", "psi_sigma", "psi_tau", "alloy")
"""Material keys of the GOST method (the DIN 743 method derives these from σ_B)."""
DIN_ONLY = ("steel_type", "d_eff")
"""Material keys of the DIN 743 method."""
DIN_STEP = ("groove_depth", "groove_radius", "groove_width", "groove_shape", "cross_bore",
            "cross_bore_at")
"""Step keys of the DIN 743 method: notches by their geometry ([DIN743-2])."""


def method(spec: ValidatedSpec) -> str:
    """The strength method: ``[shaft] method``, default "GOST" (:class:`Unusable` when the
    method given is wrong: the rules of a method are then left out, the others checked)."""
    how = spec.data["shaft"].get("method")
    if how is None:
        return "GOST"
    if not isinstance(how, str):
        raise Unusable()
    return how


def resolve_defaults(spec: ValidatedSpec) -> None:
    """Fill in the defaults that depend on the method, so that the report echoes them
    (marked assumed): with DIN743 the load case 2, no hard surface layer, and
    S_min = S_static_min = 1.2 of [DIN743-1] where the spec leaves them out.  With GOST the
    spec is left as validated."""
    sh = spec.data["shaft"]
    if method(spec) != "DIN743":
        problems = Problems()
        for key in ("din743_load_case", "din743_hard_surface"):
            if sh.get(key) is not None:
                problems.at(f"shaft.{key}", sh[key],
                            'used only by method = "DIN743" (this spec rates by GOST)')
        problems.raise_all()
        return
    lim = din_tables()["limits"]
    for key, value in (("din743_load_case", 2), ("din743_hard_surface", False),
                       ("S_min", lim["S_min"]), ("S_static_min", lim["S_static_min"])):
        path = f"shaft.{key}"
        if sh.get(key) is None or path in spec.assumed:
            sh[key] = value
            if path not in spec.assumed:
                spec.assumed.append(path)


def _grade_key(name: str) -> str:
    steels = ST.tables()["steel"]
    key = normalize_grade(name)
    if key in steels:
        return key
    latin = name.strip().replace(" ", "").replace("X", "Kh").replace("x", "Kh")
    return latin if latin in steels else key


def material(m: dict, how: str = "GOST", d_max: float = 0.0) -> tuple[Material, dict]:
    """The shaft material and a record of where each value came from.  ``how``: the
    method; ``d_max``: the largest step diameter (DIN 743: default d_eff;
    ``Problems.FAILED`` when a diameter is wrong).  The keys of the other method are
    reported each, together with the steel's own problem."""
    problems = Problems()
    if how == "DIN743":
        for key in GOST_ONLY:
            if m.get(key) is not None:
                problems.at(f"material.{key}", m[key],
                            "used only by the GOST method; DIN 743 takes the endurance limits "
                            "and the mean-stress sensitivity from sigma_B (DIN 743-3) and one "
                            "row per grade: leave it out, or give sigma_B and sigma_T of the "
                            "blank")
        out = problems.stage(din_material, m, d_max)
    else:
        for key in DIN_ONLY:
            if m.get(key) is not None:
                problems.at(f"material.{key}", m[key],
                            'used only by [shaft] method = "DIN743" (this spec rates by GOST)')
        out = problems.stage(_gost_material, m)
    problems.raise_all()
    return out


def _strengths_in_order(m: dict, sigma_B: float, sigma_T: float, origin: dict,
                        yield_name: str = "σ_T") -> None:
    """The yield strength must lie below the ultimate strength: the line names the one the
    spec gives (the other one is the grade's, and says so)."""
    if sigma_T < sigma_B:
        return
    if origin.get("sigma_T") == "given" or origin.get("sigma_B") != "given":
        of = "" if origin.get("sigma_B") == "given" else " (of the grade)"
        raise InputError.at("material.sigma_T", sigma_T, f"must be below the ultimate "
                            f"strength sigma_B = {sigma_B:g} MPa{of}")
    raise InputError.at("material.sigma_B", sigma_B, f"must be above the yield strength "
                        f"{yield_name} = {sigma_T:g} MPa of the grade (derived from "
                        f"material.grade = \"{m['grade']}\"): give sigma_T too, or leave out "
                        f"sigma_B")


def _gost_material(m: dict) -> tuple[Material, dict]:
    steels = ST.tables()["steel"]
    row, alloy_default, origin = {}, False, {}
    if m["grade"] is not None:
        key = _grade_key(m["grade"])
        if key not in steels:
            close = difflib.get_close_matches(key, list(steels), 3, 0.5)
            hint = f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""
            raise InputError.at("material.grade", m["grade"],
                                f"unknown shaft steel{hint}; known: {', '.join(steels)}; or "
                                f"leave out grade and give sigma_B and sigma_T")
        rows = steels[key]["rows"]
        hb = m["hardness_HB"]
        if hb is None:
            row = rows[0]
        else:
            fit = [r for r in rows if r["HB"] <= hb]
            if not fit:
                raise InputError.at("material.hardness_HB", hb,
                                    f"below the lowest hardness listed for steel {key} "
                                    f"({rows[0]['HB']:g} HB); give sigma_B and sigma_T instead")
            row = fit[-1]
        alloy_default = steels[key]["alloy"]
        origin = {"grade": key, "HB": row["HB"], "blank": row["blank"]}
    elif m["sigma_B"] is None or m["sigma_T"] is None:
        missing = "sigma_B" if m["sigma_B"] is None else "sigma_T"
        raise InputError(Problem(f"material.{missing}",
                                 "missing; required without a grade: the ultimate and the "
                                 "yield strength of the shaft steel (or give material.grade)"))

    def pick(name: str):
        if m.get(name) is not None:
            origin[name] = "given"
            return m[name]
        if name in row:
            origin[name] = "grade"
            return row[name]
        return None

    sigma_B, sigma_T = pick("sigma_B"), pick("sigma_T")
    _strengths_in_order(m, sigma_B, sigma_T, origin)
    s_est, _ = ST.endurance_estimates(sigma_B)
    sigma_m1 = pick("sigma_m1")
    if sigma_m1 is None:
        sigma_m1, origin["sigma_m1"] = s_est, "0.43·σ_B"
    tau_m1 = pick("tau_m1")
    if tau_m1 is None:
        tau_m1, origin["tau_m1"] = 0.58 * sigma_m1, "0.58·σ_-1"
    psi_s, psi_t = ST.mean_stress_sensitivity(sigma_B)
    if m["psi_sigma"] is not None:
        psi_s = m["psi_sigma"]
    psi_tau = pick("psi_tau")
    if psi_tau is None:
        psi_tau = psi_t if m["psi_sigma"] is None else 0.5 * psi_s
    alloy = m["alloy"] if m["alloy"] is not None else alloy_default
    return (Material(sigma_B, sigma_T, sigma_m1, tau_m1, psi_s, psi_tau, m["E"],
                     m["density"], alloy), origin)


def din_material(m: dict, d_max: float) -> tuple[Material, dict]:
    """The shaft steel for DIN 743: an EN grade of [DIN743-3] (or a GOST grade with an EN
    equivalent), or sigma_B, sigma_T and steel_type; at the blank diameter d_eff."""
    origin: dict = {}
    if m["grade"] is not None:
        name = m["grade"]
        st = D3.steel(name)
        if st is None:
            en = D3.gost_equivalent(_grade_key(name))
            st = D3.steel(en) if en else None
            if st is not None:
                origin["gost"] = _grade_key(name)
        if st is None:
            known = ", ".join(din_tables()["steel"])
            gost = ", ".join(din_tables()["gost_equivalent"])
            key = _grade_key(name)
            why = ("a GOST grade without an EN equivalent in DIN 743-3"
                   if key in ST.tables()["steel"] else "not a steel of DIN 743-3")
            raise InputError.at("material.grade", name,
                                f"{why}; known: {known} (and the GOST grades {gost}); or "
                                f"leave out grade and give sigma_B, sigma_T and steel_type")
        if m.get("steel_type") is not None and m["steel_type"] != st.type:
            raise InputError.at("material.steel_type", m["steel_type"],
                                f"steel {st.name} is {st.type} in DIN 743-3: leave out "
                                f"steel_type, or leave out grade")
        origin["grade"] = st.name
    else:
        missing = [k for k in ("sigma_B", "sigma_T", "steel_type") if m.get(k) is None]
        if missing:
            what = ("the DIN 743-3 steel type (" + ", ".join(D3.STEEL_TYPES) + ")"
                    if missing[0] == "steel_type" else "the ultimate and the yield strength")
            raise InputError(Problem(
                f"material.{missing[0]}",
                f"missing; method DIN743 without a grade needs sigma_B, sigma_T and "
                f"steel_type: {what} (or give an EN grade of DIN 743-3 as material.grade)"))
        dB, dBS = D3.REFERENCE_DIAMETER[m["steel_type"]]
        st = D3.Steel("", m["steel_type"], m["sigma_B"], m["sigma_T"], dB, dBS)
    sigma_B = m["sigma_B"] if m.get("sigma_B") is not None else st.sigma_B
    sigma_S = m["sigma_T"] if m.get("sigma_T") is not None else st.sigma_S
    origin["sigma_B"] = "given" if m.get("sigma_B") is not None else "grade"
    origin["sigma_T"] = "given" if m.get("sigma_T") is not None else "grade"
    _strengths_in_order(m, sigma_B, sigma_S, origin, "R_e")
    st = D3.Steel(st.name, st.type, sigma_B, sigma_S, st.d_B, st.d_B_S)
    d_eff = m["d_eff"] if m.get("d_eff") is not None else d_max
    if d_eff is Problems.FAILED:
        raise Unusable()     # the largest diameter is wrong: reported with the steps
    origin["d_eff"] = "given" if m.get("d_eff") is not None else "largest step"
    din = DR.material(st, d_eff)
    _, W_b, W_t = D3.endurance_limits(st.sigma_B)
    psi_s, psi_t = ST.mean_stress_sensitivity(din.sigma_B_d)
    mat = Material(din.sigma_B_d, din.sigma_S_d, W_b * din.K_1B, W_t * din.K_1B, psi_s,
                   psi_t, m["E"], m["density"], st.type != "structural", din)
    return mat, origin


def steps(spec: ValidatedSpec) -> list[Step]:
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


def loads(spec: ValidatedSpec, length: float | None) -> list[Load]:
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


def supports(spec: ValidatedSpec, length: float | None) -> list[Support]:
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


def options(spec: ValidatedSpec) -> Options:
    s = spec.data["shaft"]
    how = method(spec)
    if how != "DIN743":
        return Options(s["speed"], s["peak_factor"], s["torsion_cycle"], s["Rz"], s["K_V"])
    return Options(s["speed"], s["peak_factor"], s["torsion_cycle"], s["Rz"], s["K_V"], how,
                   s["din743_load_case"], s["din743_hard_surface"])
