"""Spec tables of the ISO 6336 rating: ``[iso]`` (with ``[iso.pinion]``, ``[iso.wheel]``) and
``[iso_factors]``, and the :class:`~.setting.IsoSetting` built from them
(:func:`iso_setting`; the builders of the setting from validated tables are
:mod:`.setting`'s).

Both tables are optional: a spec that selects ``options.method = "ISO 6336:2019"`` without
them gets every default, echoed as assumed.
"""

from __future__ import annotations

from geardesign.core.errors import InputError, Problem
from geardesign.core.spec import Field, Table
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.strength.iso6336.setting import (  # noqa: F401
    scuffing_oil_domain, scuffing_setting, setting_from, tolerance_class)
from geardesign.spur.tolerances.iso1328 import EDITIONS as TOLERANCE_EDITIONS  # noqa: F401
from geardesign.spur.tolerances.iso1328 import grades as tolerance_grades

ISO_NAME = "ISO 6336:2019"


def _gear(who: str) -> Table:
    return Table(who, f"ISO 6336 data of the {who}", (
        Field("material_type", "string", "material type of ISO 6336-5 (St normalized, V/V_alloy "
              "through-hardened, Eh case-hardened, IF induction/flame hardened, NT/NV "
              "nitrided, GG/GGG/GTS cast iron, …)", default=None, choices=tuple(T.MATERIAL_LINES),
              hint="leave out to take it from material.treatment"),
        Field("quality", "string", "material quality grade of ISO 6336-5", default="MQ",
              choices=T.QUALITIES),
        Field("sigma_Hlim", "number", "endurance limit for contact (instead of the ISO 6336-5 "
              "line)", "MPa", "σ_Hlim", default=None, minimum=150, maximum=5000),
        Field("sigma_Flim", "number", "endurance limit for bending (instead of the ISO 6336-5 "
              "line; σ_FE = 2σ_Flim)", "MPa", "σ_Flim", default=None, minimum=30, maximum=3000),
        Field("Rz_flank", "number", "mean peak-to-valley roughness of the flank", "µm", "R_zH",
              default=None, gt=0, maximum=100, hint="6·roughness_Ra of [material] when not given"),
        Field("Rz_root", "number", "mean peak-to-valley roughness of the root fillet", "µm",
              "R_zF", default=10.0, gt=0, maximum=100),
        Field("inner_diameter", "number", "bore of the gear body (reduced mass)", "mm", "d_i",
              default=0.0, minimum=0, maximum=1e5),
        Field("rim_thickness", "number", "rim thickness below the tooth root (Y_B, C_R)", "mm",
              "s_R", default=None, gt=0, hint="leave out for a solid gear"),
        Field("web_ratio", "number", "web width over face width of a web gear (C_R)", symbol="b_s/b",
              default=None, minimum=0.1, maximum=1.2, hint="leave out for a solid gear"),
    ), required=False)


SCUFFING = Table("scuffing", "scuffing by the integral temperature method (ISO/TS 6336-21): the "
                 "oil and how it reaches the mesh; leave the table out for no scuffing rating", (
    Field("fzg_load_stage", "integer", "failure load stage of the oil in the FZG A/8.3/90 test "
          "(ISO 14635-1), from the oil's data sheet", symbol="FZG", minimum=1, maximum=14,
          example=12, hint="\"> 12\" on a data sheet: give 12 (or 14 when the sheet says it "
          "passed stage 14)"),
    Field("oil_temperature", "number", "oil temperature before the mesh (sump or injection)",
          "°C", "Θ_oil", minimum=0, maximum=150, example=70.0),
    Field("oil_viscosity_100", "number", "kinematic viscosity of the oil at 100 °C", "mm^2/s",
          "ν100", default=None, minimum=2.0, maximum=300,
          hint="from iso.lubricant_viscosity with viscosity index 95 when not given"),
    Field("oil_density", "number", "density of the oil at 15 °C", "kg/m^3", "ρ15", default=890.0,
          minimum=700, maximum=1300),
    Field("lubricant", "string", "base oil (lubricant factor X_L)", default="mineral",
          choices=tuple(T.SCUFFING_X_L)),
    Field("lubrication", "string", "how the oil reaches the mesh (X_S)", default="dip",
          choices=tuple(T.SCUFFING_X_S)),
    Field("meshes", "integer", "number of gears the pinion meshes with (X_mp; a planet: 2)",
          symbol="n_p", default=1, minimum=1, maximum=12),
    Field("driving", "string", "the driving gear (approach factor X_Q)", default="pinion",
          choices=("pinion", "wheel")),
    Field("structure", "string", "flank material structure for the relative welding factor "
          "X_WrelT", default=None, choices=tuple(T.SCUFFING_X_WRELT),
          hint="from the ISO 6336-5 material types when not given (the smaller X_WrelT of the "
          "pair)"),
    Field("thermal_contact_coefficient", "number", "thermal contact coefficient "
          "√(λ ρ c) of the gear material", "N/(mm·s^0.5·K)", "B_M", default=T.B_M_STEEL,
          minimum=1.0, maximum=60.0),
    Field("S_Smin", "number", "required safety factor for scuffing (integral temperature)",
          symbol="S_Smin", default=1.8, minimum=1.0, maximum=5.0),
), required=False)


