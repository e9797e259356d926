"""One way in, one way out (geardesign.core.io): every file read through one guarded
reader, every file written through one atomic writer that looks at the target before the
work starts; Ctrl-C and SIGTERM leave no temporary file and no traceback; the float
options refuse nan and inf; a sweep's workers are capped at the cores."""

import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from geardesign.core import atomic
from geardesign.core import io as gio
from geardesign.core import run_files
from geardesign.core.errors import InputError
from tests.helpers_cli import cli, write_spec

ROOT = Path(__file__).resolve().parent.parent
SPECS = ROOT / "specs"
PLAIN = (SPECS / "spur_plain.toml").read_text(encoding="utf-8")


def _one_line(err: str) -> str:
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


# --------------------------------------------------------------------------- reading


def test_a_fifo_as_expected_file_is_refused_without_blocking(tmp_path):
    spec = write_spec(tmp_path, PLAIN)
    os.mkfifo(tmp_path / "s.expected.json")
    result = {}
    t = threading.Thread(target=lambda: result.update(r=cli("check", spec)), daemon=True)
    t.start()
    t.join(60)
    assert not t.is_alive(), "reading a FIFO blocked"
    code, out, err = result["r"]
    assert code == 2
    assert _one_line(err).endswith("s.expected.json: cannot be used: not a regular file")


def test_dev_zero_as_expected_file_is_refused_unread(tmp_path):
    spec = write_spec(tmp_path, PLAIN)
    (tmp_path / "s.expected.json").symlink_to("/dev/zero")
    code, _, err = cli("check", spec)
    assert code == 2 and "not a regular file" in _one_line(err)


def test_an_expected_file_over_the_size_limit_is_refused_unread(tmp_path, monkeypatch):
    """A 300 MB expected file (sparse: no disk used) is refused on its size; the reader
    never reads more than the limit."""
    spec = write_spec(tmp_path, PLAIN)
    with open(tmp_path / "s.expected.json", "wb") as fh:
        fh.truncate(300 * 1024 * 1024)
    reads = []
    real = os.read
    monkeypatch.setattr(gio.os, "read", lambda fd, n: reads.append(n) or real(fd, n))
    code, _, err = cli("check", spec)
    assert code == 2 and "larger than 32 MiB" in _one_line(err)
    assert sum(reads) < 1024 * 1024          # the spec, not the expected file


def test_a_deeply_nested_expected_file_is_an_input_error(tmp_path):
    spec = write_spec(tmp_path, PLAIN)
    for depth in (100, 100_000):
        (tmp_path / "s.expected.json").write_text("[" * depth + "]" * depth)
        code, _, err = cli("check", spec)
        assert code == 2 and "nested more than 64 deep" in _one_line(err)


def test_an_expected_file_that_is_no_json_is_one_line(tmp_path):
    spec = write_spec(tmp_path, PLAIN)
    for text in ("{", "\xff", "1" * 5000):
        (tmp_path / "s.expected.json").write_bytes(text.encode("latin-1"))
        code, _, err = cli("check", spec)
        assert code == 2 and "s.expected.json: " in _one_line(err)


def test_a_long_dotted_key_is_refused_before_parsing(tmp_path, monkeypatch):
    """20 000 parts take the TOML parser gigabytes; the key is refused before it parses."""
    import tomllib

    calls = []
    monkeypatch.setattr(tomllib, "loads", lambda *a, **k: calls.append(1))
    key = ".".join(["a"] * 20_000)
    path = write_spec(tmp_path, PLAIN + f"{key} = 1\n")
    code, _, err = cli("run", path, "-f", "json")
    assert code == 2 and "a dotted key of more than 32 parts (line 15)" in _one_line(err)
    assert calls == []


@pytest.mark.parametrize("text, refused", [
    ('a.b.c = 1\n"x.y".z = 2\n', False),
    ('title = "' + ".".join(["w"] * 100) + '"\n', False),     # dots in a string
    ("x = [" + ", ".join(["1.5"] * 500) + "]\n", False),       # floats in an array
    ("t = {" + ".".join(["k"] * 40) + " = 1}\n", True),       # inline table
    ("[" + ".".join(['"q"'] * 40) + "]\n", True),              # quoted header parts
    ("".join(f"[t{i}]\n" for i in range(10_001)), True),
])
def test_toml_bounds(text, refused):
    assert (gio.toml_bounds(text) is not None) == refused


