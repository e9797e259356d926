"""Cylindrical torsion spring of the PZDN (safety elastic gear coupling): strength,
stiffness, wind-up and geometry.  Pure functions on plain data.

Units: torque N·mm inside the formulas (N·m at the interface of :func:`design`), lengths mm,
stresses and moduli MPa, angles rad, stiffness N·mm/rad inside (N·m/rad at the interface).

Methods ([Lopukhov] §2.1, §2.2): the KO-2 thesis sizes the spring
as a curved beam in bending — σ = T·k/W ≤ [σ] — and takes its twist from the elastic line
of the coils, φ = T·L/(E·J), L = π·D·i.  Method A (one spring, thesis §2.1) adds the
bending of the loaded leg and requires the spring to absorb the angle the motor shaft
turns while it starts; method B (two springs, thesis §2.2) is the same without the leg.
Alternatives from the standards are selectable: the curvature factors of Wahl (inner fibre,
Shigley) and EN 13906-3, and the leg models of Shigley and EN 13906-3.
"""

from __future__ import annotations

import math
from dataclasses import field

from geardesign.core.records import dataclass

CURVATURE_MODELS = ("thesis", "wahl", "en13906")
LEG_MODELS = ("thesis", "shigley", "en13906_radial", "en13906_tangential")


# ----------------------------------------------------------------------------- strength


def curvature_factor(c: float, model: str = "thesis") -> float:
    """Stress correction (curvature) factor of a torsion spring coil in bending.

    * ``"thesis"``: k = (4c − 1)/(4c − 4) — KO-2 thesis eq. (2) of §2.1 and §2.2
      ([Lopukhov] §2.1); 1.0833 at c = 10.
    * ``"wahl"``: K_i = (4c² − c − 1)/(4c(c − 1)), the inner-fibre factor of a curved
      beam — Shigley, *Mechanical Engineering Design*, §10-12 eq. (10-43); 1.0806 at c = 10.
    * ``"en13906"``: q = (c + 0.07)/(c − 0.75) — EN 13906-3 (as implemented in the public
      EN 13906 program SpringTHREE, ``en13906.pas``); 1.0886 at c = 10.

    c = D/d is the spring index (mean coil diameter over wire diameter), c > 1.
    """
    if model == "thesis":
        return (4.0 * c - 1.0) / (4.0 * c - 4.0)
    if model == "wahl":
        return (4.0 * c * c - c - 1.0) / (4.0 * c * (c - 1.0))
    if model == "en13906":
        return (c + 0.07) / (c - 0.75)
    raise ValueError(f"unknown curvature model {model!r}")


def section_modulus(d: float) -> float:
    """Section modulus of the round wire in bending W = π·d³/32 [mm³] (KO-2 thesis eq. (4);
    the thesis computes with π = 3.14 and prints 21.195 mm³ for d = 6 mm: 21.206).

    Example: d = 6 mm gives W = π·216/32 = 21.206 mm³ (the thesis, with π = 3.14: 21.195):

    >>> round(section_modulus(6.0), 3)
    21.206
    """
    return math.pi * d ** 3 / 32.0


def second_moment(d: float) -> float:
    """Second moment of area of the wire J = π·d⁴/64 [mm⁴] (KO-2 thesis §2.1 eq. (9),
    §2.2 eq. (8))."""
    return math.pi * d ** 4 / 64.0


def bending_stress(T: float, k: float, d: float) -> float:
    """Bending stress of the coils σ = T·k/W [MPa], T [N·mm] (KO-2 thesis eq. (1))."""
    return T * k / section_modulus(d)


def min_wire_diameter(T: float, k: float, sigma_allow: float) -> float:
    """Least wire diameter d ≥ ∛(32·T·k/(π·[σ])) = 2.17·∛(T·k/[σ]) [mm], T [N·mm]
    (KO-2 thesis eq. (5) of §2.1/§2.2)."""
    return (32.0 * T * k / (math.pi * sigma_allow)) ** (1.0 / 3.0)


