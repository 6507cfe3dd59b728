"""Hostile input for every public function of ``obslib`` and the command lines' parsing.

Each call either returns a finite, valid result or raises ValueError/TypeError whose message
names the argument at fault; nothing hangs (a deadline per example) and nothing returns NaN.
Hypothesis draws random shapes, dtypes, NaN/inf, scales from 1e-300 to 1e300 and degenerate
geometry (coincident and collinear points), and arrays NumPy would misread without a word (a
masked entry, a bool among numbers, numbers as text). The arguments handed on to joblib and Dask
are refused by name before any worker starts or any connection is tried. The whole file runs in
well under a minute.
"""

from __future__ import annotations

import contextlib
import dataclasses
import importlib
import inspect
import io
import os
import pkgutil
import re
import signal
import tempfile
import warnings
from pathlib import Path
from unittest import mock

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

import obslib as ob

# deadline: far above any example's time (milliseconds) even on a loaded machine, far below a hang
FUZZ = settings(max_examples=40, deadline=10_000, suppress_health_check=[HealthCheck.too_slow])

TMP = Path(tempfile.mkdtemp(prefix="obslib-fuzz-"))  # the runner's outputs, outside the repository

SCALES = [1e-300, 1e-170, 1e-150, 1e-20, 1.0, 1e20, 1e150, 1e170, 1e300]


# --------------------------------------------------------------------------- strategies


@st.composite
def points(draw, min_n=0, max_n=6, hostile=True):
    """An (n, 2) array of points, usually legal, sometimes hostile (bad shape, dtype or value)."""
    n = draw(st.integers(min_n, max_n))
    scale = draw(st.sampled_from(SCALES))
    grid = draw(st.booleans())  # coarse grid: coincident and collinear points
    if grid:
        base = np.array(draw(st.lists(st.tuples(st.integers(-2, 2), st.integers(-2, 2)),
                                      min_size=n, max_size=n)), dtype=float).reshape(n, 2)
    else:
        base = np.array(draw(st.lists(st.tuples(st.floats(-1, 1), st.floats(-1, 1)),
                                      min_size=n, max_size=n))).reshape(n, 2)
    arr = base * scale
    if not hostile:
        return arr
    kind = draw(
        st.sampled_from(
            ["ok"] * 6 + ["nan", "inf", "shape", "bool", "complex", "str", "none", "int", "huge"]
        )
    )
    if kind == "nan" and n:
        arr[draw(st.integers(0, n - 1)), 0] = np.nan
    elif kind == "inf" and n:
        arr[draw(st.integers(0, n - 1)), 1] = -np.inf
    elif kind == "shape":
        return arr.reshape(-1)
    elif kind == "bool":
        return arr > 0
    elif kind == "complex":
        return arr + 1j
    elif kind == "str":
        return arr.astype(str)
    elif kind == "none":
        return None
    elif kind == "int":
        return base.astype(int)
    elif kind == "huge" and n:
        arr[0] = [1.7e308, -1.7e308]
    return arr


numbers = st.one_of(
    st.sampled_from([0.0, 1.0, 2.5, -1.0, np.nan, np.inf, 1e-300, 1e300, True, None, "1", 1 + 1j]),
    st.floats(0, 10),
)


def names_in(message: str, *names: str) -> bool:
    low = message.lower()
    return any(n.lower() in low for n in names)


@contextlib.contextmanager
def named_errors(*names):
    """Expect either success or a ValueError/TypeError naming one of ``names``."""
    try:
        yield
    except (ValueError, TypeError) as exc:
        assert names_in(str(exc), *names), f"{type(exc).__name__} does not name {names}: {exc}"


def finite(x):
    arr = np.asarray(x, dtype=float)
    assert np.isfinite(arr).all(), x
    return arr


# --------------------------------------------------------------------------- geometry and bounds


@FUZZ
@given(points(1, 6), points(1, 1), st.one_of(st.none(), points(1, 1)), numbers)
def test_single_target_functions(sensors, target, u, u_max):
    target = None if target is None else np.asarray(target)
    if target is not None and target.ndim == 2:
        target = target[0]
    u = None if u is None or np.ndim(u) != 2 else np.asarray(u)[0]
    with named_errors("sensor", "target", "u"):
        O = ob.observability_matrix(sensors, target, u)
        assert finite(O).shape[1] == 2
    with named_errors("sensor", "target", "u"):
        c = ob.inverse_condition_number(sensors, target, u)
        assert 0.0 <= finite(c) <= 1.0
    with named_errors("sensor", "target"):
        finite(ob.relative_rows(sensors, target))
    with named_errors("sensor", "target", "u_max"):
        b = ob.lower_bound(sensors, target, u_max)
        assert 0.0 <= finite(b) <= 1.0
    with named_errors("sensor", "target", "u_max"):
        w = finite(ob.worst_case_control(sensors, target, u_max))
        assert w.shape == (2,) and np.isclose(np.hypot(*w), float(u_max), rtol=1e-9)


@FUZZ
@given(points(0, 6), points(0, 3), numbers,
       st.sampled_from([None, "eye", "tiny", "huge", "neg", "nan", "asym", "bad"]))
