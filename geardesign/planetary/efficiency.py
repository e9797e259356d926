"""Mesh losses, torques, power flow and efficiency of planetary trains; self-locking.

Torques follow from two equilibria (Kudryavtsev's torque method, the one of Malashchenko
et al. 2017): the whole train, Σ T = 0 over the loaded members, and the planet block about
its own axis, in the carrier frame, where every mesh X passes the power P_X = T_X(ω_X − ω_h)
with its efficiency η_X in the direction the power actually flows:

.. math:: \\sum_X η_X^{k_X} ρ_X T_X = 0, \\qquad k_X = \\operatorname{sign}[T_X(ω_X - ω_h)]

(ρ_X as in :mod:`.kinematics`; k = +1 when member X drives the planet in the carrier
frame).  For the 2K-H train this is the classic T_b = −T_a u^h_ab (η^h)^k of Kreines and
Kudryavtsev (Malashchenko et al. eqs. (10)-(12)).  The sign pattern k is found by trying
each pattern and keeping the consistent one.  Bearing and churning losses are not
included.

References
----------
Kudryavtsev V. N., "Planetary gears. Handbook" (torque method, η^k); Malashchenko V. O.,
Strilets O. R., Strilets V. M., "Efficiency of a gear differential train in a device
controlling speed via the carrier", Bulletin of NTU "KhPI" 2017 No. 25 ([Malashchenko2017]), eqs.
(10)-(17); ISO/TR 14179-2:2001 and Niemann & Winter, "Maschinenelemente"
II (tooth loss factor H_V); [Malashchenko2017]; [Kudryavtsev].
"""

from __future__ import annotations

import itertools
import math

from geardesign.core.records import dataclass
from geardesign.planetary.kinematics import Speeds, Train


# the loss factor is shared gear code (the drive and the sweep use it too); these names
# stay importable from here
from geardesign.gears.losses import (  # noqa: E402,F401  (re-exported)
    EPS_ALPHA_RANGE,
    loss_factor,
    loss_factor_applies,
    mesh_loss_factor,
)


@dataclass(frozen=True)
class Flow:
    """Torques [N·m], powers [kW] and mesh (carrier-frame) powers of a steady state."""

    T: dict              # member -> external torque on it (N·m)
    P: dict              # member -> power T·ω delivered to the train (kW; > 0: input)
    P_mesh: dict         # central member -> T_X (ω_X − ω_h), the power its meshes pass (kW)
    k: dict              # central member -> +1 if it drives the planets in the carrier frame
    consistent: bool     # a power-flow pattern consistent with the losses was found


KW = math.pi / 30.0 / 1000.0   # kW per (N·m · min⁻¹)


