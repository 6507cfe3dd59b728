"""Bad input raises ValueError naming what is wrong; legal edge cases do not."""

import numpy as np
import pytest

import obslib as ob

S = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 3.0]])
O = np.array([1.0, 1.0])
T = O[None]


def callers():
    """Each public function as f(sensors, target_or_targets, u_max)."""
    return {
        "observability_matrix": lambda s, o, u: ob.observability_matrix(
            s, o[0] if np.ndim(o) == 2 else o
        ),
        "inverse_condition_number": lambda s, o, u: ob.inverse_condition_number(
            s, o[0] if np.ndim(o) == 2 else o, [0.1, 0.2]
        ),
        "lower_bound": lambda s, o, u: ob.lower_bound(s, o[0] if np.ndim(o) == 2 else o, u),
        "worst_case_control": lambda s, o, u: ob.worst_case_control(
            s, o[0] if np.ndim(o) == 2 else o, u
        ),
        "pair_bounds": lambda s, o, u: ob.pair_bounds(s, o if np.ndim(o) == 2 else o[None], u),
    }


FUNCS = callers()


@pytest.mark.parametrize("name", FUNCS)
@pytest.mark.parametrize(
    "sensors, target, u_max, message",
    [
        (np.array([[0.0, 0.0], [np.nan, 1.0]]), T, 1.0, "sensor 1 has a non-finite coordinate"),
        (np.array([[0.0, 0.0], [2.0, np.inf]]), T, 1.0, "sensor 1 has a non-finite coordinate"),
        (np.zeros(4), T, 1.0, "sensors must have shape (n, 2)"),
        (np.zeros((3, 3)), T, 1.0, "sensors must have shape (n, 2)"),
        (S, np.array([[1.0, 1.0, 1.0]]), 1.0, "shape"),
        (S, np.array([[np.nan, 1.0]]), 1.0, "non-finite"),
        (
            np.array([[0.0, 0.0], [1.0, 1.0], [5.0, 5.0]]),
            T,
            1.0,
            "sensor 1 coincides with target 0",
        ),
        (np.array([[0.0, 0.0], [2.0, 2.0], [0.0, 0.0]]), T, 1.0, "sensors 0 and 2 coincide"),
    ],
)
def test_bad_geometry(name, sensors, target, u_max, message):
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        FUNCS[name](sensors, target, u_max)


@pytest.mark.parametrize("name", ["lower_bound", "worst_case_control", "pair_bounds"])
@pytest.mark.parametrize(
    "u_max, message",
    [(-1.0, "non-negative"), (np.nan, "finite"), (np.inf, "finite"), ("fast", "u_max")],
)
def test_bad_u_max(name, u_max, message):
    with pytest.raises(ValueError, match=message):
        FUNCS[name](S, T, u_max)


def test_u_max_vector_must_match_targets():
    with pytest.raises(ValueError, match="one value per target"):
        ob.pair_bounds(S, [[1.0, 1.0], [2.0, 2.0]], [1.0, 1.0, 1.0])
    with pytest.raises(ValueError, match="non-negative for target 1"):
        ob.pair_bounds(S, [[1.0, 1.0], [2.0, 2.0]], [1.0, -1.0])


@pytest.mark.parametrize(
    "cov, message",
    [
        (np.eye(3), "shape"),
        (np.array([[1.0, 0.0], [0.0, -1.0]]), "target 0 is not positive definite"),
        (np.array([[1.0, 2.0], [2.0, 1.0]]), "not positive definite"),
        (np.array([[1.0, 0.5], [0.0, 1.0]]), "not symmetric"),
        (np.array([[1.0, np.nan], [np.nan, 1.0]]), "non-finite"),
        (np.stack([np.eye(2), np.zeros((2, 2))]), "target 1 is not positive definite"),
    ],
)
def test_bad_covariance(cov, message):
    targets = [[1.0, 1.0], [2.0, 2.0]]
    with pytest.raises(ValueError, match=message):
        ob.pair_bounds(S, targets, 1.0, cov=cov)


