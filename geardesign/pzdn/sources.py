"""Citations used in the pzdn reports, in one place so that a reference is corrected once.

"KO-2 thesis" is the master's thesis of E. V. Lopukhov, "Improvement of the device of
dynamic loads of the drive of knitting machines" (seed 000 of the method notes; its
equations are numbered per section: 2.1 = one spring, 2.2 = two springs and the start-up
model, 2.3 = regression).  The method note ``shared/methods/pzdn.md`` decodes it and
lists the thesis' errors; the corrected formulas are cited as "method note §..".
"""

THESIS_A = "KO-2 thesis §2.1"            # one spring, method A
THESIS_B = "KO-2 thesis §2.2"            # two springs, method B
THESIS_D = "KO-2 thesis §2.2 (start-up)"  # three-mass start-up model
THESIS_E = "KO-2 thesis §2.3"            # regression
NOTE_D = "method note pzdn.md §6.2 (corrected)"
NOTE_A = "method note pzdn.md §3"
EN13906 = "EN 13906-3 (SpringTHREE)"
SHIGLEY = "Shigley §10-12"
GOST9389 = "GOST 9389-75"
MECHANICS = "beam theory"
ODE = "numerical integration (scipy solve_ivp, DOP853)"
KLOSS = "Kloss formula"
SERIES = "series springs 1/C = Σ 1/C_i"
SPUR = "spur calculator (GOST 21354-87)"
TEXTBOOK_GEAR = "KO-2 thesis §2.1 (textbook [37])"
