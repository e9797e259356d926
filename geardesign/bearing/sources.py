"""Citations used in the bearing reports, in one place so that a reference is corrected once.

Editions implemented (the spec's top-level ``method``):

* ``"gost18855_94"``: GOST 18855-94 (= ISO 281:1990): L_sah = a1·a23·L10, a1 of the 1990
  table, the Russian-practice factors V, K_б, K_т and a23 (textbooks, GOST 18855-82 practice).
* ``"iso281_2007"``: ISO 281:2007 (= GOST 18855-2013): L_nm = a1·a_ISO·L10 with the 2007 a1
  table, κ = ν/ν1, e_C and C_u.

The texts of ISO 281:2007 / GOST 18855-2013 and GOST 18855-94 could not be read
([BBContact]; [Dessia]); clause numbers are therefore not quoted, and
each table's docstring in :mod:`.tables` says which public source confirms it.
"""

GOST94 = "GOST 18855-94"
ISO2007 = "ISO 281:2007"
ISO_BOTH = "ISO 281 / GOST 18855"
ISO76 = "ISO 76 / GOST 18854"
RU_PRACTICE = "GOST 18855-94 practice (Russian textbooks)"
NTN = "NTN CAT. No. 2202/E"
GOST21354_REGIMES = "GOST 21354-87 regimes (Russian textbooks)"
CATALOGUE = "catalogue"
LP = "Lundberg–Palmgren; NTN CAT. No. 2202/E (3.6)"
PRACTICE = "design practice"
D341 = "ASTM D341 (Ubbelohde–Walther)"
D2270 = "ASTM D2270 / ISO 2909"
SKF = "[SKF6000]"
PAIR = "[SKF6000] pp. 415–416, table 4; [NSK] A-36"


def method_source(method: str) -> str:
    return GOST94 if method == "gost18855_94" else ISO2007
