"""Bevel pair geometry: cones, cone distances, diameters, addendum and dedendum angles,
tooth thickness and chordal dimensions, the virtual cylindrical gears and contact ratios.
Angles [rad], lengths [mm].

Conventions.  Straight teeth ([GOST19624], Gleason straight bevel of [ISO23509]) are
specified at the outer (back) cone: outer transverse module m_te, heights h_ae = (h_a* + x)·m_te,
h_fe = (h_a* + c* − x)·m_te.  Circular-arc (spiral) teeth ([GOST19326]; the "mean section"
data of [ISO23509]) are specified at the mean cone: mean normal module m_nm, heights
h_am = (h_a* + x)·m_nm, h_fm = (h_a* + c* − x)·m_nm.  Either module may be given; the other
follows from the cone distances.  Two depth forms: ``constant_clearance`` (the tip cone of
one member parallel to the root cone of the other, θ_a1 = θ_f2: GOST 19624 and GOST 19326
form II, Gleason) and ``tapered`` (tip and root cones from the pitch apex, θ_a = atan(h_a/R):
GOST 19326 form I, ISO 23509 "standard depth").  The wheel has the shift −x1 and the
tangential shift −x_τ1 unless x_τ2 is given (``Pair.xts``).
"""

from __future__ import annotations

import math

from geardesign.bevel.inputs import Pair, pitch_angles
from geardesign.core.records import dataclass
from geardesign.gears.geometry import BasicRack, tip_thickness, undercut_shift_limit
from geardesign.spur.measurement import Tooth
from geardesign.spur.measurement import chordal as measurement_chordal
from geardesign.spur.measurement import constant_chord as measurement_constant_chord


@dataclass(frozen=True)
class Member:
    """One member (pinion or wheel) of the pair."""

    z: int
    x: float              # profile shift coefficient
    xt: float             # tangential shift coefficient
    delta: float          # pitch cone angle δ
    theta_a: float        # addendum angle θ_a
    theta_f: float        # dedendum angle θ_f
    delta_a: float        # face (tip) cone angle δ_a = δ + θ_a
    delta_f: float        # root cone angle δ_f = δ − θ_f
    d_e: float            # outer reference diameter
    d_m: float            # mean reference diameter
    h_ae: float           # outer addendum
    h_fe: float           # outer dedendum
    h_am: float           # mean addendum
    h_fm: float           # mean dedendum
    d_ae: float           # outer tip diameter
    d_fe: float           # outer root diameter
    d_am: float           # mean tip diameter
    d_fm: float           # mean root diameter
    B: float              # pitch apex to the plane of the outer tip circle
    b_ax: float           # axial length of the face cone over the face width
    d_ai: float           # inner tip diameter
    s_e: float            # outer transverse circular tooth thickness (straight) / mean normal
    s_c: float            # chordal tooth thickness at the section of s_e
    h_c: float            # chordal height at the section of s_e (virtual gear, no cos δ)
    s_cc: float           # constant chord at the section of s_e
    h_cc: float           # height to the constant chord at the section of s_e
    # mean normal section, [ISO23509] 7.8 (both tooth forms)
    s_mn: float           # mean normal circular tooth thickness
    s_mt: float           # mean transverse circular tooth thickness
    d_mn: float           # mean normal diameter (virtual gear in the normal section)
    s_mnc: float          # mean normal chordal tooth thickness
    h_amc: float          # mean chordal addendum (with the cos δ of formula 215)
    # virtual cylindrical gear (mean section, [ISO10300-1] method B1)
    z_v: float
    z_vn: float
    d_v: float
    d_va: float
    d_vb: float
    d_vf: float
    x_min: float          # least shift without undercut (virtual gear)
    s_am: float           # normal tooth thickness at the tip, mean section
    s_ae: float           # transverse tooth thickness at the tip, outer section (straight)