def test_a_stage_file_outside_the_spec_folder_is_refused(tmp_path):
    with pytest.raises(ValueError, match="inside the drive spec's folder"):
        gio.confined("../x.toml", tmp_path, tmp_path, "the drive spec's folder")
    (tmp_path / "link.toml").symlink_to("/etc/hostname")
    with pytest.raises(ValueError, match="inside"):
        gio.confined("link.toml", tmp_path, tmp_path, "the drive spec's folder")
    with pytest.raises(ValueError, match="relative"):
        gio.confined("/etc/hostname", tmp_path, tmp_path, "the drive spec's folder")


# --------------------------------------------------------------------------- writing


@pytest.mark.parametrize("target, why", [
    ("missing/r.json", "the folder"),
    ("adir", "is a folder; give a file name"),
    ("afile/r.json", "a part of the path is a file, not a folder"),
])
def test_an_unwritable_output_is_one_line_before_the_work(tmp_path, monkeypatch, target, why):
    from geardesign.core import registry

    (tmp_path / "adir").mkdir()
    (tmp_path / "afile").write_text("x")
    spec = write_spec(tmp_path, PLAIN)
    computed = []
    monkeypatch.setattr(registry, "load", lambda *a, **k: computed.append(1))
    for option in ("--output", "--plot", "--profile"):
        code, out, err = cli("run", spec, "-f", "json", option, tmp_path / target)
        assert code == 2 and out == "" and computed == []
        line = _one_line(err)
        assert line.startswith(str(tmp_path / target) + ": cannot write: ") and why in line


def test_a_sweep_checks_its_files_before_it_runs(tmp_path, monkeypatch):
    from geardesign.spur import sweep as SW

    monkeypatch.setattr(SW, "run_sweep", lambda *a, **k: pytest.fail("the sweep ran"))
    spec = SPECS / "sweep_spur_iso.toml"
    (tmp_path / "d.csv").mkdir()
    for option, name in (("--data", "no/c.csv"), ("--output", "no/r.json"),
                         ("--plot", "no/p.png"), ("--data", "d.csv")):
        code, _, err = cli("sweep", spec, option, tmp_path / name)
        assert code == 2, err
        assert "cannot write" in _one_line(err)


def test_check_update_never_writes_through_a_link_out_of_the_spec_folder(tmp_path):
    inside, outside = tmp_path / "specs", tmp_path / "other"
    inside.mkdir()
    outside.mkdir()
    victim = outside / "victim.txt"
    victim.write_text("keep me")
    spec = write_spec(inside, PLAIN)
    (inside / "s.expected.json").symlink_to(victim)
    code, _, err = cli("check", "--update", spec)
    assert code == 2
    assert "s.expected.json: cannot write: is a link to a file outside" in _one_line(err)
    assert victim.read_text() == "keep me"
    # a link to a file inside the folder is followed: the file is replaced, the link stays
    (inside / "s.expected.json").unlink()
    (inside / "real.json").write_text("{}")
    (inside / "s.expected.json").symlink_to("real.json")
    code, _, err = cli("check", "--update", spec)
    assert code == 0, err
    assert (inside / "s.expected.json").is_symlink()
    assert json.loads((inside / "real.json").read_text())["kind"] == "spur"
    assert sorted(p.name for p in inside.iterdir()) == ["real.json", "s.expected.json",
                                                          "s.toml"]


def test_the_temporary_file_is_removed_on_sigint_and_the_handlers_restored(tmp_path):
    before = signal.getsignal(signal.SIGINT)
    f = gio.AtomicFile(tmp_path / "r.json")
    assert f.tmp.exists() and signal.getsignal(signal.SIGINT) is not before
    with pytest.raises(KeyboardInterrupt):
        os.kill(os.getpid(), signal.SIGINT)
        for _ in range(1000):   # the handler runs between two bytecodes
            time.sleep(0.001)
    assert list(tmp_path.iterdir()) == []
    assert signal.getsignal(signal.SIGINT) is before
    with gio.atomic_path(tmp_path / "r.json") as tmp:
        tmp.write_text("x")
    assert signal.getsignal(signal.SIGINT) is before
    assert [p.name for p in tmp_path.iterdir()] == ["r.json"]


