"""[DIN743-2]: stress concentration factor α of a shoulder, a round groove and a cross-bore,
related stress gradient G′ and support number n, notch factors β (from α and n, or measured:
key seat, press fit, rectangular groove), the geometric size factors K_2(d) and K_3(d), and
the roughness factor K_F."""

from __future__ import annotations

import math

from geardesign.fatigue import gost25504 as g25
from geardesign.shaft.din743 import tables


def alpha_shoulder(d: float, D: float, r: float, load: str, kind: str = "shoulder") -> float:
    """Stress concentration factor α of a shoulder (Absatz) [-] ([DIN743-2] table 2):

    .. math:: α = 1 + \\frac{1}{\\sqrt{A\\frac{r}{t} + 2B\\frac{r}{d}\\left(1 + 2\\frac{r}{d}
              \\right)^2 + C\\left(\\frac{r}{t}\\right)^z\\frac{d}{D}}},\\qquad t = (D - d)/2

    Parameters
    ----------
    d, D : smaller and larger diameter [mm]; r : fillet radius [mm]; load : ``"tension"``,
        ``"bending"`` or ``"torsion"`` (A, B, C, z of ``tables.toml`` [shoulder]);
    kind : ``"shoulder"`` (Absatz) or ``"round_groove"`` (umlaufende Rundnut: d the groove
        root, D the shaft, t = (D − d)/2 the depth, r the groove radius; A, B, C, z of
        [round_groove], [DIN743-2] table 2 as transcribed in [din743py] and
        [DIN743Scripts]).

    >>> round(alpha_shoulder(84.0, 100.0, 4.0, "bending"), 4)
    2.0032
    """
    c = tables()[kind][load]
    t = (D - d) / 2.0
    return 1.0 + 1.0 / math.sqrt(c["A"] * r / t + 2.0 * c["B"] * r / d * (1.0 + 2.0 * r / d) ** 2
                                 + c["C"] * (r / t) ** c["z"] * d / D)


def shoulder_in_range(d: float, D: float, r: float) -> bool:
    """True where the α formula holds ([DIN743-2]: r/t >= 0.03, d/D <= 0.98)."""
    s = tables()["shoulder"]
    t = (D - d) / 2.0
    return r / t >= s["r_t_min"] and d / D <= s["d_D_max"]


def stress_gradient_shoulder(d: float, D: float, r: float, load: str,
                             kind: str = "shoulder") -> float:
    """Related stress gradient G′ of a shoulder or a round groove [mm⁻¹] ([DIN743-2]
    table 3): shoulder G′ = 2.3·(1 + φ)/r (tension, bending), G′ = 1.15/r (torsion); round
    groove (``kind="round_groove"``) G′ = 2·(1 + φ)/r, G′ = 1/r;
    φ = 1/(4·√(t/r) + 2) for d/D > 0.67, else 0 (as transcribed in [din743py]; the same in
    [DIN743Scripts]).  d, D, r [mm] as in :func:`alpha_shoulder`.

    >>> round(stress_gradient_shoulder(84.0, 100.0, 4.0, "bending"), 4)
    0.6501
    >>> round(stress_gradient_shoulder(40.0, 50.0, 1.0, "bending", "round_groove"), 4)
    2.1827
    """
    s = tables()["shoulder"]
    g = tables()[kind]
    if load == "torsion":
        return g["G_torsion"] / r
    t = (D - d) / 2.0
    phi = 1.0 / (4.0 * math.sqrt(t / r) + 2.0) if d / D > s["phi_d_D"] else 0.0
    return g["G_tension_bending"] * (1.0 + phi) / r


