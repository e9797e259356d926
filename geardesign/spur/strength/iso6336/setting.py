"""The ISO 6336 inputs of a pair beyond the GOST setting: :class:`IsoSetting` (accuracy,
lubricant, misalignment, required safety factors, given factors), the data of each gear
(:class:`IsoGear`) and the scuffing inputs (:class:`ScuffingSetting`), and
their builders from the validated tables ``[iso]``, ``[iso.pinion]``, ``[iso.wheel]``,
``[iso.scuffing]`` and ``[iso_factors]`` (:func:`setting_from`, :func:`scuffing_setting`;
the spur spec's :func:`.spec.iso_setting`, the planetary meshes')."""

from __future__ import annotations

from dataclasses import field

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.tolerances import iso1328
from geardesign.spur.tolerances.iso1328 import EDITIONS as TOLERANCE_EDITIONS


@dataclass(frozen=True)
class IsoGear:
    """ISO inputs of one gear."""

    material: str | None = None       # ISO 6336-5 type; None: from the heat treatment
    quality: str = "MQ"
    sigma_Hlim: float | None = None
    sigma_Flim: float | None = None
    Rz_flank: float | None = None     # µm; None: 6·Ra of the flank
    Rz_root: float = 10.0             # µm
    inner_diameter: float = 0.0       # bore of the gear body, mm
    rim_thickness: float | None = None  # s_R below the root, mm; None: solid
    web_ratio: float | None = None    # b_s/b of a web gear; None: solid


@dataclass(frozen=True)
class ScuffingSetting:
    """Oil and lubrication of the scuffing rating (ISO/TS 6336-21)."""

    fzg_load_stage: int                # FZG A/8.3/90 failure load stage of the oil, 1..14
    oil_temperature: float             # °C, before the mesh (sump or injection)
    nu100: float | None = None         # mm²/s; None: from ν40 with VI 95
    density15: float = 890.0           # kg/m³
    lubricant: str = "mineral"         # key of tables.SCUFFING_X_L
    lubrication: str = "dip"           # key of tables.SCUFFING_X_S
    meshes: int = 1                    # gears the pinion meshes with (X_mp)
    driving: str = "pinion"
    structure: str | None = None       # key of tables.SCUFFING_X_WRELT; None: from the types
    B_M: float = T.B_M_STEEL           # N/(mm·s^½·K)
    S_Smin: float = 1.8


@dataclass(frozen=True)
class IsoSetting:
    """ISO 6336 inputs of a pair beyond the GOST setting."""

    grade: int | None = None           # ISO 1328-1 flank tolerance class; None: the spec's grade
    tolerance_standard: str = iso1328.STANDARD   # edition of ISO 1328-1 of the tolerances
    nu40: float = 220.0                # mm²/s
    C_a: float | None = None           # tip relief, µm; None: C_ay from running-in
    modification: str = "none"
    f_ma: float | None = None          # µm
    f_sh: float | None = None          # µm
    K_prime: float = 0.0
    shaft_span: float | None = None
    pinion_offset: float = 0.0
    shaft_diameter: float | None = None
    f_pb: float | None = None          # µm
    f_falpha: float | None = None      # µm
    F_beta: float | None = None        # µm
    S_Hmin: float = 1.0
    S_Fmin: float = 1.4
    limited_pitting: bool = False
    optimum: bool = False
    protuberance: float = 0.0          # s_pr/m_n
    K_gamma: float = 1.0
    # meshes of this kind each gear carries, for the reduced mass: (n_P, 1) for a sun that is
    # gear 1 of a sun–planet mesh with n_P planets ([ISO6336-1] 6.5.9, planetary gears)
    meshes: tuple[int, int] = (1, 1)
    gears: tuple[IsoGear, IsoGear] = (IsoGear(), IsoGear())
    scuffing: ScuffingSetting | None = None
    overrides: dict = field(default_factory=dict)


def default_setting(setting) -> IsoSetting:
    """The ISO inputs a caller that has only the GOST setting gets: its accuracy grade,
    every other ISO input at its default."""
    return IsoSetting(grade=setting.grade)


def tolerance_class(iso: dict, accuracy: dict | None = None) -> tuple[str, int | None]:
    """The ISO 1328-1 edition and class of the rating's tolerances: ``[iso]``
    tolerance_standard and accuracy_grade; else those of ``accuracy`` (a spur spec's
    ``[accuracy]``) when it names an ISO 1328-1 edition (the drawing's tolerances); else
    ISO 1328-1:2013 and None (the caller's grade, gear.accuracy_grade)."""
    acc = accuracy or {}
    drawing = acc.get("standard") in TOLERANCE_EDITIONS
    standard = iso.get("tolerance_standard") or (acc["standard"] if drawing
                                                 else TOLERANCE_EDITIONS[0])
    grade = iso.get("accuracy_grade")
    if grade is None and drawing and acc["standard"] == standard:
        grade = acc.get("grade")
    return standard, grade


