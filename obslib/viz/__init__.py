"""Figures of the book: every matplotlib drawing lives in this package (``tracking``: Section V)."""

from . import tracking  # noqa: F401
