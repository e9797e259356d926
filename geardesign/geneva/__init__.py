"""Geneva (Maltese-cross) indexing mechanisms, external and internal, and the Geneva-indexed
spindle block of a multi-spindle automatic ([RotaryDevices]).

Modules: :mod:`.kinematics` (motion law, peaks, geometry), :mod:`.drive` (reduced inertia,
dynamic moment and power of the spindle block), :mod:`.spec` (the spec schema),
:mod:`.calculator` (spec -> result).
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.geneva.calculator.compute and
# geardesign.geneva.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "geneva",
    summary="Geneva indexing drive: motion law, geometry, spindle-block dynamic power",
    methods=("Geneva kinematics (theory of machines)", "spindle-block model of rotary devices (RotaryDevices)"),
)
