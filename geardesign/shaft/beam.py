"""Euler–Bernoulli finite-element model of a stepped shaft in one bending plane (pure
functions on numpy arrays).

Units: lengths mm, forces N, moments N·mm, E MPa (N/mm²), masses kg.  Two degrees of freedom
per node, the deflection w [mm] and the slope θ = dw/dx [rad].  The element is the cubic
Hermite beam element ([Przemieniecki] ch. 5; [Timoshenko]):

.. math::
    k_e = \\frac{EI}{L^3}\\begin{bmatrix}12 & 6L & -12 & 6L\\\\ 6L & 4L^2 & -6L & 2L^2\\\\
          -12 & -6L & 12 & -6L\\\\ 6L & 2L^2 & -6L & 4L^2\\end{bmatrix},\\qquad
    m_e = \\frac{ρAL}{420}\\begin{bmatrix}156 & 22L & 54 & -13L\\\\ 22L & 4L^2 & 13L & -3L^2\\\\
          54 & 13L & 156 & -22L\\\\ -13L & -3L^2 & -22L & 4L^2\\end{bmatrix}

Point forces and couples act at nodes only, so the nodal deflections and slopes are exact
(the element interpolates the exact cubic between loads).  Rigid supports fix w; elastic
supports add their radial stiffness to the w diagonal.  The internal bending moment and the
shear force follow from the element end forces f = k_e·u_e: M(x1) = −f_2, M(x2) = f_4,
V = f_1 (sagging moment positive).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PlaneSolution:
    """Deflection and internal forces in one plane at the nodes ``x``."""

    w: np.ndarray          # deflection at the nodes, mm
    theta: np.ndarray      # slope at the nodes, rad
    M_left: np.ndarray     # bending moment just left of each node, N·mm
    M_right: np.ndarray    # just right of each node, N·mm
    V_right: np.ndarray    # shear force just right of each node, N
    reactions: np.ndarray  # force of each support on the shaft, N


def element_stiffness(EI: float, L: float) -> np.ndarray:
    """Bending stiffness matrix of one element [N/mm, N, N·mm] (module docstring)."""
    c = EI / L ** 3
    return c * np.array([[12.0, 6 * L, -12.0, 6 * L],
                         [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                         [-12.0, -6 * L, 12.0, -6 * L],
                         [6 * L, 2 * L * L, -6 * L, 4 * L * L]])


def element_mass(m: float, L: float) -> np.ndarray:
    """Consistent mass matrix of one element of mass ``m`` [kg] and length ``L`` [mm]."""
    return m / 420.0 * np.array([[156.0, 22 * L, 54.0, -13 * L],
                                 [22 * L, 4 * L * L, 13 * L, -3 * L * L],
                                 [54.0, 13 * L, 156.0, -22 * L],
                                 [-13 * L, -3 * L * L, -22 * L, 4 * L * L]])


def assemble(x: np.ndarray, EI: np.ndarray, mass: np.ndarray | None = None):
    """Global stiffness (and mass) matrices of the chain of elements between the nodes ``x``;
    ``EI[e]`` and ``mass[e]`` belong to element e = (x[e], x[e+1])."""
    n = len(x)
    K = np.zeros((2 * n, 2 * n))
    M = np.zeros((2 * n, 2 * n)) if mass is not None else None
    for e in range(n - 1):
        L = x[e + 1] - x[e]
        s = slice(2 * e, 2 * e + 4)
        K[s, s] += element_stiffness(EI[e], L)
        if M is not None:
            M[s, s] += element_mass(mass[e], L)
    return K, M


def _supported(K: np.ndarray, supports: list[tuple[int, float | None]]) -> np.ndarray:
    """Add the springs of the elastic supports to ``K`` (in place) and return the free
    degrees of freedom (a rigid support fixes its node's deflection)."""
    fixed = set()
    for node, k in supports:
        if k is None:
            fixed.add(2 * node)
        else:
            K[2 * node, 2 * node] += k
    return np.array([i for i in range(K.shape[0]) if i not in fixed])


def solve_plane(x: np.ndarray, EI: np.ndarray, forces: np.ndarray, couples: np.ndarray,
                supports: list[tuple[int, float | None]]) -> PlaneSolution:
    """Static solution in one plane.

    Parameters
    ----------
    x : node positions [mm], increasing.
    EI : bending stiffness of each element [N·mm²].
    forces, couples : nodal transverse forces [N] and couples [N·mm].
    supports : (node index, radial stiffness [N/mm] or None for a rigid support).
    """
    n = len(x)
    K, _ = assemble(x, EI)
    F = np.zeros(2 * n)
    F[0::2] = forces
    F[1::2] = couples
    Ks = K.copy()
    free = _supported(Ks, supports)
    u = np.zeros(2 * n)
    u[free] = np.linalg.solve(Ks[np.ix_(free, free)], F[free])
    # force of each support on the shaft: rigid from the residual, springs from -k·w
    residual = K @ u - F
    reactions = np.array([residual[2 * node] if k is None else -k * u[2 * node]
                          for node, k in supports])
    M_left = np.zeros(n)
    M_right = np.zeros(n)
    V_right = np.zeros(n)
    for e in range(n - 1):
        f = element_stiffness(EI[e], x[e + 1] - x[e]) @ u[2 * e:2 * e + 4]
        M_right[e] = -f[1]
        M_left[e + 1] = f[3]
        V_right[e] = f[0]
    return PlaneSolution(u[0::2], u[1::2], M_left, M_right, V_right, reactions)


def first_bending_frequency(x: np.ndarray, EI: np.ndarray, mass: np.ndarray,
                            point_masses: np.ndarray,
                            supports: list[tuple[int, float | None]]) -> float:
    """Lowest natural circular frequency of bending [rad/s]: the generalised eigenvalue
    problem K·φ = λ·M·φ with the consistent shaft mass and the point masses (gears) on the
    deflection dofs (their rotary inertia and the gyroscopic effect are neglected).

    With K in N/mm and M in kg, λ is in 10⁻³ s⁻² (N/(mm·kg) = 1000 s⁻²): ω = √(1000·λ).
    It is solved as the largest μ = 1/λ of M·φ = μ·K·φ, which stays well conditioned when
    the point masses outweigh the shaft by orders of magnitude.
    """
    K, M = assemble(x, EI, mass)
    M[0::2, 0::2] += np.diag(point_masses)
    free = _supported(K, supports)
    # largest μ of M·φ = μ·K·φ (K positive definite, M may be nearly singular) = 1/λ_min:
    # with K = L·Lᵀ it is the largest eigenvalue of the symmetric L⁻¹·M·L⁻ᵀ (numpy only)
    Kf, Mf = K[np.ix_(free, free)], M[np.ix_(free, free)]
    L = np.linalg.cholesky(Kf)
    C = np.linalg.solve(L, np.linalg.solve(L, Mf).T)
    mu = float(np.linalg.eigvalsh(0.5 * (C + C.T))[-1])
    return float(np.sqrt(1000.0 / mu)) if mu > 0 else float("inf")
