"""The ``import`` and ``export`` commands (registered on the main app by
:func:`register`); their modules are imported only when a command runs."""

from __future__ import annotations

from enum import Enum
from pathlib import Path
from typing import Optional

import typer


class ExportFormat(str, Enum):
    rexs = "rexs"
    rexs_json = "rexs-json"


def register(app: typer.Typer, err, write) -> None:
    """Add ``import`` and ``export`` to ``app``; ``err`` prints one line on stderr,
    ``write(path, text)`` writes a file atomically (exit 2 on failure)."""

    @app.command("import")
    def import_cmd(model: Path = typer.Argument(..., help="REXS model: .rexs (XML), .rexsj "
                                                         "(JSON) or .rexsz (zip)."),
                   output: Optional[Path] = typer.Option(
                       None, "--output", "-o", help="Write the spec to this file "
                                                    "(default: standard output).")) -> None:
        """Read a REXS gear unit and write it as a spec (TOML) for `geardesign run`: a drive,
        or a planetary, worm or bevel stage (docs/rexs.md)."""
        from geardesign.commands import _targets
        from geardesign.core.errors import InputError
        from geardesign.core.text import escape_controls
        from geardesign.rexs.importer import import_model
        from geardesign.rexs.model import read_model

        _targets(output, inputs=(model,))
        try:
            imported = import_model(read_model(model), escape_controls(model.name))
        except InputError as exc:
            err(exc.problems[0].line(str(model)))
            raise typer.Exit(2)
        if output is None:
            typer.echo(imported.text, nl=False)
        else:
            write(output, imported.text)

    @app.command("export")
    def export_cmd(spec: Path = typer.Argument(..., help="Spec file: spur, planetary, worm, "
                                                         "bevel or drive."),
                   format: ExportFormat = typer.Option(ExportFormat.rexs, "--format", "-f",
                                                      help="rexs (XML) or rexs-json."),
                   output: Optional[Path] = typer.Option(
                       None, "--output", "-o", help="Write the model to this file "
                                                    "(default: standard output).")) -> None:
        """Write the gear unit of a spur, planetary, worm, bevel or drive spec as a REXS 1.5 model,
        with the computed values REXS has attributes for."""
        from geardesign.commands import _targets
        from geardesign.core.errors import InputError
        from geardesign.rexs.exporter import export_spec

        _targets(output, inputs=(spec,))
        try:
            text = export_spec(spec, "json" if format is ExportFormat.rexs_json else "xml")
        except InputError as exc:
            for p in exc.problems[:20]:
                err(p.line(str(spec)))
            raise typer.Exit(2)
        if output is None:
            typer.echo(text, nl=False)
        else:
            write(output, text)
