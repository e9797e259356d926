"""The typed data of the shaft analysis: the inputs (:class:`Step`, :class:`Load`,
:class:`Support`, :class:`Material`, :class:`Options`, joined in :class:`Inputs`) and the
records it returns (:class:`ShaftRecord` with a :class:`PointRecord` per support and load
and a :class:`SectionRecord` per section rated).  Frozen dataclasses, no formulas.

Lengths mm, forces N, torques and couples N·m, stresses MPa, speeds min⁻¹, angles rad.
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.records import dataclass
from geardesign.gears.geometry import STEEL_DENSITY
from geardesign.shaft.din743 import rating as DR

ARCMIN = math.pi / (180.0 * 60.0)


@dataclass(frozen=True)
class Step:
    length: float
    diameter: float
    bore: float = 0.0
    fillet: float = 1.0              # fillet radius at the right end, mm
    keyway: bool = False
    keyway_cutter: str = "end_mill"
    press_fit: bool = False
    groove_K_sigma: float | None = None   # groove at the right end: effective factors
    groove_K_tau: float | None = None
    Rz: float | None = None          # roughness, µm (None: the shaft's)
    # DIN 743 notches by geometry (mm): a groove at the right end, cut into this step —
    # round (depth and radius) or rectangular (with its width) — and a cross-bore
    groove_depth: float | None = None
    groove_radius: float | None = None
    groove_width: float | None = None
    cross_bore: float | None = None
    cross_bore_at: float | None = None   # from the step's left end (None: the middle)
    groove_shape: str | None = None      # "round", "rectangular", "V" (None: by the width)

    @property
    def groove_kind(self) -> str:
        """The groove's shape: ``groove_shape``, else rectangular with a width, else round."""
        if self.groove_shape:
            return self.groove_shape
        return "rectangular" if self.groove_width is not None else "round"

    @property
    def cross_bore_x(self) -> float:
        """Position of the cross-bore from the step's left end [mm]."""
        return self.length / 2.0 if self.cross_bore_at is None else self.cross_bore_at


@dataclass(frozen=True)
class Load:
    position: float
    Fy: float = 0.0
    Fz: float = 0.0
    Fx: float = 0.0
    torque: float = 0.0              # N·m, input positive, output negative
    moment_y: float = 0.0            # N·m
    moment_z: float = 0.0            # N·m
    mass: float = 0.0                # kg (critical speed)
    name: str = ""
    module: float | None = None      # mm: gear seat deflection limit 0.01·m


@dataclass(frozen=True)
class Support:
    position: float
    stiffness: float | None = None   # radial, N/mm; None = rigid
    type: str = "other"
    axial: bool = False
    name: str = ""


@dataclass(frozen=True)
class Material:
    sigma_B: float
    sigma_T: float
    sigma_m1: float
    tau_m1: float
    psi_sigma: float
    psi_tau: float
    E: float = 2.06e5
    density: float = STEEL_DENSITY   # kg/m³
    alloy: bool = False
    din: DR.Material | None = None   # the DIN 743 steel at its blank size (method DIN743)


@dataclass(frozen=True)
class Options:
    speed: float = 0.0               # min⁻¹
    peak_factor: float = 2.0         # peak / nominal load (static check)
    torsion_cycle: str = "pulsating"
    Rz: float = 6.3                  # µm
    K_V: float = 1.0                 # surface hardening factor
    method: str = "GOST"             # "GOST" or "DIN743"
    load_case: int = 2               # DIN 743-1 load case
    hard_surface: bool = False       # DIN 743 hard surface layer


@dataclass(frozen=True)
class SectionRecord:
    x: float
    label: str
    d: float
    bore: float
    M: float          # resultant bending moment, N·m
    T: float          # torque, N·m
    N: float          # axial force, N (tension positive)
    sigma_a: float
    sigma_m: float
    tau_a: float
    tau_m: float
    sigma_v_peak: float
    S_static: float
    concentrator: str
    ratio_sigma: float      # K_σ/K_dσ used
    ratio_tau: float
    K_F_sigma: float
    K_sigma_D: float
    K_tau_D: float
    S_sigma: float
    S_tau: float
    S: float
    outside_table: bool = False
    fillet_K_sigma: float | None = None   # shoulder with a fillet at this section
    fillet_t: float | None = None
    fillet_r: float | None = None
    keyway_cutter: str = ""
    din: DR.Rating | None = None          # method DIN743: every factor of the section


@dataclass(frozen=True)
class PointRecord:
    x: float
    name: str
    w_y: float
    w_z: float
    w: float          # mm
    slope: float      # rad, resultant
    R_y: float = 0.0  # support reaction on the shaft, N
    R_z: float = 0.0
    R_x: float = 0.0
    slope_y: float = 0.0   # rad, dw_y/dx (x–y plane)
    slope_z: float = 0.0   # rad, dw_z/dx (x–z plane)


@dataclass(frozen=True)
class ShaftRecord:
    length: float
    mass: float
    x: list
    M_y: list
    M_z: list
    M: list
    V_y: list
    V_z: list
    T: list
    N: list
    w_y: list
    w_z: list
    w: list
    slope: list
    supports: list
    loads: list
    sections: list
    omega_cr: float
    n_cr: float
    critical: SectionRecord | None
    critical_static: SectionRecord | None


@dataclass(frozen=True)
class Inputs:
    """Everything :func:`geardesign.shaft.solve.solve` reads: the steps from the left end,
    the loads, the supports, the material and the options; ``origin`` says where each
    material property comes from (the report's sources, :func:`.inputs.model`)."""

    steps: tuple
    loads: tuple
    supports: tuple
    material: Material
    options: Options = Options()
    origin: dict | None = field(default=None, compare=False)
