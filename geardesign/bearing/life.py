"""Rolling-bearing life to GOST 18855-94 / ISO 281:2007 (= GOST 18855-2013): pure functions.

Units: forces N, lengths mm, speed min⁻¹, life in 10⁶ revolutions or hours, viscosity
mm²/s, angles in degrees at the interface.  Table data live in :mod:`.tables`.
"""

from __future__ import annotations

import math

from geardesign.bearing import tables as T
from geardesign.core.records import dataclass


class BearingError(ValueError):
    """A calculation cannot be done with these inputs; ``key`` names the input to change."""

    def __init__(self, key: str, message: str):
        super().__init__(message)
        self.key = key


# ----------------------------------------------------------------------------- helpers


def interp(x: float, xs, ys) -> float:
    """Linear interpolation in a table, clamped at both ends (ISO 281 Table 3 permits linear
    interpolation between printed points)."""
    if x <= xs[0]:
        return ys[0]
    if x >= xs[-1]:
        return ys[-1]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1])
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]  # pragma: no cover


def is_ball(kind: str) -> bool:
    return kind in T.BALL_TYPES


def life_exponent(kind: str) -> float:
    """p = 3 for ball bearings, 10/3 for roller bearings (GOST 18855-94 / ISO 281 L10 formula;
    [Haidamaka2017] eq. (2))."""
    return 3.0 if is_ball(kind) else 10.0 / 3.0


# ----------------------------------------------------------------------------- C_r from geometry


def f_c(kind: str, gamma: float, rows: int = 1) -> float:
    """Geometry factor f_c(γ) of ISO 281:2007 Tables 2/(roller), linear interpolation.

    γ = D_w·cos α/D_pw (ball) or D_we·cos α/D_pw (roller), dimensionless.  Ball column: deep
    groove single row and angular contact; double-row deep groove; self-aligning.
    """
    if is_ball(kind):
        xs = [r[0] for r in T.F_C_BALL]
        if not xs[0] <= gamma <= xs[-1]:
            raise BearingError("bearing.D_w", f"γ = D_w·cos α/D_pw = {gamma:.4f} is outside the "
                                              f"ISO 281 f_c table ({xs[0]} … {xs[-1]})")
        col = 3 if kind == "self_aligning_ball" else (2 if kind == "deep_groove_ball" and rows == 2
                                                      else 1)
        return interp(gamma, xs, [r[col] for r in T.F_C_BALL])
    xs = [r[0] for r in T.F_C_ROLLER]
    if not xs[0] <= gamma <= xs[-1]:
        raise BearingError("bearing.D_w", f"γ = D_we·cos α/D_pw = {gamma:.4f} is outside the "
                                          f"ISO 281 f_c table ({xs[0]} … {xs[-1]})")
    return interp(gamma, xs, [r[1] for r in T.F_C_ROLLER])


@dataclass(frozen=True)
class RatingFromGeometry:
    gamma: float
    f_c: float
    b_m: float
    C_r: float


def dynamic_rating(kind: str, Z: int, D_w: float, D_pw: float, alpha_deg: float = 0.0,
                   rows: int = 1, L_we: float | None = None) -> RatingFromGeometry:
    """Basic dynamic radial load rating C_r [N] from the internal geometry.

    Ball bearings (ISO 281:2007 / GOST 18855-94; [Haidamaka2017] eqs. (3), (4)):
    D_w <= 25.4 mm: C_r = b_m·f_c·(i·cos α)^0.7·Z^(2/3)·D_w^1.8;
    D_w > 25.4 mm:  C_r = 3.647·b_m·f_c·(i·cos α)^0.7·Z^(2/3)·D_w^1.4 (3.647 = 25.4^0.4).
    Roller bearings ([Haidamaka2017] eq. (5)): C_r = b_m·f_c·(i·L_we·cos α)^(7/9)·Z^(3/4)·D_we^(29/27).
    Z rolling elements per row, D_w/D_we element diameter [mm], D_pw pitch diameter [mm],
    α contact angle, i = rows, L_we effective roller length [mm].
    """
    cos_a = math.cos(math.radians(alpha_deg))
    gamma = D_w * cos_a / D_pw
    fc = f_c(kind, gamma, rows)
    bm = T.B_M[kind]
    if is_ball(kind):
        if D_w <= T.D_W_SPLIT:
            c = bm * fc * (rows * cos_a) ** 0.7 * Z ** (2.0 / 3.0) * D_w ** 1.8
        else:
            c = 3.647 * bm * fc * (rows * cos_a) ** 0.7 * Z ** (2.0 / 3.0) * D_w ** 1.4
    else:
        if L_we is None:
            raise BearingError("bearing.L_we", "missing; required for the rating of a roller "
                                               "bearing from its geometry (effective roller length, mm)")
        c = bm * fc * (rows * L_we * cos_a) ** (7.0 / 9.0) * Z ** 0.75 * D_w ** (29.0 / 27.0)
    return RatingFromGeometry(gamma, fc, bm, c)


