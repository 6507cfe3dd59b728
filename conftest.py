"""pytest, for every test and doctest of the checkout: figures are drawn off screen (Agg), and
each test's figures are closed when it ends, so that the drawing functions' doctests can show a
figure in a line or two."""

import sys

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")
