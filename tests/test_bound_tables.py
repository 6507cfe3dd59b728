"""Theorem 1's bound as a table over subsets (obslib.bound_tables) against the SVD of
obslib.lower_bound."""

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import obslib as ob
from obslib.bound_tables import lower_bound_set_function, lower_bound_table, lower_bound_tables
from obslib.measures import subset_masks

SETTINGS = settings(derandomize=True, deadline=None, max_examples=60, database=None)
SENSORS = np.array([[0.0, 0.0], [2.0, 0.0], [0.0, 2.0]])
TARGET = np.array([1.0, 1.0])

coord = st.floats(-10.0, 10.0, allow_nan=False, allow_infinity=False)


@SETTINGS
@given(st.lists(st.tuples(coord, coord), min_size=2, max_size=7), st.floats(0.0, 3.0))
def test_lower_bound_table_matches_svd(points, u_max):
    pts = np.array(points)
    d = np.linalg.norm(pts[:, None] - pts[None], axis=-1) + np.eye(len(pts))
    assume(d.min() > 1e-3)
    s, o = pts[1:], pts[0]
    table = lower_bound_table(s, o, u_max)
    for k, m in enumerate(subset_masks(len(s))):
        assert abs(table[k] - ob.lower_bound(s[m], o, u_max)) < 1e-9


def test_tables_and_set_function_agree():
    rng = np.random.default_rng(2)
    s, o = rng.uniform(0, 10, (5, 2)), rng.uniform(0, 10, 2)
    many = lower_bound_tables((o - s)[None], 0.7)[0]
    omega = lower_bound_set_function(s, o, 0.7)
    for k, m in enumerate(subset_masks(5)):
        assert many[k] == lower_bound_table(s, o, 0.7)[k]
        assert abs(many[k] - omega(tuple(np.flatnonzero(m)))) < 1e-9


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: lower_bound_table(SENSORS, TARGET, -1.0), "u_max"),
        (lambda: lower_bound_table(SENSORS, SENSORS[0], 1.0), "coincides with target"),
        (lambda: lower_bound_tables([[[np.nan, 0.0]]], 1.0), "vectors has a non-finite"),
        (lambda: lower_bound_tables([[0.0, 1.0]], 1.0), "vectors must have shape"),
        (
            lambda: lower_bound_tables(np.ones((2, 3, 2)), [1.0, 2.0, 3.0]),
            "u_max must be a scalar or of shape \\(2,\\)",
        ),
    ],
)
def test_bad_input_raises(call, match):
    with pytest.raises(ValueError, match=match):
        call()
