"""Theorem 8's measures (obslib.measures): values against plain NumPy, conventions, properties."""

import doctest
import itertools
import warnings

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import obslib.measures as me
import obslib.submodularity as subm

SETTINGS = settings(derandomize=True, deadline=None, max_examples=60, database=None)

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)


@st.composite
def ground_sets(draw, min_n=1, max_n=6):
    """(sensors (N, 2), target (2,)), points at least 1e-2 apart."""
    n = draw(st.integers(min_n, max_n))
    pts = np.array(draw(st.lists(st.tuples(coord, coord), min_size=n + 1, max_size=n + 1)))
    d = np.linalg.norm(pts[:, None] - pts[None], axis=-1) + np.eye(n + 1) * 1e9
    assume(d.min() > 1e-2)
    return pts[1:], pts[0]


def gram(sensors, target, u=None, eps=0.0):
    O = np.asarray(target, float)[None, :] - np.asarray(sensors, float).reshape(-1, 2)
    if u is not None:
        O = np.vstack([O, u])
    return O.T @ O + eps * np.eye(2), O


def reference(sensors, target, name, eps=0.0, u=None):
    """The measure straight from its definition, with NumPy's dense routines."""
    G, O = gram(sensors, target, u, eps)
    if name == "trace":
        return np.trace(G)
    if name == "rank":
        return float(np.linalg.matrix_rank(O)) if O.size else 0.0
    if name == "logdet":
        sign, ld = np.linalg.slogdet(G)
        return ld if sign > 0 else -np.inf
    inv = np.trace(np.linalg.inv(G))
    return inv if name == "trace_inverse" else -inv


# --------------------------------------------------------------------------- values


@SETTINGS
@given(ground_sets(), st.sampled_from(me.MEASURES), st.sampled_from([0.0, 0.01, 1.0]),
       st.booleans())
def test_measure_matches_dense_definition(gs, name, eps, with_u):
    sensors, target = gs
    u = np.array([0.6, -0.8]) if with_u else None
    G, O = gram(sensors, target, u, eps)
    # keep away from numerically singular cases, where the rank threshold decides
    sv = np.linalg.svd(O, compute_uv=False)
    assume(len(sv) == 2 and sv[-1] > 1e-6 * sv[0])
    got = me.measure(sensors, target, name, eps=eps, u=u)
    assert np.isclose(got, reference(sensors, target, name, eps, u), rtol=1e-9, atol=1e-12)


@SETTINGS
@given(ground_sets(max_n=5), st.sampled_from(me.MEASURES), st.sampled_from([0.01, 1.0]))
def test_table_matches_measure_on_every_subset(gs, name, eps):
    sensors, target = gs
    table = me.measure_table(sensors, target, name, eps=eps)
    masks = me.subset_masks(len(sensors))
    for k, m in enumerate(masks):
        assert np.isclose(
            table[k], me.measure(sensors[m], target, name, eps=eps), rtol=1e-12, atol=0
        )


def test_subset_masks_bit_order():
    m = me.subset_masks(3)
    assert m.shape == (8, 3)
    assert not m[0].any() and m[7].all()
    assert [tuple(np.flatnonzero(r)) for r in m[:4]] == [(), (0,), (1,), (0, 1)]


def test_symmetric_observability_matrix():
    s, o, u = np.array([[0.0, 0.0], [2.0, 0.0]]), np.array([1.0, 1.0]), np.array([0.5, 0.0])
    G = me.symmetric_observability_matrix(s, o, u=u, eps=0.1)
    assert np.allclose(G, [[2.25 + 0.1, 0.0], [0.0, 2.1]])


def test_doctests():
    assert doctest.testmod(me, raise_on_error=False).failed == 0


# --------------------------------------------------------------------------- conventions


