"""The ``geardesign`` command line declared to typer: every command, its options and its
help (the command line's contract).  The commands themselves are :mod:`geardesign.commands`;
the options of the computing commands are the tables of :mod:`geardesign.cli_options`.
:func:`geardesign.cli.main` comes here for every command line it does not read itself.

Exit codes: 0 computed and every error-severity check passed; 1 computed but a check
failed (the report is still printed in full); 2 the input could not be used (one line per
problem on stderr, nothing written); 3 an internal error (a bug: please report it).
"""

from __future__ import annotations

import json
import os
import sys
from contextlib import contextmanager
from enum import Enum
from pathlib import Path
from typing import List, Optional

import typer

from geardesign import __version__
from geardesign import commands as C
from geardesign import completion as _complete
from geardesign.cli_options import FORMATS, OPTIONS, RUN_OPTIONS, kind_options
from geardesign.commands import (Exit, _choose_format, _err, _out, _pdf_ready, _report,
                                 _report_problems, _targets, _write)
from geardesign.core.kinds import known_kinds
from geardesign.core.errors import InputError
from geardesign.testing import ATOL, RTOL

app = typer.Typer(
    add_completion=True,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    help="Design calculations for mechanical drives. A spec file (TOML) describes the design; "
         "geardesign checks it, computes and reports. Exit codes: 0 pass, 1 a design check "
         "failed, 2 unusable input, 3 internal error (a bug: please report it).",
)

Format = Enum("Format", {f: f for f in FORMATS}, type=str)
"""The report formats as typer's choice (:data:`geardesign.cli_options.FORMATS`)."""


def _finite(value: Optional[float]) -> Optional[float]:
    """Option callback: a float option takes a finite number (``nan``, ``inf`` are no
    tolerance, no bore)."""
    import math

    if value is not None and not math.isfinite(value):
        raise typer.BadParameter(f"{value} is not a finite number")
    return value


def _option(name: str, **extra):
    """The typer option of :data:`geardesign.cli_options.OPTIONS` ``name``."""
    o = OPTIONS[name]
    return typer.Option(False if o.takes is None else None, *o.flags, help=o.help, **extra)


OPT_FORMAT = _option("format", case_sensitive=False, autocompletion=_complete.formats)
OPT_OUTPUT = _option("output")
OPT_QUIET = _option("quiet")
ARG_SPECS = typer.Argument(..., help="Spec file(s), TOML.", show_default=False)
OPT_PLOT = _option("plot")
OPT_PROFILE = _option("profile")
OPT_SELECT = _option("select")
OPT_KEEP_GOING = _option("keep_going")


def _version(value: bool) -> None:
    if value:
        sys.stdout.write(f"geardesign {__version__}\n")
        raise typer.Exit(0)


@app.callback()
def _main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """geardesign: design calculations for mechanical drives."""


@app.command("run")
def run_cmd(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
            output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
            keep_going: bool = OPT_KEEP_GOING, select: bool = OPT_SELECT,
            plot: Optional[Path] = OPT_PLOT, profile: Optional[Path] = OPT_PROFILE) -> None:
    """Compute one or more specs ("-" reads standard input), dispatching on each `kind`."""
    C.run_cmd(specs, format, output, quiet, keep_going, select, plot, profile)


assert tuple(run_cmd.__annotations__)[1:-1] == RUN_OPTIONS   # one table of the options

_DECLARED = {"format": (Optional[Format], OPT_FORMAT), "output": (Optional[Path], OPT_OUTPUT),
             "quiet": (bool, OPT_QUIET), "keep_going": (bool, OPT_KEEP_GOING),
             "select": (bool, OPT_SELECT), "plot": (Optional[Path], OPT_PLOT),
             "profile": (Optional[Path], OPT_PROFILE)}
"""The typer declaration of each option of :data:`geardesign.cli_options.OPTIONS`."""


def _kind_command(kind: str):
    """``geardesign <kind>``: only the options that apply to that calculator
    (:func:`geardesign.cli_options.kind_options`), declared to typer by the signature."""
    from inspect import Parameter, Signature

    def command(specs: List[Path], **options) -> None:
        C.kind_cmd(kind, specs, **options)

    names = kind_options(kind)
    hints = {"specs": List[Path], **{n: _DECLARED[n][0] for n in names}}
    command.__signature__ = Signature(
        [Parameter(n, Parameter.POSITIONAL_OR_KEYWORD, annotation=hints[n],
                   default=ARG_SPECS if n == "specs" else _DECLARED[n][1]) for n in hints],
        return_annotation=None)
    command.__annotations__ = dict(hints, **{"return": None})
    command.__doc__ = f"Compute {kind} spec(s) (see `geardesign list`)."
    return command


_registered = False


def _register_kinds() -> None:
    global _registered
    if not _registered:
        # by name only: a calculator's modules are imported when a spec of its kind runs
        for kind in known_kinds():
            app.command(kind)(_kind_command(kind))
        _registered = True


@app.command("list")
def list_cmd() -> None:
    """List the calculators: kind, what it does, standards used."""
    C.list_cmd()


