"""Benchmarks: the literal algorithm's exact work count; the command line's output (the JSON line
alone on stdout) and --write (special files refused, failed writes in one line, the book's data
replaced only with --update-book)."""

import json
import subprocess
import sys

import numpy as np
import pytest

from obslib.assignment import greedy_pair_assignment_literal
from obslib.tools.bench import evaluation_counts, literal_count


def test_literal_count_equals_a_counted_run():
    rng = np.random.default_rng(0)
    for n, L in [(4, 2), (10, 5), (30, 15), (12, 3)]:
        S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (L, 2))
        assert greedy_pair_assignment_literal(
            sensors=S, targets=T, u_max=1.0
        ).n_evaluations == literal_count(n, L)


def test_evaluation_counts_one_pass_and_greedy():
    c = evaluation_counts({"greedy (geometry)": [20, 40], "literal Algorithm 1": [20]})
    n, one = c["one pass"]
    assert list(n) == [20, 40] and list(one) == [20 * 19 // 2 * 10, 40 * 39 // 2 * 20]
    assert all(g > 0 for g in c["greedy (geometry)"][1])


def test_book_benchmark_rejects_an_unknown_profile_before_running():
    import pytest

    from obslib.tools.bench import bench_book

    with pytest.raises(ValueError, match="unknown profile 'nope'"):
        bench_book("nope")


# --------------------------------------------------------------------------- --write


@pytest.fixture
def quick_criteria(monkeypatch):
    """The criteria benchmark replaced by a constant result: these tests are about the writing."""
    from obslib.tools import bench

    ran = []
    monkeypatch.setattr(
        bench, "bench_criteria", lambda: ran.append(1) or {"per_pair_us": {"x": 1.5}}
    )
    return ran


@pytest.mark.parametrize("path, message", [
    ("/etc/passwd/x.json", "a part of the path is not a directory"),
    ("{tmp}/missing/x.json", "does not exist"),
    ("{tmp}", "is a directory"),
    ("", "the output path is empty"),
])
def test_an_unwritable_path_is_a_command_line_error_before_any_work(path, message, tmp_path,
                                                                    quick_criteria, capsys):
    from obslib.tools.bench import main

    with pytest.raises(SystemExit) as exc:
        main(["criteria", "--write", path.format(tmp=tmp_path)])
    assert exc.value.code == 2 and not quick_criteria
    assert message in capsys.readouterr().err
    assert not (tmp_path / "missing").exists()  # no directory is created


def test_a_special_file_is_refused_before_any_work(tmp_path, quick_criteria, capsys):
    import os

    from obslib.tools.bench import main

    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)  # a reader-less FIFO would hang the write
    for path, kind in ((fifo, "is a FIFO"), ("/dev/full", "is a character device")):
        with pytest.raises(SystemExit) as exc:
            main(["criteria", "--write", str(path)])
        err = capsys.readouterr().err
        assert exc.value.code == 2 and kind in err and not quick_criteria
        assert err.splitlines()[-1].startswith("python -m obslib.bench: error: --write ")


def test_a_write_that_fails_at_the_end_is_one_line(tmp_path):
    # a real failed write: files are limited to 100 bytes in the benchmark's process
    target = tmp_path / "x.json"
    target.write_text("old\n")
    code = ("import resource, signal, sys; signal.signal(signal.SIGXFSZ, signal.SIG_IGN); "
            "resource.setrlimit(resource.RLIMIT_FSIZE, (100, 100)); "
            "from obslib.tools import bench; bench.bench_criteria = lambda: {'a': 'x' * 500}; "
            "raise SystemExit(bench.main(sys.argv[1:]))")
    out = subprocess.run([sys.executable, "-c", code, "criteria", "--write", str(target)],
                         capture_output=True, text=True)
    assert out.returncode == 1 and "Traceback" not in out.stderr
    assert out.stderr == f"python -m obslib.bench: error: cannot write {target}: File too large\n"
    assert target.read_text() == "old\n" and [p.name for p in tmp_path.iterdir()] == ["x.json"]


def test_the_json_line_is_alone_on_stdout_and_a_file_gets_it_indented(tmp_path):
    code = ("from obslib.tools import bench; bench.bench_criteria = lambda: {'a': 1}; "
            "import sys; raise SystemExit(bench.main(sys.argv[1:]))")
    out = subprocess.run([sys.executable, "-c", code, "criteria"], capture_output=True,
                         text=True, check=True)
    assert out.stdout == '{"a": 1}\n'
    target = tmp_path / "x.json"
    subprocess.run([sys.executable, "-c", code, "criteria", "--write", str(target)], check=True,
                   capture_output=True)
    assert target.read_text() == '{\n "a": 1\n}\n'


