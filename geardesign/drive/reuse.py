"""Stage and bearing specs validated once per drive run.

The passes of a drive (the machine's torque carried back, the heat balance's efficiencies,
the shafts' misalignment) give a stage or a bearing the same spec with other loads.  The
first pass validates the spec (:func:`geardesign.core.registry.load_data`) and reads it
into the calculator's typed inputs; a later pass whose spec differs only in the loads the
drive sets takes that validated spec with the new loads, each checked by its own schema
field (:meth:`geardesign.core.spec.Field.check`), and the calculator's own reader of those
loads.  A load its field refuses makes the pass validate the whole spec again, so that the
problem is reported as the calculator reports it.  The store lives for one drive run
(:attr:`geardesign.drive.stages.Duty.memo`), so a run never sees another's values.
"""

from __future__ import annotations

import copy

from geardesign.core.spec import ValidatedSpec


def _split(path: str) -> tuple[str, str]:
    table, _, key = path.partition(".")
    return table, key


def fingerprint(kind: str, where: str, data: dict, paths: tuple[str, ...]) -> tuple:
    """The key of a spec in the store: the spec with the loads ``paths`` (``"table.key"``)
    left out."""
    d = dict(data)
    for path in paths:
        table, key = _split(path)
        t = d.get(table)
        if isinstance(t, dict) and key in t:
            d[table] = {k: v for k, v in t.items() if k != key}
    return kind, where, repr(d)


def given(data: dict, paths: tuple[str, ...]) -> dict:
    """The values of ``data`` at ``paths`` (``"table.key"``) that are given (not None)."""
    out = {}
    for path in paths:
        table, key = _split(path)
        t = data.get(table)
        if isinstance(t, dict) and t.get(key) is not None:
            out[path] = t[key]
    return out


def reloaded(schema, spec: ValidatedSpec, raw: dict, values: dict) -> ValidatedSpec | None:
    """A copy of the validated ``spec`` with ``values`` (by ``"table.key"``), each
    checked by the schema's field (``raw``: the spec as given, for the advice); ``None``
    when a value is refused or the schema has no such field (validate it again)."""
    data = copy.deepcopy(spec.data)
    for path, value in values.items():
        table, key = _split(path)
        t = schema.root.member(table)
        f = t.member(key) if t is not None and hasattr(t, "member") else None
        if f is None or not hasattr(f, "check") or not isinstance(data.get(table), dict):
            return None
        value, message = f.check(value)
        if message:
            return None
        data[table][key] = value
    return ValidatedSpec(data, list(spec.assumed), spec.source, spec.base_dir, raw)
