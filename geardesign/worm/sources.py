"""Citations used in the worm reports, in one place so that a reference is corrected once.

The texts of GOST 19650-97, GOST 19036-94, GOST 2144-76 and GOST 19672-74 could not be
consulted ([WormPascal]); each citation names the standard or the textbook
whose formula is used, and the docstring of the function gives the formula, its source and the
public implementation that confirms it where one was found.
"""

G19650 = "GOST 19650-97"
G19036 = "GOST 19036-94"
G2144 = "GOST 2144-76"
G19672 = "GOST 19672-74"
G2406 = "GOST 2.406-76; GOST 19650-97"
TEXTBOOK = "Dunaev & Lelikov; Chernavsky; Ivanov"
DUNAEV = "Dunaev & Lelikov"
CHERNAVSKY = "Chernavsky"
FRICTION = "friction table (Ivanov; Chernavsky; Dunaev & Lelikov)"
THERMAL = "thermal balance (Dunaev & Lelikov; Chernavsky)"
PRACTICE = "design practice"
MECHANICS = "mechanics"
