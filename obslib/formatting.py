"""How a number reads in the book's prose and tables: one formatter for notebooks, ledger, report.

The rules, in the order they apply:

- integers (and integer-valued counts) read as integers with thousands separated: ``10,000``;
- a count of zero reads as a word (``"none"``, or what the caller passes) in :func:`count`;
- a value whose magnitude is below a stated floor reads as a bound, ``$< 10^{-12}$``: such values
  are rounding, which differs from one CPU to another, so the text is the same on every machine;
- values from ``1e-3`` up to ``1000`` keep three significant digits, trailing zeros included
  (``3.00``, ``0.485``, ``12.5``); values of ``1000`` and more read rounded to an integer with
  separators (``1,421``); smaller or larger ones as a power of ten (``$1.23 \\times 10^{-5}$``);
- fractions read as percentages with at most one decimal (``94.3%``, ``100%``), ranges as
  ``between 3.00 and 1,421``;
- a value set beside one the paper prints keeps the paper's decimals (:func:`fixed`);
- a parameter value reads as it is set, without padding zeros (:func:`setting`: ``0.25``,
  ``1``, ``$10^{-6}$``), and a list of them in words (:func:`listing`: ``0.25, 0.5 and 1``).

Every function returns MyST Markdown (math in ``$...$``) by default; ``math=False`` gives plain
text for figure labels and printed tables (``1.23e-05`` is never produced: ``1.23×10⁻⁵``).
"""

from __future__ import annotations

import math
import numbers

from ._validate import ArgumentTypeError, as_bool, as_int, as_str

__all__ = ["number", "count", "small", "percent", "span", "setting", "listing", "fixed"]

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _real(x, name: str = "x") -> float:
    if isinstance(x, bool) or not isinstance(x, numbers.Real):
        raise ArgumentTypeError(f"{name} must be a real number, got {x!r}")
    x = float(x)
    if math.isnan(x):
        raise ValueError(f"{name} is NaN")
    return x


def _number(x, name: str) -> int | float:
    """A value to print: an ``int`` for an integer (Python or NumPy), which keeps every digit,
    else a real number (not NaN)."""
    if isinstance(x, numbers.Integral) and not isinstance(x, bool):
        return int(x)
    return _real(x, name)


def _digits(sig, math_) -> tuple[int, bool]:
    """The significant digits (at least one) and the flag for MyST math."""
    return as_int(sig, "sig", 1), as_bool(math_, "math")


def _power(mantissa: str, exponent: int, math_: bool) -> str:
    if math_:
        body = f"10^{{{exponent}}}" if mantissa == "1" else f"{mantissa} \\times 10^{{{exponent}}}"
        return f"${body}$"
    power = "10" + str(exponent).translate(_SUPERSCRIPT)
    return power if mantissa == "1" else f"{mantissa}×{power}"


def number(x, sig: int = 3, *, math: bool = True) -> str:
    """``x`` as the book prints a number (the rules in the module docstring).

    Parameters
    ----------
    x : real
        The value; integers (Python or NumPy) keep every digit.
    sig : int
        Significant digits of a non-integer between ``1e-3`` and ``1000``.
    math : bool
        MyST math for powers of ten (default) or plain text.

    Examples
    --------
    >>> number(10000), number(0.48488), number(3), number(3.0), number(1420.8)
    ('10,000', '0.485', '3', '3.00', '1,421')
    >>> number(1.234e-5), number(-2.5e7, math=False)
    ('$1.23 \\\\times 10^{-5}$', '-2.50×10⁷')
    """
    x = _number(x, "x")
    sig, math = _digits(sig, math)
    if isinstance(x, int):
        return f"{x:,}"
    if abs(x) == float("inf"):
        return ("$\\infty$" if math else "∞") if x > 0 else ("$-\\infty$" if math else "-∞")
    if x == 0:
        return "0"
    a = abs(x)
    if 1e-3 <= a < 1000:
        r = float(f"{x:.{sig - 1}e}")  # rounded to sig digits first: 0.9996 -> 1.00, not 1.000
        if abs(r) < 1000:
            digits = max(sig - 1 - _floor_log10(abs(r)), 0)
            return f"{r:.{digits}f}"
        a = abs(r)
    if 1000 <= a < 1e6:
        return f"{round(x):,}"
    mantissa, exponent = f"{x:.{sig - 1}e}".split("e")
    return _power(mantissa, int(exponent), math)


def _floor_log10(a: float) -> int:
    e = math.floor(math.log10(a))
    # guard against log10 rounding just below a power of ten
    if 10.0 ** (e + 1) <= a:
        e += 1
    return e


def count(n, zero: str = "none", *, of: int | None = None) -> str:
    """A count in words where it is zero: ``count(0) == "none"``, ``count(1234) == "1,234"``.

    With ``of``, a count out of a total: ``count(3, of=20) == "3 of 20"``,
    ``count(0, of=20) == "none of 20"``, ``count(20, of=20) == "all 20"``.
    """
    if isinstance(n, bool) or not isinstance(n, numbers.Integral):
        if isinstance(n, numbers.Real) and float(n).is_integer():
            n = int(n)
        else:
            raise ArgumentTypeError(f"n, a count, must be an integer, got {n!r}")
    n, zero = int(n), as_str(zero, "zero")
    if of is not None:
        of = as_int(of, "of", 0)
    if of is None:
        return zero if n == 0 else f"{n:,}"
    if n == 0:
        return f"{zero} of {of:,}"
    if n == of:
        return f"all {of:,}" if of > 2 else ("both" if of == 2 else "the one")
    return f"{n:,} of {of:,}"


