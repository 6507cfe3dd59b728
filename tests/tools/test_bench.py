"""Benchmark helpers that feed the book: the literal algorithm's exact work count."""

import numpy as np

from obslib.assignment import greedy_pair_assignment_literal
from obslib.tools.bench import evaluation_counts, literal_count


def test_literal_count_equals_a_counted_run():
    rng = np.random.default_rng(0)
    for n, L in [(4, 2), (10, 5), (30, 15), (12, 3)]:
        S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (L, 2))
        assert greedy_pair_assignment_literal(sensors=S, targets=T, u_max=1.0).n_evaluations == literal_count(n, L)


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
        (["book", "--sensors", "10", "--targets", "5"], "assignment benchmark only"),
    ]:
        with pytest.raises(SystemExit) as exit_:
            parse_args(argv)
        assert exit_.value.code == 2
        assert message in capsys.readouterr().err
