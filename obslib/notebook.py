"""What the book's notebooks share: how figures are drawn inline, how small numbers print.

Every notebook calls :func:`setup_figures` in its import cell, so the nine notebooks draw their
figures the same way and each figure is drawn once. :func:`format_small` prints a
rounding-level number as a bound, so stored outputs are the same on every machine.
"""

from __future__ import annotations

from ._format import format_small

__all__ = ["format_small", "setup_figures"]


def setup_figures() -> None:
    """Inline figures as PNG, each drawn once, with titles at a fixed height.

    - PNG only, with ``bbox_inches=None``: every figure sets its own layout with
      ``fig.subplots_adjust`` (margins found once with ``tight_layout``), whereas the inline
      backend's default ``bbox_inches="tight"`` draws each figure a second time to measure it.
    - ``axes.titley = 1.0``: a title sits just above its axes. Matplotlib's default (``None``)
      lifts it over tick labels on the top of the axes, which costs measuring every tick label
      of the axes at each draw (about 15 % of the book's drawing time). No 2-D axes of the book
      has top tick labels, so their titles land where the default puts them (the stored
      figures are byte-identical either way; ``tests/test_notebook.py``). 3-D axes are placed
      differently and keep the default (:func:`obslib.pair_form.plot_fig2`); a new figure with
      top tick labels must set its title's height itself.
    """
    import matplotlib as mpl
    from matplotlib_inline.backend_inline import set_matplotlib_formats

    set_matplotlib_formats("png", bbox_inches=None)
    mpl.rcParams["axes.titley"] = 1.0