ISO = Table("iso", "ISO 6336:2019 rating data (used when options.method or options.methods "
            "names ISO 6336:2019)", (
    Field("accuracy_grade", "integer", "flank tolerance class of ISO 1328-1 (2013: 1…11; "
          "1995: accuracy grade 0…12)", symbol="A", default=None, minimum=0, maximum=12,
          hint="accuracy.grade when [accuracy] names an ISO 1328-1 edition, else "
               "gear.accuracy_grade"),
    Field("tolerance_standard", "string", "edition of ISO 1328-1 whose tolerances give f_pb, "
          "f_fα, f_Hβ and F_β", default=None, choices=TOLERANCE_EDITIONS,
          hint="accuracy.standard when it names an ISO 1328-1 edition, else ISO 1328-1:2013"),
    Field("lubricant_viscosity", "number", "kinematic viscosity of the oil at 40 °C (ISO VG)",
          "mm^2/s", "ν40", default=220.0, minimum=2, maximum=3200),
    Field("tip_relief", "number", "amount of tip relief C_a (K_v)", "µm", "C_a", default=None,
          minimum=0, maximum=1000, hint="the running-in amount C_ay when not given"),
    Field("helix_modification", "string", "helix modification (K_Hβ method C)", default="none",
          choices=tuple(T.HELIX_MODIFICATION)),
    Field("f_ma", "number", "mesh misalignment from manufacturing", "µm", "f_ma", default=None,
          minimum=0, maximum=1000, hint="f_Hβ, the larger helix slope tolerance of the pair, when not given (no provision for adjustment; give 0.5·f_Hβ for gears adjusted at assembly or lapped)"),
    Field("f_sh", "number", "mesh misalignment from the shaft deflections", "µm", "f_sh",
          default=None, minimum=0, maximum=1000, hint="computed from the pinion shaft when not given"),
    Field("shaft_K_prime", "number", "constant K' of the pinion arrangement (ISO 6336-1 "
          "figure: 0.48/0.8 arrangement a, −0.48/−0.8 b, 1.33 c, −0.36/−0.6 d, −0.6/−1.0 e)",
          symbol="K'", default=0.0, minimum=-1.5, maximum=1.5),
    Field("shaft_span", "number", "bearing span of the pinion shaft", "mm", "l", default=None,
          gt=0),
    Field("pinion_offset", "number", "offset of the pinion from the middle of the span", "mm",
          "s", default=0.0, minimum=0, maximum=1e5),
    Field("shaft_diameter", "number", "diameter of the pinion shaft", "mm", "d_sh", default=None,
          gt=0),
    Field("f_pb", "number", "transverse base pitch deviation of the pair (instead of ISO 1328)",
          "µm", "f_pb", default=None, minimum=0, maximum=1000),
    Field("f_falpha", "number", "profile form deviation of the pair (instead of ISO 1328)", "µm",
          "f_fα", default=None, minimum=0, maximum=1000),
    Field("F_beta", "number", "total helix deviation of the pair (instead of ISO 1328)", "µm",
          "F_β", default=None, minimum=0, maximum=1000),
    Field("S_Hmin", "number", "required safety factor for pitting", symbol="S_Hmin",
          default=1.0, minimum=1.0, maximum=5.0),
    Field("S_Fmin", "number", "required safety factor for tooth bending", symbol="S_Fmin",
          default=1.4, minimum=1.0, maximum=5.0),
    Field("limited_pitting", "boolean", "limited pitting permitted (Z_NT reference 10⁹ cycles)",
          default=False),
    Field("optimum_conditions", "boolean", "optimum lubrication, material, manufacturing and "
          "experience (Z_NT, Y_NT = 1 at 10¹⁰ cycles instead of 0.85)", default=False),
    Field("protuberance", "number", "residual protuberance undercut of the tool s_pr/m_n",
          symbol="s_pr*", default=0.0, minimum=0, maximum=0.5),
    _gear("pinion"),
    _gear("wheel"),
    SCUFFING,
), required=False, in_template=False)