# ----------------------------------------------------------------------------- X, Y, e


@dataclass(frozen=True)
class LoadFactors:
    """e, X, Y chosen for one load case and how they were found."""

    e: float
    X: float
    Y: float
    ratio: float                 # F_a/(V·F_r) compared with e (inf for a pure axial load)
    entry: float | None = None   # table entry (f0·Fa/C0r, Fa/C0r, i·f0·Fa/C0r, ...)
    entry_name: str = ""
    clamped: str = ""            # "", "below" or "above" the table
    note: str = ""


def _ratio(Fr: float, Fa: float, V: float) -> float:
    return math.inf if Fr <= 0.0 else Fa / (V * Fr)


def _tan(alpha_deg: float) -> float:
    return math.tan(math.radians(alpha_deg))


def _clamp_flag(x: float, lo: float, hi: float) -> str:
    return "below" if x < lo else ("above" if x > hi else "")


def load_factors(kind: str, Fr: float, Fa: float, *, rows: int = 1, alpha_deg: float | None = None,
                 V: float = 1.0, C_0r: float | None = None, f0: float | None = None,
                 e_given: float | None = None, Y_given: float | None = None,
                 Y1_given: float | None = None) -> LoadFactors:
    """X, Y, e for P = X·V·F_r + Y·F_a (ISO 281:2007 Table 3 / GOST 18855-94; [GOST18855]
    §A.4.3–A.4.5).  F_a/(V·F_r) <= e gives the "<= e" column (X = 1, Y = 0 for single-row
    bearings).  V = 1 in ISO 281; GOST 18855-94 practice compares F_a/(V·F_r) with e.

    Deep groove: entry f0·Fa/C0r when f0 is given, else the textbook Fa/C0r column.
    Angular contact: α = 10°/15° by i·f0·Fa/C0r, α = 12° by the textbook i·Fa/C0r table,
    α = 20…45° fixed rows (linear interpolation between printed angles).
    Self-aligning ball, tapered and spherical roller: e = 1.5·tan α (α from the catalogue e
    when e is given); a catalogue Y (for F_a/F_r > e) may replace 0.4·cot α / 0.67·cot α.
    A catalogue Y1 (for F_a/F_r <= e of double-row and spherical roller bearings) replaces
    the scaled Y.  Cylindrical roller: X = 1, Y = 0 (axial load not counted).  Thrust with
    α = 90°: P = F_a.
    """
    ratio = _ratio(Fr, Fa, V)
    if kind == "cylindrical_roller":
        return LoadFactors(math.inf, 1.0, 0.0, ratio, note="axial load not counted (α = 0)")

    if kind == "deep_groove_ball":
        if Fa <= 0.0:
            return LoadFactors(T.DEEP_GROOVE[0][2], 1.0, 0.0, ratio, note="no axial load")
        if C_0r is None:
            raise BearingError("bearing.C_0r", "missing; required to find e, X, Y of a deep groove "
                                               "ball bearing under axial load (static rating, N)")
        if f0 is not None:
            x, col, name = f0 * Fa / C_0r, 0, "f0·Fa/C0r"
        else:
            x, col, name = Fa / C_0r, 1, "Fa/C0r"
        xs = [r[col] for r in T.DEEP_GROOVE]
        e = interp(x, xs, [r[2] for r in T.DEEP_GROOVE])
        Y = interp(x, xs, [r[3] for r in T.DEEP_GROOVE])
        flag = _clamp_flag(x, xs[0], xs[-1])
        if ratio <= e:
            return LoadFactors(e, 1.0, 0.0, ratio, x, name, flag)
        return LoadFactors(e, T.DEEP_GROOVE_X, Y, ratio, x, name, flag)

    if kind == "angular_contact_ball":
        a = alpha_deg
        if a is None:
            raise BearingError("bearing.contact_angle", "missing; required for an angular contact "
                                                        "ball bearing (deg)")
        if a in T.ANGULAR_VARIABLE or a == 12.0:
            if C_0r is None:
                raise BearingError("bearing.C_0r", f"missing; required to find e, X, Y of an "
                                                   f"angular contact ball bearing with α = {a:g}°")
            if a == 12.0:
                x = rows * Fa / C_0r
                xs = [r[0] for r in T.ANGULAR_12_TEXTBOOK]
                e = interp(x, xs, [r[1] for r in T.ANGULAR_12_TEXTBOOK])
                Y = interp(x, xs, [r[2] for r in T.ANGULAR_12_TEXTBOOK])
                flag = _clamp_flag(x, xs[0], xs[-1])
                if rows != 1:
                    raise BearingError("bearing.rows", "the α = 12° table covers single-row "
                                                       "bearings only; use rows = 1")
                if ratio <= e:
                    return LoadFactors(e, 1.0, 0.0, ratio, x, "i·Fa/C0r", flag)
                return LoadFactors(e, T.ANGULAR_12_X, Y, ratio, x, "i·Fa/C0r", flag,
                                   "α = 12° textbook table (unverified)")
            if f0 is None:
                raise BearingError("bearing.f0", f"missing; required for α = {a:g}°: the ISO 281 "
                                                 f"table is entered with i·f0·Fa/C0r (catalogue f0)")
            tab = T.ANGULAR_VARIABLE[a]
            x = rows * f0 * Fa / C_0r
            xs = [r[0] for r in T.DEEP_GROOVE]
            col = lambda k: [r[k] for r in tab["rows"]]  # noqa: E731
            e = interp(x, xs, col(0))
            flag = _clamp_flag(x, xs[0], xs[-1])
            if rows == 1:
                if ratio <= e:
                    return LoadFactors(e, 1.0, 0.0, ratio, x, "i·f0·Fa/C0r", flag)
                return LoadFactors(e, tab["X_single"], interp(x, xs, col(1)), ratio, x,
                                   "i·f0·Fa/C0r", flag)
            if ratio <= e:
                return LoadFactors(e, 1.0, interp(x, xs, col(2)), ratio, x, "i·f0·Fa/C0r", flag)
            return LoadFactors(e, tab["X_double"], interp(x, xs, col(3)), ratio, x,
                               "i·f0·Fa/C0r", flag)
        angles = [r[0] for r in T.ANGULAR_FIXED]
        if not angles[0] <= a <= angles[-1]:
            raise BearingError("bearing.contact_angle", f"α = {a:g}° is not tabulated for angular "
                                                        f"contact ball bearings: use 10, 12, 15 or "
                                                        f"20 … 45°")
        col = lambda k: interp(a, angles, [r[k] for r in T.ANGULAR_FIXED])  # noqa: E731
        e = col(1)
        note = "" if a in angles else "interpolated between printed contact angles"
        if rows == 1:
            if ratio <= e:
                return LoadFactors(e, 1.0, 0.0, ratio, note=note)
            return LoadFactors(e, col(2), col(3), ratio, note=note)
        if ratio <= e:
            return LoadFactors(e, col(4), col(5), ratio, note=note)
        return LoadFactors(e, col(6), col(7), ratio, note=note)

    if kind in ("self_aligning_ball", "tapered_roller", "spherical_roller"):
        tan_a = _alpha_tan(alpha_deg, e_given)
        e = 1.5 * tan_a
        cot = 1.0 / tan_a
        if kind == "self_aligning_ball":
            s = T.SELF_ALIGNING
            X_le, Y_le, X_gt, Y_gt = s["X_le"], s["Y_le_cot"] * cot, s["X_gt"], s["Y_gt_cot"] * cot
            scale = s["Y_le_cot"] / s["Y_gt_cot"]
        else:
            r = T.ROLLER_RADIAL[2 if rows == 2 else 1]
            X_le, Y_le, X_gt, Y_gt = r["X_le"], r["Y_le_cot"] * cot, r["X_gt"], r["Y_gt_cot"] * cot
            scale = r["Y_le_cot"] / r["Y_gt_cot"]
        note = ""
        if Y_given is not None:
            Y_le, Y_gt = Y_given * scale, Y_given
            note = "catalogue Y"
        if Y1_given is not None and Y_le > 0.0:
            Y_le = Y1_given
            note = "catalogue Y1, Y"
        if ratio <= e:
            return LoadFactors(e, X_le, Y_le, ratio, note=note)
        return LoadFactors(e, X_gt, Y_gt, ratio, note=note)

    if kind in T.THRUST_TYPES:
        a = 90.0 if alpha_deg is None else alpha_deg
        if a >= 90.0:
            return LoadFactors(math.inf, 0.0, 1.0, ratio, note="axial load only (α = 90°)")
        if kind == "thrust_ball":
            raise BearingError("bearing.contact_angle", "thrust ball bearings are covered for "
                                                        "α = 90° only; use 90")
        t = T.THRUST_ROLLER
        tan_a = _tan(a)
        e = t["e_tan"] * tan_a
        if Fa <= 0.0:
            raise BearingError("load.F_a", "a thrust bearing needs an axial load")
        if rows == 2 and ratio <= e:
            return LoadFactors(e, t["X_le_tan"] * tan_a, t["Y_le"], ratio,
                               note="thrust roller, α < 90° (unverified)")
        return LoadFactors(e, t["X_gt_tan"] * tan_a, t["Y_gt"], ratio,
                           note="thrust roller, α < 90° (unverified)")
    raise BearingError("bearing.type", f"unknown bearing type {kind!r}")  # pragma: no cover


