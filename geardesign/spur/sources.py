"""Citations used in the spur reports, in one place so that a reference is corrected once.

The text of GOST 16532-70 could not be consulted, so its
table numbers are not quoted; each citation names the standard, and the docstring of the
function that computes the quantity gives the formula and the public implementation that
confirms it.
"""

G16532 = "GOST 16532-70"
G16532_SPAN = "GOST 16532-70; DIN 3960"
G13755 = "GOST 13755-81"
SLIDING = "theory of gearing; Dobrov 2017 (3)"
DOBROV = "Dobrov 2017 (10), (20)"
PRACTICE = "design practice"
G19274 = "GOST 19274-73; ISO 21771"
G19274_MEMORY = "GOST 19274-73 (handbook form, verify)"
