import numpy as np
import pytest

import obslib as ob


def test_matrix_rows_are_target_minus_sensor_then_u():
    s = np.array([[0.0, 0.0], [3.0, 1.0]])
    o = np.array([1.0, 2.0])
    assert np.array_equal(ob.observability_matrix(s, o), [[1.0, 2.0], [-2.0, 1.0]])
    O = ob.observability_matrix(s, o, u=[0.5, -0.5])
    assert O.shape == (3, 2) and np.array_equal(O[-1], [0.5, -0.5])


def test_inverse_condition_number_matches_eigenvalues_of_gram():
    rng = np.random.default_rng(3)
    for _ in range(200):
        s = rng.uniform(-5, 5, size=(rng.integers(1, 6), 2))
        o = rng.uniform(-5, 5, size=2)
        u = rng.uniform(-2, 2, size=2)
        O = np.vstack([o - s, u])
        lam = np.linalg.eigvalsh(O.T @ O)
        expected = np.sqrt(max(lam[0], 0.0) / lam[1])
        # eigvalsh knows lambda_min only to eps * lambda_max, so compare squares
        assert ob.inverse_condition_number(s, o, u) ** 2 == pytest.approx(expected**2, abs=1e-12)


def test_batch_of_controls_equals_one_at_a_time():
    s = np.array([[0.0, 0.0], [3.0, 1.0], [1.0, 4.0]])
    o = np.array([1.0, 2.0])
    controls = np.random.default_rng(0).normal(size=(50, 2))
    batch = ob.inverse_condition_number(s, o, controls)
    single = [ob.inverse_condition_number(s, o, u) for u in controls]
    assert batch.shape == (50,)
    np.testing.assert_allclose(batch, single, rtol=0, atol=1e-15)


def test_single_sensor_without_control_has_rank_one():
    assert ob.inverse_condition_number([[1.0, 1.0]], [0.0, 0.0]) == 0.0


def test_control_perpendicular_and_equal_length_is_perfectly_conditioned():
    # one sensor at distance 2 along x, control of norm 2 along y: O = [[-2, 0], [0, 2]]
    assert ob.inverse_condition_number([[2.0, 0.0]], [0.0, 0.0], [0.0, 2.0]) == pytest.approx(1.0)


@pytest.mark.parametrize("m", [2, 3, 5, 8, 9, 12])
def test_closed_form_inverse_condition_equals_svd(m):
    """The Cauchy-Binet closed form (m <= 8 rows) and the SVD path agree with numpy's SVD."""
    # the kernel itself: the public functions take sensors and a target, not a stack of matrices
    from obslib._kernels import inverse_condition

    rng = np.random.default_rng(m)
    stack = rng.normal(size=(500, m, 2)) * 10.0 ** rng.uniform(-3, 4, size=(500, 1, 1))
    stack[:50, :, 1] = 3.0 * stack[:50, :, 0]  # parallel rows: rank one
    stack[50:100, 1:, :] = stack[50:100, :1, :] * rng.uniform(
        0.5, 2, size=(50, m - 1, 1)
    )  # collinear
    stack[50:100, 1:, 1] += 1e-9 * stack[50:100, 1:, 0]  # ... nearly
    sv = np.linalg.svd(stack, compute_uv=False)
    np.testing.assert_allclose(
        inverse_condition(stack), sv[:, -1] / sv[:, 0], rtol=1e-7, atol=1e-14
    )


# --------------------------------------------------------------------------- batched forms


def test_batched_inverse_condition_numbers_equal_the_per_scene_function():
    """Padded stacks of scenes of every kind (2-6 sensors, scales 1e-3..1e4), control by control."""
    from obslib.observability import inverse_condition_numbers
    from obslib.scenes import random_scene_batch

    batch = random_scene_batch(400, 3)
    rng = np.random.default_rng(4)
    controls = rng.normal(size=(400, 9, 2)) * batch.u_max[:, None, None]
    many = inverse_condition_numbers(batch.rows, controls)
    one = inverse_condition_numbers(batch.rows, controls[:, 0])
    still = inverse_condition_numbers(batch.rows)
    assert many.shape == (400, 9) and one.shape == (400,) and still.shape == (400,)
    for k in range(400):
        sc = batch.scene(k)
        want = ob.inverse_condition_number(sc.sensors, sc.target, controls[k])
        np.testing.assert_allclose(many[k], want, rtol=1e-12, atol=1e-15)
        assert one[k] == pytest.approx(want[0], rel=1e-12, abs=1e-15)
        assert still[k] == pytest.approx(ob.inverse_condition_number(sc.sensors, sc.target),
                                         rel=1e-12, abs=1e-15)


def test_batched_polar_grid_equals_the_per_scene_function():
    from obslib.controls import disc_controls
    from obslib.observability import inverse_condition_numbers_polar
    from obslib.scenes import random_scene_batch

    batch = random_scene_batch(200, 5, kinds=("generic", "spread", "near-parallel"))
    n_radii, n_angles = 5, 16
    radii = batch.u_max[:, None] * np.arange(1, n_radii + 1)[None, :] / n_radii
    grid = inverse_condition_numbers_polar(
        batch.rows, radii, 2 * np.pi * np.arange(n_angles) / n_angles
    )
    assert grid.shape == (200, n_radii, n_angles)
    for k in range(200):
        sc = batch.scene(k)
        want = ob.inverse_condition_number(
            sc.sensors, sc.target, disc_controls(sc.u_max, n_radii, n_angles)
        )
        np.testing.assert_allclose(grid[k].ravel(), want[1:], rtol=1e-11, atol=1e-15)


def test_batched_forms_reject_bad_input():
    from obslib.observability import inverse_condition_numbers, inverse_condition_numbers_polar

    with pytest.raises(ValueError, match="rows"):
        inverse_condition_numbers(np.ones((3, 2, 3)))
    with pytest.raises(ValueError, match="non-finite"):
        inverse_condition_numbers([[[np.nan, 1.0], [1.0, 2.0]]])
    with pytest.raises(ValueError, match="u"):
        inverse_condition_numbers(np.ones((3, 2, 2)), np.full((3, 2), np.inf))
    with pytest.raises(ValueError, match="radii"):
        inverse_condition_numbers_polar(np.ones((3, 2, 2)), -np.ones((3, 2)), np.zeros(4))


def test_batched_form_on_one_scene_and_on_padding_only():
    from obslib.observability import inverse_condition_numbers

    s, o, u = np.array([[0.0, 0.0], [3.0, 1.0], [1.0, 4.0]]), np.array([1.0, 2.0]), [0.5, -0.2]
    rows = o - s
    assert inverse_condition_numbers(rows) == pytest.approx(
        ob.inverse_condition_number(s, o), rel=1e-14
    )
    assert inverse_condition_numbers(rows, u) == pytest.approx(
        ob.inverse_condition_number(s, o, u), rel=1e-14
    )
    padded = np.vstack([rows, np.zeros((3, 2))])
    assert inverse_condition_numbers(padded, u) == pytest.approx(
        ob.inverse_condition_number(s, o, u), rel=1e-14
    )
    assert inverse_condition_numbers(np.zeros((4, 3, 2))).tolist() == [0.0] * 4  # empty scenes