def test_pair_bounds_and_relative_vectors(sensors, targets, u_max, cov_kind):
    cov = {None: None, "eye": np.eye(2), "tiny": 1e-170 * np.array([[2.0, 0.3], [0.3, 1.0]]),
           "huge": 1e170 * np.eye(2), "neg": -np.eye(2), "nan": np.full((2, 2), np.nan),
           "asym": np.array([[1.0, 0.5], [0.0, 1.0]]), "bad": np.eye(3)}[cov_kind]
    with named_errors("sensor", "target", "cov", "mahalanobis"):
        v = finite(ob.relative_vectors(sensors, targets, cov))
        assert v.ndim == 3 and v.shape[2] == 2
    with named_errors("sensor", "target", "u_max", "cov"):
        W = finite(ob.pair_bounds(sensors, targets, u_max, cov))
        assert ((W >= 0) & (W <= 1)).all()
        assert np.array_equal(W, W.transpose(1, 0, 2))  # elementwise kernel: exact symmetry
        assert (np.diagonal(W, axis1=0, axis2=1) == 0).all()


@FUZZ
@given(numbers, numbers, numbers, st.sampled_from([(), (3,), (2, 2)]))
def test_pair_bound_polar(alpha, theta, q, shape):
    a = (
        np.full(shape, alpha, dtype=object)
        if shape and not isinstance(alpha, (str, type(None)))
        else alpha
    )
    with named_errors("alpha", "theta", "u_over_d"):
        out = finite(ob.pair_bound_polar(a, theta, q))
        assert ((out >= 0) & (out <= 1)).all()


# --------------------------------------------------------------------------- measures


@FUZZ
@given(points(0, 5), points(1, 1), st.sampled_from(list(ob.MEASURES) + ["nope", 3, None]), numbers,
       st.one_of(st.none(), points(1, 1)), st.sampled_from([1e-10, 0.0, 1.5, -1.0, np.nan, True]))
def test_measures(sensors, target, name, eps, u, rank_rtol):
    target = None if target is None else np.asarray(target)
    if target is not None and target.ndim == 2:
        target = target[0]
    u = None if u is None or np.ndim(u) != 2 else np.asarray(u)[0]
    args = ("sensor", "target", "measure", "eps", "u", "rank_rtol", "overflow")
    with named_errors(*args):
        value = ob.measure(sensors, target, name, eps, u, rank_rtol)
        assert not np.isnan(value)
        if name == "rank":
            assert value in (0.0, 1.0, 2.0)
    with named_errors(*args):
        G = ob.symmetric_observability_matrix(sensors, target, u, eps)
        assert not np.isnan(G).any() and G.shape == (2, 2)
    with named_errors(*args, "masks"):
        table = ob.measure_table(sensors, target, name, eps, u, rank_rtol=rank_rtol)
        assert not np.isnan(table).any()


# --------------------------------------------------------------------------- pair assignment


@st.composite
def weights(draw):
    n = draw(st.integers(0, 6))
    L = draw(st.integers(0, 3))
    w = np.array(draw(st.lists(st.floats(0, 1), min_size=n * n * L, max_size=n * n * L))).reshape(
        n, n, L
    )
    w = w + w.transpose(1, 0, 2)
    kind = draw(
        st.sampled_from(
            ["ok"] * 4 + ["neg", "nan", "asym", "bool", "complex", "2d", "none", "huge"]
        )
    )
    if kind == "neg" and w.size:
        w[0, -1, 0] = w[-1, 0, 0] = -0.5
    elif kind == "nan" and w.size:
        w[0, 0, 0] = np.nan
    elif kind == "asym" and n > 1 and L:
        w[0, 1, 0] += 1.0
    elif kind == "bool":
        return w > 0.5
    elif kind == "complex":
        return w + 0j
    elif kind == "2d":
        return w[..., 0] if not w.size else w.reshape(n, -1)
    elif kind == "none":
        return None
    elif kind == "huge" and w.size:
        w *= 1e300
    return w


def valid_pairs(res, n, L, unique_sensors=True):
    triples = res.triples
    assert np.isfinite(res.value) and res.value >= 0
    assert all(0 <= i < j < n and 0 <= l < L for i, j, l in triples)
    assert len({l for *_, l in triples}) == len(triples)
    if unique_sensors:
        used = [s for i, j, _ in triples for s in (i, j)]
        assert len(used) == len(set(used))


@FUZZ
@given(
    weights(),
    st.sampled_from([None, 1, 3, 2.5, 0, True, "2"]),
    st.sampled_from([False, True, "no", None]),
)
def test_pair_assignment_from_weights(W, k, ordered):
    shape = np.shape(W) if W is not None else (0, 0, 0)
    n, L = (shape[0], shape[-1]) if len(shape) == 3 else (0, 0)
    args = ("W", "k", "sensor", "target", "ordered", "give")
    with named_errors(*args):
        valid_pairs(ob.greedy_pair_assignment(W, k=k), n, L)
    with named_errors(*args):
        valid_pairs(ob.relaxed_pair_assignment(W, ordered), n, L, unique_sensors=False)
    with named_errors(*args):
        valid_pairs(ob.optimal_pair_assignment(W), n, L)