_FACTORS = (
    ("K_v", "dynamic factor", 1.0, 10.0), ("K_Hbeta", "face load factor, contact", 1.0, 10.0),
    ("K_Fbeta", "face load factor, bending", 1.0, 10.0),
    ("K_Halpha", "transverse load factor, contact", 1.0, 10.0),
    ("K_Falpha", "transverse load factor, bending", 1.0, 10.0),
    ("c_th", "theoretical single stiffness [N/(mm·µm)]", 5.0, 40.0),
    ("c_prime", "single stiffness [N/(mm·µm)]", 1.0, 40.0),
    ("c_gamma_alpha", "mesh stiffness [N/(mm·µm)]", 1.0, 60.0),
    ("Z_E", "elasticity factor [√MPa]", 50.0, 300.0), ("Z_H", "zone factor", 1.0, 3.5),
    ("Z_eps", "contact ratio factor", 0.5, 1.0), ("Z_beta", "helix angle factor", 1.0, 1.5),
    ("Z_B", "single pair contact factor, pinion", 1.0, 1.5),
    ("Z_D", "single pair contact factor, wheel", 1.0, 1.5),
    ("Z_L", "lubricant factor", 0.7, 1.3), ("Z_v", "velocity factor", 0.7, 1.3),
    ("Z_R", "roughness factor", 0.5, 1.3),
    ("Z_NT1", "life factor, contact, pinion", 0.5, 1.7),
    ("Z_NT2", "life factor, contact, wheel", 0.5, 1.7),
    ("Z_W1", "work hardening factor, pinion", 0.7, 1.3),
    ("Z_W2", "work hardening factor, wheel", 0.7, 1.3),
    ("Z_X1", "size factor, contact, pinion", 0.5, 1.1),
    ("Z_X2", "size factor, contact, wheel", 0.5, 1.1),
    ("Y_F1", "tooth form factor, pinion", 0.5, 5.0), ("Y_F2", "tooth form factor, wheel", 0.5, 5.0),
    ("Y_S1", "stress correction factor, pinion", 1.0, 4.0),
    ("Y_S2", "stress correction factor, wheel", 1.0, 4.0),
    ("Y_beta", "helix angle factor, bending", 0.5, 1.3), ("Y_DT", "deep tooth factor", 0.7, 1.0),
    ("Y_B1", "rim thickness factor, pinion", 1.0, 2.0),
    ("Y_B2", "rim thickness factor, wheel", 1.0, 2.0),
    ("Y_NT1", "life factor, bending, pinion", 0.5, 2.5),
    ("Y_NT2", "life factor, bending, wheel", 0.5, 2.5),
    ("Y_deltarelT1", "relative notch sensitivity factor, pinion", 0.5, 1.5),
    ("Y_deltarelT2", "relative notch sensitivity factor, wheel", 0.5, 1.5),
    ("Y_RrelT1", "relative surface factor, pinion", 0.5, 1.2),
    ("Y_RrelT2", "relative surface factor, wheel", 0.5, 1.2),
    ("Y_X1", "size factor, bending, pinion", 0.5, 1.1),
    ("Y_X2", "size factor, bending, wheel", 0.5, 1.1),
    ("Y_M1", "mean stress influence factor, pinion", 0.5, 1.0),
    ("Y_M2", "mean stress influence factor, wheel", 0.5, 1.0),
    ("eta_oil", "dynamic viscosity of the oil at the oil temperature [mPa·s] (scuffing)",
     0.5, 20000.0),
    ("K_Bgamma", "helical load factor (scuffing)", 1.0, 1.3),
    ("X_M", "flash factor [K·N^-0.75·s^0.5·m^-0.5·mm] (scuffing)", 5.0, 200.0),
    ("X_alphabeta", "angle factor (scuffing)", 0.8, 1.3),
    ("X_BE", "geometry factor at the pinion tip (scuffing)", 0.0, 2.0),
    ("X_eps", "contact ratio factor (scuffing)", 0.05, 2.0),
    ("X_Q", "approach factor (scuffing)", 0.6, 1.0),
    ("X_Ca", "tip relief factor (scuffing)", 1.0, 3.0),
    ("X_E", "running-in factor (scuffing)", 1.0, 3.0),
    ("mu_mC", "mean coefficient of friction (scuffing)", 0.005, 0.3),
    ("X_WrelT", "relative welding factor (scuffing)", 0.3, 2.0),
)
ISO_FACTORS = Table("iso_factors", "ISO 6336 factors given instead of computed", tuple(
    Field(key, "number", name, symbol=key.replace("beta", "β").replace("alpha", "α")
          .replace("eps", "ε").replace("delta", "δ"), default=None, minimum=lo, maximum=hi)
    for key, name, lo, hi in _FACTORS), required=False, in_template=False,
    hint="each given factor replaces the computed one and is marked in the report")

