"""Rolling-bearing load factors to GOST 18855-94 / ISO 281:2007 (= GOST 18855-2013):
e, X, Y of the dynamic equivalent load P = X·F_r + Y·F_a and X_0, Y_0 of the static
equivalent load, one function per clause.  Units: forces N, angles in degrees."""

from __future__ import annotations

import math

from geardesign.bearing import tables as T
from geardesign.bearing.life import BearingError, interp
from geardesign.core.records import dataclass


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

    Example: a radial ball bearing without axial load has X = 1, Y = 0, so P = F_r:

    >>> equivalent_load(1000.0, 0.0, load_factors("deep_groove_ball", 1000.0, 0.0))
    1000.0
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
