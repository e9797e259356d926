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
    from geardesign.cli_options import parse

    command = parse(sys.argv, os.environ)
    if command is None:
        from geardesign.cli_app import run

        run()
    else:
        command()
        sys.exit(0)


def _err(line: str) -> None:
    from geardesign.core.text import escape_controls

    sys.stderr.write(escape_controls(line) + "\n")


def main() -> None:
    """Console entry point: never a traceback for the user."""
    try:
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
