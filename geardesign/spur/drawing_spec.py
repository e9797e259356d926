"""Spec tables of the gear drawing: ``[accuracy]`` (tolerances and backlash) and
``[drawing]`` (test dimensions and the data table), added to the ``kind = "spur"`` schema."""

from __future__ import annotations

from geardesign.core.spec import REQUIRED, Field, Table
from geardesign.spur.tolerances import gost1643, iso1328

STANDARDS = (gost1643.STANDARD, *iso1328.EDITIONS)


def _um(key: str, name: str, lo: float = 0.0, hi: float = 10000.0, **kw) -> Field:
    return Field(key, "number", name, "µm", key, default=None, minimum=lo, maximum=hi, **kw)


def _temp(key: str, who: str) -> Field:
    return Field(key, "number", f"operating temperature of the {who}", "°C", f"t_{who}",
                 default=None, minimum=-100.0, maximum=400.0,
                 hint="20 °C (the drawing temperature) when not given")


def _expansion(key: str, who: str) -> Field:
    return Field(key, "number", f"linear expansion coefficient of the {who}", "1e-6/K",
                 f"α_{who}", default=None, minimum=0.0, maximum=100.0,
                 hint="11.5 (steel) when a temperature is given; cast iron 10.5, aluminium 23")


ACCURACY = Table("accuracy", "accuracy, tooth thickness allowances and backlash", (
    Field("standard", "string", "tolerance standard", default=REQUIRED, choices=STANDARDS,
          example=gost1643.STANDARD),
    Field("grade", "integer", "accuracy degree (GOST 1643-81: 3…12), flank tolerance class "
          "(ISO 1328-1:2013: 1…11) or accuracy grade (ISO 1328-1:1995: 0…12)",
          default=REQUIRED, minimum=0, maximum=12, example=8),
    Field("mating", "string", "type of mating (GOST 1643-81): guaranteed backlash and the class "
          "of centre-distance deviation", default=None, choices=gost1643.MATINGS, example="B",
          hint="required with GOST 1643-81; with ISO 1328-1 it sets j_n min (else ISO/TR 10064-2)"),
    Field("center_distance_class", "string", "class of centre-distance deviation (GOST "
          "1643-81), when it differs from the one of the type of mating", default=None,
          choices=gost1643.CLASSES),
    _um("jn_min", "required least normal backlash (instead of the standard's value)"),
    _um("fa", "limit deviation ±f_a of the centre distance (instead of the class value)",
        hint="required with ISO 1328-1"),
    _um("E_Hs1", "least additional rack shift of the pinion, −E_Hs (GOST 1643-81 table value, "
        "without its sign)", hint="from the backlash balance when not given"),
    _um("E_Hs2", "least additional rack shift of the wheel, −E_Hs"),
    _um("T_H1", "tolerance on the additional rack shift of the pinion (GOST 1643-81)",
        example=100.0, hint="required with GOST 1643-81 (T_H by F_r and the type of backlash "
                            "tolerance)"),
    _um("T_H2", "tolerance on the additional rack shift of the wheel (GOST 1643-81)",
        example=160.0),
    _um("A_sne1", "upper tooth thickness allowance of the pinion (ISO 1328-1 pairs: "
        "DIN 3967 / ISO 21771), ≤ 0", lo=-10000.0, hi=0.0,
        hint="from the backlash balance when not given"),
    _um("A_sne2", "upper tooth thickness allowance of the wheel, ≤ 0 (an internal gear: of "
        "its teeth, ≤ 0 as well: wider spaces)", lo=-10000.0, hi=0.0),
    _um("T_sn1", "tooth thickness tolerance of the pinion (ISO pairs)",
        hint="required with ISO 1328-1"),
    _um("T_sn2", "tooth thickness tolerance of the wheel (ISO pairs)"),
    _temp("temperature_housing", "housing"),
    _temp("temperature_pinion", "pinion"),
    _temp("temperature_wheel", "wheel"),
    _expansion("expansion_housing", "housing"),
    _expansion("expansion_pinion", "pinion"),
    _expansion("expansion_wheel", "wheel"),
), required=False, hint="the report then gives the tolerances, the backlash range, the test "
                        "dimensions with their limits and the drawing data table")

DRAWING = Table("drawing", "gear drawing: test dimensions and the data table", (
    Field("k1", "integer", "number of teeth spanned for W, pinion", symbol="k1", default=None,
          minimum=1, maximum=1000, hint="the tool's choice when not given"),
    Field("k2", "integer", "number of teeth spanned for W, wheel (an internal gear: spaces)",
          symbol="k2", default=None,
          minimum=1, maximum=1000),
    Field("ball_diameter1", "number", "ball or pin diameter for M_d, pinion", "mm", "D1",
          default=None, minimum=0.01, maximum=1000.0,
          hint="chosen to touch near mid-height when not given"),
    Field("ball_diameter2", "number", "ball or pin diameter for M_d, wheel (an internal "
          "gear: between its teeth)", "mm", "D2",
          default=None, minimum=0.01, maximum=1000.0),
    Field("helix_hand", "string", "hand of the pinion's helix (the wheel's is opposite)",
          default=None, choices=("right", "left"), hint="helical gears; right when not given"),
), required=False, hint="with [accuracy] the dimensions carry their limits")
