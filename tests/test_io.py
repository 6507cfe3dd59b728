"""Safe output writes: regular files replaced atomically, other paths written once, bad paths
refused."""

import errno
import json
import os
import signal
import stat
import subprocess
import sys

import pytest

from obslib._io import (
    STOP_SIGNALS,
    OutputPathError,
    Stopped,
    as_input_file,
    as_output_path,
    command,
    uninterrupted,
    write_output,
)


def test_regular_file_is_written_and_left_alone_when_unchanged(tmp_path):
    p = tmp_path / "out.md"
    assert write_output(p, "hello\n") is True
    assert p.read_text() == "hello\n"
    mtime = p.stat().st_mtime_ns
    assert write_output(p, "hello\n") is False
    assert p.stat().st_mtime_ns == mtime
    assert write_output(p, "other\n") is True
    assert p.read_text() == "other\n"
    assert [q.name for q in tmp_path.iterdir()] == ["out.md"]  # no temporary file left


def test_mode_of_an_existing_file_is_kept(tmp_path):
    p = tmp_path / "out.md"
    p.write_text("x")
    p.chmod(0o640)
    write_output(p, "y")
    assert stat.S_IMODE(p.stat().st_mode) == 0o640


def test_a_fifo_or_a_device_is_refused_before_any_work(tmp_path):
    # a FIFO nobody reads would hang the write; a device is not a file that can be replaced
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    for special, kind in ((fifo, "is a FIFO"), ("/dev/null", "is a character device")):
        with pytest.raises(OutputPathError, match=f"{kind}.*not a regular file"):
            as_output_path(special)
        with pytest.raises(OutputPathError, match=kind):
            write_output(special, "x")  # never opened: this would block on the FIFO
    assert stat.S_ISFIFO(fifo.stat().st_mode)
    link = tmp_path / "to-null"
    link.symlink_to("/dev/null")
    with pytest.raises(OutputPathError, match="is a character device"):
        as_output_path(link)


def test_a_symlink_is_written_through_and_kept(tmp_path):
    (tmp_path / "real").mkdir()
    target = tmp_path / "real" / "data.json"
    target.write_text("old\n")
    link = tmp_path / "data.json"
    link.symlink_to(target)
    chain = tmp_path / "chain.json"
    chain.symlink_to(link)
    assert as_output_path(chain) == chain
    assert write_output(chain, "new\n") is True
    assert chain.is_symlink() and link.is_symlink() and target.read_text() == "new\n"
    assert sorted(q.name for q in (tmp_path / "real").iterdir()) == ["data.json"]
    dangling = tmp_path / "later.json"
    dangling.symlink_to(tmp_path / "real" / "later.json")  # written through: the file is created
    assert write_output(dangling, "x") and (tmp_path / "real" / "later.json").read_text() == "x"
    broken = tmp_path / "broken.json"
    broken.symlink_to(tmp_path / "nowhere" / "x.json")
    with pytest.raises(OutputPathError, match="does not exist"):
        as_output_path(broken)


def test_a_failed_write_leaves_the_file_and_no_temporary(tmp_path, monkeypatch):
    p = tmp_path / "out.json"
    p.write_text("old\n")

    def full(fd):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(os, "fsync", full)
    with pytest.raises(OSError, match="No space left"):
        write_output(p, "new text\n")
    assert p.read_text() == "old\n" and [q.name for q in tmp_path.iterdir()] == ["out.json"]


def test_a_write_beyond_the_file_size_limit_fails_cleanly(tmp_path):
    # a real failed write (EFBIG, as a full disk gives ENOSPC), in a process limited to 1 kB files
    p = tmp_path / "out.json"
    p.write_text("old\n")
    code = ("import resource, signal, sys; signal.signal(signal.SIGXFSZ, signal.SIG_IGN); "
            "resource.setrlimit(resource.RLIMIT_FSIZE, (1000, 1000)); "
            "from obslib._io import write_or_report; "
            "sys.exit(0 if write_or_report('prog', sys.argv[1], 'x' * 5000) else 1)")
    out = subprocess.run([sys.executable, "-c", code, str(p)], capture_output=True, text=True)
    assert out.returncode == 1 and out.stderr == f"prog: error: cannot write {p}: File too large\n"
    assert p.read_text() == "old\n" and [q.name for q in tmp_path.iterdir()] == ["out.json"]


