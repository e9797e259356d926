"""The bevel spec read into typed, frozen inputs (N·mm, mm, rad, MPa).  Every rule across
keys that the schema cannot state is checked here, all of them in one round
(:class:`~geardesign.core.errors.Problems`): a spec with three mistakes reports three lines."""

from __future__ import annotations

import math

from geardesign.core.errors import Problem, Problems
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
    xt2: float | None = None      # the wheel's x_τ (None: −x_τ1)
    rho_a02: float | None = None  # the wheel's cutter tip radius coefficient (None: ρ_a0*)

    @property
    def xts(self) -> tuple[float, float]:
        """Tangential shift coefficients of pinion and wheel: a thickness modification
        with backlash need not be equal and opposite ([ISOTR10300-30] sample 1:
        x_sm = 0.036 / −0.055, x_τ = 2·x_sm)."""
        return self.xt1, -self.xt1 if self.xt2 is None else self.xt2

    @property
    def rho_a0s(self) -> tuple[float, float]:
        """Cutter tip radius coefficients of pinion and wheel ([ISOTR10300-30] sample 1:
        0.8 mm and 1.2 mm)."""
        return self.rho_a0, self.rho_a0 if self.rho_a02 is None else self.rho_a02


@dataclass(frozen=True)
class Load:
    """Operating load: T1 [N·mm], n1 [min⁻¹]."""

    T1: float
    n1: float
    rotation: str         # pinion, seen from its back: "cw" | "ccw"
    driver: str           # "pinion" | "wheel"
    K_A: float
    K_v: float | None     # given; None: by [ISO10300-1] method B or assumed (bevel.factors)
    mounting: str
    K_alpha: float | None  # K_Hα = K_Fα given; None: as K_v
    T_peak: float | None = None   # peak pinion torque [N·mm] (static checks)


@dataclass(frozen=True)
class Material:
    """Long-life strength limits [MPa] and elastic constants."""

    sigma_Hlim: tuple[float, float]
    sigma_Flim: tuple[float, float]
    hardness: str
    E: float
    nu: float
    type: str = "Eh"      # ISO 6336-5 material type (static limits, running-in)
    sigma_02: float | None = None             # yield strength (Y_δrelT,st of St, V)
    sigma_HPmax: tuple[float, float] | None = None   # GOST peak limits [MPa]
    sigma_FSt: tuple[float, float] | None = None


@dataclass(frozen=True)
class Accuracy:
    """Single pitch deviations f_pt of pinion and wheel [µm] and the density [kg/mm³] for
    K_v and K_Hα by [ISO10300-1] method B (:mod:`geardesign.bevel.factors`)."""

    f_pt: tuple[float, float]
    rho: float


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
    accuracy: Accuracy | None = None


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


SIZE_KEYS = ("module", "z1", "z2", "face_width")
"""The keys of ``[pair]`` that the design mode proposes."""


def _size_rules(pr: dict, design: dict | None, problems: Problems) -> None:
    """Either the pair's size (module, teeth, face width) or a ``[design]`` table."""
    for key in SIZE_KEYS:
        if design is None and pr.get(key) is None:
            problems.add(Problem(f"pair.{key}", "missing; give it, or a [design] table "
                                 "(ratio = ...) to have the pair proposed"))
        elif design is not None and pr.get(key) is not None:
            problems.at(f"pair.{key}", pr[key], "leave it out: [design] proposes the "
                        "module, the teeth and the face width (or remove [design])")


def read(data: dict) -> Inputs:
    """Typed inputs from a validated spec; every cross-key problem in one round.  With a
    ``[design]`` table the pair's module and face width are placeholders (1 mm) and its
    teeth z1 = design.z1, z2 = round(u·z1): :func:`geardesign.bevel.design.propose` sizes it."""
    pr, ld, mt, rt = data["pair"], data["load"], data["material"], data["rating"]
    design = data.get("design")
    problems = Problems()
    _size_rules(pr, design, problems)
    problems.raise_all()
    if design is not None:
        z1 = design["z1"]
        size = (1.0, z1, max(z1, round(design["ratio"] * z1)), 1.0)
    else:
        size = (pr["module"], pr["z1"], pr["z2"], pr["face_width"])
    pair = Pair(pr["teeth"] == "spiral", size[0], pr["module_at"], size[1], size[2],
                math.radians(pr["shaft_angle"]), size[3],
                math.radians(pr["spiral_angle"]), pr["hand"],
                math.radians(pr["pressure_angle"]), pr["addendum"], pr["clearance"],
                pr["root_radius"], pr["x1"], pr["xt1"], pr["depth"], pr.get("xt2"),
                pr.get("root_radius2"))
    problems.stage(_pair_rules, pair, pr, problems)
    problems.raise_all()
    peak = ld.get("peak_torque")
    if peak is not None and peak < ld["torque"]:
        problems.at("load.peak_torque", peak, f"must be at least the nominal "
                    f"torque load.torque = {ld['torque']:g} N·m (the largest short-time torque); "
                    f"leave it out for no peak check")
    for key in ("sigma_HPmax", "sigma_FSt"):
        one = [k for k in (f"{key}1", f"{key}2") if mt.get(k) is not None]
        if len(one) == 1:
            problems.at(f"material.{one[0]}", mt[one[0]], f"give {key}1 and {key}2 together "
                        f"(the GOST 21354 peak limits of both members), or neither")
    problems.raise_all()
    load = Load(ld["torque"] * 1e3, ld["speed"], ld["rotation"], ld["driver"],
                ld["application_factor"], ld.get("dynamic_factor"), ld["mounting"],
                ld.get("transverse_factor"), None if peak is None else peak * 1e3)
    material = Material((mt["sigma_Hlim1"], mt["sigma_Hlim2"]),
                        (mt["sigma_Flim1"], mt["sigma_Flim2"]), mt["hardness"], mt["E"],
                        mt["poisson"], mt.get("type", "Eh"), mt.get("sigma_02"),
                        _pair_of(mt, "sigma_HPmax"), _pair_of(mt, "sigma_FSt"))
    acc = data.get("accuracy")
    accuracy = None if acc is None else Accuracy((acc["f_pt1"], acc["f_pt2"]),
                                                 acc["density"] * 1e-9)
    return Inputs(pair, load, material, Rating(rt["method"], rt["S_Hmin"], rt["S_Fmin"]),
                  accuracy)


def _pair_of(mt: dict, key: str) -> tuple[float, float] | None:
    """``(key1, key2)`` of ``[material]`` when both are given, else None (the GOST peak
    check is then not made, and the report says so)."""
    a, b = mt.get(f"{key}1"), mt.get(f"{key}2")
    return None if a is None or b is None else (a, b)
