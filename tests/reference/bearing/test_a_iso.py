"""a_ISO (ISO 281:2007, systems approach) and ν1.

No manufacturer's worked example or printed calculator output with a_ISO was found (searched:
"modified rating life example", SKF/Schaeffler/NSK/NTN catalogue examples, MESYS manual
pages; SKF prints a_SKF only, as a diagram).  The standard's own a_ISO diagrams were not
available either.  What is tested here against published text:

* the constants and ν1 as transcribed from ISO 281:2007 equations (28)–(36) by a public
  solver ([BBContact]; [Dessia]);
* properties the standard states: a_ISO <= 50; κ limited to 0.1 … 4; a_ISO -> 0.1 as
  e_C·C_u/P -> 0 (SKF ConCentra manual: "as the value of ηc(Pu/P) tends to zero, a_SKF tends
  to 0.1 for all values of κ"; the ISO curves share the shape);
* the choice c3 = 0.19087 for 0.4 <= κ < 1 (ball): continuity at κ = 0.4.

A synthetic a_ISO table (our own recomputation) is regression only
(``tests/regression/test_bearing_method_note.py``).
"""

import pytest

from geardesign.bearing import a_iso as AI
from tests.conftest import assert_ref


def test_nu1_branches():
    # ν1 = 45000·n^−0.83·D_pw^−0.5 (n < 1000), 4500·n^−0.5·D_pw^−0.5 (n >= 1000)
    assert_ref(AI.nu1(500.0, 60.0), 45000 * 500 ** -0.83 * 60 ** -0.5, 1e-12, "ν1 n < 1000")
    assert_ref(AI.nu1(1000.0, 60.0), 4500 * 1000 ** -0.5 * 60 ** -0.5, 1e-12, "ν1 n >= 1000")


@pytest.mark.parametrize("kind", ["deep_groove_ball", "cylindrical_roller"])
@pytest.mark.parametrize("kappa", [0.1, 0.5, 1.0, 4.0])
def test_tends_to_0_1_without_fatigue_limit(kind, kappa):
    assert_ref(AI.a_iso(kind, kappa, 1.0, 1e-9, 1000.0).value, 0.1, 1e-3, "a_ISO as r -> 0")


@pytest.mark.parametrize("kind", ["deep_groove_ball", "cylindrical_roller"])
def test_lower_bound_at_kappa_0_1(kind):
    # at κ = 0.1 the bracket constant vanishes: a_ISO = 0.1 whatever e_C·C_u/P
    for r in (0.01, 0.1, 1.0):
        assert_ref(AI.a_iso(kind, 0.1, 1.0, r * 1000.0, 1000.0).value, 0.1, 2e-3, "κ = 0.1")


def test_cap_50_and_kappa_range():
    a = AI.a_iso("deep_groove_ball", 2.0, 1.0, 2000.0, 1000.0)
    assert a.value == 50.0 and a.capped
    low = AI.a_iso("deep_groove_ball", 0.05, 1.0, 100.0, 1000.0)
    assert low.kappa_clamped == "low" and low.kappa_used == 0.1
    high = AI.a_iso("deep_groove_ball", 9.0, 1.0, 100.0, 1000.0)
    assert high.kappa_clamped == "high" and high.value == AI.a_iso(
        "deep_groove_ball", 4.0, 1.0, 100.0, 1000.0).value


@pytest.mark.parametrize("kind", ["deep_groove_ball", "cylindrical_roller"])
@pytest.mark.parametrize("kappa_edge", [0.4, 1.0])
def test_continuity_at_band_edges(kind, kappa_edge):
    # With c3 = 0.19087 a_ISO is continuous at κ = 0.4 and 1 (0.019087 would jump ×4 … ×35).
    for r in (0.05, 0.2, 0.5):
        below = AI.a_iso(kind, kappa_edge - 1e-9, 1.0, r * 1000.0, 1000.0).value
        above = AI.a_iso(kind, kappa_edge, 1.0, r * 1000.0, 1000.0).value
        assert abs(below / above - 1.0) < 2e-3, (kind, kappa_edge, r, below, above)


def test_printed_exponent_would_jump():
    # documents the rejected reading 0.019087: the ball bracket constant at κ = 0.4
    assert abs(2.2649 / 0.4 ** 0.054381 - 1.9987 / 0.4 ** 0.19087) < 2e-4
    assert abs(2.2649 / 0.4 ** 0.054381 - 1.9987 / 0.4 ** 0.019087) > 0.3


def test_ep_rule():
    # with EP additives, κ < 1 and e_C >= 0.2: κ = 1 and a_ISO <= 3 (ISO 281 §9.3.3.4, secondary)
    a = AI.a_iso("deep_groove_ball", 0.3, 0.5, 800.0, 1000.0, ep_additives=True)
    assert a.ep_rule and a.kappa_used == 1.0 and a.value <= 3.0
