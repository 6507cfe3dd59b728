"""What the notebooks share (obslib.notebook): figure settings, small-number printing."""

import matplotlib

matplotlib.use("agg")

import matplotlib as mpl  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from obslib.notebook import format_small, setup_figures  # noqa: E402


def _title_box(titley, projection=None, top_ticks=False):
    """The drawn title's bounding box (pixels) with ``axes.titley = titley``."""
    with mpl.rc_context({"axes.titley": titley}):
        fig = Figure(figsize=(4, 3), dpi=100)
        FigureCanvasAgg(fig)
        ax = fig.add_subplot(projection=projection)
        if projection is None:
            ax.plot([0.0, 1.0], [0.0, 1.0])
            if top_ticks:
                ax.xaxis.tick_top()
        ax.set_title("a title")
        fig.canvas.draw()
        return np.array(ax.title.get_window_extent().bounds)


def test_setup_figures_fixes_the_title_height():
    with mpl.rc_context():
        setup_figures()
        assert mpl.rcParams["axes.titley"] == 1.0


def test_setup_figures_freezes_the_objects_alive_for_the_collector():
    import gc

    before = len(gc.get_objects())  # tracked objects, excluding frozen ones
    try:
        with mpl.rc_context():
            setup_figures()
        assert gc.get_freeze_count() >= before
        assert len(gc.get_objects()) < before
    finally:
        gc.unfreeze()


def test_fixed_title_height_is_where_matplotlib_puts_2d_titles():
    # the book's 2-D axes have no top tick labels and no offset text: same position
    np.testing.assert_array_equal(_title_box(1.0), _title_box(None))


def test_the_fixed_height_differs_where_the_docstring_says_it_does():
    # tick labels on top lift an automatic title over them, not a fixed one
    assert _title_box(None, top_ticks=True)[1] > _title_box(1.0, top_ticks=True)[1]
    # and 3-D axes place their titles differently, hence pair_form's rc_context for them
    assert _title_box(None, projection="3d")[1] != _title_box(1.0, projection="3d")[1]


def test_format_small():
    assert format_small(3e-17) == "< 1e-12"
    assert format_small(0.123456) == "0.123"
    assert format_small(2e-9, 1e-10) == "2e-09"
