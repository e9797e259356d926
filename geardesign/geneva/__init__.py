"""Geneva (Maltese-cross) indexing mechanisms, external and internal, and the Geneva-indexed
spindle block of a multi-spindle automatic ([RotaryDevices]).

Modules: :mod:`.kinematics` (motion law, peaks, geometry), :mod:`.drive` (reduced inertia,
dynamic moment and power of the spindle block), :mod:`.spec` (the spec schema),
:mod:`.calculator` (spec -> result).
"""

from geardesign.core.registry import Calculator
from geardesign.geneva.calculator import compute
from geardesign.geneva.spec import SCHEMA

CALCULATOR = Calculator(
    kind="geneva",
    summary="Geneva indexing drive: motion law, geometry, spindle-block dynamic power",
    methods=("Geneva kinematics (theory of machines)", "spindle-block model of rotary devices (RotaryDevices)"),
    schema=SCHEMA,
    compute=compute,
)
