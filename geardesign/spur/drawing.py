"""From the calculation to the gear drawing: the tolerances and the backlash range of the
pair, the test dimensions of each gear with their limits, and the drawing data table
(GOST 2.403-75 / ISO 1340 parameter table).

Internal pairs (:class:`~geardesign.spur.internal.InternalPairGeometry`): the same
tolerances (the internal gear's by its own d, b), its tooth thickness allowances those of
its teeth (≤ 0: wider spaces; [DIN3967], :mod:`~geardesign.spur.tolerances.backlash`), the
least backlash at a_w + f_a, the dimension between two balls or pins and the radial
single-ball dimension from its space width, the span over k spaces (with an internal
calliper: a standard disc micrometer does not reach into an internal gear) and the chordal
thickness of its teeth (a tooth calliper reaches them only in a large ring).

inputs (:func:`drawing_inputs`, every :class:`InputError`) → solve (:func:`solve`, pure,
typed records) → report (:func:`add_drawing`: rows, the data table and the checks).
"""

from __future__ import annotations

import math

from geardesign.core.errors import InputError, Problem
from geardesign.core.records import dataclass
from geardesign.core.result import DataTable, Result, check
from geardesign.core.spec import ValidatedSpec
from geardesign.spur.geometry import PairGeometry
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


# ----------------------------------------------------------------------------- report


def _pair(sec, key, values, unit, symbol, name, source, names=("pinion", "wheel")):
    for i, v in enumerate(values):
        sec.add(f"{key}{i + 1}", v, unit, f"{symbol}{i + 1}", f"{name}, {names[i]}", source)


def _accuracy_rows(res: Result, acc: Accuracy, g) -> None:
    names = (who(0, g), who(1, g))
    internal = is_internal(g)
    src_bl = SRC_BACKLASH_INT if internal else SRC_BACKLASH
    close = "a_w + f_a" if internal else "a_w − f_a"
    open_ = "a_w − f_a" if internal else "a_w + f_a"
    src = SRC_GOST if acc.standard == gost1643.STANDARD else acc.standard
    sec = res.section("accuracy", "Accuracy, tooth thickness allowances and backlash")
    sec.add("designation", acc.designation, None, "", "accuracy on the drawing", src)
    if acc.mating is not None:
        sec.add("mating", acc.mating, None, "", "type of mating", SRC_GOST)
    if acc.fa_class is not None:
        sec.add("fa_class", acc.fa_class, None, "", "class of centre-distance deviation",
                SRC_GOST)
    if acc.flank is not None:
        for attr, sym, name in (("f_pT", "f_pT", "single pitch tolerance"),
                                ("F_pT", "F_pT", "cumulative pitch tolerance"),
                                ("F_alphaT", "F_αT", "total profile tolerance"),
                                ("f_falphaT", "f_fαT", "profile form tolerance"),
                                ("f_HalphaT", "f_HαT", "profile slope tolerance"),
                                ("F_betaT", "F_βT", "total helix tolerance"),
                                ("f_fbetaT", "f_fβT", "helix form tolerance"),
                                ("f_HbetaT", "f_HβT", "helix slope tolerance"),
                                ("F_rT", "F_rT", "runout tolerance")):
            _pair(sec, attr, tuple(getattr(f, attr) for f in acc.flank), "µm", sym, name,
                  iso1328.source(attr, acc.standard), names)
    sec.add("jn_min_required", acc.jn_required, "µm", "j_n min", "required least normal backlash",
            acc.jn_source)
    sec.add("fa", acc.fa, "µm", "±f_a", "limit deviation of the centre distance",
            SRC_GOST + " (½ IT of a_w)" if acc.fa_class else "spec")
    how = "balance of j_n min" if acc.upper_assumed else "spec"
    if acc.E_Hs is not None:
        _pair(sec, "E_Hs", acc.E_Hs, "µm", "−E_Hs",
              "least additional rack shift" + (" (from the backlash balance)"
                                               if acc.upper_assumed else "")
              + (" (internal gear: into its rim, away from the axis)" if internal else ""),
              SRC_GOST, names)
        _pair(sec, "T_H", acc.T_H, "µm", "T_H", "tolerance on the additional rack shift", "spec",
              names)
    _pair(sec, "E_sns", acc.upper, "µm", "E_sns", "upper tooth thickness allowance (normal)",
          f"{src_bl}; {how}", names)
    _pair(sec, "E_sni", acc.lower, "µm", "E_sni", "lower tooth thickness allowance (normal)",
          src_bl, names)
    if internal:   # the internal gear's space width: the same allowances, opposite sign
        sec.add("E_ens2", -acc.upper[1], "µm", "E_ens2", "least space width allowance "
                "(normal), internal gear: −E_sns2", src_bl)
        sec.add("E_eni2", -acc.lower[1], "µm", "E_eni2", "largest space width allowance "
                "(normal), internal gear: −E_sni2", src_bl)
    b = acc.backlash
    sec.add("jn_min", b.jn_min, "µm", "j_n min", f"least normal backlash at 20 °C, {close}",
            src_bl)
    sec.add("jn_max", b.jn_max, "µm", "j_n max", f"largest normal backlash at 20 °C, {open_}",
            src_bl)
    if acc.thermal is not None:
        sec.add("j_thermal", b.j_thermal, "µm", "j_θ",
                "backlash change at operating temperature (housing and gears)", src_bl)
        sec.add("jn_min_hot", b.jn_min_hot, "µm", "j_n min,θ",
                "least normal backlash at operating temperature", src_bl)
        sec.add("jn_max_hot", b.jn_max_hot, "µm", "j_n max,θ",
                "largest normal backlash at operating temperature", src_bl)


