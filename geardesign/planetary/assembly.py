"""Assembly conditions of a planetary train: coaxiality, neighbouring planets, equal
spacing (and the admissible uneven angles), and the mesh phasing of the planets.

Pure functions; lengths in mm, angles in degrees where so named.

References
----------
Kudryavtsev V. N., Kirdyashev Yu. N., "Planetary gears. Handbook", 1977 (conditions of
coaxiality, neighbourhood and assembly); Matusevich et al. 2017, eqs. (2)-(5) (coaxiality
with shifts), (3), (4) (neighbourhood and assembly, garbled in the scan and rebuilt in
[Matusevich2017]); Parker R. G., Lin J., "Mesh phasing relationships in
planetary and epicyclic gears", J. Mech. Des. 126 (2004) (in-phase and sequential
phasing).
"""

from __future__ import annotations

import math
from functools import reduce

from geardesign.core.records import dataclass
from geardesign.planetary.kinematics import Train


def neighbour_clearance(a_w: float, d_a_max: float, angle: float) -> float:
    """Gap between the tip circles of two neighbouring planets [mm].

    .. math:: c_n = 2 a_w \\sin(θ/2) - d_{a,max}

    a_w the radius of the planet axes, θ the angle between the neighbours [rad],
    d_a,max the largest tip diameter of the planet block.  The planets clear each other
    if c_n > 0; Kudryavtsev recommends c_n >= 0.5 m.
    References: Kudryavtsev (neighbourhood condition); [Matusevich2017]; [Kudryavtsev].
    """
    return 2.0 * a_w * math.sin(0.5 * angle) - d_a_max


def max_planets(a_w: float, d_a_max: float, gap: float) -> int:
    """Largest number of equally spaced planets whose tips clear by ``gap`` [mm]:
    n_max = ⌊π / arcsin((d_a,max + gap)/(2a_w))⌋ (0 if even two do not fit)."""
    s = (d_a_max + gap) / (2.0 * a_w)
    if s >= 1.0:
        return 1
    return int(math.floor(math.pi / math.asin(s) + 1e-9))


@dataclass(frozen=True)
class Spacing:
    """Equal-spacing (assembly) condition and the admissible planet angles."""

    N: dict              # member -> number of admissible planet positions per revolution
    N_eff: int           # positions admissible for every member at once
    equal_ok: bool       # N_eff divisible by the number of planets
    angles: list         # planet angles [deg]: equal, or the nearest admissible ones
    min_angle: float     # smallest angle between neighbouring planets [deg]


def assembly_numbers(train: Train) -> dict[str, int]:
    """Number of admissible planet positions per revolution for each central member,
    with the ring ``ring`` as the reference.

    A planet may be placed at an angle θ (from the first one) if every central gear then
    shows the same tooth phase to it; for a member X meshing crown c_X (s_X = +1 external,
    −1 internal) against the ring b meshing crown c_b this gives θ = 2πj/N_X,

    .. math:: N_X = \\frac{|z_X z_{c_b} + s_X z_b z_{c_X}|}{\\gcd(z_{c_X}, z_{c_b})}

    Single-crown 2K-H: N = z_a + z_b; stepped planet: (z_a z_f + z_b z_g)/gcd(z_g, z_f);
    3K: z_a + z_b and (z_e z_g − z_b z_f)/gcd(z_g, z_f).  Derived by matching the tooth
    phases ([Matusevich2017]; [Kudryavtsev], where the same forms are given); the 2K-H
    form (z_a + z_b)/n_w ∈ ℤ is Kudryavtsev's.
    """
    zb, cb = train.ring, train.crown("ring")
    out = {}
    for x in train.central:
        if x == "ring":
            continue
        zx, cx = train.teeth(x), train.crown(x)
        s = 1 if x == "sun" else -1
        out[x] = abs(zx * cb + s * zb * cx) // math.gcd(cx, cb)
    return out


def spacing(train: Train) -> Spacing:
    """Equal spacing possible if every N_X (:func:`assembly_numbers`) is a multiple of
    the number of planets; otherwise the admissible angles nearest to 360°·i/n_w are the
    multiples of 360°/N_eff, N_eff = gcd of the N_X (Kudryavtsev, unequal spacing)."""
    N = assembly_numbers(train)
    N_eff = reduce(math.gcd, N.values())
    k = train.planets
    ok = N_eff % k == 0
    if ok:
        angles = [360.0 * i / k for i in range(k)]
    else:
        angles = [360.0 * round(i * N_eff / k) / N_eff for i in range(k)]
    gaps = [(angles[(i + 1) % k] - angles[i]) % 360.0 or 360.0 for i in range(k)]
    return Spacing(N, N_eff, ok, angles, min(gaps) if k > 1 else 360.0)


@dataclass(frozen=True)
class Phasing:
    """Mesh phases of the planets (fractions of a mesh cycle, relative to planet 1)."""

    sun: list
    ring: list
    kind: str            # "in phase", "sequential" or "mixed"


def phasing(train: Train, angles_deg: list[float]) -> Phasing:
    """Phase of each planet's sun mesh and ring mesh relative to the first planet:

    .. math:: γ_{s,i} = \\operatorname{frac}(z_a θ_i/2π), \\quad
              γ_{r,i} = \\operatorname{frac}(-z_b θ_i/2π)

    "in phase": all γ_s = 0 (z_a θ_i/2π integers: every planet meshes alike, the mesh
    forces add up); "sequential": the γ_s take every value j/n_w once (equally spaced
    planets with z_a/n_w not an integer, gcd(z_a, n_w) = 1: the forces partly cancel);
    otherwise "mixed".  References: Parker & Lin 2004 (mesh phasing); [Kudryavtsev] (phasing to
    cancel sidebands).
    """
    def frac(v: float) -> float:
        f = v - math.floor(v + 1e-9)
        return 0.0 if abs(f) < 1e-9 or abs(f - 1.0) < 1e-9 else f

    g_s = [frac(train.sun * a / 360.0) for a in angles_deg]
    g_r = [frac(-train.ring * a / 360.0) for a in angles_deg]
    k = len(angles_deg)
    if all(g == 0.0 for g in g_s):
        kind = "in phase"
    elif sorted(round(g * k) for g in g_s) == list(range(k)) and all(
            abs(g * k - round(g * k)) < 1e-6 for g in g_s):
        kind = "sequential"
    else:
        kind = "mixed"
    return Phasing(g_s, g_r, kind)
