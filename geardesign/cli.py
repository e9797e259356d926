"""The ``geardesign`` command line: a thin layer over :mod:`geardesign.core`.

Exit codes: 0 computed and every error-severity check passed; 1 computed but a check
failed (the report is still printed in full); 2 the input could not be used (one line per
problem on stderr, nothing written); 3 an internal error (a bug: please report it).
"""

from __future__ import annotations

import json
import os
import sys
from contextlib import contextmanager

# The beam and eigenvalue problems are small (a few hundred unknowns): OpenBLAS's threads
# only cost there, and on a busy machine their spinning makes one solve take 0.1 s instead
# of 1 ms.  One thread unless the user chose otherwise (read when numpy is first imported).
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
from enum import Enum
from pathlib import Path
from typing import List, Optional

import typer

from geardesign import __version__
from geardesign import completion as _complete
from geardesign.core import registry
from geardesign.core.errors import InputError, Problem
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


class Format(str, Enum):
    table = "table"
    json = "json"
    jsonl = "jsonl"
    markdown = "markdown"
    csv = "csv"
    html = "html"
    pdf = "pdf"


FORMAT_HELP = ("Output format. Default: table on a terminal, json when stdout is a pipe or "
               "file; with --output, taken from the file extension (.json, .jsonl, .md, .csv, "
               ".html, .pdf, .txt). pdf needs the report extra and a Chromium.")

EXTENSIONS = {".json": "json", ".jsonl": "jsonl", ".md": "markdown", ".markdown": "markdown",
              ".csv": "csv", ".html": "html", ".htm": "html", ".pdf": "pdf", ".txt": "table"}
"""Report formats by the extension of --output."""


def _err(line: str) -> None:
    """One line on stderr; control characters of a path or a value are shown, never obeyed."""
    from geardesign.core.text import escape_controls

    sys.stderr.write(escape_controls(line) + "\n")


def _out(line: str) -> None:
    from geardesign.core.text import escape_controls

    sys.stdout.write(escape_controls(line) + "\n")


def _finite(value: Optional[float]) -> Optional[float]:
    """Option callback: a float option takes a finite number (``nan``, ``inf`` are no
    tolerance, no bore)."""
    import math

    if value is not None and not math.isfinite(value):
        raise typer.BadParameter(f"{value} is not a finite number")
    return value


def _targets(*paths: Optional[Path]) -> None:
    """Every file to be written is looked at before the work starts
    (:func:`geardesign.core.io.target_problem`): one line and exit 2 when one cannot be."""
    from geardesign.core.io import target_problem

    for path in paths:
        if path is not None:
            why = target_problem(path)
            if why is not None:
                _err(f"{path}: cannot write: {why}")
                raise typer.Exit(2)


MAX_PROBLEM_LINES = 20
"""Input problems printed at most; the rest are counted (a spec with millions of unknown
keys still gives a short answer)."""


def _report_problems(problems: list[str]) -> None:
    for line in problems[:MAX_PROBLEM_LINES]:
        _err(line)
    if len(problems) > MAX_PROBLEM_LINES:
        _err(f"... and {len(problems) - MAX_PROBLEM_LINES} more problems")


def _choose_format(fmt: Optional[Format], output: Optional[Path]) -> str:
    if fmt is not None:
        return fmt.value
    if output is not None:
        suffix = output.suffix.lower()
        if suffix not in EXTENSIONS and str(output) not in ("/dev/null", "/dev/stdout"):
            _err(f"{output}: cannot write a report as {suffix or 'a file without extension'}; "
                 f"use one of {', '.join(EXTENSIONS)} or give --format")
            raise typer.Exit(2)
        return EXTENSIONS.get(suffix, "json")
    return "table" if sys.stdout.isatty() else "json"