def test_singular_conventions_without_warnings():
    o = np.array([1.0, 1.0])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # empty set: O^T O = 0
        assert me.measure([], o, "rank") == 0.0
        assert me.measure([], o, "trace") == 0.0
        assert me.measure([], o, "logdet") == -np.inf
        assert me.measure([], o, "trace_inverse") == np.inf
        assert me.measure([], o, "neg_trace_inverse") == -np.inf
        # one sensor: rank one
        s1 = [[0.0, 0.0]]
        assert me.measure(s1, o, "rank") == 1.0
        assert me.measure(s1, o, "logdet") == -np.inf
        assert me.measure(s1, o, "trace_inverse") == np.inf
        # two sensors collinear with the target: still rank one
        col = [[0.0, 0.0], [3.0, 3.0]]
        assert me.measure(col, o, "rank") == 1.0
        assert me.measure(col, o, "logdet") == -np.inf
        # a prior makes everything finite: log det(eps I) and trace((eps I)^-1)
        assert np.isclose(me.measure([], o, "logdet", eps=0.5), 2 * np.log(0.5))
        assert np.isclose(me.measure([], o, "trace_inverse", eps=0.5), 4.0)
        assert np.isclose(me.measure(col, o, "logdet", eps=0.5), reference(col, o, "logdet", 0.5))
        # a u row not parallel to o - p makes one sensor enough
        assert np.isfinite(me.measure(s1, o, "logdet", u=[1.0, 0.0]))
        assert me.measure(s1, o, "rank", u=[1.0, 0.0]) == 2.0
        # rank ignores eps
        assert me.measure(s1, o, "rank", eps=1.0) == 1.0
        # and a table over all subsets of a degenerate set has no NaN
        t = me.measure_table(col, o, "trace_inverse")
        assert not np.isnan(t).any()


def test_rank_threshold_near_collinear():
    o = np.zeros(2)
    s = np.array([[1.0, 0.0], [-1.0, 1e-12]])  # sigma ratio ~ 5e-13 < 1e-10
    assert me.measure(s, o, "rank") == 1.0
    assert me.measure(s, o, "rank", rank_rtol=0.0) == 2.0
    s = np.array([[1.0, 0.0], [-1.0, 1e-6]])
    assert me.measure(s, o, "rank") == 2.0


def test_direction_table():
    assert me.DIRECTION["trace_inverse"] == "decreasing"
    assert all(me.DIRECTION[n] == "increasing" for n in me.MEASURES if n != "trace_inverse")


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: me.measure([[0, 0], [1, 0]], [1, 1], "condition"), "unknown measure"),
        (lambda: me.measure([[0, 0], [1, 0]], [1, 1], "logdet", eps=-1.0), "eps"),
        (lambda: me.measure([[0, 0], [1, 0]], [1, 1], "logdet", eps=np.nan), "eps"),
        (lambda: me.measure([[0, 0], [1, 0]], [1, 1], "logdet", u=[1, 2, 3]), "u must have shape"),
        (
            lambda: me.measure([[0, 0], [1, 0]], [1, 1], "logdet", u=[np.inf, 0]),
            "u has a non-finite",
        ),
        (lambda: me.measure([[1, 1], [1, 0]], [1, 1], "trace"), "sensor 0 coincides with target"),
        (lambda: me.measure([[0, 0], [0, 0]], [1, 1], "trace"), "sensors 0 and 1 coincide"),
        (lambda: me.measure([[0, np.nan]], [1, 1], "trace"), "sensor 0 has a non-finite"),
        (lambda: me.measure([[0, 0]], [1, 1, 1], "trace"), "target must have shape"),
        (lambda: me.measure([[0, 0]], [1, 1], "rank", rank_rtol=2.0), "rank_rtol"),
        (
            lambda: me.measure_table([[0, 0], [1, 0]], [1, 1], "trace", masks=np.ones((2, 3))),
            "masks",
        ),
        (lambda: me.measure_from_vectors(np.ones((3, 3)), np.ones((1, 3)), "trace"), "vectors"),
        (lambda: me.subset_masks(-1), "n must be at least 0"),
        (lambda: me.subset_masks(40), "too large"),
    ],
)
def test_bad_input_raises(call, match):
    with pytest.raises(ValueError, match=match):
        call()


# --------------------------------------------------------------------------- properties that hold


def _audit(sensors, target, name, eps, min_size=0, u=None):
    return subm.audit_set_function(
        sensors, values=me.measure_table(sensors, target, name, eps=eps, u=u), min_size=min_size
    )


