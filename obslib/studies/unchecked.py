"""Statements of the paper that it does not check itself, and the parameters of their notebook.

The computations live in one module per topic (:mod:`obslib.studies.replay`,
:mod:`obslib.studies.greedy_tightness`, :mod:`obslib.studies.eq4`,
:mod:`obslib.studies.hardness`, :mod:`obslib.studies.fig9_measure`,
:mod:`obslib.studies.experiment_details`); this module holds the parameters of the notebook
that shows them (``11_unchecked_statements``) under each profile.
"""

from __future__ import annotations

import copy

__all__ = ["NOTEBOOK", "DEFAULTS", "QUICK", "notebook_params"]

NOTEBOOK = "11_unchecked_statements"

#: The notebook's defaults (its tagged ``parameters`` cell) ...
DEFAULTS = {
    "seed": 0,
    "n_seeds_typical": 1000,
    "jitter_fractions": [1e-06, 1e-05, 0.0001, 0.001, 0.01, 0.1],
    "n_jitter": 200,
    "n_geometries": 2000,
    "n_refine": 200,
    "u_max": 1.0,
    "n_3dm": 40,
    "solver_L": [5, 10, 15, 20],
    "time_budget": 60.0,
    "problem3_L": [2, 5, 10, 20],
    "problem3_trials": 30,
    "n_seeds_disc": 100,
    "n_radii": 10,
    "n_angles": 180,
}

#: ... and what the ``quick`` profile changes.
QUICK = {
    "n_seeds_typical": 100,
    "n_jitter": 20,
    "n_geometries": 200,
    "n_refine": 40,
    "n_3dm": 10,
    "solver_L": [3, 6],
    "time_budget": 2.0,
    "problem3_L": [2, 5],
    "problem3_trials": 5,
    "n_seeds_disc": 10,
    "n_radii": 3,
    "n_angles": 36,
}


def notebook_params(profile: str = "paper") -> dict:
    """Parameters of the notebook under ``profile``: :func:`obslib.profiles.params` once the
    notebook is registered there, these defaults (with :data:`QUICK` for ``quick``) before."""
    from ..profiles import PROFILES, params, profile_names

    if profile not in profile_names():
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    if NOTEBOOK in PROFILES["paper"]:
        return params(NOTEBOOK, profile)
    out = copy.deepcopy(DEFAULTS)
    if profile == "quick":
        out.update(QUICK)
    return out
