"""The book's one number formatter: what it prints, read back, is the number to its precision."""

import math
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as hs

from obslib import _format as F


def _read_back(text: str) -> float:
    """The value a reader takes from ``text`` (MyST math or plain)."""
    t = text.replace(",", "").replace("$", "").strip()
    m = re.fullmatch(r"(-?[\d.]+) \\times 10\^\{(-?\d+)\}", t)
    if m:
        return float(m.group(1)) * 10.0 ** int(m.group(2))
    return float(t)


@given(hs.floats(min_value=-1e300, max_value=1e300, allow_nan=False).filter(lambda v: v != 0))
def test_number_reads_back_to_three_significant_digits(x):
    back = _read_back(F.number(x))
    if abs(x) >= 1000 and abs(x) < 1e6:  # rounded to an integer
        assert abs(back - x) <= 0.5
    else:
        assert math.isclose(back, x, rel_tol=5e-3)


@given(hs.integers(min_value=-10**12, max_value=10**12))
def test_integers_keep_every_digit(n):
    assert int(F.number(n).replace(",", "")) == n
    assert int(F.number(np.int64(n)).replace(",", "")) == n


def test_examples_of_the_writing_rules():
    assert F.number(10000) == "10,000"
    assert F.number(3.0) == "3.00"
    assert F.number(0.9996) == "1.00"
    assert F.number(999.96) == "1,000"
    assert F.number(2.5e-5) == "$2.50 \\times 10^{-5}$"
    assert F.number(2.5e-5, math=False) == "2.50×10⁻⁵"
    assert F.span(3.0, 1420.8) == "between 3.00 and 1,421"
    assert F.small(1e-17) == "$< 10^{-12}$"
    assert F.small(1e-50, floor=1e-40) == "$< 10^{-40}$"
    assert F.count(0) == "none"
    assert F.count(0, of=20000) == "none of 20,000"
    assert F.count(20, of=20) == "all 20"
    assert F.percent(0.943) == "94.3%"
    assert F.percent(1.0) == "100%"
    assert F.percent(1e-6) == "< 0.1%"
    assert F.percent(0.99999) == "> 99.9%"


@pytest.mark.parametrize("bad", [True, "1", None, complex(1, 1), float("nan")])
def test_bad_numbers_are_named_errors(bad):
    with pytest.raises(ValueError, match="must be a real number|is NaN"):
        F.number(bad)


@pytest.mark.parametrize("call", [lambda: F.count(2.5), lambda: F.percent(1.5),
                                  lambda: F.small(1.0, floor=0)])
def test_bad_arguments_are_named_errors(call):
    with pytest.raises(ValueError):
        call()
