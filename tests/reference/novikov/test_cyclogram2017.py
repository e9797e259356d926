"""Cyclogram 2017, Table 1 ([Matyushenko2017]): N. V. Matyushenko, A. V. Fedchenko,
V. A. Berezhnoi, "Numerical study of the cyclogram and of the overlap at re-engagement of
adjacent teeth", Bulletin of NTU "KhPI", series "Problems of mechanical drive", 2017,
No. 25.  "Minimum allowable face width (in units of p_x) for different basic racks,
m_n = 1.0, β = 15°, z1 = 17", five racks (column names unreadable in the scan).

Rows as printed: "1": {q_21/p_x} per rack; (2): 0.99999 for all; "3": 1.67303, 1.96127,
1.68662, 1.63401, 1.83522.  Row 2 is the least width for 2 points (criterion 1, k = 1:
b_w = p_x; the paper's program found it numerically, hence 0.99999, tolerance 2e-5); row 3
the least width for 3 points (criterion 2, k = 1), which depends on the offset only through
δ, its distance to the nearest integer: 2 − δ (tolerance 1e-5, the print's last digit).

Misprint: the scan of criterion 2 reads b_w ≥ (1 + k)p_x **+** |q_21 − n·p_x|; that would
give 2 + δ (2.32697 for column 1), not the printed 1.67303.  The tool uses "−"
(geometry.min_face_width), which reproduces all five columns.
"""

import pytest

from geardesign.novikov.geometry import min_face_width

OFFSETS = (0.32697, 0.03873, 0.31338, 0.36599, 0.83522)
ROW2 = 0.99999
ROW3 = (1.67303, 1.96127, 1.68662, 1.63401, 1.83522)


def delta(offset: float) -> float:
    return min(offset, 1.0 - offset)


@pytest.mark.parametrize("col", range(5))
def test_least_face_width_for_two_points(col):
    assert abs(min_face_width(2, 1.0, delta(OFFSETS[col])) - ROW2) <= 2e-5


@pytest.mark.parametrize("col", range(5))
def test_least_face_width_for_three_points(col):
    assert abs(min_face_width(3, 1.0, delta(OFFSETS[col])) - ROW3[col]) <= 1e-5


def test_the_printed_plus_sign_is_a_misprint():
    d = delta(OFFSETS[0])
    assert abs((1 + 1) + d - ROW3[0]) > 0.6          # "+" reading: 2.32697 ≠ 1.67303
    assert abs(min_face_width(3, 1.0, d) - ROW3[0]) <= 1e-5