def _limit_rows(sec, key: str, sym: str, name: str, limits, who: str) -> None:
    """The upper and lower limit rows of one test dimension (none without [accuracy])."""
    if limits:
        for j, (side, word) in enumerate((("upper", "max"), ("lower", "min"))):
            sec.add(f"{key}_{side}", limits[j], "mm", f"{sym} {word}",
                    f"{name}, {side} limit, {who}", SRC_MEAS)


def _test_rows(res: Result, tests: tuple, g) -> None:
    sec = res.section("test_dimensions", "Test dimensions")
    for i, t in enumerate(tests):
        n, name, ins = i + 1, who(i, g), inner(g, i)
        sec.add(f"k{n}", t.k, "-", f"k{n}", ("spaces" if ins else "teeth") + f" spanned, {name}",
                SRC_MEAS)
        sec.add(f"W{n}", t.W, "mm", f"W{n}", f"span over k {'spaces' if ins else 'teeth'}, {name}"
                + (" (internal calliper with ball or disc anvils: a standard disc micrometer "
                   "does not reach into an internal gear)" if ins else ""), SRC_MEAS)
        sec.add(f"d_W{n}", t.d_W, "mm", f"d_W{n}", f"diameter where the calliper touches, {name}",
                SRC_MEAS)
        _limit_rows(sec, f"W{n}", f"W{n}", "span", t.W_limits, name)
        sec.add(f"D{n}", t.D, "mm", f"D{n}", f"ball/pin diameter, {name}"
                + (" (chosen: contact near d + 2x·m_n)" if t.D_chosen else ""), SRC_MEAS)
        sec.add(f"M{n}", t.M, "mm", f"M{n}", f"dimension {'between' if ins else 'over'} two "
                f"balls, {name}", SRC_MEAS)
        sec.add(f"d_M_contact{n}", t.d_M_contact, "mm", f"d_c{n}",
                f"diameter where the ball touches the flanks, {name}", SRC_MEAS)
        _limit_rows(sec, f"M{n}", f"M{n}", "over balls", t.M_limits, name)
        sec.add(f"M_r{n}", t.M_r, "mm", f"M_r{n}", f"radial single-ball dimension (axis to the "
                f"{'near' if ins else 'far'} point of the ball), {name}", SRC_MEAS)
        _limit_rows(sec, f"M_r{n}", f"M_r{n}", "radial single-ball dimension", t.M_r_limits,
                    name)
        sec.add(f"s_chord{n}", t.s_c, "mm", f"s̄{n}", f"chordal tooth thickness (normal), {name}"
                + (" (of its teeth; a tooth calliper reaches them only in a large ring)"
                   if ins else ""), SRC_MEAS)
        sec.add(f"h_chord{n}", t.h_c, "mm", f"h̄{n}", f"chordal height from the tip, {name}",
                SRC_MEAS)
        _limit_rows(sec, f"s_chord{n}", f"s̄{n}", "chordal thickness", t.s_c_limits, name)
        sec.add(f"s_const{n}", t.s_cc, "mm", f"s̄_c{n}", f"constant chord, {name}", SRC_MEAS)
        sec.add(f"h_const{n}", t.h_cc, "mm", f"h̄_c{n}", f"constant chord height from the tip, "
                f"{name}", SRC_MEAS)
        _limit_rows(sec, f"s_const{n}", f"s̄_c{n}", "constant chord", t.s_cc_limits, name)


COLUMNS = [("parameter", "parameter", None), ("symbol", "symbol", None), ("unit", "unit", None),
           ("pinion", "pinion", None), ("pinion_es", "pinion upper dev.", None),
           ("pinion_ei", "pinion lower dev.", None), ("wheel", "wheel", None),
           ("wheel_es", "wheel upper dev.", None), ("wheel_ei", "wheel lower dev.", None)]