def _alpha_tan(alpha_deg: float | None, e_given: float | None) -> float:
    """tan α from the contact angle, or from the catalogue e = 1.5·tan α."""
    if e_given is not None:
        return e_given / 1.5
    if alpha_deg is None or alpha_deg <= 0.0:
        raise BearingError("bearing.contact_angle", "missing; give the contact angle (deg) or the "
                                                    "catalogue value bearing.e")
    return _tan(alpha_deg)


def equivalent_load(Fr: float, Fa: float, lf: LoadFactors, V: float = 1.0, K_b: float = 1.0,
                    K_t: float = 1.0, thrust: bool = False) -> float:
    """Equivalent dynamic load [N].

    Radial bearings: P = (X·V·F_r + Y·F_a)·K_б·K_т (GOST 18855-94 practice, [Haidamaka2017] eq. (6));
    ISO 281: P = X·F_r + Y·F_a (V = K_б = K_т = 1 unless given as application factors).
    Thrust bearings: P_a = X·F_r + Y·F_a (α = 90°: P_a = F_a).
    """
    if thrust:
        return (lf.X * Fr + lf.Y * Fa) * K_b * K_t
    return (lf.X * V * Fr + lf.Y * Fa) * K_b * K_t


# ----------------------------------------------------------------------------- static


