"""The printed constants of the nonlinear contact model.

Source: A. P. Popov, A. I. Mironenko, M. G. Mozgovoi, O. I. Savenkov, "Contact strength of
gears accounting for the nonlinear relation between tooth deformations and stresses",
Bulletin of NTU "KhPI" 2017 No. 25 ([Popov2017]).  Each printed constant (3 decimals; tolerance half
a unit of the last digit,
one unit where the paper rounds a rounded value) is derived from the general formulas of
geardesign.spur.strength.contact_models for equal steels, ν = 0.3.

Misprints of the paper, computed correctly here:
* eq. (18) prints 0.859; its own eq. (19) needs 0.889 (0.889^(10/21) = 0.946,
  0.859^(10/21) = 0.930);
* the ratio of point-contact stresses prints as "1,224" (garbled): 0.33/0.294 = 1.122.
"""

import math

from geardesign.spur.strength.contact_models import hertz_line, popov_line, popov_point

NU = 0.3


def unit_line(model):
    # F = E = ρ = b = 1: b0 and σ are the coefficients of sqrt(Fρ/(Eb)) and sqrt(FE/(ρb))
    return model(1.0, 1.0, 1.0, 1.0, NU, 1.0, NU)


def test_hertz_line_constants():
    b0, s = unit_line(hertz_line)
    assert abs(b0 - 1.522) < 0.0005 and abs(s - 0.418) < 0.0005


def test_nonlinear_line_constants_eq10_eq11():
    b0, s = unit_line(popov_line)
    assert abs(b0 - 1.604) < 0.0005   # eq. (10)
    assert abs(s - 0.396) < 0.0005    # eq. (11)


def test_line_contact_gain():
    ratio = unit_line(hertz_line)[1] / unit_line(popov_line)[1]
    assert abs(ratio - 1.0555) < 0.0005          # σ_H 1.0555× lower
    assert abs(ratio ** 2 - 1.114) < 0.0005       # load capacity +11.4 %


def test_point_contact_constants_eq19_to_eq25():
    # eq. (19) from eq. (18) with 0.889 (the paper prints 0.859: misprint)
    assert abs(0.889 ** (10 / 21) - 0.946) < 0.0005
    assert abs(0.859 ** (10 / 21) - 0.946) > 0.01
    alpha = 0.5
    b0, bK, smax = popov_point(1.0, 1.0, alpha, 1.0, NU, 1.0, NU)
    x = alpha / (alpha + NU)                       # αρF/((α+ν)E) with F = ρ = E = 1
    assert abs(b0 / x ** (1 / 3) - 1.275) < 0.0005                         # eq. (23)
    assert abs(bK / (1.0 / (alpha ** 2 * (alpha + NU))) ** (1 / 3) - 1.275) < 0.0005  # eq. (24)
    assert abs(smax / (alpha * (alpha + NU) ** 2) ** (1 / 3) - 0.294) < 0.0005     # eq. (25)
    S = 2 * ((1 - NU ** 2) * x) ** 0.7
    assert abs(smax / (alpha / S ** (20 / 21)) - 0.534) < 0.0005           # eq. (22)


def test_point_contact_gain():
    # n = 1: b0 coefficient 1.202, σ_max = 3/(2π·1.202²) = 0.33 (printed)
    assert abs(3 / (2 * math.pi * 1.202 ** 2) - 0.33) < 0.005
    gain = 0.33 / 0.294
    assert abs(gain - 1.1224) < 0.0005            # printed garbled as "1,224"
    assert abs(gain ** 3 - 1.414) < 0.0005        # load capacity +41.4 %
    assert abs(gain ** 3 / 1.114 - 1.269) < 0.001  # point vs line: 1.27
