"""Citations used in the Geneva reports, in one place so that a reference is corrected once.

Geneva kinematics are the classical slider-crank relations of the Geneva mechanism found in
every theory-of-machines textbook (Artobolevsky, "Teoriya mekhanizmov i mashin"; Kozhevnikov,
"Teoriya mekhanizmov i mashin"; Sclater & Chironis, "Mechanisms and Mechanical Devices
Sourcebook", chapter "Kinematics of intermittent mechanisms").  The textbook pages were not
re-read for this implementation: the formulas are derived in the docstrings from the
geometry (a right angle between crank and slot at entry), so that they can be checked
without the books.

The spindle-block indexing drive follows the paper of [RotaryDevices], "Modelling of rotary devices
of machine aggregates" (authors not preserved in the source), eqs. (1)-(3) and the power
balance printed before them; [RotaryDevices].
"""

GENEVA = "Geneva kinematics (theory of machines)"
GENEVA_GEOM = "Geneva geometry (entry at a right angle)"
SEED_POWER = "[RotaryDevices], power balance (N_b, N_sh)"
SEED_EQ1 = "[RotaryDevices] eq. (1)"
SEED_EQ2 = "[RotaryDevices] eq. (2)"
SEED_EQ3 = "[RotaryDevices] eq. (3)"
PLANETARY = "[RotaryDevices] (ω_sh = ω_sh.rab ± u_p·ω_b)"
DYNAMICS = "rigid-body dynamics"
PRACTICE = "design practice"
