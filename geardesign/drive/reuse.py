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


def fingerprint(kind: str, where: str, data: dict, table: str, keys: tuple[str, ...]) -> tuple:
    """The key of a spec in the store: the spec with the loads ``table.keys`` left out."""
    d = dict(data)
    t = d.get(table)
    if isinstance(t, dict):
        d[table] = {k: v for k, v in t.items() if k not in keys}
    return kind, where, repr(d)


def reloaded(schema, spec: ValidatedSpec, raw: dict, table: str,
             values: dict) -> ValidatedSpec | None:
    """A copy of the validated ``spec`` with ``values`` in its table ``table``, each
    checked by the schema's field (``raw``: the spec as given, for the advice); ``None``
    when a value is refused or the table has no such field (validate it again)."""
    t = schema.root.member(table)
    if t is None or not isinstance(spec.data.get(table), dict):
        return None
    data = copy.deepcopy(spec.data)
    for key, value in values.items():
        f = t.member(key)
        if f is None or not hasattr(f, "check"):
            return None
        value, message = f.check(value)
        if message:
            return None
        data[table][key] = value
    return ValidatedSpec(data, list(spec.assumed), spec.source, spec.base_dir, raw)
