"""The README's "A short tour" is real output: every ``$ geardesign ...`` command of the
section is run as a user types it (at ``COLUMNS=100``, from a folder holding ``specs/`` and
the spec files the section shows), and the lines the README prints must be what the command
prints, in order (``...`` stands for lines left out; ``$ echo $?`` is followed by the exit
code of the command before).

On purpose only, ``python -m pytest tests/test_readme_tour.py --update-readme`` rewrites the
shown output of each drifted command (and its exit code) from a real run, keeping where the
README leaves lines out (see :func:`regenerate`); then review ``git diff README.md``."""

from __future__ import annotations

import difflib
import re
import shlex

import pytest

from tests.conftest import ROOT
from tests.helpers_cli import cli

GAP = "..."


def tour() -> str:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    start = text.index("## A short tour")
    end = text.index("\n## ", start + 1)
    return text[start:end]


def blocks(section: str) -> list[tuple[str, list[str]]]:
    """The fenced blocks of the section: (language, lines)."""
    return [(lang, body.split("\n")) for lang, body in
            re.findall(r"```(\w*)\n(.*?)\n```", section, flags=re.S)]


def commands(section: str) -> list[tuple[list[str], list[str], int | None, str]]:
    """(argv after ``geardesign``, the output lines shown, the exit code shown or None, the
    README's text of the command, its output and exit code)."""
    out = []
    for lang, lines in blocks(section):
        if lang or not lines or not lines[0].startswith("$ geardesign "):
            continue
        i = 0
        while i < len(lines):
            argv = shlex.split(lines[i][2:])[1:]
            j = i + 1
            while j < len(lines) and not lines[j].startswith("$ "):
                j += 1
            shown, code = lines[i + 1:j], None
            if j < len(lines) and lines[j] == "$ echo $?":
                code = int(lines[j + 1])
                j += 2
            out.append((argv, shown, code, "\n".join(lines[i:j])))
            i = j
    return out


def runs(shown: list[str]) -> list[list[str]]:
    """The shown lines split at the ``...`` (an empty run where a gap begins or ends)."""
    segments, cur = [], []
    for line in shown:
        if line == GAP:
            segments.append(cur)
            cur = []
        else:
            cur.append(line)
    segments.append(cur)
    return segments


def matches(shown: list[str], actual: list[str]) -> bool:
    """The shown lines are the actual ones with runs of lines left out at the ``...``."""
    segments = runs(shown)
    pos = 0
    for k, seg in enumerate(segments):
        if not seg:
            continue
        if k == 0:                                  # no gap before: the output begins so
            if actual[:len(seg)] != seg:
                return False
            pos = len(seg)
            continue
        found = next((p for p in range(pos, len(actual) - len(seg) + 1)
                      if actual[p:p + len(seg)] == seg), None)
        if found is None:
            return False
        pos = found + len(seg)
    return not segments[-1] or pos == len(actual)   # no gap after: the output ends so


def regenerate(shown: list[str], actual: list[str]) -> list[str]:
    """The shown lines rewritten from the actual output, keeping the README's cuts: each run
    of lines between ``...`` is replaced by as many actual lines, from the line most like the
    run's first line onwards (the first run from the start, a last run without ``...`` after
    it to the end of the output)."""
    segments = runs(shown)
    out: list[str] = []
    pos = 0
    for k, seg in enumerate(segments):
        if k:
            out.append(GAP)
        if not seg:
            continue
        last = k == len(segments) - 1
        if k == 0:
            start = 0
        else:
            rest = actual[pos:] or [""]
            score = [difflib.SequenceMatcher(None, seg[0], line).ratio() for line in rest]
            start = pos + score.index(max(score))
        end = len(actual) if last else start + len(seg)
        out.extend(actual[start:end])
        pos = min(end, len(actual))
    return out


