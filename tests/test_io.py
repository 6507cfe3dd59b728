"""Safe output writes: regular files replaced atomically, other paths written once, bad paths
refused."""

import os
import stat
import threading

import pytest

from obslib._io import OutputPathError, as_output_path, write_output


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


def test_fifo_is_written_once_and_never_read(tmp_path):
    fifo = tmp_path / "pipe"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    assert as_output_path(fifo) == fifo
    write_output(fifo, "through the pipe\n")
    reader.join(timeout=10)
    assert got == ["through the pipe\n"]


def test_full_device_fails_without_reading(tmp_path):
    if not os.path.exists("/dev/full"):
        pytest.skip("no /dev/full on this system")
    with pytest.raises(OSError):
        write_output("/dev/full", "x" * 100)


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
