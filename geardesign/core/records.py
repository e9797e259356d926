"""Records made cheaply: :func:`dataclass`, a drop-in for :func:`dataclasses.dataclass`.

Python 3.11 builds every method of a dataclass by compiling its source text when the class
is created: six for a frozen record (``__init__``, ``__repr__``, ``__eq__``, ``__hash__``,
``__setattr__``, ``__delattr__``), about 0.8 ms a record on the test machine, and a spur run
creates some 50 records, a drive with shafts some 130 (issue 32: a quarter of a small
spec's start-up; issue 28).  Here nothing is compiled when a record is made:

* the fields are collected as :func:`dataclasses.dataclass` collects them (:func:`_collect`:
  ``field()`` or plain defaults, those of record bases first, the same refusals), stored
  where :func:`dataclasses.fields`, ``asdict`` and ``replace`` find them;
* ``__init__`` is the code the standard library writes, compiled once for its
  :func:`shape` (what each field does, whatever its name) and kept beside the bytecode as
  the bytecode is (:func:`shape_code`), with the field names put in; defaults are the
  function's own, factories in its globals;
* ``__repr__``, ``__eq__``, ``__hash__`` and a frozen record's ``__setattr__``/
  ``__delattr__`` are shared functions over the record's field names that print, compare,
  hash and refuse exactly as the generated ones do (``compare``/``hash``/``repr`` of
  :func:`dataclasses.field` honoured, methods the class defines itself kept, ``__hash__``
  set as :func:`dataclasses.dataclass` sets it); the docstring of an undocumented record is
  the name and signature, as the standard library writes it, and ``__dataclass_params__``
  and ``__match_args__`` say what the record is.

A class with a dataclass base not made here, an ``InitVar``, ``ClassVar`` or ``KW_ONLY``
annotation, a field named ``self`` or ``_...``, its own ``__setattr__``, or options beyond
``frozen`` and ``kw_only`` goes to :func:`dataclasses.dataclass` unchanged.
tests/test_records.py compares both on every record of the package.
"""

from __future__ import annotations

import abc
import dataclasses
from dataclasses import _FIELD, MISSING, Field
from functools import lru_cache
from operator import attrgetter
from pathlib import Path
from reprlib import recursive_repr
from types import FunctionType, MemberDescriptorType


def dataclass(cls=None, /, *, frozen: bool = False, kw_only: bool = False, **options):
    """:func:`dataclasses.dataclass` with no method compiled per class (see the module)."""

    def wrap(cls):
        if options or not _plain(cls):
            return dataclasses.dataclass(cls, frozen=frozen, kw_only=kw_only, **options)
        own = cls.__dict__
        class_hash = own.get("__hash__", MISSING)
        explicit_hash = not (class_hash is MISSING
                             or (class_hash is None and "__eq__" in own))
        fields = _collect(cls, frozen, kw_only)
        cls.__dataclass_params__ = _params(frozen, kw_only)
        _set(cls, "__init__", _init(cls, fields, frozen))
        if "__match_args__" not in own:
            cls.__match_args__ = tuple(f.name for f in fields if f.init and not f.kw_only)
        if "__repr__" not in own:
            _set(cls, "__repr__", _repr([f.name for f in fields if f.repr]))
        if "__eq__" not in own:
            _set(cls, "__eq__", _eq(_values([f.name for f in fields if f.compare])))
        if not explicit_hash:
            # as dataclasses does for eq=True: a frozen record hashes its compared fields,
            # a mutable one is unhashable
            hashed = [f.name for f in fields if (f.compare if f.hash is None else f.hash)]
            if frozen:
                _set(cls, "__hash__", _hash(_values(hashed)))
            else:
                cls.__hash__ = None
        if frozen:
            names = frozenset(f.name for f in fields)
            _set(cls, "__setattr__", _frozen_setattr(cls, names))
            _set(cls, "__delattr__", _frozen_delattr(cls, names))
        if not own.get("__doc__"):     # as dataclasses writes it: the name and the signature
            cls.__doc__ = cls.__name__ + _signature(cls, fields).replace(" -> None", "")
        abc.update_abstractmethods(cls)
        return cls

    return wrap if cls is None else wrap(cls)


