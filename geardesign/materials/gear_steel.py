"""Gear steels for GOST 21354-87: the library (``gear_steel.toml``) and how a spec's
material table becomes a :class:`GearMaterial`.

A material is named by grade + heat treatment + hardness, or given by its treatment,
hardness and properties; explicit values override library values.  The strength data
that depend on the treatment class (σ_Hlim, S_H, Z_N max, σ_HPmax, σ_Flim, S_F, σ_FSt,
γ_A, q_F) come from the treatment table; sources are listed in the TOML file.
"""

from __future__ import annotations

import re
from dataclasses import field
from functools import lru_cache
from pathlib import Path

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass

DATA = Path(__file__).with_name("gear_steel.toml")

E_STEEL = 2.06e5   # MPa (GOST 21354-87 Z_E = 190 for steel pairs follows from it with ν = 0.3)
NU_STEEL = 0.3

#: blank factors: S_F'' (bending safety factor for the blank, MATLAB DANNYE ``SFII``) and
#: Y_z (limit stress under peak load, Delphi ``TPer``): forging or stamping / rolled /
#: casting.
BLANKS = {"forging": (1.0, 1.0), "rolled": (1.15, 0.9), "casting": (1.3, 0.8)}

_LINEAR = re.compile(r"^\s*(?:(?P<a>[\d.]+)\s*\*\s*(?P<var>[A-Za-z_]+))?\s*(?:\+?\s*(?P<b>[\d.]+))?\s*$")


def linear(expr: str, values: dict[str, float | None]) -> float | None:
    """Evaluate a table entry of the form ``a*X + b`` or ``b`` (X a named hardness or
    σ_T); ``None`` if X is not known."""
    m = _LINEAR.match(expr)
    if not m:
        raise ValueError(f"gear_steel.toml: cannot read {expr!r}")
    b = float(m.group("b")) if m.group("b") else 0.0
    if m.group("var") is None:
        return b
    x = values.get(m.group("var"))
    return None if x is None else float(m.group("a")) * x + b


@lru_cache(maxsize=1)
def library() -> dict:
    from geardesign.core.data import toml_table

    return toml_table(DATA)


#: Russian grade letters written in Latin as in the library (GOST 4543 names: 40Х -> 40Kh).
_TRANSLIT = str.maketrans({"Х": "Kh", "х": "Kh", "Н": "N", "н": "N", "А": "A", "а": "A",
                           "М": "M", "м": "M", "Г": "G", "г": "G", "Т": "T", "т": "T",
                           "Ю": "Yu", "ю": "Yu", "С": "S", "с": "S", "Ф": "F", "В": "V",
                           "Р": "R", "Ц": "Ts", "Ц".lower(): "Ts", "Л": "L", "л": "L"})


def normalize_grade(name: str) -> str:
    """Library spelling of a grade: Cyrillic letters transliterated, spaces dropped
    (``"40Х"`` and ``"40X"`` -> ``"40Kh"``, ``"12ХН3А"`` -> ``"12KhN3A"``, cast steel
    ``"40ХЛ"`` -> ``"40KhL"``)."""
    name = name.strip().replace(" ", "").translate(_TRANSLIT)
    if name in library()["steel"]:
        return name
    latin = name.replace("X", "Kh").replace("x", "Kh")
    return latin if latin in library()["steel"] else name


def _plain(name: str) -> str:
    return "".join(name.split()).upper().replace("AISI", "").replace("SAE", "")


def equivalent_of(name: str) -> str | None:
    """The library grade that lists ``name`` among its equivalent grades (``"4140"``,
    ``"AISI 4140"`` -> ``"42CrMo4"``; ``"C45"`` -> ``"45"``), or None."""
    k = _plain(name)
    for grade, steel in library()["steel"].items():
        if any(_plain(e) == k for e in steel.get("equivalents", ())):
            return grade
    return None


def grades() -> tuple[str, ...]:
    return tuple(library()["steel"])


def treatments() -> tuple[str, ...]:
    return tuple(library()["treatment"])


