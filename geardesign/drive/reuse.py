"""Stage and bearing specs validated once per drive run.

The passes of a drive (the machine's torque carried back, the heat balance's efficiencies,
the shafts' misalignment) give a stage or a bearing the same spec with other loads.  The
first pass validates the spec (:func:`geardesign.core.registry.load_data`) and reads it
into the calculator's typed inputs; a later pass whose spec differs only in the loads the
drive sets takes that validated spec with the new loads, each checked by its own schema
field (:meth:`geardesign.core.spec.Field.check`), and the calculator's own reader of those
loads.  A load its field refuses makes the pass validate the whole spec again, so that the
problem is reported as the calculator reports it.  The store lives for one drive run
(:attr:`geardesign.drive.stages.Duty.memo`), so a run never sees another's values.  A
reused spec copies the tables that hold the new values and shares the others with the
stored spec: the readers and reports of the calculators do not change a validated spec's
tables once it has been read.
"""

from __future__ import annotations


from geardesign.core.spec import ValidatedSpec


def _split(path: str) -> tuple[tuple[str, ...], str]:
    """``"iso.scuffing.oil_temperature"`` -> ``(("iso", "scuffing"), "oil_temperature")``."""
    tables, _, key = path.rpartition(".")
    return tuple(tables.split(".")), key


def _table(data: dict, tables: tuple[str, ...]):
    """The (sub-)table of ``data`` at ``tables``, or None."""
    t = data
    for name in tables:
        t = t.get(name) if isinstance(t, dict) else None
    return t if isinstance(t, dict) else None


def _copied(data: dict, tables: tuple[str, ...]):
    """The (sub-)table of ``data`` at ``tables`` after copying each table on the way
    (``data`` itself is copied by the caller), or None; other tables stay shared."""
    t = data
    for name in tables:
        sub = t.get(name)
        if not isinstance(sub, dict):
            return None
        t[name] = sub = dict(sub)
        t = sub
    return t


def fingerprint(kind: str, where: str, data: dict, paths: tuple[str, ...]) -> tuple:
    """The key of a spec in the store: the spec with the values at ``paths``
    (``"table.key"``, ``"table.sub.key"``) left out."""
    d = dict(data)
    for path in paths:
        tables, key = _split(path)
        t = _copied(d, tables)
        if t is not None:
            t.pop(key, None)
    return kind, where, repr(d)


def given(data: dict, paths: tuple[str, ...]) -> dict:
    """The values of ``data`` at ``paths`` that are given (not None), by path."""
    out = {}
    for path in paths:
        tables, key = _split(path)
        t = _table(data, tables)
        if t is not None and t.get(key) is not None:
            out[path] = t[key]
    return out


def reloaded(schema, spec: ValidatedSpec, raw: dict, paths: tuple[str, ...]
             ) -> ValidatedSpec | None:
    """A copy of the validated ``spec`` with the values ``raw`` (the spec as given, kept for
    the advice) gives at ``paths``, each checked by the schema's field and no longer an
    assumed default; ``None`` (validate ``raw`` again) when a value is refused, the schema
    has no such field, or ``raw`` leaves out a value that ``spec`` has."""
    values = given(raw, paths)
    data = dict(spec.data)          # the tables on the paths copied, the others shared
    for path in paths:
        tables, key = _split(path)
        t = _copied(data, tables)
        if path not in values:
            if t is not None and t.get(key) is not None:
                return None
            continue
        f = _field(schema, tables, key)
        if f is None or not hasattr(f, "check") or t is None:
            return None
        value, message = f.check(values[path])
        if message:
            return None
        t[key] = value
    assumed = [a for a in spec.assumed if a not in values]
    return ValidatedSpec(data, assumed, spec.source, spec.base_dir, raw)


_FIELDS: dict = {}
"""The schema fields of the load paths found so far, by ``(id(schema), tables, key)``
(with the schema, so that an id is never taken for another's)."""


def _field(schema, tables: tuple[str, ...], key: str):
    """The field of ``schema`` at ``tables`` and ``key`` (None when it has none)."""
    found = _FIELDS.get((id(schema), tables, key))
    if found is not None and found[0] is schema:
        return found[1]
    member = schema.root
    for name in tables:
        member = member.member(name) if hasattr(member, "member") else None
    f = member.member(key) if hasattr(member, "member") else None
    _FIELDS[id(schema), tables, key] = (schema, f)
    return f
