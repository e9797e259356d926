"""Records made cheaply: :func:`dataclass`, a drop-in for :func:`dataclasses.dataclass`.

Python 3.11 builds every method of a dataclass by compiling its source text when the class
is created: six for a frozen record (``__init__``, ``__repr__``, ``__eq__``, ``__hash__``,
``__setattr__``, ``__delattr__``), about 0.8 ms a record on the test machine, and a spur run
creates some 40 records, a designed gearbox some 130 (issue 32: a quarter of a small spec's
start-up).  Here only ``__init__`` is compiled, the same code the standard library writes
(defaults, ``default_factory``, ``init=False`` fields, ``__post_init__``); ``__repr__``,
``__eq__``, ``__hash__`` and a frozen record's ``__setattr__``/``__delattr__`` are shared
functions over the record's field names that print, compare, hash and refuse exactly as the
generated ones do (``compare``/``hash``/``repr`` of :func:`dataclasses.field` honoured,
methods the class defines itself kept, ``__hash__`` set as :func:`dataclasses.dataclass`
sets it), and ``__dataclass_params__`` says what the record is.  The standard library
still collects the fields, so :func:`dataclasses.fields`, ``asdict``, ``replace`` and a
dataclass subclass work as on any dataclass; a class with a dataclass base, an
``InitVar``, ``ClassVar`` or ``KW_ONLY`` annotation, a field named ``self`` or ``_...``, or
options beyond ``frozen`` and ``kw_only`` goes to :func:`dataclasses.dataclass` unchanged.
tests/test_records.py compares both on every record of the package.
"""

from __future__ import annotations

import dataclasses
from operator import attrgetter
from reprlib import recursive_repr


def dataclass(cls=None, /, *, frozen: bool = False, kw_only: bool = False, **options):
    """:func:`dataclasses.dataclass` with one method compiled per class instead of six
    (see the module)."""

    def wrap(cls):
        if options or not _plain(cls):
            return dataclasses.dataclass(cls, frozen=frozen, kw_only=kw_only, **options)
        own = cls.__dict__
        class_hash = own.get("__hash__", dataclasses.MISSING)
        explicit_hash = not (class_hash is dataclasses.MISSING
                             or (class_hash is None and "__eq__" in own))
        documented = bool(own.get("__doc__"))
        cls = dataclasses.dataclass(cls, init=False, repr=False, eq=False, kw_only=kw_only)
        fields = dataclasses.fields(cls)
        _set(cls, "__init__", _init(cls, fields, frozen))
        if not documented:     # as dataclasses writes it: the name and the signature
            import inspect

            cls.__doc__ = cls.__name__ + str(inspect.signature(cls)).replace(" -> None", "")
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
        params = cls.__dataclass_params__
        params.init = params.repr = params.eq = True
        params.frozen = frozen
        return cls

    return wrap if cls is None else wrap(cls)


def _plain(cls) -> bool:
    """A class this module makes: no dataclass base (frozen or not, the standard library
    checks the pair), no ``InitVar``, ``ClassVar`` or ``KW_ONLY`` annotation, no field
    named like the method's own names, no ``__setattr__`` of its own; the others go to
    :func:`dataclasses.dataclass` unchanged."""
    if any(hasattr(b, "__dataclass_fields__") for b in cls.__mro__[1:]):
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


def _init(cls, fields, frozen: bool):
    """The ``__init__`` the standard library writes for ``fields``, compiled once."""
    scope = {"__factory": _HAS_FACTORY, "__set": object.__setattr__}
    params, keywords, body, defaulted = [], [], [], False
    for f in fields:
        n = f.name
        if f.default_factory is not dataclasses.MISSING:
            scope[f"__f_{n}"] = f.default_factory
            value = f"__f_{n}() if {n} is __factory else {n}" if f.init else f"__f_{n}()"
            param = f"{n}=__factory"
        elif f.default is not dataclasses.MISSING:
            scope[f"__d_{n}"] = f.default
            value = n if f.init else None       # the class attribute holds the default
            param = f"{n}=__d_{n}"
        else:
            value = n if f.init else None
            param = n
            if f.init and not f.kw_only and defaulted:
                raise TypeError(f"non-default argument {n!r} follows default argument")
        if f.init:
            (keywords if f.kw_only else params).append(param)
            defaulted = defaulted or (param != n and not f.kw_only)
        if value is not None:
            body.append(f"__set(self, {n!r}, {value})" if frozen else f"self.{n} = {value}")
    if keywords:
        params += ["*", *keywords]
    if hasattr(cls, "__post_init__"):
        body.append("self.__post_init__()")
    text = (f"def __init__(self, {', '.join(params)}):\n    "
            + "\n    ".join(body or ["pass"]) + "\n")
    exec(text, scope)
    fn = scope["__init__"]
    fn.__annotations__ = {**{f.name: f.type for f in fields if f.init}, "return": None}
    return fn


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