def setting_from(iso: dict, gears: tuple[dict, dict], overrides: dict, scuffing,
                 accuracy: dict | None = None, **extra):
    """The :class:`~.rating.IsoSetting` of validated ``[iso]`` pair keys, the two gear
    tables in rating order, the given factors, the scuffing setting and the tolerances'
    edition and class (:func:`tolerance_class`; ``accuracy``: a spur spec's ``[accuracy]``)
    (``extra``: further fields of the setting, e.g. a planetary mesh's ``K_gamma`` and
    ``nu40``)."""
    standard, grade = tolerance_class(iso, accuracy)
    values = dict(
        grade=grade, tolerance_standard=standard, C_a=iso["tip_relief"],
        modification=iso["helix_modification"], f_ma=iso["f_ma"], f_sh=iso["f_sh"],
        K_prime=iso["shaft_K_prime"], shaft_span=iso["shaft_span"],
        pinion_offset=iso["pinion_offset"], shaft_diameter=iso["shaft_diameter"],
        f_pb=iso["f_pb"], f_falpha=iso["f_falpha"], F_beta=iso["F_beta"],
        S_Hmin=iso["S_Hmin"], S_Fmin=iso["S_Fmin"], limited_pitting=iso["limited_pitting"],
        optimum=iso["optimum_conditions"], protuberance=iso["protuberance"],
        gears=tuple(IsoGear(t["material_type"], t["quality"], t["sigma_Hlim"], t["sigma_Flim"],
                            t["Rz_flank"], t["Rz_root"], t["inner_diameter"],
                            t["rim_thickness"], t["web_ratio"]) for t in gears),
        overrides=dict(overrides), scuffing=scuffing)
    if "lubricant_viscosity" in iso:
        values["nu40"] = iso["lubricant_viscosity"]
    values.update(extra)
    return IsoSetting(**values)


def scuffing_oil_domain(t: dict, nu40: float, where: str) -> None:
    """Refuse a scuffing oil outside the domain of its viscosity formulas: ν100 (given, or from
    ν40 with VI 95 by ASTM D2270) and ν at the oil temperature by ASTM D341 (Ubbelohde–Walther,
    Z = ν + 0.7), which hold for ν >= 2 mm²/s.  ``where`` is the key of the table
    (``iso.scuffing``, ``strength.scuffing``).  Raises :class:`InputError` naming the key."""
    from geardesign.materials.lubricants import OilError, nu100_from_vi, viscosity_at

    nu100 = t["oil_viscosity_100"]
    key = f"{where}.oil_viscosity_100"
    try:
        if nu100 is None:
            nu100 = nu100_from_vi(nu40, 95.0)
    except OilError as exc:
        raise InputError(Problem(key, f"missing, and the one from ν40 = {nu40:g} mm²/s with "
                            f"viscosity index 95 cannot be used ({exc}); give it")) from None
    try:
        viscosity_at(t["oil_temperature"], nu40, nu100)
    except OilError as exc:
        raise InputError.at(f"{where}.oil_temperature", t["oil_temperature"],
                            f"the oil (ν40 = {nu40:g}, ν100 = {nu100:g} mm²/s) is outside the "
                            f"viscosity-temperature relation there ({exc})") from None


def scuffing_setting(t: dict | None, meshes: int | None = None, nu40: float | None = None,
                     where: str = "iso.scuffing"):
    """The :class:`~.rating.ScuffingSetting` of a validated scuffing table (``[iso.scuffing]``
    or the planetary ``[strength.scuffing]``, which has no ``meshes`` and ``driving``:
    ``meshes`` then comes from the train); None without a table.  The oil is checked by
    :func:`scuffing_oil_domain` with ν40 (default that of
    :class:`~.rating.IsoSetting`)."""
    if t is None:
        return None
    scuffing_oil_domain(t, IsoSetting.nu40 if nu40 is None else nu40, where)
    return ScuffingSetting(
        fzg_load_stage=t["fzg_load_stage"], oil_temperature=t["oil_temperature"],
        nu100=t["oil_viscosity_100"], density15=t["oil_density"], lubricant=t["lubricant"],
        lubrication=t["lubrication"], meshes=meshes if meshes is not None else t["meshes"],
        driving=t.get("driving", "pinion"), structure=t["structure"],
        B_M=t["thermal_contact_coefficient"], S_Smin=t["S_Smin"])
