"""Euler–Bernoulli finite-element model of a stepped shaft in one bending plane (pure
functions on lists of floats: the matrices are banded, so no dense algebra is needed).

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

The global matrices are kept as their upper band (half bandwidth 3 with the dofs ordered
w₀, θ₀, w₁, θ₁, …): the static solution by the banded Cholesky factorisation K = L·Lᵀ
([GolubVanLoan] §4.3.5, algorithm 4.3.5), the critical speed by power iteration on
L⁻¹·M·L⁻ᵀ (:func:`solve`).  A rigid support's dof keeps a unit row and column (its
deflection 0), which leaves the other pivots exactly those of the system without it.
"""

from __future__ import annotations

import math

from geardesign.core.records import dataclass

BAND = 3                     # half bandwidth of the global matrices
POWER_ITERATIONS = 500       # beyond: the dense eigenvalue problem
POWER_TOL = 1e-14            # relative change of the Rayleigh quotient that ends the iteration


class NotPositiveDefinite(ArithmeticError):
    """The stiffness matrix is not positive definite: the shaft is not held (a pivot of its
    Cholesky factorisation is not positive)."""


@dataclass(frozen=True)
class PlaneSolution:
    """Deflection and internal forces in one plane at the nodes ``x``."""

    w: list                # deflection at the nodes, mm
    theta: list            # slope at the nodes, rad
    M_left: list           # bending moment just left of each node, N·mm
    M_right: list          # just right of each node, N·mm
    V_right: list          # shear force just right of each node, N
    reactions: list        # force of each support on the shaft, N


def element_stiffness(EI: float, L: float) -> list[list[float]]:
    """Bending stiffness matrix k_e of one element [N/mm, N, N·mm] (module docstring) of
    bending stiffness ``EI`` [N·mm²] and length ``L`` [mm].

    Example: EI = 1, L = 1 gives the Euler–Bernoulli element matrix (12, 6L, 4L², 2L²):

    >>> element_stiffness(1.0, 1.0)[:2]
    [[12.0, 6.0, -12.0, 6.0], [6.0, 4.0, -6.0, 2.0]]
    """
    c = EI / L ** 3
    return [[c * 12.0, c * (6 * L), c * -12.0, c * (6 * L)],
            [c * (6 * L), c * (4 * L * L), c * (-6 * L), c * (2 * L * L)],
            [c * -12.0, c * (-6 * L), c * 12.0, c * (-6 * L)],
            [c * (6 * L), c * (2 * L * L), c * (-6 * L), c * (4 * L * L)]]


def element_mass(m: float, L: float) -> list[list[float]]:
    """Consistent mass matrix m_e of one element of mass ``m`` [kg] and length ``L`` [mm]
    (module docstring)."""
    c = m / 420.0
    return [[c * 156.0, c * (22 * L), c * 54.0, c * (-13 * L)],
            [c * (22 * L), c * (4 * L * L), c * (13 * L), c * (-3 * L * L)],
            [c * 54.0, c * (13 * L), c * 156.0, c * (-22 * L)],
            [c * (-13 * L), c * (-3 * L * L), c * (-22 * L), c * (4 * L * L)]]


def _band(mats, n: int) -> list[list[float]]:
    """Upper band (row i: entries (i, i) … (i, i+3)) of the global matrix of the chain of
    element matrices ``mats``; element e occupies the dofs 2e … 2e+3 (an entry takes at
    most two contributions)."""
    B = [[0.0] * (BAND + 1) for _ in range(2 * n)]
    for e, me in enumerate(mats):
        for a in range(4):
            row, r = B[2 * e + a], me[a]
            for b in range(a, 4):
                row[b - a] += r[b]
    return B


def assemble(x, EI, mass=None):
    """Global stiffness (and mass) matrices, as upper bands (:func:`_band`), of the chain of
    elements between the nodes ``x``; ``EI[e]`` and ``mass[e]`` belong to element
    e = (x[e], x[e+1])."""
    n = len(x)
    L = [x[e + 1] - x[e] for e in range(n - 1)]
    K = _band((element_stiffness(EI[e], L[e]) for e in range(n - 1)), n)
    M = _band((element_mass(mass[e], L[e]) for e in range(n - 1)), n) \
        if mass is not None else None
    return K, M


