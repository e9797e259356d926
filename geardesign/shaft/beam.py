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
([GolubVanLoan] §4.3.5, algorithm 4.3.5), the critical speed by the Lanczos process on
L⁻¹·M·L⁻ᵀ (:func:`solve`, :func:`_largest_mu`).  A rigid support's dof keeps a unit row
and column (its deflection 0), which leaves the other pivots exactly those of the system
without it.
"""

from __future__ import annotations

import math
import operator

from geardesign.core.records import dataclass
from geardesign.shaft.tridiagonal import largest_eigenvalue

BAND = 3                     # half bandwidth of the global matrices
POWER_ITERATIONS = 500       # steps of the Lanczos process; beyond: the dense problem
POWER_TOL = 1e-14            # relative change of the eigenvalue that ends the process


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


def _stiffness_terms(EI: float, L: float) -> tuple:
    """The distinct entries of k_e (module docstring): c·12, c·6L, −c·12, c·4L², −c·6L,
    c·2L² with c = EI/L³."""
    c = EI / L ** 3
    return (c * 12.0, c * (6 * L), c * -12.0, c * (4 * L * L), c * (-6 * L), c * (2 * L * L))


def _mass_terms(m: float, L: float) -> tuple:
    """The distinct entries of m_e (module docstring): c·156, c·22L, c·54, −c·13L, c·4L²,
    c·13L, −c·3L², −c·22L with c = m/420."""
    c = m / 420.0
    return (c * 156.0, c * (22 * L), c * 54.0, c * (-13 * L), c * (4 * L * L), c * (13 * L),
            c * (-3 * L * L), c * (-22 * L))


def element_stiffness(EI: float, L: float) -> list[list[float]]:
    """Bending stiffness matrix k_e of one element [N/mm, N, N·mm] (module docstring) of
    bending stiffness ``EI`` [N·mm²] and length ``L`` [mm].

    Example: EI = 1, L = 1 gives the Euler–Bernoulli element matrix (12, 6L, 4L², 2L²):

    >>> element_stiffness(1.0, 1.0)[:2]
    [[12.0, 6.0, -12.0, 6.0], [6.0, 4.0, -6.0, 2.0]]
    """
    s12, s6, m12, s4, m6, s2 = _stiffness_terms(EI, L)
    return [[s12, s6, m12, s6], [s6, s4, m6, s2], [m12, m6, s12, m6], [s6, s2, m6, s4]]


def element_mass(m: float, L: float) -> list[list[float]]:
    """Consistent mass matrix m_e of one element of mass ``m`` [kg] and length ``L`` [mm]
    (module docstring)."""
    a156, a22, a54, m13, a4, a13, m3, m22 = _mass_terms(m, L)
    return [[a156, a22, a54, m13], [a22, a4, a13, m3], [a54, a13, a156, m22],
            [m13, m3, m22, a4]]


_NO_ELEMENT = (0.0,) * 8


def _assemble(x, EI, mass=None):
    """:func:`assemble` and each element's :func:`_stiffness_terms`.  An entry of the
    upper band takes at most two contributions: node j's rows from the elements j−1 (the
    entries of its second node) and j (of its first)."""
    n = len(x)
    L = [x[e + 1] - x[e] for e in range(n - 1)]
    ks = [_stiffness_terms(EI[e], L[e]) for e in range(n - 1)]
    K = []
    left = _NO_ELEMENT
    for right in ks + [_NO_ELEMENT]:
        s12, s6, m12, s4, m6, s2 = right[:6]
        K.append([left[0] + s12, left[4] + s6, m12, s6])       # k_22 + k_00, k_23 + k_01
        K.append([left[3] + s4, m6, s2, 0.0])                   # k_33 + k_11
        left = right
    M = None
    if mass is not None:
        M = []
        left = _NO_ELEMENT
        for right in [_mass_terms(mass[e], L[e]) for e in range(n - 1)] + [_NO_ELEMENT]:
            a156, a22, a54, m13, a4, a13, m3, m22 = right
            M.append([left[0] + a156, left[7] + a22, a54, m13])
            M.append([left[4] + a4, a13, m3, 0.0])
            left = right
    return K, M, ks


def assemble(x, EI, mass=None):
    """Global stiffness (and mass) matrices, as upper bands (row i: entries (i, i) …
    (i, i+3); element e occupies the dofs 2e … 2e+3), of the chain of elements between the
    nodes ``x``; ``EI[e]`` and ``mass[e]`` belong to element e = (x[e], x[e+1])."""
    return _assemble(x, EI, mass)[:2]


def dense(B: list[list[float]]) -> list[list[float]]:
    """The full symmetric matrix of an upper band."""
    N = len(B)
    A = [[0.0] * N for _ in range(N)]
    for i, row in enumerate(B):
        for k, v in enumerate(row):
            if i + k < N:
                A[i][i + k] = A[i + k][i] = v
    return A


def cholesky(B: list[list[float]]) -> list[tuple[float, float, float, float]]:
    """Banded Cholesky factor of the symmetric positive definite matrix with upper band
    ``B``: row i of the result holds L[i][i−3 … i] ([GolubVanLoan] algorithm 4.3.5, the
    band of width 3 written out; the rows before the first count as those of the unit
    matrix, whose zeros leave every sum as it is).  Raises :class:`NotPositiveDefinite`
    for a pivot that is not positive."""
    Lo = []
    p1 = p2 = p3 = _UNIT                 # rows i-1, i-2, i-3 of the factor
    b1 = b2 = b3 = _PAD                  # rows i-1, i-2, i-3 of the band
    for i, b0 in enumerate(B):
        l0 = b3[3] / p3[3]
        l1 = (b2[2] - l0 * p2[2]) / p2[3]
        l2 = (b1[1] - l0 * p1[1] - l1 * p1[2]) / p1[3]
        s = b0[0] - l0 * l0 - l1 * l1 - l2 * l2
        if not s > 0.0:
            raise NotPositiveDefinite(i)
        row = (l0, l1, l2, math.sqrt(s))
        Lo.append(row)
        p1, p2, p3, b1, b2, b3 = row, p1, p2, b0, b1, b2
    return Lo


_PAD = (0.0,) * (BAND + 1)
_UNIT = (0.0,) * BAND + (1.0,)


def _forward(Lo, b):
    """y with L·y = b (the band of width 3 written out; the factor's rows before the first
    hold zeros)."""
    y = []
    y1 = y2 = y3 = 0.0
    for (l0, l1, l2, l3), bi in zip(Lo, b):
        y1, y2, y3 = (bi - l0 * y3 - l1 * y2 - l2 * y1) / l3, y1, y2
        y.append(y1)
    return y


def _backward(Lo, y):
    """x with Lᵀ·x = y."""
    x = [0.0] * len(y)
    x1 = x2 = x3 = 0.0                   # x[i+1], x[i+2], x[i+3]
    r1 = r2 = r3 = _PAD                  # rows i+1, i+2, i+3 of the factor
    for i in range(len(y) - 1, -1, -1):
        r0 = Lo[i]
        x0 = (y[i] - r1[2] * x1 - r2[1] * x2 - r3[0] * x3) / r0[3]
        x[i] = x0
        x1, x2, x3, r1, r2, r3 = x0, x1, x2, r0, r1, r2
    return x


def _rows(B):
    """The rows of the symmetric matrix with upper band ``B``: entries (i, i−3 … i+3)."""
    Bp = [_PAD, _PAD, _PAD] + list(B)
    return [(Bp[i][3], Bp[i + 1][2], Bp[i + 2][1], r[0], r[1], r[2], r[3])
            for i, r in enumerate(B)]


def _operator(Lo, M):
    """C·q = L⁻¹·(M·(L⁻ᵀ·q)) as a function of q, from the factor ``Lo`` and the upper band
    of M: the backward substitution (:func:`_backward`), then M's product and the forward
    substitution (:func:`_forward`) in one sweep; each row's coefficients gathered once."""
    N = len(Lo)
    Lp = list(Lo) + [_PAD, _PAD, _PAD]
    back = [(Lp[i + 1][2], Lp[i + 2][1], Lp[i + 3][0], Lp[i][3]) for i in range(N)]
    back.reverse()
    sweep = [r + lo for r, lo in zip(_rows(M), Lo)]

    def apply(q):
        x = []
        x1 = x2 = x3 = 0.0
        for (a, b, c, d), yi in zip(back, reversed(q)):
            x1, x2, x3 = (yi - a * x1 - b * x2 - c * x3) / d, x1, x2
            x.append(x1)
        x.reverse()
        return forward_of_m(x)

    def forward_of_m(x):
        """L⁻¹·(M·x)."""
        x = x + [0.0, 0.0, 0.0]
        y = []
        w0 = w1 = w2 = y1 = y2 = y3 = 0.0
        w3, w4, w5 = x[0], x[1], x[2]
        for (a, b, c, d, e, f, g, l0, l1, l2, l3), w6 in zip(sweep, x[3:]):
            mv = a * w0 + b * w1 + c * w2 + d * w3 + e * w4 + f * w5 + g * w6
            y1, y2, y3 = (mv - l0 * y3 - l1 * y2 - l2 * y1) / l3, y1, y2
            y.append(y1)
            w0, w1, w2, w3, w4, w5 = w1, w2, w3, w4, w5, w6
        return y
    apply.forward_of_m = forward_of_m
    return apply


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
    C = L⁻¹·M·L⁻ᵀ by the Lanczos process (:func:`_largest_mu`, [GolubVanLoan] §10.1), which
    converges faster than the power iteration's Rayleigh quotient ((μ₂/μ₁)²ᵏ); should it
    not settle, by the dense symmetric eigenvalue problem.  K not positive definite (the
    shaft not held) raises :class:`NotPositiveDefinite`.
    """
    n = len(x)
    K0, M, ke = _assemble(x, EI, mass)
    for i, m in enumerate(point_masses):
        M[2 * i][0] += m
    K = [list(r) for r in K0]
    fixed = _supported(K, M, supports)
    Lo = cholesky(K)
    mu = _largest_mu(Lo, M)
    omega = math.sqrt(1000.0 / mu) if mu > 0 else math.inf

    Kp = [_PAD, _PAD, _PAD] + K0 + [_PAD, _PAD, _PAD]
    out = []
    for forces, couples in planes:
        F = [0.0] * (2 * n)
        F[0::2] = [float(f) for f in forces]
        F[1::2] = [float(c) for c in couples]
        b = [0.0 if g in fixed else F[g] for g in range(2 * n)]
        u = _backward(Lo, _forward(Lo, b))
        reactions = [_row_times(Kp, u, 2 * node) - F[2 * node] if k is None
                     else -k * u[2 * node] for node, k in supports]
        M_left, M_right, V_right = [0.0] * n, [0.0] * n, [0.0] * n
        w, th = u[0::2], u[1::2]
        for e, (s12, s6, m12, s4, m6, s2) in enumerate(ke):    # f = k_e·u_e, rows 0, 1, 3
            u0, u1, u2, u3 = w[e], th[e], w[e + 1], th[e + 1]
            V_right[e] = s12 * u0 + s6 * u1 + m12 * u2 + s6 * u3
            M_right[e] = -(s6 * u0 + s4 * u1 + m6 * u2 + s2 * u3)
            M_left[e + 1] = s6 * u0 + s2 * u1 + m6 * u2 + s4 * u3
        out.append(PlaneSolution(w, th, M_left, M_right, V_right, reactions))
    return out, omega


def _row_times(Bp, u, i: int) -> float:
    """Row i of the symmetric matrix whose upper band, padded with three zero rows on each
    side, is ``Bp``, times ``u``: Σ_k A[i][i+k]·u[i+k], k = −3 … 3 in order."""
    a, b, c = Bp[i][3], Bp[i + 1][2], Bp[i + 2][1]
    d, e, f, g = Bp[i + 3]
    w = [0.0, 0.0, 0.0] + list(u) + [0.0, 0.0, 0.0]
    return (a * w[i] + b * w[i + 1] + c * w[i + 2] + d * w[i + 3] + e * w[i + 4]
            + f * w[i + 5] + g * w[i + 6])


def _largest_mu(Lo, M) -> float:
    """Largest eigenvalue of C = L⁻¹·M·L⁻ᵀ (the largest μ of M·φ = μ·K·φ, :func:`solve`)
    by the symmetric Lanczos process ([GolubVanLoan] §10.1): from the unit vector q₁, the
    orthonormal q₂, q₃, … of the Krylov space with α_k = q_kᵀCq_k, β_k = ‖Cq_k − α_k q_k −
    β_{k−1} q_{k−1}‖ span it, and the largest eigenvalue θ_k of the tridiagonal T_k
    (diagonal α, off-diagonal β: :func:`~geardesign.shaft.tridiagonal.largest_eigenvalue`)
    rises to μ from below,
    faster than the Rayleigh quotient of the power iteration (a few steps where that takes
    ten or more); it ends when θ_k changes by less than ``POWER_TOL`` relative, or when
    the changes, falling at least by half a step, leave less than that to come.  The start
    is the static deflection under the masses' weight, φ₀ = K⁻¹·M·1 (Rayleigh's shape),
    q₁ ∝ Lᵀφ₀ = L⁻¹·M·1.  Should the process break down before that (an invariant
    subspace) or not settle, the dense symmetric problem."""
    mul = operator.mul
    apply = _operator(Lo, M)
    q = apply.forward_of_m([1.0, 0.0] * (len(Lo) // 2))
    norm = math.sqrt(math.fsum(map(mul, q, q)))
    alpha: list[float] = []
    beta: list[float] = []
    if norm > 0:
        q_old, b_old, theta_old, change_old = None, 0.0, 0.0, math.inf
        q = [v / norm for v in q]
        for _ in range(min(POWER_ITERATIONS, len(Lo))):
            w = apply(q)
            a = math.fsum(map(mul, q, w))
            if q_old is None:
                w = [wi - a * qi for wi, qi in zip(w, q)]
            else:
                w = [wi - a * qi - b_old * pi for wi, qi, pi in zip(w, q, q_old)]
            alpha.append(a)
            theta = largest_eigenvalue(alpha, beta, theta_old)
            change = abs(theta - theta_old) if len(alpha) > 1 else math.inf
            if change <= POWER_TOL * abs(theta):
                return theta
            # the changes fall faster than geometrically: once they halve at least, the
            # rest sums to below change·r/(1 − r) <= 2·change·r, r the last ratio
            r = change / change_old if len(alpha) > 2 else math.inf
            if r <= 0.5 and 2.0 * change * r <= POWER_TOL * abs(theta):
                return theta
            change_old = change
            b = math.sqrt(math.fsum(map(mul, w, w)))
            if not b > POWER_TOL * abs(theta):
                break                   # an invariant subspace: the dense problem decides
            beta.append(b)
            q_old, q, b_old, theta_old = q, [v / b for v in w], b, theta
    import numpy as np

    Ld = np.zeros((len(Lo), len(Lo)))
    for i, row in enumerate(Lo):
        for k, v in enumerate(row):
            if i - BAND + k >= 0:
                Ld[i, i - BAND + k] = v
    Cd = np.linalg.solve(Ld, np.linalg.solve(Ld, np.array(dense(M))).T)
    return float(np.linalg.eigvalsh(0.5 * (Cd + Cd.T))[-1])