def _load(path: Path, expect_kind: Optional[str]):
    """A spec file, or the spec on standard input when the path is ``-``."""
    if str(path) != "-":
        return registry.load(path, expect_kind)
    from geardesign.core.io import MAX_SPEC_BYTES, decode, parse_toml

    raw = sys.stdin.buffer.read(MAX_SPEC_BYTES + 1)   # a pipe: read at most the limit
    if len(raw) > MAX_SPEC_BYTES:
        raise InputError(Problem("", "cannot be used: larger than 4 MiB; a spec is a few kB"))
    calc, spec = registry.load_data(parse_toml(decode(raw)), "<stdin>", expect_kind)
    spec.base_dir = Path.cwd()
    return calc, spec


def _compute_all(paths: List[Path], expect_kind: Optional[str], mode: Optional[str] = None):
    """Compute every spec; ``mode`` (from ``--select``/``--design``) overrides the spec's
    top-level ``mode`` key for calculators that have one."""
    results, problems = [], []
    for path in paths:
        try:
            calc, spec = _load(path, expect_kind)
            if mode is not None:
                field = calc.schema.root.member("mode")
                if field is None or mode not in (field.choices or ()):
                    raise InputError(Problem("", f"--{mode} does not apply to a {calc.kind} spec"))
                _overridable(spec, calc.schema, field, mode)
                spec.data["mode"] = mode
                if "mode" in spec.assumed:
                    spec.assumed.remove("mode")
            results.append(calc.compute(spec))
        except InputError as exc:
            problems.extend(p.line("<stdin>" if str(path) == "-" else str(path))
                            for p in exc.problems)
    return results, problems


def _overridable(spec, schema, field, mode: str) -> None:
    """A mode flag (``--select``) stands for the default mode (``mode = "check"``: rate
    what the spec gives, whose designation the selection then replaces); a spec that sets
    another mode itself (a bearing pair, ``mode = "pair"`` with ``[pair]``) asks for a
    different calculation, and the flag is refused in one line instead of a complaint
    about the tables of the spec's own mode."""
    written = None if "mode" in spec.assumed else spec.data.get("mode")
    if written is None or written in (mode, field.default):
        return
    own = [f"[{t.key}]" for t in schema.tables
           if f'mode = "{written}"' in t.description and spec.data.get(t.key) is not None]
    remove = f" and remove {', '.join(own)}" if own else ""
    raise InputError(Problem(
        "mode", f'--{mode} replaces only mode = "{field.default}" (the default); this spec '
        f'sets mode = "{written}": run it without --{mode}, or write mode = "{mode}" in place '
        f'of "{written}"{remove}', written))


def _pdf_ready(fmt_name: str, output: Optional[Path]) -> None:
    """A PDF report needs Playwright and a Chromium, and a file or a pipe to go to: one
    line and exit 2 before any work when one is missing."""
    if fmt_name != "pdf":
        return
    from geardesign.rendering.browser import INSTALL_HINT, missing

    why = missing()
    if why:
        _err(f"geardesign: --format pdf: {why}; install: {INSTALL_HINT}")
        raise typer.Exit(2)
    if output is None and (sys.stdout.isatty() or not hasattr(sys.stdout, "buffer")):
        # a terminal, or a text-only stream (an embedding program's): no place for bytes
        _err("geardesign: --format pdf writes a file: give --output FILE.pdf")
        raise typer.Exit(2)


def _report(results: list, fmt_name: str, output: Optional[Path], quiet: bool,
            color: bool = False, width: Optional[int] = None) -> None:
    """The report in ``fmt_name`` to ``output`` (atomically) or standard output."""
    from geardesign.core.render import render, render_pdf

    if fmt_name == "pdf":
        from geardesign.rendering.browser import BrowserMissing

        try:
            data = render_pdf(results)
        except BrowserMissing as exc:
            _err(f"geardesign: --format pdf: {exc}")
            raise typer.Exit(2)
        if output is not None:
            _write(output, data)
        elif not quiet:
            sys.stdout.buffer.write(data)
            sys.stdout.flush()
        return
    text = render(results, fmt_name, color=color, width=width)
    if output is not None:
        _write(output, text)
    elif not quiet:
        sys.stdout.write(text)


