"""The chapters' helpers, one module per notebook, named after it without its number (as Labbe
keeps ``kf_book/`` beside his notebooks): what a chapter's hidden cells call to glue its numbers
and tables into the prose. The chapters' figures are drawn by :mod:`obslib.viz`, one module per
chapter; what several chapters share is in :mod:`obsbook.prose`, :mod:`obsbook.glue` and
:mod:`obsbook.tables`.

A notebook imports its module, ``from obsbook.chapters import model_and_bound as chapter``, and
its hidden cells are calls such as ``chapter.glue_theorem1(a1, n_controls)``: no function is
defined in a notebook.
"""