OPTIONS_METHODS = Field(
    "methods", "array", "several strength methods in one run, each reported under its own name",
    default=None, items="string", min_items=1, max_items=2,
    choices=("GOST 21354-87", ISO_NAME), hint="instead of method, e.g. [\"GOST 21354-87\", "
    "\"ISO 6336:2019\"]")


def chosen(options: dict) -> list[str]:
    """The strength methods a spec asks for, in the order given (``methods`` wins over
    ``method``; a method named twice counts once)."""
    names = options.get("methods") or [options["method"]]
    return list(dict.fromkeys(names))


def _written(value, path: str, assumed: list) -> bool:
    """Whether a validated value holds anything the spec wrote (not a default: an empty
    table, as the template prints it, holds nothing)."""
    if isinstance(value, dict):
        return any(_written(v, f"{path}.{k}", assumed) for k, v in value.items())
    if isinstance(value, list):
        return any(_written(v, path, assumed) for v in value) or (
            bool(value) and not all(isinstance(v, dict) for v in value))
    return value is not None and path not in assumed


def unused_tables(spec) -> None:
    """``[iso]`` and ``[iso_factors]`` with a value in a spec that does not rate by ISO 6336
    (the GOST 21354-87 method alone) would be silently unused: an input error naming the
    table and the key that selects the method.  Raises :class:`InputError`."""
    d = spec.data
    if ISO_NAME in chosen(d["options"]):
        return
    problems = [Problem(key, f"[{key}] is read only by the ISO 6336 rating, and this spec "
                        f"rates by {' and '.join(chosen(d['options']))}: set options.method = "
                        f"\"{ISO_NAME}\" or options.methods = [\"GOST 21354-87\", "
                        f"\"{ISO_NAME}\"], or leave [{key}] out", Problem.NO_VALUE)
                for key in ("iso", "iso_factors") if _written(d.get(key), key, spec.assumed)]
    if problems:
        raise InputError(problems)