@FUZZ
@given(points(0, 7), points(0, 3), numbers, st.sampled_from([None, 1, 4, 2.5, -1]))
def test_pair_assignment_from_geometry(sensors, targets, u_max, k):
    n = np.shape(sensors)[0] if np.ndim(sensors) == 2 else 0
    L = np.shape(targets)[0] if np.ndim(targets) == 2 else 0
    args = ("sensor", "target", "u_max", "k", "give", "pairs need")
    with named_errors(*args):
        valid_pairs(
            ob.greedy_pair_assignment(sensors=sensors, targets=targets, u_max=u_max, k=k), n, L
        )
    with named_errors(*args):
        valid_pairs(ob.relaxed_pair_assignment(sensors=sensors, targets=targets, u_max=u_max), n, L,
                    unique_sensors=False)


# --------------------------------------------------------------------------- teams


@FUZZ
@given(points(0, 6), points(0, 3), st.sampled_from(["logdet", "trace", "rank", "neg_trace_inverse",
                                                    "trace_inverse", "nope"]),
       st.sampled_from([1.0, 0.0, 1e-300, 1e300, -1.0, np.nan, True]))
def test_team_assignment(sensors, targets, name, eps):
    n = np.shape(sensors)[0] if np.ndim(sensors) == 2 else 0
    L = np.shape(targets)[0] if np.ndim(targets) == 2 else 0
    args = ("sensor", "target", "measure", "eps", "overflow")
    with named_errors(*args):
        teams = ob.greedy_team_assignment(sensors, targets, name, eps)
        assert len(teams) == L and sorted(i for t in teams for i in t) == list(range(n))
    with named_errors(*args, "assignments"):
        teams, value = ob.optimal_team_assignment(sensors, targets, name, eps)
        assert not np.isnan(value) and len(teams) == L
        assert sorted(i for t in teams for i in t) == list(range(n))


# --------------------------------------------------------------------------- set-function audits


@st.composite
def moderate_points(draw, min_n, max_n):
    n = draw(st.integers(min_n, max_n))
    pts = np.array(
        draw(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3)), min_size=n, max_size=n)),
        dtype=float,
    ).reshape(n, 2)
    return pts * draw(st.sampled_from([1e-20, 1e-3, 1.0, 1e3, 1e20]))


@FUZZ
@given(
    moderate_points(1, 4),
    moderate_points(1, 1),
    st.floats(0, 10),
    st.sampled_from(list(ob.MEASURES)),
)
def test_audits(sensors, target, u_max, name):
    # The set-function audits at moderate scales (1e-20 to 1e20); extreme scales are tested below.
    with named_errors("sensor", "target", "u_max", "overflow"):
        table = ob.lower_bound_table(sensors, target[0], u_max)
        assert not np.isnan(table).any()
    with named_errors("sensor", "target", "measure", "values", "overflow"):
        ob.audit_set_function(sensors, values=ob.measure_table(sensors, target[0], name, eps=1.0))


@pytest.mark.parametrize("c", [1e150, 1e-150, 2.0**1000])
def test_lower_bound_table_at_extreme_scale(c):
    # The bound is homogeneous of degree 0 in (coordinates, u_max); at these scales squared lengths
    # overflow or underflow unless the kernel changes unit, so equality with the unit-scale table
    # (and with the SVD of lower_bound at that scale) shows it does.
    S = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    o = np.array([0.3, 0.4])
    with np.errstate(all="raise"):
        table = ob.lower_bound_table(S * c, o * c, c)
    np.testing.assert_allclose(table, ob.lower_bound_table(S, o, 1.0), rtol=1e-9)
    for k in range(8):
        idx = [i for i in range(3) if k >> i & 1]
        assert table[k] == pytest.approx(
            ob.lower_bound(S[idx].reshape(-1, 2) * c, o * c, c), rel=1e-9, abs=0
        )


# --------------------------------------------------------------------------- command lines


#: Words of the four command lines, and wrong values for them.
ARGV_WORDS = st.sampled_from([
    "--profile", "paper", "quick", "nosuch", "--id", "thm1", "nosuch-id", "--write",
    "/nonexistent/x.md", "x.json", "--json", "-p", "n_seeds", "seed", "abc", "-5", "2.5", "05",
    "01", "99", "--in-place", "book", "scaling", "assignment", "criteria", "[1]", "", "--jobs",
    "0", "-1", "3", "--robustness", "--notebooks", "/nonexistent", "--sensors", "--targets",
    "--no-progress", "--help-me",
])


def _cli_mains():
    """Each command line's ``main(argv)``, with what would do the work replaced by a stub: the
    test is about the arguments, which every command checks before any work."""
    from obsbook import report
    from obslib import _io, claims
    from obslib.claims import __main__ as claims_cli
    from obslib.claims import robustness
    from obslib.tools import bench, run

    stubs = [mock.patch.object(_io, "write_output", lambda *a, **k: True),
             mock.patch.object(_io, "write_or_report", lambda *a, **k: True),
             mock.patch.object(bench, "write_or_report", lambda *a, **k: True),
             mock.patch.object(run, "write_output", lambda *a, **k: True),
             mock.patch.object(run, "execute_all", lambda *a, **k: {}),
             mock.patch.object(run, "precompile", lambda: None),
             mock.patch.object(run, "TIMES_FILE", TMP / "fuzz_times.json"),
             mock.patch.object(run, "EXECUTION_PAGE", TMP / "fuzz_execution.md"),
             mock.patch.object(run, "RUNS_DIR", TMP / "fuzz_runs"),
             mock.patch.object(claims_cli, "evaluate", lambda *a, **k: []),
             mock.patch.object(claims_cli, "write_or_report", lambda *a, **k: True),
             mock.patch.object(robustness, "verdict_robustness", lambda *a, **k: []),
             mock.patch.object(robustness, "write_json", lambda *a, **k: True),
             mock.patch.object(claims, "evaluate", lambda *a, **k: []),
             mock.patch.object(report, "render_report", lambda *a, **k: "")]
    stubs += [mock.patch.object(bench, name, lambda *a, **k: {})
              for name in ("bench_assignment", "bench_book", "bench_scaling", "bench_criteria")]
    mains = {"python -m obslib.run": run.main, "python -m obslib.bench": bench.main,
             "python -m obslib.claims": claims_cli.main, "python -m obsbook.report": report.main}
    return stubs, mains