@dataclass(frozen=True)
class StaticLoad:
    X0: float
    Y0: float
    P0: float


def static_load(kind: str, Fr: float, Fa: float, *, rows: int = 1, alpha_deg: float | None = None,
                e_given: float | None = None, Y0_given: float | None = None) -> StaticLoad:
    """Equivalent static load P0 = max(F_r, X0·F_r + Y0·F_a) (ISO 76 / GOST 18854; [GOST18855]
    §A.4.7).  Cylindrical roller: P0 = F_r; thrust with α = 90°: P0a = F_a.  A catalogue Y0
    (tapered, spherical and self-aligning bearings) replaces 0.22·cot α / 0.44·cot α."""
    if kind == "cylindrical_roller":
        return StaticLoad(1.0, 0.0, Fr)
    if kind in T.THRUST_TYPES:
        return StaticLoad(0.0, 1.0, Fa)
    if kind == "deep_groove_ball":
        X0, Y0 = T.STATIC_DEEP_GROOVE
    elif kind == "angular_contact_ball":
        a = alpha_deg if alpha_deg is not None else 0.0
        xs = [r[0] for r in T.STATIC_Y0_ANGULAR]
        y0 = interp(a, xs, [r[1] for r in T.STATIC_Y0_ANGULAR])
        X0, Y0 = (0.5, y0) if rows == 1 else (1.0, 2.0 * y0)
    else:
        cot = 1.0 / _alpha_tan(alpha_deg, e_given)
        r = 2 if (rows == 2 or kind == "self_aligning_ball") else 1
        X0, y = T.STATIC_ROLLER[r]
        Y0 = y * cot if Y0_given is None else Y0_given
    return StaticLoad(X0, Y0, max(Fr, X0 * Fr + Y0 * Fa))


