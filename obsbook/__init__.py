"""obsbook: what only the book needs, kept beside it (as Labbe keeps ``kf_book/`` beside his
notebooks): figure setup, glue and table helpers for the notebooks, each chapter's helpers, and
the rendering of the reproduction report. It calls :mod:`obslib`; :mod:`obslib` never imports it.

Numbers read the same everywhere because every page formats them with the library's one formatter,
:mod:`obslib.formatting`, and glues them as formatted text (:func:`glue_number`,
:func:`glue_text`, :func:`glue_texts`). A notebook calls :func:`setup` in its import cell:
figures at most 7.5 in wide, text at least 10 pt, constrained layout (:mod:`obsbook.figures`).
Tables are numbered, caption above (:func:`numbered_table`, :func:`rows_table`). The prose names
sensors, pairs, sets and points one way (:mod:`obsbook.prose`). Each chapter's glue and tables
are in its module of :mod:`obsbook.chapters`, named after its notebook; its figures are drawn by
:mod:`obslib.viz`.
"""

from .figures import setup
from .glue import glue_number, glue_text, glue_texts
from .tables import formatted_table, markdown_table, numbered_table, rows_table

__all__ = ["setup", "glue_number", "glue_text", "glue_texts", "formatted_table", "markdown_table",
           "numbered_table", "rows_table"]