@dataclass(frozen=True)
class Geometry:
    """The pair: cones, modules, virtual gear pair, contact ratios."""

    spiral: bool
    Sigma: float
    u: float
    beta_m: float
    alpha_n: float
    alpha_vt: float       # transverse pressure angle of the virtual gear
    beta_vb: float        # base helix angle of the virtual gear
    m_te: float
    m_tm: float
    m_nm: float
    R_e: float
    R_m: float
    b: float
    u_v: float            # virtual gear ratio z_v2/z_v1
    a_v: float            # virtual centre distance
    g_va: float           # length of action of the virtual gear
    p_vet: float          # transverse base pitch of the virtual gear
    b_eff: float          # effective face width b_v,eff = 0.85·b
    eps_va: float         # transverse contact ratio ε_vα
    eps_vb: float         # face contact ratio ε_vβ (effective face width)
    eps_vg: float         # virtual contact ratio ε_vγ = ε_vα + ε_vβ
    rho_rel: float        # equivalent radius of curvature normal to the contact line
    pinion: Member
    wheel: Member

    @property
    def members(self) -> tuple[Member, Member]:
        return self.pinion, self.wheel


def modules(p: Pair, delta1: float) -> tuple[float, float, float, float, float]:
    """Modules and cone distances (m_te, m_tm, m_nm, R_e, R_m) from the module as given.

    .. math::
        R_e = \\frac{m_{te} z_1}{2 \\sin δ_1},\\quad R_m = R_e - b/2,\\quad
        m_{tm} = m_{te} R_m / R_e,\\quad m_{nm} = m_{tm} \\cos β_m

    (from the mean normal module: m_tm = m_nm/cos β_m, R_m = m_tm z_1/(2 sin δ_1),
    R_e = R_m + b/2).  [ISO23509] §5.2; [GOST19624] table 1 items 8-11; [GOST19326] table 1.

    >>> from geardesign.bevel.inputs import Pair
    >>> p = Pair(False, 3.0, "outer", 20, 40, math.pi / 2, 22.0, 0.0, "right",
    ...          math.radians(20), 1.0, 0.2, 0.25, 0.0, 0.0, "tapered")
    >>> round(modules(p, pitch_angles(20, 40, math.pi / 2)[0])[3], 5)
    67.08204
    """
    cb = math.cos(p.beta_m)
    if p.module_at == "outer":
        m_te = p.m
        R_e = m_te * p.z1 / (2.0 * math.sin(delta1))
        R_m = R_e - 0.5 * p.b
        m_tm = m_te * R_m / R_e
    else:
        m_tm = p.m / cb
        R_m = m_tm * p.z1 / (2.0 * math.sin(delta1))
        R_e = R_m + 0.5 * p.b
        m_te = m_tm * R_e / R_m
    return m_te, m_tm, m_tm * cb, R_e, R_m


def transverse_angles(alpha_n: float, beta_m: float) -> tuple[float, float]:
    """Transverse pressure angle α_vt and base spiral angle β_vb of the virtual gear.

    .. math:: \\tan α_{vt} = \\tan α_n / \\cos β_m,\\quad \\sin β_{vb} = \\sin β_m \\cos α_n

    [ISO10300-1] §6 (method B1); the helical relations of ``geardesign.gears.geometry``.
    """
    from geardesign.gears.geometry import transverse_angles as helical

    return helical(alpha_n, beta_m)


def virtual_ratio(u: float, delta1: float, delta2: float) -> float:
    """Virtual gear ratio u_v = u·cos δ1/cos δ2 (u² at Σ = 90°).  [ISO10300-1] §6.

    >>> d1, d2 = pitch_angles(20, 50, math.pi / 2)
    >>> round(virtual_ratio(2.5, d1, d2), 9)
    6.25
    """
    return u * math.cos(delta1) / math.cos(delta2)


EFFECTIVE_FACE = 0.85
"""Effective face width over the face width, b_v,eff = 0.85·b: the contact pattern of a
pair checked under a light test load.  [ISO10300-1] annex A; [ISOTR10300-30] sample 1
(b_v,eff = 21.590 mm of b = 25.4 mm)."""