def _write(path: Path, text) -> None:
    """``text`` (or bytes) to ``path`` through the one atomic writer; a failure is one
    line, exit 2."""
    from geardesign.core.io import atomic_path, write_atomic

    try:
        if isinstance(text, bytes):
            with atomic_path(path) as tmp:
                Path(tmp).write_bytes(text)
        else:
            write_atomic(path, text)
    except InputError as exc:
        _err(f"{path}: cannot write: {exc.problems[0].message}")
        raise typer.Exit(2)
    except OSError as exc:
        _err(f"{path}: cannot write ({exc.strerror or exc})")
        raise typer.Exit(2)


def _write_plot(results: list, plot: Path) -> None:
    """``--plot FILE``: the start-up transient of the one result that has a time history
    (a pzdn spec with [startup]); written atomically, matplotlib imported only here."""
    from geardesign.pzdn.plot import PlotError, write_plot

    with_history = [r for r in results if any(s.key == "history" for s in r.sections)]
    if not with_history and len(results) == 1 and results[0].kind == "spur":
        _write_spur_file(results[0], plot, "write_plot")
        return
    if not with_history and len(results) == 1:
        _write_report_plot(results[0], plot)
        return
    if len(with_history) != 1:
        _err(f"{plot}: --plot needs exactly one spec with a start-up time history (a pzdn "
             f"spec with [startup] and history_points >= 2); {len(with_history)} given")
        raise typer.Exit(2)
    try:
        write_plot(with_history[0], plot)
    except PlotError as exc:
        _err(f"{plot}: {exc}")
        raise typer.Exit(2)


def _write_report_plot(result, plot: Path) -> None:
    """``--plot FILE.svg`` of a kind whose report has pictures (shaft diagrams, a drive's
    power flow and heat balance): the report's pictures in one SVG."""
    from geardesign.rendering.figures import plot_svg

    svg = plot_svg(result)
    if svg is None:
        _err(f"{plot}: --plot: a {result.kind} result has no picture; pictures: spur, pzdn "
             f"(with [startup]), {', '.join(PLOT_KINDS)}, sweep")
        raise typer.Exit(2)
    if plot.suffix.lower() != ".svg":
        _err(f"{plot}: --plot of a {result.kind} result writes .svg")
        raise typer.Exit(2)
    _write(plot, svg)


def _write_spur_file(result, path: Path, writer: str) -> None:
    """``--plot`` / ``--profile`` of a spur result (geardesign.spur.export)."""
    from geardesign.spur import export

    try:
        getattr(export, writer)(result, path)
    except export.ExportError as exc:
        _err(f"{path}: {exc}")
        raise typer.Exit(2)


def _emit(paths: List[Path], fmt: Optional[Format], output: Optional[Path], quiet: bool,
          expect_kind: Optional[str] = None, mode: Optional[str] = None,
          plot: Optional[Path] = None, keep_going: bool = False,
          profile: Optional[Path] = None) -> None:
    fmt_name = _choose_format(fmt, output)
    _pdf_ready(fmt_name, output)
    _targets(output, plot, profile)
    results, problems = _compute_all(paths, expect_kind, mode)
    if problems:
        _report_problems(problems)
        if not keep_going or not results:
            raise typer.Exit(2)
    if plot is not None:
        _write_plot(results, plot)
    if profile is not None:
        if len(results) != 1 or results[0].kind != "spur":
            _err(f"{profile}: --profile needs exactly one spur spec")
            raise typer.Exit(2)
        _write_spur_file(results[0], profile, "write_profile")
    to_terminal = output is None and sys.stdout.isatty()
    color = to_terminal and not os.environ.get("NO_COLOR")
    width = None
    if to_terminal:
        from geardesign.core.render import terminal_width

        width = terminal_width()
    code = 2 if problems else max(r.exit_code for r in results)
    _report(results, fmt_name, output, quiet, color, width)
    if output is not None and not quiet:
        verdicts = ", ".join(f"{r.source}: {r.verdict}" for r in results)
        _err(f"wrote {output} ({verdicts})")
    raise typer.Exit(code)


OPT_FORMAT = typer.Option(None, "--format", "-f", help=FORMAT_HELP, case_sensitive=False,
                          autocompletion=_complete.formats)
