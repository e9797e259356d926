"""Kinematics of 2K-H and 3K planetary trains by the Willis method, and the
characteristic frequencies used in vibration diagnostics.

The train is described by its central members (sun ``sun``, ring ``ring``, second ring
``ring2`` of a 3K train) and the carrier ``carrier``.  Each central member X meshes one
crown of the planet block (z_c teeth), externally (s_X = +1, the sun) or internally
(s_X = −1, a ring).  Relative to the carrier the planet block turns at ω_p and

.. math:: ω_X - ω_h = ρ_X\\,ω_p, \\qquad ρ_X = -s_X\\,z_c/z_X

(an external mesh reverses the sense of rotation, an internal one keeps it).  Hence the
fixed-carrier (Willis) ratio of two members u^h_XY = (ω_X − ω_h)/(ω_Y − ω_h) = ρ_X/ρ_Y,
e.g. u^h_ab = −z_b/z_a for the simple 2K-H train.  Two conditions (a fixed member and
an input speed, or two given speeds of a differential) fix ω_h and ω_p.

Speeds are in min⁻¹ (any unit works: the relations are linear), frequencies in Hz.

References
----------
Kudryavtsev V. N., Kirdyashev Yu. N. (eds.), "Planetary gears. Handbook", 1977 (Willis
method, 2K-H and 3K schemes); Matusevich et al. 2017, eq. (1) (3K ratio);
Gavrilov et al. 2017 (BELAZ motor-wheel, frequencies), [Matusevich2017]; [Gavrilov2017]; [Kudryavtsev].
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

SCHEMES = ("2K-H", "2K-H-stepped", "3K")
CENTRAL = ("sun", "ring", "ring2")
MEMBERS = ("sun", "ring", "ring2", "carrier")


@dataclass(frozen=True)
class Train:
    """Tooth numbers of a train (all positive; rings are internal gears).

    ``planet2`` is the second crown of a stepped planet (2K-H-stepped: it meshes the
    ring; 3K: it meshes ``ring2``); ``None`` for a single-crown planet.  ``ring2`` is the
    second (output) ring of a 3K train.
    """

    scheme: str
    sun: int
    planet: int
    ring: int
    planets: int
    planet2: int | None = None
    ring2: int | None = None

    def crown(self, member: str) -> int:
        """Teeth of the planet crown that meshes a central member."""
        if member == "sun":
            return self.planet
        if member == "ring":
            return self.planet2 if self.scheme == "2K-H-stepped" else self.planet
        if member == "ring2":
            return self.planet2 if self.planet2 is not None else self.planet
        raise KeyError(member)

    def teeth(self, member: str) -> int:
        return {"sun": self.sun, "ring": self.ring, "ring2": self.ring2}[member]

    @property
    def central(self) -> tuple[str, ...]:
        return ("sun", "ring", "ring2") if self.scheme == "3K" else ("sun", "ring")

    @property
    def members(self) -> tuple[str, ...]:
        return self.central + ("carrier",)

    @property
    def loaded(self) -> tuple[str, ...]:
        """Members that carry an external torque: the 3K carrier runs free."""
        return self.central if self.scheme == "3K" else self.central + ("carrier",)

    def rho(self, member: str) -> float:
        """ρ_X = (ω_X − ω_h)/ω_p = −s_X z_c/z_X (see the module notes)."""
        s = 1.0 if member == "sun" else -1.0
        return -s * self.crown(member) / self.teeth(member)

    def willis(self, x: str, y: str) -> float:
        """Fixed-carrier ratio u^h_XY = (ω_X − ω_h)/(ω_Y − ω_h) = ρ_X/ρ_Y.

        Kudryavtsev (Willis formula); for the 2K-H train u^h_ab = −z_b/z_a, for a stepped
        planet −z_g z_b/(z_a z_f) (Malashchenko et al. 2017, eq. (18))."""
        return self.rho(x) / self.rho(y)


@dataclass(frozen=True)
class Speeds:
    """Absolute speeds of the members (min⁻¹), the carrier speed and the planet speed
    relative to the carrier."""

    n: dict          # member -> absolute speed
    n_carrier: float
    n_planet_rel: float

    def rel(self, member: str) -> float:
        """Speed relative to the carrier."""
        return self.n[member] - self.n_carrier

    @property
    def n_planet(self) -> float:
        """Absolute speed of the planet block about its own axis."""
        return self.n_carrier + self.n_planet_rel


class KinematicsError(ValueError):
    """The given speeds do not determine the motion (e.g. two conditions on one member)."""


def _coefficients(train: Train, member: str) -> tuple[float, float]:
    """ω_X = a·ω_h + b·ω_p."""
    if member == "carrier":
        return 1.0, 0.0
    return 1.0, train.rho(member)


def speeds(train: Train, conditions: dict[str, float]) -> Speeds:
    """Speeds of all members from two conditions ``{member: speed}`` (a fixed member has
    speed 0).

    Solves ω_X = ω_h + ρ_X ω_p for the two given members (Willis).  Raises
    :class:`KinematicsError` if the two conditions are dependent (the same member twice,
    or two members that always turn together)."""
    (m1, w1), (m2, w2) = conditions.items()
    a1, b1 = _coefficients(train, m1)
    a2, b2 = _coefficients(train, m2)
    det = a1 * b2 - a2 * b1
    if abs(det) < 1e-12:
        raise KinematicsError(f"the speeds of {m1} and {m2} do not determine the motion")
    w_h = (w1 * b2 - w2 * b1) / det
    w_p = (a1 * w2 - a2 * w1) / det
    n = {m: (w_h if m == "carrier" else w_h + train.rho(m) * w_p) for m in train.members}
    return Speeds(n, w_h, w_p)


def ratio(train: Train, fixed: str, driving: str, driven: str) -> float:
    """Transmission ratio i = n_driving/n_driven with ``fixed`` held (signed).

    For the 2K-H train with the ring fixed, sun → carrier: i = 1 + z_b/z_a; for the 3K
    train, ring b fixed, sun → ring e (Matusevich et al. 2017, eq. (1)):

    .. math:: U^b_{ae} = \\frac{1 + z_b/z_a}{1 - z_b z_f/(z_g z_e)}

    Returns ``math.inf`` if the driven member stands still."""
    s = speeds(train, {fixed: 0.0, driving: 1.0})
    out = s.n[driven]
    return math.inf if abs(out) < 1e-15 else 1.0 / out


# ----------------------------------------------------------------------------- frequencies


@dataclass(frozen=True)
class Frequencies:
    """Rotation and mesh frequencies [Hz] (Gavrilov et al. 2017, Table 1 notation)."""

    f: dict              # member -> absolute rotation frequency
    f_rel: dict          # member -> |frequency relative to the carrier|; "planet" too
    f_carrier: float
    f_mesh: float        # mesh frequency of the sun–planet–ring meshes
    f_mesh2: float | None  # mesh frequency of the second crown's mesh (stepped, 3K)
    planet_pass: float   # planets passing a point of the ring: n_w |f_ring − f_h|
    fault: dict          # local-fault frequencies: sun, planet (one flank), ring (, ring2)


def frequencies(train: Train, s: Speeds) -> Frequencies:
    """Characteristic frequencies for diagnostics.

    .. math::
        f_z = z_a |f_a - f_h| = z_b |f_b - f_h|,\\quad
        f_{1} = f_z/z_a,\\; f_{2} = f_z/z_g,\\; f_{3} = f_z/z_b \\;(\\text{relative to the carrier})

    planet pass n_w|f_b − f_h|; local faults: sun n_w|f_a − f_h|, planet f_z/z_g (one
    flank; twice that when both flanks work), ring n_w|f_b − f_h|.
    References: Gavrilov, Ishin, Goman, Skorokhodov 2017 (BELAZ motor-wheel), Table 1;
    [Gavrilov2017] (McFadden & Smith's planetary relations).
    """
    f = {m: s.n[m] / 60.0 for m in train.members}
    f_h = s.n_carrier / 60.0
    f_rel = {m: abs(f[m] - f_h) for m in train.central}
    f_mesh = train.sun * f_rel["sun"]
    f_rel["planet"] = abs(s.n_planet_rel) / 60.0
    f_mesh2 = None
    if train.scheme == "3K":
        f_mesh2 = train.ring2 * f_rel["ring2"]
        f_rel["planet2"] = f_mesh2 / train.crown("ring2")
    elif train.scheme == "2K-H-stepped":
        f_mesh2 = train.ring * f_rel["ring"]
        f_rel["planet2"] = f_rel["planet"]
    n_w = train.planets
    fault = {"sun": n_w * f_rel["sun"], "planet": f_rel["planet"], "ring": n_w * f_rel["ring"]}
    if train.scheme == "3K":
        fault["ring2"] = n_w * f_rel["ring2"]
    return Frequencies(f, f_rel, f_h, f_mesh, f_mesh2, n_w * f_rel["ring"], fault)


def sidebands(f_mesh: float, f_fault: float, f_carrier: float, harmonics: int,
              orders: int) -> list[list[float]]:
    """Sideband family around each mesh harmonic (polyharmonic modulation):

    .. math:: h f_z \\pm k f_d \\pm l f_h, \\qquad h = 1..H,\\; k, l = 0..K

    one sorted list per harmonic h (only positive frequencies, duplicates removed).
    References: Gavrilov et al. 2017, text before Table 1 (families (ω_z ± kω_d),
    (ω_z ± lω_H ± kω_d)); [Gavrilov2017].
    """
    out = []
    for h in range(1, harmonics + 1):
        values = set()
        for k in range(-orders, orders + 1):
            for l in range(-orders, orders + 1):
                f = h * f_mesh + k * f_fault + l * abs(f_carrier)
                if f > 0.0:
                    values.add(round(f, 9))
        out.append(sorted(values))
    return out


def discriminant(amplitudes: list[float]) -> float:
    """Dimensional discriminant: the root sum of squares of the amplitudes of the first
    mesh harmonics,

    .. math:: S_{fz} = \\sqrt{\\textstyle\\sum_{n=1}^{5} S_{n f_z}^2}

    Reconstructed from Gavrilov et al. 2017, eq. (1) (illegible in the scan) so that their
    Table 2 is reproduced exactly ([Gavrilov2017]).

    Example: amplitudes 3 and 4 give √(9 + 16) = 5:

    >>> discriminant([3.0, 4.0])
    5.0
    """
    return math.sqrt(sum(a * a for a in amplitudes))


def relative_growth(S: float, S0: float) -> float:
    """Dimensionless discriminant P_fz = (S_fz − S_fz0)/S_fz0 (Gavrilov et al. 2017,
    eq. (2), reconstructed as :func:`discriminant`).

    Example: S = 1.5 against S0 = 1 is a growth of 0.5:

    >>> relative_growth(1.5, 1.0)
    0.5
    """
    return (S - S0) / S0
