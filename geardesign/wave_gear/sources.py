"""Citations used in the wave-gear (flexible wheel) reports, in one place.

[Tkachenko2017], V. N. Tkachenko, A. V. Ustinenko, S. V. Borisenko, "Experimental study of the
stress-strain state of the toothed flexible wheel of a wave gear" (Bulletin of NTU "KhPI",
2017); equation numbers as in the paper.  Eqs. (9)-(10) (shift corrections α_x) are
illegible in the source and are not implemented: α_x = 1.
"""

TK_EQ1 = "Tkachenko 2017 eq. (1)"
TK_EQ4_5 = "Tkachenko 2017 eqs. (4)-(5)"
TK_HEFF = "Tkachenko 2017 (h = 0.45 m)"
TK_EQ6 = "Tkachenko 2017 eq. (6), α_x = 1"
TK_EQ7_8 = "Tkachenko 2017 eqs. (7)-(8)"
TK_REC = "Tkachenko 2017 (H0/m = 2.5...3)"
RING = "thin-ring bending (Ivanov, wave gears)"
WAVE = "wave-gear kinematics (Ivanov 1981)"
RACK = "GOST 13755-81"
FATIGUE = "fatigue safety (Serensen; s = s_σ s_τ/√(s_σ² + s_τ²))"
PRACTICE = "design practice"
STRELNIKOV = "Strelnikov 2017 (axial forces)"
