"""The book's one number formatter: what it prints, read back, is the number to its precision."""

import math
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from obslib import formatting


def _read_back(text: str) -> float:
    """The value a reader takes from ``text`` (MyST math or plain)."""
    t = text.replace(",", "").replace("$", "").strip()
    m = re.fullmatch(r"(-?[\d.]+) \\times 10\^\{(-?\d+)\}", t)
    if m:  # as one literal, so that subnormal values do not underflow on the way
        return float(f"{m.group(1)}e{m.group(2)}")
    return float(t)


@given(st.floats(min_value=-1e300, max_value=1e300, allow_nan=False).filter(lambda v: v != 0))
def test_number_reads_back_to_three_significant_digits(x):
    back = _read_back(formatting.number(x))
    if abs(x) >= 1000 and abs(x) < 1e6:  # rounded to an integer
        assert abs(back - x) <= 0.5
    else:
        assert math.isclose(back, x, rel_tol=5e-3)


@given(st.integers(min_value=-10**12, max_value=10**12))
def test_integers_keep_every_digit(n):
    assert int(formatting.number(n).replace(",", "")) == n
    assert int(formatting.number(np.int64(n)).replace(",", "")) == n


def test_examples_of_the_writing_rules():
    assert formatting.number(10000) == "10,000"
    assert formatting.number(3.0) == "3.00"
    assert formatting.number(0.9996) == "1.00"
    assert formatting.number(999.96) == "1,000"
    assert formatting.number(2.5e-5) == "$2.50 \\times 10^{-5}$"
    assert formatting.number(2.5e-5, math=False) == "2.50×10⁻⁵"
    assert formatting.span(3.0, 1420.8) == "between 3.00 and 1,421"
    assert formatting.small(1e-17) == "$< 10^{-12}$"
    assert formatting.small(1e-50, floor=1e-40) == "$< 10^{-40}$"
    assert formatting.count(0) == "none"
    assert formatting.count(0, of=20000) == "none of 20,000"
    assert formatting.count(20, of=20) == "all 20"
    assert formatting.percent(0.943) == "94.3%"
    assert formatting.percent(1.0) == "100%"
    assert formatting.percent(1e-6) == "< 0.1%"
    assert formatting.percent(0.99999) == "> 99.9%"


@pytest.mark.parametrize("bad", [True, "1", None, complex(1, 1), float("nan")])
def test_bad_numbers_are_named_errors(bad):
    with pytest.raises(ValueError, match="must be a real number|is NaN"):
        formatting.number(bad)


@pytest.mark.parametrize("call, name", [
    (lambda: formatting.count(2.5), "n"),
    (lambda: formatting.count(3, of="20"), "of"),
    (lambda: formatting.percent(1.5), "fraction"),
    (lambda: formatting.small(1.0, floor=0), "floor"),
    (lambda: formatting.number(2.0, sig=0), "sig"),
    (lambda: formatting.span(1.0, None), "hi"),
    (lambda: formatting.listing([]), "items"),
    (lambda: formatting.listing([[1.0]]), "items"),
    (lambda: formatting.listing(object()), "items"),
    (lambda: formatting.setting(1.0, math=1), "math"),
])
def test_bad_arguments_are_named_errors(call, name):
    with pytest.raises(ValueError, match=rf"^{name}\b"):
        call()


def test_infinite_values_read_as_infinity():
    assert formatting.setting(float("inf")) == formatting.number(float("inf")) == "$\\infty$"
    assert formatting.setting(-float("inf"), math=False) == "-∞"


@given(st.floats(min_value=1e-3, max_value=999, allow_nan=False))
def test_setting_reads_back_to_three_significant_digits_without_padding(x):
    text = formatting.setting(x)
    assert math.isclose(float(text.replace(",", "")), x, rel_tol=5e-3)
    assert not (("." in text) and text.endswith("0")), text  # no padding zeros


def test_settings_and_lists_of_them():
    assert [formatting.setting(v) for v in (0.25, 1.0, 2, 1e-6, 1e4, 0.0)] == [
        "0.25", "1", "2", "$10^{-6}$", "10,000", "0"]
    assert formatting.setting(2.5e-7, math=False) == "2.5×10⁻⁷"
    assert formatting.listing([0.0, 0.25, 0.5, 1.0, 2.0]) == "0, 0.25, 0.5, 1 and 2"
    assert formatting.listing(["D-optimal", "A-optimal"], "or") == "D-optimal or A-optimal"
    with pytest.raises(ValueError):
        formatting.listing([])
    with pytest.raises(ValueError):
        formatting.setting(True)


def test_fixed_decimals_beside_printed_values():
    assert formatting.fixed(0.0990614, 4) == "0.0991"
    assert formatting.fixed(-0.00001, 2) == "0.00"  # no negative zero
    assert formatting.fixed(12345.678, 1) == "12,345.7"
    assert float(formatting.fixed(0.53452248, 4)) == 0.5345
    with pytest.raises(ValueError):
        formatting.fixed(1.0, -1)
