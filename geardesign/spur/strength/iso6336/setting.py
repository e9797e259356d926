"""The ISO 6336 inputs of a pair beyond the GOST setting: :class:`IsoSetting` (accuracy,
lubricant, misalignment, required safety factors, given factors), the data of each gear
(:class:`IsoGear`) and the scuffing inputs (:class:`ScuffingSetting`), as
:mod:`.spec` builds them from ``[iso]``, ``[iso.pinion]``, ``[iso.wheel]`` and
``[iso_factors]``."""

from __future__ import annotations

from dataclasses import dataclass, field

from geardesign.spur.strength.iso6336 import tables as T
from geardesign.spur.tolerances import iso1328


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
