"""pytest, for every test and doctest of the checkout: figures are drawn off screen (Agg), and
each test's figures are closed when it ends, so that the drawing functions' doctests can show a
figure in a line or two.

``make test`` runs the tests on one pytest-xdist worker per core, a file at a time
(``-n auto --dist loadfile``), so that the cells of a notebook run in order in one kernel (nbval).
The tests that share costly state across files take it under a lock: the rendered book
(``tests/test_book.py``) and the ledger at the paper's sizes (``tests/conftest.py``).
"""

import sys

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    if "matplotlib.pyplot" in sys.modules:
        sys.modules["matplotlib.pyplot"].close("all")