@app.command("template")
def template_cmd(kind: str = typer.Argument(..., help="Calculator kind, e.g. spur.",
                                            autocompletion=_complete.kinds)) -> None:
    """Print a complete commented example spec."""
    C.template_cmd(kind)


@app.command("schema")
def schema_cmd(kind: str = typer.Argument(..., help="Calculator kind, e.g. spur.",
                                          autocompletion=_complete.kinds)) -> None:
    """Print the JSON Schema of a calculator's spec (units in the descriptions)."""
    from geardesign.core.template import json_schema

    sys.stdout.write(json.dumps(json_schema(C.schema(kind)), indent=2,
                                ensure_ascii=False) + "\n")


@app.command("sweep")
def sweep_cmd(spec: Path = typer.Argument(..., help="Sweep spec: a spur spec with a [sweep] "
                                                    "table.", show_default=False),
              vary: List[str] = typer.Option([], "--vary", help="Vary a key: "
                                             "KEY=FROM:TO:STEP or KEY=V1,V2,... (repeatable; "
                                             "adds to or replaces [sweep]).",
                                             autocompletion=_complete.vary_keys),
              samples: Optional[int] = typer.Option(None, "--samples", help="Evaluate a "
                                                    "scrambled Sobol sample of N candidates "
                                                    "instead of the full grid."),
              seed: Optional[int] = typer.Option(None, "--seed", help="Seed of the sample."),
              workers: int = typer.Option(1, "--workers", min=1, max=256,
                                          help="Local processes evaluating chunks; at most "
                                               "the cores available unless "
                                               "--force-workers."),
              force_workers: bool = typer.Option(False, "--force-workers",
                                                 help="Start --workers processes even when "
                                                      "that is more than the cores "
                                                      "(each holds a chunk in memory)."),
              scheduler: Optional[str] = typer.Option(None, "--scheduler", help="Dask "
                                                      "scheduler address (tcp://HOST:8786): "
                                                      "evaluate the chunks on that cluster "
                                                      "(refused when it does not answer "
                                                      "within 10 s)."),
              data: Optional[Path] = typer.Option(None, "--data", help="Write every "
                                                  "candidate (inputs, key results, checks) "
                                                  "to FILE.csv or FILE.parquet."),
              emit_spec: Optional[int] = typer.Option(None, "--emit-spec", min=1,
                                                      help="Print the spur spec of ranked "
                                                           "variant K (geardesign run "
                                                           "reproduces it)."),
              plot: Optional[Path] = typer.Option(None, "--plot", help="Plot the feasible "
                                                  "front (FILE.png|svg; needs matplotlib)."),
              format: Optional[Format] = OPT_FORMAT, output: Optional[Path] = OPT_OUTPUT,
              quiet: bool = OPT_QUIET) -> None:
    """Sweep a spur pair over ranges of its data: every variant rated by the vectorised
    kernel, ranked by the objectives, with the Pareto front (exit 1 when none is feasible)."""
    from geardesign.spur import sweep as SW

    fmt_name = _choose_format(format, output)
    _pdf_ready(fmt_name, output)
    if data is not None and data.suffix.lower() not in (".csv", ".parquet"):
        _err(f"{data}: --data must end in .csv or .parquet")
        raise Exit(2)
    if plot is not None and plot.suffix.lower() not in (".png", ".svg", ".pdf"):
        _err(f"{plot}: --plot must end in .png, .svg or .pdf")
        raise Exit(2)
    _targets(output, data, plot, inputs=[spec])
    cores = _cores()
    if workers > cores and not force_workers:
        if not quiet:
            _err(f"geardesign sweep: --workers {workers}: using {cores}, the cores available "
                 f"(--force-workers to start {workers})")
        workers = cores
    try:
        from geardesign.core.spec import load_toml

        raw = load_toml(spec)
        base, sw = SW.load_sweep(raw, str(spec), vary, samples, seed)
    except InputError as exc:
        _report_problems([p.line(str(spec)) for p in exc.problems])
        raise Exit(2)
    sink = writer = None
    if data is not None:
        from geardesign.spur.sweep_io import DatasetWriter

        try:
            writer = DatasetWriter(data)
        except InputError as exc:
            _err(f"{data}: cannot write: {exc.problems[0].message}")
            raise Exit(2)
        except (OSError, ImportError) as exc:
            _err(f"{data}: cannot write ({exc})")
            raise Exit(2)
        sink = writer.write
    bar = None
    if not quiet and sys.stderr.isatty():
        from rich.progress import Progress

        bar = Progress(transient=True)
        task = bar.add_task("sweep", total=sw.size)
        bar.start()
    complete = False
    try:
        summary = SW.run_sweep(base, sw, workers, scheduler,
                               (lambda n: bar.advance(task, n)) if bar else None, sink)
        complete = True
    except SW.SchedulerError as exc:
        _err(f"geardesign sweep: --scheduler {scheduler}: {exc}")
        raise Exit(2)
    finally:
        if bar is not None:
            bar.stop()
        if writer is not None:
            writer.close(complete)
    res = SW.sweep_result(base, sw, summary, str(spec))
    if emit_spec is not None:
        ranked = summary["head"]
        if ranked is None or emit_spec > len(ranked["index"]):
            n = 0 if ranked is None else len(ranked["index"])
            _err(f"{spec}: --emit-spec {emit_spec}: the sweep ranked {n} variants")
            raise Exit(2)
        from geardesign.spur.sweep_io import toml_text

        text = toml_text(SW.variant_spec(base, sw, int(ranked["index"][emit_spec - 1])))
        if output is not None:
            _write(output, text)
        else:
            sys.stdout.write(text)
        raise Exit(0)
    if plot is not None:
        from geardesign.spur.sweep_io import plot_front

        try:
            plot_front(summary, sw, plot)
        except ImportError:
            _err(f"{plot}: matplotlib is not installed, so no plot can be written; install "
                 f"it with `pip install matplotlib` (the plot extra of geardesign)")
            raise Exit(2)
    to_terminal = output is None and sys.stdout.isatty()
    from geardesign.core.render import terminal_width

    _report([res], fmt_name, output, quiet, to_terminal and not os.environ.get("NO_COLOR"),
            terminal_width() if to_terminal else None)
    raise Exit(res.exit_code)