# ----------------------------------------------------------------------------- life


def basic_life(C: float, P: float, p: float) -> float:
    """Basic rating life L10 = (C/P)^p [10⁶ rev] (GOST 18855-94 / ISO 281; [GOST18855]);
    infinite when it exceeds the float range (the caller refuses it)."""
    try:
        return (C / P) ** p
    except OverflowError:
        return math.inf


def hours(L_mrev: float, n: float) -> float:
    """Life in hours at constant speed n [min⁻¹]: L_h = 10⁶·L/(60·n) ([Haidamaka2017] eq. (2))."""
    return 1.0e6 * L_mrev / (60.0 * n)


def a1_factor(reliability: float, method: str) -> float:
    """Life adjustment factor for reliability a1 of the edition (tables in :mod:`.tables`;
    linear interpolation between printed reliabilities).  GOST 18855-94: 90 … 99 %;
    ISO 281:2007 / GOST 18855-2013: 90 … 99.95 %."""
    table = T.A1_GOST94 if method == "gost18855_94" else T.A1_ISO2007
    rs = [r[0] for r in table]
    if not rs[0] <= reliability <= rs[-1]:
        raise BearingError("requirements.reliability",
                           f"outside the a1 table of this edition ({rs[0]:g} … {rs[-1]:g} %)")
    return interp(reliability, rs, [r[1] for r in table])


def nu1(n: float, D_pw: float) -> float:
    """Reference kinematic viscosity ν1 [mm²/s] (ISO 281:2007 eq. (28)/(29), standards check §1):
    ν1 = 45000·n^−0.83·D_pw^−0.5 for n < 1000 min⁻¹, ν1 = 4500·n^−0.5·D_pw^−0.5 for n >= 1000
    (n [min⁻¹], D_pw [mm]).  The two branches differ by ~2 % at n = 1000 (inherent)."""
    if n < 1000.0:
        return 45000.0 * n ** -0.83 * D_pw ** -0.5
    return 4500.0 * n ** -0.5 * D_pw ** -0.5


@dataclass(frozen=True)
class AIso:
    value: float
    kappa_used: float
    ratio: float                 # e_C·C_u/P (thrust: divided by 3 or 2.5)
    capped: bool
    limit: float
    kappa_clamped: str           # "", "low" (κ < 0.1) or "high" (κ > 4)
    ep_rule: bool


