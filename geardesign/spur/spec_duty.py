"""The duty of a spur pair's strength rating from the spec's ``[load]``: nominal torque (or
power), life, GOST regime or load spectrum, peak torque; every rule across keys an input
error naming the key."""

from __future__ import annotations

from geardesign.core.errors import InputError, Problem, Problems
from geardesign.core.spec import ValidatedSpec


def _fmt(x: float) -> str:
    return f"{x:.4f}".rstrip("0").rstrip(".")


def duty_from_spec(spec: ValidatedSpec, load: dict | None, torque_given: bool):
    """The duty of the strength calculation from [load] (torque or power, life, regime or
    spectrum, peak torque); input errors name the key."""
    from geardesign.spur.loads import torque_from_power
    from geardesign.spur.strength.rating import Duty, Life

    if load is None:
        raise InputError(Problem("load", "missing table [load] (speed1, torque1, life_hours): "
                                 "required with [material]"))
    problems = Problems()
    if load["torque1"] is not None and load["power"] is not None:
        problems.add(Problem("load.power", "give torque1 or power, not both", load["power"]))
    if not torque_given:
        problems.add(Problem("load.torque1", "missing; required with [material]: the nominal "
                             "pinion torque in N·m (or load.power in kW)"))
    if load["life_hours"] is None:
        problems.add(Problem("load.life_hours", "missing; required with [material]: the "
                             "required life in hours"))
    blocks = problems.stage(blocks_from_spec, load)
    problems.raise_all()
    T1 = load["torque1"] if load["torque1"] is not None else torque_from_power(load["power"],
                                                                               load["speed1"])
    if load["peak_torque1"] is not None and load["peak_torque1"] < T1:
        raise InputError.at("load.peak_torque1", load["peak_torque1"],
                            f"smaller than the nominal torque T1 = {_fmt(T1)} N·m; give the "
                            f"largest short-time torque")
    regime = load["regime"]
    if regime is None and not blocks:
        regime = "0"
        load["regime"] = "0"
        spec.assumed.append("load.regime")
    life = Life(load["life_hours"], (load["meshes_pinion"], load["meshes_wheel"]),
                regime if not blocks else None, blocks)
    return Duty(T1, load["speed1"], load["application_factor"], load["peak_torque1"],
                load["reverse_torque_ratio"], life)


def blocks_from_spec(load: dict) -> tuple:
    """The load spectrum of [[load.spectrum]] as blocks (empty without one)."""
    from geardesign.spur.loads import Block

    if not load["spectrum"]:
        return ()
    problems = Problems()
    if load["regime"] is not None:
        problems.add(Problem("load.regime", "give a regime or a spectrum, not both",
                             load["regime"]))
    total = sum(b["time_share"] for b in load["spectrum"])
    if abs(total - 1.0) > 1e-6:
        problems.add(Problem("load.spectrum", f"the time shares add up to {total:.6g}; they "
                             "must add up to 1", load["spectrum"]))

    def largest_block() -> None:
        if max(b["torque_ratio"] for b in load["spectrum"]) < 1.0 - 1e-9:
            raise InputError.at("load.spectrum", load["spectrum"], "no block has torque_ratio "
                                "= 1: torque1 must be the torque of the largest long-acting "
                                "block")

    problems.stage(largest_block)
    problems.raise_all()
    return tuple(Block(b["torque_ratio"], b["time_share"], b["speed_ratio"])
                 for b in load["spectrum"])
