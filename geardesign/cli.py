"""The ``geardesign`` command line: a thin layer over :mod:`geardesign.core`.

:func:`main` runs a command line.  The common ones (a run, a kind's command, ``validate``,
``list``, ``template`` with plainly written options) are read by
:mod:`geardesign.cli_options` and do not import typer and click; every other one, and
every mistake, is read by typer (:mod:`geardesign.cli_app`, the command line's contract:
help, options and error messages), which both read alike (tests/test_cli_options.py).

Exit codes: 0 computed and every error-severity check passed; 1 computed but a check
failed (the report is still printed in full); 2 the input could not be used (one line per
problem on stderr, nothing written); 3 an internal error (a bug: please report it).
"""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Callable, Optional

# The beam and eigenvalue problems are small (a few hundred unknowns): OpenBLAS's threads
# only cost there, and on a busy machine their spinning makes one solve take 0.1 s instead
# of 1 ms.  One thread unless the user chose otherwise (read when numpy is first imported).
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")


def __getattr__(name: str):
    # the typer application and its parts (geardesign.cli_app), imported when asked for
    if not name.startswith("__"):
        from geardesign import cli_app

        return getattr(cli_app, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def _dispatch() -> None:
    command = parse(sys.argv, os.environ)
    if command is None:
        from geardesign.cli_app import run

        run()
    else:
        command()
        sys.exit(0)


def parse(argv: list[str], environ) -> Optional[Callable[[], None]]:
    """The call of :mod:`geardesign.commands` that ``argv`` asks for, or ``None`` when
    typer is to read it (:mod:`geardesign.cli_options`)."""
    if len(argv) < 2 or any(k.endswith("_COMPLETE") for k in environ):
        return None
    name, rest = argv[1], argv[2:]
    if name == "--version" and not rest:
        return _version
    from geardesign import commands as C
    from geardesign.cli_options import (RUN_OPTIONS, VALIDATE_OPTIONS, _plain, kind_options,
                                        read_options)

    if name == "list":
        return None if rest else C.list_cmd
    if name == "template":
        return (lambda: C.template_cmd(rest[0])) if len(rest) == 1 and _plain(rest[0]) else None
    if name == "run":
        allowed, call = RUN_OPTIONS, C.run_cmd
    elif name == "validate":
        allowed, call = VALIDATE_OPTIONS, C.validate_cmd
    else:
        from geardesign.core.kinds import KINDS

        if name not in KINDS:
            return None
        allowed = kind_options(name)
        call = lambda specs, **kw: C.kind_cmd(name, specs, **kw)    # noqa: E731
    read = read_options(rest, allowed)
    if read is None or not read[0]:
        return None
    args, values = read
    return lambda: call([Path(a) for a in args], **values)


def _version() -> None:
    import sys

    from geardesign import __version__
    from geardesign.commands import Exit

    sys.stdout.write(f"geardesign {__version__}\n")
    raise Exit(0)


def _err(line: str) -> None:
    from geardesign.core.text import escape_controls

    sys.stderr.write(escape_controls(line) + "\n")


def main() -> None:
    """Console entry point: never a traceback for the user."""
    from geardesign.core.run_files import inputs_kept

    try:
        with inputs_kept():        # no output of the command replaces a file it reads
            _dispatch()
    except SystemExit as exc:
        if exc.code == 130:       # typer ends a Ctrl-C in a command with a silent exit 130
            _err("geardesign: interrupted")
        raise
    except KeyboardInterrupt:
        _err("geardesign: interrupted")
        sys.exit(130)
    except BrokenPipeError:
        sys.exit(0)
    except Exception as exc:  # pragma: no cover - a bug
        if os.environ.get("GEARDESIGN_DEBUG"):
            raise
        _err(f"geardesign: internal error: {type(exc).__name__}: {exc} "
             f"(please report it; set GEARDESIGN_DEBUG=1 for the traceback)")
        sys.exit(3)