def allowable_torque(sigma_allow: float, k: float, d: float) -> float:
    """Torque at which the coils reach [σ]: T = [σ]·W/k [N·mm] (eq. (1) solved for T).

    Example: the inverse of :func:`bending_stress` (identity):

    >>> round(bending_stress(allowable_torque(600.0, 1.2, 6.0), 1.2, 6.0), 9)
    600.0
    """
    return sigma_allow * section_modulus(d) / k


# ----------------------------------------------------------------------------- stiffness


def wire_length(D: float, i: float) -> float:
    """Length of the working coils L = π·D·i [mm] (lead angle neglected, cos α ≈ 1;
    KO-2 thesis §2.1 eq. (11), §2.2 eq. (7))."""
    return math.pi * D * i


def leg_length(arm: float, D: float, model: str = "thesis") -> float:
    """Wire length [mm] with the same twist compliance as a loaded straight leg.

    The leg's bending adds φ_leg = T·L_leg/(E·J) to the twist of the coils, where T is the
    spring torque and ``arm`` R the distance from the spring axis to the point where the
    force acts (the finger of the coupling), so that F = T/R.

    * ``"thesis"``: φ₁ = F·l²/(2EJ) with F = T/l, l = R (KO-2 thesis §2.1 eqs. (7), (8),
      tip slope of a cantilever) → L_leg = R/2.
    * ``"shigley"``: each leg adds l/3 (tip deflection of a cantilever over the arm),
      N_a = N_b + (l1 + l2)/(3πD) — Shigley eq. (10-47) → L_leg = R/3.
    * ``"en13906_radial"``: radial leg from the coil to the load point, cantilever of length
      R − D/2 loaded at radius R → L_leg = (R − D/2)³/(3R²) (EN 13906-3 via SpringTHREE
      ``CalcRadialEndFlex`` (2R/D − 1)³/(24πn(R/D)²), times the coil wire length πDn).
    * ``"en13906_tangential"``: tangential leg → L_leg = (4R² − D²)/(12R) (EN 13906-3 via
      SpringTHREE ``CalcTangentialEndFlex`` (4(R/D)² − 1)/(12πn(R/D)), times πDn).
    """
    if model == "thesis":
        return arm / 2.0
    if model == "shigley":
        return arm / 3.0
    if model == "en13906_radial":
        return (arm - D / 2.0) ** 3 / (3.0 * arm * arm)
    if model == "en13906_tangential":
        return (4.0 * arm * arm - D * D) / (12.0 * arm)
    raise ValueError(f"unknown leg model {model!r}")


def arm_for_leg_length(L_leg: float, D: float, model: str = "thesis") -> float:
    """The arm R [mm] whose leg has the equivalent length ``L_leg`` (inverse of
    :func:`leg_length`; the radial model by bisection, it is increasing in R > D/2)."""
    if model == "thesis":
        return 2.0 * L_leg
    if model == "shigley":
        return 3.0 * L_leg
    if model == "en13906_tangential":
        return (12.0 * L_leg + math.sqrt(144.0 * L_leg ** 2 + 16.0 * D * D)) / 8.0
    if model == "en13906_radial":
        lo, hi = D / 2.0, D / 2.0 + 1.0
        while leg_length(hi, D, model) < L_leg:
            hi = D / 2.0 + 2.0 * (hi - D / 2.0)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if leg_length(mid, D, model) < L_leg:
                lo = mid
            else:
                hi = mid
        return 0.5 * (lo + hi)
    raise ValueError(f"unknown leg model {model!r}")


def twist(T: float, L: float, E: float, J: float) -> float:
    """Twist angle of the spring φ = T·L/(E·J) [rad], T [N·mm], L [mm] (KO-2 thesis §2.2
    eq. (6); §2.1 eq. (12) for the coils)."""
    return T * L / (E * J)


def stiffness(E: float, J: float, L: float) -> float:
    """Angular stiffness C = T/φ = E·J/L [N·mm/rad] (KO-2 thesis §2.2 eq. (11))."""
    return E * J / L


# ----------------------------------------------------------------------------- wind-up


