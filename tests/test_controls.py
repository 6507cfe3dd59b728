"""The disc of controls (obslib.controls)."""

import numpy as np
import pytest

from obslib.controls import disc_controls, disc_mesh


def test_disc_mesh_closes_the_polar_grid():
    controls = disc_controls(2.0, 3, 8)
    vals = np.arange(len(controls), dtype=float)
    X, Y, Z = disc_mesh(controls, vals, 3, 8)
    assert X.shape == Y.shape == Z.shape == (4, 9)
    assert (X[0] == 0).all() and (Z[0] == 0).all()
    assert np.array_equal(Z[:, -1], Z[:, 0]) and np.array_equal(X[:, -1], X[:, 0])
    np.testing.assert_allclose(np.hypot(X[-1], Y[-1]), 2.0)
    assert Z[1, 0] == 1 and Z[3, 7] == len(controls) - 1
    with pytest.raises(ValueError, match="controls"):
        disc_mesh(controls[1:], vals[1:], 3, 8)


@pytest.mark.parametrize("args, message", [
    ((-1.0, 3, 8), "u_max must be finite and non-negative"),
    ((np.inf, 3, 8), "u_max must be finite"),
    (("1", 3, 8), "u_max must be numeric"),
    ((1.0, 0, 8), "n_radii must be at least 1, got 0"),
    ((1.0, 2.5, 8), "n_radii must be an integer, got 2.5"),
    ((1.0, 3.0, 8), "n_radii must be an integer, got 3.0"),
    ((1.0, 3, True), "n_angles must be an integer, got True"),
])
def test_bad_scalar_arguments_are_named(args, message):
    with pytest.raises(ValueError, match=message):
        disc_controls(*args)


def test_counts_are_integers_of_any_integer_type():
    assert np.array_equal(disc_controls(1.0, np.int64(3), np.int32(8)), disc_controls(1.0, 3, 8))
