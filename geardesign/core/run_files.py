"""The files of the running command: what it has read as inputs and what it has written,
so that no output replaces either (:func:`geardesign.core.atomic.target_problem`).

The reader (:func:`geardesign.core.io.read_regular`) keeps each spec, stage file and
model it reads; the writer (:class:`geardesign.core.atomic.AtomicFile`) each file it has
written; the command line opens the scope of one command (:func:`inputs_kept`).  Outside
a command (the library) nothing is kept.  Files are known by device and inode: a link or
a hard link to a file is that file.
"""

from __future__ import annotations

import os
import stat
from contextlib import contextmanager
from typing import Iterator


_INPUTS: dict | None = None
"""The files the running command has read as inputs or written: (device, inode) -> (the
path, ``"input"`` or ``"output"``); ``None`` outside a command (:func:`inputs_kept`)."""


@contextmanager
def inputs_kept() -> Iterator[None]:
    """The scope of one command: every file read as an input in it
    (:func:`geardesign.core.io.read_regular`) and every file it writes
    (:class:`geardesign.core.atomic.AtomicFile`) is remembered (:func:`keep_file`), and
    :func:`geardesign.core.atomic.target_problem` refuses to write over any of them
    again."""
    global _INPUTS
    saved, _INPUTS = _INPUTS, {}
    try:
        yield
    finally:
        _INPUTS = saved


def keep_file(st: os.stat_result, path, role: str = "input") -> None:
    """Remember the regular file ``path`` (its ``os.stat`` result ``st``) as an ``"input"``
    or ``"output"`` of the running command, if a command is running (:func:`inputs_kept`)."""
    if _INPUTS is not None and stat.S_ISREG(st.st_mode):
        _INPUTS.setdefault((st.st_dev, st.st_ino), (str(path), role))


def overwrite_problem(st: os.stat_result, inputs) -> str | None:
    """Why the file of ``st`` must not be written by the running command, or None: it is
    one of the paths ``inputs`` or a file the command has read or written already (the same
    device and inode: the file itself, a link or a hard link to it)."""
    here = (st.st_dev, st.st_ino)
    for given in inputs:
        if given is None or str(given) == "-":
            continue
        try:
            other = os.stat(given)
        except (OSError, ValueError):
            continue
        if (other.st_dev, other.st_ino) == here:
            return _AS_INPUT.format(given)
    kept = None if _INPUTS is None else _INPUTS.get(here)
    if kept is None:
        return None
    return (_AS_INPUT if kept[1] == "input" else _AS_OUTPUT).format(kept[0])


_AS_INPUT = "it is {}, which this run reads as an input; write the output to another file"
_AS_OUTPUT = "it is {}, which this run has written already; give each output its own file"