# --- hardness conversion ---------------------------------------------------------------


def hb_from_hrc(hrc: float) -> float:
    """Brinell hardness from Rockwell C (cubic fit of the conversion chart).

    .. math:: HB = 0.118508·HRC^2 + 0.440352·HRC + 149.565

    Reference: ZPCIL ``HBRCHV.h`` (public GOST 21354-87 program);
    GOST 21354-87 converts surface hardness in HRC to HB for N_HG.
    """
    return 0.118508 * hrc * hrc + 0.440352 * hrc + 149.565


def hv_from_hrc(hrc: float) -> float:
    """Vickers hardness from Rockwell C (ZPCIL ``HBRCHV.h`` cubic fit).

    .. math:: HV = 5.11658·10^{-3}·HRC^3 − 0.333507·HRC^2 + 13.8183·HRC + 19.1313
    """
    return 5.11658e-3 * hrc ** 3 - 0.333507 * hrc ** 2 + 13.8183 * hrc + 19.1313


def hrc_from_hv(hv: float) -> float:
    """Inverse of :func:`hv_from_hrc` (monotonic on 20…70 HRC), by bisection."""
    lo, hi = 0.0, 80.0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if hv_from_hrc(mid) < hv:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


@dataclass(frozen=True)
class TreatmentLimits:
    """The GOST 21354-87 data of a treatment class at a hardness (no grade needed)."""

    sigma_Hlim: float
    sigma_Flim: float
    S_H: float
    S_F: float
    Z_N_max: float
    gamma_A: float
    q_F: int


def treatment_limits(treatment: str, HB: float) -> TreatmentLimits:
    """Endurance limits and required safety factors of a homogeneous treatment
    (``normalized``, ``improved``) at a Brinell hardness, from ``gear_steel.toml``: used by
    calculators that borrow the GOST 21354-87 allowables (e.g. Novikov gears)."""
    t = library()["treatment"][treatment]
    if t["hardness"] != "HB":
        raise ValueError(f"treatment {treatment!r} is not rated by HB")
    values = {"HB": HB}
    return TreatmentLimits(linear(t["sigma_Hlim"], values), linear(t["sigma_Flim"], values),
                           t["S_H"], t["S_F"], t["Z_N_max"], t["gamma_A"], int(t["q_F"]))


# --- the material -----------------------------------------------------------------------


@dataclass(frozen=True)
class GearMaterial:
    """Everything GOST 21354-87 needs of one gear's material (MPa, hardness numbers)."""

    label: str
    treatment: str
    homogeneous: bool
    HB: float                 # surface hardness converted to HB (N_HG, ≤ 350 HB class)
    HRC: float | None
    HV: float | None
    HRC_core: float | None
    E: float
    nu: float
    sigma_T: float | None
    sigma_Hlim: float
    S_H: float
    Z_N_max: float
    sigma_HPmax: float | None
    sigma_Flim: float
    S_F: float
    sigma_FSt: float
    gamma_A: float
    q_F: int
    Y_z: float
    given: frozenset = field(default_factory=frozenset)
    warnings: tuple = ()
    #: the library row used (grade name) and where its numbers were read, or None for a
    #: material given by its properties
    grade: str | None = None
    source: str | None = None

    @property
    def soft(self) -> bool:
        """Surface hardness <= 350 HB (GOST 21354-87 "H <= 350 HB" class)."""
        return self.HB <= 350.0


