"""The spec of a connection read into typed inputs (N·mm, mm, µm, MPa); every rule across
keys that the schema cannot state raises a one-line :class:`InputError` here.  Independent
rules are collected (:class:`~geardesign.core.errors.Problems`): every mistake of a spec is
reported in one run, a rule that needs a wrong value is left out."""

from __future__ import annotations

import re

from geardesign.connection import iso286
from geardesign.connection import sources as S
from geardesign.connection import spline as SP
from geardesign.connection import tables
from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.records import dataclass


def fmt(x: float, digits: int = 3) -> str:
    """A number for a message: at most ``digits`` decimals, no trailing zeros."""
    text = f"{x:.{digits}f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text == "-0" else text


@dataclass(frozen=True)
class Load:
    T: float          # nominal torque [N·mm]
    K_A: float
    F_ax: float       # [N]

    @property
    def T_d(self) -> float:
        """Design torque K_A·T [N·mm]."""
        return self.K_A * self.T


def load(data: dict) -> Load:
    ld = data["load"]
    return Load(ld["torque"] * 1e3, ld["application_factor"], ld["axial_force"])


# --------------------------------------------------------------------------- key


@dataclass(frozen=True)
class KeyInput:
    d: float
    l: float
    form: str
    count: int
    din: bool
    b: float
    h: float
    t1: float
    t2: float | None
    source: str              # of the section: table row or the spec
    hub_length: float | None
    hub_material: str
    allowable_pressure: float | None
    allowable_shear: float | None
    shaft_strength: float | None
    hub_strength: float | None
    key_strength: float | None
    f_H: float


def key(data: dict) -> KeyInput:
    """The key: its size (the table row of the shaft diameter, or the spec's numbers), its
    length against the size and the hub, the DIN 6892 strengths; each rule independent."""
    k = data["key"]
    problems = Problems()
    size = problems.stage(_key_size, k)
    if size is not Problems.FAILED:
        problems.stage(_bearing_length, k, size[0])
    problems.stage(_hub_length, k)
    problems.stage(_din_strengths, k)
    problems.raise_all()
    b, h, t1, t2, source = size
    return KeyInput(k["shaft_diameter"], k["length"], k["form"], k["count"],
                    k["standard"] == "DIN 6885-1", b, h, t1, t2, source, k["hub_length"],
                    k["hub_material"], k["allowable_pressure"], k["allowable_shear"],
                    k["shaft_strength"], k["hub_strength"], k["key_strength"],
                    k["hardness_factor"])


def _key_size(k: dict) -> tuple[float, float, float, float | None, str]:
    """b, h, t1, t2 and their source: the spec's numbers (all three), else the table."""
    names = ("width", "height", "shaft_depth")
    given = [n for n in names if k[n] is not None]
    if given and len(given) < 3:
        missing = [n for n in names if k[n] is None]
        raise InputError(Problem(
            "key." + missing[0], "missing; a key not from the table needs key.width, "
            "key.height and key.shaft_depth together"))
    if given:
        h, t1 = k["height"], k["shaft_depth"]
        if t1 >= h:
            raise InputError.at("key.shaft_depth", t1, f"must be less than the key height "
                                f"key.height = {fmt(h)} mm (the key must stand out into the "
                                f"hub)")
        return k["width"], h, t1, None, "spec (key not from the table)"
    d = k["shaft_diameter"]
    size = tables.key_for_diameter(d)
    if size is None:
        first, last = tables.key_sizes()[0], tables.key_sizes()[-1]
        raise InputError.at("key.shaft_diameter", d, f"outside the key table of GOST "
                            f"23360-78 / DIN 6885-1 (over {fmt(first.d_over)} up to "
                            f"{fmt(last.d_to)} mm); give key.width, key.height and "
                            f"key.shaft_depth for another key")
    return size.b, size.h, size.t1, size.t2, f"{S.KEY_TABLE} (keys.csv row {size.row})"