def a_iso(kind: str, kappa: float, e_C: float, C_u: float, P: float,
          ep_additives: bool = False) -> AIso:
    """Life modification factor a_ISO (ISO 281:2007, systems approach; standards check §5).

    Radial ball: a_ISO = 0.1·[1 − (2.5671 − c2/κ^c3)^0.83·(e_C·C_u/P)^(1/3)]^−9.3;
    radial roller: a_ISO = 0.1·[1 − (1.5859 − c2/κ^c3)·(e_C·C_u/P)^0.4]^−9.185, with (c2, c3)
    by κ band (0.1 <= κ < 0.4, 0.4 <= κ < 1, 1 <= κ <= 4; :data:`.tables.A_ISO_BALL`).
    Thrust ball/roller: the same with e_C·C_u/(3·P) / e_C·C_u/(2.5·P) (medium confidence).
    κ is limited to 0.1 … 4; a_ISO <= 50 (and 50 where the bracket is <= 0).  With effective
    EP additives, κ < 1 and e_C >= 0.2, κ = 1 is used and a_ISO <= 3 (ISO 281 §9.3.3.4 as
    transcribed, secondary).

    **Ball exponent c3 for 0.4 <= κ < 1: 0.19087 is used, not 0.019087.**  The standard's
    print could not be read.  One public implementation (Dessia MechanicalComponents) uses
    0.019087; the one that transcribes ISO 281 equation (32) uses 0.19087, as do both roller
    branches.  Only 0.19087 keeps a_ISO continuous at κ = 0.4 (bracket constant
    1.9987/0.4^0.19087 = 2.3807 against 2.2649/0.4^0.054381 = 2.3806); 0.019087 gives 2.0340,
    a jump of a_ISO by a factor of 4 to 35 for e_C·C_u/P between 0.2 and 1.
    """
    ball = is_ball(kind)
    bands = T.A_ISO_BALL if ball else T.A_ISO_ROLLER
    const, expo, r_expo, slope = T.A_ISO_BALL_CONST if ball else T.A_ISO_ROLLER_CONST
    clamped = "low" if kappa < T.KAPPA_MIN else ("high" if kappa > T.KAPPA_MAX else "")
    k = min(max(kappa, T.KAPPA_MIN), T.KAPPA_MAX)
    limit = T.A_ISO_MAX
    ep = ep_additives and k < 1.0 and e_C >= T.EP_E_C_MIN
    if ep:
        k, limit = 1.0, T.A_ISO_MAX_EP
    c2, c3 = bands[0][1:]
    for start, b2, b3 in bands:
        if k >= start:
            c2, c3 = b2, b3
    r = e_C * C_u / (P * T.THRUST_LOAD_DIVISOR.get(kind, 1.0))
    base = const - c2 / k ** c3
    term = (max(base, 0.0) ** expo) * r ** r_expo
    bracket = 1.0 - term
    if bracket <= 0.0:
        return AIso(limit, k, r, True, limit, clamped, ep)
    value = 0.1 * bracket ** -slope
    return AIso(min(value, limit), k, r, value > limit, limit, clamped, ep)


def c_u_estimate(kind: str, C_0: float, D_pw: float) -> float:
    """Approximate fatigue load limit C_u [N] from the static rating (ISO 281:2007 annex
    approximation via [Haidamaka2017], unverified): C_0/22 (ball), C_0/8.2 (roller)
    for D_pw <= 100 mm, times (100/D_pw)^0.5 / ^0.3 beyond."""
    div, expo = T.C_U_ESTIMATE["ball" if is_ball(kind) else "roller"]
    c = C_0 / div
    if D_pw > 100.0:
        c *= (100.0 / D_pw) ** expo
    return c


def e_c_guide(level: str, D_pw: float) -> float:
    """Contamination factor e_C from the ISO 281:2007 guide table: the middle of the range of
    the contamination level for D_pw < 100 mm or >= 100 mm."""
    lo, hi = T.E_C_GUIDE[level][0 if D_pw < 100.0 else 1]
    return 0.5 * (lo + hi)


def k_t(temperature: float | None) -> float:
    """Temperature factor K_т (Russian practice, :data:`.tables.K_T`): 1 up to 100 °C,
    linear interpolation to 1.40 at 250 °C."""
    if temperature is None or temperature <= T.K_T[0][0]:
        return 1.0
    return interp(temperature, [r[0] for r in T.K_T], [r[1] for r in T.K_T])


def a23_default(kind: str, conditions: str) -> float:
    """Middle of the textbook a23 range for the bearing type and conditions (GOST 18855-94
    practice, :data:`.tables.A23`)."""
    lo, hi = T.A23[kind][T.A23_CONDITIONS.index(conditions)]
    return 0.5 * (lo + hi)


