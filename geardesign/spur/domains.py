"""The domains of the spur inputs changed or built in Python: each field of the typed
inputs (:class:`geardesign.spur.inputs.Inputs`) that a spec key holds is held to that key's
domain (:mod:`geardesign.spur.spec`), as reading a spec holds it."""

from __future__ import annotations


SPEC_KEYS = {
    "m_n": ("gear.module", 1.0), "z1": ("gear.z1", None), "z2": ("gear.z2", None),
    "x1": ("gear.x1", 1.0), "x2": ("gear.x2", 1.0), "beta": ("gear.helix_angle", None),
    "b_w": ("gear.face_width", 1.0), "T1": ("load.torque1", 1.0),
    "n1": ("load.speed1", 1.0), "speed1": ("load.speed1", 1.0),
    "K_A": ("load.application_factor", 1.0), "T_peak": ("load.peak_torque1", 1.0),
    "reverse_ratio": ("load.reverse_torque_ratio", 1.0),
}
"""The spec key of each field :meth:`Inputs.replace` changes, and the factor to the key's
unit (``None``: taken as it is; ``beta`` [rad] is checked in degrees)."""


def check_changes(changes: dict) -> None:
    """Raise :class:`~geardesign.core.errors.InputError` with every value of ``changes``
    outside the domain of its spec key (:data:`SPEC_KEYS`; the key, the value in the key's
    unit, what is allowed)."""
    import math

    from geardesign.core.errors import InputError, Problem
    from geardesign.spur.spec import SCHEMA

    found = []
    for name, value in changes.items():
        if name not in SPEC_KEYS or (value is None and name == "T_peak"):
            continue
        key, scale = SPEC_KEYS[name]
        table, leaf = key.split(".")
        shown = value
        if name == "beta" and isinstance(value, (int, float)) and not isinstance(value, bool):
            shown = math.degrees(value)
        elif scale is not None and isinstance(value, float):
            shown = value * scale
        _, message = SCHEMA.root.member(table).member(leaf).check(shown)
        if message:
            found.append(Problem(f"{key} ({name})", message, shown))
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
    if inputs.speed1 is not None:
        values["speed1"] = inputs.speed1
    check_changes(values)
