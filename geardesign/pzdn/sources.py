"""Citations used in the pzdn reports, in one place so that a reference is corrected once.

"KO-2 thesis" is the master's thesis of E. V. Lopukhov, "Improvement of the device of
dynamic loads of the drive of knitting machines" ([Lopukhov]; its
equations are numbered per section: 2.1 = one spring, 2.2 = two springs and the start-up
model, 2.3 = regression).  Its errors are listed in docs/pzdn.md; corrected formulas are cited as
"[Lopukhov] §.. (corrected)".
"""

THESIS_A = "KO-2 thesis §2.1"            # one spring, method A
THESIS_B = "KO-2 thesis §2.2"            # two springs, method B
THESIS_D = "KO-2 thesis §2.2 (start-up)"  # three-mass start-up model
THESIS_E = "KO-2 thesis §2.3"            # regression
NOTE_D = "[Lopukhov] §2.2 (corrected)"
NOTE_A = "[Lopukhov] §2.1"
EN13906 = "EN 13906-3 (SpringTHREE)"
SHIGLEY = "Shigley §10-12"
GOST9389 = "GOST 9389-75"
MECHANICS = "beam theory"
ODE = "numerical integration (scipy solve_ivp, DOP853)"
ODE_EXACT = "exact solution of the linear model (matrix exponential)"
METHOD_ODE = "numerical integration (scipy)"
METHOD_EXACT = "numerical integration (exact, matrix exponential)"


def ode(sim) -> str:
    """The source of the results of a start-up integration (:class:`.simulate.Simulation`)."""
    return ODE_EXACT if sim.exact else ODE
KLOSS = "Kloss formula"
SERIES = "series springs 1/C = Σ 1/C_i"
SPUR = "spur calculator (GOST 21354-87)"
TEXTBOOK_GEAR = "KO-2 thesis §2.1 (textbook [37])"
