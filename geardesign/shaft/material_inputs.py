"""The shaft's material and strength method read from a validated spec: ``[shaft] method``
(GOST 25.504-82 or DIN 743), the defaults that depend on it, and ``[material]`` resolved
to a :class:`~geardesign.shaft.records.Material` (a grade of the steel table or given
strengths; with DIN 743 the DIN 743-3 steel at its blank size).  Every rule raises
:class:`~geardesign.core.errors.InputError` (one line: key, value, what is allowed)."""

from __future__ import annotations


from geardesign.core.errors import InputError, Problem, Problems, Unusable
from geardesign.core.spec import ValidatedSpec
from geardesign.materials.gear_steel import normalize_grade
from geardesign.shaft import strength as ST
from geardesign.shaft.din743 import part3 as D3
from geardesign.shaft.din743 import rating as DR
from geardesign.shaft.din743 import tables as din_tables
from geardesign.shaft.records import Material

GOST_ONLY = ("hardness_HB", "sigma_m1", "tau_m1", "psi_sigma", "psi_tau", "alloy")
"""Material keys of the GOST method (the DIN 743 method derives these from σ_B)."""
DIN_ONLY = ("steel_type", "d_eff")
"""Material keys of the DIN 743 method."""

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
            from difflib import get_close_matches  # only to name a close match

            close = get_close_matches(key, list(steels), 3, 0.5)
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
