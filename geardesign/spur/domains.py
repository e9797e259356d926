"""The domains of the spur inputs changed or built in Python: each field of the typed
inputs (:class:`geardesign.spur.inputs.Inputs`) that a spec key holds is held to that key's
domain (:mod:`geardesign.spur.spec`), as reading a spec holds it."""

from __future__ import annotations


SPEC_KEYS = {
    "m_n": "gear.module", "z1": "gear.z1", "z2": "gear.z2", "x1": "gear.x1", "x2": "gear.x2",
    "beta": "gear.helix_angle", "b_w": "gear.face_width", "T1": "load.torque1",
    "n1": "load.speed1", "speed1": "load.speed1", "K_A": "load.application_factor",
    "T_peak": "load.peak_torque1", "reverse_ratio": "load.reverse_torque_ratio",
}
"""The spec key of each field :meth:`Inputs.replace` changes (the same units, but ``beta``:
radians here, degrees in the spec)."""


def check_changes(changes: dict) -> None:
    """Raise :class:`~geardesign.core.errors.InputError` with every value of ``changes``
    outside the domain of its spec key (:data:`SPEC_KEYS`; the key, the value in the key's
    unit, what is allowed); ``None`` (an optional value not given) is not checked."""
    import math

    from geardesign.core.errors import InputError, Problem
    from geardesign.spur.spec import SCHEMA

    found = []
    for name, value in changes.items():
        if name not in SPEC_KEYS or value is None:
            continue
        if name == "beta" and isinstance(value, (int, float)) and not isinstance(value, bool):
            value = math.degrees(value)
        table, leaf = SPEC_KEYS[name].split(".")
        _, message = SCHEMA.root.member(table).member(leaf).check(value)
        if message:
            found.append(Problem(f"{SPEC_KEYS[name]} ({name})", message, value))
    if found:
        raise InputError(found)


def check_built(inputs) -> None:
    """The domains of :data:`SPEC_KEYS` for inputs built in Python (no spec read them):
    the pair's fields and the duty's, as :func:`check_changes` holds them."""
    values = {name: getattr(inputs.pair, name) for name in SPEC_KEYS
              if hasattr(inputs.pair, name)}
    if inputs.strength is not None:
        duty = inputs.strength.duty
        values.update({name: getattr(duty, name) for name in SPEC_KEYS if hasattr(duty, name)})
    values["speed1"] = inputs.speed1
    check_changes(values)