def kinematic_windup(n: float, t: float) -> float:
    """Angle the motor shaft turns while it starts, uniformly accelerated to ω in t:
    φ₂ = ω·t/2 = π·n·t/60 [rad], n [min⁻¹], t [s] (KO-2 thesis §2.1 eq. (14); t = 10·t₁,
    t₁ the break-away time of the driving mass)."""
    return math.pi * n * t / 60.0


def design_angle(required: float, step_deg: float) -> float:
    """Required angle [rad] rounded up to a multiple of ``step_deg`` (the thesis rounds
    47.34° up to 50°, [Lopukhov] §2.1)."""
    deg = math.degrees(required)
    return math.radians(math.ceil(deg / step_deg - 1e-9) * step_deg)


def coils_for_angle(phi: float, T: float, E: float, J: float, D: float, L_leg: float) -> float:
    """Working coils that give the angle φ at the torque T [N·mm]:
    i = (φ·E·J/T − L_leg)/(π·D) — KO-2 thesis §2.1 eq. (15) (garbled in the thesis;
    reconstructed as i = (φ − φ₁)·E·J/(π·D·T))."""
    return (phi * E * J / T - L_leg) / (math.pi * D)


# ----------------------------------------------------------------------------- geometry


def working_height(d: float, i: float, p: float) -> float:
    """Working (body) height H = d + (i − 1)·p [mm] (KO-2 thesis §2.1 eq. (16))."""
    return d + (i - 1.0) * p


def wound_diameter(D: float, i: float, phi: float) -> float:
    """Mean coil diameter after winding up by φ [rad]: D' = D·i/(i + φ/2π) (Shigley
    eq. (10-51); the wire length is kept, the turns increase by φ/2π)."""
    return D * i / (i + phi / (2.0 * math.pi))


def wound_pitch(H: float, d: float, i: float, phi: float) -> float:
    """Pitch of a body held at its height H when wound up by φ: the turns grow to
    i + φ/2π over the same height, p' = (H − d)/(i − 1 + φ/2π) [mm] (geometry of the
    helix; the coils touch when p' < d)."""
    return (H - d) / (i - 1.0 + phi / (2.0 * math.pi))


def touching_angle(H: float, d: float, i: float) -> float:
    """Wind-up angle [rad] at which the coils of a body held at height H touch
    (p' = d in :func:`wound_pitch`): φ = 2π·((H − d)/d − (i − 1))."""
    return 2.0 * math.pi * ((H - d) / d - (i - 1.0))


def free_body_length(d: float, i: float, phi: float) -> float:
    """Body length of a close-wound spring with free ends after winding up by φ:
    L = d·(i + 1 + φ/2π) [mm] (Shigley §10-12)."""
    return d * (i + 1.0 + phi / (2.0 * math.pi))


def standard_wire(d_min: float, series: tuple[float, ...]) -> tuple[float, bool]:
    """The first diameter of the series >= d_min, and True; above the series d_min rounded
    up to 0.1 mm, and False."""
    for d in series:
        if d >= d_min - 1e-12:
            return d, True
    return math.ceil(d_min * 10.0 - 1e-9) / 10.0, False


# ----------------------------------------------------------------------------- design


@dataclass(frozen=True)
class SpringInput:
    """One torsion spring.  Torque in N·m, lengths mm, stresses MPa, angles rad."""

    T: float                      # design (working) torque, N·m
    E: float
    sigma_allow: float
    d: float | None = None        # wire diameter; None: d_min rounded up to the series
    c: float | None = None        # design index (used for k, as the thesis); None: D/d
    D: float | None = None        # mean coil diameter; None: c·d
    i: float | None = None        # working coils; None: from the design angle (method A)
    p: float | None = None        # pitch; None: d + gap
    curvature: str = "thesis"
    leg_arm: float | None = None  # finger arm R of the loaded leg, from the spring axis
    leg2_arm: float | None = None  # arm of the second (free) leg; None: clamped at the body
    leg_model: str = "thesis"
    phi_required: float | None = None  # required wind-up (method A), rad
    phi_design: float | None = None    # design angle, rad (>= phi_required)
    phi_stop: float | None = None      # stop angle of the coupling (torque limit), rad
    pitch_gap: float = 2.0
    wire_series: tuple = ()