def small(x, floor: float = 1e-12, sig: int = 3, *, math: bool = True) -> str:
    """``x`` as :func:`number`, or the bound ``< floor`` when ``|x| < floor`` (rounding level).

    Examples
    --------
    >>> small(3e-17), small(0.25), small(2e-9, floor=1e-7, math=False)
    ('$< 10^{-12}$', '0.250', '< 10⁻⁷')
    """
    x = _real(x)
    floor = _real(floor, "floor")
    sig, math = _digits(sig, math)
    if not floor > 0:
        raise ValueError(f"floor must be positive, got {floor!r}")
    if abs(x) < floor:
        mantissa, exponent = f"{floor:.{sig - 1}e}".split("e")
        m = mantissa.rstrip("0").rstrip(".")
        if math:
            body = f"10^{{{int(exponent)}}}" if m == "1" else f"{m} \\times 10^{{{int(exponent)}}}"
            return f"$< {body}$"
        return "< " + _power(m, int(exponent), False)
    return number(x, sig, math=math)


def percent(fraction, decimals: int = 1) -> str:
    """A fraction in ``[0, 1]`` as a percentage with at most ``decimals`` decimals: ``94.3%``.

    Whole percentages drop the decimal (``100%``, ``0%``); a fraction that is not zero but rounds to
    zero reads ``< 0.1%``, one that is not one but rounds to 100 reads ``> 99.9%``.
    """
    f = _real(fraction, "fraction")
    decimals = as_int(decimals, "decimals", 0)
    if not 0 <= f <= 1:
        raise ValueError(f"fraction must lie in [0, 1], got {f!r}")
    p = round(100 * f, decimals)
    step = 10.0 ** -decimals
    if p == 0 and f > 0:
        return f"< {step:g}%"
    if p == 100 and f < 1:
        return f"> {100 - step:g}%"
    text = f"{p:.{decimals}f}".rstrip("0").rstrip(".") if decimals else f"{p:.0f}"
    return f"{text}%"


def span(lo, hi, sig: int = 3, *, math: bool = True) -> str:
    """A range in words: ``span(3.0, 1420.8) == "between 3.00 and 1,421"``; equal ends read once."""
    lo, hi = _number(lo, "lo"), _number(hi, "hi")
    a, b = number(lo, sig, math=math), number(hi, sig, math=math)
    return a if a == b else f"between {a} and {b}"


def setting(x, *, math: bool = True) -> str:
    """A parameter value as it is set: at most three significant digits and no padding zeros.

    Examples
    --------
    >>> setting(0.25), setting(1.0), setting(2), setting(20000), setting(1e-6)
    ('0.25', '1', '2', '20,000', '$10^{-6}$')
    """
    x, math = _number(x, "x"), as_bool(math, "math")
    if isinstance(x, int) or abs(x) == float("inf"):
        return number(x, math=math)
    if x == 0:
        return "0"
    if float(x).is_integer() and abs(x) < 1e6:
        return f"{int(x):,}"
    a = abs(x)
    if 1e-3 <= a < 1000:
        return f"{float(f'{x:.2e}'):g}"
    mantissa, exponent = f"{x:.2e}".split("e")
    m = mantissa.rstrip("0").rstrip(".")
    return _power(m, int(exponent), math)


def fixed(x, decimals: int) -> str:
    """``x`` to a fixed number of decimals, to set beside a value printed with that precision
    (the paper's ``0.5345``): ``fixed(0.09906, 4) == "0.0991"``.

    Examples
    --------
    >>> fixed(0.099061, 4), fixed(-0.0493, 4), fixed(1234.5, 1)
    ('0.0991', '-0.0493', '1,234.5')
    """
    x = _real(x)
    if isinstance(decimals, bool) or not isinstance(decimals, numbers.Integral) or decimals < 0:
        raise ValueError(f"decimals must be a non-negative integer, got {decimals!r}")
    text = f"{x:,.{int(decimals)}f}"
    return "0" + text[2:] if text.startswith("-0") and float(text.replace(",", "")) == 0 else text


def listing(items, conjunction: str = "and") -> str:
    """Items (text, or numbers read by :func:`setting`) in words: ``a, b and c``.

    Examples
    --------
    >>> listing([0.25, 0.5, 1.0, 2.0]), listing(["D", "A"], "or"), listing([3])
    ('0.25, 0.5, 1 and 2', 'D or A', '3')
    """
    if isinstance(items, (str, bytes)) or not hasattr(items, "__iter__"):
        raise ArgumentTypeError(f"items must be a sequence of text or numbers, got {items!r}")
    conjunction = as_str(conjunction, "conjunction")
    words = [x if isinstance(x, str) else setting(_number(x, "items")) for x in items]
    if not words:
        raise ValueError("items: nothing to list")
    return words[0] if len(words) == 1 else ", ".join(words[:-1]) + f" {conjunction} " + words[-1]