def flow(train: Train, s: Speeds, eta: dict, given: str, T_given: float,
         unknown: tuple[str, ...], driven: str | None = None) -> Flow:
    """Torques of the loaded members for a torque ``T_given`` on member ``given``.

    ``eta``: mesh efficiency of each central member's mesh(es) (η_X < 1);
    ``unknown``: the two loaded members whose torques are sought (the other loaded
    members, if any, carry no torque); ``driven``: the member that must take power out
    of the train.  Solves Σ T = 0 and Σ η_X^{k_X} ρ_X T_X = 0 for each sign pattern k of
    the unknown central members and keeps the pattern that the resulting powers confirm
    and in which ``driven`` absorbs power (with friction the statics admit a second state
    in which the driven member is itself driven and all the power is lost in the meshes;
    if only that one exists, ``given`` cannot drive ``driven``: the train is self-locking
    in that direction and ``consistent`` is false).
    """
    rel = {x: s.rel(x) for x in train.central}
    if abs(s.n_planet_rel) < 1e-12:
        eta = {x: 1.0 for x in train.central}   # the train turns as a block: no mesh loss
    k_given = 1 if T_given * rel.get(given, 0.0) >= 0.0 else -1
    central_unknown = [u for u in unknown if u != "carrier"]
    best, best_signs_ok = None, False
    for ks in itertools.product((1, -1), repeat=len(central_unknown)):
        k = dict(zip(central_unknown, ks))
        if given in train.central:
            k[given] = k_given
        # unknowns u1, u2: Σ T = 0 over loaded members; planet balance over central members
        c = {x: eta[x] ** k.get(x, 1) * train.rho(x) for x in train.central}
        a11, a12 = 1.0, 1.0
        b1 = -T_given
        a21 = c.get(unknown[0], 0.0) if unknown[0] != "carrier" else 0.0
        a22 = c.get(unknown[1], 0.0) if unknown[1] != "carrier" else 0.0
        b2 = -(c[given] * T_given if given in train.central else 0.0)
        det = a11 * a22 - a12 * a21
        if abs(det) < 1e-15:
            continue
        T1 = (b1 * a22 - a12 * b2) / det
        T2 = (a11 * b2 - a21 * b1) / det
        T = {m: 0.0 for m in train.members}
        T[given], T[unknown[0]], T[unknown[1]] = T_given, T1, T2
        tol = 1e-9 * abs(T_given) * (max(abs(v) for v in s.n.values()) + 1.0)
        ok = all(T[x] * rel[x] * k[x] >= -tol for x in central_unknown)
        if driven is not None:
            ok = ok and T[driven] * s.n[driven] <= tol
        signs_ok = all(T[x] * rel[x] * k[x] >= -tol for x in central_unknown)
        P = {m: T[m] * s.n[m] * KW for m in train.members}
        P_mesh = {x: T[x] * rel[x] * KW for x in train.central}
        candidate = Flow(T, P, P_mesh, {x: k.get(x, 1) for x in train.central}, ok)
        if ok:
            return candidate
        if best is None or (signs_ok and not best_signs_ok):
            best, best_signs_ok = candidate, signs_ok
    return best


def efficiency(f: Flow, driving: tuple[str, ...], driven: str) -> float:
    """η = −P_driven/Σ P_driving (kW), the output over the power supplied.

    With a controlled carrier of a differential (Malashchenko et al., eq. (13)), the
    branch efficiency η_13 = −T_3ω_3/(T_1ω_1 + T_4ω_4) is this with the carrier counted
    among the driving members (its power is negative when the carrier brakes).
    """
    supplied = sum(f.P[m] for m in driving)
    return -f.P[driven] / supplied if supplied != 0.0 else math.nan


def efficiency_2kh_braked_carrier(i: float, eta_h: float, w1: float, w4: float,
                                  driving: str = "sun") -> float:
    """Closed forms of Malashchenko et al. 2017 for a 2K-H differential whose carrier is
    braked (speed ω4 imposed, e.g. by a pump), sun 1 ↔ ring 3, i = z_3/z_1:

    .. math::
        η_{13} = η^{(4)} \\frac{ω_1 - ω_4(1 + i)}{ω_1 - ω_4(1 + i η^{(4)})}
        \\quad\\text{(sun drives, eq. (14))},\\qquad
        η_{31} = η^{(4)} \\frac{ω_3 i - ω_4(1 + i)}{ω_3 i - ω_4(η^{(4)} + i)}
        \\quad\\text{(ring drives, eq. (17))}

    ``w1`` is the speed of the driving member (ω_1 or ω_3).  The formulas hold while
    numerator and denominator are positive; a numerator ≤ 0 is the paper's self-braking
    (the driven member stops or reverses).  The general solver :func:`flow` gives the same
    values (``tests/test_planetary_efficiency.py``).

    Example: with the carrier at rest (ω4 = 0) the train is the fixed-carrier one, η = η^(4)
    (identity):

    >>> efficiency_2kh_braked_carrier(3.0, 0.97, 100.0, 0.0)
    0.97
    """
    if driving == "sun":
        return eta_h * (w1 - w4 * (1.0 + i)) / (w1 - w4 * (1.0 + i * eta_h))
    return eta_h * (w1 * i - w4 * (1.0 + i)) / (w1 * i - w4 * (eta_h + i))
