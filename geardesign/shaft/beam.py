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
    return _element_stiffnesses(np.array([EI], dtype=float), np.array([L], dtype=float))[0]


def element_mass(m: float, L: float) -> np.ndarray:
    """Consistent mass matrix of one element of mass ``m`` [kg] and length ``L`` [mm]."""
    return _element_masses(np.array([m], dtype=float), np.array([L], dtype=float))[0]


def _element_stiffnesses(EI: np.ndarray, L: np.ndarray) -> np.ndarray:
    """The stiffness matrices k_e (module docstring) of the elements of bending stiffness
    ``EI`` [N·mm²] and length ``L`` [mm], shape (elements, 4, 4)."""
    c = EI / L ** 3
    L6, L4, L2 = 6 * L, 4 * L * L, 2 * L * L     # the products of element_stiffness
    one = np.ones_like(L)
    k = np.array([[12.0 * one, L6, -12.0 * one, L6],
                  [L6, L4, -L6, L2],
                  [-12.0 * one, -L6, 12.0 * one, -L6],
                  [L6, L2, -L6, L4]])
    return np.moveaxis(c * k, -1, 0)


def _element_masses(m: np.ndarray, L: np.ndarray) -> np.ndarray:
    """The consistent mass matrices m_e (module docstring) of the elements of mass ``m``
    [kg] and length ``L`` [mm], shape (elements, 4, 4)."""
    L4, L3 = 4 * L * L, -3 * L * L               # the products of element_mass
    one = np.ones_like(L)
    k = np.array([[156.0 * one, 22 * L, 54.0 * one, -13 * L],
                  [22 * L, L4, 13 * L, L3],
                  [54.0 * one, 13 * L, 156.0 * one, -22 * L],
                  [-13 * L, L3, -22 * L, L4]])
    return np.moveaxis(m / 420.0 * k, -1, 0)


def _scatter(ke: np.ndarray, n: int) -> np.ndarray:
    """Global matrix (2n × 2n) of the chain of element matrices ``ke`` (elements, 4, 4):
    element e occupies the dofs 2e … 2e+3.  For one (a, b) the target entries of the
    elements are distinct, and an entry takes at most two contributions, so the sums are
    those of adding the elements one by one."""
    K = np.zeros((2 * n, 2 * n))
    base = 2 * np.arange(n - 1)
    for a in range(4):
        for b in range(4):
            K[base + a, base + b] += ke[:, a, b]
    return K


def assemble(x: np.ndarray, EI: np.ndarray, mass: np.ndarray | None = None):
    """Global stiffness (and mass) matrices of the chain of elements between the nodes ``x``;
    ``EI[e]`` and ``mass[e]`` belong to element e = (x[e], x[e+1])."""
    n = len(x)
    L = np.diff(np.asarray(x, dtype=float))
    K = _scatter(_element_stiffnesses(np.asarray(EI, dtype=float), L), n)
    M = _scatter(_element_masses(np.asarray(mass, dtype=float), L), n) \
        if mass is not None else None
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


def solve(x: np.ndarray, EI: np.ndarray, mass: np.ndarray, point_masses: np.ndarray,
          planes: list[tuple[np.ndarray, np.ndarray]],
          supports: list[tuple[int, float | None]]) -> tuple[list[PlaneSolution], float]:
    """Static solutions of the planes and the lowest natural circular frequency of bending
    [rad/s], on one factorisation of the stiffness matrix.

    Parameters
    ----------
    x : node positions [mm], increasing.
    EI : bending stiffness of each element [N·mm²]; ``mass`` its mass [kg].
    point_masses : masses at the nodes [kg] (gears), on the deflection dofs.
    planes : per plane, the nodal transverse forces [N] and couples [N·mm].
    supports : (node index, radial stiffness [N/mm] or None for a rigid support).

    Statics: K·u = F on the free dofs.  The force of each support on the shaft: a rigid one
    from the residual K·u − F, a spring −k·w.  Internal forces from the element end forces
    f = k_e·u_e (module docstring).

    Frequency: the generalised eigenvalue problem K·φ = λ·M·φ with the consistent shaft mass
    and the point masses (their rotary inertia and the gyroscopic effect are neglected).
    With K in N/mm and M in kg, λ is in 10⁻³ s⁻² (N/(mm·kg) = 1000 s⁻²): ω = √(1000·λ).  It
    is solved as the largest μ = 1/λ of M·φ = μ·K·φ (well conditioned when the point masses
    outweigh the shaft by orders of magnitude): the largest eigenvalue of the symmetric
    C = L⁻¹·M·L⁻ᵀ (K = L·Lᵀ) by power iteration with the Rayleigh quotient μ = xᵀCx
    ([GolubVanLoan] §7.3, §8.2), which converges as (μ₂/μ₁)²ᵏ; should it not settle, by the
    dense symmetric eigenvalue problem.  K not positive definite (the shaft not held) raises
    ``numpy.linalg.LinAlgError``.
    """
    n = len(x)
    K, M = assemble(x, EI, mass)
    M[0::2, 0::2] += np.diag(point_masses)
    Ks = K.copy()
    free = _supported(Ks, supports)
    Kf, Mf = Ks[np.ix_(free, free)], M[np.ix_(free, free)]
    chol = np.linalg.cholesky(Kf)            # raises LinAlgError unless K is positive definite
    F = np.zeros((2 * n, len(planes)))
    for j, (forces, couples) in enumerate(planes):
        F[0::2, j] = forces
        F[1::2, j] = couples
    U = np.zeros((2 * n, len(planes)))
    U[free] = np.linalg.solve(Kf, F[free])
    L_inv = np.linalg.solve(chol, np.eye(len(free)))
    C = L_inv @ Mf @ L_inv.T
    mu = _largest_mu(0.5 * (C + C.T))
    omega = float(np.sqrt(1000.0 / mu)) if mu > 0 else float("inf")

    L = np.diff(np.asarray(x, dtype=float))
    ke = _element_stiffnesses(np.asarray(EI, dtype=float), L)
    e = np.arange(n - 1)
    dofs = 2 * e[:, None] + np.arange(4)[None, :]
    residual = K @ U - F
    out = []
    for j in range(len(planes)):
        u = U[:, j]
        reactions = np.array([residual[2 * node, j] if k is None else -k * u[2 * node]
                              for node, k in supports])
        f = np.einsum("eab,eb->ea", ke, u[dofs])
        M_left, M_right, V_right = np.zeros(n), np.zeros(n), np.zeros(n)
        M_right[:-1] = -f[:, 1]
        M_left[1:] = f[:, 3]
        V_right[:-1] = f[:, 0]
        out.append(PlaneSolution(u[0::2].copy(), u[1::2].copy(), M_left, M_right, V_right,
                                 reactions))
    return out, omega


POWER_ITERATIONS = 500       # beyond: the dense eigenvalue problem
POWER_TOL = 1e-14            # relative change of the Rayleigh quotient that ends the iteration


def _largest_mu(C: np.ndarray) -> float:
    """Largest eigenvalue of the symmetric C = L⁻¹·M·L⁻ᵀ (the largest μ of M·φ = μ·K·φ,
    :func:`solve`): power iteration with the Rayleigh quotient, else the dense problem."""
    x = C.sum(axis=1)
    mu_old = 0.0
    for _ in range(POWER_ITERATIONS):
        nx = float(np.linalg.norm(x))
        if not nx > 0:
            break
        x = x / nx
        y = C @ x
        mu = float(x @ y)
        if abs(mu - mu_old) <= POWER_TOL * abs(mu):
            return mu
        mu_old, x = mu, y
    return float(np.linalg.eigvalsh(C)[-1])
