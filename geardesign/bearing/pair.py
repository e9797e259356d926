"""Axial loads of two angular contact ball or tapered roller bearings adjusted against each
other (face-to-face or back-to-back, practically zero clearance, no preload): pure functions.

A radial load on such a bearing induces an axial force F_i in it ([SKF6000] pp. 415–416,
table 4; [NSK] A-36, example 5):

* tapered roller bearings: F_i = k·F_r/Y, k = 0.5 ([SKF6000], [NTN] A-26; NSK uses 0.6),
  Y the catalogue factor for F_a/F_r > e;
* angular contact ball bearings: F_i = R·F_r, R by the contact angle: 0.50 (20°), 0.57
  (25°), 0.66 (30°), 0.88 (40°) (SKF rolling bearings catalogue, table 11 of the angular
  contact section; 0.88 = 0.5/0.57, the ISO 281 single-row Y at 40°).

The external axial load K_a on the shaft is carried by one bearing, B below (the pair is
relabelled when it points the other way).  Equilibrium with each bearing carrying at least
its own induced force gives the cases 1a–1c/2a–2c of the catalogue tables in one rule:

    F_aB = max(F_iB, F_iA + K_a),   F_aA = max(F_iA, F_iB − K_a).

Example (NSK example 5: Fr1 = 1 569 N, Y1 = 0.73; Fr2 = 3 931 N, Y2 = 1.60, K_a = 2 000 N
on bearing 1, k = 0.6):

>>> f = solve(induced_tapered(3931.0, 1.60, 0.6), induced_tapered(1569.0, 0.73, 0.6), 2000.0)
>>> round(f.F_aB)
3474
"""

from __future__ import annotations

from geardesign.core.records import dataclass

K_TAPERED = 0.5
R_ANGULAR = ((20.0, 0.50), (25.0, 0.57), (30.0, 0.66), (40.0, 0.88))


def induced_tapered(F_r: float, Y: float, k: float = K_TAPERED) -> float:
    """Induced axial force of a tapered roller bearing, F_i = k·F_r/Y [N]."""
    return k * F_r / Y


def r_angular(alpha_deg: float) -> float:
    """R of F_i = R·F_r for an angular contact ball bearing with contact angle α [deg]
    (linear between the tabulated angles, the end values beyond them)."""
    pts = R_ANGULAR
    if alpha_deg <= pts[0][0]:
        return pts[0][1]
    for (a0, r0), (a1, r1) in zip(pts, pts[1:]):
        if alpha_deg <= a1:
            return r0 + (r1 - r0) * (alpha_deg - a0) / (a1 - a0)
    return pts[-1][1]


def induced_angular(F_r: float, alpha_deg: float, R: float | None = None) -> float:
    """Induced axial force of an angular contact ball bearing, F_i = R·F_r [N]."""
    return (r_angular(alpha_deg) if R is None else R) * F_r


@dataclass(frozen=True)
class PairLoads:
    F_iA: float          # induced force of A, N
    F_iB: float          # induced force of B (the bearing that carries K_a), N
    K_a: float           # external axial load, N (>= 0)
    F_aA: float
    F_aB: float


def solve(F_iA: float, F_iB: float, K_a: float) -> PairLoads:
    """Axial loads of bearings A and B when the external axial load K_a >= 0 is carried by
    B (see the module docstring)."""
    if K_a < 0.0:
        raise ValueError("K_a must be >= 0: relabel the bearings")
    F_aB = max(F_iB, F_iA + K_a)
    F_aA = max(F_iA, F_iB - K_a)
    return PairLoads(F_iA, F_iB, K_a, F_aA, F_aB)


def carrier(arrangement: str, F_a: float) -> str:
    """Which bearing carries an external axial load F_a on the shaft that points from A
    to B (F_a > 0) or from B to A (F_a < 0): face-to-face (X) the bearing it points to,
    back-to-back (O) the other one."""
    towards = "B" if F_a >= 0.0 else "A"
    if arrangement == "face_to_face":
        return towards
    return "A" if towards == "B" else "B"


def pair_types() -> tuple[str, ...]:
    return ("angular_contact_ball", "tapered_roller")