def dense(B: list[list[float]]) -> list[list[float]]:
    """The full symmetric matrix of an upper band."""
    N = len(B)
    A = [[0.0] * N for _ in range(N)]
    for i, row in enumerate(B):
        for k, v in enumerate(row):
            if i + k < N:
                A[i][i + k] = A[i + k][i] = v
    return A


def cholesky(B: list[list[float]]) -> list[list[float]]:
    """Banded Cholesky factor of the symmetric positive definite matrix with upper band
    ``B``: row i of the result holds L[i][i−3 … i] ([GolubVanLoan] algorithm 4.3.5).
    Raises :class:`NotPositiveDefinite` for a pivot that is not positive."""
    N = len(B)
    Lo = [[0.0] * (BAND + 1) for _ in range(N)]      # Lo[i][k] = L[i][i - BAND + k]
    for i in range(N):
        li = Lo[i]
        for j in range(max(0, i - BAND), i + 1):
            s = B[j][i - j]
            lj = Lo[j]
            for k in range(max(0, i - BAND), j):
                s -= li[k - i + BAND] * lj[k - j + BAND]
            if j == i:
                if not s > 0.0:
                    raise NotPositiveDefinite(i)
                li[BAND] = math.sqrt(s)
            else:
                li[j - i + BAND] = s / lj[BAND]
    return Lo


_PAD = [0.0] * (BAND + 1)


def _forward(Lo, b):
    """y with L·y = b (the band of width 3 written out; the factor's rows before the first
    hold zeros)."""
    y = [0.0, 0.0, 0.0] + list(b)
    for i, (l0, l1, l2, l3) in enumerate(Lo, 3):
        y[i] = (y[i] - l0 * y[i - 3] - l1 * y[i - 2] - l2 * y[i - 1]) / l3
    return y[3:]


def _backward(Lo, y):
    """x with Lᵀ·x = y."""
    N = len(y)
    x = list(y) + [0.0, 0.0, 0.0]
    L = list(Lo) + [_PAD, _PAD, _PAD]
    for i in range(N - 1, -1, -1):
        x[i] = (x[i] - L[i + 1][2] * x[i + 1] - L[i + 2][1] * x[i + 2]
                - L[i + 3][0] * x[i + 3]) / L[i][3]
    return x[:N]


def _rows(B):
    """The rows of the symmetric matrix with upper band ``B``: entries (i, i−3 … i+3)."""
    Bp = [_PAD, _PAD, _PAD] + list(B)
    return [(Bp[i][3], Bp[i + 1][2], Bp[i + 2][1], r[0], r[1], r[2], r[3])
            for i, r in enumerate(B)]


def _matvec(rows, v):
    """A·v with the rows of :func:`_rows`."""
    w = [0.0, 0.0, 0.0] + list(v) + [0.0, 0.0, 0.0]
    return [a * w[i] + b * w[i + 1] + c * w[i + 2] + d * w[i + 3] + e * w[i + 4]
            + f * w[i + 5] + g * w[i + 6] for i, (a, b, c, d, e, f, g) in enumerate(rows)]


def _supported(K, M, supports: list[tuple[int, float | None]]) -> set[int]:
    """Add the springs of the elastic supports to ``K`` (in place); a rigid support fixes
    its node's deflection: its row and column become those of the unit matrix in ``K`` and
    zero in ``M``.  Returns the fixed dofs."""
    fixed = set()
    for node, k in supports:
        if k is None:
            fixed.add(2 * node)
        else:
            K[2 * node][0] += k
    for g in fixed:
        for A, diag in ((K, 1.0), (M, 0.0)):
            if A is None:
                continue
            A[g][:] = [diag] + [0.0] * BAND
            for k in range(1, BAND + 1):
                if g - k >= 0:
                    A[g - k][k] = 0.0
    return fixed