def _signature(cls, fields) -> str:
    """``str(inspect.signature(cls))`` of a record whose ``__init__`` is :func:`_init`'s,
    written from its fields (the way :class:`inspect.Signature` writes them)."""
    import inspect

    if type(cls) is not type or "__new__" in cls.__dict__:
        return str(inspect.signature(cls))
    params, keywords = [], []
    for f in fields:
        if not f.init:
            continue
        kind = repr(f.type) if isinstance(f.type, str) else inspect.formatannotation(f.type)
        text = f"{f.name}: {kind}"
        if f.default_factory is not MISSING:
            text += f" = {_HAS_FACTORY!r}"
        elif f.default is not MISSING:
            text += f" = {f.default!r}"
        (keywords if f.kw_only else params).append(text)
    if keywords:
        params += ["*", *keywords]
    return f"({', '.join(params)}) -> None"


def _plain(cls) -> bool:
    """A class this module makes: dataclass bases only of this module's records, no
    ``InitVar``, ``ClassVar`` or ``KW_ONLY`` annotation, no field named like the method's
    own names, no ``__setattr__`` of its own; the others go to
    :func:`dataclasses.dataclass` unchanged."""
    if any(hasattr(b, "__dataclass_fields__") and not is_record(b) for b in cls.__mro__[1:]):
        return False
    own = cls.__dict__
    if "__setattr__" in own or "__delattr__" in own:
        return False
    for name, kind in own.get("__annotations__", {}).items():
        text = kind if isinstance(kind, str) else repr(kind)
        if (name == "self" or name.startswith("_") or "InitVar" in text
                or "ClassVar" in text or "KW_ONLY" in text):
            return False
    return True


def _collect(cls, frozen: bool, kw_only: bool) -> list[dataclasses.Field]:
    """The fields of a :func:`_plain` class, as :func:`dataclasses.dataclass` collects
    them: those of its dataclass bases (a frozen record's bases frozen, a mutable one's
    mutable), then a ``field()`` or a plain default per annotation of its own (one that
    a base has keeps its place), the class attribute set to the default or removed, a
    mutable default and a ``field()`` without annotation refused; stored where
    :func:`dataclasses.fields` finds them."""
    fields = {}
    bases = frozen_base = False
    for b in cls.__mro__[-1:0:-1]:
        base_fields = getattr(b, "__dataclass_fields__", None)
        if base_fields is not None:
            bases = True
            fields.update((f.name, f) for f in base_fields.values())
            frozen_base = frozen_base or b.__dataclass_params__.frozen
    own = cls.__dict__
    annotations = own.get("__annotations__", {})
    mine = []
    for name, kind in annotations.items():
        default = getattr(cls, name, MISSING)
        if isinstance(default, Field):
            f = default
        else:
            if isinstance(default, MemberDescriptorType):     # a __slots__ entry
                default = MISSING
            f = dataclasses.field(default=default)
        f.name, f.type, f._field_type = name, kind, _FIELD
        if f.kw_only is MISSING:
            f.kw_only = kw_only
        if f.default.__class__.__hash__ is None:
            raise ValueError(f"mutable default {type(f.default)} for field {name} is not "
                             "allowed: use default_factory")
        mine.append(f)
    for f in mine:
        fields[f.name] = f
        if isinstance(getattr(cls, f.name, None), Field):
            if f.default is MISSING:
                delattr(cls, f.name)
            else:
                setattr(cls, f.name, f.default)
    for name, value in own.items():
        if isinstance(value, Field) and name not in annotations:
            raise TypeError(f"{name!r} is a field but has no type annotation")
    if bases and frozen_base and not frozen:
        raise TypeError("cannot inherit non-frozen dataclass from a frozen one")
    if bases and not frozen_base and frozen:
        raise TypeError("cannot inherit frozen dataclass from a non-frozen one")
    cls.__dataclass_fields__ = fields
    return list(fields.values())