def contact_ratios(d_va: tuple[float, float], d_vb: tuple[float, float], a_v: float,
                   alpha_vt: float, m_nm: float, beta_m: float, b_eff: float
                   ) -> tuple[float, float, float, float, float]:
    """Length of action g_vα [mm], transverse base pitch p_vet [mm] and the contact ratios
    ε_vα, ε_vβ, ε_vγ of the virtual cylindrical gear pair (mean section, no backlash).

    .. math::
        g_{vα} = \\tfrac12\\Big(\\sqrt{d_{va1}^2 - d_{vb1}^2} + \\sqrt{d_{va2}^2 - d_{vb2}^2}\\Big)
                 - a_v \\sin α_{vt},\\quad p_{vet} = \\frac{π m_{nm} \\cos α_{vt}}{\\cos β_m},\\quad
        ε_{vα} = \\frac{g_{vα}}{p_{vet}},\\quad
        ε_{vβ} = \\frac{b_{v,eff} \\sin β_m}{π m_{nm}},\\quad ε_{vγ} = ε_{vα} + ε_{vβ}

    with the effective face width b_v,eff (:data:`EFFECTIVE_FACE`).  [ISO10300-1] annex A
    (method B1, formulae A.17, A.18, A.23-A.25); checked against [ISOTR10300-30] sample 1.
    """
    g = 0.5 * sum(math.sqrt(max(a * a - c * c, 0.0)) for a, c in zip(d_va, d_vb))
    g -= a_v * math.sin(alpha_vt)
    p_vet = math.pi * m_nm * math.cos(alpha_vt) / math.cos(beta_m)
    eps_a = g / p_vet
    eps_b = b_eff * math.sin(beta_m) / (math.pi * m_nm)
    return g, p_vet, eps_a, eps_b, eps_a + eps_b


def relative_curvature(alpha_n: float, beta_m: float, d_v1: float, d_v2: float) -> float:
    """Equivalent radius of curvature ρ_rel [mm] normal to the contact line at the mean point
    (no hypoid offset).

    .. math::
        ρ_t = \\frac{\\sin α_n}{\\cos^2 β_m\\,(2/d_{v1} + 2/d_{v2})},\\quad
        \\tan β_B = \\tan β_m \\sin α_n,\\quad ρ_{rel} = ρ_t \\cos^2 β_B

    (R_m tan δ = d_v/2).  [ISO10300-1] annex A, formulae A.37-A.39 with α_lim = 0;
    [ISOTR10300-30] sample 1 (ρ_t = 13.173, β_B = 13.468°, ρ_rel = 12.459 mm).
    """
    rho_t = math.sin(alpha_n) / (math.cos(beta_m) ** 2 * (2.0 / d_v1 + 2.0 / d_v2))
    beta_B = math.atan(math.tan(beta_m) * math.sin(alpha_n))
    return rho_t * math.cos(beta_B) ** 2


@dataclass(frozen=True)
class Chords:
    """Chordal dimensions of one member at one section (:func:`tooth_chords`) [mm]."""

    d_vn: float           # diameter of the virtual gear in the normal section
    s_c: float            # chordal tooth thickness
    h_c: float            # chordal height (virtual gear)
    h_c_iso: float        # chordal height with the cos δ of [ISO23509] formula 215
    s_cc: float           # constant chord
    h_cc: float           # height to the constant chord