OPT_OUTPUT = typer.Option(None, "--output", "-o", help="Write the report to FILE (atomically).")
OPT_QUIET = typer.Option(False, "--quiet", "-q",
                         help="No report on stdout and no notes on stderr; the exit code tells "
                              "the verdict (input errors are still printed).")
ARG_SPECS = typer.Argument(..., help="Spec file(s), TOML.", show_default=False)
OPT_PLOT = typer.Option(None, "--plot", help="Write the start-up transient of a pzdn spec "
                        "with [startup], or the mesh of a spur pair, to FILE (.png or .svg; "
                        "needs matplotlib); the report's pictures of a shaft, drive, worm, "
                        "planetary, geneva, novikov, ball_clutch or epicycle_rim to FILE.svg.")
OPT_PROFILE = typer.Option(None, "--profile", help="Write the tooth profiles of a spur pair "
                           "in mesh to FILE (.dxf needs ezdxf, or .svg).")
OPT_SELECT = typer.Option(False, "--select",
                          help="Selection mode, as mode = \"select\" in the spec (bearing: the "
                               "smallest catalogue bearing that meets the required life; it "
                               "replaces mode = \"check\" and the given designation, not "
                               "mode = \"pair\").")


def _version(value: bool) -> None:
    if value:
        sys.stdout.write(f"geardesign {__version__}\n")
        raise typer.Exit(0)


@app.callback()
def _main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """geardesign: design calculations for mechanical drives."""


OPT_KEEP_GOING = typer.Option(False, "--keep-going", "-k",
                              help="With several specs: report the usable ones even when "
                                   "others are refused (the exit code is still 2).")


@app.command("run")
def run_cmd(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
            output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
            keep_going: bool = OPT_KEEP_GOING, select: bool = OPT_SELECT,
            plot: Optional[Path] = OPT_PLOT, profile: Optional[Path] = OPT_PROFILE) -> None:
    """Compute one or more specs ("-" reads standard input), dispatching on each `kind`."""
    _emit(specs, format, output, quiet, mode="select" if select else None, plot=plot,
          keep_going=keep_going, profile=profile)


PLOT_KINDS = ("shaft", "drive", "worm", "planetary", "geneva", "novikov", "ball_clutch", "epicycle_rim")
"""Kinds besides spur and pzdn whose command has ``--plot`` (the report's pictures)."""


def _kind_command(kind: str):
    """``geardesign <kind>``: only the options that apply to that calculator."""
    if kind == "bearing":
        def command(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
                    output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
                    keep_going: bool = OPT_KEEP_GOING, select: bool = OPT_SELECT) -> None:
            _emit(specs, format, output, quiet, expect_kind=kind,
                  mode="select" if select else None, keep_going=keep_going)
    elif kind == "pzdn":
        def command(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
                    output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
                    keep_going: bool = OPT_KEEP_GOING, plot: Optional[Path] = OPT_PLOT) -> None:
            _emit(specs, format, output, quiet, expect_kind=kind, plot=plot,
                  keep_going=keep_going)
    elif kind == "spur":
        def command(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
                    output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
                    keep_going: bool = OPT_KEEP_GOING, plot: Optional[Path] = OPT_PLOT,
                    profile: Optional[Path] = OPT_PROFILE) -> None:
            _emit(specs, format, output, quiet, expect_kind=kind, plot=plot,
                  keep_going=keep_going, profile=profile)
    elif kind in PLOT_KINDS:
        def command(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
                    output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
                    keep_going: bool = OPT_KEEP_GOING, plot: Optional[Path] = OPT_PLOT) -> None:
            _emit(specs, format, output, quiet, expect_kind=kind, plot=plot,
                  keep_going=keep_going)
    else:
        def command(specs: List[Path] = ARG_SPECS, format: Optional[Format] = OPT_FORMAT,
                    output: Optional[Path] = OPT_OUTPUT, quiet: bool = OPT_QUIET,
                    keep_going: bool = OPT_KEEP_GOING) -> None:
            _emit(specs, format, output, quiet, expect_kind=kind, keep_going=keep_going)

    command.__doc__ = f"Compute {kind} spec(s) (see `geardesign list`)."
    return command


_registered = False