@lru_cache(maxsize=None)
def _params(frozen: bool, kw_only: bool):
    """The ``__dataclass_params__`` :func:`dataclasses.dataclass` gives a record of these
    options (``init``, ``repr`` and ``eq`` true), taken from an empty class it makes without
    methods (one for every record of the same options)."""

    class Probe:
        """A class for its parameters (documented: no signature is read for its doc)."""

    params = dataclasses.dataclass(Probe, init=False, repr=False, eq=False,
                                   kw_only=kw_only).__dataclass_params__
    params.init = params.repr = params.eq = True
    params.frozen = frozen
    return params


def _init(cls, fields, frozen: bool):
    """The ``__init__`` the standard library writes for ``fields``: the code of its
    :func:`shape` (:func:`shape_code`: kept beside the bytecode) with the names
    of ``fields`` put in; defaults as the function's defaults, factories in its globals."""
    scope = {"__factory": _HAS_FACTORY, "__set": object.__setattr__,
             "__name__": cls.__module__}
    defaults, kwdefaults = [], {}
    for i, f in enumerate(fields):
        if f.default_factory is not MISSING:
            scope[f"__f_{i}"] = f.default_factory
            default = _HAS_FACTORY
        else:
            default = f.default
        if not f.init:
            continue
        if f.kw_only:
            if default is not MISSING:
                kwdefaults[f.name] = default
        elif default is not MISSING:
            defaults.append(default)
        elif defaults:
            raise TypeError(f"non-default argument {f.name!r} follows default argument")
    key = shape(fields, frozen, hasattr(cls, "__post_init__"))
    code = shape_code(key)
    names = {f"_{i}": f.name for i, f in enumerate(fields)}
    code = code.replace(
        co_varnames=tuple(names.get(v, v) for v in code.co_varnames),
        co_names=tuple(names.get(v, v) for v in code.co_names),
        co_consts=tuple(names.get(c, c) if isinstance(c, str) else c
                        for c in code.co_consts))
    fn = FunctionType(code, scope, "__init__", tuple(defaults) or None)
    fn.__kwdefaults__ = kwdefaults or None
    fn.__annotations__ = {**{f.name: f.type for f in fields if f.init}, "return": None}
    return fn


def shape(fields, frozen: bool, post_init: bool) -> str:
    """What the ``__init__`` of a record does, whatever its names: ``f`` (frozen) or ``m``,
    then a letter a field: ``P`` a positional parameter (with or without a default, which
    the function holds), ``K`` a keyword-only one, ``F``/``G`` the same with a
    ``default_factory``, ``N`` a factory's value not in the signature, ``X`` nothing (a
    field not in the signature: its default is the class attribute); ``+``:
    ``__post_init__`` is called."""
    letters = []
    for f in fields:
        factory = f.default_factory is not MISSING
        if f.init:
            letters.append(("G" if factory else "K") if f.kw_only else ("F" if factory else "P"))
        else:
            letters.append("N" if factory else "X")
    return ("f" if frozen else "m") + "".join(letters) + ("+" if post_init else "")


def source(key: str) -> str:
    """The source of the ``__init__`` of :func:`shape` ``key``, field ``i`` named ``_i``:
    the statements :func:`dataclasses.dataclass` writes, without the defaults."""
    frozen, post_init = key[0] == "f", key.endswith("+")
    params, keywords, body = [], [], []
    for i, letter in enumerate(key[1:-1] if post_init else key[1:]):
        n = f"_{i}"
        if letter in "PF":
            params.append(n)
        elif letter in "KG":
            keywords.append(n)
        value = {"P": n, "K": n, "F": f"__f{n}() if {n} is __factory else {n}",
                 "N": f"__f{n}()", "X": None}.get(letter, f"__f{n}() if {n} is __factory else {n}")
        if value is not None:
            body.append(f"__set(self, {n!r}, {value})" if frozen else f"self.{n} = {value}")
    if keywords:
        params += ["*", *keywords]
    if post_init:
        body.append("self.__post_init__()")
    return (f"def __init__(self{''.join(', ' + p for p in params)}):\n    "
            + "\n    ".join(body or ["pass"]) + "\n")


