"""Citations used in the planetary reports, in one place so that a reference is corrected
once.  The docstring of the function that computes a quantity gives its formula."""

from geardesign.spur import sources as _spur

WILLIS = "Willis method (Kudryavtsev)"
MATUSEVICH = "Matusevich et al. 2017"
MATUSEVICH_1 = "Matusevich et al. 2017 eq. (1)"
COAX = "Matusevich et al. 2017 eqs. (2), (15)-(28)"
QUALITY = "Matusevich et al. 2017 eqs. (31)-(37)"
KUDRYAVTSEV = "Kudryavtsev, Planetary gears"
ASSEMBLY = "Kudryavtsev; Matusevich et al. 2017 (4)"
PHASING = "Parker & Lin 2004"
G16532 = "GOST 16532-70"
G19274 = _spur.G19274
G19274_MEMORY = _spur.G19274_MEMORY
SLIDING = "theory of gearing; Dobrov 2017 (3)"
HV = "ISO/TR 14179-2; Niemann"
TORQUE = "torque method (Kudryavtsev); Malashchenko et al. 2017 (10)-(12)"
MALASHCHENKO = "Malashchenko et al. 2017 (13), (16)"
BELAZ = "Gavrilov et al. 2017"
G21354 = "GOST 21354-87"
PRACTICE = "design practice"
SYNTHESIS = "synthesis (this program)"
