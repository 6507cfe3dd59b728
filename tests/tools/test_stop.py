"""Stopping the runner at any moment loses nothing: real runs of ``python -m obslib.run`` over
copies of small notebooks in a temporary folder, killed by a signal at several moments (before
any kernel, while a kernel computes, right as a notebook is renamed into place, with SIGKILL
before that rename), and concurrent reruns sharing one index.

After every stop each notebook must parse and be either exactly the file it was or a complete
execution; what finished is recorded (sidecar and index entry, or the times file) and what was
stopped is not; kernels are gone; the exit status is ``128 +`` the signal's number.
"""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import nbformat
import pytest

from obslib.tools import run

from .test_run import write_notebook

#: Runs ``python -m obslib.run``'s ``main`` with its outputs moved under the folder ``argv[1]``
#: (the checkout's ``_build`` and ``book`` are not touched). With ``STOP_AT=<moment>:<SIGNAL>``
#: the process sends itself the signal at that moment: ``precompile`` (before any kernel),
#: ``kernel`` (a kernel has just started: its process id goes to ``kernel.pid``) or ``rename``
#: (a notebook is written in full, right before it is renamed into place).
RUNNER = """\
import os, signal, sys
from pathlib import Path
from obslib.tools import _papermill, run
tmp = Path(sys.argv[1])
run.RUNS_DIR, run.TIMES_FILE = tmp / "runs", tmp / "times.json"
run.EXECUTION_PAGE = tmp / "execution.md"
moment, _, name = os.environ.get("STOP_AT", "").partition(":")
def stop():
    os.kill(os.getpid(), getattr(signal, name))
if moment == "precompile":
    run.precompile = stop
elif moment == "kernel":
    started = _papermill.KERNELS.started
    def hook(provisioner):
        started(provisioner)
        (tmp / "kernel.pid").write_text(str(provisioner.pid))
        stop()
    _papermill.KERNELS.started = hook
elif moment == "rename":
    rename = os.replace
    def replace(src, dst):
        if str(dst).endswith(".ipynb"):
            stop()
        return rename(src, dst)
    os.replace = replace
raise SystemExit(run.main(sys.argv[2:]))
"""


@pytest.fixture
def folder(tmp_path):
    """Three small notebooks: ``a`` prints at once, ``b`` records its kernel's process id and
    computes for a minute (a stop must kill it), ``c`` prints."""
    nbs = tmp_path / "nbs"
    nbs.mkdir()
    write_notebook(nbs / "a.ipynb", "n = 2", ["print('a' * 2000 * n)"])
    write_notebook(nbs / "b.ipynb", "n = 2", [
        "import os, time\n"
        f"open({str(tmp_path / 'b.pid')!r}, 'w').write(str(os.getpid()))\n"
        "time.sleep(60)"])
    write_notebook(nbs / "c.ipynb", "n = 2", ["print(n)"])
    return tmp_path