def resolve(m: dict, key: str) -> GearMaterial:
    """Build a :class:`GearMaterial` from a validated ``[material.X]`` table.

    Raises :class:`InputError` naming ``key`` (e.g. ``material.pinion``) when the grade is
    unknown, the treatment does not suit it, or the hardness or a needed value is missing.
    """
    lib = library()
    treat_key = m["treatment"]
    treat = lib["treatment"][treat_key]
    grade = m.get("grade")
    steel = None
    alias_note = ""
    if grade is not None:
        grade = normalize_grade(grade)
        if grade not in lib["steel"] and equivalent_of(grade) is not None:
            alias = equivalent_of(grade)
            alias_note = (f"{key}: grade {m['grade']} read as {alias} "
                          f"({lib['steel'][alias]['standard']}), a grade of about the same "
                          f"chemistry; its data are that standard's")
            grade = alias
        steel = lib["steel"].get(grade)
        if steel is None:
            import difflib  # only to name a close match

            close = difflib.get_close_matches(grade, list(lib["steel"]), 3, 0.5)
            hint = f" (did you mean {', '.join(repr(c) for c in close)}?)" if close else ""
            raise InputError.at(f"{key}.grade", m["grade"],
                                f"unknown steel{hint}; known: {', '.join(lib['steel'])} (and "
                                f"equivalents such as 41Cr4, 4140, 1045: `geardesign materials` "
                                f"lists them); or leave out grade and give the properties")
        if treat_key not in steel["treatments"]:
            raise InputError.at(f"{key}.treatment", treat_key,
                                f"not a treatment for steel {grade}; use one of "
                                f"{', '.join(steel['treatments'])}")

    kind = treat["hardness"]
    hb, hrc, hv = m.get("hardness_HB"), m.get("hardness_HRC"), m.get("hardness_HV")
    given_hardness = {"HB": hb, "HRC": hrc, "HV": hv}[kind]
    if given_hardness is None:
        others = [k for k, v in (("hardness_HB", hb), ("hardness_HRC", hrc), ("hardness_HV", hv))
                  if v is not None]
        extra = f" (not {others[0]})" if others else ""
        raise InputError(Problem(f"{key}.hardness_{kind}",
                                 f"missing; required: the surface hardness in {kind} for "
                                 f"treatment \"{treat_key}\"{extra}"))
    if kind == "HB":
        HB, HRC, HV = hb, None, None
    elif kind == "HRC":
        HRC = hrc
        HB, HV = hb_from_hrc(hrc), hv_from_hrc(hrc)
    else:
        HV = hv
        HRC = hrc_from_hv(hv)
        HB = hb_from_hrc(HRC)
    core = m.get("core_HRC")
    if treat_key == "nitrided" and core is None and m.get("sigma_Flim") is None:
        raise InputError(Problem(f"{key}.core_HRC",
                                 "missing; required for a nitrided gear (σ_Flim = 12·HRC_core + 290), "
                                 "or give sigma_Flim"))

    warnings = [alias_note] if alias_note else []
    lo, hi = treat["range"]
    if not lo <= given_hardness <= hi:
        warnings.append(f"{key}: hardness {given_hardness:g} {kind} is outside the range "
                        f"{lo:g}…{hi:g} {kind} of treatment \"{treat_key}\"; GOST 21354-87 "
                        f"limits are given for that range only")
    if treat_key == "nitrided" and core is not None:
        clo, chi = treat["core_range"]
        if not clo <= core <= chi:
            warnings.append(f"{key}: core hardness {core:g} HRC is outside {clo:g}…{chi:g} HRC")

    ni = bool(steel and steel["Ni"])

    def pick(name: str) -> str:
        return treat.get(f"{name}_Ni", treat[name]) if ni else treat[name]

    sigma_T = m.get("sigma_T")
    if sigma_T is None and steel is not None:
        for min_hb, t, value in steel["sigma_T"]:
            if t == treat_key and HB >= min_hb:
                sigma_T = value
        if treat_key == "through_hardened" and sigma_T is not None:
            warnings.append(
                f"{key}: σ_T = {sigma_T:g} MPa is the {steel['standard']} minimum of the "
                f"grade after quenching and tempering at 500 °C or above, far below the "
                f"yield strength at {given_hardness:g} {kind}; σ_HPmax = 2.8·σ_T is then on "
                f"the safe side; give the blank's yield strength as sigma_T")
    values = {"HB": HB, "HRC": HRC, "HV": HV, "HRC_core": core, "sigma_T": sigma_T}
    S_F = treat.get("S_F_Ni", treat["S_F"]) if ni else treat["S_F"]
    blank_SF, Y_z = BLANKS[m["blank"]]

    def val(name: str, default):
        v = m.get(name)
        return (v, True) if v is not None else (default, False)

    given = set()
    out = {}
    for name, default in (
        ("sigma_Hlim", linear(treat["sigma_Hlim"], values)),
        ("sigma_Flim", linear(pick("sigma_Flim"), values)),
        ("sigma_FSt", linear(pick("sigma_FSt"), values)),
        ("sigma_HPmax", linear(treat["sigma_HPmax"], values)),
        ("S_H", treat["S_H"]),
        ("S_F", S_F * blank_SF),
        ("E", E_STEEL),
        ("nu", NU_STEEL),
    ):
        out[name], was_given = val(name, default)
        if was_given:
            given.add(name)
    if out["sigma_HPmax"] is None:
        if steel is not None:
            raise InputError(Problem(f"{key}.sigma_T",
                                     f"missing; required for the static contact check of a "
                                     f"\"{treat_key}\" gear (σ_HPmax = 2.8·σ_T) and the library "
                                     f"row of steel {grade} has no yield strength for it "
                                     f"(not found in its source): give the yield strength of "
                                     f"the blank as sigma_T, or sigma_HPmax"))
        raise InputError(Problem(f"{key}.sigma_T",
                                 "missing; required for the static contact check of a "
                                 f"\"{treat_key}\" gear (σ_HPmax = 2.8·σ_T): give the yield "
                                 "strength of the blank, or a grade, or sigma_HPmax"))
    label = ", ".join(x for x in (grade, treat["name"],
                                  f"{given_hardness:g} {kind}") if x)
    return GearMaterial(
        label=label, treatment=treat_key, homogeneous=treat["homogeneous"], HB=HB, HRC=HRC,
        HV=HV, HRC_core=core, E=out["E"], nu=out["nu"], sigma_T=sigma_T,
        sigma_Hlim=out["sigma_Hlim"], S_H=out["S_H"], Z_N_max=treat["Z_N_max"],
        sigma_HPmax=out["sigma_HPmax"], sigma_Flim=out["sigma_Flim"], S_F=out["S_F"],
        sigma_FSt=out["sigma_FSt"], gamma_A=treat["gamma_A"],
        q_F=6 if m["root_ground"] else int(treat["q_F"]), Y_z=Y_z,
        given=frozenset(given), warnings=tuple(warnings), grade=grade if steel else None,
        source=source_of(grade) if steel else None)


