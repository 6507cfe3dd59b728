"""Tables for the book's pages: cells formatted as text, Markdown tables of rows, and numbered
MyST tables with their caption above.

The book numbers every table and puts its caption above it. :func:`numbered_table` writes a MyST
``{list-table}`` with the caption as its title and a ``:name:`` to refer to it; a notebook glues
it (:func:`obsbook.glue_text`) and places it with ``{glue:md}`` and ``:format: myst``, which is
what makes the directive a numbered table (a plain Markdown output is not parsed as MyST).
"""

from __future__ import annotations

import re

__all__ = ["formatted_table", "markdown_table", "numbered_table", "rows_table"]


def formatted_table(table, fmt: str = "{:.3f}", formats=None, na: str = "\u2013"):
    """``table`` (a DataFrame) with every cell formatted as text: ``fmt`` by default,
    ``formats[column]`` for the columns given, ``na`` for missing values.

    Its HTML and text outputs are the same at every run (a pandas ``Styler`` would store its
    memory address).

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


def _cells(row: dict, columns: dict) -> list[str]:
    cells = []
    for key, fmt in columns.values():
        if callable(fmt):
            cells.append(fmt(row))
        else:
            v = row.get(key)
            cells.append("" if v is None else format(v, fmt))
    return cells


def markdown_table(rows: list, columns: dict) -> str:
    """A Markdown table of ``rows`` (dicts): ``columns`` maps a header to ``(key, format)``,
    ``format`` a format spec (``".3f"``) or a callable of the row.

    Examples
    --------
    >>> rows = [{"s": "a", "v": 1.2345}, {"s": "b"}]
    >>> cols = {"name": ("s", "s"), "value": ("v", ".2f"),
    ...         "upper": (None, lambda r: r["s"].upper())}
    >>> print(markdown_table(rows, cols))
    | name | value | upper |
    |---|---|---|
    | a | 1.23 | A |
    | b |  | B |
    """
    head = "| " + " | ".join(columns) + " |"
    sep = "|" + "|".join("---" for _ in columns) + "|"
    return "\n".join([head, sep] + ["| " + " | ".join(_cells(r, columns)) + " |" for r in rows])


_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_-]*")


def numbered_table(table, caption: str, name: str, *, columns: dict | None = None,
                   index: bool | None = None, widths: str = "auto") -> str:
    """A numbered MyST table, caption above: a ``{list-table}`` directive.

    Parameters
    ----------
    table : pandas.DataFrame or list of dict
        A DataFrame's cells as they are (format them first, :func:`formatted_table`); rows
        (dicts) are formatted by ``columns`` as in :func:`markdown_table`.
    caption : str
        The caption (MyST, one line), shown above the table with its number.
    name : str
        Label of the table, for ``{numref}`` references (letters, digits, ``-``, ``_``).
    columns : dict, optional
        For rows: header -> ``(key, format)``. Not used with a DataFrame.
    index : bool, optional
        Whether a DataFrame's index is the first column, headed by the index's name; by
        default it is unless it is the plain ``0, 1, ...``. There is never an extra header
        row for the index's name.
    widths : str
        The directive's ``:widths:``.

    Examples
    --------
    >>> import pandas as pd
    >>> t = pd.DataFrame({"N": [10, 20], "time (s)": ["0.12", "0.50"]})
    >>> print(numbered_table(t, "Time per size.", "tab-time"))
    ```{list-table} Time per size.
    :header-rows: 1
    :name: tab-time
    :widths: auto
    <BLANKLINE>
    * - N
      - time (s)
    * - 10
      - 0.12
    * - 20
      - 0.50
    ```
    """
    if not isinstance(caption, str) or not caption.strip() or "\n" in caption:
        raise ValueError("caption must be one line of text")
    if not isinstance(name, str) or not _NAME.fullmatch(name):
        raise ValueError(f"name must be a label of letters, digits, '-' and '_', got {name!r}")
    if isinstance(table, list):
        if not columns:
            raise ValueError("rows need columns: header -> (key, format)")
        header = list(columns)
        body = [_cells(r, columns) for r in table]
    else:
        if columns is not None:
            raise ValueError("columns apply to rows (a list of dict), not to a DataFrame")
        import pandas as pd

        if index is None:
            index = not (isinstance(table.index, pd.RangeIndex) and table.index.start == 0
                         and table.index.step == 1)
        header = ([str(table.index.name or "")] if index else []) + [str(c) for c in table.columns]
        body = [([str(i)] if index else []) + [str(v) for v in row]
                for i, row in zip(table.index, table.itertuples(index=False))]
    lines = [f"```{{list-table}} {caption.strip()}", ":header-rows: 1", f":name: {name}",
             f":widths: {widths}", ""]
    for row in [header, *body]:
        if len(row) != len(header):
            raise ValueError(f"a row has {len(row)} cells, the header {len(header)}")
        lines += [("* - " if k == 0 else "  - ") + " ".join(str(c).split()) for k, c in
                  enumerate(row)]
    return "\n".join(lines + ["```"])


def rows_table(rows, caption: str, name: str, headers=("quantity", "value")) -> str:
    """A numbered MyST table (:func:`numbered_table`) of ``rows``, tuples of cells already
    formatted as text, one cell per header.

    Parameters
    ----------
    rows : list of tuple of str
        The rows, each with one cell per header.
    caption, name : str
        As in :func:`numbered_table`.
    headers : tuple of str
        The column headers; by default a two-column table of quantities and their values.

    Examples
    --------
    >>> print(rows_table([("largest error", "0.12")], "Errors.", "tab-err"))
    ```{list-table} Errors.
    :header-rows: 1
    :name: tab-err
    :widths: auto
    <BLANKLINE>
    * - quantity
      - value
    * - largest error
      - 0.12
    ```
    """
    keys = [f"c{k}" for k in range(len(headers))]
    for row in rows:
        if len(row) != len(headers):
            raise ValueError(f"a row has {len(row)} cells, the headers {len(headers)}")
    return numbered_table([dict(zip(keys, row)) for row in rows], caption, name,
                          columns={h: (k, "s") for h, k in zip(headers, keys)})
