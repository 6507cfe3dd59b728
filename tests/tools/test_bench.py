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
