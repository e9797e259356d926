"""Start-up of the command line: a run pays only for what it uses (issue 32).  These tests
count imported modules and built commands, never time."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from geardesign import cli
from geardesign.core import registry


def _modules_after(*argv: str) -> set[str]:
    """The modules a fresh interpreter holds after ``geardesign ARGV``."""
    code = ("import sys\n"
            f"sys.argv = ['geardesign', *{list(argv)!r}]\n"
            "from geardesign.cli import main\n"
            "try:\n    main()\nexcept SystemExit:\n    pass\n"
            "sys.stderr.write(' '.join(sys.modules))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    return set(done.stderr.split())


def test_catalog_file_matches_the_calculators():
    stored = json.loads(registry.CATALOG.read_text("utf-8"))
    built = [[c.kind, c.summary, list(c.methods)] for c in registry.all_calculators()]
    assert stored == built, "rewrite it: python -m geardesign.core.registry"


@pytest.mark.parametrize("argv", [("list",), ("--help",), ("--version",)])
def test_listing_and_help_import_no_calculator_numpy_or_rich(argv):
    loaded = _modules_after(*argv)
    assert "typer" in loaded        # the check itself ran
    assert not {"numpy", "scipy", "rich"} & loaded
    assert not {m for m in loaded if m.startswith("geardesign.spur")}


def test_a_run_builds_only_the_command_it_names(monkeypatch):
    import typer.main

    built = []
    real = typer.main.get_command_from_info

    def counting(*args, **kw):
        info = kw.get("command_info", args[0] if args else None)
        built.append(info.name)
        return real(*args, **kw)

    monkeypatch.setattr(typer.main, "get_command_from_info", counting)
    monkeypatch.setattr(sys, "argv", ["geardesign", "template", "spur"])
    with pytest.raises(SystemExit):
        cli.main()
    assert built == ["template"]
    names = [c.name for c in cli.app.registered_commands]
    assert {"run", "list", "sweep", "template", "spur"} <= set(names)   # restored after


def test_top_level_help_lists_every_command(capsys, monkeypatch):
    monkeypatch.setattr(sys, "argv", ["geardesign", "--help"])
    with pytest.raises(SystemExit):
        cli.main()
    out = capsys.readouterr().out
    for name in ("run", "list", "template", "sweep", "validate", *registry.known_kinds()):
        assert f" {name} " in out or f" {name}\n" in out
