"""Former home of the scalar checks, now in :mod:`obslib._validate`; re-exports them for the modules
not yet importing them from there."""

from ._validate import positive_float, positive_int

__all__ = ["positive_int", "positive_float"]