def test_the_readable_lines_of_every_benchmark_go_to_stderr(monkeypatch, capsys):
    from obslib.tools import bench

    monkeypatch.setattr(bench, "SCALING_SIZES", {name: [8] for name in bench.SCALING_SIZES})
    bench.bench_scaling(repeat=1)
    bench.bench_criteria(5, repeat=1)
    bench.bench_assignment(sensors=20, targets=10)
    out, err = capsys.readouterr()
    assert out == "" and "greedy (geometry)" in err and "per pair" in err and "N=20" in err


def test_the_book_benchmark_prints_its_json_alone_with_the_stack_guard(tmp_path, monkeypatch,
                                                                         capsys):
    # the book benchmark over one tiny notebook instead of the book's
    from obslib.tools import bench, run

    from .test_run import write_notebook

    tiny = write_notebook(tmp_path / "00_tiny.ipynb", "n = 2", ["print(n)"])
    monkeypatch.setattr(run, "notebooks", lambda: [tiny])
    assert bench.main(["book", "--jobs", "1"]) == 0
    out, err = capsys.readouterr()
    result = json.loads(out)
    assert out.count("\n") == 1 and result["notebooks"] == 1
    exec_s, stack_s = result["exec_s"], result["stack_floor_s"]  # both rounded to 0.01 s
    rounding = 0.005 / exec_s + 0.005 / stack_s  # relative error of their ratio, at most
    assert result["exec_over_stack"] == pytest.approx(exec_s / stack_s, rel=rounding, abs=1e-3)
    verdict = "met" if result["exec_over_stack"] <= 3.5 else "MISSED"
    assert f"target <= 3.5: {verdict}" in err and bench.EXEC_OVER_STACK_MAX == 3.5


@pytest.mark.parametrize("argv, message", [
    (["criteria", "--write", "{data}/criteria_times.json"], "Add --update-book"),
    (["scaling", "--write", "{data}/scaling_times.json"], "Add --update-book"),
    (["scaling", "--write", "{link}"], "Add --update-book"),  # a link into book/data
    (["criteria", "--update-book"], "--update-book goes with --write"),
    (["criteria", "--write", "{tmp}/x.json", "--update-book"], "is not the book's data"),
])
def test_the_books_data_is_replaced_only_when_asked(argv, message, tmp_path, quick_criteria,
                                                   capsys):
    from obslib.tools.bench import BOOK_DATA, main, parse_args

    link = tmp_path / "times.json"
    link.symlink_to(BOOK_DATA / "scaling_times.json")
    argv = [a.format(data=BOOK_DATA, tmp=tmp_path, link=link) for a in argv]
    before = {p.name: p.read_bytes() for p in BOOK_DATA.iterdir()}
    with pytest.raises(SystemExit) as exc:
        main(argv)
    assert exc.value.code == 2 and message in capsys.readouterr().err and not quick_criteria
    assert {p.name: p.read_bytes() for p in BOOK_DATA.iterdir()} == before
    ok = parse_args(["criteria", "--write", str(BOOK_DATA / "criteria_times.json"),
                     "--update-book"])
    assert ok.update_book and ok.write == BOOK_DATA / "criteria_times.json"


def test_assignment_benchmark_at_a_given_size_runs_the_greedy_alone(capsys):
    import json

    from obslib.assignment import greedy_pair_assignment
    from obslib.tools.bench import main

    assert main(["assignment", "--sensors", "60", "--targets", "30"]) == 0
    out, err = capsys.readouterr()
    result = json.loads(out.strip().splitlines()[-1])
    assert set(result) == {"n_sensors", "n_targets", "greedy_s", "n_evaluations", "peak_rss_gb"}
    assert (result["n_sensors"], result["n_targets"]) == (60, 30)
    assert 0 < result["greedy_s"] and 0 < result["peak_rss_gb"] < 64
    rng = np.random.default_rng(0)  # the benchmark's scene
    S, T = rng.uniform(0, 100, (60, 2)), rng.uniform(0, 100, (30, 2))
    assert result["n_evaluations"] == greedy_pair_assignment(sensors=S, targets=T,
                                                             u_max=1.0).n_evaluations
    assert "greedy from geometry, N=60 L=30" in err and "literal" not in err


def test_assignment_size_options_are_checked_on_the_command_line(capsys):
    import pytest

    from obslib.tools.bench import parse_args

    for argv, message in [
        (["assignment", "--sensors", "100"], "give both"),
        (["assignment", "--sensors", "10", "--targets", "6"], "N >= 2L"),
        (["assignment", "--sensors", "10", "--targets", "0"], "at least one target"),
        (["book", "--sensors", "10", "--targets", "5"], "and tracking benchmarks only"),
    ]:
        with pytest.raises(SystemExit) as exit_:
            parse_args(argv)
        assert exit_.value.code == 2
        assert message in capsys.readouterr().err
