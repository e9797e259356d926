"""Files in and out: the one guarded reader and the one atomic writer.

Every file the tool reads (a spec, a stage file, the ``*.expected.json`` of ``geardesign
check``) goes through :func:`read_regular`; every file it writes (``--output``, ``--data``,
``--plot``, ``--profile``, ``check --update``, the plot a pzdn spec names) goes through
:func:`atomic_path` / :class:`AtomicFile`, after :func:`check_target` has looked at the
target before the work starts.

Reading
    * only a regular file: the type is checked on the open descriptor before a byte is
      read, so a FIFO or a device never blocks and is never read without bound;
    * at most ``limit`` bytes (a spec 4 MiB, an expected document 32 MiB), checked on the
      size and again while reading;
    * TOML: dotted keys of at most :data:`MAX_KEY_PARTS` parts and at most
      :data:`MAX_TABLE_HEADERS` table headers, counted before the parser sees the text
      (the parser's cost grows with the square of a dotted key's length);
    * JSON: nesting at most :data:`MAX_JSON_DEPTH` deep;
    * confinement (:func:`confined`): a file a spec refers to lies inside the spec's folder;
    * within a command, each spec, stage file and model read is remembered
      (:mod:`geardesign.core.run_files`): no output of the command replaces it.

Writing: :mod:`geardesign.core.atomic` (its names are importable from here too).
"""

from __future__ import annotations

import json
import os
import re
import stat
from pathlib import Path
from typing import Any

from geardesign.core.errors import InputError, Problem

MiB = 1024 * 1024
MAX_SPEC_BYTES = 4 * MiB
"""A spec or stage file larger than this is refused before it is parsed (real specs are a
few kB)."""
MAX_JSON_BYTES = 32 * MiB
"""An expected result document larger than this is refused unread (the largest example's is
0.3 MiB)."""
MAX_JSON_DEPTH = 64
"""Nesting of arrays and objects in a JSON document read (a result document nests about 8
deep)."""
MAX_KEY_PARTS = 32
"""Parts of one dotted TOML key (``a.b.c`` has 3); a spec's tables nest at most 5 deep."""
MAX_TABLE_HEADERS = 10_000
"""``[table]`` and ``[[array]]`` headers in one TOML file."""


class FileRefused(OSError):
    """A path that is not a regular file of a sensible size."""


# --------------------------------------------------------------------------- reading

def read_regular(path: Path, limit: int, what: str = "a spec is a few kB",
                 source: bool = True) -> bytes:
    """The bytes of the regular file ``path`` of at most ``limit`` bytes; ``source``: the
    file is an input of the design (a spec, a stage file, a model), which the running
    command must not overwrite (:func:`geardesign.core.run_files.keep_file`); an expected
    document that ``check --update`` replaces is not.

    Raises :class:`FileRefused` (not a regular file, too large; ``what`` says what a
    sensible size is), ``IsADirectoryError``, ``FileNotFoundError`` or another ``OSError``."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise IsADirectoryError(21, "Is a directory", str(path))
        if not stat.S_ISREG(st.st_mode):
            raise FileRefused("not a regular file")
        if source:
            from geardesign.core.run_files import keep_file

            keep_file(st, path)
        too_large = FileRefused(f"larger than {_size(limit)}; {what}")
        if st.st_size > limit:
            raise too_large
        chunks, total = [], 0
        while True:
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                break
            total += len(chunk)
            if total > limit:
                raise too_large
            chunks.append(chunk)
        return b"".join(chunks)
    finally:
        os.close(fd)


def _size(n: int) -> str:
    return f"{n // MiB} MiB" if n >= MiB else f"{n} bytes"


def read_problem(exc: OSError, kind: str = "spec file") -> Problem:
    """The one line of an unreadable file (no key: it concerns the whole file)."""
    if isinstance(exc, FileNotFoundError):
        return Problem("", "file not found")
    if isinstance(exc, IsADirectoryError):
        return Problem("", f"is a directory, not a {kind}")
    if isinstance(exc, FileRefused):
        return Problem("", f"cannot be used: {exc}")
    return Problem("", f"cannot be read ({exc.strerror or exc})")


def decode(raw: bytes) -> str:
    """UTF-8 text; a file that is not is one :class:`InputError` line."""
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(Problem("", f"not UTF-8 text (byte {exc.start})")) from None


def read_toml(path: Path) -> dict:
    """A TOML spec or stage file through :func:`read_regular` and :func:`parse_toml`;
    every problem is one :class:`InputError` line."""
    try:
        raw = read_regular(path, MAX_SPEC_BYTES)
    except OSError as exc:
        raise InputError(read_problem(exc)) from None
    return parse_toml(decode(raw))


_STRINGS = re.compile(r'"""[\s\S]*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|\'[^\'\n]*\'')
_PART = r"""(?:[A-Za-z0-9_-]+|"[^"\n]*"|'[^'\n]*')"""
_HEADER = re.compile(r"^[ \t]*\[\[?[ \t]*[A-Za-z_\"']", re.M)