def start(folder: Path, options: list, notebooks: str, stop_at: str = "") -> subprocess.Popen:
    """The runner over the notebooks named by the letters ``notebooks``, in that order."""
    env = {**os.environ, "STOP_AT": stop_at}
    names = [str(folder / "nbs" / f"{n}.ipynb") for n in notebooks]
    return subprocess.Popen([sys.executable, "-c", RUNNER, str(folder), *options, *names],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def wait_for(predicate, seconds=60.0):
    end = time.monotonic() + seconds
    while not predicate():
        assert time.monotonic() < end, "timed out"
        time.sleep(0.02)


def alive(pid: int) -> bool:
    """Whether process ``pid`` runs (a zombie, dead and not yet reaped, does not)."""
    try:
        return Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except (FileNotFoundError, ProcessLookupError):
        return False


def check_notebooks(folder: Path, originals: dict) -> dict:
    """Every notebook parses and validates, and is its original bytes or a complete execution
    (every code cell executed); returns ``{name: "original" | "executed"}``."""
    state = {}
    for name, data in originals.items():
        path = folder / "nbs" / name
        nb = nbformat.read(path, as_version=4)
        nbformat.validate(nb)
        if path.read_bytes() == data:
            state[name] = "original"
        else:
            assert all(c.execution_count for c in nb.cells if c.cell_type == "code"), name
            state[name] = "executed"
    return state


def originals(folder: Path) -> dict:
    return {p.name: p.read_bytes() for p in sorted((folder / "nbs").glob("*.ipynb"))}


def leftovers(folder: Path) -> list:
    """Temporary files left anywhere under the folder."""
    return sorted(p.name for p in folder.rglob(".*") if p.name not in (".index.lock",
                                                                         ".execution_times.lock"))


def test_sigkill_right_before_a_notebook_is_renamed_leaves_every_notebook_as_it_was(folder):
    # the notebook is fully written to its temporary file, not yet renamed: only SIGKILL stops
    # here without cleaning up, and the committed file is intact
    before = originals(folder)
    p = start(folder, ["--in-place", "--jobs", "1"], "ac", "rename:SIGKILL")
    p.communicate(timeout=120)
    assert p.returncode == -signal.SIGKILL
    assert check_notebooks(folder, before) == {"a.ipynb": "original", "b.ipynb": "original",
                                               "c.ipynb": "original"}


def test_sigterm_as_a_notebook_is_renamed_keeps_it_and_stops_the_running_one(folder):
    before = originals(folder)
    p = start(folder, ["--in-place", "--jobs", "2"], "ab", "rename:SIGTERM")
    out, err = p.communicate(timeout=120)
    assert p.returncode == 128 + signal.SIGTERM, err
    # "a" was being renamed when the signal came: the rename completes and "a" is recorded;
    # "b" computes for a minute: its kernel is killed and the file left as it was
    assert check_notebooks(folder, before) == {"a.ipynb": "executed", "b.ipynb": "original",
                                               "c.ipynb": "original"}
    assert err.splitlines()[-1] == ("python -m obslib.run: stopped by SIGTERM: 1 notebook(s) "
                                    "finished and recorded, 1 stopped (b), 0 not started")
    assert "Traceback" not in err and out.startswith("a.ipynb")
    assert set(json.loads((folder / "times.json").read_text())) == {"a.ipynb"}
    if (folder / "b.pid").exists():  # b's kernel may have been killed before its cell ran
        wait_for(lambda: not alive(int((folder / "b.pid").read_text())), 10)
    assert leftovers(folder) == []


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGHUP])
def test_a_stop_while_a_kernel_computes_records_what_finished_and_nothing_else(folder, signum):
    before = originals(folder)
    p = start(folder, ["-p", "n", "3", "--jobs", "1"], "abc")
    wait_for(lambda: (folder / "b.pid").exists())  # "a" is done and recorded, "b" computes
    kernel = int((folder / "b.pid").read_text())
    p.send_signal(signum)
    out, err = p.communicate(timeout=120)
    assert p.returncode == 128 + signum, err
    name = signal.Signals(signum).name
    assert err.splitlines()[-1] == (f"python -m obslib.run: stopped by {name}: 1 notebook(s) "
                                    "finished and recorded, 1 stopped (b), 1 not started")
    assert check_notebooks(folder, before) == {n: "original" for n in before}  # reruns: copies
    index = json.loads((folder / "runs" / "index.json").read_text())["runs"]
    label = index[0]["output"].split("/")[0]
    assert [e["notebook"] for e in index] == ["a"] and index[0]["injected"] == {"n": 3}
    written = sorted(p.name for p in (folder / "runs" / label).iterdir())
    assert written == ["a.ipynb", "a.json"]  # nothing of "b" or "c"
    rerun = nbformat.read(folder / "runs" / label / "a.ipynb", 4)
    assert "a" * 6000 + "\n" in [o.get("text") for c in rerun.cells for o in c.get("outputs", [])]
    wait_for(lambda: not alive(kernel), 10)
    assert leftovers(folder) == []