def required_rating(P: float, life_h: float, n: float, p: float, a: float = 1.0) -> float:
    """Dynamic rating needed for a target life: C_req = P·(60·n·L_h/(10⁶·a))^(1/p) [N], with
    a = a1·a23 (GOST) or a1·a_ISO (ISO 281) ([Haidamaka2017]; [GOST18855])."""
    return P * (60.0 * n * life_h / (1.0e6 * a)) ** (1.0 / p)


def system_life(lives, slope: float) -> float:
    """Life of several bearings that all must survive: L = (Σ L_i^−e)^(−1/e) (Weibull slope
    e = 10/9 ball, 9/8 roller; NTN CAT. No. 2202/E formula (3.6))."""
    return sum(L ** -slope for L in lives) ** (-1.0 / slope)


@dataclass(frozen=True)
class SpectrumResult:
    P_m: float                   # equivalent (mean) load [N]
    n_m: float                   # mean speed [min⁻¹]
    revolutions_share: list      # share of revolutions of each block
    damage_share: list           # share of fatigue damage of each block


def spectrum_mean(P: list, n: list, t: list, p: float) -> SpectrumResult:
    """Mean load of a stepped spectrum: P_m = [Σ P_j^p·n_j·t_j / Σ n_j·t_j]^(1/p),
    n_m = Σ n_j·t_j / Σ t_j (GOST 18855-94 / ISO 281; NTN CAT. No. 2202/E formula (4.12)).
    t_j are time shares; the damage share of block j is P_j^p·n_j·t_j / Σ."""
    rev = [nj * tj for nj, tj in zip(n, t)]
    dmg = [Pj ** p * r for Pj, r in zip(P, rev)]
    total_rev = sum(rev)
    total_t = sum(t)
    total_dmg = sum(dmg)
    P_m = (total_dmg / total_rev) ** (1.0 / p)
    return SpectrumResult(P_m, total_rev / total_t, [r / total_rev for r in rev],
                          [d / total_dmg if total_dmg > 0.0 else 0.0 for d in dmg])


def miner_hours(block_hours: list, t: list) -> float:
    """Palmgren–Miner over time shares: 1/L = Σ t_j/L_j (L_j the life [h] at block j)."""
    return 1.0 / sum(tj / Lj for tj, Lj in zip(t, block_hours))


@dataclass(frozen=True)
class RibCapacity:
    F_ap: float          # permissible continuous axial load (rib and roller ends), N
    F_a_max: float       # flange strength limit for a continuous axial load, N
    k1: float
    k2: float

    @property
    def limit(self) -> float:
        return min(self.F_ap, self.F_a_max)


def rib_capacity(C_0r: float, F_r: float, n: float, d: float, D: float, series: str,
                 lubricant: str = "oil") -> RibCapacity:
    """Axial load a single-row cylindrical roller bearing with ribs on both rings (NJ, NUP)
    carries continuously ([SKF6000] p. 518):

    F_ap = k1·C0·10⁴/(n·(d + D)) − k2·F_r   [kN, kN, min⁻¹, mm]; k1 = 1.5, k2 = 0.15 with
    oil, 1 and 0.1 with grease (the base oil's κ >= 2, 60 K above ambient); and never more
    than F_a,max = 0.0045·D^1.5 (diameter series 2) or 0.0023·D^1.7 (other series) [kN, mm].
    Forces in N here; short axial loads may be twice, shocks three times F_ap (not used).

    >>> round(rib_capacity(53000.0, 5000.0, 1500.0, 40.0, 80.0, "2").F_ap)
    3667
    """
    k1, k2 = (1.5, 0.15) if lubricant == "oil" else (1.0, 0.1)
    F_ap = (k1 * (C_0r / 1000.0) * 1.0e4 / (n * (d + D)) - k2 * F_r / 1000.0) * 1000.0
    diameter_series_2 = series in ("2", "22")
    F_a_max = (0.0045 * D ** 1.5 if diameter_series_2 else 0.0023 * D ** 1.7) * 1000.0
    return RibCapacity(max(F_ap, 0.0), F_a_max, k1, k2)
