"""Ball overrunning-safety clutch ([Malashchenko2025]): the freewheel part (force sharing among the
balls) and the torque-limiting part (limit torque from the spring preload and the socket
angle with friction, the centrifugal term, self-locking, spring and ball-contact checks).

Modules: :mod:`.clutch` (forces and limit torque), :mod:`.spring` (helical spring),
:mod:`.contact` (Hertz ball contact), :mod:`.spec`, :mod:`.calculator`.
"""

from geardesign.ball_clutch.calculator import compute
from geardesign.ball_clutch.spec import SCHEMA
from geardesign.core.registry import Calculator

CALCULATOR = Calculator(
    kind="ball_clutch",
    summary="ball overrunning-safety clutch: limit torque, speed effect, spring, ball contact",
    methods=("Malashchenko et al. 2025", "Wahl spring formulas", "Hertz contact"),
    schema=SCHEMA,
    compute=compute,
)
