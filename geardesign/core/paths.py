"""A path with its links followed, for every path a user gives (a spec, a stage file, an
output, an expected document)."""

from __future__ import annotations

import errno
from pathlib import Path


def resolved(path) -> Path:
    """``Path(path).resolve()``, with a loop of symbolic links raised as the ``OSError``
    (ELOOP) that opening such a path raises, instead of the ``RuntimeError`` of
    :meth:`pathlib.Path.resolve` before Python 3.13: every caller already says an
    unusable path in one line.

    >>> import os, tempfile
    >>> d = tempfile.mkdtemp()
    >>> os.symlink(os.path.join(d, "b"), os.path.join(d, "a"))
    >>> os.symlink(os.path.join(d, "a"), os.path.join(d, "b"))
    >>> try:
    ...     resolved(os.path.join(d, "a"))
    ... except OSError as exc:
    ...     print(exc.strerror)
    a loop of symbolic links
    """
    try:
        return Path(path).resolve()
    except RuntimeError:
        raise OSError(errno.ELOOP, "a loop of symbolic links", str(path)) from None