def prepare(spec) -> None:
    """When the spec rates by ISO 6336: fill the defaults of ``[iso]`` (echoed as assumed) and
    check the inputs that depend on each other.  Raises :class:`InputError`."""
    from geardesign.core.spec import _validate_table

    d = spec.data
    if ISO_NAME not in chosen(d["options"]):
        return
    problems: list = []
    if d.get("iso") is None:
        d["iso"] = _validate_table(ISO, {}, "iso", problems, spec.assumed)
    iso = d["iso"]
    for who in ("pinion", "wheel"):
        if iso.get(who) is None:
            iso[who] = _validate_table(ISO.member(who), {}, f"iso.{who}", problems, spec.assumed)
    problems += pair_problems(iso, "iso", d.get("accuracy"))
    if chosen(d["options"]) == [ISO_NAME] and d.get("material") is not None:
        for who in ("pinion", "wheel"):
            problems += gost_material_problems(d["material"][who], f"material.{who}",
                                               f"iso.{who}", "iso")
    load = d.get("load") or {}
    if chosen(d["options"]) == [ISO_NAME] and load.get("regime") is not None:
        if "load.regime" in spec.assumed:        # the GOST default: not echoed as used
            spec.assumed.remove("load.regime")
            load["regime"] = None
        else:
            problems.append(Problem("load.regime", REGIME_NOT_READ, load["regime"]))
    if problems:
        raise InputError(problems)


def pair_problems(iso: dict, path: str, accuracy: dict | None = None) -> list:
    """The rules across the pair keys of an ``[iso]`` table (``path`` names it in the
    messages): the pinion shaft needs its span and diameter with an offset inside the
    span; the accuracy grade a class of the tolerances' edition (:func:`tolerance_class`,
    with the spec's ``[accuracy]``); the scuffing oil's ν100 below its ν40."""
    problems = []
    if iso["pinion_offset"] and (iso["shaft_span"] is None or iso["shaft_diameter"] is None):
        problems.append(Problem(f"{path}.pinion_offset", f"given without {path}.shaft_span and "
                                f"{path}.shaft_diameter: the shaft deflection needs all three "
                                f"(or give {path}.f_sh)", iso["pinion_offset"]))
    if iso["shaft_span"] is not None and iso["pinion_offset"] > 0.5 * iso["shaft_span"]:
        problems.append(Problem(f"{path}.pinion_offset", f"lies outside the bearing span "
                                f"(s <= l/2 = {0.5 * iso['shaft_span']:g} mm)",
                                iso["pinion_offset"]))
    standard, grade = tolerance_class(iso, accuracy)
    classes = tolerance_grades(standard)
    if iso["accuracy_grade"] is not None and grade not in classes:
        problems.append(Problem(f"{path}.accuracy_grade", f"is not a class of {standard}: give "
                                f"{classes.start}…{classes.stop - 1}", grade))
    sc = iso.get("scuffing")
    if sc is not None and sc["oil_viscosity_100"] is not None \
            and sc["oil_viscosity_100"] >= iso["lubricant_viscosity"]:
        problems.append(Problem(f"{path}.scuffing.oil_viscosity_100", f"must be smaller than "
                                f"the viscosity at 40 °C ({path}.lubricant_viscosity = "
                                f"{iso['lubricant_viscosity']:g} mm²/s)",
                                sc["oil_viscosity_100"]))
    return problems


def gear_checks(iso: dict, geom, paths: tuple[str, str] = ("iso.pinion", "iso.wheel"),
                gears: tuple[dict, dict] | None = None) -> None:
    """Inputs that need the geometry: a bore inside the root circle, a rim within the
    domain of Y_B; an internal gear has no bore (its body is the rim).  ``gears``: the
    two gear tables in rating order (default ``iso["pinion"]``, ``iso["wheel"]``),
    ``paths`` their keys in the messages.  Raises :class:`InputError`."""
    from geardesign.spur.strength.iso6336.part3 import y_b_domain

    problems = []
    internal = bool(getattr(geom, "internal", False))
    tables = gears if gears is not None else (iso["pinion"], iso["wheel"])
    for i, (t, path) in enumerate(zip(tables, paths)):
        gear = geom.gears[i]
        if internal and i == 1:
            if t["inner_diameter"]:
                problems.append(Problem(f"{path}.inner_diameter", "an internal gear has no "
                                        "bore: its body is the rim below the tooth roots "
                                        f"(give {path}.rim_thickness, or leave the key out)",
                                        t["inner_diameter"]))
            continue
        if t["inner_diameter"] >= gear.d_f:
            problems.append(Problem(f"{path}.inner_diameter", f"must be smaller than the root "
                                    f"diameter d_f = {gear.d_f:.3f} mm", t["inner_diameter"]))
        if t["rim_thickness"] is not None:
            low = y_b_domain(t["rim_thickness"], gear.h, geom.inp.m_n)
            if t["rim_thickness"] <= low:
                problems.append(Problem(f"{path}.rim_thickness", f"too thin: ISO 6336-3 rates "
                                        f"rims thicker than 0.5·h = {low:.3f} mm (Y_B); "
                                        f"thicken the rim", t["rim_thickness"]))
            elif 2.0 * t["rim_thickness"] > gear.d_f - t["inner_diameter"]:
                problems.append(Problem(f"{path}.rim_thickness", "larger than the gear body "
                                        "between the bore and the root circle",
                                        t["rim_thickness"]))
    if problems:
        raise InputError(problems)