def _direct_gains_hold(sensors, target, name, eps, min_size=0, submodular=True, u=None):
    """Every nested (A, B, x) recomputed with measure() directly, no witness finder."""
    n = len(sensors)
    f = {}
    for k in range(n + 1):
        for S in itertools.combinations(range(n), k):
            f[S] = me.measure(sensors[list(S)], target, name, eps=eps, u=u)
    scale = 1e-9 * max(abs(v) for v in f.values()) + 1e-12
    for B in f:
        if len(B) < min_size:
            continue
        for x in set(range(n)) - set(B):
            Bx = tuple(sorted(B + (x,)))
            assert f[Bx] >= f[B] - scale  # monotone increasing
            if not submodular:
                continue
            for k in range(min_size, len(B)):
                for A in itertools.combinations(B, k):
                    Ax = tuple(sorted(A + (x,)))
                    assert f[Ax] - f[A] >= f[Bx] - f[B] - scale


@SETTINGS
@given(ground_sets(max_n=6), st.sampled_from([1e-3, 1.0, 50.0]), st.booleans())
def test_logdet_with_prior_is_monotone_submodular(gs, eps, with_u):
    sensors, target = gs
    u = np.array([0.3, 0.4]) if with_u else None
    a = _audit(sensors, target, "logdet", eps, u=u)
    assert a.monotone_increasing and a.submodular, (a.monotone_witness, a.submodular_witness)


@SETTINGS
@given(ground_sets(min_n=2, max_n=6))
def test_logdet_without_prior_on_sets_of_two_is_monotone_submodular(gs):
    sensors, target = gs
    v = target - sensors
    cross = np.abs(v[:, None, 0] * v[None, :, 1] - v[:, None, 1] * v[None, :, 0])
    norms = np.linalg.norm(v, axis=1)
    assume((cross + np.eye(len(v)) > 1e-6 * norms[:, None] * norms[None, :]).all())
    a = _audit(sensors, target, "logdet", 0.0, min_size=2)
    assert a.monotone_increasing and a.submodular


@SETTINGS
@given(ground_sets(max_n=5), st.sampled_from([1e-3, 1.0]))
def test_logdet_direct_recomputation(gs, eps):
    sensors, target = gs
    _direct_gains_hold(sensors, target, "logdet", eps)


@SETTINGS
@given(ground_sets(max_n=6), st.booleans())
def test_trace_is_modular_and_increasing(gs, with_u):
    sensors, target = gs
    a = _audit(sensors, target, "trace", 0.0, u=np.array([1.0, 0.0]) if with_u else None)
    assert a.monotone_increasing and a.modular


@st.composite
def on_lines(draw):
    """Sensors on one or two lines through the target: many rank-deficient subsets."""
    n = draw(st.integers(2, 6))
    phis = draw(st.lists(st.floats(0, 3.1), min_size=2, max_size=2))
    which = draw(st.lists(st.integers(0, 1), min_size=n, max_size=n))
    ts = draw(st.lists(st.floats(0.1, 5.0), min_size=n, max_size=n, unique=True))
    signs = draw(st.lists(st.sampled_from([-1.0, 1.0]), min_size=n, max_size=n))
    o = np.array([1.0, 2.0])
    d = np.array([[np.cos(phis[w]), np.sin(phis[w])] for w in which])
    return o + (np.array(signs) * np.array(ts))[:, None] * d, o


@SETTINGS
@given(st.one_of(ground_sets(max_n=6), on_lines()))
def test_rank_is_monotone_submodular(gs):
    sensors, target = gs
    a = _audit(sensors, target, "rank", 0.0)
    assert a.monotone_increasing and a.submodular


@SETTINGS
@given(ground_sets(max_n=6), st.sampled_from([1e-3, 1.0]))
def test_trace_inverse_decreases_and_its_negative_increases(gs, eps):
    sensors, target = gs
    assert _audit(sensors, target, "trace_inverse", eps).monotone_decreasing
    assert _audit(sensors, target, "neg_trace_inverse", eps).monotone_increasing
    _direct_gains_hold(sensors, target, "neg_trace_inverse", eps, submodular=False)


# --------------------------------------------------------------------------- the property that
# fails


def neg_tr_inv(sensors, target, eps):
    G, _ = gram(sensors, target, None, eps)
    return -np.trace(np.linalg.inv(G))