def toml_bounds(text: str) -> str | None:
    """Why ``text`` is refused before it is parsed, or ``None``: a dotted key of more than
    :data:`MAX_KEY_PARTS` parts, or more than :data:`MAX_TABLE_HEADERS` table headers.
    Strings are left out of the count (a title may hold dots)."""
    bare = _STRINGS.sub('""', text)
    run = re.search(r"(?:%s[ \t]*\.[ \t]*){%d,}%s" % (_PART, MAX_KEY_PARTS, _PART), bare)
    if run is not None:
        return (f"a dotted key of more than {MAX_KEY_PARTS} parts (line "
                f"{bare.count(chr(10), 0, run.start()) + 1}); a spec's tables nest a few deep")
    headers = len(_HEADER.findall(bare))
    if headers > MAX_TABLE_HEADERS:
        return f"{headers} table headers, more than {MAX_TABLE_HEADERS}"
    return None


def parse_toml(text: str) -> dict:
    """Parse TOML text after :func:`toml_bounds`; a syntax error or nesting deeper than the
    parser can follow is one :class:`InputError` line."""
    import tomllib

    from geardesign.core.text import escape_controls

    why = toml_bounds(text)
    if why is not None:
        raise InputError(Problem("", f"cannot be used: {why}"))
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(Problem("", f"not valid TOML: {escape_controls(str(exc))}")) from None
    except RecursionError:
        raise InputError(Problem("", "arrays or tables nested too deeply to be a spec")) from None


def read_json(path: Path, limit: int = MAX_JSON_BYTES,
              what: str = "a result document is well under 1 MiB", label: str = "") -> Any:
    """A JSON document through :func:`read_regular`, nested at most :data:`MAX_JSON_DEPTH`
    deep; ``FileNotFoundError`` passes, every other problem is one :class:`InputError`
    (its message begins with ``label``, when given, to name the file)."""
    def refuse(problem: Problem) -> InputError:
        return InputError(Problem("", f"{label}: {problem.message}" if label
                                  else problem.message))

    try:
        raw = read_regular(path, limit, what, source=False)
    except FileNotFoundError:
        raise
    except OSError as exc:
        raise refuse(read_problem(exc, "JSON file")) from None
    try:
        doc = json.loads(decode(raw))
    except InputError as exc:
        raise refuse(exc.problems[0]) from None
    except RecursionError:
        doc, deep = None, True
    except ValueError as exc:
        raise refuse(Problem("", f"not valid JSON: {exc}")) from None
    else:
        deep = _depth(doc) > MAX_JSON_DEPTH
    if deep:
        raise refuse(Problem("", f"cannot be used: arrays or objects nested more than "
                                 f"{MAX_JSON_DEPTH} deep"))
    return doc


def _depth(doc: Any) -> int:
    """Nesting depth of a parsed JSON value, without recursion."""
    deepest, stack = 0, [(doc, 0)]
    while stack:
        node, d = stack.pop()
        deepest = max(deepest, d)
        if d > MAX_JSON_DEPTH:
            break
        if isinstance(node, dict):
            stack.extend((v, d + 1) for v in node.values())
        elif isinstance(node, list):
            stack.extend((v, d + 1) for v in node)
    return deepest


def confined(name: str, base: Path | None, root: Path | None, what: str) -> Path:
    """The file ``name`` a spec refers to, relative to ``base``, resolved (links followed);
    ``ValueError`` when it is absolute or lies outside ``root`` (``..``, a link pointing
    elsewhere).  ``what`` names the folder in the message ("the drive spec's folder")."""
    from geardesign.core.paths import resolved

    path = Path(name)
    if path.is_absolute():
        raise ValueError(f"must be a path relative to {what}")
    if base is not None:
        path = base / path
    try:
        path = resolved(path)
        if root is not None:
            path.relative_to(resolved(root))
    except OSError as exc:
        raise ValueError(f"cannot be used ({exc.strerror})") from None
    except ValueError:
        raise ValueError(f"must be a file inside {what}") from None
    return path


_WRITERS = {"target_problem", "check_target", "signals_deferred", "worker_signals",
            "AtomicFile", "atomic_path", "write_atomic"}


def __getattr__(name: str):
    # the one atomic writer (geardesign.core.atomic), imported when asked for
    if name in _WRITERS:
        from geardesign.core import atomic

        return getattr(atomic, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