def _compiled(key: str):
    """The code of :func:`source` ``key``."""
    scope: dict = {}
    exec(source(key), scope)
    return scope["__init__"].__code__


_SHAPES: dict | None = None
"""The code of each :func:`shape` this process has used, read from the cache beside the
bytecode at the first record (:func:`shape_code`)."""

_NEW: list[str] = []
"""The shapes this process compiled (written to the cache when it exits)."""


def _shapes_stamp() -> tuple:
    """What the kept shapes were compiled from: this module's source (:func:`source`)."""
    from geardesign.core import data

    return (1, data.stat(__file__))


def shape_code(key: str):
    """The code of the ``__init__`` of :func:`shape` ``key``: from the cache that
    :mod:`geardesign.core.data` keeps beside this module's bytecode, or compiled (about
    0.05 ms a shape, a hundred shapes for a drive) and added to that cache when the process
    exits, so that a later run compiles none.  The cache is stamped with this module's
    source, which writes the shapes."""
    global _SHAPES
    if _SHAPES is None:
        from geardesign.core import data

        _SHAPES = data.kept(Path(__file__), "shapes", _shapes_stamp()) or {}
    code = _SHAPES.get(key)
    if code is None:
        code = _SHAPES[key] = _compiled(key)
        if not _NEW:
            import atexit

            atexit.register(_keep_shapes)
        _NEW.append(key)
    return code


def _keep_shapes() -> None:
    """Add the shapes compiled here to the cache (with those another process kept since)."""
    from geardesign.core import data

    stamp = _shapes_stamp()
    merged = dict(data.kept(Path(__file__), "shapes", stamp) or {})
    merged.update({k: _SHAPES[k] for k in _NEW})
    data.keep(Path(__file__), "shapes", stamp, merged)


def is_record(cls) -> bool:
    """A class made by :func:`dataclass` here (not handed to the standard library)."""
    return getattr(getattr(cls, "__eq__", None), "__code__", None) is _eq(None).__code__


def record_shape(cls) -> str:
    """The :func:`shape` of a record made here."""
    return shape(dataclasses.fields(cls), cls.__dataclass_params__.frozen,
                 hasattr(cls, "__post_init__"))


class _HasFactory:
    def __repr__(self) -> str:
        return "<factory>"


_HAS_FACTORY = _HasFactory()


def _frozen_setattr(cls, names: frozenset):
    def __setattr__(self, name, value):
        if type(self) is cls or name in names:
            raise dataclasses.FrozenInstanceError(f"cannot assign to field {name!r}")
        super(cls, self).__setattr__(name, value)
    return __setattr__


def _frozen_delattr(cls, names: frozenset):
    def __delattr__(self, name):
        if type(self) is cls or name in names:
            raise dataclasses.FrozenInstanceError(f"cannot delete field {name!r}")
        super(cls, self).__delattr__(name)
    return __delattr__


def _set(cls, name: str, fn) -> None:
    fn.__qualname__ = f"{cls.__qualname__}.{name}"
    setattr(cls, name, fn)


def _values(names: list[str]):
    """The tuple of a record's values of ``names`` (C-speed for one or more names)."""
    if not names:
        return lambda self: ()
    get = attrgetter(*names)
    if len(names) == 1:
        return lambda self: (get(self),)
    return get


def _repr(names: list[str]):
    @recursive_repr()
    def __repr__(self) -> str:
        return (self.__class__.__qualname__ + "("
                + ", ".join(f"{n}={getattr(self, n)!r}" for n in names) + ")")
    return __repr__


def _eq(values):
    def __eq__(self, other):
        if other.__class__ is self.__class__:
            return values(self) == values(other)
        return NotImplemented
    return __eq__


def _hash(values):
    def __hash__(self) -> int:
        return hash(values(self))
    return __hash__