def source_of(grade: str) -> str:
    """Where the numbers of library grade ``grade`` were read: the row's ``source``, or for
    the GOST rows (which carry none) the standard of the blank strength, [Dunaev] table 2.1
    for the hardness bands of improved blanks and [GOST21354] for the allowables of the
    treatment table (see the comment of ``gear_steel.toml``)."""
    steel = library()["steel"][grade]
    return steel.get("source", f"σ_T: {steel['standard']} test piece, of improved blanks by "
                               f"hardness band after [Dunaev] table 2.1 (unverified); "
                               f"allowables [GOST21354]")


def data_used(m: GearMaterial) -> str:
    """One line naming where the data of material ``m`` come from, for the reports: the
    library row and its source, and the values the spec gave instead."""
    given = ", ".join(sorted(m.given))
    if m.grade is None:
        return "given in the spec" + (f" ({given})" if given else "") + \
            "; allowables of the treatment table ([GOST21354])"
    return f"library row {m.grade}: {m.source}" + (f"; given in the spec: {given}"
                                                   if given else "")


def iso_type(grade: str | None, treatment: str) -> str | None:
    """The ISO 6336-5 material type the library row of ``grade`` gives for ``treatment``
    (the ``iso6336_5`` table of the row), or None."""
    if grade is None or grade not in library()["steel"]:
        return None
    return library()["steel"][grade].get("iso6336_5", {}).get(treatment)


__all__ = ["GearMaterial", "resolve", "grades", "treatments", "hb_from_hrc", "hv_from_hrc",
           "hrc_from_hv", "BLANKS", "source_of", "iso_type", "data_used"]
