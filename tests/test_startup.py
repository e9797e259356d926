"""Start-up of the command line: a run pays only for what it uses (issue 32).  These tests
count imported modules and built commands, never time."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from geardesign import cli
from geardesign.core import registry

ROOT = Path(__file__).resolve().parent.parent


def _modules_after(*argv: str) -> set[str]:
    """The modules a fresh interpreter holds after ``geardesign ARGV``."""
    code = ("import sys\n"
            f"sys.argv = ['geardesign', *{list(argv)!r}]\n"
            "from geardesign.cli import main\n"
            "try:\n    main()\nexcept SystemExit:\n    pass\n"
            "sys.stderr.write(' '.join(sys.modules))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT)
    return set(done.stderr.split())


def test_catalog_file_matches_the_calculators():
    stored = json.loads(registry.CATALOG.read_text("utf-8"))
    built = [[c.kind, c.summary, list(c.methods)] for c in registry.all_calculators()]
    assert stored == built, "rewrite it: python -m geardesign.core.registry"


@pytest.mark.parametrize("argv", [("list",), ("--help",), ("--version",)])
def test_listing_and_help_import_no_calculator_numpy_or_rich(argv):
    loaded = _modules_after(*argv)
    assert "geardesign.cli" in loaded        # the check itself ran
    assert not {"numpy", "scipy", "rich"} & loaded
    assert not {m for m in loaded if m.startswith("geardesign.spur")}


@pytest.mark.parametrize("argv", [("list",), ("--version",), ("template", "spur"),
                                  ("validate", "specs/spur_design.toml"),
                                  ("run", "specs/spur_plain.toml", "-f", "json"),
                                  ("spur", "specs/spur_plain.toml", "--format=json", "-q")])
def test_common_command_lines_import_no_typer_click_or_rich(argv):
    loaded = _modules_after(*argv)
    assert "geardesign.cli" in loaded
    assert not {m.partition(".")[0] for m in loaded} & {"typer", "click", "rich"}


def test_a_json_run_imports_no_rich_scipy_or_unused_calculator():
    loaded = _modules_after("run", "specs/spur_plain.toml", "-f", "json")
    assert "geardesign.spur.calculator" in loaded
    assert not {"rich", "scipy", "numpy", "tempfile", "csv"} & loaded
    others = {m.split(".")[1] for m in loaded if m.startswith("geardesign.")} & set(registry.KINDS)
    assert others == {"spur"}


def test_template_and_validate_import_no_numpy_and_template_no_calculation():
    loaded = _modules_after("template", "spur")
    assert "geardesign.spur.spec" in loaded
    assert not {"numpy", "scipy", "geardesign.spur.calculator"} & loaded
    assert not {"numpy", "scipy"} & _modules_after("validate", "specs/spur_design.toml")


def test_a_table_imports_rich_and_typer_only_for_what_it_reads():
    loaded = _modules_after("run", "specs/spur_plain.toml", "-f", "table")
    assert "rich" in loaded and "typer" not in loaded
    assert "typer" in _modules_after("run", "specs/spur_plain.toml", "--help")


def test_every_calculator_uses_the_schema_of_its_spec_module():
    from geardesign.core import kinds

    for kind in registry.KINDS:
        assert kinds.schema(kind) is registry.get(kind).schema, kind


def test_a_run_builds_only_the_command_it_names(monkeypatch):
    import typer.main

    built = []
    real = typer.main.get_command_from_info

    def counting(*args, **kw):
        info = kw.get("command_info", args[0] if args else None)
        built.append(info.name)
        return real(*args, **kw)

    monkeypatch.setattr(typer.main, "get_command_from_info", counting)
    monkeypatch.setattr(sys, "argv", ["geardesign", "schema", "spur"])
    with pytest.raises(SystemExit):
        cli.main()
    assert built == ["schema"]
    names = [c.name for c in cli.app.registered_commands]
    assert {"run", "list", "sweep", "template", "spur"} <= set(names)   # restored after


def test_top_level_help_lists_every_command(capsys, monkeypatch):
    monkeypatch.setattr(sys, "argv", ["geardesign", "--help"])
    with pytest.raises(SystemExit):
        cli.main()
    out = capsys.readouterr().out
    for name in ("run", "list", "template", "sweep", "validate", *registry.known_kinds()):
        assert f" {name} " in out or f" {name}\n" in out


def test_kinds_are_the_packages_pkgutil_finds():
    import pkgutil

    import geardesign
    from geardesign.core import kinds

    found = {m.name for m in pkgutil.iter_modules(geardesign.__path__)
             if m.ispkg and m.name not in kinds.NOT_CALCULATORS and not m.name.startswith("_")}
    assert set(kinds.KINDS) == found