@dataclass
class SpringDesign:
    inp: SpringInput
    c_design: float          # index used for k
    c_actual: float          # D/d
    k: float
    d_min: float
    d: float
    d_in_series: bool
    D: float
    p: float
    W: float
    J: float
    sigma: float             # at the design torque
    T_allow: float           # N·m, torque at [σ]
    L: float                 # coil wire length, mm
    L_leg: float             # equivalent length of the legs, mm
    C: float                 # stiffness of the coils EJ/L, N·m/rad
    C_finger: float          # stiffness at the finger (coils + legs), N·m/rad
    phi_T: float             # twist at the design torque at the finger, rad
    phi_body: float          # twist of the coils at the design torque, rad
    phi_leg: float           # leg bending at the design torque, rad
    F_leg: float | None      # leg force at the design torque, N
    i: float
    i_required: float | None
    H: float
    extra: dict = field(default_factory=dict)


def design(s: SpringInput) -> SpringDesign:
    """Size or check one spring (methods A and B of the KO-2 thesis).

    Order: index c (given, else D/d), curvature factor k(c), d_min = 2.17·∛(T·k/[σ]) and
    the wire d (given, else the series value ≥ d_min), mean diameter D (given, else c·d),
    J, W, σ = T·k/W; coils i (given, else rounded up from the design angle: method A),
    L = πDi, leg equivalent length, stiffness C = EJ/L and at the finger EJ/(L + L_leg),
    twist at T, height H = d + (i − 1)p.  The caller has validated the inputs (d < D,
    p ≥ d, ...).
    """
    T = s.T * 1000.0  # N·mm
    if s.d is not None and s.c is None and s.D is not None:
        c_design = s.D / s.d
    elif s.c is not None:
        c_design = s.c
    else:  # d unknown and c unknown: solve d = d_min(k(D/d)) by iteration
        d = (32.0 * T / (math.pi * s.sigma_allow)) ** (1.0 / 3.0)
        for _ in range(50):
            d = min_wire_diameter(T, curvature_factor(s.D / d, s.curvature), s.sigma_allow)
        c_design = s.D / d
    k = curvature_factor(c_design, s.curvature)
    d_min = min_wire_diameter(T, k, s.sigma_allow)
    if s.d is not None:
        d, in_series = s.d, True
    else:
        d, in_series = standard_wire(d_min, s.wire_series)
    D = s.D if s.D is not None else c_design * d
    if s.d is None and s.c is None:   # index follows the chosen wire
        c_design = D / d
        k = curvature_factor(c_design, s.curvature)
    p = s.p if s.p is not None else d + s.pitch_gap
    W, J = section_modulus(d), second_moment(d)
    sigma = T * k / W
    L_leg = 0.0
    if s.leg_arm is not None:
        L_leg += leg_length(s.leg_arm, D, s.leg_model)
    if s.leg2_arm is not None:
        L_leg += leg_length(s.leg2_arm, D, s.leg_model)
    i_required = None
    if s.phi_design is not None:
        i_required = coils_for_angle(s.phi_design, T, s.E, J, D, L_leg)
    if s.i is not None:
        i = s.i
    else:
        i = max(math.ceil(i_required - 1e-9), 1)
    L = wire_length(D, i)
    C = stiffness(s.E, J, L) / 1000.0
    C_finger = stiffness(s.E, J, L + L_leg) / 1000.0
    F_leg = s.T * 1000.0 / s.leg_arm if s.leg_arm is not None else None
    return SpringDesign(
        inp=s, c_design=c_design, c_actual=D / d, k=k, d_min=d_min, d=d, d_in_series=in_series,
        D=D, p=p, W=W, J=J, sigma=sigma, T_allow=allowable_torque(s.sigma_allow, k, d) / 1000.0,
        L=L, L_leg=L_leg, C=C, C_finger=C_finger, phi_T=twist(T, L + L_leg, s.E, J),
        phi_body=twist(T, L, s.E, J), phi_leg=twist(T, L_leg, s.E, J), F_leg=F_leg, i=i,
        i_required=i_required, H=working_height(d, i, p))
