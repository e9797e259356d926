"""geardesign.core.records.dataclass makes the records the standard library would: the same
signature, fields, hashability and frozenness for every record of the package, and the
same construction, repr, equality, hash, asdict, replace and refusals on records that use
every feature (defaults, factories, init=False fields, __post_init__, compare/hash/repr
flags, methods of their own, subclasses)."""

from __future__ import annotations

import copy
import dataclasses
import importlib
import inspect
import marshal
import os
import pkgutil
import subprocess
import sys
import typing
from dataclasses import field
from pathlib import Path

import pytest

import geardesign
from geardesign.core import records


def _package_records() -> list[type]:
    out = []
    for m in pkgutil.walk_packages(geardesign.__path__, "geardesign."):
        module = importlib.import_module(m.name)
        for obj in vars(module).values():
            if (isinstance(obj, type) and obj.__module__ == m.name
                    and dataclasses.is_dataclass(obj) and records.is_record(obj)):
                out.append(obj)
    return out


RECORDS = _package_records()


def _twin(cls: type) -> type:
    """The standard library's dataclass of the same fields."""
    specs = []
    for f in dataclasses.fields(cls):
        kw = dict(init=f.init, repr=f.repr, compare=f.compare, hash=f.hash, kw_only=f.kw_only)
        if f.default is not dataclasses.MISSING:
            kw["default"] = f.default
        if f.default_factory is not dataclasses.MISSING:
            kw["default_factory"] = f.default_factory
        specs.append((f.name, f.type, field(**kw)))
    return dataclasses.make_dataclass(cls.__name__, specs,
                                      frozen=cls.__dataclass_params__.frozen)


def test_the_package_makes_its_records_here():
    assert len(RECORDS) > 200


@pytest.mark.parametrize("cls", RECORDS, ids=lambda c: f"{c.__module__}.{c.__qualname__}")
def test_a_record_is_the_standard_librarys(cls):
    twin = _twin(cls)
    assert str(inspect.signature(cls)) == str(inspect.signature(twin))
    assert records._signature(cls, dataclasses.fields(cls)) == str(inspect.signature(cls))
    assert cls.__match_args__ == twin.__match_args__
    assert (cls.__hash__ is None) == (twin.__hash__ is None)
    params = cls.__dataclass_params__
    assert params.init and params.repr and params.eq
    if "__doc__" not in vars(cls) or cls.__doc__.startswith(cls.__name__ + "("):
        assert cls.__doc__ == twin.__doc__
    # the fields are those the standard library would collect: no annotation of the class
    # is a ClassVar, InitVar or KW_ONLY under any name (its own test of string annotations)
    for name, kind in vars(cls).get("__annotations__", {}).items():
        for marker, test in ((typing.ClassVar, dataclasses._is_classvar),
                             (dataclasses.InitVar, dataclasses._is_initvar),
                             (dataclasses.KW_ONLY, dataclasses._is_kw_only)):
            module = typing if marker is typing.ClassVar else dataclasses
            assert not test(kind, module)
            assert not (isinstance(kind, str)
                        and dataclasses._is_type(kind, cls, module, marker, test)), name


def test_every_record_shape_is_the_code_of_its_source():
    """The ``__init__`` code of each record's shape is what its source compiles to."""
    for key in {records.record_shape(c) for c in RECORDS}:
        scope: dict = {}
        exec(records.source(key), scope)
        assert scope["__init__"].__code__.co_code == records.shape_code(key).co_code, key


_RUN = ("import geardesign.drive.calculator, geardesign.bevel.calculator; "
        "from geardesign.core import records; print(len(records._NEW))")


def _compiled_in_a_run(prefix, dont_write: bool = False) -> int:
    env = {**os.environ, "PYTHONPYCACHEPREFIX": str(prefix)}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    if dont_write:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    out = subprocess.run([sys.executable, "-c", _RUN], env=env, capture_output=True,
                         text=True, check=True, cwd=Path(__file__).resolve().parent.parent)
    return int(out.stdout)


def test_the_shapes_compiled_once_are_kept_beside_the_bytecode(tmp_path):
    """A run compiles the shapes it uses and keeps them with the bytecode (here under a
    PYTHONPYCACHEPREFIX); the next run compiles none; nothing is kept when Python writes no
    bytecode; a cache of another source of records.py is not used."""
    assert _compiled_in_a_run(tmp_path / "none", dont_write=True) > 20
    assert _compiled_in_a_run(tmp_path / "none", dont_write=True) > 20
    first = _compiled_in_a_run(tmp_path / "kept")
    assert first > 20
    assert _compiled_in_a_run(tmp_path / "kept") == 0
    (cache,) = (tmp_path / "kept").rglob("records.py.shapes.*.data")
    stamp, kept = marshal.loads(cache.read_bytes())
    assert len(kept) == first and stamp == records._shapes_stamp()
    cache.write_bytes(marshal.dumps(((0,), kept)))        # another source: compiled again
    assert _compiled_in_a_run(tmp_path / "kept") == first
    cache.write_bytes(b"not marshal")                      # unreadable: compiled again
    assert _compiled_in_a_run(tmp_path / "kept") == first


