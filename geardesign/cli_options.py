"""The options of the commands that compute and list, as data, and the reading of their
common command lines without typer.

:mod:`geardesign.cli_app` declares every command to typer from these tables (typer is the
command line's contract: its help, its options and its error messages).  A command line
that only names ``run``, ``validate``, ``list``, ``template`` or a kind with its arguments
and options, each written the plain way (``-f json``, ``--format json``, ``--format=json``,
``-fjson``, ``-qk``), is read by :func:`read_options` (:func:`geardesign.cli.parse`) into
the same call of :mod:`geardesign.commands` that typer would make, so that a
run does not import typer and click (more than half of a small spec's start-up).  Every
other command line (``--help``, an unknown option, a missing argument, a value that
looks like an option, shell completion) goes to typer; tests/test_cli_options.py
checks that both read every command line alike.
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional

from geardesign.core.text import FORMATS

FORMAT_HELP = ("Output format. Default: table on a terminal, json when stdout is a pipe or "
               "file; with --output, taken from the file extension (.json, .jsonl, .md, .csv, "
               ".html, .pdf, .txt). pdf needs the report extra and a Chromium.")

EXTENSIONS = {".json": "json", ".jsonl": "jsonl", ".md": "markdown", ".markdown": "markdown",
              ".csv": "csv", ".html": "html", ".htm": "html", ".pdf": "pdf", ".txt": "table"}
"""Report formats by the extension of --output."""

PLOT_KINDS = ("shaft", "drive", "worm", "planetary", "geneva", "novikov", "ball_clutch",
              "epicycle_rim")
"""Kinds besides spur and pzdn whose command has ``--plot`` (the report's pictures)."""


class Opt:
    """One option: its parameter name, its flags (long first), whether it takes a value
    (``path`` or one of ``choices``) or is a flag, and its help."""

    __slots__ = ("name", "flags", "takes", "help", "choices")

    def __init__(self, name: str, flags: tuple[str, ...], takes: Optional[str], help: str,
                 choices: tuple[str, ...] = ()) -> None:
        self.name, self.flags, self.takes, self.help = name, flags, takes, help
        self.choices = choices


OPTIONS = {o.name: o for o in (
    Opt("format", ("--format", "-f"), "choice", FORMAT_HELP, FORMATS),
    Opt("output", ("--output", "-o"), "path", "Write the report to FILE (atomically)."),
    Opt("quiet", ("--quiet", "-q"), None,
        "No report on stdout and no notes on stderr; the exit code tells the verdict (input "
        "errors are still printed)."),
    Opt("keep_going", ("--keep-going", "-k"), None,
        "With several specs: report the usable ones even when others are refused (the exit "
        "code is still 2)."),
    Opt("select", ("--select",), None,
        "Selection mode, as mode = \"select\" in the spec (bearing: the smallest catalogue "
        "bearing that meets the required life; it replaces mode = \"check\" and the given "
        "designation, not mode = \"pair\")."),
    Opt("plot", ("--plot",), "path",
        "Write the start-up transient of a pzdn spec with [startup], or the mesh of a spur "
        "pair, to FILE (.png or .svg; needs matplotlib); the report's pictures of a shaft, "
        "drive, worm, planetary, geneva, novikov, ball_clutch or epicycle_rim to FILE.svg."),
    Opt("profile", ("--profile",), "path",
        "Write the tooth profiles of a spur pair in mesh to FILE (.dxf needs ezdxf, or .svg)."),
)}
"""The options shared by ``run``, the kinds' commands and ``validate``."""

RUN_OPTIONS = ("format", "output", "quiet", "keep_going", "select", "plot", "profile")
VALIDATE_OPTIONS = ("quiet",)


def kind_options(kind: str) -> tuple[str, ...]:
    """The options of ``geardesign KIND``: only those that apply to that calculator."""
    extra = {"bearing": ("select",), "pzdn": ("plot",), "spur": ("plot", "profile")}.get(
        kind, ("plot",) if kind in PLOT_KINDS else ())
    return ("format", "output", "quiet", "keep_going", *extra)


def _plain(token: str) -> bool:
    """A value or an argument as typer would take it: not empty, not option-like."""
    return token != "" and (token == "-" or not token.startswith("-"))


def read_options(tokens: list[str], allowed: tuple[str, ...]):
    """``(arguments, {option: value})`` of ``tokens`` for the options ``allowed``, or
    ``None`` for anything not written the plain way (typer then reads it)."""
    by_flag = {f: OPTIONS[n] for n in allowed for f in OPTIONS[n].flags}
    args: list[str] = []
    values: dict = {}
    i = 0
    while i < len(tokens):
        tok = tokens[i]
        i += 1
        if tok == "--":
            if not all(t != "" for t in tokens[i:]):
                return None
            args.extend(tokens[i:])
            break
        if not tok.startswith("-") or tok == "-":
            if tok == "":
                return None
            args.append(tok)
            continue
        if tok.startswith("--"):
            flag, eq, value = tok.partition("=")
            opt = by_flag.get(flag)
            if opt is None or (eq and opt.takes is None):
                return None
            if opt.takes is None:
                values[opt.name] = True
                continue
        else:                               # -x, -xVALUE, -qk
            opt = None
            for j, ch in enumerate(tok[1:], 1):
                opt = by_flag.get("-" + ch)
                if opt is None:
                    return None
                if opt.takes is not None:
                    value, eq = tok[j + 1:], tok[j + 1:] != ""
                    break
                values[opt.name] = True
            if opt.takes is None:
                continue
        if not eq:
            if i >= len(tokens):
                return None
            value, i = tokens[i], i + 1
        if not _plain(value) or (opt.takes == "choice" and value not in opt.choices):
            return None
        values[opt.name] = Path(value) if opt.takes == "path" else value
    return args, values