def _sweep_until_its_temporary_file(tmp_path, sig, after: float = 0.0):
    """A long sweep writing --data; ``sig`` once its temporary file exists (and ``after``
    seconds more: a later moment of the run, e.g. inside the Sobol' kernel's start)."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "geardesign", "sweep", str(SPECS / "sweep_spur_reducer.toml"),
         "--samples", "2000000", "--data", str(tmp_path / "d.csv"), "-f", "json"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    try:
        for _ in range(12000):
            if list(tmp_path.glob(".d.csv.*.tmp")) or proc.poll() is not None:
                break
            time.sleep(0.01)
        assert list(tmp_path.glob(".d.csv.*.tmp")), "no temporary file appeared"
        time.sleep(after)
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert list(tmp_path.iterdir()) == []
    return proc.returncode, out, err


@pytest.mark.parametrize("after", [0.004, 0.012, 0.02, 0.03])
def test_ctrl_c_at_any_moment_of_a_sweep_is_one_line_and_leaves_no_file(tmp_path, after):
    """A Ctrl-C during compiled code that cannot pass it on (SciPy's Sobol' kernel reading
    its direction numbers) was printed as "Exception ignored" and lost: the sweep went on,
    then failed to commit the file the handler had removed (exit 3).  Signals are held
    during such calls, and a commit whose file the handler removed is an interruption."""
    code, out, err = _sweep_until_its_temporary_file(tmp_path, signal.SIGINT, after)
    assert code == 130 and out == ""
    assert _one_line(err) == "geardesign: interrupted"


def test_a_commit_after_the_signal_removed_the_file_is_an_interruption(tmp_path):
    f = gio.AtomicFile(tmp_path / "r.json")
    f.tmp.write_text("x")
    atomic._remove_live()
    with pytest.raises(KeyboardInterrupt):
        f.commit()
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_in_a_sweep_is_one_line_and_leaves_no_file(tmp_path):
    code, out, err = _sweep_until_its_temporary_file(tmp_path, signal.SIGINT)
    assert code == 130 and out == ""
    assert _one_line(err) == "geardesign: interrupted"


def test_sigterm_in_a_sweep_leaves_no_file(tmp_path):
    code, out, err = _sweep_until_its_temporary_file(tmp_path, signal.SIGTERM)
    assert code == -signal.SIGTERM and "Traceback" not in err


# --------------------------------------------------------------------------- options


@pytest.mark.parametrize("value", ["nan", "inf", "-inf", "NaN"])
def test_float_options_refuse_non_finite_values(tmp_path, value):
    spec = write_spec(tmp_path, PLAIN)
    for args in (("check", spec, "--rtol", value), ("bearings", "--bore", value)):
        code, out, err = cli(*args)
        assert code == 2 and out == "" and "Traceback" not in err
        assert "is not a finite number" in err or "is not in the range" in err


def test_sweep_workers_are_capped_at_the_cores(tmp_path, monkeypatch):
    from geardesign.spur import sweep as SW

    seen = {}
    real = SW.run_sweep

    def spy(data, sw, workers=1, *rest):
        seen["workers"] = workers
        return real(data, sw, 1, *rest)

    monkeypatch.setattr(SW, "run_sweep", spy)
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0, 1})
    spec = SPECS / "sweep_spur_iso.toml"
    code, _, err = cli("sweep", spec, "--workers", "32", "-f", "json")
    assert code in (0, 1) and seen["workers"] == 2
    assert _one_line(err) == ("geardesign sweep: --workers 32: using 2, the cores available "
                              "(--force-workers to start 32)")
    code, _, err = cli("sweep", spec, "--workers", "3", "--force-workers", "-f", "json")
    assert code in (0, 1) and seen["workers"] == 3 and err == ""


def test_an_unreachable_scheduler_is_one_line(tmp_path, monkeypatch):
    pytest.importorskip("dask.distributed")
    from geardesign.spur import sweep_dask

    monkeypatch.setattr(sweep_dask, "CONNECT_TIMEOUT", 1.0)      # 10 s in use
    spec = SPECS / "sweep_spur_iso.toml"
    for address in ("tcp://127.0.0.1:9", "nonsense://x"):
        code, out, err = cli("sweep", spec, "--scheduler", address, "-f", "json")
        assert code == 2 and out == ""
        assert _one_line(err).startswith(f"geardesign sweep: --scheduler {address}: cannot "
                                         f"reach the Dask scheduler within 1 s")


def test_reading_a_missing_spec_and_a_directory():
    with pytest.raises(InputError, match="file not found"):
        gio.read_toml(Path("/nonexistent/x.toml"))
    with pytest.raises(InputError, match="is a directory"):
        gio.read_toml(SPECS)


@pytest.mark.parametrize("step", ["5e-324", "1e-300"])
def test_a_sweep_step_too_small_to_count_is_one_line(step):
    code, out, err = cli("sweep", SPECS / "sweep_spur_iso.toml", "--vary",
                         f"gear.module=2:3:{step}", "-f", "json")
    assert code == 2 and out == ""
    assert _one_line(err).endswith(f"sweep.gear.module.step = {step}: gives more than "
                                   f"1000000 values, the most per key: use a larger step")


# ------------------------------------------------ no output replaces an input of the run


def _kept(path: Path) -> tuple:
    """What must not change: the bytes of a file and which file it is."""
    st = path.stat()
    return path.read_bytes(), st.st_ino


_WRITING = [
    ("run", "{spec}", "-f", "json", "--output", "{out}"),
    ("spur", "{spec}", "-f", "json", "--output", "{out}"),
    ("run", "{spec}", "-f", "json", "--plot", "{out}"),
    ("run", "{spec}", "-f", "json", "--profile", "{out}"),
    ("run", "{other}", "{spec}", "-f", "json", "--output", "{out}"),
    ("export", "{spec}", "--output", "{out}"),
    ("sweep", "{sweep}", "-f", "csv", "--output", "{out}"),
]
"""Every command line that writes a file under any name: the output options of run, a
kind's command, export and sweep."""

