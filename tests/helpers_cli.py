"""Run the command line in-process (fast) or as a real process."""

from __future__ import annotations

import io
import subprocess
import sys
from contextlib import redirect_stderr, redirect_stdout

from geardesign.cli import main


def cli(*args: str) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    old = sys.argv
    sys.argv = ["geardesign", *map(str, args)]
    try:
        with redirect_stdout(out), redirect_stderr(err):
            try:
                main()
                code = 0
            except SystemExit as exc:
                code = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        sys.argv = old
    return code, out.getvalue(), err.getvalue()


def cli_process(*args: str, **kw) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "geardesign", *map(str, args)],
                          capture_output=True, text=True, **kw)


def write_spec(tmp_path, text: str, name: str = "s.toml"):
    """Write a spec file in ``tmp_path`` and return its path."""
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def run_bad(tmp_path, text: str) -> list[str]:
    """Run a spec that must be refused: exit 2, nothing on stdout, no traceback; the
    problem lines with the file written as ``s.toml``."""
    path = write_spec(tmp_path, text)
    code, out, err = cli("run", path, "--format", "json")
    assert code == 2, err
    assert out == "" and "Traceback" not in err
    return [line.replace(str(path), "s.toml") for line in err.splitlines()]


def _no_constant(name: str):
    raise AssertionError(f"{name} in the JSON document")


def run_failing(tmp_path, text: str) -> dict:
    """Run a spec whose design fails: exit 1, nothing on stderr; the JSON document (which
    must hold no NaN or Infinity)."""
    import json

    code, out, err = cli("run", write_spec(tmp_path, text), "--format", "json")
    assert code == 1 and err == "", err
    doc = json.loads(out, parse_constant=_no_constant)
    assert doc["verdict"] == "fail"
    return doc


def failed_errors(doc: dict) -> list[dict]:
    """The failed error-severity checks of a result document."""
    return [c for c in doc["checks"] if not c["passed"] and c["severity"] == "error"]


def changed(base: dict, **changes) -> dict:
    """A copy of a spec dict with ``table__key=value`` changes (None removes the key)."""
    import copy

    data = copy.deepcopy(base)
    for path, value in changes.items():
        *head, last = path.split("__")
        node = data
        for part in head:
            node = node.setdefault(part, {})
        if value is None:
            node.pop(last, None)
        else:
            node[last] = value
    return data
