"""The commands of the command line without the command-line parser: what ``run``, a
kind's command, ``validate``, ``list`` and ``template`` do once their options are read.

:mod:`geardesign.cli_app` declares them to typer (the command line's contract: help, options,
errors); :mod:`geardesign.cli_options` reads the common command lines without importing
typer.  Both call these functions; they end with :class:`Exit` (the exit code)."""

from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import List, Optional

from geardesign.cli_options import EXTENSIONS, PLOT_KINDS
from geardesign.core.errors import InputError, Problem


class Exit(SystemExit):
    """The end of a command with its exit code (0 pass, 1 a check failed, 2 unusable
    input): a :class:`SystemExit`, which typer and click let through unchanged."""


def _err(line: str) -> None:
    """One line on stderr; control characters of a path or a value are shown, never obeyed."""
    from geardesign.core.text import escape_controls

    sys.stderr.write(escape_controls(line) + "\n")


def _out(line: str) -> None:
    from geardesign.core.text import escape_controls

    sys.stdout.write(escape_controls(line) + "\n")


def _targets(*paths: Optional[Path], inputs=()) -> None:
    """Every file to be written is looked at before the work starts
    (:func:`geardesign.core.atomic.target_problem`; none may be one of the ``inputs`` the
    command reads, nor the file of another output): one line and exit 2 when one cannot
    be."""
    seen: list[Path] = []
    for path in paths:
        if path is not None:
            from geardesign.core.atomic import target_problem

            why = target_problem(path, inputs=inputs)
            if why is None and any(_same_file(path, other) for other in seen):
                why = "it is given for two outputs; give each output its own file"
            if why is not None:
                _err(f"{path}: cannot write: {why}")
                raise Exit(2)
            seen.append(path)


def _same_file(a: Path, b: Path) -> bool:
    """Whether the paths ``a`` and ``b`` name one file (links followed; a hard link)."""
    if os.path.realpath(a) == os.path.realpath(b):
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


MAX_PROBLEM_LINES = 20
"""Input problems printed at most; the rest are counted (a spec with millions of unknown
keys still gives a short answer)."""


def _report_problems(problems: list[str]) -> None:
    for line in problems[:MAX_PROBLEM_LINES]:
        _err(line)
    if len(problems) > MAX_PROBLEM_LINES:
        _err(f"... and {len(problems) - MAX_PROBLEM_LINES} more problems")


def _choose_format(fmt: Optional[str], output: Optional[Path]) -> str:
    if fmt is not None:
        return getattr(fmt, "value", fmt)     # a Format of the typer command, or its value
    if output is not None:
        suffix = output.suffix.lower()
        if suffix not in EXTENSIONS and str(output) not in ("/dev/null", "/dev/stdout"):
            _err(f"{output}: cannot write a report as {suffix or 'a file without extension'}; "
                 f"use one of {', '.join(EXTENSIONS)} or give --format")
            raise Exit(2)
        return EXTENSIONS.get(suffix, "json")
    return "table" if sys.stdout.isatty() else "json"


def _load(path: Path, expect_kind: Optional[str]):
    """A spec file, or the spec on standard input when the path is ``-``."""
    from geardesign.core import registry

    if str(path) != "-":
        return registry.load(path, expect_kind)
    from geardesign.core.io import MAX_SPEC_BYTES, decode, parse_toml

    raw = sys.stdin.buffer.read(MAX_SPEC_BYTES + 1)   # a pipe: read at most the limit
    if len(raw) > MAX_SPEC_BYTES:
        raise InputError(Problem("", "cannot be used: larger than 4 MiB; a spec is a few kB"))
    calc, spec = registry.load_data(parse_toml(decode(raw)), "<stdin>", expect_kind)
    spec.base_dir = Path.cwd()
    return calc, spec


def _compute_all(paths: List[Path], expect_kind: Optional[str], mode: Optional[str] = None,
                 advise: bool = True):
    """Compute every spec; ``mode`` (from ``--select``/``--design``) overrides the spec's
    top-level ``mode`` key for calculators that have one; ``advise=False``: the rating
    without the search for the failed checks' fixes (``validate``: the same input
    problems, :class:`geardesign.core.registry.Calculator`)."""
    results, problems = [], []
    if sum(str(p) == "-" for p in paths) > 1:
        _err("-: standard input is given more than once; it can be read once")
        raise Exit(2)
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
            results.append((calc.compute if advise else calc.rate)(spec))
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
        raise Exit(2)
    if output is None and (sys.stdout.isatty() or not hasattr(sys.stdout, "buffer")):
        # a terminal, or a text-only stream (an embedding program's): no place for bytes
        _err("geardesign: --format pdf writes a file: give --output FILE.pdf")
        raise Exit(2)


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
            raise Exit(2)
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
    from geardesign.core.atomic import atomic_path, write_atomic

    try:
        if isinstance(text, bytes):
            with atomic_path(path) as tmp:
                Path(tmp).write_bytes(text)
        else:
            write_atomic(path, text)
    except InputError as exc:
        _err(f"{path}: cannot write: {exc.problems[0].message}")
        raise Exit(2)
    except OSError as exc:
        _err(f"{path}: cannot write ({exc.strerror or exc})")
        raise Exit(2)


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
        raise Exit(2)
    try:
        write_plot(with_history[0], plot)
    except PlotError as exc:
        _err(f"{plot}: {exc}")
        raise Exit(2)


