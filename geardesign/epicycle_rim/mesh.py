"""Ring-planet mesh stiffness of a planetary train: planet positions, mesh phases, the
stepwise total stiffness N_Σ(φ) and its pulsation (paper B).

Pure functions on plain data.  Angles in degrees; mesh positions and phases in fractions of
the ring's angular pitch φ_w = 360°/z_r.

One ring-planet mesh carries floor(ε_α) + 1 tooth pairs over the fraction frac(ε_α) of each
pitch and floor(ε_α) pairs over the rest (for 1 < ε_α < 2: two pairs over ε_α − 1, one pair
over 2 − ε_α), so c(t) = c1·N_z(t) (paper B, Fig. 4).  The total N_Σ = Σ_i N_z,i of the n_p
meshes depends on their relative phases γ_i.  For identical planets at carrier angles ψ_i
the ring-planet phases are γ_i = frac(z_r·ψ_i/360°): with z_r/n_p not an integer, equally
spaced planets are already sequentially phased (paper B assumed them in phase).
"""

from __future__ import annotations

import cmath
import math

from geardesign.core.records import dataclass


def angles_from_shifts(n_planets: int, shifts: list[float], z_ring: int) -> list[float]:
    """Planet angles from paper B's relative shifts k_ij of adjacent planet axes.

    .. math:: Δφ_{ij} = k_{ij}\\,φ_w,\\quad φ_w = 360°/z_r,\\quad θ_{ij} = 360°/n_p + Δφ_{ij}

    and Σk = 0 so that Σθ = 360°.  Planet 1 is at 0°, planet i+1 at ψ_i + θ_i,i+1.

    References
    ----------
    Yaglinskyi et al. 2017, eq. (3) and (4) (k = 0.4, 0.2, −0.6 for the Raba 118.77 train;
    φ_w = 360°/z_r reconstructed from the printed 2°15′ and 1°7′).
    """
    pitch = 360.0 / z_ring
    out = [0.0]
    for k in shifts[:-1]:
        out.append(out[-1] + 360.0 / n_planets + k * pitch)
    return out


def mesh_phases(angles: list[float], z_ring: int, model: str = "actual") -> list[float]:
    """Ring-planet mesh phases γ_i (fractions of a pitch, in [0, 1)).

    ``actual``: γ_i = frac(z_r·ψ_i/360°), the phase that the tooth count imposes on identical
    planets at carrier angles ψ_i (sign conventions do not change N_Σ's pulsation).
    ``paper``: paper B's model, in which equally spaced planets mesh in phase and a planet
    displaced by k pitches from its equal-spacing position is k pitches out of phase:
    γ_i = frac((ψ_i − 360°·i/n_p)/φ_w).

    References
    ----------
    Parker R. G., Lin J., "Mesh phasing relationships in planetary and epicyclic gears",
    J. Mech. Des. 126 (2004) (γ_rn = ±z_r ψ_n/2π; from memory, not re-read here);
    Yaglinskyi et al. 2017, eq. (3)-(4) and Fig. 5 (paper model).
    """
    n = len(angles)
    if model == "actual":
        raw = [((z_ring * a) % 360.0) / 360.0 for a in angles]
    elif model == "paper":
        pitch = 360.0 / z_ring
        raw = [((a - 360.0 * i / n) / pitch) % 1.0 for i, a in enumerate(angles)]
    else:
        raise ValueError(f"unknown phase model {model!r}")
    # round off the floating-point noise of angles like 360/7 (a phase of 1 − 1e-15 is 0)
    return [round(g, 12) % 1.0 for g in raw]


@dataclass(frozen=True)
class Pulsation:
    """Pair count N_Σ over one mesh period and its pulsation.

    ``segments``: (duration as a fraction of the period, N_Σ) pieces of the step function,
    starting at φ = 0.  ``mu`` is paper B's pulsation depth (half range over mean);
    ``mu_h[h-1]`` the amplitude of the h-th harmonic of N_Σ over its mean.
    """

    phases: tuple
    segments: tuple
    n_min: int
    n_max: int
    mean: float
    mu: float
    mu_h: tuple
    h_dominant: int


def _mesh_count(x: float, phase: float, eps: float) -> int:
    """Pairs in contact of one mesh at the position x (fraction of a pitch)."""
    base = math.floor(eps)
    frac = eps - base
    return base + (1 if ((x - phase) % 1.0) < frac else 0)


