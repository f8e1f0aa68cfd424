"""Every file is written whole or not at all (deathsphere.writers.atomic),
and a stopped command exits with the contract's status, in one line."""

import glob
import os
import pathlib
import re
import signal
import subprocess
import sys
import time

import pytest

import deathsphere
from deathsphere.writers.atomic import atomic_file, atomic_path, not_written


#: What writes a file (or starts an encoder that does), outside a docstring's example.
WRITES = re.compile(r"""savefig\(|ParquetWriter\(|\.write_table\(|write_bytes\(|write_text\(|Popen\(|"""
                    r"""open\([^)]*["'][wax]b?["']""")


#: Modules that start a process writing to the terminal only, never a file:
#: ``deathsphere docs TOPIC`` hands a long page to the user's pager on a terminal.
TERMINAL_ONLY = {"cli/docs.py"}


def test_every_module_that_writes_a_file_writes_it_through_atomic():
    package = pathlib.Path(deathsphere.__file__).parent
    unguarded = []
    for path in package.rglob("*.py"):
        if str(path.relative_to(package)) in TERMINAL_ONLY:
            text = path.read_text(encoding="utf-8")
            # its one process is the pager, and nothing else in it writes
            assert [line for line in text.splitlines() if WRITES.search(line)] == [
                line for line in text.splitlines() if "Popen(" in line and "PIPE" in line], path
            continue
        text = path.read_text(encoding="utf-8")
        lines = [line for line in text.splitlines() if WRITES.search(line) and ">>>" not in line]
        if lines and path.name != "atomic.py" and "deathsphere.writers.atomic" not in text:
            unguarded.append(f"{path.relative_to(package)}: {lines[0].strip()}")
    assert unguarded == []


def _leftovers(folder):
    return sorted(glob.glob(os.path.join(folder, ".*.part*")))


def test_a_complete_write_appears_under_its_name_with_a_plain_files_mode(tmp_path):
    target = tmp_path / "out.csv"
    with atomic_file(target, "w") as out:
        out.write("x\n1\n")
        assert not target.exists()  # nothing under the name before the end
        assert len(_leftovers(tmp_path)) == 1 and _leftovers(tmp_path)[0].endswith(".part.csv")
    mask = os.umask(0)
    os.umask(mask)
    assert target.read_text() == "x\n1\n" and _leftovers(tmp_path) == []
    assert target.stat().st_mode & 0o777 == 0o666 & ~mask


@pytest.mark.parametrize("stop", [OSError(28, "No space left on device"), KeyboardInterrupt()])
def test_a_failed_write_leaves_the_old_file_and_no_temporary(tmp_path, stop):
    target = tmp_path / "out.parquet"
    target.write_bytes(b"the earlier result")
    not_written()
    with pytest.raises(type(stop)):
        with atomic_path(target) as temp:
            assert temp.endswith(".part.parquet")  # the format's extension, for ffmpeg and matplotlib
            with open(temp, "wb") as out:
                out.write(b"half")
            raise stop
    assert target.read_bytes() == b"the earlier result"
    assert _leftovers(tmp_path) == [] and not_written() == [str(target)]


def test_a_figure_that_fails_to_save_leaves_nothing(tmp_path):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    from deathsphere.render.figures import save_figure

    target = tmp_path / "map.png"
    with pytest.raises(ValueError):
        save_figure(Figure(), target, "no-such-format", 50)
    assert os.listdir(tmp_path) == []


def test_a_table_file_that_fails_midway_is_status_3_and_named(run, tmp_path, monkeypatch):
    import deathsphere.cli.base as base

    def half_then_full_disk(chunks, out, **_):
        out.write("input_row\n1\n")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(base, "write_csv", half_then_full_disk)
    target = tmp_path / "grid.csv"
    res = run("sweep", "--theta", "60", "--alpha", "10", "--output", str(target))
    assert res.exit_code == 3
    assert res.stderr.strip().splitlines() == [
        f"deathsphere: error: cannot write the results: No space left on device; not written: {target}"]
    assert os.listdir(tmp_path) == []