def _write_report_plot(result, plot: Path) -> None:
    """``--plot FILE.svg`` of a kind whose report has pictures (shaft diagrams, a drive's
    power flow and heat balance): the report's pictures in one SVG."""
    from geardesign.rendering.figures import plot_svg

    svg = plot_svg(result)
    if svg is None:
        _err(f"{plot}: --plot: a {result.kind} result has no picture; pictures: spur, pzdn "
             f"(with [startup]), {', '.join(PLOT_KINDS)}, sweep")
        raise Exit(2)
    if plot.suffix.lower() != ".svg":
        _err(f"{plot}: --plot of a {result.kind} result writes .svg")
        raise Exit(2)
    _write(plot, svg)


def _write_spur_file(result, path: Path, writer: str) -> None:
    """``--plot`` / ``--profile`` of a spur result (geardesign.spur.export)."""
    from geardesign.spur import export

    try:
        getattr(export, writer)(result, path)
    except export.ExportError as exc:
        _err(f"{path}: {exc}")
        raise Exit(2)


def _emit(paths: List[Path], fmt: Optional[str], output: Optional[Path], quiet: bool,
          expect_kind: Optional[str] = None, mode: Optional[str] = None,
          plot: Optional[Path] = None, keep_going: bool = False,
          profile: Optional[Path] = None) -> None:
    fmt_name = _choose_format(fmt, output)
    _pdf_ready(fmt_name, output)
    _targets(output, plot, profile, inputs=paths)
    results, problems = _compute_all(paths, expect_kind, mode)
    if problems:
        _report_problems(problems)
        if not keep_going or not results:
            raise Exit(2)
    if plot is not None:
        _write_plot(results, plot)
    if profile is not None:
        if len(results) != 1 or results[0].kind != "spur":
            _err(f"{profile}: --profile needs exactly one spur spec")
            raise Exit(2)
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
    raise Exit(code)


def run_cmd(specs: List[Path], format: Optional[str] = None, output: Optional[Path] = None,
            quiet: bool = False, keep_going: bool = False, select: bool = False,
            plot: Optional[Path] = None, profile: Optional[Path] = None) -> None:
    """Compute one or more specs ("-" reads standard input), dispatching on each `kind`."""
    _emit(specs, format, output, quiet, mode="select" if select else None, plot=plot,
          keep_going=keep_going, profile=profile)


def kind_cmd(kind: str, specs: List[Path], format: Optional[str] = None,
             output: Optional[Path] = None, quiet: bool = False, keep_going: bool = False,
             select: bool = False, plot: Optional[Path] = None,
             profile: Optional[Path] = None) -> None:
    """``geardesign KIND``: compute specs of that kind only (the options the kind has are
    :func:`geardesign.cli_options.kind_options`)."""
    _emit(specs, format, output, quiet, expect_kind=kind, mode="select" if select else None,
          plot=plot, keep_going=keep_going, profile=profile)


def list_cmd() -> None:
    """List the calculators: kind, what it does, standards used."""
    from geardesign.core.kinds import catalog

    rows = catalog()
    width = max(len(kind) for kind, _, _ in rows)
    for kind, summary, methods in rows:
        sys.stdout.write(f"{kind:<{width}}  {summary} [{', '.join(methods)}]\n")


def schema(kind: str):
    """The spec schema of the calculator ``kind``; an unknown kind is one line (with the
    closest known one) and exit 2."""
    from geardesign.core.kinds import KINDS, schema

    if kind not in KINDS:
        import difflib

        close = difflib.get_close_matches(kind, list(KINDS), 1, 0.6)
        hint = f' (did you mean "{close[0]}"?)' if close else ""
        known = ", ".join(KINDS)
        _err(f'geardesign: unknown calculator "{kind}"{hint}; known: {known}')
        raise Exit(2)
    return schema(kind)


def template_cmd(kind: str) -> None:
    """Print a complete commented example spec."""
    from geardesign.core.template import template

    sys.stdout.write(template(schema(kind)))


def validate_cmd(specs: List[Path], quiet: bool = False) -> None:
    """Check spec file(s) without reporting results: exit 0 if usable, 2 if not."""
    results, problems = _compute_all(specs, None, advise=False)
    if not quiet:
        for r in results:
            _out(f"{r.source}: ok ({r.kind})")
    if problems:
        _report_problems(problems)
        raise Exit(2)
