"""The README's "A short tour" is real output: every ``$ geardesign ...`` command of the
section is run as a user types it (at ``COLUMNS=100``, from a folder holding ``specs/`` and
the spec files the section shows), and the lines the README prints must be what the command
prints, in order (``...`` stands for lines left out; ``$ echo $?`` is followed by the exit
code of the command before)."""

from __future__ import annotations

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


def commands(section: str) -> list[tuple[list[str], list[str], int | None]]:
    """(argv after ``geardesign``, the output lines shown, the exit code shown or None)."""
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
            out.append((argv, shown, code))
            i = j
    return out


def matches(shown: list[str], actual: list[str]) -> bool:
    """The shown lines are the actual ones with runs of lines left out at the ``...``."""
    segments, cur = [], []
    for line in shown:
        if line == GAP:
            segments.append(cur)
            cur = []
        else:
            cur.append(line)
    segments.append(cur)
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


SECTION = tour()
COMMANDS = commands(SECTION)


def test_the_tour_shows_commands():
    assert len(COMMANDS) >= 3
    assert any(code == 1 for _, _, code in COMMANDS)
    assert any(code == 2 for _, _, code in COMMANDS)


@pytest.mark.parametrize("argv,shown,code", COMMANDS, ids=[" ".join(c[0]) for c in COMMANDS])
def test_tour_output_is_what_the_command_prints(argv, shown, code, tmp_path, monkeypatch):
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
    assert matches(shown, actual), (
        "README.md, A short tour: the output of `geardesign " + " ".join(argv) + "` is now:\n"
        + "\n".join(actual))
    if code is not None:
        assert got == code


def test_gaps_are_matched_as_runs_of_lines():
    assert matches(["a", GAP, "c"], ["a", "b", "b", "c"])
    assert not matches(["a", GAP, "c"], ["a", "c", "d"])
    assert matches([GAP, "c", GAP], ["a", "c", "d"])
    assert not matches(["b"], ["a", "b"])