def _bearing_length(k: dict, b: float) -> None:
    from geardesign.connection.key import bearing_length

    l, form = k["length"], k["form"]
    l_p = bearing_length(l, b, form)
    if l_p <= 0:
        of = ("key.width" if k["width"] is not None else
              f"derived from key.shaft_diameter = {fmt(k['shaft_diameter'])} mm by the "
              f"key table")
        raise InputError.at("key.length", l, f"must be longer than the key width b = {fmt(b)} "
                            f"mm ({of}; form {form}: bearing length l_p = {fmt(l_p)} mm)")


def _hub_length(k: dict) -> None:
    l, L_hub = k["length"], k["hub_length"]
    if L_hub is not None and l > L_hub:
        fits = [v for v in tables.key_lengths() if v <= L_hub]
        hint = (f"use a standard key of at most {fmt(fits[-1])} mm or a longer hub" if fits
                else "use a longer hub")
        raise InputError.at("key.length", l, f"longer than the hub (key.hub_length = "
                            f"{fmt(L_hub)} mm): {hint}")


def _din_strengths(k: dict) -> None:
    """DIN 6892 method C needs the three strengths (each missing one reported) unless both
    permissible stresses are given."""
    if k["standard"] != "DIN 6885-1" or (k["allowable_pressure"] is not None
                                         and k["allowable_shear"] is not None):
        return
    need = {"shaft_strength": "the shaft yield strength R_e",
            "hub_strength": "the hub strength (R_e of steel, R_m of cast iron)",
            "key_strength": "the key yield strength R_e"}
    problems = Problems()
    for name, what in need.items():
        if k[name] is None:
            problems.add(Problem("key." + name, f"missing; DIN 6892 method C needs {what} "
                                 f"(MPa), or give key.allowable_pressure and "
                                 f"key.allowable_shear"))
    problems.raise_all()


# --------------------------------------------------------------------------- spline

_DESIGNATION = re.compile(
    r"^\s*(?:[WN]\s*)?(\d+(?:\.\d+)?)\s*[x×]\s*(\d+(?:\.\d+)?)\s*(?:[x×]\s*(\d+))?\s*$")


@dataclass(frozen=True)
class SplineInput:
    d_B: float
    m: float
    z: int
    source: str
    gost: bool
    l: float
    psi: float
    use: str
    hardness: str
    conditions: str
    allowable_pressure: float | None


def _spline_size(s: dict) -> tuple[float, float, int, str]:
    numbers = [n for n in ("reference_diameter", "module", "teeth") if s[n] is not None]
    if s["designation"] is not None:
        if numbers:
            raise InputError(Problem("spline." + numbers[0], "give either spline.designation "
                                     "or the numbers (reference_diameter, module, teeth), not "
                                     "both", s[numbers[0]]))
        m = _DESIGNATION.match(s["designation"])
        if not m:
            raise InputError.at("spline.designation", s["designation"],
                                'must read d_B x m x z, e.g. "W 40x2x18" (or d_B x m, e.g. '
                                '"40x2", for a size of the series table)')
        d_B, mod = float(m.group(1)), float(m.group(2))
        row = tables.spline_size(d_B, mod)
        if m.group(3) is None:
            if row is None:
                raise InputError.at("spline.designation", s["designation"],
                                    f"the series table has no spline {fmt(d_B)} x {fmt(mod)}; "
                                    f"give the number of teeth (d_B x m x z)")
            return d_B, mod, row.z, f"{S.SPLINE_GEOM}; splines.csv row {row.row}"
        z = int(m.group(3))
        if not (0 < d_B <= 1000 and 0 < mod <= 20 and 6 <= z <= 200):
            raise InputError.at("spline.designation", s["designation"],
                                "d_B must lie in 0...1000 mm, m in 0...20 mm and z in 6...200")
        src = S.SPLINE_GEOM + (f"; splines.csv row {row.row}" if row and row.z == z else "")
        return d_B, mod, z, src
    for n in ("reference_diameter", "module"):
        if s[n] is None:
            raise InputError(Problem("spline." + n, 'missing; give spline.designation (e.g. '
                                     '"W 40x2x18") or spline.reference_diameter and '
                                     'spline.module'))
    d_B, mod = s["reference_diameter"], s["module"]
    if s["teeth"] is not None:
        return d_B, mod, s["teeth"], S.SPLINE_GEOM
    row = tables.spline_size(d_B, mod)
    if row is None:
        raise InputError.at("spline.module", mod, f"the series table has no spline "
                            f"{fmt(d_B)} x {fmt(mod)}; give spline.teeth")
    return d_B, mod, row.z, f"{S.SPLINE_GEOM}; splines.csv row {row.row}"


