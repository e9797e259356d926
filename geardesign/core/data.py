"""The data files shipped with the package (tables, catalogues, material libraries), read
once and kept parsed beside the bytecode.

A table is a TOML or CSV file: the data, with its sources, as people read and review it.
Parsing it costs more than the calculation that uses it (the gear steel library, some
15 000 characters of TOML, takes longer to read than to rate a spur pair), so
:func:`parsed` keeps what the parser returned in the package's ``__pycache__`` folder, as
Python keeps compiled modules there: ``<file>.<parser>.<cache tag>.data``, in
:mod:`marshal` format, stamped with the size and modification time of the data file and of
the modules that hold the parser.  A stamp that differs, a cache that cannot be read, or a
value that :mod:`marshal` cannot write (only ``None``, booleans, numbers, strings, lists,
tuples and dicts) means the file is parsed again; nothing is written when Python writes no
bytecode (``PYTHONDONTWRITEBYTECODE``, ``-B``) or the folder is not writable, and
``PYTHONPYCACHEPREFIX`` moves the cache with the bytecode.
"""

from __future__ import annotations

import marshal
import os
import sys
from pathlib import Path
from typing import Any, Callable

_FORMAT = 1
"""Version of the cache layout (a change makes every cache stale)."""


def toml_table(path: Path) -> dict:
    """The content of the TOML data file ``path`` (:func:`parsed` by :mod:`tomllib`)."""
    return parsed(path, _toml)


def _toml(text: str) -> dict:
    import tomllib

    return tomllib.loads(text)


def csv_table(path: Path) -> list[dict[str, str]]:
    """The rows of the CSV data file ``path`` as dicts by the header's names (lines that
    begin with ``#`` are comments), :func:`parsed`."""
    return parsed(path, csv_rows)


def csv_rows(text: str) -> list[dict[str, str]]:
    """The rows of a CSV text as :func:`csv_table` reads them."""
    import csv

    return list(csv.DictReader(
        line for line in text.splitlines(keepends=True) if not line.startswith("#")))


def parsed(path: Path, parse: Callable[[str], Any]) -> Any:
    """``parse(text of path)``, from the cache beside the bytecode when it is current (see
    the module); the value is a fresh object either way (no caller shares it)."""
    path = Path(path)
    stamp = _stamp(path, parse)
    cache = _cache_file(path, parse)
    if cache is not None:
        try:
            with open(cache, "rb") as f:
                kept, value = marshal.loads(f.read())
            if kept == stamp:
                return value
        except (OSError, EOFError, ValueError, TypeError):
            pass                       # no cache yet, or one of another layout: parse
    value = parse(path.read_text(encoding="utf-8"))
    if cache is not None and not sys.dont_write_bytecode:
        _write(cache, stamp, value)
    return value


def kept(owner: Path, name: str, stamp: tuple) -> Any:
    """The value :func:`keep` last kept for ``owner`` under ``name`` with this ``stamp``
    (``None`` when there is none, or it was kept with another stamp, or cannot be read):
    a cache beside the bytecode for what a module makes from its own source."""
    cache = _cache_name(Path(owner), name)
    if cache is None:
        return None
    try:
        with open(cache, "rb") as f:
            was, value = marshal.loads(f.read())
    except (OSError, EOFError, ValueError, TypeError):
        return None
    return value if was == stamp else None


def keep(owner: Path, name: str, stamp: tuple, value: Any) -> None:
    """Keep ``value`` (anything :mod:`marshal` writes, code objects included) for
    :func:`kept`; nothing is written when Python writes no bytecode."""
    cache = _cache_name(Path(owner), name)
    if cache is not None and not sys.dont_write_bytecode:
        _write(cache, stamp, value)


def stat(path) -> tuple[int, int]:
    """The modification time [ns] and size of ``path``: the stamp of a file's content."""
    return _stat(path)


def _stamp(path: Path, parse: Callable) -> tuple:
    """What the cache must match: the data file, the module of the parser and this one
    (whose readers a parser may call)."""
    module = sys.modules.get(parse.__module__)
    source = getattr(module, "__file__", None)
    return (_FORMAT, _stat(path), _stat(source) if source else None, _stat(__file__),
            parse.__qualname__)


def _stat(path) -> tuple[int, int]:
    st = os.stat(path)
    return st.st_mtime_ns, st.st_size


def _cache_file(path: Path, parse: Callable) -> Path | None:
    """``__pycache__/<file>.<parser>.<cache tag>.data`` beside ``path`` (or under
    ``sys.pycache_prefix``, as the bytecode is), or ``None`` when Python keeps none."""
    return _cache_name(path, parse.__qualname__.strip('_') or 'parse')


def _cache_name(path: Path, what: str) -> Path | None:
    """``__pycache__/<file>.<what>.<cache tag>.data`` beside ``path`` (see
    :func:`_cache_file`)."""
    tag = sys.implementation.cache_tag
    if tag is None:
        return None
    name = f"{path.name}.{what}.{tag}.data"
    folder = path.resolve().parent
    if sys.pycache_prefix:
        return Path(sys.pycache_prefix, *folder.parts[1:], name)
    return folder / "__pycache__" / name


def _write(cache: Path, stamp: tuple, value: Any) -> None:
    """Write the cache atomically (a reader sees the old file or the new one); a value
    :mod:`marshal` cannot write, or a folder that cannot be written, leaves none."""
    try:
        data = marshal.dumps((stamp, value))
    except ValueError:
        return
    tmp = cache.with_name(f"{cache.name}.{os.getpid()}.tmp")
    try:
        cache.parent.mkdir(parents=True, exist_ok=True)
        tmp.write_bytes(data)
        os.replace(tmp, cache)
    except OSError:
        try:
            tmp.unlink()
        except OSError:
            pass
