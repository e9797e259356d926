"""The one atomic writer: every file the tool writes (``--output``, ``--data``, ``--plot``,
``--profile``, ``check --update``, the plot a pzdn spec names) goes through
:func:`atomic_path` / :class:`AtomicFile`, after :func:`check_target` has looked at the
target before the work starts (the readers are :mod:`geardesign.core.io`).

* the target is checked first (:func:`check_target`): a missing folder, a folder where
  a file is wanted, a folder that cannot be written is one line before the work starts;
* no output replaces an input of the same run: a spec, a stage file, a REXS model (or a
  link or hard link to one) named on the command line is refused before the work starts,
  and any file read as an input during a command (:func:`geardesign.core.run_files.inputs_kept`,
  recorded by :func:`geardesign.core.io.read_regular`) is refused when it is written; nor
  does one output replace another written by the same command;
* the data go to a temporary file beside the target, flushed to disk, then renamed over
  it in one step: a reader never sees half a file;
* the temporary file is covered by the signal handlers from its creation (the signals
  are blocked while it is created and registered): SIGINT, SIGTERM or SIGHUP remove it;
  SIGINT then ends the run as a KeyboardInterrupt (one line, exit 130), the others with
  the signal's default action.
"""

from __future__ import annotations

import os
import signal
import stat
import threading
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator

from geardesign.core.errors import InputError, Problem


def target_problem(path: Path, inside: Path | None = None, inputs=()) -> str | None:
    """Why ``path`` cannot be written, or ``None``.  Looked at before the work starts: the
    folder must exist and be writable, the path must not be a folder; with ``inside``, the
    file written (a link followed) must lie in that folder; the file must not be one of
    ``inputs`` (the paths the command was given to read) nor a file the running command
    has read as an input (:func:`geardesign.core.run_files.inputs_kept`)."""
    from geardesign.core.paths import resolved

    path = Path(path)
    try:
        real = resolved(path) if path.is_symlink() else path
    except OSError as exc:
        return f"is {exc.strerror}"
    if inside is not None:
        try:
            resolved(real).relative_to(resolved(inside))
        except (ValueError, OSError):
            return (f"is a link to a file outside {inside}; remove the link or write "
                    f"that file yourself")
    try:
        st = os.stat(real)
    except FileNotFoundError:
        st = None
    except NotADirectoryError:
        return "a part of the path is a file, not a folder"
    except OSError as exc:
        return f"cannot be written ({exc.strerror})"
    if st is not None and stat.S_ISDIR(st.st_mode):
        return "is a folder; give a file name"
    if st is not None and not stat.S_ISREG(st.st_mode):
        return None          # /dev/null, a FIFO, a terminal: written directly
    if st is not None:
        from geardesign.core.run_files import overwrite_problem

        why = overwrite_problem(st, inputs)
        if why is not None:
            return why
    folder = real.parent if str(real.parent) else Path(".")
    if not folder.exists():
        return f"the folder {folder} does not exist"
    if not folder.is_dir():
        return f"{folder} is a file, not a folder"
    if not os.access(folder, os.W_OK | os.X_OK):
        return f"the folder {folder} cannot be written"
    return None


def check_target(path: Path, inside: Path | None = None, label: str = "", inputs=()) -> None:
    """Raise :class:`InputError` (one line) when :func:`target_problem` finds a reason;
    ``label`` names the file when the line's source is another (the spec)."""
    why = target_problem(path, inside, inputs)
    if why is not None:
        raise InputError(Problem("", f"{label}: cannot write: {why}" if label else why))


_HANDLED = tuple(getattr(signal, s) for s in ("SIGINT", "SIGTERM", "SIGHUP")
                 if hasattr(signal, s))
_LIVE: set = set()
_PREVIOUS: dict = {}


def _on_signal(signum, frame) -> None:
    """Remove every temporary file being written, then do what the handler before ours
    would have done: a Python handler is called, SIGINT becomes a KeyboardInterrupt, any
    other signal its default action."""
    previous = _PREVIOUS.get(signum)
    _remove_live()
    if callable(previous):
        previous(signum, frame)
        return
    if signum == signal.SIGINT:
        raise KeyboardInterrupt
    if previous == signal.SIG_IGN:
        return
    signal.signal(signum, signal.SIG_DFL)
    os.kill(os.getpid(), signum)


def _remove_live() -> None:
    for tmp in list(_LIVE):
        try:
            os.unlink(tmp)
        except OSError:
            pass
        _LIVE.discard(tmp)
    _restore()


def _restore() -> None:
    for sig, handler in list(_PREVIOUS.items()):
        try:
            signal.signal(sig, handler)
        except (ValueError, TypeError):
            pass
    _PREVIOUS.clear()


def _protect() -> bool:
    """Install the handlers (once for all live files); False outside the main thread."""
    if _PREVIOUS:
        return True
    try:
        for sig in _HANDLED:
            _PREVIOUS[sig] = signal.signal(sig, _on_signal)
    except ValueError:     # not the main thread: no handlers
        _restore()
        return False
    return True


