"""The bevel spec read into typed, frozen inputs (N·mm, mm, rad, MPa).  Every rule across
keys that the schema cannot state is checked here, all of them in one round
(:class:`~geardesign.core.errors.Problems`): a spec with three mistakes reports three lines."""

from __future__ import annotations

import math

from geardesign.core.errors import Problems
from geardesign.core.records import dataclass

DELTA_MAX = math.radians(89.5)
"""Largest pitch cone angle: a crown (δ = 90°) or internal bevel gear is not covered."""

FACE_MAX = 0.5
"""Largest face width over the outer cone distance b/R_e: beyond it the inner end nears the
apex and the mean section no longer represents the tooth ([ISO23509] §5 recommends ≤ 1/3)."""


@dataclass(frozen=True)
class Pair:
    """Bevel pair geometry inputs: angles [rad], lengths [mm]."""

    spiral: bool
    m: float              # module as given (m_te or m_nm, see module_at)
    module_at: str        # "outer" | "mean"
    z1: int
    z2: int
    Sigma: float
    b: float
    beta_m: float
    hand: str             # pinion hand: "right" | "left"
    alpha_n: float
    ha: float             # addendum coefficient h_a*
    c: float              # clearance coefficient c*
    rho_a0: float         # cutter tip radius coefficient
    x1: float
    xt1: float
    depth: str            # "constant_clearance" | "tapered"


@dataclass(frozen=True)
class Load:
    """Operating load: T1 [N·mm], n1 [min⁻¹]."""

    T1: float
    n1: float
    rotation: str         # pinion, seen from its back: "cw" | "ccw"
    driver: str           # "pinion" | "wheel"
    K_A: float
    K_v: float
    mounting: str
    K_alpha: float


@dataclass(frozen=True)
class Material:
    """Long-life strength limits [MPa] and elastic constants."""

    sigma_Hlim: tuple[float, float]
    sigma_Flim: tuple[float, float]
    hardness: str
    E: float
    nu: float


@dataclass(frozen=True)
class Rating:
    method: str
    S_Hmin: float
    S_Fmin: float

    @property
    def iso(self) -> bool:
        return self.method in ("iso10300", "both")

    @property
    def gost(self) -> bool:
        return self.method in ("gost21354", "both")


@dataclass(frozen=True)
class Inputs:
    """Everything :func:`geardesign.bevel.solve.solve` needs."""

    pair: Pair
    load: Load
    material: Material
    rating: Rating


def pitch_angles(z1: int, z2: int, Sigma: float) -> tuple[float, float]:
    """Pitch cone angles δ1, δ2 [rad] of a pair with shaft angle Σ [rad].

    .. math:: \\tan δ_1 = \\frac{\\sin Σ}{u + \\cos Σ},\\quad δ_2 = Σ - δ_1,\\quad u = z_2/z_1

    [ISO23509] §5.2; [GOST19624] table 1 item 6.

    >>> [round(math.degrees(d), 4) for d in pitch_angles(20, 40, math.pi / 2)]
    [26.5651, 63.4349]
    """
    u = z2 / z1
    d1 = math.atan2(math.sin(Sigma), u + math.cos(Sigma))
    return d1, Sigma - d1


def _pair_rules(p: Pair, given: dict, problems: Problems) -> None:
    """The rules across keys of ``[pair]`` (``given``: the values as written)."""
    if p.spiral and p.beta_m <= 0.0:
        problems.at("pair.spiral_angle", 0.0, 'spiral teeth need a mean spiral angle > 0 '
                    '(e.g. 35); for β_m = 0 write teeth = "straight"')
    if not p.spiral and p.beta_m > 0.0:
        problems.at("pair.spiral_angle", given["spiral_angle"],
                    'straight teeth have β_m = 0; remove spiral_angle or write '
                    'teeth = "spiral"')
    if p.z2 < p.z1:
        problems.at("pair.z2", p.z2, f"the wheel has at least as many teeth as the pinion "
                    f"(z1 = {p.z1}); swap z1 and z2")
        return
    d1, d2 = pitch_angles(p.z1, p.z2, p.Sigma)
    if not (0.0 < d1 and d2 < DELTA_MAX):
        problems.at("pair.shaft_angle", given["shaft_angle"],
                    f"with z2/z1 = {p.z2 / p.z1:.3g} the wheel's pitch cone angle would be "
                    f"{math.degrees(d2):.1f}°; a crown or internal bevel gear (δ2 >= "
                    f"{math.degrees(DELTA_MAX):g}°) is not covered: use a smaller shaft angle")
        return
    # the outer cone distance from the module as given (see geometry.cone_distances)
    if p.module_at == "outer":
        R_e = p.m * p.z1 / (2.0 * math.sin(d1))
    else:
        R_m = p.m / math.cos(p.beta_m) * p.z1 / (2.0 * math.sin(d1))
        R_e = R_m + 0.5 * p.b
    if p.b > FACE_MAX * R_e:
        problems.at("pair.face_width", p.b, f"must be at most {FACE_MAX:g}·R_e = "
                    f"{FACE_MAX * R_e:.4g} mm (outer cone distance R_e = {R_e:.4g} mm); "
                    f"ISO 23509 recommends b <= R_e/3 = {R_e / 3:.4g} mm")


def read(data: dict) -> Inputs:
    """Typed inputs from a validated spec; every cross-key problem in one round."""
    pr, ld, mt, rt = data["pair"], data["load"], data["material"], data["rating"]
    pair = Pair(pr["teeth"] == "spiral", pr["module"], pr["module_at"], pr["z1"], pr["z2"],
                math.radians(pr["shaft_angle"]), pr["face_width"],
                math.radians(pr["spiral_angle"]), pr["hand"],
                math.radians(pr["pressure_angle"]), pr["addendum"], pr["clearance"],
                pr["root_radius"], pr["x1"], pr["xt1"], pr["depth"])
    problems = Problems()
    problems.stage(_pair_rules, pair, pr, problems)
    problems.raise_all()
    load = Load(ld["torque"] * 1e3, ld["speed"], ld["rotation"], ld["driver"],
                ld["application_factor"], ld["dynamic_factor"], ld["mounting"],
                ld["transverse_factor"])
    material = Material((mt["sigma_Hlim1"], mt["sigma_Hlim2"]),
                        (mt["sigma_Flim1"], mt["sigma_Flim2"]), mt["hardness"], mt["E"],
                        mt["poisson"])
    return Inputs(pair, load, material, Rating(rt["method"], rt["S_Hmin"], rt["S_Fmin"]))