def test_the_lock_serialises_read_modify_write_across_processes(tmp_path):
    # two processes each add 40 entries to one JSON list, read-modify-write under the lock
    counter = tmp_path / "list.json"
    write_output(counter, "[]")
    code = ("import json, sys; from pathlib import Path; from obslib._io import locked, "
            "write_output\n"
            "p = Path(sys.argv[1])\n"
            "for k in range(40):\n"
            "    with locked(p.with_name('.lock')):\n"
            "        items = json.loads(p.read_text())\n"
            "        write_output(p, json.dumps(items + [sys.argv[2] + str(k)]))\n")
    procs = [subprocess.Popen([sys.executable, "-c", code, str(counter), tag]) for tag in "ab"]
    assert [q.wait(timeout=120) for q in procs] == [0, 0]
    items = json.loads(counter.read_text())
    assert sorted(items) == sorted(f"{t}{k}" for t in "ab" for k in range(40))


@pytest.mark.parametrize("bad, why", [
    ("", "empty"),
    ("{tmp}", "is a directory"),
    ("{tmp}/missing/out.json", "does not exist"),
    ("{tmp}/file.txt/out.json", "not a directory"),
])
def test_impossible_paths_are_refused_before_work(tmp_path, bad, why):
    (tmp_path / "file.txt").write_text("x")
    with pytest.raises(OutputPathError, match=why):
        as_output_path(bad.format(tmp=tmp_path))
    assert not (tmp_path / "missing").exists()


def test_unwritable_directory_is_refused(tmp_path):
    if os.geteuid() == 0:
        pytest.skip("root may write anywhere")
    d = tmp_path / "ro"
    d.mkdir(mode=0o500)
    with pytest.raises(OutputPathError, match="permission denied"):
        as_output_path(d / "out.json")


def test_a_missing_or_special_input_file_is_named(tmp_path):
    from obslib._validate import MissingFileError

    (tmp_path / "data.json").write_text("{}")
    assert as_input_file(tmp_path / "data.json") == tmp_path / "data.json"
    os.mkfifo(tmp_path / "pipe")
    for bad, why in ((tmp_path / "none.json", "no such file"), (tmp_path / "pipe", "is a FIFO"),
                     (tmp_path, "is a directory")):
        with pytest.raises(MissingFileError, match=why) as exc:
            as_input_file(bad)
        assert isinstance(exc.value, ValueError) and isinstance(exc.value, FileNotFoundError)


# --------------------------------------------------------------------------------------------
# Stopping a command
# --------------------------------------------------------------------------------------------


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM, signal.SIGHUP])
def test_a_stop_signal_ends_a_command_with_one_line_and_128_plus_its_number(signum, capsys):
    ran = []
    before = {s: signal.getsignal(s) for s in STOP_SIGNALS}

    @command("python -m demo")
    def main(argv=None):
        try:
            os.kill(os.getpid(), signum)
            ran.append("not reached")  # the handler raises at the next bytecode
        finally:
            ran.append("finally")
        return 0

    assert main([]) == 128 + signum
    assert ran == ["finally"]
    name = signal.Signals(signum).name
    assert capsys.readouterr().err == f"python -m demo: stopped by {name}\n"
    assert {s: signal.getsignal(s) for s in STOP_SIGNALS} == before  # the old handlers are back


def test_a_signal_inside_an_uninterrupted_block_stops_at_its_end(tmp_path, capsys):
    steps = []

    @command("python -m demo")
    def main(argv=None):
        with uninterrupted():
            os.kill(os.getpid(), signal.SIGTERM)
            steps.append("first file")
            os.kill(os.getpid(), signal.SIGTERM)  # a second signal during the stop: ignored
            steps.append("second file")
        steps.append("after the block")  # not reached
        return 0

    assert main([]) == 143 and steps == ["first file", "second file"]
    assert capsys.readouterr().err == "python -m demo: stopped by SIGTERM\n"


def test_stopped_is_not_an_exception_and_carries_a_detail():
    stop = Stopped(signal.SIGHUP, "2 finished")
    assert not isinstance(stop, Exception) and stop.status == 129 and stop.name == "SIGHUP"
