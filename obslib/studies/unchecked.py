"""Statements of the paper that it does not check itself, and the parameters of their notebook.

The computations live in one module per topic (:mod:`obslib.studies.replay`,
:mod:`obslib.studies.greedy_tightness`, :mod:`obslib.studies.eq4`,
:mod:`obslib.studies.hardness`, :mod:`obslib.studies.fig9_measure`,
:mod:`obslib.studies.experiment_details`); this module holds the parameters of the notebook
that shows them (``11_unchecked_statements``) under each profile.
"""

from __future__ import annotations

__all__ = ["NOTEBOOK", "notebook_params"]

NOTEBOOK = "11_unchecked_statements"

def notebook_params(profile: str = "paper") -> dict:
    """Parameters of the notebook under ``profile`` (:func:`obslib.profiles.params`).

    Examples
    --------
    >>> from obslib.profiles import params
    >>> from obslib.studies.unchecked import NOTEBOOK, notebook_params
    >>> notebook_params("quick") == params(NOTEBOOK, "quick")
    True
    """
    from ..profiles import params

    return params(NOTEBOOK, profile)
