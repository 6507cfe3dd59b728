"""Checks of the drawings' arguments that the library's validators (:mod:`obslib._validate`) do
not make: a series of values to plot."""

from __future__ import annotations

import numpy as np

from .._validate import as_float_array

__all__ = ["as_series"]


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