@pytest.mark.parametrize("prog", ["python -m obslib.run", "python -m obslib.bench",
                                  "python -m obslib.claims", "python -m obsbook.report"])
@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(argv=st.lists(ARGV_WORDS, max_size=6))
def test_command_line_refuses_wrong_arguments_in_one_line(prog, argv):
    # Either the command runs (its work stubbed: exit status 0), or it stops before any work
    # with exit status 2 and one line on stderr, "<prog>: error: ...", and no traceback.
    stubs, mains = _cli_mains()
    err = io.StringIO()
    with contextlib.ExitStack() as stack:
        for s in stubs:
            stack.enter_context(s)
        stack.enter_context(contextlib.redirect_stderr(err))
        stack.enter_context(contextlib.redirect_stdout(io.StringIO()))
        try:
            code = mains[prog](argv)
        except SystemExit as exc:
            code = exc.code
    lines = [ln for ln in err.getvalue().splitlines() if ln.strip()]
    assert "Traceback" not in err.getvalue(), err.getvalue()
    if code == 0:
        return
    assert code == 2, (argv, code, err.getvalue())
    assert lines and lines[-1].startswith(f"{prog}: error: "), (argv, err.getvalue())


def test_the_command_lines_check_their_arguments_before_any_work():
    # the stubs above are never reached by a refused command line: a bad profile stops each
    stubs, mains = _cli_mains()
    for prog, main in mains.items():
        argv = ["book", "--profile", "nosuch"] if "bench" in prog else ["--profile", "nosuch"]
        with contextlib.redirect_stderr(io.StringIO()) as err, pytest.raises(SystemExit) as exc:
            main(argv)
        assert exc.value.code == 2 and "nosuch" in err.getvalue(), prog


# --------------------------------------------------------------------------- regressions


def test_geometry_greedy_with_a_far_target_terminates():
    # once a NaN weight made the target's candidate list refill forever (0/0 in the kernel)
    rng = np.random.default_rng(0)
    S = rng.uniform(0, 1, (6, 2))
    for T in (np.array([[1e155, 0.0], [0.5, 0.5]]), np.array([[1e155, 0.0]])):
        res = ob.greedy_pair_assignment(sensors=S, targets=T, u_max=1.0)
        valid_pairs(res, 6, T.shape[0])
        assert len(res.triples) == T.shape[0]
    for c in (1e200, 1e-170):  # all coordinates scaled (u_max not): weights are finite limits
        res = ob.greedy_pair_assignment(
            sensors=S * c, targets=np.array([[3.0, 3.0], [0.5, 0.5]]) * c, u_max=1.0
        )
        valid_pairs(res, 6, 2)
        assert len(res.triples) == 2


def test_teams_at_extreme_scale_are_valid_or_refused():
    rng = np.random.default_rng(1)
    S, T = rng.uniform(0, 10, (8, 2)), rng.uniform(0, 10, (3, 2))
    with pytest.raises(ValueError, match="eps"):  # eps = 1 is below the float range against 1e310
        ob.greedy_team_assignment(S * 1e155, T * 1e155)
    base = ob.greedy_team_assignment(S, T)
    assert ob.greedy_team_assignment(S * 1e150, T * 1e150, eps=1e300) == base
    assert ob.greedy_team_assignment(S * 1e155, T * 1e155, "rank") == ob.greedy_team_assignment(
        S, T, "rank"
    )


def test_negative_weights_are_refused_by_every_solver():
    W = np.zeros((4, 4, 2))
    W[0, 1, 0] = W[1, 0, 0] = -0.3
    W[2, 3, 1] = W[3, 2, 1] = 0.5
    for solve in (
        ob.greedy_pair_assignment,
        ob.relaxed_pair_assignment,
        ob.optimal_pair_assignment,
    ):
        with pytest.raises(ValueError, match=r"W\[0, 1, 0\] = -0.3 is negative"):
            solve(W)


def test_asymmetric_and_nan_weights_are_refused():
    W = np.zeros((4, 4, 1))
    W[0, 1, 0] = 0.2
    with pytest.raises(ValueError, match="symmetric"):
        ob.greedy_pair_assignment(W)
    W[1, 0, 0] = np.nan
    with pytest.raises(ValueError, match="not finite"):
        ob.relaxed_pair_assignment(W)