def support_number(G: float, sigma_S_d: float, hard_surface: bool = False) -> float:
    """Support number n [-] ([DIN743-2]):

    .. math:: n = 1 + \\sqrt{G'}\\cdot 10^{-(0.33 + σ_S(d)/712\\,\\mathrm{MPa})}
              \\quad(\\text{hard surface layer: } n = 1 + \\sqrt{G'}\\cdot 10^{-0.7})

    Parameters
    ----------
    G : related stress gradient [mm⁻¹]; sigma_S_d : yield strength σ_S(d) [MPa].

    >>> round(support_number(1.0, 712.0), 4)
    1.0468
    """
    s = tables()["support_number"]
    expo = s["hard"] if hard_surface else s["a"] + sigma_S_d / s["b"]
    return 1.0 + math.sqrt(G) * 10.0 ** (-expo)


def beta_from_alpha(alpha: float, n: float) -> float:
    """Notch factor β = α/n [-] ([DIN743-2]); n is taken no larger than α (β >= 1), as in
    [din743py]."""
    return alpha / min(n, alpha)


def K_2(d: float) -> float:
    """Geometric size factor K_2(d) of bending and torsion [-] ([DIN743-2]):

    .. math:: K_2(d) = 1 - 0.2\\,\\frac{\\lg(d/7.5\\,\\mathrm{mm})}{\\lg 20}
              \\quad(7.5 \\le d < 150\\ \\mathrm{mm}),\\qquad K_2 = 0.8\\ (d \\ge 150)

    Tension and compression: K_2 = 1.  Below 7.5 mm K_2 = 1 (the formula's lower end).

    >>> round(K_2(40.0), 4)
    0.8882
    """
    s = tables()["size"]
    d = min(max(d, s["d_0"]), s["d_max"])
    return 1.0 - s["k"] * math.log10(d / s["d_0"]) / math.log10(20.0)


def K_3(d: float, beta: float) -> float:
    """Size factor K_3(d) of a notch factor measured at another diameter [-] ([DIN743-2]):

    .. math:: K_3(d) = 1 - 0.2\\,\\lg β\\,\\frac{\\lg(d/7.5\\,\\mathrm{mm})}{\\lg 20}
              \\quad(7.5 \\le d < 150),\\qquad K_3 = 1 - 0.2\\lg β\\ (d \\ge 150)

    (Below 7.5 mm the value at 7.5 mm.)
    """
    s = tables()["size"]
    d = min(max(d, s["d_0"]), s["d_max"])
    return 1.0 - s["k"] * math.log10(beta) * math.log10(d / s["d_0"]) / math.log10(20.0)


def beta_measured(kind: str, d: float, sigma_B_d: float) -> tuple[float, float]:
    """Notch factors β_σ (bending and tension) and β_τ of a key seat (``"key"``) or a press
    fit (``"press_fit"``) at the diameter d [-] ([DIN743-2] table 1):

    .. math:: β_σ(d_{BK}) = c\\,(σ_B(d)/1000\\,\\mathrm{MPa})^e,\\quad
              β_τ(d_{BK}) = t_a β_σ(d_{BK}) + t_b,\\quad
              β(d) = β(d_{BK})\\,\\frac{K_3(d_{BK})}{K_3(d)}

    key seat: c = 3.0, e = 0.38, β_τ = 0.56·β_σ + 0.1; press fit: c = 2.7, e = 0.43,
    β_τ = 0.65·β_σ; d_BK = 40 mm; K_3 of each with its own β(d_BK).

    >>> [round(b, 4) for b in beta_measured("key", 40.0, 1000.0)]
    [3.0, 1.78]
    """
    c = tables()[kind]
    bs = c["c"] * (sigma_B_d / 1000.0) ** c["e"]
    bt = c["t_a"] * bs + c["t_b"]
    return (bs * K_3(c["d_BK"], bs) / K_3(d, bs), bt * K_3(c["d_BK"], bt) / K_3(d, bt))


