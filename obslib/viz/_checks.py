"""Checks of the drawings' arguments that the library's validators (:mod:`obslib._validate`) do
not make: a series of values to plot, one tracking run, and runs keyed by strategy."""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array, as_instance, as_mapping
from ..tracking import STRATEGIES, BatchResult, TrackingResult

__all__ = ["as_series", "as_run", "as_runs"]


def as_series(x, name: str, length: int | None = None) -> np.ndarray:
    """``x`` as a one-dimensional array of finite floats (``length`` of them if given), else a
    ValueError naming ``name``.

    Examples
    --------
    >>> as_series([1, 2], "error")
    array([1., 2.])
    >>> as_series([1, 2], "error", 3)
    Traceback (most recent call last):
    ...
    ValueError: error must have 3 values, got shape (2,)
    """
    arr = as_float_array(x, name)
    if arr.ndim != 1 or (length is not None and arr.shape[0] != length):
        n = "one or more" if length is None else str(length)
        raise ValueError(f"{name} must have {n} values, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must be finite")
    return arr


def as_run(run, name: str) -> TrackingResult:
    """``run`` if it is one tracking run (a :class:`~obslib.tracking.TrackingResult` that is not
    a batch), else a ValueError naming ``name``."""
    as_instance(run, TrackingResult, name)
    if isinstance(run, BatchResult):
        raise ValueError(f"{name} must be one run, not a batch of runs")
    return run


def as_runs(runs, name: str, cls=TrackingResult, n: int | None = None) -> dict:
    """``runs`` as a dict strategy -> an instance of ``cls`` (``n`` strategies if given), the
    strategies among the paper's (:data:`obslib.tracking.STRATEGIES`), else a ValueError naming
    ``name``."""
    runs = as_mapping(runs, name)
    for s, r in runs.items():
        if s not in STRATEGIES:
            raise ValueError(f"{name}: unknown strategy {s!r}; known: {STRATEGIES}")
        as_instance(r, cls, name)
    if n is not None and len(runs) != n:
        raise ValueError(f"{name} must hold {n} strategies, got {len(runs)}")
    return runs
