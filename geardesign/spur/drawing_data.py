"""The drawing data of a spur pair, computed: the [accuracy] table resolved against the
pair (GOST 1643-81 or ISO 1328-1 tolerances, tooth thickness allowances, the backlash range
with the centre-distance and thermal effects) and the test dimensions of each gear with
their limits (span, dimension over balls, radial single-ball dimension, chordal and
constant-chord thickness).  :mod:`geardesign.spur.drawing` writes them into the report.

Internal pairs (:class:`~geardesign.gears.internal.InternalPairGeometry`): the same
tolerances (the internal gear's by its own d, b), its tooth thickness allowances those of
its teeth (≤ 0: wider spaces; [DIN3967], :mod:`~geardesign.spur.tolerances.backlash`), the
least backlash at a_w + f_a, the dimension between two balls or pins and the radial
single-ball dimension from its space width, the span over k spaces (with an internal
calliper: a standard disc micrometer does not reach into an internal gear) and the chordal
thickness of its teeth (a tooth calliper reaches them only in a large ring).

Every input problem of [accuracy] and [drawing] is an :class:`InputError` raised here
(:func:`accuracy_of`, :func:`tests_of`); the records are frozen.
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.spec import ValidatedSpec
from geardesign.gears.geometry import PairGeometry
from geardesign.spur.measurement import (
    MeasurementError,
    Tooth,
    ball_touches,
    chordal,
    constant_chord,
    ideal_ball,
    over_balls,
    span,
)
from geardesign.spur.tolerances import gost1643, iso1328
from geardesign.spur.tolerances.backlash import (
    Backlash,
    Thermal,
    backlash_range,
    centre_distance_effect,
    upper_allowances,
)
from geardesign.spur.tolerances.gost1643 import ToleranceError

STEEL_EXPANSION = 11.5  # 1e-6/K, assumed for a member whose coefficient is not given
SRC_GOST = "GOST 1643-81"
SRC_BACKLASH = "ISO 21771:2007; ISO/TR 10064-2:1996"
SRC_BACKLASH_INT = SRC_BACKLASH + "; DIN 3967:1978 (internal pair: A_a of opposite sign)"
SRC_MEAS = "GOST 16532-70; ISO 21771:2007"
GOST_ONLY = ("E_Hs1", "E_Hs2", "T_H1", "T_H2", "center_distance_class")
ISO_ONLY = ("A_sne1", "A_sne2", "T_sn1", "T_sn2")


@dataclass(frozen=True)
class Accuracy:
    """Resolved accuracy of the pair.  Allowances in µm on the normal tooth thickness at the
    reference circle: ``upper``/``lower`` per gear (≤ 0)."""

    standard: str
    grade: int
    designation: str
    mating: str | None
    fa_class: str | None
    jn_required: float
    jn_source: str
    fa: float
    upper: tuple[float, float]
    lower: tuple[float, float]
    upper_assumed: bool
    E_Hs: tuple[float, float] | None
    T_H: tuple[float, float] | None
    flank: tuple | None            # ISO 1328-1 FlankTolerances per gear
    thermal: Thermal | None
    backlash: Backlash


@dataclass(frozen=True)
class GearTests:
    """Test dimensions of one gear; limits are ``None`` without [accuracy]."""

    k: int
    W: float
    d_W: float
    W_limits: tuple[float, float] | None
    D: float
    D_chosen: bool
    M: float
    d_M_contact: float
    M_limits: tuple[float, float] | None
    M_r: float
    M_r_limits: tuple[float, float] | None
    s_c: float
    h_c: float
    s_c_limits: tuple[float, float] | None
    s_cc: float
    h_cc: float
    s_cc_limits: tuple[float, float] | None


# ----------------------------------------------------------------------------- inputs


def _error(exc: ToleranceError | MeasurementError) -> InputError:
    return InputError.at(exc.key, exc.value, str(exc))


TEMPS = ("temperature_housing", "temperature_pinion", "temperature_wheel")
EXPANSIONS = ("expansion_housing", "expansion_pinion", "expansion_wheel")


def assume_expansion(spec: ValidatedSpec) -> None:
    """Steel's expansion coefficient for a member without one, when a temperature is given
    (echoed as assumed); called before the inputs are echoed."""
    acc = spec.data["accuracy"]
    if all(acc[k] is None for k in TEMPS):
        for k in EXPANSIONS:
            if acc[k] is not None:
                raise InputError.at(f"accuracy.{k}", acc[k], "applies only with an operating "
                                    "temperature (temperature_housing, _pinion, _wheel)")
        return
    for k in EXPANSIONS:
        if acc[k] is None:
            acc[k] = STEEL_EXPANSION
            spec.assumed.append(f"accuracy.{k}")


def _thermal(acc: dict, spec: ValidatedSpec) -> Thermal | None:
    if all(acc[k] is None for k in TEMPS):
        return None
    assume_expansion(spec)
    vals = [20.0 if acc[k] is None else acc[k] for k in TEMPS]
    vals += [acc[k] * 1e-6 for k in EXPANSIONS]
    return Thermal(*vals)


def _require(acc: dict, key: str, why: str) -> float:
    if acc[key] is None:
        raise InputError(Problem(f"accuracy.{key}", f"missing; required with {why}"))
    return acc[key]


def accuracy_of(g: PairGeometry, spec: ValidatedSpec) -> Accuracy:
    """Resolve the [accuracy] table against the pair: standard values, allowances, backlash."""
    acc = spec.data["accuracy"]
    std, grade = acc["standard"], acc["grade"]
    a_w, m_n, alpha_n = g.a_w, g.inp.m_n, g.inp.rack.alpha_n
    gost = std == gost1643.STANDARD
    for key in (ISO_ONLY if gost else GOST_ONLY):
        if acc.get(key) is not None:
            raise InputError.at(f"accuracy.{key}", acc[key],
                                f"applies to {'ISO 1328-1' if gost else gost1643.STANDARD} "
                                f"only; remove it with standard = \"{std}\"")
    try:
        thermal = _thermal(acc, spec)
        j_th = 0.0 if thermal is None else centre_distance_effect(
            1000.0 * thermal.delta_a(a_w, g.g1.d_w, g.g2.d_w, is_internal(g)), g.alpha_tw,
            g.beta_b)
        mating = acc["mating"]
        flank = None
        if gost:
            gost1643.check_grade(grade)
            if mating is None:
                raise InputError(Problem("accuracy.mating", "missing; required with GOST 1643-81: "
                                         "the type of mating H, E, D, C, B or A"))
            fa_class = acc["center_distance_class"] or gost1643.mating(mating)["fa_class"]
            fa = acc["fa"] if acc["fa"] is not None else gost1643.fa(fa_class, a_w)
            designation = gost1643.designation(grade, mating)
        else:
            iso1328.check_grade(grade, std)
            fa_class = None
            fa = _require(acc, "fa", f"{std} (it sets no centre-distance tolerance): "
                          "the limit deviation ±f_a of the centre distance in µm")
            flank = tuple(iso1328.flank_tolerances(grade, gi.d, m_n, g.inp.b_w, std)
                          for gi in g.gears)
            designation = iso1328.designation(grade, std)
        if acc["jn_min"] is not None:
            jn, jn_src = acc["jn_min"], "spec"
        elif mating is not None:
            jn, jn_src = gost1643.jn_min(mating, a_w), SRC_GOST + " (IT of a_w, ISO 286-1)"
        else:
            jn, jn_src = iso1328.jbn_min(a_w, m_n), "ISO/TR 10064-2:1996"
    except ToleranceError as exc:
        raise _error(exc) from None

    balanced = upper_allowances(jn, fa, alpha_n, g.alpha_tw, g.beta_b, j_th)
    if gost:
        T_H = (_require(acc, "T_H1", "GOST 1643-81: the tolerance T_H on the additional rack "
                        "shift of the pinion in µm (GOST 1643-81, T_H by F_r and the type of "
                        "backlash tolerance)"),
               _require(acc, "T_H2", "GOST 1643-81: the tolerance T_H on the additional rack "
                        "shift of the wheel in µm"))
        assumed = acc["E_Hs1"] is None or acc["E_Hs2"] is None
        E_Hs = tuple(acc[k] if acc[k] is not None
                     else gost1643.rack_shift_from_thickness(balanced, alpha_n)
                     for k in ("E_Hs1", "E_Hs2"))
        upper = tuple(gost1643.thickness_from_rack_shift(e, alpha_n) for e in E_Hs)
        lower = tuple(gost1643.thickness_from_rack_shift(e + t, alpha_n)
                      for e, t in zip(E_Hs, T_H))
    else:
        T_sn = (_require(acc, "T_sn1", f"{std}: the tooth thickness tolerance of the "
                         "pinion in µm (DIN 3967 series)"),
                _require(acc, "T_sn2", f"{std}: the tooth thickness tolerance of the "
                         "wheel in µm"))
        assumed = acc["A_sne1"] is None or acc["A_sne2"] is None
        upper = tuple(acc[k] if acc[k] is not None else balanced for k in ("A_sne1", "A_sne2"))
        lower = tuple(u - t for u, t in zip(upper, T_sn))
        E_Hs = T_H = None
    bl = backlash_range(upper, lower, fa, alpha_n, g.alpha_tw, g.beta_b, j_th)
    return Accuracy(std, grade, designation, mating, fa_class, jn, jn_src, fa, upper, lower,
                    assumed, E_Hs, T_H, flank, thermal, bl)


def is_internal(g) -> bool:
    """Whether gear 2 of the pair is an internal gear."""
    return getattr(g, "internal", False)


def inner(g, i: int) -> bool:
    """Whether gear ``i`` (0 pinion, 1 wheel) is an internal gear."""
    return i == 1 and is_internal(g)


def _width(g, i: int, s_n: float) -> float:
    """What the test-dimension functions of :mod:`~geardesign.spur.measurement` take for a
    normal tooth thickness ``s_n``: the thickness itself, or for an internal gear its space
    width e_n = π m_n − s_n."""
    return math.pi * g.inp.m_n - s_n if inner(g, i) else s_n


def _tooth(g: PairGeometry, i: int) -> Tooth:
    gi = g.gears[i]
    return Tooth(gi.z, g.inp.m_n, g.inp.rack.alpha_n, g.inp.beta, _width(g, i, gi.s_n), gi.d_a,
                 gi.d_l, inner(g, i))


def tests_of(g: PairGeometry, spec: ValidatedSpec, acc: Accuracy | None) -> tuple:
    """Test dimensions of both gears, with limits from ``acc``."""
    dr = spec.data.get("drawing") or {}
    out = []
    cos_a = math.cos(g.inp.rack.alpha_n)
    for i, gi in enumerate(g.gears):
        n = i + 1
        t = _tooth(g, i)
        lim = None if acc is None else (acc.upper[i] * 1e-3, acc.lower[i] * 1e-3)
        k = dr.get(f"k{n}")
        # the flanks' measurable band: external from the active limit to the tip, internal
        # from the (inner) tip to the outer end of the involute
        band = (gi.d_a, gi.d_l) if inner(g, i) else (max(gi.d_p, gi.d_l), gi.d_a)
        try:
            if k is None:
                k, W, d_W = gi.k, gi.W, gi.d_W
            else:
                W, d_W = span(gi.z, gi.x, g.inp.m_n, g.inp.rack.alpha_n, g.inp.beta, k,
                              *band, g.inp.b_w, f"drawing.k{n}")
        except MeasurementError as exc:
            raise _error(exc) from None
        D = dr.get(f"ball_diameter{n}")
        chosen = D is None
        if chosen:
            D = ideal_ball(t)
        res = over_balls(t, D) if ideal_ok(t, D) else None
        why = (("it is too large: its centre would lie inside the base circle; choose a "
                "smaller ball") if t.internal else
               ("it is too small: it would sink below the base circle into the tooth space; "
                "choose a larger ball")) if res is None else ball_touches(t, res)
        if why is not None:
            key = f"drawing.ball_diameter{n}"
            if chosen:
                raise InputError(Problem(key, f"missing: no ball near mid-height fits this gear "
                                         f"({why}); give the ball diameter"))
            raise InputError.at(key, D, f"the ball does not touch the flanks: {why}")
        ch, cc = chordal(t), constant_chord(t)
        if lim is None:
            W_l = M_l = s_l = c_l = None
        else:
            if gi.s_n + lim[1] <= 0.1 * gi.s_n:
                raise InputError(Problem(
                    "accuracy", f"the thickness allowances ({acc.upper[i]:.1f}…"
                    f"{acc.lower[i]:.1f} µm) leave less than a tenth of the {who(i, g)}'s tooth "
                    f"thickness s_n = {gi.s_n:.4f} mm: give smaller allowances or tolerances"))
            # an internal gear's span is over spaces: thinner teeth make it longer
            W_l = _max_min(W + (-e if inner(g, i) else e) * cos_a for e in lim)
            try:
                balls = tuple(over_balls(t, D, _width(g, i, gi.s_n + e)) for e in lim)
            except MeasurementError:
                raise _thin_tooth(spec, g, t.internal, n, D, chosen, gi.s_n, acc.upper[i],
                                  acc.lower[i]) from None
            M_l = _max_min(b.M for b in balls)
            Mr_l = _max_min(b.M_r for b in balls)
            s_l = _max_min(chordal(t, _width(g, i, gi.s_n + e)).s_c for e in lim)
            c_l = _max_min(constant_chord(t, _width(g, i, gi.s_n + e)).s_c for e in lim)
        if lim is None:
            Mr_l = None
        out.append(GearTests(k, W, d_W, W_l, D, chosen, res.M, res.d_c, M_l, res.M_r, Mr_l,
                             ch.s_c, ch.h_c, s_l, cc.s_c, cc.h_c, c_l))
    return tuple(out)


def _max_min(values) -> tuple[float, float]:
    """The two limits of a test dimension as (upper, lower): the upper thickness allowance
    gives the larger dimension over balls of an external gear but the smaller one between
    balls (and span over spaces) of an internal gear."""
    a, b = values
    return (a, b) if a >= b else (b, a)


def _thin_tooth(spec: ValidatedSpec, g, internal: bool, n: int, D: float, chosen: bool,
                s_n: float, upper: float, lower: float) -> InputError:
    """The ball sinks below the base circle of the thinnest tooth (an internal gear: its
    centre falls inside the base circle with the narrowest space) the allowances permit.
    A ball the user gave is his to change; a ball chosen here (at mid-height of the
    nominal tooth, from the module and the teeth) is not: the error then names the inputs
    it follows from, the module and the allowances of [accuracy]."""
    allowances = (f"the thickness allowances {upper:.1f}…{lower:.1f} µm (from [accuracy]) "
                  f"on s_n{n} = {s_n:.4f} mm")
    if not chosen:
        return InputError.at(f"drawing.ball_diameter{n}", D, (
            f"the ball's centre falls inside the base circle with the narrowest space "
            f"{allowances} permit: choose a smaller ball") if internal else (
            f"the ball sinks below the base circle of the thinnest tooth {allowances} "
            f"permit: choose a larger ball"))
    gear = spec.data.get("gear")
    where = ("gear.module", gear["module"]) if gear is not None else ("accuracy", Problem.NO_VALUE)
    part, miss = (("space too narrow", "has its centre inside the base circle") if internal
                  else ("tooth too thin", "sinks below the base circle"))
    return InputError(Problem(where[0], f"{allowances} leave the {who(n - 1, g)}'s {part} "
                              f"for a measuring ball: the ball chosen for it (D{n} = "
                              f"{D:.4g} mm, derived from the module and z{n}) {miss}; check "
                              f"the unit of the module (mm), give smaller allowances in "
                              f"[accuracy], or give drawing.ball_diameter{n}", where[1]))


def who(i: int, g=None) -> str:
    return ("pinion", "internal gear" if g is not None and is_internal(g) else "wheel")[i]


def ideal_ok(t: Tooth, D: float) -> bool:
    try:
        over_balls(t, D)
        return True
    except MeasurementError:
        return False
