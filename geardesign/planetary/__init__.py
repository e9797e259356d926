"""Planetary trains 2K-H (simple and stepped planet) and 3K: Willis kinematics, assembly
conditions, geometry of every external and internal mesh with shifts, efficiency and
self-locking, strength of every mesh to GOST 21354-87 (through the spur rating),
diagnostic frequencies, and a synthesis mode.

Modules: :mod:`.kinematics`, :mod:`.assembly`, :mod:`.geometry`, :mod:`.efficiency`,
:mod:`.strength`, :mod:`.synthesis` (pure functions), :mod:`.checks`, :mod:`.spec`,
:mod:`.inputs` (with :mod:`.train`, :mod:`.shifts`), :mod:`.solve`, :mod:`.report` (with
:mod:`.report_strength`), :mod:`.calculator`.  The tooth loss factor is shared gear code:
:mod:`geardesign.gears.losses`.  Internal-gear geometry is shared code:
:mod:`geardesign.gears.internal`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules (the drive's
# loss model uses .efficiency) does not import the calculation
__getattr__ = lazy_calculator(
    "planetary",
    summary="planetary train 2K-H/3K: kinematics, assembly, geometry with shifts, "
            "efficiency, self-locking, strength, frequencies, synthesis",
    methods=("Willis method", "GOST 16532-70", "GOST 19274-73", "Matusevich et al. 2017"),
)