def test_neg_trace_inverse_hand_example():
    """A three-sensor counter-example checkable by hand (eps = 1, target at the origin).

    Rows a = (1, 1), b = (2, 1), c = (1, 2). trace(G^-1) = tr(G) / det(G) for 2 x 2 G:
    I + aa^T = [[2, 1], [1, 2]] -> 4/3; adding c -> [[3, 3], [3, 6]] -> 9/9 = 1: gain 1/3.
    I + aa^T + bb^T = [[6, 3], [3, 3]] -> 9/9 = 1; adding c -> [[7, 5], [5, 7]] -> 14/24: gain 5/12.
    The gain of c grows from 1/3 to 5/12 when b joins: -trace(G^-1) is not submodular.
    """
    o = np.array([0.0, 0.0])
    s = -np.array([[1.0, 1.0], [2.0, 1.0], [1.0, 2.0]])  # rows o - p = a, b, c
    f = {S: neg_tr_inv(s[list(S)].reshape(-1, 2), o, 1.0)
         for k in range(4) for S in itertools.combinations(range(3), k)}
    assert np.isclose(f[(0, 2)] - f[(0,)], 1 / 3)
    assert np.isclose(f[(0, 1, 2)] - f[(0, 1)], 5 / 12)
    for name, sign in (("neg_trace_inverse", 1.0), ("trace_inverse", -1.0)):
        t = me.measure_table(s, o, name, eps=1.0)
        assert np.isclose(sign * (t[0b101] - t[0b001]), 1 / 3)
        assert np.isclose(sign * (t[0b111] - t[0b011]), 5 / 12)
    a = subm.audit_set_function(s, values=me.measure_table(s, o, "neg_trace_inverse", eps=1.0))
    assert not a.submodular and a.monotone_increasing
    w = a.submodular_witness
    assert (w.A, w.B, w.x) == ((0,), (0, 1), 2)
    # b and c are mirror images about a, so the same holds with their roles swapped; no other
    assert a.n_submodular_violations == 2
    assert np.isclose(t[0b111] - t[0b101], t[0b111] - t[0b011])


# --------------------------------------------------------------------------- the shared kernels


@pytest.mark.parametrize("with_u", [False, True])
def test_measures_from_vectors_is_bitwise_measure_from_vectors(with_u):
    # Bitwise is legitimate here: both calls run the same code on arrays of the same shapes, so
    # every BLAS call has the same shape (and the same kernel) in both; nothing is compared across
    # differently shaped calls.
    rng = np.random.default_rng(4)
    v = rng.normal(size=(700, 6, 2)) * 10.0 ** rng.uniform(-2, 2, size=(700, 1, 1))
    u = rng.normal(size=(700, 2)) if with_u else None
    masks = me.subset_masks(6)
    for eps in (0.0, 1.0):
        many = me.measures_from_vectors(v, masks, me.MEASURES, eps, u)
        for name in me.MEASURES:
            assert np.array_equal(many[name], me.measure_from_vectors(v, masks, name, eps, u),
                                  equal_nan=True), name


def test_blocked_matrix_product_equals_the_product_to_rounding():
    # the blocked product is a kernel with no public entry of its own, so it is tested directly
    from obslib._kernels import matmul_rows

    # matmul_rows multiplies non-negative data (squared lengths, squared cross products) by 0/1
    # masks, as its callers do. Each entry is then a sum of `inner` non-negative terms; any order
    # of summation (BLAS picks it by CPU, thread count and block shape) is within
    # inner * eps_machine of the exact sum, relative to the entry itself. That bound is the
    # tolerance, so the test holds on every CPU and BLAS thread count.
    rng = np.random.default_rng(5)
    for rows, inner, cols in ((5000, 21, 64), (3000, 7, 128), (10, 3, 8), (20000, 28, 256)):
        x = rng.random((rows, inner)) * 10.0 ** rng.uniform(-3, 3, size=(rows, 1))
        w = (rng.random((inner, cols)) < 0.5).astype(float)
        exact = np.einsum("rk,kc->rc", x.astype(np.longdouble), w.astype(np.longdouble))
        rtol = inner * np.finfo(float).eps
        for ww in (w, w.T.copy().T):
            got = matmul_rows(x, ww)
            assert got.shape == (rows, cols)
            assert (np.abs(got - exact) <= rtol * exact).all()

