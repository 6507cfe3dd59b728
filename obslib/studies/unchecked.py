"""Statements of the paper that it does not check itself, and the parameters of their notebook.

The computations live in one module per topic (:mod:`obslib.studies.replay`,
:mod:`obslib.studies.greedy_tightness`, :mod:`obslib.studies.eq4`,
:mod:`obslib.studies.hardness`, :mod:`obslib.studies.fig9_measure`,
:mod:`obslib.studies.experiment_details`); this module holds the parameters of the notebook
that shows them (``11_unchecked_statements``), whose parameters :func:`obslib.profiles.params`
reads.
"""

from __future__ import annotations

__all__ = ["NOTEBOOK"]

NOTEBOOK = "11_unchecked_statements"