def _make(deco):
    @deco(frozen=True)
    class A:
        """A record with every feature."""
        a: float
        b: int = 2
        c: tuple = ()
        d: list = field(default_factory=list)
        e: float = field(default=1.0, compare=False, repr=False)
        f: dict = field(default_factory=dict, init=False)
        g: str = field(default="x", init=False)
        h: float = field(default=0.0, hash=False)
        k: int = field(default=4, kw_only=True)
        m: str = field(kw_only=True, default="m")

        def __post_init__(self):
            object.__setattr__(self, "f", {"k": self.a})

    @deco
    class B:
        x: int
        y: list = field(default_factory=lambda: [1])

    @deco(frozen=True)
    class C:
        v: float

        def __eq__(self, other):
            return True

    @deco(frozen=True)
    class D:
        pass

    @dataclasses.dataclass(frozen=True)
    class E(A):
        q: int = 3

    @deco(frozen=True, kw_only=True)
    class F:
        u: float
        w: float = 2.0

    @deco(frozen=True)
    class G(A):
        """A record of a record: its fields after A's, c's default its own."""
        q: int = 3
        c: tuple = (1,)

    return {"A": (A, [(1.0,), (1.0, 3, (1,), [2], 5.0, 0.5)]), "B": (B, [(1,), (2, [3])]),
            "C": (C, [(1.0,)]), "D": (D, [()]), "E": (E, [(1.0,), (2.0, 1)]), "F": (F, [()]),
            "G": (G, [(1.0,), (2.0, 1, (3,), [4], 5.0, 0.5, 7)])}


OURS, THEIRS = _make(records.dataclass), _make(dataclasses.dataclass)


def _hash(obj):
    try:
        return hash(obj)
    except TypeError as exc:
        return str(exc)


@pytest.mark.parametrize("name", sorted(OURS))
def test_records_behave_as_dataclasses(name):
    ours, cases = OURS[name]
    theirs, _ = THEIRS[name]
    assert str(inspect.signature(ours)) == str(inspect.signature(theirs))
    assert ours.__doc__ == theirs.__doc__
    for args in cases:
        if name == "F":       # keyword-only
            args, kwargs = (), {"u": 1.0}
            x, y = ours(**kwargs), theirs(**kwargs)
            assert repr(x) == repr(y) and x == ours(**kwargs) and hash(x) == hash(ours(**kwargs))
            continue
        x, y = ours(*args), theirs(*args)
        assert repr(x) == repr(y) and vars(x) == vars(y)
        assert dataclasses.asdict(x) == dataclasses.asdict(y)
        assert (x == ours(*args), x != ours(*args)) == (y == theirs(*args), y != theirs(*args))
        assert (x == y) is False or name == "C"
        assert (_hash(x) == _hash(ours(*args))) == (_hash(y) == _hash(theirs(*args)))
        assert repr(copy.deepcopy(x)) == repr(x)
        first = dataclasses.fields(ours)[0].name if dataclasses.fields(ours) else None
        if first is not None:
            assert repr(dataclasses.replace(x, **{first: 9})) == repr(
                dataclasses.replace(y, **{first: 9}))
        if ours.__dataclass_params__.frozen and first is not None:
            for obj in (x, y):
                with pytest.raises(dataclasses.FrozenInstanceError):
                    setattr(obj, first, 0)
                with pytest.raises(dataclasses.FrozenInstanceError):
                    delattr(obj, first)


def test_a_record_of_a_record_is_made_here_and_frozenness_must_match():
    assert records.is_record(OURS["G"][0])
    assert [f.name for f in dataclasses.fields(OURS["G"][0])] == [
        f.name for f in dataclasses.fields(THEIRS["G"][0])]
    for deco in (records.dataclass, dataclasses.dataclass):
        @deco
        class Mutable:
            a: int = 1

        @deco(frozen=True)
        class Frozen:
            a: int = 1

        with pytest.raises(TypeError, match="cannot inherit frozen dataclass from a non-frozen"):
            deco(frozen=True)(type("X", (Mutable,), {"__annotations__": {"b": int}, "b": 2}))
        with pytest.raises(TypeError, match="cannot inherit non-frozen dataclass from a frozen"):
            deco(type("Y", (Frozen,), {"__annotations__": {"b": int}, "b": 2}))


def test_a_missing_argument_and_a_default_before_a_plain_field_are_refused():
    with pytest.raises(TypeError, match="missing 1 required positional argument: 'a'"):
        OURS["A"][0]()

    class Bad:
        a: int = 1
        b: int

    with pytest.raises(TypeError, match="non-default argument 'b' follows default argument"):
        records.dataclass(Bad)