_NAMED = [
    (("sweep", "{sweep}", "--plot", "{out}"), "out.png"),
    (("sweep", "{sweep}", "--data", "{out}"), "out.csv"),
    (("check", "--update", "{spec}"), "s.expected.json"),
]
"""Those whose file must have its own ending or name: a link or a hard link only."""


@pytest.mark.parametrize("command, how, name", [(c, h, "out.json") for c in _WRITING
                                                for h in ("same", "link", "hard link")]
                         + [(c, h, name) for c, name in _NAMED for h in ("link", "hard link")])
def test_no_output_replaces_a_file_the_command_reads(tmp_path, monkeypatch, command, how, name):
    """Every command and option that writes a file refuses one that is a file it reads
    (the file itself, a link or a hard link to it): one line naming both and what to do,
    exit 2, before the work, the input unchanged."""
    from geardesign.core import registry
    from geardesign.spur import sweep as SW

    spec = write_spec(tmp_path, PLAIN, "s.toml")
    other = write_spec(tmp_path, PLAIN, "other.toml")
    sweep = tmp_path / "sw.toml"
    sweep.write_text((SPECS / "sweep_spur_reducer.toml").read_text(encoding="utf-8"),
                     encoding="utf-8")
    victim = sweep if command[0] == "sweep" else spec
    out = victim if how == "same" else tmp_path / name
    if how == "link":
        out.symlink_to(victim.name)
    elif how == "hard link":
        os.link(victim, out)
    before = _kept(victim)
    computed = []
    monkeypatch.setattr(registry, "load", lambda *a, **k: computed.append(1))
    monkeypatch.setattr(SW, "run_sweep", lambda *a, **k: computed.append(1))
    args = [a.format(spec=spec, other=other, sweep=sweep, out=out) for a in command]
    code, stdout, err = cli(*args)
    assert code == 2 and stdout == "" and computed == [], err
    line = _one_line(err)
    assert "which this run reads as an input; write the output to another file" in line
    assert str(victim.name) in line
    assert _kept(victim) == before


def test_no_output_replaces_a_file_a_spec_names(tmp_path):
    """A file read during the run (a drive's stage file) is refused when the report would
    replace it: one line, exit 2, the stage file unchanged, nothing else written."""
    drive = (SPECS / "drive_worm_spur.toml").read_text(encoding="utf-8")
    (tmp_path / "d.toml").write_text(drive, encoding="utf-8")
    stage = tmp_path / "worm_single_start_reducer.toml"
    stage.write_text((SPECS / stage.name).read_text(encoding="utf-8"), encoding="utf-8")
    before = _kept(stage)
    code, out, err = cli("run", tmp_path / "d.toml", "-f", "json", "--output", stage)
    assert code == 2 and out == ""
    assert "which this run reads as an input" in _one_line(err)
    assert _kept(stage) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["d.toml", stage.name]
    # the same report to another file is written
    code, _, err = cli("run", tmp_path / "d.toml", "-f", "json", "--output", tmp_path / "r.json")
    assert code == 0, err


def test_import_refuses_to_replace_its_model(tmp_path):
    model = tmp_path / "m.rexs"
    model.write_bytes((ROOT / "tests" / "data" / "rexs" / "FVA_worm_stage_1-4.rexs").read_bytes())
    before = _kept(model)
    (tmp_path / "m.toml").symlink_to("m.rexs")
    code, out, err = cli("import", model, "--output", tmp_path / "m.toml")
    assert code == 2 and out == ""
    assert "which this run reads as an input" in _one_line(err)
    assert _kept(model) == before