def _stop_when_writing(tmp_path, args, sig, group=False):
    """Start the command, send ``sig`` once its temporary file exists (to
    its whole process group with ``group``, as a terminal's Ctrl-C does);
    (status, stderr)."""
    proc = subprocess.Popen([sys.executable, "-m", "deathsphere", *args], cwd=tmp_path, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True, start_new_session=group)
    try:
        # with ``group``: once rows are written, so that the workers are running
        while proc.poll() is None and not (_leftovers(tmp_path) and (not group or _written(tmp_path))):
            time.sleep(0.02)
        assert proc.poll() is None, "the command ended before it wrote anything"
        if group:
            os.killpg(proc.pid, sig)
        else:
            proc.send_signal(sig)
        _, err = proc.communicate(timeout=60)
    finally:
        if group:  # the workers too, should the test fail
            try:
                os.killpg(proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        proc.kill()
    return proc.returncode, err


@pytest.mark.parametrize("sig, status, word", [(signal.SIGINT, 130, "interrupted"),
                                               (signal.SIGTERM, 143, "terminated")])
def test_a_stopped_parquet_sweep_leaves_no_file(tmp_path, sig, status, word):
    pytest.importorskip("pyarrow")
    code, err = _stop_when_writing(
        tmp_path, ["sweep", "--theta", "0:180:0.01", "--alpha", "-90:90:0.05", "--output", "big.parquet"], sig)
    assert code == status
    assert err.splitlines() == [f"deathsphere: {word}; not written: big.parquet"]
    assert os.listdir(tmp_path) == []


def _written(folder):
    try:
        return any(os.path.getsize(temp) for temp in _leftovers(folder))
    except OSError:
        return False


@pytest.mark.parametrize("sig, status, word", [(signal.SIGINT, 130, "interrupted"),
                                               (signal.SIGTERM, 143, "terminated")])
def test_a_stop_sent_to_every_process_of_a_parallel_sweep_is_one_line(tmp_path, sig, status, word):
    # the worker processes get the signal too: the caller alone acts on it
    code, err = _stop_when_writing(
        tmp_path, ["sweep", "--theta", "0:180:0.01", "--alpha", "-90:90:0.05", "--jobs", "2", "--output", "big.csv"],
        sig, group=True)
    assert code == status
    assert err.splitlines() == [f"deathsphere: {word}; not written: big.csv"]
    assert os.listdir(tmp_path) == []


def test_an_interrupted_mp4_leaves_no_file_and_no_encoder(tmp_path):
    pytest.importorskip("matplotlib")
    from deathsphere.viewer import has_ffmpeg

    if not has_ffmpeg():
        pytest.skip("ffmpeg is not installed")
    code, err = _stop_when_writing(
        tmp_path, ["simulate", "--theta", "60", "--alpha", "10", "--periods", "1", "--output", "run.mp4"],
        signal.SIGINT, group=True)  # as a terminal's Ctrl-C: ffmpeg is sent it too
    assert code == 130
    assert err.splitlines() == ["deathsphere: interrupted; not written: run.mp4"]
    assert os.listdir(tmp_path) == []
    assert _encoders_writing_in(tmp_path) == []


def _encoders_writing_in(folder):
    """The processes whose command line names ``folder`` (an ffmpeg left running)."""
    found = []
    for cmdline in glob.glob("/proc/[0-9]*/cmdline"):
        try:
            with open(cmdline, "rb") as f:
                text = f.read().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if str(folder) in text and "ffmpeg" in text:
            found.append(text)
    return found


def test_a_stop_inside_the_import_machinery_is_deferred_not_lost():
    """Raised inside importlib's own code the exception would be swallowed
    (and could leave a module lock held): it is retried once out of it."""
    from types import SimpleNamespace

    import deathsphere.cli.base as base

    inside = SimpleNamespace(f_code=SimpleNamespace(co_filename="<frozen importlib._bootstrap>"))
    try:
        base._raise_or_defer(base.Terminated, inside)
        assert base._DEFERRED == [base.Terminated]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
    outside = SimpleNamespace(f_code=SimpleNamespace(co_filename=__file__))
    with pytest.raises(base.Terminated):
        base._retry_deferred(signal.SIGALRM, outside)
    assert base._DEFERRED == []
