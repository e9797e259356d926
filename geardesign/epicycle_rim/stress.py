"""Stresses in the tooth-root fillets and the rim of a thin ring gear (paper A, steps 1-6).

Pure functions on plain data; stresses in MPa.  The chain of paper A (Gutyria et al. 2017):

1. loading-mode factor μ_F of each stage, eq. (2);
2. nominal tooth-bending stress σ_Fn = σ_F / Y_F;
3. Huber-von Mises combination with the rim hoop stress, eq. (3);
4. design stresses σ = K_c·σ_n·μ_F, eq. (1);
5. the stress cycle of each fillet in each stage (Table 1 structure);
6. the equivalent symmetric amplitude from a limiting-amplitude (Haigh) diagram, eq. (8),
   or, selectable, Goodman, Gerber and Serensen-Kinasoshvili.

Equations (2) and (3) are garbled in the printed source; their reconstruction ([Gutyria2017],
uncertainty register items 1-2) reproduces three of the four
columns of the paper's Table 1 to ±0.03 MPa.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

FILLETS = ("left", "right")


def loading_mode_factor(torque_levels: list[float], time_fractions: list[float],
                        q_F: float) -> float:
    """Loading-mode factor of a stage from its torque spectrum.

    .. math:: μ_F = \\Big[\\sum_i (T_i/T_{max})^{q_F}\\, t_i/t_Σ\\Big]^{1/q_F}

    Parameters
    ----------
    torque_levels : relative torques T_i/T_max, 0 < T_i' <= 1 [-].
    time_fractions : durations t_i of each level (any unit; normalised by their sum).
    q_F : exponent of the fatigue curve (6 for HB < 350, 9 above) [-].

    References
    ----------
    Gutyria et al. 2017, eq. (2) (Palmgren-Miner summation); the outer 1/q_F root is
    reconstructed ([Gutyria2017] eq. (2)): μ_F
    multiplies a stress in eq. (1).
    """
    total = sum(time_fractions)
    s = sum(t ** q_F * w / total for t, w in zip(torque_levels, time_fractions))
    return s ** (1.0 / q_F)


def mode_factor_from_table(k_FE: float, q_F: float) -> float:
    """μ_F of a GOST 21354-87 typical loading mode: the q_F-th root of its equivalence
    factor K_FE (the table holds K_FE; eq. (2) of Gutyria et al. 2017 works with the root).

    References
    ----------
    GOST 21354-87 typical loading modes (table in ``tables.toml``, from [Gutyria2017]; the GOST text
    was not consulted); Gutyria et al. 2017, eq. (2).
    """
    return k_FE ** (1.0 / q_F)


def nominal_bending_stress(sigma_F: float, Y_F: float) -> float:
    """Nominal tooth-bending stress without concentration.

    .. math:: σ_{Fn} = σ_F / Y_F

    Parameters
    ----------
    sigma_F : root bending stress by GOST 21354-87 [MPa].
    Y_F : tooth form factor, which includes the root stress concentration [-].

    References
    ----------
    Gutyria et al. 2017, text before eq. (1) (259.3/3.3 = 78.6 MPa).
    """
    return sigma_F / Y_F


def von_mises_plane(s1: float, s2: float) -> float:
    """Huber-von Mises equivalent stress of a plane state without shear.

    .. math:: σ_{eq} = \\sqrt{σ_1^2 + σ_2^2 - σ_1 σ_2}

    Parameters
    ----------
    s1, s2 : normal stresses in two perpendicular directions [MPa].

    References
    ----------
    Gutyria et al. 2017, eq. (3) (reconstructed; shear τ ≈ 0.05σ_t neglected as the paper
    states); [Gutyria2017] eq. (3).

    Examples: uniaxial σ gives σ; σ1 = −σ2 (pure shear τ = σ) gives √3·σ:

    >>> von_mises_plane(100.0, 0.0)
    100.0
    >>> round(von_mises_plane(100.0, -100.0), 4)
    173.2051
    """
    return math.sqrt(s1 * s1 + s2 * s2 - s1 * s2)


@dataclass(frozen=True)
class Cycle:
    """Stress cycle of one fillet in one stage [MPa]; ``R`` = σ_min/σ_max."""

    fillet: str
    stage: str
    mu_F: float
    s_max: float
    s_min: float

    @property
    def R(self) -> float:
        return self.s_min / self.s_max if self.s_max != 0.0 else -math.inf

    @property
    def s_m(self) -> float:
        return 0.5 * (self.s_max + self.s_min)

    @property
    def s_a(self) -> float:
        return 0.5 * (self.s_max - self.s_min)


@dataclass(frozen=True)
class RimStresses:
    """Nominal stresses at the loaded tooth [MPa].

    ``eq_tension``/``eq_compression``: Huber-Mises combination of ±σ_Fn with the hoop stress
    under the loaded tooth, signed as the bending (+ tension side, − compression side).
    """

    sigma_Fn: float
    hoop_loaded: float
    hoop_between: float
    eq_tension: float
    eq_compression: float


def rim_stresses(sigma_Fn: float, hoop_loaded: float, hoop_between: float) -> RimStresses:
    """Signed Huber-Mises stresses of the two fillets of the loaded tooth.

    Parameters
    ----------
    sigma_Fn : nominal bending stress (> 0) [MPa].
    hoop_loaded : rim hoop stress on the inner surface under the loaded tooth σ_t,load [MPa].
    hoop_between : rim hoop stress midway between loaded teeth σ_t,betw [MPa].

    References
    ----------
    Gutyria et al. 2017, eq. (3), reconstructed ([Gutyria2017] eq. (3): 130.87 MPa on the
    tension side and −75.72 MPa on the compression side for the Raba 118/77 ring).
    """
    return RimStresses(
        sigma_Fn, hoop_loaded, hoop_between,
        von_mises_plane(sigma_Fn, hoop_loaded),
        -von_mises_plane(-sigma_Fn, hoop_loaded),
    )


def fillet_cycles(rs: RimStresses, K_c: float, stage: str, mu_F: float,
                  tension_fillet: str) -> list[Cycle]:
    """Stress cycles of both fillets of a tooth in one stage (one cycle per planet passage).

    Design stress σ = K_c·σ_n·μ_F (eq. (1)).  The fillet on the tension side of the loaded
    tooth cycles between the Mises stress of the loaded tooth and the rim stress under it;
    the fillet on the compression side between the rim stress midway between loaded teeth
    and the (negative) Mises stress:

    ================  =====================  ========================
    fillet            σ_max                  σ_min
    ================  =====================  ========================
    tension side      K_c μ_F σ_eq,tension   K_c μ_F σ_t,load
    compression side  K_c μ_F σ_t,betw       K_c μ_F σ_eq,compression
    ================  =====================  ========================

    Parameters
    ----------
    rs : nominal stresses (:func:`rim_stresses`).
    K_c : load-sharing non-uniformity factor between planets [-].
    stage : stage name; mu_F : its loading-mode factor [-].
    tension_fillet : ``"left"`` or ``"right"``, the fillet on the tension side in this stage.

    References
    ----------
    Gutyria et al. 2017, eq. (1) and Table 1 (structure reconstructed).
    """
    f = K_c * mu_F
    out = []
    for fillet in FILLETS:
        if fillet == tension_fillet:
            out.append(Cycle(fillet, stage, mu_F, f * rs.eq_tension, f * rs.hoop_loaded))
        else:
            out.append(Cycle(fillet, stage, mu_F, f * rs.hoop_between, f * rs.eq_compression))
    return out


# ----------------------------------------------------------------- mean-stress correction

MEAN_STRESS_MODELS = ("cubic", "goodman", "gerber", "kinasoshvili")


def equivalent_amplitude(s_a: float, s_m: float, sigma_u: float, model: str = "cubic",
                         psi_D: float | None = None) -> float:
    """Amplitude of the symmetric cycle equivalent to (σ_a, σ_m).

    With s = σ_m/σ_u:

    * ``cubic`` (paper A, modified Heywood diagram, eq. (7)/(8)):
      σ_-1eq = σ_a / [1 − (s + s² + s³)/3]
    * ``goodman``: σ_-1eq = σ_a / (1 − s)
    * ``gerber``: σ_-1eq = σ_a / (1 − s²)
    * ``kinasoshvili`` (Serensen-Kinasoshvili): σ_-1eq = σ_a + ψ_σD·σ_m, with
      ψ_σD = ψ_σ/K the part's mean-stress sensitivity
      (:func:`geardesign.fatigue.gost25504.mean_stress_sensitivity`)

    The diagrams hold inside the 45° rays from σ_m = ±σ_u, i.e. |σ_m| + σ_a < σ_u; outside,
    the result is NaN (the calculator reports a failed check instead).

    Parameters
    ----------
    s_a, s_m : amplitude and mean stress [MPa]; sigma_u : ultimate strength [MPa].
    model : one of :data:`MEAN_STRESS_MODELS`; psi_D : ψ_σD for ``kinasoshvili`` [-].

    References
    ----------
    Gutyria et al. 2017, eq. (7) and (8) (verified against Table 1 to ±0.02 MPa);
    Goodman, Gerber: eq. (4) of the same paper with (k1, k2) = (1, 0) and (0, 1);
    Serensen-Kinasoshvili: GOST 25.504-82 (form from [Gutyria2017] eqs. (4)-(8), the
    GOST text was not consulted).
    """
    if abs(s_m) + s_a >= sigma_u:
        return math.nan
    s = s_m / sigma_u
    if model == "cubic":
        return s_a / (1.0 - (s + s * s + s ** 3) / 3.0)
    if model == "goodman":
        return s_a / (1.0 - s)
    if model == "gerber":
        return s_a / (1.0 - s * s)
    if model == "kinasoshvili":
        if psi_D is None:
            raise ValueError("kinasoshvili needs psi_D")
        return s_a + psi_D * s_m
    raise ValueError(f"unknown mean-stress model {model!r}")


# ----------------------------------------------------------------- thin-ring hoop estimate


@dataclass(frozen=True)
class HoopEstimate:
    """Thin-ring estimate of the hoop stress on the inner rim surface [MPa]."""

    F_t: float          # tangential mesh force per planet [N]
    F_r: float          # radial (separating) force per planet [N]
    R_m: float          # mean radius of the rim [mm]
    M_load: float       # bending moment under a load [N·mm]
    M_between: float    # bending moment midway between loads [N·mm]
    N_load: float       # hoop force under a load [N]
    N_between: float    # hoop force midway [N]
    hoop_loaded: float
    hoop_between: float


def thin_ring_hoop_stress(torque: float, module: float, z: int, n_planets: int,
                          face_width: float, rim_thickness: float,
                          pressure_angle: float) -> HoopEstimate:
    """Hoop stress of the rim loaded by the n_p radial mesh forces, as a free thin ring.

    A thin ring of mean radius R_m and section b×δ carries n equal outward radial loads F_r,
    2β = 2π/n apart.  Bending moments (inner fibre in compression under a load, in tension
    midway) and hoop forces:

    .. math::
        M_A = \\frac{F_r R_m}{2}\\Big(\\frac1β - \\cot β\\Big),\\quad
        M_B = \\frac{F_r R_m}{2}\\Big(\\frac1{\\sin β} - \\frac1β\\Big),\\quad
        N_A = \\frac{F_r}{2\\tan β},\\quad N_B = \\frac{F_r}{2\\sin β}

    σ_t,load = −6M_A/(bδ²) + N_A/(bδ), σ_t,betw = +6M_B/(bδ²) + N_B/(bδ).  For n = 2 this is
    the ring in diametral tension: M_A = F·R/π, M_B = F·R·(1/2 − 1/π), N_A = 0, N_B = F/2.

    Loads: F_t = 2000·T/(d·n_p) at the reference diameter d = m·z, F_r = F_t·tan α_w; the
    mean radius R_m = d/2 + 1.25m + δ/2 (root radius of a ring without profile shift).

    It ignores the teeth, which stiffen the section, the tangential mesh forces and the
    spline supports: for the Raba 118/77 ring it gives about twice the finite-element values
    that paper A uses ([Roark]).  Use it only when no FE values are at hand.

    Parameters
    ----------
    torque : ring torque [N·m]; module [mm]; z : ring teeth; n_planets : planets;
    face_width, rim_thickness : b and δ [mm]; pressure_angle : working pressure angle [rad].

    References
    ----------
    Thin circular ring under equal radial loads: Timoshenko, Strength of Materials, Part I,
    §"thin curved bars"; Roark's Formulas for Stress and Strain, ring cases (case number not
    checked); [Roark] (not validated against the paper).
    """
    d = module * z
    F_t = 2000.0 * torque / (d * n_planets)
    F_r = F_t * math.tan(pressure_angle)
    R_m = 0.5 * d + 1.25 * module + 0.5 * rim_thickness
    beta = math.pi / n_planets
    M_A = 0.5 * F_r * R_m * (1.0 / beta - 1.0 / math.tan(beta))
    M_B = 0.5 * F_r * R_m * (1.0 / math.sin(beta) - 1.0 / beta)
    N_A = F_r / (2.0 * math.tan(beta))
    N_B = F_r / (2.0 * math.sin(beta))
    W = face_width * rim_thickness ** 2 / 6.0
    A = face_width * rim_thickness
    return HoopEstimate(F_t, F_r, R_m, M_A, M_B, N_A, N_B,
                        -M_A / W + N_A / A, M_B / W + N_B / A)