def test_outside_a_command_nothing_is_remembered(tmp_path):
    """The library (no command running) reads without keeping a list of inputs; within a
    command the list is the command's own and is gone after it."""
    spec = write_spec(tmp_path, PLAIN)
    gio.read_toml(spec)
    assert run_files._INPUTS is None
    assert atomic.target_problem(spec) is None
    expected = tmp_path / "s.expected.json"
    expected.write_text("{}")
    with run_files.inputs_kept():
        gio.read_toml(spec)
        assert "reads as an input" in atomic.target_problem(spec)
        gio.read_json(expected)        # an expected document: check --update replaces it
        assert atomic.target_problem(expected) is None
    assert run_files._INPUTS is None and atomic.target_problem(spec) is None


@pytest.mark.parametrize("args", [
    ("run", "{spec}", "-f", "json", "--output", "{d}/r.json", "--profile", "{d}/r.json"),
    ("run", "{spec}", "-f", "json", "--output", "{d}/r.json", "--profile", "{d}/./r.json"),
    ("run", "{spec}", "-f", "json", "--plot", "{d}/p.svg", "--profile", "{d}/link.svg"),
    ("sweep", "{sweep}", "-f", "csv", "--output", "{d}/r.csv", "--data", "{d}/r.csv"),
])
def test_two_outputs_of_one_command_are_never_one_file(tmp_path, monkeypatch, args):
    """Two outputs of a command (a report and a drawing, a report and the sweep's data)
    written to one file, by its name, another spelling or a link: one line, exit 2, before
    the work (the second would silently replace the first)."""
    from geardesign.core import registry
    from geardesign.spur import sweep as SW

    spec = write_spec(tmp_path, PLAIN)
    (tmp_path / "link.svg").symlink_to("p.svg")
    computed = []
    monkeypatch.setattr(registry, "load", lambda *a, **k: computed.append(1))
    monkeypatch.setattr(SW, "run_sweep", lambda *a, **k: computed.append(1))
    code, out, err = cli(*[a.format(spec=spec, sweep=SPECS / "sweep_spur_reducer.toml",
                                    d=tmp_path) for a in args])
    assert code == 2 and out == "" and computed == [], err
    assert _one_line(err).endswith("cannot write: it is given for two outputs; give each "
                                   "output its own file")


def test_a_report_never_replaces_a_file_the_run_has_written(tmp_path):
    """The plot a pzdn spec names (written during the calculation) and the report to the
    same file: the plot stays, the report is refused in one line, exit 2."""
    pytest.importorskip("matplotlib")
    text = (SPECS / "pzdn_ko2_startup_comparison.toml").read_text(encoding="utf-8")
    spec = write_spec(tmp_path, text.replace("[startup]\n", '[startup]\nplot = "r.svg"\n', 1))
    code, out, err = cli("run", spec, "-f", "json", "--output", tmp_path / "r.svg")
    assert code == 2 and out == ""
    assert _one_line(err).endswith("which this run has written already; give each output "
                                   "its own file")
    assert (tmp_path / "r.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")


@pytest.mark.parametrize("args", [
    ("run", "{loop}"),
    ("run", "{spec}", "-f", "json", "--output", "{loop}"),
    ("run", "{spec}", "-f", "json", "--plot", "{loop}"),
    ("run", "{spec}", "-f", "json", "--profile", "{loop}"),
    ("sweep", "{sweep}", "-f", "json", "--output", "{loop}"),
    ("sweep", "{sweep}", "--data", "{loop}.csv"),
    ("export", "{spec}", "--output", "{loop}"),
    ("import", "{loop}"),
    ("check", "{loop}"),
    ("check", "--update", "{spec}"),
    ("run", "{drive}", "-f", "json"),
])
def test_a_loop_of_links_anywhere_a_path_goes_is_one_line(tmp_path, args):
    """A loop of symbolic links as a spec, an output, an expected file, a model or a stage
    file a drive names: one line, exit 2 (``Path.resolve`` raised a RuntimeError, an
    internal error)."""
    spec = write_spec(tmp_path, PLAIN, "s.toml")
    for a, b in (("loop", "loop2"), ("loop2", "loop"), ("loop.csv", "loop2.csv"),
                 ("loop2.csv", "loop.csv"), ("s.expected.json", "s.expected.json")):
        (tmp_path / a).symlink_to(b)
    drive = (SPECS / "drive_worm_spur.toml").read_text(encoding="utf-8")
    (tmp_path / "d.toml").write_text(drive.replace('file = "worm_single_start_reducer.toml"',
                                                   'file = "loop"'), encoding="utf-8")
    code, out, err = cli(*[a.format(spec=spec, loop=tmp_path / "loop", drive=tmp_path / "d.toml",
                                    sweep=SPECS / "sweep_spur_reducer.toml") for a in args])
    assert code == 2 and out == "", err
    assert "symbolic links" in _one_line(err)