def test_weight_tensor_beyond_the_memory_limit_is_refused_up_front():
    S = np.column_stack([np.arange(2000.0), np.zeros(2000)])
    T = np.column_stack([np.arange(1000.0), np.ones(1000)])
    with pytest.raises(ValueError, match=r"greedy_pair_assignment\(sensors="):
        ob.pair_bounds(S, T, 1.0)
    with pytest.raises(ValueError, match="GiB"):
        from obslib.assignment import greedy_pair_assignment_literal

        greedy_pair_assignment_literal(sensors=S, targets=T, u_max=1.0)


def test_tiny_covariance_is_positive_definite():
    # determinant 1e-340 underflows; the check is made on the normalised matrix
    rng = np.random.default_rng(2)
    S, T = rng.uniform(0, 10, (5, 2)), rng.uniform(0, 10, (2, 2))
    cov = np.array([[2.0, 0.3], [0.3, 1.0]])
    a = ob.pair_bounds(S, T, 1.0, cov=1e-170 * cov)
    b = ob.pair_bounds(S * 1e85, T * 1e85, 1.0, cov=cov)  # the same Mahalanobis geometry
    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-14)
    with pytest.raises(ValueError, match="cov of target 0 is not positive definite"):
        ob.pair_bounds(S, T, 1.0, cov=1e-170 * np.array([[1.0, 2.0], [2.0, 1.0]]))


@pytest.mark.parametrize("call, error, name", [
    (lambda: ob.greedy_pair_assignment(np.zeros((4, 4, 1)), k=2.5), TypeError, "k"),
    (lambda: ob.greedy_pair_assignment(np.zeros((4, 4, 1)), k=True), TypeError, "k"),
    (lambda: ob.relaxed_pair_assignment(np.zeros((4, 4, 1)), ordered="no"), TypeError, "ordered"),
    (lambda: ob.pair_bounds([[0, 0], [1j, 1]], [[2, 2]], 1.0), TypeError, "sensors"),
    (lambda: ob.pair_bounds([[0, 0], [1, 1]], [[2, 2]], True), TypeError, "u_max"),
    (lambda: ob.lower_bound([[0, 0], [1, 1]], [True, False], 1.0), TypeError, "target"),
    (lambda: ob.measure([[0, 0], [1, 1]], [2, 2], "logdet", eps=True), TypeError, "eps"),
    (lambda: ob.scenes.random_scenes(3, None), TypeError, "seed"),
    (lambda: ob.scenes.random_scenes(3, 0, kinds="generic"), TypeError, "kinds"),
    (lambda: ob.scenes.random_scene_batch(3, 1.5), TypeError, "seed"),
])
def test_argument_types_are_named_errors(call, error, name):
    with pytest.raises(error, match=name):
        call()


# --------------------------------------------------------------------------- scale invariance


@pytest.mark.parametrize("c", [1e-150, 1e-75, 1e-20, 1e20, 1e75, 1e150])
def test_unit_invariant_quantities_do_not_depend_on_the_unit(c):
    # Every ratio of the paper is invariant when all lengths (coordinates, u_max; eps, a squared
    # length, by c^2) change unit. At c = 1 the computations are the plain formulas; at any other
    # c the rounding of the scaled inputs (one ulp) is all that may differ, hence rtol 1e-9 and,
    # for the pair bounds in [0, 1], atol 1e-12.
    rng = np.random.default_rng(3)
    S, T = rng.uniform(0, 10, (9, 2)), rng.uniform(0, 10, (3, 2))
    u, o, uu = 1.3, T[0], np.array([0.4, -0.7])
    assert ob.inverse_condition_number(S * c, o * c, uu * c) == pytest.approx(
        ob.inverse_condition_number(S, o, uu), rel=1e-9)
    assert ob.inverse_condition_number(S[:2] * c, o * c) == pytest.approx(
        ob.inverse_condition_number(S[:2], o), rel=1e-9)
    assert ob.lower_bound(S * c, o * c, u * c) == pytest.approx(ob.lower_bound(S, o, u), rel=1e-9)
    np.testing.assert_allclose(ob.worst_case_control(S * c, o * c, u * c) / c,
                               ob.worst_case_control(S, o, u), rtol=1e-9, atol=1e-12)
    W = ob.pair_bounds(S, T, u)
    np.testing.assert_allclose(ob.pair_bounds(S * c, T * c, u * c), W, rtol=1e-9, atol=1e-12)
    cov = np.array([[2.0, 0.3], [0.3, 1.0]])
    np.testing.assert_allclose(ob.pair_bounds(S * c, T * c, u, cov=cov * c * c),
                               ob.pair_bounds(S, T, u, cov=cov), rtol=1e-9, atol=1e-12)
    for name in ("rank",):
        assert ob.measure(S * c, o * c, name) == ob.measure(S, o, name) == 2.0
        assert ob.measure(S[:1] * c, o * c, name) == 1.0
    assert ob.measure(S * c, o * c, "logdet", eps=c * c) == pytest.approx(
        ob.measure(S, o, "logdet", eps=1.0) + 4 * np.log(c), rel=1e-9)
    assert ob.measure(S * c, o * c, "trace") == pytest.approx(
        ob.measure(S, o, "trace") * c * c, rel=1e-9
    )
    g = ob.greedy_pair_assignment(sensors=S, targets=T, u_max=u)
    assert ob.greedy_pair_assignment(sensors=S * c, targets=T * c, u_max=u * c).triples == g.triples
    assert ob.greedy_pair_assignment(ob.pair_bounds(S * c, T * c, u * c)).triples == g.triples
    r = ob.relaxed_pair_assignment(sensors=S, targets=T, u_max=u)
    assert (
        ob.relaxed_pair_assignment(sensors=S * c, targets=T * c, u_max=u * c).triples == r.triples
    )
    assert ob.optimal_pair_assignment(ob.pair_bounds(S * c, T * c, u * c)).triples == \
        ob.optimal_pair_assignment(W).triples
    small_S = S[:5]
    for name, eps in (("rank", 1.0), ("logdet", 1.0), ("trace", 1.0), ("neg_trace_inverse", 1.0)):
        e = eps if name == "rank" else eps * c * c
        assert ob.greedy_team_assignment(S * c, T * c, name, e) == ob.greedy_team_assignment(
            S, T, name, eps
        )
        assert ob.optimal_team_assignment(small_S * c, T * c, name, e)[0] == \
            ob.optimal_team_assignment(small_S, T, name, eps)[0]


