"""obsbook: what only the book needs, kept beside it (as Labbe keeps ``kf_book/`` beside his
notebooks): figure setup, glue and table helpers for the notebooks, and the rendering of the
reproduction report. It calls :mod:`obslib`; :mod:`obslib` never imports it.

Numbers read the same everywhere because every page formats them with the library's one formatter,
re-exported here (:func:`number`, :func:`count`, :func:`small`, :func:`percent`, :func:`span`,
:func:`setting`, :func:`listing`).
"""

from obslib._format import count, listing, number, percent, setting, small, span

__all__ = ["number", "count", "small", "percent", "span", "setting", "listing"]