def iso_setting(spec, overrides: dict | None = None):
    """The :class:`~.rating.IsoSetting` of a validated, prepared spec."""
    iso = spec.data["iso"]
    o = {k: v for k, v in (spec.data.get("iso_factors") or {}).items() if v is not None}
    if overrides:
        o.update(overrides)
    return setting_from(iso, (iso["pinion"], iso["wheel"]), o,
                        scuffing_setting(iso.get("scuffing"), nu40=iso["lubricant_viscosity"]),
                        accuracy=spec.data.get("accuracy"))


#: ``[material.<gear>]`` keys of the GOST 21354-87 rating that the ISO 6336 rating does not
#: read, and the key the ISO rating takes instead (``{gear}``: the gear's ISO table,
#: ``{pair}``: the pair's).
REGIME_NOT_READ = ("is the GOST 21354-87 typical load regime, not read by the ISO 6336 "
                   "rating (it rates the nominal torque, or a [[load.spectrum]] by ISO "
                   "6336-6): leave it out, or give options.methods = [\"GOST 21354-87\", "
                   "\"ISO 6336:2019\"]")

GOST_ONLY_MATERIAL = {
    "sigma_Flim": "is the GOST 21354-87 bending endurance limit σ_Flimb (about σ_FE = "
                  "2·σ_Flim of ISO 6336-5), not read by the ISO 6336 rating: give "
                  "{gear}.sigma_Flim (the ISO 6336-5 σ_Flim) instead",
    "S_H": "is the GOST 21354-87 required safety, not read by the ISO 6336 rating: give "
           "{pair}.S_Hmin instead",
    "S_F": "is the GOST 21354-87 required safety, not read by the ISO 6336 rating: give "
           "{pair}.S_Fmin instead",
    "sigma_HPmax": "is the GOST 21354-87 static limit, not read by the ISO 6336 rating (its "
                   "static limit is σ_Hlim·Z_NT at the static point): leave it out",
    "sigma_FSt": "is the GOST 21354-87 static limit, not read by the ISO 6336 rating (its "
                 "static limit is σ_Flim·Y_ST·Y_NT·Y_δrelT at the static point): leave it out",
    "root_ground": "is the GOST 21354-87 root treatment (q_F), not read by the ISO 6336 "
                   "rating: give {gear}.Rz_root (the root roughness, Y_RrelT) instead",
}


def gost_material_problems(material: dict, path: str, gear: str, pair: str) -> list:
    """Keys of a validated ``[material.<gear>]`` table (``path``) that only the GOST rating
    reads, given in a spec rated by ISO 6336 alone: each is an input error naming the ISO
    key to give instead.  A nitrided gear without ``core_HRC`` keeps its ``sigma_Flim``:
    the library's GOST row needs one of the two."""
    problems = []
    for key, message in GOST_ONLY_MATERIAL.items():
        value = material.get(key)
        if value is None or value is False:
            continue
        if key == "sigma_Flim" and material.get("treatment") == "nitrided" \
                and material.get("core_HRC") is None:
            continue
        problems.append(Problem(f"{path}.{key}", message.format(gear=gear, pair=pair), value))
    return problems