@pytest.mark.parametrize(
    "args, message",
    [
        ((-1.0, 0.5, 0.1), "alpha"),
        ((1.0, np.nan, 0.1), "theta"),
        ((1.0, 0.5, -2.0), "u_over_d"),
        ((np.inf, 0.5, 0.1), "alpha"),
    ],
)
def test_bad_polar_arguments(args, message):
    with pytest.raises(ValueError, match=message):
        ob.pair_bound_polar(*args)


def test_bad_control():
    with pytest.raises(ValueError, match="u has a non-finite"):
        ob.inverse_condition_number(S, O, [np.nan, 0.0])
    with pytest.raises(ValueError, match="u must have shape"):
        ob.inverse_condition_number(S, O, [1.0, 2.0, 3.0])


def test_no_nan_from_legal_degenerate_input():
    """Collinear sensors and u_max = 0 give 0 and finite values, not NaN."""
    line = np.array([[0.0, 0.0], [1.0, 0.0], [3.0, 0.0]])
    assert ob.lower_bound(line, [2.0, 0.0], 0.0) == 0.0
    W = ob.pair_bounds(line, [[2.0, 0.0], [2.0, 1.0]], 0.0)
    assert np.isfinite(W).all() and np.all(W[:, :, 0] == 0)
    assert ob.inverse_condition_number(line, [2.0, 0.0], [0.0, 0.0]) == 0.0


def test_each_check_runs_in_one_place_in_the_same_order():
    """The public functions validate once and hand validated arrays to private workers; the first
    fault of an input with several is still the one the argument order names (sensors before
    targets before u_max; vectors' dtype, then masks' dtype, then their shapes)."""
    bad_s, bad_t = np.array([[0.0, 0.0], [np.nan, 1.0]]), np.array([[np.inf, 1.0]])
    with pytest.raises(ValueError, match="sensor 1 has a non-finite"):
        ob.pair_bounds(bad_s, bad_t, -1.0, cov=-np.eye(2))
    with pytest.raises(ValueError, match="target 0 has a non-finite"):
        ob.pair_bounds(S, bad_t, -1.0, cov=-np.eye(2))
    with pytest.raises(ValueError, match="cov of target 0"):  # the scene and cov before u_max
        ob.pair_bounds(S, T, -1.0, cov=-np.eye(2))
    with pytest.raises(ValueError, match="masks must be booleans"):
        ob.measures.measures_from_vectors(np.zeros(3), [["a"]], ("trace",))
    with pytest.raises(ValueError, match="vectors must have shape"):
        ob.measures.measures_from_vectors(np.zeros(3), [[1, 0]], ("trace",))
    with pytest.raises(ValueError, match="unknown measure"):
        ob.measure_table(S, O, "nope", eps=-1.0, masks=[["a"]])
    with pytest.raises(ValueError, match="eps"):
        ob.measure_table(S, O, "trace", eps=-1.0, masks=[["a"]])
    with pytest.raises(ValueError, match="masks must have shape"):
        ob.measure_table(S, O, "trace", masks=[[True, False]])
    # the private route gives the public result bit for bit
    from obslib._validate import as_points, validated_vectors, vectors_between

    rng = np.random.default_rng(3)
    for _ in range(20):
        s, t = rng.normal(size=(5, 2)), rng.normal(size=(3, 2)) + 4
        cov = np.array([[2.0, 0.3], [0.3, 1.0]])
        a = validated_vectors(s, t, cov)
        b = vectors_between(as_points(s), as_points(t, "targets"), cov)
        assert all(np.array_equal(x, y) for x, y in zip(a, b))


# --------------------------------------------------------------------------------------------
# One error contract: every bad input is a ValueError, wrong types also a TypeError
# --------------------------------------------------------------------------------------------