def tooth_chords(z_v: float, m: float, alpha_n: float, beta: float, s: float, h_a: float,
                 delta: float) -> Chords:
    """Chordal tooth thickness, chordal heights and the constant chord of a bevel member on
    its virtual cylindrical gear (z_v = z/cos δ teeth of the module m at the section of the
    thickness s, helix β), in the normal section, by the chord functions of the spur package
    ([ISO21771] 6.2, [GOST16532]; called):

    .. math::
        d_{vn} = \\frac{d_v}{\\cos^2 β_{vb}},\\quad ψ = \\frac{s}{d_{vn}},\\quad
        \\bar s = d_{vn} \\sin ψ,\\quad \\bar h_a = h_a + \\tfrac12 d_{vn} (1 - \\cos ψ),\\quad
        \\bar h_{a,ISO} = h_a + \\tfrac12 d_{vn} \\cos δ\\,(1 - \\cos ψ)

    .. math:: \\bar s_c = s \\cos^2 α_n,\\quad \\bar h_c = h_a - \\tfrac14 s \\sin 2α_n

    At the mean section, d_vn is the mean normal diameter d_mn = d_m/((1 − sin²β_m cos²α_n)
    cos δ) of [ISO23509] formula (213), s̄ its mean normal chordal thickness s_mnc (214); its
    mean chordal addendum h_amc (215) carries the factor cos δ on the rise of the arc over
    the chord (h̄_a,ISO), which the chordal height of the virtual gear (h̄_a, the rule of
    [GOST16532] applied to the virtual gear: for straight teeth at the outer cone
    h̄_ae ≈ h_ae + s_e² cos δ/(4 d_e), the handbook form of [GOST19624] table 4 as applied by
    [Dunaev]) does not.  The constant chord s̄_c, h̄_c (the measurement of [GOST19624] and
    [GOST19326] by the constant chord, the [GOST16532] form) does not depend on the diameter.
    Each is reported under its own key.  Checked: d_vn, s̄, h̄_a,ISO by [ISO23509] annex F.2
    through [ISO23509Calc] (d_mn1 = 82.241, s_mnc1 = 6.458, h_amc1 = 4.955 mm); h̄_a and the
    constant chord have no printed bevel case.

    >>> c = tooth_chords(14 / math.cos(0.3446), 3.21332, math.radians(20), math.radians(35),
    ...                  6.465, 4.836, 0.3446)
    >>> round(c.d_vn, 2), round(c.s_c, 3), round(c.h_c, 4), round(c.h_c_iso, 4)
    (82.24, 6.458, 4.963, 4.9555)
    >>> round(c.s_cc, 4), round(c.h_cc, 4)
    (5.7087, 3.7971)
    """
    t = Tooth(z_v, m, alpha_n, beta, s, z_v * m / math.cos(beta) + 2.0 * h_a, 0.0)
    c = measurement_chordal(t)
    cc = measurement_constant_chord(t)
    return Chords(t.d / math.cos(t.beta_b) ** 2, c.s_c, c.h_c,
                  h_a + math.cos(delta) * (c.h_c - h_a), cc.s_c, cc.h_c)


