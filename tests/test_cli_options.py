"""The command lines read without typer (geardesign.cli_options) are read as typer reads
them: the same options for every command, and for any command line that the short reader
accepts, the same arguments and option values as typer's own parser gives."""

from __future__ import annotations

from pathlib import Path

import pytest
import typer.main
from hypothesis import given, settings
from hypothesis import strategies as st

from geardesign import cli, cli_app
from geardesign.cli_options import (OPTIONS, RUN_OPTIONS, VALIDATE_OPTIONS, kind_options,
                                    read_options)
from geardesign.core import registry

COMMANDS = {"run": RUN_OPTIONS, "validate": VALIDATE_OPTIONS,
            **{k: kind_options(k) for k in registry.KINDS}}


def _click_command(name: str):
    cli_app._register_kinds()
    return typer.main.get_command(cli_app.app).commands[name]


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_typer_declares_the_options_of_the_table(name):
    params = _click_command(name).params
    assert [p.name for p in params] == ["specs", *COMMANDS[name]]
    for p in params[1:]:
        o = OPTIONS[p.name]
        assert tuple(p.opts) == o.flags and p.is_flag == (o.takes is None), p.name
        assert p.help == o.help
        if o.takes == "choice":
            assert tuple(p.type.choices) == o.choices


def _typer_reads(name: str, tokens: list[str]) -> tuple[list[str], dict]:
    cmd = _click_command(name)
    ctx = cmd.make_context(name, list(tokens))
    values = {k: v for k, v in ctx.params.items() if k != "specs" and v not in (None, False)}
    values = {k: getattr(v, "value", v) for k, v in values.items()}
    return [str(p) for p in ctx.params["specs"]], values


WORDS = ["a.toml", "b.toml", "-", "--", "json", "csv", "JSON", "out.json", "x.svg", "",
         "-f", "--format", "--format=json", "--format=", "-fjson", "-fcsv", "-o",
         "--output", "--output=r.md", "-oreport.md", "-q", "--quiet", "-k", "--keep-going",
         "-qk", "-kq", "-qf", "-qfjson", "--select", "--plot", "--plot=p.svg", "--profile",
         "-x", "--help", "-h", "--quiet=1", "--selec", "-fq"]


@settings(max_examples=300, deadline=None)
@given(name=st.sampled_from(["run", "validate", "spur", "bearing", "pzdn", "shaft", "drive"]),
       tokens=st.lists(st.sampled_from(WORDS), max_size=7))
def test_what_the_short_reader_accepts_typer_reads_alike(name, tokens):
    read = read_options(tokens, COMMANDS[name])
    if read is None or not read[0]:
        return            # typer reads it (and reports any mistake; no spec: a missing one)
    args, values = read
    assert _typer_reads(name, tokens) == (args, {k: str(v) if isinstance(v, Path) else v
                                                 for k, v in values.items()})


@pytest.mark.parametrize("tokens", [
    ["a.toml", "-f", "json"], ["--format=csv", "a.toml", "b.toml", "-q"],
    ["-fjson", "-o", "r.json", "a.toml"], ["-qk", "a.toml", "--", "-b.toml"], ["-"]])
def test_plain_command_lines_are_read_without_typer(tokens):
    assert read_options(tokens, RUN_OPTIONS) is not None
    args, values = read_options(tokens, RUN_OPTIONS)
    assert _typer_reads("run", tokens) == (args, {k: str(v) if isinstance(v, Path) else v
                                                  for k, v in values.items()})


@pytest.mark.parametrize("argv", [["run"], ["run", "--help"], ["run", "a.toml", "-x"],
                                  ["run", "a.toml", "-f", "JSON"], ["sweep", "a.toml"],
                                  ["check", "a.toml"], ["list", "x"], ["template"],
                                  ["template", "--help"], ["--help"], ["nonsense", "a"]])
def test_everything_else_goes_to_typer(argv):
    assert cli.parse(["geardesign", *argv], {}) is None


def test_shell_completion_goes_to_typer():
    assert cli.parse(["geardesign", "run", "a.toml"], {"_GEARDESIGN_COMPLETE": "x"}) is None
