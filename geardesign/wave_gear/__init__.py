"""Flexible wheel of a wave (strain-wave) gear: the stress-increase factor K_0 = K_zh·K_σ of
Tkachenko, Ustinenko and Borisenko ([Tkachenko2017]) with the stiffness factor K_zh of the
toothed rim from the tooth profile, the recommended rim thickness and the endurance check.

Eqs. (9)-(10) of the paper (shift corrections) are illegible in the source and are not
implemented (α_x = 1).

Modules: :mod:`.rim` (K_zh), :mod:`.flexwheel` (kinematics, stresses, endurance),
:mod:`.spec`, :mod:`.calculator`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.wave_gear.calculator.compute and
# geardesign.wave_gear.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "wave_gear",
    summary="wave-gear flexible wheel: rim stiffness factor K_zh, stress increase K_0, endurance",
    methods=("Tkachenko, Ustinenko, Borisenko 2017", "GOST 13755-81",
             "thin-ring bending"),
)
