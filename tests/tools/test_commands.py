"""The four command lines keep one contract at their edges: a FIFO or device given to ``--write``
is refused before any work, a symbolic link is written through, a write that fails at the end is
one line and exit status 1 with the file left as it was, a missing input file is an error, and a
stop signal ends the command with one line and the status ``128 +`` the signal's number."""

import json
import os
import signal
import subprocess
import sys

import pytest

#: Per command: code that replaces its work by a constant result (the tests are about its edges),
#: and an argument list that writes a file (``{out}``: its name).
COMMANDS = {
    "python -m obslib.claims": (
        "from obslib.claims import __main__ as m; m.evaluate = lambda *a, **k: []; "
        "m.as_json = lambda records: [{'id': 'x' * 300}]",
        "m", ["--write", "{out}.json"]),
    "python -m obslib.claims --robustness": (
        "from obslib.claims import __main__ as m; "
        "m.robustness.verdict_robustness = lambda *a, **k: [{'claim': 'x' * 300}]",
        "m", ["--robustness", "--write", "{out}.json"]),
    "python -m obsbook.report": (
        "import obslib.claims; obslib.claims.evaluate = lambda *a, **k: []; "
        "from obsbook import report as m; m.render_report = lambda *a, **k: 'page ' * 100",
        "m", ["--write", "{out}.md"]),
    "python -m obslib.bench": (
        "from obslib.tools import bench as m; m.bench_criteria = lambda: {'a': 'x' * 300}",
        "m", ["criteria", "--write", "{out}.json"]),
}


#: Per command: the function that does its work, replaced by the stub above.
WORK = {"python -m obslib.claims": "m.evaluate",
        "python -m obslib.claims --robustness": "m.robustness.verdict_robustness",
        "python -m obsbook.report": "obslib.claims.evaluate",
        "python -m obslib.bench": "m.bench_criteria"}


def command_line(name: str, out: str, before: str = "", work: str = "") -> list:
    """``python -c`` running the command's ``main`` on its writing arguments, its work stubbed
    (or, with ``work``, replaced by that expression); ``before`` runs first."""
    stub, module, argv = COMMANDS[name]
    argv = [a.format(out=out) for a in argv]
    code = (f"{before}{stub}; " + (f"{WORK[name]} = {work}; " if work else "")
            + f"import sys; raise SystemExit({module}.main(sys.argv[1:]))")
    return [sys.executable, "-c", code, *argv]


def prog(name: str) -> str:
    return " ".join(name.split()[:3])


@pytest.mark.parametrize("name", COMMANDS)
def test_a_fifo_is_refused_before_any_work(name, tmp_path):
    fifo = tmp_path / "out"
    for suffix in (".json", ".md"):
        os.mkfifo(fifo.with_suffix(suffix))
    mark = tmp_path / "worked"  # the work would leave this mark: it must not run
    out = subprocess.run(command_line(name, str(fifo), work=f"lambda *a, **k: open({str(mark)!r}, "
                                      "'w')"), capture_output=True, text=True, timeout=120)
    assert out.returncode == 2 and "is a FIFO" in out.stderr and not mark.exists(), out.stderr
    assert out.stderr.splitlines()[-1].startswith(f"{prog(name)}: error: --write ")
    assert "Traceback" not in out.stderr and out.stdout == ""


@pytest.mark.parametrize("name", COMMANDS)
def test_a_symlink_is_written_through(name, tmp_path):
    real = tmp_path / "real"
    real.mkdir()
    suffix = COMMANDS[name][2][-1].rsplit(".", 1)[1]
    target = real / f"data.{suffix}"
    target.write_text("old")
    (tmp_path / f"out.{suffix}").symlink_to(target)
    subprocess.run(command_line(name, str(tmp_path / "out")), check=True, capture_output=True,
                   timeout=120)
    assert (tmp_path / f"out.{suffix}").is_symlink() and target.read_text() != "old"
    assert sorted(p.name for p in real.iterdir()) == [target.name]


@pytest.mark.parametrize("name", COMMANDS)
def test_a_write_that_fails_at_the_end_is_one_line_and_exit_status_1(name, tmp_path):
    # a real failed write (EFBIG, as a full disk gives ENOSPC): files limited to 100 bytes
    suffix = COMMANDS[name][2][-1].rsplit(".", 1)[1]
    target = tmp_path / f"out.{suffix}"
    target.write_text("old\n")
    limit = ("import resource, signal; signal.signal(signal.SIGXFSZ, signal.SIG_IGN); "
             "resource.setrlimit(resource.RLIMIT_FSIZE, (100, 100)); ")
    out = subprocess.run(command_line(name, str(tmp_path / "out"), limit), capture_output=True,
                         text=True, timeout=120)
    assert out.returncode == 1, out.stderr
    assert out.stderr == f"{prog(name)}: error: cannot write {target}: File too large\n"
    assert target.read_text() == "old\n" and [p.name for p in tmp_path.iterdir()] == [target.name]


@pytest.mark.parametrize("name", COMMANDS)
def test_a_stop_signal_ends_the_command_in_one_line(name, tmp_path):
    # the work sends the stop signal: the command stops where it is, writes nothing, and says so
    stop = "lambda *a, **k: os.kill(os.getpid(), signal.SIGTERM)"
    out = subprocess.run(command_line(name, str(tmp_path / "out"), "import os, signal; ", stop),
                         capture_output=True, text=True, timeout=120)
    assert out.returncode == 128 + signal.SIGTERM, out.stderr
    assert out.stderr == f"{prog(name)}: stopped by SIGTERM\n" and out.stdout == ""
    assert list(tmp_path.iterdir()) == []


def test_a_missing_or_special_robustness_file_is_an_error(tmp_path, capsys):
    from obsbook import report

    os.mkfifo(tmp_path / "fifo.json")
    for path, why in ((tmp_path / "none.json", "no such file"),
                      (tmp_path / "fifo.json", "is a FIFO")):
        with pytest.raises(SystemExit) as exc:
            report.main(["--robustness", str(path), "--write", str(tmp_path / "r.md")])
        err = capsys.readouterr().err
        assert exc.value.code == 2 and why in err  # argparse: usage, then the one error line
        assert err.splitlines()[-1].startswith("python -m obsbook.report: error: --robustness")
    assert not (tmp_path / "r.md").exists()


def test_the_claims_command_writes_what_it_prints(tmp_path, capsys):
    from obslib.claims.__main__ import main

    path = tmp_path / "ledger.json"
    assert main(["--id", "thm2", "--profile", "quick", "--json"]) == 0
    printed = json.loads(capsys.readouterr().out)
    assert main(["--id", "thm2", "--profile", "quick", "--write", str(path)]) == 0
    assert json.loads(path.read_text()) == printed


def test_the_runner_refuses_a_fifo_for_a_notebook_before_any_work(tmp_path, capsys):
    from obslib.tools import run

    fifo = tmp_path / "01_x.ipynb"
    os.mkfifo(fifo)  # papermill would wait on it forever
    with pytest.raises(SystemExit) as exc:
        run.main(["--in-place", str(fifo)])
    err = capsys.readouterr().err
    assert exc.value.code == 2 and "is a FIFO" in err
    assert err.splitlines()[-1].startswith("python -m obslib.run: error: ")
