"""Figures of the studies beyond the paper (matplotlib); the computations live in :mod:`obslib.studies`."""