def test_wrong_types_in_every_layer_are_caught_as_value_errors():
    from obslib import tracking as tr
    from obslib._validate import ArgumentTypeError

    setup = tr.PAPER_CIRCLE.replace(steps=3)
    for call in (lambda: tr.monte_carlo(setup, n_seeds=2.0),
                 lambda: tr.simulate(setup, "best-pair", seed=True),
                 lambda: tr.simulate_batch(setup, "best-pair", seeds=[0, None]),
                 lambda: ob.controls.disc_controls(1.0, 3.0, 8),
                 lambda: ob.greedy_pair_assignment(np.zeros((4, 4, 1)), k=2.5)):
        with pytest.raises(ValueError) as exc:
            call()
        assert isinstance(exc.value, TypeError) and isinstance(exc.value, ArgumentTypeError)


def test_the_pair_solvers_refuse_weights_and_geometry_together_alike():
    S, T = [[0, 0], [1, 0], [10, 0], [11, 0.5]], [[0.5, 1], [10.5, 1]]
    W = ob.pair_bounds(S, T, 1.0)
    from obslib.assignment import greedy_pair_assignment_literal

    for solve in (ob.greedy_pair_assignment, ob.relaxed_pair_assignment,
                  greedy_pair_assignment_literal):
        for extra in ({"sensors": S}, {"targets": T}, {"u_max": 1.0}, {"cov": np.eye(2)}):
            with pytest.raises(ValueError, match=r"^give either W or sensors/targets, not both$"):
                solve(W, **extra)
        with pytest.raises(ValueError, match=r"^give W, or sensors=, targets= and u_max="):
            solve(sensors=S, targets=T)


def test_validators_take_the_value_first():
    from obslib import _validate as v

    assert v.as_int(3, "n", 1) == 3 and v.as_positive(2.5, "step") == 2.5
    assert v.as_nonnegative(0, "u_max") == 0.0
    with pytest.raises(ValueError, match="step must be finite and positive, got 0"):
        v.as_positive(0, "step")
    with pytest.raises(v.ArgumentTypeError, match="n must be an integer, got 3.0"):
        v.as_int(3.0, "n", 1)


# --------------------------------------------------------------------------------------------
# One validator per public entry point (scipy.optimize's `_milp_iv` pattern)
# --------------------------------------------------------------------------------------------

#: The core modules: the paper's numerics and the assignment solvers.
CORE = ("observability", "bounds", "measures", "assignment", "teams", "pair_form", "scenes",
        "controls", "submodularity", "bound_tables", "sweep", "published_runs")


def _entry_points():
    """``(module, function name, ast of its body without the docstring)`` of every public function
    with arguments of the core modules."""
    import ast
    import importlib
    import inspect

    out = []
    for name in CORE:
        mod = importlib.import_module(f"obslib.{name}")
        tree = ast.parse(inspect.getsource(mod))
        defs = {n.name: n for n in tree.body if isinstance(n, ast.FunctionDef)}
        for fn in mod.__all__:
            node = defs.get(fn)
            if node is None or not node.args.args + node.args.kwonlyargs:
                continue
            body = node.body
            if body and isinstance(body[0], ast.Expr) and isinstance(body[0].value, ast.Constant):
                body = body[1:]
            out.append((name, fn, body))
    return out


def _called(nodes) -> set:
    import ast

    names = set()
    for node in nodes:
        for sub in ast.walk(node):
            if isinstance(sub, ast.Call):
                f = sub.func
                names.add(f.id if isinstance(f, ast.Name) else getattr(f, "attr", ""))
    return names


def test_every_core_entry_point_validates_in_one_iv_function_first():
    """Each public function of the core starts with one call to its ``_..._iv`` function, which
    returns the canonical arguments, and calls no validator of ``obslib._validate`` after it:
    the rest is the computation (or a call of the worker)."""
    from obslib import _validate

    validators = {n for n in dir(_validate) if n.startswith(("as_", "check_"))} | {
        "broadcast", "validated_vectors", "vectors_between"}
    entries = _entry_points()
    assert len(entries) > 50
    for module, fn, body in entries:
        first = [n for n in _called(body[:1]) if n.endswith("_iv")]
        assert first, f"obslib.{module}.{fn}: its first statement calls no _..._iv function"
        later = _called(body[1:]) & validators
        assert not later, f"obslib.{module}.{fn} validates after its _iv function: {later}"