def beta_ring_groove(d: float, t: float, m: float, r: float, sigma_S_d: float
                     ) -> tuple[float, float, float]:
    """Notch factors β_σzd, β_σb, β_τ of a rectangular groove (umlaufende Rechtecknut, e.g.
    for a retaining ring) at the groove root diameter d [-] ([DIN743-2] section 4.2.4, as
    transcribed in [din743py] with ρ* as in [DIN743Scripts]; constants ``tables.toml``
    [ring_groove]):

    .. math:: ρ^* = 10^{-(0.514 + 0.00152\\,σ_S(d)/\\mathrm{MPa})}\\ \\mathrm{mm}

              β^*_{σzd} = 0.9\\,(1.27 + 1.17\\sqrt{t/(r + 2.9ρ^*)}),\\quad
              β^*_{σb} = 0.9\\,(1.14 + 1.08\\sqrt{t/(r + 2.9ρ^*)}),\\quad
              β^*_τ = 1.48 + 0.45\\sqrt{t/(r + ρ^*)}

              β(d_{BK}) = β^*\\ (m/t \\ge 1.4),\\qquad
              β(d_{BK}) = 1.08\\,β^*\\,(m/t)^{-0.2}\\ (m/t < 1.4)

              β(d) = β(d_{BK})\\,K_3(d_{BK})/K_3(d),\\quad d_{BK} = 30\\ \\mathrm{mm}

    β_σ at most 4, β_τ at most 2.5 (before and after the m/t correction, as in
    [din743py]).  β is measured with R_z = 20 µm: K_F is taken relative to it
    (:func:`K_F_relative`).

    Parameters
    ----------
    d : groove root diameter [mm]; t : groove depth [mm]; m : groove width [mm];
    r : root radius [mm]; sigma_S_d : yield strength σ_S(d) [MPa].

    >>> [round(b, 4) for b in beta_ring_groove(30.0, 1.0, 2.0, 0.1, 500.0)]
    [3.2311, 2.9535, 2.5]
    """
    c = tables()["ring_groove"]
    rho = 10.0 ** -(c["rho_a"] + c["rho_b"] * sigma_S_d)
    out = []
    for load in ("tension", "bending", "torsion"):
        k = c[load]
        b = min(k["f"] * (k["a"] + k["b"] * math.sqrt(t / (r + k["k"] * rho))), k["beta_max"])
        if m / t < c["m_t_min"]:
            b = min(b * c["c_m"] * (m / t) ** c["e_m"], k["beta_max"])
        out.append(b * K_3(c["d_BK"], b) / K_3(d, b))
    return out[0], out[1], out[2]


def beta_v_notch(d: float, sigma_B_d: float) -> tuple[float, float, float]:
    """Notch factors β_σzd, β_σb, β_τ of a V-notch (Spitzkerbe, a sharp circumferential
    notch) at its root diameter d [-] ([DIN743-2] section 4.2.3, as transcribed in
    [din743py]; ``tables.toml`` [v_notch]):

    .. math:: β_{σzd}(d_{BK}) = 0.109\\,σ_B(d)/100\\,\\mathrm{MPa} + 1.074,\\quad
              β_{σb}(d_{BK}) = 0.0923\\,σ_B(d)/100\\,\\mathrm{MPa} + 0.985,\\quad
              β_τ(d_{BK}) = 0.8\\,β_{σb}(d_{BK})

              β(d) = β(d_{BK})\\,K_3(d_{BK})/K_3(d),\\quad d_{BK} = 15\\ \\mathrm{mm}

    β is measured with R_z = 20 µm (:func:`K_F_relative`); valid for 0.05 <= t/d <= 0.2.

    Parameters
    ----------
    d : root diameter [mm]; sigma_B_d : tensile strength σ_B(d) [MPa].

    >>> [round(b, 4) for b in beta_v_notch(15.0, 500.0)]
    [1.619, 1.4465, 1.1572]
    """
    c = tables()["v_notch"]
    bzd = c["tension"]["a"] * sigma_B_d / 100.0 + c["tension"]["b"]
    bb = c["bending"]["a"] * sigma_B_d / 100.0 + c["bending"]["b"]
    bt = c["torsion_of_bending"] * bb
    return tuple(b * K_3(c["d_BK"], b) / K_3(d, b) for b in (bzd, bb, bt))