@contextmanager
def signals_deferred():
    """Hold SIGINT, SIGTERM and SIGHUP while the block runs, and deliver them after it.

    For calls into compiled code that cannot pass an exception on (a Cython ``noexcept``
    function prints a KeyboardInterrupt raised inside it as "Exception ignored" and goes
    on, e.g. SciPy's Sobol' kernel reading its direction numbers): a Ctrl-C during such a
    call would be lost and the run finish as if complete.  Outside the main thread, or
    where signals cannot be masked, the block runs as it is."""
    if not hasattr(signal, "pthread_sigmask") or \
            threading.current_thread() is not threading.main_thread():
        yield
        return
    old = signal.pthread_sigmask(signal.SIG_BLOCK, _HANDLED)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, old)


def worker_signals() -> None:
    """In a worker process: ignore SIGINT (the parent stops the pool and reports the
    interruption once) and forget the parent's temporary files."""
    _LIVE.clear()
    _PREVIOUS.clear()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


class AtomicFile:
    """A temporary file beside ``path`` that replaces it in one rename on :meth:`commit`
    and disappears on :meth:`abort` or a signal.

    * A symbolic link is followed: the file it points to is replaced, the link stays; with
      ``inside``, that file must lie in the folder ``inside`` (:func:`target_problem`).
    * An existing file keeps its permission bits; a new one gets the ordinary permissions
      (umask), not mkstemp's 0600.
    * A path that exists and is not a regular file (``/dev/null``, a FIFO, a terminal) is
      written directly (:attr:`tmp` is the path itself): it is never replaced.
    """

    def __init__(self, path: Path, inside: Path | None = None):
        path = Path(path)
        why = target_problem(path, inside)
        if why is not None:
            raise InputError(Problem("", why))
        self.path = path.resolve() if path.is_symlink() else path
        try:
            self._st = os.stat(self.path)
        except FileNotFoundError:
            self._st = None
        self.direct = self._st is not None and not stat.S_ISREG(self._st.st_mode)
        if self.direct:
            self.tmp = self.path
            return
        folder = self.path.parent if str(self.path.parent) else Path(".")
        blocked = hasattr(signal, "pthread_sigmask") and _protect()
        if blocked:
            old = signal.pthread_sigmask(signal.SIG_BLOCK, _HANDLED)
        try:
            import tempfile   # shutil, random: only when a file is written

            fd, tmp = tempfile.mkstemp(prefix=f".{self.path.name}.", suffix=".tmp", dir=folder)
            os.close(fd)
            _LIVE.add(tmp)
        finally:
            if blocked:
                signal.pthread_sigmask(signal.SIG_SETMASK, old)
        self.tmp = Path(tmp)

    def commit(self) -> None:
        """Flush the temporary file to disk and rename it over the target."""
        if self.direct:
            return
        tmp = str(self.tmp)
        if tmp not in _LIVE:
            # the signal handler removed it (a Ctrl-C whose KeyboardInterrupt was swallowed,
            # e.g. raised inside a finaliser): the run was interrupted, not complete
            self._forget()
            raise KeyboardInterrupt
        try:
            if self._st is not None:
                mode = stat.S_IMODE(self._st.st_mode)
            else:
                umask = os.umask(0)
                os.umask(umask)
                mode = 0o666 & ~umask
            os.chmod(tmp, mode)
            fd = os.open(tmp, os.O_RDONLY)
            try:
                os.fsync(fd)
            finally:
                os.close(fd)
            os.replace(tmp, self.path)
        except BaseException:
            self.abort()
            raise
        self._forget()
        from geardesign.core.run_files import keep_file

        try:
            keep_file(os.stat(self.path), self.path, "output")
        except OSError:
            pass

    def abort(self) -> None:
        """Remove the temporary file; the target stays as it was."""
        if self.direct:
            return
        try:
            os.unlink(self.tmp)
        except OSError:
            pass
        self._forget()

    def _forget(self) -> None:
        _LIVE.discard(str(self.tmp))
        if not _LIVE:
            _restore()

    def __enter__(self) -> Path:
        return self.tmp

    def __exit__(self, kind, exc, tb) -> None:
        if kind is None:
            self.commit()
        else:
            self.abort()


@contextmanager
def atomic_path(path: Path, inside: Path | None = None) -> Iterator[Path]:
    """A temporary path beside ``path`` to write to (:class:`AtomicFile`): on success it
    replaces ``path`` in one rename, on failure or a signal it is removed."""
    with AtomicFile(path, inside) as tmp:
        yield tmp


def write_atomic(path: Path, text: str, inside: Path | None = None) -> None:
    """Write ``text`` to ``path`` atomically (:class:`AtomicFile`)."""
    with atomic_path(path, inside) as tmp:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write(text)
