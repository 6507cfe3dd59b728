"""The figures of the pair closed form (obslib.viz.pair_form) draw, and reject bad options."""

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from obslib.pair_form import bound_surface, fine_grid, grid_maximum  # noqa: E402
from obslib.viz import pair_form as pf  # noqa: E402


def test_figures_draw():
    ax = pf.plot_fig1()
    assert ax.get_aspect() == 1.0
    a, t = fine_grid(5.0, 10, 8)
    Z = bound_surface(a, t)
    fig = pf.plot_fig2(a, t, Z, [0.1, 0.3, 0.5, 0.7], "test", mark=grid_maximum(a, t, Z))
    assert len(fig.axes) == 4
    fig = pf.plot_fig2(a, t, Z, [0.1, 0.3], mark=grid_maximum(a, t, Z), panels="contour")
    assert len(fig.axes) == 2 and all(ax.name == "rectilinear" for ax in fig.axes)
    plt.close("all")
    with pytest.raises(ValueError, match="panels"):
        pf.plot_fig2(a, t, Z, [0.1], panels="surface")
    with pytest.raises(ValueError, match="d_io"):
        pf.plot_fig1(d_io=0.0)
