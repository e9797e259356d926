"""ISO 6336-1 K_v method B against an independent public implementation.

Source: G. F. de Souza Rebouças, Drivetrain, GitHub ``gfsReboucas/Drivetrain`` at commit
4a88df348fc70d04254c84bd375bb2bab0d15d0d, file ``ISO_6336.m``, method
``dynamic_factor_from_range`` (Table 8 constants C_v1…C_v7, B_p, B_f, B_k, N_S from the
line load, eqs. (13)–(22) of [ISO6336-1]), evaluated at the inputs below in double
precision.  The printed K_v of the worked examples (ISO/TR 6336-30 example 1: 1.003;
KISSsoft NREL: 1.02, 1.06) are far below resonance and rounded: a 1 % error in a Table 8
constant moves them by less than their last digit.  These points cover the four speed
ranges (subcritical, main resonance, intermediate, supercritical), both sides of
ε_γ = 2 and of 1.5/2.5 (C_v7), both sides of K_A F_t/b = 100 N/mm (N_S) and N = N_S.
Tolerance 1e-12 relative.
"""

import pytest

from geardesign.spur.strength.iso6336 import part1 as P1

# (N, c' [N/(mm·µm)], f_pb,eff [µm], f_fα,eff [µm], C_a [µm], K_A F_t/b [N/mm], ε_γ, K_v)
CASES = [
    (0.4, 14.0, 9.5, 7.0, 20.0, 60.0, 1.4, 1.8432000000000004),
    (0.4, 14.0, 9.5, 7.0, 10.0, 320.0, 1.4, 1.1466),
    (1.0, 14.0, 9.5, 7.0, 20.0, 60.0, 1.4, 5.5646666666666675),
    (1.0, 14.0, 9.5, 7.0, 10.0, 320.0, 1.4, 1.743375),
    (1.3, 14.0, 9.5, 7.0, 20.0, 60.0, 1.4, 4.276738095238096),
    (1.3, 14.0, 9.5, 7.0, 10.0, 320.0, 1.4, 1.463049107142857),
    (2.0, 14.0, 9.5, 7.0, 20.0, 60.0, 1.4, 2.5595),
    (2.0, 14.0, 9.5, 7.0, 10.0, 320.0, 1.4, 1.08928125),
    (0.4, 14.0, 9.5, 7.0, 20.0, 60.0, 1.8, 1.8432000000000004),
    (0.4, 14.0, 9.5, 7.0, 10.0, 320.0, 1.8, 1.1466),
    (1.0, 14.0, 9.5, 7.0, 20.0, 60.0, 1.8, 5.5646666666666675),
    (1.0, 14.0, 9.5, 7.0, 10.0, 320.0, 1.8, 1.743375),
    (1.3, 14.0, 9.5, 7.0, 20.0, 60.0, 1.8, 4.298821028150998),
    (1.3, 14.0, 9.5, 7.0, 10.0, 320.0, 1.8, 1.4851320400557602),
    (2.0, 14.0, 9.5, 7.0, 20.0, 60.0, 1.8, 2.6110268434634407),
    (2.0, 14.0, 9.5, 7.0, 10.0, 320.0, 1.8, 1.1408080934634408),
    (0.4, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 1.6602036036036036),
    (0.4, 14.0, 9.5, 7.0, 10.0, 320.0, 2.3, 1.1173016891891892),
    (1.0, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 4.114755813953488),
    (1.0, 14.0, 9.5, 7.0, 10.0, 320.0, 2.3, 1.5178829941860466),
    (1.3, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 3.3661292326720798),
    (1.3, 14.0, 9.5, 7.0, 10.0, 320.0, 2.3, 1.3975456570906846),
    (2.0, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 2.367960457630202),
    (2.0, 14.0, 9.5, 7.0, 10.0, 320.0, 2.3, 1.2370958742968685),
    (0.4, 14.0, 9.5, 7.0, 20.0, 60.0, 2.8, 1.5462417204301075),
    (0.4, 14.0, 9.5, 7.0, 10.0, 320.0, 2.8, 1.0985493548387097),
    (1.0, 14.0, 9.5, 7.0, 20.0, 60.0, 2.8, 3.241047058823529),
    (1.0, 14.0, 9.5, 7.0, 10.0, 320.0, 2.8, 1.3806742647058825),
    (1.3, 14.0, 9.5, 7.0, 20.0, 60.0, 2.8, 2.806343602346599),
    (1.3, 14.0, 9.5, 7.0, 10.0, 320.0, 2.8, 1.316105391826542),
    (2.0, 14.0, 9.5, 7.0, 20.0, 60.0, 2.8, 2.2267389937106916),
    (2.0, 14.0, 9.5, 7.0, 10.0, 320.0, 2.8, 1.2300135613207548),
    (0.85, 14.0, 9.5, 7.0, 10.0, 320.0, 2.0, 1.311525),
    (0.85, 14.0, 9.5, 7.0, 10.0, 320.0, 2.8, 1.209417379032258),
    (2.0, 14.0, 9.5, 7.0, 10.0, 320.0, 2.0, 1.21428125),
    (0.4, 14.0, 9.5, 7.0, 10.0, 320.0, 2.0, 1.1466),
    (0.77, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 2.270891936936937),
    (0.78, 14.0, 9.5, 7.0, 20.0, 60.0, 2.3, 4.114755813953488),
]


@pytest.mark.parametrize("N, c_prime, f_pb, f_f, C_a, line_load, eps_gamma, expected", CASES)
def test_k_v_method_b_of_drivetrain(N, c_prime, f_pb, f_f, C_a, line_load, eps_gamma, expected):
    N_S = P1.lower_resonance_limit(line_load)
    K, _ = P1.dynamic_factor(N, N_S, c_prime, f_pb, f_f, C_a, line_load, eps_gamma)
    assert float(K) == pytest.approx(expected, rel=1e-12)


def test_resonance_ranges_named_at_their_limits():
    """[ISO6336-1] 6.5.3: subcritical up to N_S, main resonance to 1.15, intermediate below
    1.5, supercritical from 1.5 (N_S = 0.85 at K_A F_t/b >= 100 N/mm)."""
    names = [P1.dynamic_factor(N, 0.85, 14.0, 9.5, 7.0, 10.0, 320.0, 2.3)[1]
             for N in (0.85, 0.86, 1.15, 1.16, 1.49, 1.5)]
    assert [str(n) for n in names] == ["subcritical", "main resonance", "main resonance",
                                       "intermediate", "intermediate", "supercritical"]