def pair_geometry(p: Pair) -> Geometry:
    """All geometry of the pair; see the module docstring for the conventions.

    Heights at the basis section (outer for straight, mean for spiral teeth), angles
    θ_f = atan(h_f/R) at that section, θ_a from the mating member's θ_f (constant
    clearance) or atan(h_a/R) (tapered); heights elsewhere follow the cones:
    h(R) = h_basis + (R − R_basis)·tan θ.  Diameters d = m_t z, d_a = d + 2 h_a cos δ,
    d_f = d − 2 h_f cos δ; B = R_e cos δ − h_ae sin δ; along the face cone over the face
    width b the axial length b_ax = b cos δ_a/cos θ_a and the inner tip diameter
    d_ai = d_ae − 2 b sin δ_a/cos θ_a.  [GOST19624] table 1; [GOST19326] table 1;
    [ISO23509] §5; checked for straight teeth of both depth forms by [KHK] (standard and
    Gleason straight bevel examples).
    """
    d1, d2 = pitch_angles(p.z1, p.z2, p.Sigma)
    m_te, m_tm, m_nm, R_e, R_m = modules(p, d1)
    outer = not p.spiral
    m_basis, R_basis = (m_te, R_e) if outer else (m_nm, R_m)
    xs, xts, zs, deltas = (p.x1, -p.x1), p.xts, (p.z1, p.z2), (d1, d2)
    h_a = [(p.ha + x) * m_basis for x in xs]
    h_f = [(p.ha + p.c - x) * m_basis for x in xs]
    th_f = [math.atan(h / R_basis) for h in h_f]
    if p.depth == "constant_clearance":
        th_a = [th_f[1], th_f[0]]
    else:
        th_a = [math.atan(h / R_basis) for h in h_a]
    alpha_vt, beta_vb = transverse_angles(p.alpha_n, p.beta_m)
    racks = [BasicRack(p.alpha_n, p.ha, p.c, rho) for rho in p.rho_a0s]
    u = p.z2 / p.z1
    parts = []
    for i in (0, 1):
        z, x, xt, dl = zs[i], xs[i], xts[i], deltas[i]
        ta, tf = math.tan(th_a[i]), math.tan(th_f[i])
        h_ae = h_a[i] + (R_e - R_basis) * ta
        h_fe = h_f[i] + (R_e - R_basis) * tf
        h_am = h_a[i] - (R_basis - R_m) * ta
        h_fm = h_f[i] - (R_basis - R_m) * tf
        d_e, d_m = m_te * z, m_tm * z
        c = math.cos(dl)
        d_ae = d_e + 2.0 * h_ae * c
        face = p.b / math.cos(th_a[i])   # the face cone's length over the face width
        # thickness at the section of the module: outer transverse (straight, [GOST19624]
        # table 4) or mean normal (spiral, [GOST19326] table 4), and at the mean normal
        # section for both ([ISO23509] 7.8, formulae 206, 211, 212)
        k_s = 0.5 * math.pi + 2.0 * x * math.tan(p.alpha_n) + xt
        s = k_s * m_basis
        s_mn = k_s * m_nm
        iso = tooth_chords(z / c, m_nm, p.alpha_n, p.beta_m, s_mn, h_am, dl)
        basis = tooth_chords(z / c, m_te, p.alpha_n, 0.0, s, h_ae, dl) if outer else iso
        d_v = d_m / c
        z_v = z / c
        d_va, d_vf = d_v + 2.0 * h_am, d_v - 2.0 * h_fm
        x_eff = x + xt / (2.0 * math.tan(p.alpha_n))
        s_am = tip_thickness(z_v, x_eff, d_v, d_va, alpha_vt, p.alpha_n, p.beta_m)
        s_ae = (tip_thickness(z / c, x_eff, d_e / c, d_e / c + 2.0 * h_ae, p.alpha_n,
                              p.alpha_n, 0.0) if outer else math.nan)
        parts.append(Member(
            z, x, xt, dl, th_a[i], th_f[i], dl + th_a[i], dl - th_f[i], d_e, d_m, h_ae, h_fe,
            h_am, h_fm, d_ae, d_e - 2.0 * h_fe * c, d_m + 2.0 * h_am * c,
            d_m - 2.0 * h_fm * c, R_e * c - h_ae * math.sin(dl),
            face * math.cos(dl + th_a[i]), d_ae - 2.0 * face * math.sin(dl + th_a[i]),
            s, basis.s_c, basis.h_c, basis.s_cc, basis.h_cc, s_mn, s_mn / math.cos(p.beta_m),
            iso.d_vn, iso.s_c, iso.h_c_iso,
            z_v, z_v / (math.cos(beta_vb) ** 2 * math.cos(p.beta_m)), d_v, d_va,
            d_v * math.cos(alpha_vt), d_vf,
            undercut_shift_limit(z_v, alpha_vt, p.beta_m, racks[i]), s_am, s_ae))
    P, W = parts
    a_v = 0.5 * (P.d_v + W.d_v)
    b_eff = EFFECTIVE_FACE * p.b
    g, p_vet, ea, eb, eg = contact_ratios((P.d_va, W.d_va), (P.d_vb, W.d_vb), a_v, alpha_vt,
                                          m_nm, p.beta_m, b_eff)
    return Geometry(p.spiral, p.Sigma, u, p.beta_m, p.alpha_n, alpha_vt, beta_vb, m_te, m_tm,
                    m_nm, R_e, R_m, p.b, virtual_ratio(u, d1, d2), a_v, g, p_vet, b_eff, ea,
                    eb, eg, relative_curvature(p.alpha_n, p.beta_m, P.d_v, W.d_v), P, W)
