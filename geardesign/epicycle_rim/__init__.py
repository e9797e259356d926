"""Ring gear (epicycle) rim of a planetary train: probabilistic fatigue of the thin rim and
parametric resonance of the ring.

Modules: :mod:`.stress` (fillet and rim stresses, mean-stress correction), :mod:`.endurance`
(the fillet's stress concentration and the part endurance limit, from the GOST 25.504-82
formulas of :mod:`geardesign.fatigue`), :mod:`.mesh` (planet positions, mesh phases,
stiffness pulsation), :mod:`.mathieu` (Mathieu/Ince-Strutt, Floquet), :mod:`.resonance`
(resonance frequencies and speeds), :mod:`.rim` (thin-rim factors), :mod:`.checks`,
:mod:`.spec`; the calculator: :mod:`.inputs` (with :mod:`.fatigue_inputs`) → :mod:`.solve`
→ :mod:`.report`, joined by :mod:`.calculator`.
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules does not
# import the calculation
__getattr__ = lazy_calculator(
    "epicycle_rim",
    summary="ring-gear rim: probabilistic fatigue of the thin rim, parametric resonance",
    methods=("GOST 25.504-82 (Serensen-Kogaev)", "Gutyria et al. 2017",
    "Yaglinskyi et al. 2017", "Mathieu/Floquet"),
)