def test_coordinates_whose_difference_overflows_are_named():
    with pytest.raises(ValueError, match="sensor 0 and target 0 are too far apart"):
        ob.lower_bound([[-1.7e308, 0.0], [0.0, 1.0]], [1.7e308, 0.0], 1.0)
    with pytest.raises(ValueError, match="sensor 1 and target 0 are too far apart"):
        ob.pair_bounds([[0.0, 1.0], [-1.7e308, 0.0]], [[1.7e308, 0.0]], 1.0)


def test_integers_beyond_the_float_range_are_named():
    with pytest.raises(ValueError, match="sensors has an integer beyond the float range"):
        ob.pair_bounds([[0, 10**400], [1, 1]], [[2, 2]], 1.0)
    with pytest.raises(ValueError, match="u_max has an integer beyond the float range"):
        ob.lower_bound([[0, 0], [1, 1]], [2, 2], 10**400)


# --------------------------------------------------------------------------- every public function


def _public_functions() -> dict:
    """Every function in the ``__all__`` of a public module of obslib (no part of its dotted name
    begins with an underscore), once, under the module that defines it."""
    found = {}
    for info in pkgutil.walk_packages(ob.__path__, "obslib."):
        if any(part.startswith("_") for part in info.name.split(".")[1:]):
            continue
        mod = importlib.import_module(info.name)
        for name in getattr(mod, "__all__", ()):
            obj = getattr(mod, name)
            if inspect.isfunction(inspect.unwrap(obj)):
                found.setdefault(f"{obj.__module__}.{obj.__qualname__}", obj)
    return found


PUBLIC = _public_functions()

#: Calls per public function (``OBSLIB_FUZZ_EXAMPLES`` for a longer search).
FUZZ_EXAMPLES = int(os.environ.get("OBSLIB_FUZZ_EXAMPLES", 25))

#: Wrong types and wrong values, one of which is given to one argument at a time.
HOSTILE = [None, True, "x", 1 + 1j, np.nan, -np.inf, -1, 2.5, 0, [], [[np.nan, 0.0]],
           np.zeros((2, 3)), np.array(["a", "b"]), {"a": 1}, object(),
           # arrays NumPy would misread without a word: a masked entry, a bool among numbers,
           # numbers as text in an object array
           np.ma.masked_array([[0.0, 1.0], [2.0, 3.0]], mask=[[False, True], [False, False]]),
           [[0.0, 1.0], [True, 2.0]], np.array([["1.5", 2.0]], dtype=object)]

#: Where an argument's error may be named by a part of it: an entry or a row of an array
#: (``sensor 1 ...``, ``W[0, 1, 0] ...``, ``cov 0 ...``, ``each seed ...``).
ALIASES = {"sensors": ("sensor",), "targets": ("target",), "strategies": ("strategy",),
           "seeds": ("seed",), "values": ("value", "f("), "names": ("measure", "name"),
           "masks": ("mask",), "kinds": ("kind",), "ids": ("id",), "counts": ("count", "scene"),
           "u": ("control",), "ground": ("sensor",), "name": ("measure", "criterion"),
           "arms": ("arm",)}

#: Public functions whose result may hold NaN by design, with the reason.
DOCUMENTED_NAN = {
    "obslib.tracking.stats.spearman": "the rank correlation of a constant or NaN slice is NaN",
}


def _names(fn) -> list[str]:
    return [p.name for p in inspect.signature(fn).parameters.values()
            if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]


def _named(message: str, names) -> bool:
    low = message.lower()
    return any(re.search(rf"(?<![a-z_]){re.escape(w.lower())}", low)
               for n in names for w in (n, *ALIASES.get(n, ())))


def _same(a, b) -> bool:
    """Whether a wrong value is the parameter's default (then it is not wrong)."""
    return a is b or (type(a) is type(b) and isinstance(a, (int, float, str)) and a == b)


