"""Benchmarks: the literal algorithm's exact work count, and the command line's --write."""

import json

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


def test_a_write_that_fails_at_the_end_is_one_line(quick_criteria, capsys):
    from obslib.tools.bench import main

    assert main(["criteria", "--write", "/dev/full"]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "cannot write /dev/full" in err and "Traceback" not in err


def test_a_fifo_is_written_once_and_never_read(tmp_path, quick_criteria):
    import os
    import threading

    from obslib.tools.bench import main

    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_text()))
    reader.start()
    assert main(["criteria", "--write", str(fifo)]) == 0
    reader.join(timeout=30)
    assert json.loads(got[0]) == {"per_pair_us": {"x": 1.5}}


def test_stdout_piped_and_a_regular_file(tmp_path):
    import subprocess
    import sys

    code = ("from obslib.tools import bench; bench.bench_criteria = lambda: {'a': 1}; "
            "import sys; raise SystemExit(bench.main(sys.argv[1:]))")
    out = subprocess.run([sys.executable, "-c", code, "criteria", "--write", "/dev/stdout"],
                         capture_output=True, text=True, check=True)  # stdout is a pipe
    lines = out.stdout.splitlines()
    assert json.loads(lines[0]) == {"a": 1} and json.loads("".join(lines[1:])) == {"a": 1}
    target = tmp_path / "x.json"
    subprocess.run([sys.executable, "-c", code, "criteria", "--write", str(target)], check=True,
                   capture_output=True)
    assert json.loads(target.read_text()) == {"a": 1}


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
