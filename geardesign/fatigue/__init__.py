"""Fatigue resistance of parts by GOST 25.504-82 ([GOST25504]), shared by the calculators
that use it (the shaft, the ring-gear rim, and DIN 743 where it has the same form).

Modules: :mod:`.gost25504` (the factors of the part endurance limit: blank size,
similarity criterion, sensitivity, K_σ/K_dσ, roughness, anisotropy, the total reduction
factor K_σD, the mean-stress sensitivity, the scatter, and the safety factors) and
:mod:`.probability` (quantiles of the endurance limit, probability of non-failure, S-N
curve and life).  Pure functions on floats; stresses MPa, lengths mm.
"""
