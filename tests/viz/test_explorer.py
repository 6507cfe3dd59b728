"""The bound explorer as a still figure (obslib.viz.explorer): its map of the bound with one
more sensor is Theorem 1's bound evaluated point by point, its marks are where the explorer puts
them, and its text is clean at the book's sizes."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

import obslib as ob  # noqa: E402
from obslib.viz import explorer  # noqa: E402

#: The explorer's first state in the book (the pair closed-form chapter).
START = {"sensors": [[-2.5, -1.5], [2.0, -2.0]], "target": [0.5, 1.0], "control": [0.6, 0.3],
         "u_max": 1.0}


def test_the_map_is_the_bound_with_one_more_sensor_point_by_point():
    # batched SVD of every scene at once against lower_bound called at each point
    rng = np.random.default_rng(3)
    sensors, target = rng.uniform(-4, 4, (3, 2)), rng.uniform(-1, 1, 2)
    xs, ys = np.linspace(-5, 5, 9), np.linspace(-4, 4, 7)
    got = explorer.candidate_bounds(sensors, target, 0.7, xs, ys)
    want = [[ob.lower_bound(np.vstack([sensors, [x, y]]), target, 0.7) for x in xs] for y in ys]
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-15)


def test_a_point_on_the_target_adds_nothing():
    got = explorer.candidate_bounds([[-1, 0], [0, 2]], [0, 0], 1.0, [0.0], [0.0])
    assert got[0, 0] == pytest.approx(ob.lower_bound([[-1, 0], [0, 2]], [0, 0], 1.0))


def test_the_still_shows_the_state_and_its_best_point():
    from obsbook import figures

    fig = explorer.plot_explorer_view(**START, grid=41)
    ax = fig.axes[0]
    bound = ob.lower_bound(START["sensors"], START["target"], START["u_max"])
    exact = ob.inverse_condition_number(START["sensors"], START["target"], START["control"])
    assert ax.get_title() == f"Theorem 1 bound {bound:.3f}, exact value for the arrow {exact:.3f}"
    # the star sits on the grid's largest bound with one more sensor
    half = ax.get_xlim()[1]
    xs = np.linspace(-half, half, 41)
    heat = explorer.candidate_bounds(START["sensors"], START["target"], 1.0, xs, xs)
    k, m = np.unravel_index(np.argmax(heat), heat.shape)
    (star,) = [line for line in ax.get_lines() if line.get_label().startswith("best place")]
    assert star.get_xydata().tolist() == [[xs[m], xs[k]]]
    # the view holds every point and the disc of controls, as the explorer's does
    assert half >= 5 and all(abs(v) < half for p in START["sensors"] for v in p)
    _, d = figures.render(fig)
    assert figures.problems(d) == [] and d["size"][0] <= 750
    plt.close(fig)


@pytest.mark.parametrize("change, message", [
    ({"control": [2.0, 0.0]}, "control"),
    ({"grid": 1}, "grid"),
    ({"grid": 5000}, "grid"),
    ({"u_max": -1.0}, "u_max"),
    ({"sensors": [[0.5, 1.0]]}, "sensor"),
])
def test_bad_states_are_refused_by_name(change, message):
    with pytest.raises(ValueError, match=message):
        explorer.plot_explorer_view(**{**START, **change})
    plt.close("all")


def test_bad_grids_are_refused_by_name():
    with pytest.raises(ValueError, match="xs"):
        explorer.candidate_bounds([[0, 0]], [1, 1], 1.0, [], [0.0])
    with pytest.raises(ValueError, match="ys"):
        explorer.candidate_bounds([[0, 0]], [1, 1], 1.0, [0.0], [[0.0, np.nan]])