def test_a_stop_before_any_notebook_runs_writes_nothing(folder):
    before = originals(folder)
    p = start(folder, ["--in-place"], "abc", "precompile:SIGTERM")
    out, err = p.communicate(timeout=120)
    assert p.returncode == 128 + signal.SIGTERM, err
    assert err == "python -m obslib.run: stopped by SIGTERM\n" and out == ""
    assert check_notebooks(folder, before) == {n: "original" for n in before}
    assert not (folder / "times.json").exists() and leftovers(folder) == []


def test_a_stop_as_a_kernel_starts_kills_it_and_starts_no_other(folder):
    # the kernel dies before its first reply; a kernel that does not start is normally started
    # again, but not during a stop
    before = originals(folder)
    p = start(folder, ["--in-place", "--jobs", "1"], "bac", "kernel:SIGHUP")
    out, err = p.communicate(timeout=120)
    assert p.returncode == 128 + signal.SIGHUP, err
    assert err.splitlines()[-1] == ("python -m obslib.run: stopped by SIGHUP: 0 notebook(s) "
                                    "finished and recorded, 1 stopped (b), 2 not started")
    assert "starting another" not in err and out == ""
    assert check_notebooks(folder, before) == {n: "original" for n in before}
    wait_for(lambda: not alive(int((folder / "kernel.pid").read_text())), 10)
    assert leftovers(folder) == []


def test_concurrent_reruns_never_lose_an_index_entry(folder):
    # two processes record 40 reruns each into one index at the same time
    code = ("import sys; from pathlib import Path; from obslib.tools import run\n"
            "runs, nb = Path(sys.argv[1]), Path(sys.argv[2])\n"
            "for k in range(40):\n"
            "    dst = runs / f'{sys.argv[3]}{k}' / nb.name\n"
            "    run._record(run.Run(nb, dst, {'n': k}, dst.parent.name, None, {'n': k}), 1.0)\n")
    runs, nb = folder / "runs", folder / "nbs" / "c.ipynb"
    procs = [subprocess.Popen([sys.executable, "-c", code, str(runs), str(nb), tag])
             for tag in ("x", "y")]
    assert [q.wait(timeout=120) for q in procs] == [0, 0]
    index = json.loads((runs / "index.json").read_text())["runs"]
    assert sorted(e["output"] for e in index) == sorted(
        f"{t}{k}/c.ipynb" for t in "xy" for k in range(40))
    assert all(json.loads((runs / e["output"]).with_suffix(".json").read_text()) == e
               for e in index)


def test_a_failing_notebook_lets_the_running_ones_finish_and_records_them(folder, capfd):
    bad = write_notebook(folder / "nbs" / "bad.ipynb", "n = 1", ["raise RuntimeError('boom')"])
    slow = write_notebook(folder / "nbs" / "slow.ipynb", "n = 1",
                          ["import time; time.sleep(2); print(n)"])  # runs on as bad fails
    runs = run.plan([slow, bad], "quick", {}, False, folder / "runs")
    seen = []
    with pytest.raises(run.RunFailed, match="bad") as exc:
        run.execute_all(runs, jobs=2, on_done=lambda r, dt: seen.append(r.notebook.stem))
    assert seen == ["slow"] and set(exc.value.times) == {"slow.ipynb"}
    # the failed notebook is saved as far as it ran, with its error, as papermill saves it
    failed = nbformat.read(folder / "runs" / "quick" / "bad.ipynb", 4)
    errors = [o for c in failed.cells for o in c.get("outputs", []) if o.output_type == "error"]
    assert [(e.ename, e.evalue) for e in errors] == [("RuntimeError", "boom")]
    assert leftovers(folder) == []


def test_execute_leaves_the_destination_untouched_when_the_text_is_unchanged(folder):
    src = folder / "nbs" / "c.ipynb"
    dst = folder / "out" / "c.ipynb"
    run.execute(src, dst)
    stamp = dst.stat().st_mtime_ns
    run.execute(src, dst)
    assert dst.stat().st_mtime_ns == stamp and leftovers(folder) == []
