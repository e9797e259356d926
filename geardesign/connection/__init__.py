"""Shaft-hub connections: parallel keys ([GOST23360], [DIN6885-1], [DIN6892]), involute
splines ([DIN5480], [GOST6033]) and cylindrical interference fits ([DIN7190-1], [ISO286]).

Modules: :mod:`.key`, :mod:`.spline`, :mod:`.fit` (pure formulas), :mod:`.iso286` (limit
deviations of a fit), :mod:`.tables` (the CSV and TOML data), :mod:`.spec` (the spec schema),
:mod:`.inputs` (spec -> typed inputs, every input rule), :mod:`.solve` (inputs -> one record
per connection type), :mod:`.calculator` (record -> report rows and checks).
"""

from __future__ import annotations

from geardesign.core.registry import lazy_calculator

# the calculator is built on first use (geardesign.connection.calculator.compute and
# geardesign.connection.spec.SCHEMA): importing one of the package's modules does not import the
# calculation, and the calculator's modules import the package without a cycle
__getattr__ = lazy_calculator(
    "connection",
    summary="shaft-hub connection: parallel key, involute spline or interference fit",
    methods=("GOST 23360-78 / DIN 6885-1, DIN 6892", "DIN 5480 / GOST 6033-80",
             "DIN 7190-1, ISO 286"),
)
