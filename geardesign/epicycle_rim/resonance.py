"""Parametric resonances of the ring: excitation frequencies, instability bands and the
vehicle speeds at which they occur (paper B).

Pure functions on plain data; frequencies in Hz, speeds in km/h, lengths in mm.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass
from geardesign.epicycle_rim import mathieu
from geardesign.epicycle_rim.mesh import Pulsation


def resonance_frequency(k0: float, order: int) -> float:
    """Excitation frequency of the parametric resonance of order n.

    .. math:: Ω_n = 2 k_0 / \\sqrt{a_n} = 2 k_0 / n, \\qquad a_n = n^2

    Parameters
    ----------
    k0 : natural frequency of the ring [Hz]; order : n = 1, 2, … (a = 1, 4, 9, 16, …).

    References
    ----------
    Yaglinskyi et al. 2017, eq. (10) and the formula Ω = 2k0/√a before Table 1.
    """
    return 2.0 * k0 / order


def speed_from_mesh_frequency(f_mesh: float, z_ring: int, wheel_radius: float,
                              carrier_ratio: float = 1.0) -> float:
    """Vehicle speed at which the ring-planet mesh frequency is f_mesh, fixed ring.

    .. math:: f_z = z_r\\, n_H,\\qquad n_H = i_{HW}\\, n_W,\\qquad
              V = 3.6 \\cdot 2π\\, \\frac{R}{1000}\\, \\frac{f_z}{z_r\\, i_{HW}}

    Parameters
    ----------
    f_mesh : mesh frequency [Hz]; z_ring : ring teeth; wheel_radius : R [mm];
    carrier_ratio : i_HW = n_carrier/n_wheel (1 when the carrier is the wheel hub).

    Returns
    -------
    V [km/h].

    References
    ----------
    Kinematics of a 2K-H train with fixed ring (the planets pass each ring tooth n_H times
    per second; each passage is one mesh of z_r teeth per revolution).  Paper B's eq. (1)
    for V_T is garbled in the source and its Table 1 speeds are 30.6 times lower than this
    relation ([Yaglinskyi2017]).
    """
    return 3.6 * 2.0 * math.pi * wheel_radius / 1000.0 * f_mesh / (z_ring * carrier_ratio)


@dataclass(frozen=True)
class Excitation:
    """The stiffness excitation used in the Mathieu model: harmonic ``h`` of the mesh
    frequency with depth ``mu``."""

    h: int
    mu: float
    depth_definition: str


def excitation(p: Pulsation, depth_definition: str = "harmonic") -> Excitation:
    """Dominant harmonic of N_Σ and the pulsation depth used for the Mathieu equation.

    ``harmonic``: μ is the Fourier amplitude of the dominant harmonic h of N_Σ over its mean;
    ``half_range``: paper B's c_a/c_m = (N_max − N_min)/(2N̄), applied at the same harmonic.

    References
    ----------
    Yaglinskyi et al. 2017, eq. (2), (5) (sinusoidal approximation of c_Σ(t));
    :func:`geardesign.epicycle_rim.mesh.pulsation`.
    """
    if depth_definition == "harmonic":
        return Excitation(p.h_dominant, p.mu_h[p.h_dominant - 1], depth_definition)
    if depth_definition == "half_range":
        return Excitation(p.h_dominant, p.mu, depth_definition)
    raise ValueError(f"unknown depth definition {depth_definition!r}")


@dataclass(frozen=True)
class OrderBand:
    """Instability band of order n in terms of Ω/k0 (the excitation) and f_m/k0 (mesh)."""

    order: int
    a_lo: float | None
    a_hi: float | None
    ratio_lo: float | None     # Ω/k0
    ratio_hi: float | None
    mesh_lo: float | None      # f_m/k0
    mesh_hi: float | None


def order_bands(p: Pulsation, exc: Excitation, orders: list[int],
                model: str = "sinusoid") -> list[OrderBand]:
    """Instability bands for each order n.

    ``sinusoid``: Mathieu along b = μa/2 (exact characteristic values), Ω = h·f_m.
    ``stepwise``: Floquet transfer matrix of the actual step function N_Σ(t), searched near
    f_m/k0 = 2/(n·h) (a band too narrow for the sampling is reported as None).

    References
    ----------
    Yaglinskyi et al. 2017, eq. (6), (9), (10); :mod:`geardesign.epicycle_rim.mathieu`.
    """
    out = []
    for n in orders:
        if model == "sinusoid":
            b = mathieu.band_exact(n, exc.mu)
            out.append(OrderBand(n, b.a_lo, b.a_hi, b.ratio_lo, b.ratio_hi,
                                 b.ratio_lo / exc.h, b.ratio_hi / exc.h))
        elif model == "stepwise":
            r0 = 2.0 / (n * exc.h)
            width = min(0.9, 2.0 * exc.mu / n + 0.02)
            found = mathieu.stepwise_band(list(p.segments), r0, width)
            if found is None:
                out.append(OrderBand(n, None, None, None, None, None, None))
            else:
                lo, hi = found
                out.append(OrderBand(n, 4.0 / (hi * exc.h) ** 2, 4.0 / (lo * exc.h) ** 2,
                                     lo * exc.h, hi * exc.h, lo, hi))
        else:
            raise ValueError(f"unknown stiffness model {model!r}")
    return out


def overlaps(lo: float, hi: float, range_lo: float, range_hi: float) -> bool:
    """Whether the intervals [lo, hi] and [range_lo, range_hi] overlap."""
    return lo <= range_hi and hi >= range_lo