def solve(x, EI, mass, point_masses, planes, supports: list[tuple[int, float | None]]
          ) -> tuple[list[PlaneSolution], float]:
    """Static solutions of the planes and the lowest natural circular frequency of bending
    [rad/s], on one factorisation of the stiffness matrix.

    Parameters
    ----------
    x : node positions [mm], increasing.
    EI : bending stiffness of each element [N·mm²]; ``mass`` its mass [kg].
    point_masses : masses at the nodes [kg] (gears), on the deflection dofs.
    planes : per plane, the nodal transverse forces [N] and couples [N·mm].
    supports : (node index, radial stiffness [N/mm] or None for a rigid support).

    Statics: K·u = F with K = L·Lᵀ.  The force of each support on the shaft: a rigid one
    from the residual K·u − F, a spring −k·w.  Internal forces from the element end forces
    f = k_e·u_e (module docstring).

    Frequency: the generalised eigenvalue problem K·φ = λ·M·φ with the consistent shaft mass
    and the point masses (their rotary inertia and the gyroscopic effect are neglected).
    With K in N/mm and M in kg, λ is in 10⁻³ s⁻² (N/(mm·kg) = 1000 s⁻²): ω = √(1000·λ).  It
    is solved as the largest μ = 1/λ of M·φ = μ·K·φ (well conditioned when the point masses
    outweigh the shaft by orders of magnitude): the largest eigenvalue of the symmetric
    C = L⁻¹·M·L⁻ᵀ by power iteration with the Rayleigh quotient μ = xᵀCx ([GolubVanLoan]
    §7.3, §8.2), which converges as (μ₂/μ₁)²ᵏ; should it not settle, by the dense symmetric
    eigenvalue problem.  K not positive definite (the shaft not held) raises
    :class:`NotPositiveDefinite`.
    """
    n = len(x)
    K0, M = assemble(x, EI, mass)
    for i, m in enumerate(point_masses):
        M[2 * i][0] += m
    K = [list(r) for r in K0]
    fixed = _supported(K, M, supports)
    Lo = cholesky(K)
    mu = _largest_mu(Lo, M)
    omega = math.sqrt(1000.0 / mu) if mu > 0 else math.inf

    L = [x[e + 1] - x[e] for e in range(n - 1)]
    ke = [element_stiffness(EI[e], L[e]) for e in range(n - 1)]
    K0_rows = _rows(K0)
    out = []
    for forces, couples in planes:
        F = [0.0] * (2 * n)
        F[0::2] = [float(f) for f in forces]
        F[1::2] = [float(c) for c in couples]
        b = [0.0 if g in fixed else F[g] for g in range(2 * n)]
        u = _backward(Lo, _forward(Lo, b))
        Ku = _matvec(K0_rows, u)
        reactions = [Ku[2 * node] - F[2 * node] if k is None else -k * u[2 * node]
                     for node, k in supports]
        M_left, M_right, V_right = [0.0] * n, [0.0] * n, [0.0] * n
        for e in range(n - 1):
            ue, k = u[2 * e:2 * e + 4], ke[e]
            f0, f1, f3 = (k[0][0] * ue[0] + k[0][1] * ue[1] + k[0][2] * ue[2] + k[0][3] * ue[3],
                          k[1][0] * ue[0] + k[1][1] * ue[1] + k[1][2] * ue[2] + k[1][3] * ue[3],
                          k[3][0] * ue[0] + k[3][1] * ue[1] + k[3][2] * ue[2] + k[3][3] * ue[3])
            M_right[e] = -f1
            M_left[e + 1] = f3
            V_right[e] = f0
        out.append(PlaneSolution(u[0::2], u[1::2], M_left, M_right, V_right, reactions))
    return out, omega


def _largest_mu(Lo, M) -> float:
    """Largest eigenvalue of C = L⁻¹·M·L⁻ᵀ (the largest μ of M·φ = μ·K·φ, :func:`solve`):
    power iteration with the Rayleigh quotient, else the dense problem."""
    rows = _rows(M)

    def C(v):
        return _forward(Lo, _matvec(rows, _backward(Lo, v)))

    x = C([1.0] * len(Lo))
    mu_old = 0.0
    for _ in range(POWER_ITERATIONS):
        nx = math.sqrt(math.fsum(v * v for v in x))
        if not nx > 0:
            break
        x = [v / nx for v in x]
        y = C(x)
        mu = math.fsum(a * b for a, b in zip(x, y))
        if abs(mu - mu_old) <= POWER_TOL * abs(mu):
            return mu
        mu_old, x = mu, y
    import numpy as np

    Ld = np.zeros((len(Lo), len(Lo)))
    for i, row in enumerate(Lo):
        for k, v in enumerate(row):
            if i - BAND + k >= 0:
                Ld[i, i - BAND + k] = v
    Cd = np.linalg.solve(Ld, np.linalg.solve(Ld, np.array(dense(M))).T)
    return float(np.linalg.eigvalsh(0.5 * (Cd + Cd.T))[-1])