def drawing_table(g: PairGeometry, acc: Accuracy | None, tests: tuple, hand: str | None,
                  rack_name: str) -> DataTable:
    """The parameter table of each gear's drawing (GOST 2.403-75 / ISO 1340): one row per
    parameter, a column per gear with the upper and lower deviations of the test dimensions.
    An internal gear (the wheel column of an internal pair) has its span over spaces and the
    dimension between balls; the shift is in the GOST 19274-73 sign, named."""
    p = g.inp
    rows = []
    internal = is_internal(g)

    def row(name, sym, unit, v1, v2, dev1=(None, None), dev2=(None, None)):
        rows.append({"parameter": name, "symbol": sym, "unit": unit, "pinion": v1,
                     "pinion_es": dev1[0], "pinion_ei": dev1[1], "wheel": v2,
                     "wheel_es": dev2[0], "wheel_ei": dev2[1]})

    beta = math.degrees(p.beta)
    row("normal module", "m_n", "mm", p.m_n, p.m_n)
    row("number of teeth", "z", "-", p.z1, p.z2)
    if internal:
        row("toothing", "", "", "external", "internal")
    row("basic rack", "", "", rack_name, rack_name)
    row("profile shift coefficient" + (" (internal gear: GOST 19274-73 sign, + away from "
                                       "the axis)" if internal else ""), "x", "-", p.x1, p.x2)
    row("helix angle", "β", "deg", beta, beta)
    if beta > 0:
        h1 = hand or "right"
        row("hand of helix", "", "", h1, "left" if h1 == "right" else "right")
    if acc is not None:
        row("accuracy", "", "", acc.designation, acc.designation)
    d = [(None, None)] * 2
    for attr, lim, name, sym in (("W", "W_limits", "span over k teeth"
                                  + (" (internal gear: k spaces)" if internal else ""), "W"),
                                 ("M", "M_limits", "dimension over balls"
                                  + (" (internal gear: between)" if internal else ""), "M"),
                                 ("M_r", "M_r_limits", "radial single-ball dimension", "M_r"),
                                 ("s_c", "s_c_limits", "chordal tooth thickness", "s̄")):
        if acc is not None:
            d = [tuple(getattr(t, lim)[j] - getattr(t, attr) for j in (0, 1)) for t in tests]
        if attr == "W":
            row("teeth spanned", "k", "-", tests[0].k, tests[1].k)
        if attr == "M":
            row("ball diameter", "D", "mm", tests[0].D, tests[1].D)
        row(name, sym, "mm", getattr(tests[0], attr), getattr(tests[1], attr), d[0], d[1])
        if attr == "s_c":
            row("chordal height", "h̄", "mm", tests[0].h_c, tests[1].h_c)
    row("reference diameter", "d", "mm", g.g1.d, g.g2.d)
    row("tip diameter", "d_a", "mm", g.g1.d_a, g.g2.d_a)
    row("root diameter", "d_f", "mm", g.g1.d_f, g.g2.d_f)
    row("mating gear: number of teeth", "z", "-", p.z2, p.z1)
    fa = None if acc is None else acc.fa * 1e-3
    row("centre distance", "a_w", "mm", g.a_w, g.a_w, (fa, -fa if fa else None),
        (fa, -fa if fa else None))
    return DataTable("drawing", "Drawing data table (GOST 2.403-75 / ISO 1340)", COLUMNS, rows)


def add_drawing(res: Result, g: PairGeometry, spec: ValidatedSpec) -> None:
    """Accuracy, backlash, test dimensions and the drawing data table of the pair."""
    acc = accuracy_of(g, spec) if spec.data.get("accuracy") is not None else None
    tests = tests_of(g, spec, acc)
    if acc is not None:
        _accuracy_rows(res, acc, g)
        res.methods.append(acc.standard)
    _test_rows(res, tests, g)
    r = g.inp.rack
    rack = ("GOST 13755-81" if (abs(math.degrees(r.alpha_n) - 20.0) < 1e-9 and r.h_a == 1.0
                                and r.c == 0.25 and abs(r.rho_f - 0.38) < 1e-12)
            else f"α = {math.degrees(r.alpha_n):g}°, h_a* = {r.h_a:g}, c* = {r.c:g}, "
                 f"ρ_f* = {r.rho_f:g}")
    hand = (spec.data.get("drawing") or {}).get("helix_hand")
    res.tables.append(drawing_table(g, acc, tests, hand, rack))
    if acc is not None:
        b = acc.backlash
        least = min(b.jn_min, b.jn_min_hot)
        internal = is_internal(g)
        src_bl = SRC_BACKLASH_INT if internal else SRC_BACKLASH
        res.checks.append(check(
            "BACKLASH_JAM", least >= 0.0, "error",
            f"the least normal backlash is {least:.1f} µm (centre distance at "
            f"{'a_w + f_a' if internal else 'a_w − f_a'}"
            f"{', at operating temperature' if b.jn_min_hot < b.jn_min else ''}): the teeth "
            f"jam; thin the teeth (larger E_Hs / more negative A_sne), a wider centre-distance "
            f"class or a larger a_w tolerance {'downward' if internal else 'upward'}",
            f"the least normal backlash {least:.1f} µm keeps the teeth free", least, 0.0,
            src_bl))
        res.checks.append(check(
            "BACKLASH_GUARANTEED", least >= acc.jn_required - 1e-6, "warning",
            f"the least normal backlash {least:.1f} µm is below the required j_n min = "
            f"{acc.jn_required:.1f} µm: increase the upper thickness allowances by "
            f"{(acc.jn_required - least) / (2 * math.cos(g.inp.rack.alpha_n)):.1f} µm each",
            f"the least normal backlash {least:.1f} µm meets j_n min = {acc.jn_required:.1f} µm",
            least, acc.jn_required, src_bl))
