"""Mathieu characteristic values (the Ince-Strutt boundaries) against published output.

Source: S. Zhang, J. Jin, "Computation of Special Functions", Wiley 1996, program MCVA2
(subroutine CVA2), printed example for q = 25, m = 0 … 12, nine decimals; the example
block is kept in the public Fortran 90 transcription GitHub ``victorlei/smop-testsuite``,
file ``f2matlab/comp_spec_func/mcva2.f90`` (commit f79e9aad91a8068dce7b5ad011ddc213836ca750).
Tolerance: 1e-8 (one unit of the ninth decimal plus rounding).

The numerical Floquet check (:func:`geardesign.epicycle_rim.floquet.floquet_trace`) must give |trace| = 2 on these boundaries: a_{2m}, b_{2m}
are π-periodic (trace +2), a_{2m+1}, b_{2m+1} π-antiperiodic (trace −2).  For m <= 2 at
q = 25 the solutions grow by e^{10} over a period and the trace changes by more than 1e-5 per
unit of the ninth printed decimal, so those orders are not used for this check.
"""

import pytest

from geardesign.epicycle_rim import floquet as F
from geardesign.epicycle_rim import mathieu as M

Q = 25.0
A = [-40.256779547, -21.314899691, -3.522164727, 12.964079444, 27.805240581, 40.050190986,
     48.975786716, 57.534689001, 69.524065166, 85.076999882, 103.230204804, 123.643012376,
     146.207690643]
B = [None, -40.256778985, -21.314860622, -3.520941527, 12.986489953, 28.062765899,
     41.801071292, 55.002957151, 69.057988351, 85.023356505, 103.225680042, 123.642713667,
     146.207674647]


@pytest.mark.parametrize("m", range(13))
def test_characteristic_values_q25(m):
    assert abs(M.characteristic_value("a", m, Q) - A[m]) < 1e-8
    if m:
        assert abs(M.characteristic_value("b", m, Q) - B[m]) < 1e-8


@pytest.mark.parametrize("m", [3, 4, 7, 12])
def test_floquet_trace_on_the_boundaries(m):
    sign = 1.0 if m % 2 == 0 else -1.0
    assert F.floquet_trace(A[m], Q) == pytest.approx(2.0 * sign, abs=1e-5)
    if m:
        assert F.floquet_trace(B[m], Q) == pytest.approx(2.0 * sign, abs=1e-5)
