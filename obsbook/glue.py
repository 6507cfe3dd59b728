"""Numbers glued into the prose as the book prints them, for ``{glue:md}`` and ``{glue:text}``.

A number is formatted once, by :func:`obslib.formatting.number` (or its siblings :func:`count`,
:func:`percent`, ...), and glued as that text: the page never rounds it again, and the text is
the same on every machine. The glued object carries two forms: MyST (``$...$`` math for powers
of ten) for ``{glue:md}`name:myst``` (the ``:myst`` makes its math render; without it the
text is read as CommonMark) and plain text (``1.23×10⁻⁵``) for ``{glue:text}`name```, shown
without the quotes a glued ``str`` would get.
"""

from __future__ import annotations

from obslib.formatting import number

__all__ = ["Formatted", "glue_text", "glue_texts", "glue_number"]


class Formatted:
    """Formatted text to glue: ``markdown`` for ``{glue:md}``, ``plain`` (default: the same)
    for ``{glue:text}``.

    Examples
    --------
    >>> f = Formatted("$10^{-5}$", "10⁻⁵")
    >>> f, f._repr_markdown_()
    (10⁻⁵, '$10^{-5}$')
    """

    def __init__(self, markdown: str, plain: str | None = None):
        if not isinstance(markdown, str) or (plain is not None and not isinstance(plain, str)):
            raise ValueError("glued text must be a str (format the number first)")
        self.markdown = markdown
        self.plain = markdown if plain is None else plain

    def __repr__(self) -> str:
        return self.plain

    def _repr_markdown_(self) -> str:
        return self.markdown


def glue_text(name: str, text: str, plain: str | None = None) -> Formatted:
    """Glue ``text``, already formatted (``number(x)``, ``count(n)``, ... of
    :mod:`obslib.formatting`), as ``name``, not displayed in the cell; ``plain`` is the form
    ``{glue:text}`` shows (by default ``text`` itself, so give it when ``text`` holds math).
    Returns the glued object.

    Examples
    --------
    In a notebook: ``glue_text("n_trials", count(20000))``, then ``{glue:md}`n_trials:myst```
    in the prose. Outside a notebook the object is made all the same:

    >>> from obslib.formatting import count
    >>> glue_text("n_trials", count(20000))
    20,000
    """
    from myst_nb import glue

    if not isinstance(name, str) or not name.isidentifier():
        raise ValueError(f"name must be an identifier, got {name!r}")
    value = Formatted(text, plain)
    glue(name, value, display=False)
    return value


def glue_texts(**texts: str) -> dict:
    """Glue each formatted text under its name (:func:`glue_text`), in the order given.

    Parameters
    ----------
    **texts : str
        Name -> text, already formatted (``number(x)``, ``count(n)``, a sentence, a table).

    Returns
    -------
    dict
        Name -> the glued :class:`Formatted` object.

    Examples
    --------
    >>> from obslib.formatting import count, number
    >>> glued = glue_texts(n_runs=count(200), ratio=number(0.48488))
    >>> list(glued), glued["ratio"]
    (['n_runs', 'ratio'], 0.485)
    """
    return {name: glue_text(name, text) for name, text in texts.items()}


def glue_number(name: str, x, sig: int = 3) -> Formatted:
    """Glue the number ``x`` under ``name`` as the book prints it
    (:func:`obslib.formatting.number` with ``sig`` significant digits): MyST for ``{glue:md}``,
    plain for ``{glue:text}``.

    Examples
    --------
    >>> glue_number("ratio", 0.48488), glue_number("tiny", 1.234e-5)._repr_markdown_()
    (0.485, '$1.23 \\\\times 10^{-5}$')
    """
    return glue_text(name, number(x, sig), number(x, sig, math=False))
