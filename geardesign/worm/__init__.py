"""Cylindrical worm pairs: geometry to GOST 19650-97, efficiency and self-locking, strength
of the wheel, worm deflection and thermal balance (the classical method of the Russian
textbooks), and a design mode proposing a_w, m, q.

Modules: :mod:`.geometry` (pure geometry), :mod:`.kinematics` (speeds, friction,
efficiency, forces), :mod:`.strength` (wheel stresses, allowables, worm deflection),
:mod:`.thermal` (oil temperature), :mod:`.pair` (the whole analysis on plain data),
:mod:`.design` (standard series, a_w proposal), :mod:`.checks`, :mod:`.advice`,
:mod:`.spec`, :mod:`.inputs` (spec -> typed inputs), :mod:`.solve` (inputs -> record),
:mod:`.report` (record -> rows and checks), :mod:`.calculator` (spec -> result),
:mod:`.tables` (the data of ``tables.toml``).
"""

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use: importing one of the package's modules (the drive
# reads the typed inputs and records) does not import the calculation's report
__getattr__ = lazy_calculator(
    "worm",
    summary="cylindrical worm pair: geometry, efficiency, self-locking, wheel strength, "
            "worm deflection, oil temperature; design mode",
    methods=("GOST 19650-97", "GOST 19036-94", "GOST 2144-76",
             "Dunaev & Lelikov / Chernavsky (strength, thermal)"),
)