def spline(data: dict, assumed: tuple | list = ()) -> SplineInput:
    """The spline: its size, the profile shift the size gives, the tooth hardness against
    the use; each rule independent.  ``assumed``: the keys the spec leaves to their
    defaults (``ValidatedSpec.assumed``)."""
    s = data["spline"]
    problems = Problems()
    size = problems.stage(_spline_size, s)
    if size is not Problems.FAILED:
        problems.stage(_spline_shift, s, *size[:3])
    problems.stage(_spline_hardness, s, "spline.hardness" in assumed)
    problems.raise_all()
    d_B, m, z, src = size
    return SplineInput(d_B, m, z, src, s["standard"] == "GOST 6033-80", s["length"],
                       s["load_factor"], s["use"], s["hardness"], s["conditions"],
                       s["allowable_pressure"])


def _spline_shift(s: dict, d_B: float, m: float, z: int) -> None:
    """The profile shift of DIN 5480 that d_B, m and z give must lie in its range; the line
    names the key the spec gives (the designation, the teeth, or the module when the teeth
    come from the series table)."""
    lo, hi = SP.X_RANGE
    x = (d_B - m * z - 1.1 * m) / (2.0 * m)
    if lo - 1e-9 <= x <= hi + 1e-9:
        return
    ok = [zz for zz in range(6, 201)
          if lo - 1e-9 <= (d_B - m * zz - 1.1 * m) / (2 * m) <= hi + 1e-9]
    hint = ((f"use z = {ok[0]}" + (f" or {ok[-1]}" if ok[-1] != ok[0] else "")) if ok
            else "change the module")
    if s["designation"] is not None:
        key, value, of = "spline.designation", s["designation"], ""
    elif s["teeth"] is not None:
        key, value, of = "spline.teeth", z, ""
    else:
        key, value = "spline.module", m
        of = " (z derived from the series table for spline.reference_diameter and module)"
    raise InputError.at(key, value, f"z = {z}{of} on d_B = {fmt(d_B)} mm with m = {fmt(m)} mm "
                        f"gives the profile shift x = {x:.3f}, outside {lo}...{hi} of DIN "
                        f"5480: {hint}")


def _spline_hardness(s: dict, default: bool) -> None:
    """A hub sliding under load needs hardened teeth (the table has no pressure for soft
    ones); the line names the use when the hardness is the default."""
    if (s["allowable_pressure"] is not None
            or s["hardness"] in tables.toml()["spline_pressure"][s["use"]]):
        return
    if default:
        raise InputError.at("spline.use", s["use"], 'a hub sliding under load needs hardened '
                            'teeth: give spline.hardness = "hardened" (the default is "soft") '
                            "or spline.allowable_pressure")
    raise InputError.at("spline.hardness", s["hardness"], "a hub sliding under load needs "
                        'hardened teeth (spline.hardness = "hardened") or give '
                        "spline.allowable_pressure")


# --------------------------------------------------------------------------- fit


@dataclass(frozen=True)
class FitInput:
    d: float
    D_a: float
    D_i: float
    l: float
    U_min: float              # [µm]
    U_max: float
    fit_name: str             # "" when the interferences are given
    source: str               # of the interferences
    rz_shaft: float
    rz_hub: float
    joining: str
    surface: str
    mu: float
    mu_source: str
    mu_e: float               # press-in coefficient of friction
    mu_e_source: str
    pressure_limit: str       # model of the permissible joint pressure
    S_R: float
    S_P: float
    E_I: float
    nu_I: float
    R_eI: float
    E_A: float
    nu_A: float
    R_eA: float
    alpha_A: float
    room: float
    clearance: float          # joining clearance [mm]