def _has_nan(x, depth=0) -> bool:
    if depth > 4:
        return False
    if isinstance(x, float):
        return x != x
    if isinstance(x, np.ndarray) and x.dtype.kind in "fc":
        return bool(np.isnan(x).any())
    if isinstance(x, dict):
        return any(_has_nan(v, depth + 1) for v in x.values())
    if isinstance(x, (list, tuple)):
        return any(_has_nan(v, depth + 1) for v in x[:50])
    if dataclasses.is_dataclass(x) and not isinstance(x, type):
        return any(_has_nan(getattr(x, f.name), depth + 1) for f in dataclasses.fields(x))
    return False


class _Hang(Exception):
    pass


@contextlib.contextmanager
def _time_limit(seconds: int):
    """A call that takes longer than ``seconds`` is stopped with :class:`_Hang`."""
    def stop(signum, frame):
        raise _Hang(f"no answer within {seconds} s")

    old = signal.signal(signal.SIGALRM, stop)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def _raised_in(exc: BaseException) -> str:
    """The file of the innermost frame of ``exc``'s traceback."""
    tb = exc.__traceback__
    while tb.tb_next is not None:
        tb = tb.tb_next
    return tb.tb_frame.f_code.co_filename


LIBRARY = (str(Path(ob.__file__).parent), str(Path(ob.__file__).parents[1] / "obsbook"))


def test_every_public_function_is_found():
    # the enumeration reaches every layer, so a new public function cannot be left out
    for expected in ("obslib.bounds.lower_bound", "obslib.tracking.batch.simulate",
                     "obslib.studies.two_sensors_tracking.partner_study",
                     "obslib.claims.robustness.",
                     "obslib.viz.tracking.", "obslib.tools.run.", "obslib.profiles.params",
                     "obslib.symbolic.theorem4.", "obslib.scenes.random_scenes"):
        assert any(k.startswith(expected) for k in PUBLIC), expected
    assert len(PUBLIC) > 250


@pytest.mark.parametrize("qualname", sorted(k for k, f in PUBLIC.items()
                                             if _names(f) and f.__name__ != "main"))
@settings(max_examples=FUZZ_EXAMPLES, deadline=None, derandomize=True, phases=(Phase.generate,),
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_public_function_refuses_a_wrong_argument_by_name(qualname, data, tmp_path, monkeypatch):
    # Every required argument, one chosen argument and some of the others get a wrong type or
    # value (one of HOSTILE), the rest their defaults, so the call must refuse: a ValueError
    # (ArgumentTypeError is one) raised by the library itself, naming one of its arguments;
    # or, where every such value happens to be accepted, a result without NaN. Never another
    # exception, a hang, or an error from inside NumPy. The command lines' ``main(argv)`` are
    # tested below, through their arguments.
    fn = PUBLIC[qualname]
    monkeypatch.chdir(tmp_path)  # a path argument "x" is written here, not in the checkout
    params = [p for p in inspect.signature(fn).parameters.values()
              if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)]
    target = data.draw(st.sampled_from([p.name for p in params]), label="target")
    args = {}
    for p in params:  # required arguments and the target are wrong, the others wrong or default
        if p.default is p.empty or p.name == target or data.draw(st.booleans(), label=p.name):
            wrong = [v for v in HOSTILE if not _same(v, p.default)]  # None: often the default
            args[p.name] = data.draw(st.sampled_from(wrong), label=p.name)
    names = [p.name for p in params]
    try:
        with _time_limit(30), warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = fn(**args)
    except ValueError as exc:
        where = _raised_in(exc)
        assert where.startswith(LIBRARY), f"{qualname}: raised inside {where}: {exc!r}"
        assert _named(str(exc), names), f"{qualname}: the error names no argument: {exc!r}"
    else:
        assert qualname in DOCUMENTED_NAN or not _has_nan(out), f"{qualname}({args}): NaN {out!r}"
    finally:
        plt.close("all")


# --------------------------------------------------------------------------- what numpy misreads


#: Arrays NumPy reads silently as something else, per kind: a masked entry read as a number, a
#: bool among numbers read as 0 or 1, numeric text in an object array read as a number.
def _misread(good: np.ndarray) -> dict:
    mask = np.zeros(good.shape, dtype=bool)
    mask.flat[-1] = True
    with_bool = good.tolist()
    flat = with_bool
    while isinstance(flat[-1], list):
        flat = flat[-1]
    flat[-1] = True
    text = good.astype(object)
    text.flat[-1] = str(good.flat[-1])
    return {"masked": np.ma.masked_array(good, mask=mask), "bool": with_bool, "text": text}


S4 = np.array([[-3.0, 2.0], [0.0, 0.0], [1.0, -1.0], [4.0, 0.5]])
T2 = np.array([[2.0, 3.0], [5.0, 3.0]])
W4 = ob.pair_bounds(S4, T2, 1.0)