def rewrite(raw: str, shown: list[str], argv_line: str, actual: list[str], code: int | None,
            got: int) -> None:
    """Replace the README's text of one command (``raw``) by the regenerated one."""
    path = ROOT / "README.md"
    text = path.read_text(encoding="utf-8")
    new = [argv_line, *regenerate(shown, actual)]
    if code is not None:
        new += ["$ echo $?", str(got)]
    assert text.count(raw) == 1, "README.md: the tour shows this command twice"
    path.write_text(text.replace(raw, "\n".join(new)), encoding="utf-8")


SECTION = tour()
COMMANDS = commands(SECTION)


def test_the_tour_shows_commands():
    assert len(COMMANDS) >= 3
    assert any(code == 1 for _, _, code, _ in COMMANDS)
    assert any(code == 2 for _, _, code, _ in COMMANDS)


@pytest.mark.parametrize("argv,shown,code,raw", COMMANDS,
                         ids=[" ".join(c[0]) for c in COMMANDS])
def test_tour_output_is_what_the_command_prints(argv, shown, code, raw, tmp_path, monkeypatch,
                                                update_readme):
    (tmp_path / "specs").symlink_to(ROOT / "specs", target_is_directory=True)
    for lang, lines in blocks(SECTION):      # the spec files the tour shows but specs/ lacks
        name = lines[0][2:].strip() if lines and lines[0].startswith("# ") else ""
        if lang == "toml" and name.endswith(".toml") and "/" not in name:
            (tmp_path / name).write_text("\n".join(lines[1:]) + "\n", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("COLUMNS", "100")
    monkeypatch.delenv("NO_COLOR", raising=False)
    got, out, err = cli(*argv)
    actual = (out + err).rstrip("\n").split("\n")
    if update_readme and not (matches(shown, actual) and code in (None, got)):
        rewrite(raw, shown, raw.split("\n", 1)[0], actual, code, got)
        return
    assert matches(shown, actual), (
        "README.md, A short tour: the output of `geardesign " + " ".join(argv) + "` is now:\n"
        + "\n".join(actual) + "\n(rewrite it from real runs: --update-readme)")
    if code is not None:
        assert got == code


def test_gaps_are_matched_as_runs_of_lines():
    assert matches(["a", GAP, "c"], ["a", "b", "b", "c"])
    assert not matches(["a", GAP, "c"], ["a", "c", "d"])
    assert matches([GAP, "c", GAP], ["a", "c", "d"])
    assert not matches(["b"], ["a", "b"])


def test_regenerate_keeps_the_cuts():
    assert regenerate(["a", GAP, "c"], ["a", "b", "c"]) == ["a", GAP, "c"]
    assert regenerate(["a", GAP, "c 1"], ["a2", "b", "c 2", "d"]) == ["a2", GAP, "c 2", "d"]
    assert regenerate(["x", "y", GAP], ["p", "q", "r"]) == ["p", "q", GAP]
    assert regenerate([GAP, "PASS 2"], ["a", "FAIL 3", "PASS 3"]) == [GAP, "PASS 3"]
    for shown, actual in ((["a", GAP, "c"], ["a", "b", "c"]), ([GAP, "x"], ["w", "x"])):
        assert matches(regenerate(shown, actual), actual)


def test_update_readme_rewrites_only_the_drifted_block(tmp_path, monkeypatch):
    """The rewrite replaces the command's text, output and exit code, nothing else."""
    readme = tmp_path / "README.md"
    readme.write_text("intro\n```\n$ geardesign run a.toml\nold\n...\nend 1\n$ echo $?\n0\n```\n"
                      "tail\n", encoding="utf-8")
    monkeypatch.setattr(__import__(__name__, fromlist=["ROOT"]), "ROOT", tmp_path)
    raw = "$ geardesign run a.toml\nold\n...\nend 1\n$ echo $?\n0"
    rewrite(raw, ["old", GAP, "end 1"], "$ geardesign run a.toml", ["new", "x", "end 2"], 0, 1)
    assert readme.read_text(encoding="utf-8") == (
        "intro\n```\n$ geardesign run a.toml\nnew\n...\nend 2\n$ echo $?\n1\n```\ntail\n")