def _interference(f: dict) -> tuple[float, float, str, str]:
    given = [n for n in ("interference_min", "interference_max") if f[n] is not None]
    if f["fit"] is not None:
        if given:
            raise InputError(Problem("fit." + given[0], "give either fit.fit or the "
                                     "interferences, not both", f[given[0]]))
        try:
            ft = iso286.fit(f["fit"], f["diameter"])
        except iso286.FitError as exc:
            raise InputError.at("fit.fit", f["fit"], str(exc)) from None
        return ft.U_min, ft.U_max, ft.name, f"{S.ISO286}, iso286.csv row {ft.row}"
    if len(given) < 2:
        missing = [n for n in ("interference_min", "interference_max") if f[n] is None]
        raise InputError(Problem("fit." + missing[0], 'missing; give fit.fit (e.g. "H7/s6") '
                                 "or fit.interference_min and fit.interference_max (µm)"))
    if f["interference_min"] > f["interference_max"]:
        raise InputError.at("fit.interference_min", f["interference_min"],
                            f"must not exceed fit.interference_max = "
                            f"{fmt(f['interference_max'])} µm")
    return f["interference_min"], f["interference_max"], "", "spec"


def fit(data: dict) -> FitInput:
    """The interference fit: the hub's wall, the shaft's bore and the interferences, each
    rule independent."""
    from geardesign.connection.fit import CLEARANCE_SHARE

    f = data["fit"]
    d, D_a, D_i = f["diameter"], f["hub_outer_diameter"], f["shaft_bore"]
    problems = Problems()
    problems.stage(_walls, d, D_a, D_i)
    interference = problems.stage(_interference, f)
    if interference is not Problems.FAILED:
        problems.stage(_grips, d, *interference[:3])
    problems.raise_all()
    U_min, U_max, name, src = interference
    friction = tables.toml()["friction"][f["hub_material"]]
    if f["friction"] is not None:
        mu, mu_src = f["friction"], "spec"
    else:
        mu, mu_src = friction[f["joining"]][f["surface"]], S.FRICTION
    if f["friction_press_in"] is not None:
        mu_e, mu_e_src = f["friction_press_in"], "spec"
    else:
        mu_e, mu_e_src = friction["press"][f["surface"]], S.FRICTION_PRESS_IN
    clearance = (f["joining_clearance"] if f["joining_clearance"] is not None
                 else CLEARANCE_SHARE * d)
    return FitInput(d, D_a, D_i, f["length"], U_min, U_max, name, src, f["rz_shaft"],
                    f["rz_hub"], f["joining"], f["surface"], mu, mu_src, mu_e, mu_e_src,
                    f["pressure_limit"], f["slip_safety"],
                    f["yield_safety"], f["shaft_modulus"], f["shaft_poisson"],
                    f["shaft_yield"], f["hub_modulus"], f["hub_poisson"], f["hub_yield"],
                    f["hub_expansion"], f["room_temperature"], clearance)


def _walls(d: float, D_a: float, D_i: float) -> None:
    problems = Problems()
    if D_a <= d:
        problems.at("fit.hub_outer_diameter", D_a, f"must be larger than the joint diameter "
                    f"fit.diameter = {fmt(d)} mm (the hub needs a wall)")
    if D_i >= d:
        problems.at("fit.shaft_bore", D_i, f"must be smaller than the joint diameter "
                    f"fit.diameter = {fmt(d)} mm (0 for a solid shaft)")
    problems.raise_all()


def _grips(d: float, U_min: float, U_max: float, name: str) -> None:
    if U_max <= 0:
        what = f'"{name}" gives' if name else "the interferences give"
        raise InputError.at("fit.fit" if name else "fit.interference_max", name or U_max,
                            f"{what} no interference at {fmt(d)} mm (largest {fmt(U_max, 1)} "
                            f"µm): a clearance or transition fit transmits nothing by "
                            f"friction; choose an interference fit such as H7/s6")