def pulsation(phases: list[float], eps: float, harmonics: int = 12) -> Pulsation:
    """Exact step function N_Σ(φ) of the meshes and its pulsation measures.

    .. math::
        \\bar N = n_p ε_α,\\qquad μ = \\frac{N_{max} - N_{min}}{2 \\bar N}, \\qquad
        μ_h = \\frac{2}{π h \\bar N}\\,\\big|\\sin(π h\\, \\mathrm{frac}\\, ε_α)\\big|\\,
              \\Big|\\sum_i e^{2π i h γ_i}\\Big|

    μ_h is the Fourier amplitude of the h-th harmonic of the mesh frequency (a rectangular
    pulse of width frac(ε_α) per mesh, shifted by γ_i); ``h_dominant`` the largest one.

    Parameters
    ----------
    phases : γ_i of the meshes [fraction of a pitch]; eps : transverse contact ratio ε_α > 1;
    harmonics : how many harmonics to return.

    References
    ----------
    Yaglinskyi et al. 2017, eq. (2) and the stepwise algorithm (Fig. 4-5): μ = c_a/c_m, their
    1/3 (in phase) and 1/9 (shifted) are the rounded 0.352 and 0.117 of the exact sums;
    harmonic amplitudes: Fourier series of a rectangular pulse train.
    """
    frac = eps - math.floor(eps)
    cuts = sorted({0.0, *((p % 1.0) for p in phases), *(((p + frac) % 1.0) for p in phases)})
    cuts.append(1.0)
    segments = []
    for a, b in zip(cuts[:-1], cuts[1:]):
        if b - a <= 1e-15:
            continue
        mid = 0.5 * (a + b)
        n = sum(_mesh_count(mid, p, eps) for p in phases)
        if segments and segments[-1][1] == n:
            segments[-1] = (segments[-1][0] + b - a, n)
        else:
            segments.append((b - a, n))
    counts = [n for _, n in segments]
    mean = sum(w * n for w, n in segments)
    mu_h = []
    for h in range(1, harmonics + 1):
        s = abs(sum(cmath.exp(2j * math.pi * h * p) for p in phases))
        if s < 1e-9 * len(phases):  # exact cancellation (e.g. sequential phasing)
            s = 0.0
        mu_h.append(2.0 / (math.pi * h * mean) * abs(math.sin(math.pi * h * frac)) * s)
    best = max(range(len(mu_h)), key=lambda i: (mu_h[i] > 1e-12, mu_h[i])) + 1
    return Pulsation(tuple(phases), tuple(segments), min(counts), max(counts), mean,
                     (max(counts) - min(counts)) / (2.0 * mean), tuple(mu_h), best)


# ----------------------------------------------------------------- assembly and spacing


def assembly_index(angle: float, z_sun: int, z_ring: int) -> float:
    """(z_s + z_r)·θ/360° for a planet at θ from planet 1; identical planets assemble only if
    it is an integer (fixed ring, all planets meshing with sun and ring).

    References
    ----------
    Assembly condition of a 2K-H train with identical planets (e.g. Kudryavtsev, planetary
    gear design handbooks; [Yaglinskyi2017]; design practice).
    """
    return (z_sun + z_ring) * angle / 360.0


def assembly_step(z_sun: int, z_ring: int) -> float:
    """Smallest angular step [deg] between assemblable planet positions: 360°/(z_s + z_r)."""
    return 360.0 / (z_sun + z_ring)


def nearest_assemblable(angles: list[float], z_sun: int, z_ring: int) -> list[float]:
    """Each angle rounded to the nearest multiple of 360°/(z_s + z_r) [deg]."""
    step = assembly_step(z_sun, z_ring)
    return [round(a / step) * step for a in angles]


def min_spacing(angles: list[float]) -> float:
    """Smallest angle between neighbouring planets [deg] (angles in any order)."""
    s = sorted(a % 360.0 for a in angles)
    gaps = [b - a for a, b in zip(s, s[1:])] + [s[0] + 360.0 - s[-1]]
    return min(gaps)


def spacing_limit(tip_diameter_planet: float, center_distance: float) -> float:
    """Least angle between neighbouring planet axes for their tip circles not to touch [deg].

    .. math:: θ_{min} = 2 \\arcsin\\frac{d_{a,p}/2}{a_w}

    References
    ----------
    Neighbouring condition of planetary trains (design practice); no clearance added.
    """
    ratio = 0.5 * tip_diameter_planet / center_distance
    return 180.0 if ratio >= 1.0 else math.degrees(2.0 * math.asin(ratio))
