"""[DIN743-2]: stress concentration factor α of a shoulder, related stress gradient G′ and
support number n, notch factors β (from α and n, or measured: key seat, press fit), the
geometric size factors K_2(d) and K_3(d), and the roughness factor K_F."""

from __future__ import annotations

import math

from geardesign.epicycle_rim import endurance as E
from geardesign.shaft.din743 import tables


def alpha_shoulder(d: float, D: float, r: float, load: str) -> float:
    """Stress concentration factor α of a shoulder (Absatz) [-] ([DIN743-2] table 2):

    .. math:: α = 1 + \\frac{1}{\\sqrt{A\\frac{r}{t} + 2B\\frac{r}{d}\\left(1 + 2\\frac{r}{d}
              \\right)^2 + C\\left(\\frac{r}{t}\\right)^z\\frac{d}{D}}},\\qquad t = (D - d)/2

    Parameters
    ----------
    d, D : smaller and larger diameter [mm]; r : fillet radius [mm]; load : ``"tension"``,
        ``"bending"`` or ``"torsion"`` (A, B, C, z of ``tables.toml`` [shoulder]).

    >>> round(alpha_shoulder(84.0, 100.0, 4.0, "bending"), 4)
    2.0032
    """
    c = tables()["shoulder"][load]
    t = (D - d) / 2.0
    return 1.0 + 1.0 / math.sqrt(c["A"] * r / t + 2.0 * c["B"] * r / d * (1.0 + 2.0 * r / d) ** 2
                                 + c["C"] * (r / t) ** c["z"] * d / D)


def shoulder_in_range(d: float, D: float, r: float) -> bool:
    """True where the α formula holds ([DIN743-2]: r/t >= 0.03, d/D <= 0.98)."""
    s = tables()["shoulder"]
    t = (D - d) / 2.0
    return r / t >= s["r_t_min"] and d / D <= s["d_D_max"]


def stress_gradient_shoulder(d: float, D: float, r: float, load: str) -> float:
    """Related stress gradient G′ of a shoulder [mm⁻¹] ([DIN743-2] table 3):
    G′ = 2.3·(1 + φ)/r (tension, bending), G′ = 1.15/r (torsion);
    φ = 1/(4·√(t/r) + 2) for d/D > 0.67, else 0 (as transcribed in [din743py]).

    >>> round(stress_gradient_shoulder(84.0, 100.0, 4.0, "bending"), 4)
    0.6501
    """
    s = tables()["shoulder"]
    if load == "torsion":
        return s["G_torsion"] / r
    t = (D - d) / 2.0
    phi = 1.0 / (4.0 * math.sqrt(t / r) + 2.0) if d / D > s["phi_d_D"] else 0.0
    return s["G_tension_bending"] * (1.0 + phi) / r


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


def K_F(Rz: float, sigma_B_d: float) -> tuple[float, float]:
    """Roughness factors K_Fσ, K_Fτ [-] ([DIN743-2]; the same form as [GOST25504]):
    K_Fσ = 1 − 0.22·lg(R_z/µm)·(lg(σ_B(d)/20 MPa) − 1), K_Fτ = 0.575·K_Fσ + 0.425.

    >>> [round(k, 4) for k in K_F(10.0, 1000.0)]
    [0.8462, 0.9116]
    """
    k = E.roughness_factor(Rz, sigma_B_d)
    return k, 0.575 * k + 0.425