def _register_kinds() -> None:
    global _registered
    if not _registered:
        # by name only: a calculator's modules are imported when a spec of its kind runs
        for kind in registry.known_kinds():
            app.command(kind)(_kind_command(kind))
        _registered = True


@app.command("list")
def list_cmd() -> None:
    """List the calculators: kind, what it does, standards used."""
    rows = registry.catalog()
    width = max(len(kind) for kind, _, _ in rows)
    for kind, summary, methods in rows:
        sys.stdout.write(f"{kind:<{width}}  {summary} [{', '.join(methods)}]\n")


def _calculator(kind: str) -> registry.Calculator:
    if kind not in registry.KINDS:
        import difflib

        close = difflib.get_close_matches(kind, list(registry.KINDS), 1, 0.6)
        hint = f' (did you mean "{close[0]}"?)' if close else ""
        known = ", ".join(registry.KINDS)
        _err(f'geardesign: unknown calculator "{kind}"{hint}; known: {known}')
        raise typer.Exit(2)
    return registry.get(kind)


@app.command("template")
def template_cmd(kind: str = typer.Argument(..., help="Calculator kind, e.g. spur.",
                                            autocompletion=_complete.kinds)) -> None:
    """Print a complete commented example spec."""
    from geardesign.core.spec import template

    sys.stdout.write(template(_calculator(kind).schema))


@app.command("schema")
def schema_cmd(kind: str = typer.Argument(..., help="Calculator kind, e.g. spur.",
                                          autocompletion=_complete.kinds)) -> None:
    """Print the JSON Schema of a calculator's spec (units in the descriptions)."""
    from geardesign.core.spec import json_schema

    sys.stdout.write(json.dumps(json_schema(_calculator(kind).schema), indent=2,
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
        raise typer.Exit(2)
    if plot is not None and plot.suffix.lower() not in (".png", ".svg", ".pdf"):
        _err(f"{plot}: --plot must end in .png, .svg or .pdf")
        raise typer.Exit(2)
    _targets(output, data, plot)
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
        raise typer.Exit(2)
    sink = writer = None
    if data is not None:
        from geardesign.spur.sweep_io import DatasetWriter

        try:
            writer = DatasetWriter(data)
        except InputError as exc:
            _err(f"{data}: cannot write: {exc.problems[0].message}")
            raise typer.Exit(2)
        except (OSError, ImportError) as exc:
            _err(f"{data}: cannot write ({exc})")
            raise typer.Exit(2)
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
        raise typer.Exit(2)
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
            raise typer.Exit(2)
        from geardesign.spur.sweep_io import toml_text

        text = toml_text(SW.variant_spec(base, sw, int(ranked["index"][emit_spec - 1])))
        if output is not None:
            _write(output, text)
        else:
            sys.stdout.write(text)
        raise typer.Exit(0)
    if plot is not None:
        from geardesign.spur.sweep_io import plot_front

        try:
            plot_front(summary, sw, plot)
        except ImportError:
            _err(f"{plot}: matplotlib is not installed, so no plot can be written; install "
                 f"it with `pip install matplotlib` (the plot extra of geardesign)")
            raise typer.Exit(2)
    to_terminal = output is None and sys.stdout.isatty()
    from geardesign.core.render import terminal_width

    _report([res], fmt_name, output, quiet, to_terminal and not os.environ.get("NO_COLOR"),
            terminal_width() if to_terminal else None)
    raise typer.Exit(res.exit_code)


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
        raise typer.Exit(2)
    raise typer.Exit(code)


@app.command("validate")
def validate_cmd(specs: List[Path] = ARG_SPECS, quiet: bool = OPT_QUIET) -> None:
    """Check spec file(s) without reporting results: exit 0 if usable, 2 if not."""
    results, problems = _compute_all(specs, None)
    if not quiet:
        for r in results:
            _out(f"{r.source}: ok ({r.kind})")
    if problems:
        _report_problems(problems)
        raise typer.Exit(2)


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


def main() -> None:
    """Console entry point: never a traceback for the user."""
    _register_kinds()
    try:
        with _only_requested(sys.argv):
            app()
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