#: (call taking the argument, argument's name, a good value of it)
ARRAY_ARGUMENTS = [
    (lambda x: ob.lower_bound(x, T2[0], 1.0), "sensors", S4),
    (lambda x: ob.lower_bound(S4, x, 1.0), "target", T2[0]),
    (lambda x: ob.inverse_condition_number(S4, T2[0], x), "u", np.array([0.3, 0.1])),
    (lambda x: ob.pair_bounds(S4, x, 1.0), "targets", T2),
    (lambda x: ob.pair_bounds(S4, T2, x), "u_max", np.array([1.0, 2.0])),
    (lambda x: ob.pair_bounds(S4, T2, 1.0, cov=x), "cov", np.array([[2.0, 0.3], [0.3, 1.0]])),
    (lambda x: ob.pair_bound_polar(x, 1.0, 1.0), "alpha", np.array([0.5, 2.0])),
    (lambda x: ob.greedy_pair_assignment(x), "W", W4),
    (lambda x: ob.relaxed_pair_assignment(sensors=x, targets=T2, u_max=1.0), "sensors", S4),
    (lambda x: ob.optimal_pair_assignment(x), "W", W4),
    (lambda x: ob.measure(S4, T2[0], "trace", u=x), "u", np.array([0.3, 0.1])),
    (lambda x: ob.greedy_team_assignment(S4, x), "targets", T2),
    (lambda x: ob.bounds.lower_bounds(x, 1.0), "rows", S4[None] - T2[:1, None]),
    (lambda x: ob.measures.measures_from_vectors(x, [[True] * 4]), "vectors", S4),
]


@pytest.mark.parametrize("kind", ["masked", "bool", "text"])
@pytest.mark.parametrize("index", range(len(ARRAY_ARGUMENTS)))
def test_arrays_numpy_would_misread_are_refused_by_name(index, kind):
    call, name, good = ARRAY_ARGUMENTS[index]
    call(good)  # the good value is accepted
    bad = _misread(good)[kind]
    with pytest.raises(ValueError) as exc:
        call(bad)
    assert _named(str(exc.value), [name]), exc.value
    if kind != "masked":
        assert isinstance(exc.value, TypeError)


# --------------------------------------------------------------------------- joblib and Dask


@pytest.mark.parametrize("backend, n_jobs, scheduler, name", [
    ("joblib", 0, None, "n_jobs"),  # joblib: "n_jobs == 0 has no meaning"; was all cores
    ("joblib", -1, None, "n_jobs"),  # joblib: every core; here None says so
    ("joblib", -7, None, "n_jobs"),  # joblib: silently one process
    ("joblib", 2.0, None, "n_jobs"),
    ("joblib", True, None, "n_jobs"),
    ("joblib", "2", None, "n_jobs"),
    ("serial", 2, None, "n_jobs"),  # was ignored
    ("dask", 2, "tcp://127.0.0.1:8786", "n_jobs"),
    ("serial", None, "tcp://127.0.0.1:8786", "scheduler"),  # was ignored
    ("joblib", None, "tcp://127.0.0.1:8786", "scheduler"),
    ("dask", None, None, "scheduler"),
    ("dask", None, "nohost", "scheduler"),  # no port: Dask would wait for it
    ("dask", None, "tcp:// 1.2.3.4:8786", "scheduler"),
    ("dask", None, 8786, "scheduler"),
    ("dask", None, {"address": "tcp://x:1"}, "scheduler"),
    ("threads", None, None, "backend"),
    (None, None, None, "backend"),
])
def test_arguments_for_joblib_and_dask_are_named_before_anything_starts(backend, n_jobs,
                                                                         scheduler, name):
    from obslib.studies import general_assignment, greedy_vs_relaxed
    from obslib.sweep import run_sweep

    calls = (lambda: run_sweep(pow, [dict(base=2, exp=1)], backend, n_jobs, scheduler),
             lambda: greedy_vs_relaxed.fig8_sweep([2], 2, 0, backend=backend, n_jobs=n_jobs,
                                                  scheduler=scheduler),
             lambda: general_assignment.fig9_sweep([6], 2, 0, backend=backend, n_jobs=n_jobs,
                                                   scheduler=scheduler))
    for call in calls:
        with _time_limit(5), pytest.raises(ValueError) as exc:  # no worker, no connection
            call()
        assert _named(str(exc.value), [name]), exc.value


@pytest.mark.parametrize("kwargs, name", [
    ({"measure": "trace_inverse"}, "measure"), ({"measure": "nope"}, "measure"),
    ({"eps": -1.0}, "eps"), ({"n_targets": 2.5}, "n_targets"), ({"side": 0.0}, "side"),
])
def test_the_trials_arguments_are_checked_before_the_tasks_go_out(kwargs, name, monkeypatch):
    from obslib.studies import general_assignment

    monkeypatch.setattr(general_assignment, "run_sweep", lambda *a, **k: pytest.fail("dispatched"))
    with pytest.raises(ValueError) as exc:
        general_assignment.fig9_sweep([6], 2, 0, backend="joblib", n_jobs=2, **kwargs)
    assert _named(str(exc.value), [name]), exc.value


def test_an_address_where_no_scheduler_answers_is_a_named_error():
    import dask

    from obslib.sweep import run_sweep

    with dask.config.set({"distributed.comm.timeouts.connect": "1s"}), _time_limit(60):
        with pytest.raises(ValueError, match=r"^scheduler 'tcp://127.0.0.1:9': no Dask sched"):
            run_sweep(pow, [dict(base=2, exp=1)], "dask", scheduler="tcp://127.0.0.1:9")


def test_tasks_must_be_keyword_dicts():
    from obslib.sweep import run_sweep

    for tasks in ([{1: 2}], [[("base", 2)]], [{"base": 2}, 3], "base"):
        with pytest.raises(ValueError, match="tasks"):
            run_sweep(pow, tasks)