def alpha_cross_bore(d: float, d_L: float) -> tuple[float, float, float]:
    """Stress concentration factors α_σzd, α_σb, α_τ of a cross-bore (Querbohrung) of
    diameter d_L [mm] in a solid shaft of diameter d [mm] ([DIN743-2] section 5.2.3, as
    transcribed in [din743py]; constants ``tables.toml`` [cross_bore]):

    .. math:: α_{σzd} = 3 - d_L/d,\\quad α_{σb} = 3 + 1.4\\,d_L/d - 2.8\\sqrt{d_L/d},\\quad
              α_τ = 2.023 - 1.125\\sqrt{d_L/d}

    (on the net section of :func:`cross_bore_section`).

    >>> [round(a, 4) for a in alpha_cross_bore(50.0, 4.0)]
    [2.92, 2.32, 1.7048]
    """
    c = tables()["cross_bore"]
    x = d_L / d
    a = [c[k]["a0"] + c[k]["a1"] * x + c[k]["a2"] * math.sqrt(x)
         for k in ("tension", "bending", "torsion")]
    return a[0], a[1], a[2]


def stress_gradient_cross_bore(d: float, d_L: float, load: str) -> float:
    """Related stress gradient G′ of a cross-bore [mm⁻¹] ([DIN743-2] table 3, as
    transcribed in [din743py]): G′_zd = 2.3/r, G′_b = 2.3/r + 2/d, G′_t = 1.15/r + 2/d with
    r = d_L/2 the hole's radius and d the shaft diameter [mm].

    >>> round(stress_gradient_cross_bore(50.0, 4.0, "bending"), 4)
    1.19
    """
    c = tables()["cross_bore"][load]
    return c["g"] / (d_L / 2.0) + c["g_d"] / d


def cross_bore_section(d: float, d_L: float) -> tuple[float, float, float]:
    """Net section of a solid shaft of diameter d [mm] with a cross-bore of diameter d_L
    [mm]: area A = πd²/4 − d_L·d [mm²], section moduli W_b = πd³/32 − d_L·d²/6 and
    W_t = πd³/16 − d_L·d²/6 [mm³] (the nominal stresses of the cross-bore's α, as
    transcribed in [din743py]).

    >>> [round(v, 1) for v in cross_bore_section(50.0, 4.0)]
    [1763.5, 10605.2, 22877.0]
    """
    return (math.pi * d * d / 4.0 - d_L * d, math.pi * d ** 3 / 32.0 - d_L * d * d / 6.0,
            math.pi * d ** 3 / 16.0 - d_L * d * d / 6.0)


def K_F_relative(Rz: float, sigma_B_d: float, Rz_B: float) -> tuple[float, float]:
    """Roughness factors of a notch factor measured on a specimen of roughness R_z,B [-]
    ([DIN743-2], as transcribed in [din743py]): K_F(R_z)/K_F(R_z,B) for σ and τ
    (:func:`K_F`); R_z, R_z,B [µm], σ_B(d) [MPa].

    >>> [round(k, 4) for k in K_F_relative(20.0, 800.0, 20.0)]
    [1.0, 1.0]
    """
    a, b = K_F(Rz, sigma_B_d), K_F(Rz_B, sigma_B_d)
    return a[0] / b[0], a[1] / b[1]


def K_F(Rz: float, sigma_B_d: float) -> tuple[float, float]:
    """Roughness factors K_Fσ, K_Fτ [-] ([DIN743-2]; the same form as [GOST25504]):
    K_Fσ = 1 − 0.22·lg(R_z/µm)·(lg(σ_B(d)/20 MPa) − 1), K_Fτ = 0.575·K_Fσ + 0.425.

    >>> [round(k, 4) for k in K_F(10.0, 1000.0)]
    [0.8462, 0.9116]
    """
    k = g25.roughness_factor(Rz, sigma_B_d)
    return k, g25.torsion_roughness_factor(k)