@app.command("check")
def check_cmd(specs: List[Path] = ARG_SPECS,
              rtol: float = typer.Option(RTOL, "--rtol", min=0.0, max=1.0,
                                         callback=_finite,
                                         help="Relative tolerance: of a number to itself, "
                                              "of an array's elements to the array's "
                                              "largest magnitude."),
              atol: float = typer.Option(ATOL, "--atol", min=0.0, max=1e300,
                                         callback=_finite,
                                         help="Absolute tolerance of every number, in its "
                                              "own unit."),
              update: bool = typer.Option(False, "--update",
                                          help="Rewrite each SPEC.expected.json from the "
                                               "current results (on purpose; review the diff)."),
              quiet: bool = OPT_QUIET) -> None:
    """Compare each spec's results with SPEC.expected.json beside it (golden files in your
    CI): exit 0 when nothing moved, 1 when a quantity or a verdict moved, 2 for unusable
    input or a missing expected file."""
    from geardesign.testing import check_golden, expected_path

    code, problems = 0, []
    for spec in specs:
        try:
            moved = check_golden(spec, update=update, rtol=rtol, atol=atol)
        except InputError as exc:
            problems.extend(p.line(str(spec)) for p in exc.problems)
            continue
        except FileNotFoundError:
            problems.append(f"{spec}: no {expected_path(spec).name} beside it; write it with "
                            f"geardesign check --update {spec}")
            continue
        except OSError as exc:
            problems.append(f"{spec}: {expected_path(spec).name} cannot be written or read "
                            f"({exc.strerror or exc})")
            continue
        if update:
            if not quiet:
                _out(f"{spec}: wrote {expected_path(spec).name}")
        elif moved:
            code = 1
            _out(f"{spec}: {len(moved)} quantities moved")
            for d in moved:
                _out(f"  {d.line()}")
        elif not quiet:
            _out(f"{spec}: unchanged")
    if problems:
        _report_problems(problems)
        raise Exit(2)
    raise Exit(code)


@app.command("validate")
def validate_cmd(specs: List[Path] = ARG_SPECS, quiet: bool = OPT_QUIET) -> None:
    """Check spec file(s) without reporting results: exit 0 if usable, 2 if not."""
    C.validate_cmd(specs, quiet)


def _cores() -> int:
    """The cores this process may run on (its CPU affinity, else the machine's count)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:   # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


# browsing the built-in data (geardesign/browse.py): geardesign materials, geardesign bearings
from geardesign import browse as _browse  # noqa: E402

_browse.register(app, _choose_format, _finite)

# REXS exchange (geardesign/rexs/cli.py): geardesign import MODEL.rexs, geardesign export SPEC
from geardesign.rexs import cli as _rexs  # noqa: E402

_rexs.register(app, _err, _write)


@contextmanager
def _only_requested(argv: List[str]):
    """Keep only the subcommand that ``argv`` names, when it names one: typer builds a
    click command (``inspect.signature``, its parameters) for every registered command on
    each start, and one run uses one.  The top-level ``--help``, ``--version``, a mistyped
    command name and shell completion still see every command."""
    commands, groups = list(app.registered_commands), list(app.registered_groups)
    if len(argv) >= 2 and not argv[1].startswith("-") and not any(
            k.endswith("_COMPLETE") for k in os.environ):
        named = [c for c in commands
                 if (c.name or c.callback.__name__.replace("_", "-")) == argv[1]]
        if named:
            app.registered_commands[:], app.registered_groups[:] = named, []
    try:
        yield
    finally:
        app.registered_commands[:], app.registered_groups[:] = commands, groups


def run() -> None:
    """Read the command line with typer and run its command (the kinds' commands
    registered first)."""
    _register_kinds()
    with _only_requested(sys.argv):
        app()
