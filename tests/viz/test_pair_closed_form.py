"""The figures of the pair closed form (obslib.viz.pair_closed_form): they draw, reject bad options,
and keep their labels clear of each other and of the marked maxima."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from obslib.pair_form import bound_surface, fine_grid, grid_maximum  # noqa: E402
from obslib.viz import pair_closed_form  # noqa: E402


def test_figures_draw():
    ax = pair_closed_form.plot_fig1()
    assert ax.get_aspect() == 1.0
    a, t = fine_grid(5.0, 10, 8)
    Z = bound_surface(a, t)
    fig = pair_closed_form.plot_fig2(a, t, Z, [0.1, 0.3, 0.5, 0.7], "test",
                                     mark=grid_maximum(a, t, Z))
    assert len(fig.axes) == 4
    fig = pair_closed_form.plot_fig2(a, t, Z, [0.1, 0.3], mark=grid_maximum(a, t, Z),
                                     panels="contour")
    assert len(fig.axes) == 2 and all(ax.name == "rectilinear" for ax in fig.axes)
    plt.close("all")
    with pytest.raises(ValueError, match="panels"):
        pair_closed_form.plot_fig2(a, t, Z, [0.1], panels="surface")
    with pytest.raises(ValueError, match="d_io"):
        pair_closed_form.plot_fig1(d_io=0.0)


def test_ray_hits_are_the_radii_of_concentric_circles():
    x = np.linspace(-3, 3, 601)
    X, Y = np.meshgrid(x, x)
    fig = plt.figure()
    cs = fig.add_subplot().contour(X, Y, np.hypot(X, Y), levels=[0.5, 1.0, 2.0, 4.0])
    hits = pair_closed_form._ray_hits(cs, np.zeros(2), np.array([np.cos(0.3), np.sin(0.3)]))
    np.testing.assert_allclose(hits[:3], [0.5, 1.0, 2.0], atol=2e-3)  # the grid's step: 0.01
    assert hits[3] is None  # radius 4 is outside the grid
    plt.close(fig)


@pytest.mark.parametrize("panels", ["all", "contour"])
def test_fig2_text_is_clear_of_other_text_and_of_the_maxima(panels):
    from obsbook import figures

    a, t = fine_grid(5.0, 40, 90)
    Z = bound_surface(a, t)
    mark = grid_maximum(a, t, Z)
    fig = pair_closed_form.plot_fig2(a, t, Z, [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7], mark=mark,
                                     panels=panels)
    _, d = figures.render(fig)
    assert figures.problems(d) == [] and d["size"][0] <= 750
    # no contour label within 4 px of a star (12 pt across: 8.3 px from its centre to its tips)
    height = d["size"][1]
    renderer = fig.canvas.get_renderer()  # at the figure's dpi: the image was drawn at twice it
    for ax in fig.axes:
        if ax.name != "rectilinear":
            continue
        star = ax.get_lines()[-1]
        centres = ax.transData.transform(star.get_xydata())
        for text in ax.texts:
            b = text.get_window_extent(renderer)
            for x, y in centres:
                dx = max(b.x0 - x, 0, x - b.x1)
                dy = max(b.y0 - y, 0, y - b.y1)
                assert np.hypot(dx, dy) > 8.3 + 4, f"{text.get_text()} at {x, height - y}"
    plt.close(fig)
