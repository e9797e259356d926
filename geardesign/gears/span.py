"""Span (base tangent length) of a spur or helical involute gear, external or internal
(GOST 16532-70, DIN 3960:1987 §3.6): the number of teeth spanned, W and the diameter on
which the calliper touches the flanks.

Pure functions on plain numbers.  Lengths in mm, angles in radians.
"""

from __future__ import annotations

import math

from geardesign.involute import inv


def span_teeth_ideal(z: int, x: float, m_n: float, alpha_n: float, alpha_t: float,
                     beta_b: float, d: float, d_b: float) -> float:
    """Real-valued number of teeth spanned for which the calliper touches the flanks on the
    circle d + 2x·m_n (mid-height of the tooth):

    .. math::
        k_{id} = \\frac{z}{π}\\Big[\\frac{\\tan α_x}{\\cos^2 β_b}
            - \\frac{2x\\tan α}{z} - \\operatorname{inv} α_t\\Big] + 0.5,
        \\qquad \\cos α_x = \\frac{d_b}{d + 2 x m_n}

    References: GOST 16532-70 (base tangent length); DIN 3960:1987 §3.6.  The cos²β_b
    follows because the calliper faces are normal to the base helix: the contact point
    rolls W·cos β_b/2 from the tangency line (KISSsoft agrees, ``tests/reference``;
    the ZPCIL program, uses cos β_b).

    Example: for an unshifted spur gear α_x = α and the formula reduces to z·α/π + 0.5, the
    handbook rule k = z/9 + 0.5 for α = 20° (exact, since 20° = π/9): z = 18 gives 2.5.

    >>> import math
    >>> a = math.radians(20.0)
    >>> round(span_teeth_ideal(18, 0.0, 1.0, a, a, 0.0, 18.0, 18.0 * math.cos(a)), 9)
    2.5
    """
    cos_ax = d_b / (d + 2.0 * x * m_n)
    if cos_ax >= 1.0:
        return 1.0
    tan_ax = math.tan(math.acos(cos_ax))
    return z / math.pi * (tan_ax / math.cos(beta_b) ** 2 - 2.0 * x * math.tan(alpha_n) / z
                          - inv(alpha_t)) + 0.5


def base_tangent_length(z: int, x: float, m_n: float, alpha_n: float, alpha_t: float,
                        beta_b: float, d: float, d_b: float, k: int) -> tuple[int, float, float]:
    """Base tangent length (span) W over k teeth, in the normal section, and the diameter
    d_W on which the calliper touches the flanks.

    .. math::
        W = m_n \\cos α \\,[π(k - 0.5) + 2x \\tan α + z \\operatorname{inv} α_t],
        \\qquad \\tan α_W = \\frac{W \\cos^2 β_b}{z m_n \\cos α},
        \\quad d_W = \\frac{d_b}{\\cos α_W}

    Returns ``(k, W, d_W)``.

    References: GOST 16532-70 (base tangent length); ZPCIL ``GEOM.h``
    ([ZPCIL] GEOM.h); d_W as KISSsoft's d_MWk (DIN 3960).
    """
    W = m_n * math.cos(alpha_n) * (math.pi * (k - 0.5) + 2.0 * x * math.tan(alpha_n) + z * inv(alpha_t))
    tan_aw = W * math.cos(beta_b) ** 2 / (z * m_n * math.cos(alpha_n))
    return k, W, d_b * math.sqrt(1.0 + tan_aw * tan_aw)


def span_measurable(W: float, d_W: float, d_low: float, d_a: float, beta_b: float,
                    b_w: float) -> bool:
    """A span can be measured if the calliper touches the flanks between the lower point
    of the active profile (``d_low``) and the tip, and, for helical gears, the face is wider
    than W·sin β_b (both anvils on the same teeth).  GOST 16532-70; DIN 3960 §3.6."""
    ok = d_low - 1e-9 <= d_W <= d_a + 1e-9
    return ok and (beta_b == 0.0 or b_w > W * math.sin(beta_b))


def choose_span_teeth(z: int, x: float, m_n: float, alpha_n: float, alpha_t: float,
                      beta_b: float, d: float, d_b: float, d_low: float, d_a: float,
                      b_w: float) -> tuple[int, float, float]:
    """Number of teeth spanned: the integer nearest to :func:`span_teeth_ideal` (a half
    rounded down, as in the published span tables: z = 18, α = 20° gives k = 2) for which
    :func:`span_measurable` holds, trying the next nearest when it does not (a narrow
    helical gear needs a smaller k).  If none of the six nearest is measurable the nearest
    is returned and the span check of the calculator warns.  Returns ``(k, W, d_W)``."""
    k_id = span_teeth_ideal(z, x, m_n, alpha_n, alpha_t, beta_b, d, d_b)
    candidates = sorted(range(1, max(z, 2)), key=lambda k: (abs(k - k_id), k))[:6]
    for k in candidates:
        k, W, d_W = base_tangent_length(z, x, m_n, alpha_n, alpha_t, beta_b, d, d_b, k)
        if span_measurable(W, d_W, d_low, d_a, beta_b, b_w):
            return k, W, d_W
    return base_tangent_length(z, x, m_n, alpha_n, alpha_t, beta_b, d, d_b, candidates[0])
