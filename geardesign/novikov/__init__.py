"""Novikov gear pairs with two lines of action (DLZ) on the GOST 15023-76 basic rack:
geometry, axial overlap and the minimum face width criteria of the cyclogram paper, real
multi-pair engagement with load sharing (system (2)), phase bending and contact stresses,
and the critical stresses against allowables (Korotkin's NOVGOST-17 algorithm).

Modules: :mod:`.rack` and ``racks.toml`` (rack constants as data), :mod:`.tables`
(Korotkin's coefficient tables), :mod:`.factors` (K_W, K_F, K_H, K_ψ, Y_v),
:mod:`.geometry` (pair, Table 1, phases, cyclogram criteria), :mod:`.deviations` (the
error model), :mod:`.stress` (eq. (3), (4) and their inverses), :mod:`.sharing`
(system (2)), :mod:`.engagement` (the phase loop), :mod:`.checks`, :mod:`.spec`,
:mod:`.inputs`, :mod:`.solve`, :mod:`.report`, :mod:`.calculator`.  The GOST 21354-87
allowables come from the shared code (:mod:`geardesign.spur.strength.gost21354`,
:mod:`geardesign.materials.gear_steel`).
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.novikov.calculator.compute and
# geardesign.novikov.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "novikov",
    summary="Novikov DLZ pair (GOST 15023-76 rack): geometry, axial overlap, multi-pair "
            "engagement, phase bending and contact stresses",
    methods=("GOST 15023-76", "Korotkin 2017 (NOVGOST-17)", "Cyclogram 2017",
             "GOST 1643-81", "GOST 21354-87"),
)
