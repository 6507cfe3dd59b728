"""What the book's notebooks share: how figures are drawn inline, how numbers print.

Superseded by the book's own helpers, ``obsbook`` (``obsbook.setup``,
``obsbook.formatted_table``): kept for the notebooks not yet moved there.

Every notebook calls :func:`setup_figures` in its import cell, so the nine notebooks draw their
figures the same way and each figure is drawn once. :func:`format_small` prints a
rounding-level number as a bound, so stored outputs are the same on every machine.
:func:`formatted_table` gives a table whose cells are already formatted text, so its HTML and
text outputs are the same at every run (a pandas ``Styler`` would store its memory address).
"""

from __future__ import annotations

from ._format import format_small

__all__ = ["format_small", "formatted_table", "setup_figures"]


def setup_figures() -> None:
    """Inline figures as PNG, each drawn once, with titles at a fixed height; the objects
    imported so far frozen for the garbage collector.

    - PNG only, with ``bbox_inches=None``: every figure sets its own layout with
      ``fig.subplots_adjust`` (margins found once with ``tight_layout``), whereas the inline
      backend's default ``bbox_inches="tight"`` draws each figure a second time to measure it.
    - ``axes.titley = 1.0``: a title sits just above its axes. Matplotlib's default (``None``)
      lifts it over tick labels on the top of the axes, which costs measuring every tick label
      of the axes at each draw (about 15 % of the book's drawing time). No 2-D axes of the book
      has top tick labels, so their titles land where the default puts them (the stored
      figures are byte-identical either way; ``tests/test_notebook.py``). 3-D axes are placed
      differently and keep the default (:func:`obslib.viz.pair_form.plot_fig2`); a new figure with
      top tick labels must set its title's height itself.
    - The objects imported so far (the modules and their tables, alive as long as the kernel)
      are moved to the garbage collector's permanent generation (``gc.freeze()``). Python's
      automatic full collections walk every tracked object: after importing SymPy, pandas and
      matplotlib each took about 70 ms, and notebook 02 triggers several (0.44 s of full
      collections against 0.14 s frozen). Nothing is computed differently; garbage made later
      is collected as before.
    """
    import gc

    import matplotlib as mpl
    from matplotlib_inline.backend_inline import set_matplotlib_formats

    set_matplotlib_formats("png", bbox_inches=None)
    mpl.rcParams["axes.titley"] = 1.0
    gc.freeze()


def formatted_table(table, fmt: str = "{:.3f}", formats=None, na: str = "\u2013"):
    """``table`` (a DataFrame) with every cell formatted as text: ``fmt`` by default,
    ``formats[column]`` for the columns given, ``na`` for missing values.

    Examples
    --------
    >>> import numpy as np, pandas as pd
    >>> t = pd.DataFrame({"n": [1000.0, np.nan], "r": [0.5, 0.25]})
    >>> formatted_table(t, formats={"n": "{:,.0f}"}).to_dict("list")
    {'n': ['1,000', '–'], 'r': ['0.500', '0.250']}
    """
    formats = dict(formats or {})
    unknown = set(formats) - set(table.columns)
    if unknown:
        raise ValueError(f"formats name columns the table does not have: {sorted(unknown)}")
    out = table.astype(object).copy()
    for col in table.columns:
        f = formats.get(col, fmt)
        out[col] = [na if v is None or (isinstance(v, float) and v != v) else f.format(v)
                    for v in table[col]]
    return out
