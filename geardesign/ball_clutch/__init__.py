"""Ball overrunning-safety clutch ([Malashchenko2025]): the freewheel part (force sharing among the
balls) and the torque-limiting part (limit torque from the spring preload and the socket
angle with friction, the centrifugal term, self-locking, spring and ball-contact checks).

Modules: :mod:`.clutch` (forces and limit torque), :mod:`.spring` (helical spring),
:mod:`.contact` (Hertz ball contact), :mod:`.spec`, :mod:`.calculator`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.ball_clutch.calculator.compute and
# geardesign.ball_clutch.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "ball_clutch",
    summary="ball overrunning-safety clutch: limit torque, speed effect, spring, ball contact",
    methods=("Malashchenko et al. 2025", "Wahl spring formulas", "Hertz contact"),
)
