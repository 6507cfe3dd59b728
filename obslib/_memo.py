"""One computation of each study: a cache on a pure function's arguments.

The chapters and the claims ledger call the same study functions with the same arguments; with
:func:`memoized` the second call returns the first one's result, so a number the book shows in
two places comes from one computation. Arguments are told apart by type as well as value
(``1``, ``1.0`` and ``True`` are three calls). A call with an unhashable argument (a list where
a tuple is expected) is not cached: it runs the function, whose own validation then names the
argument. Results are shared between callers, so they must not be changed in place.
"""

from __future__ import annotations

from functools import lru_cache, wraps

__all__ = ["memoized"]


def memoized(maxsize: int = 8):
    """Decorator: cache a pure function on its arguments (at most ``maxsize`` results).

    Examples
    --------
    >>> calls = []
    >>> @memoized()
    ... def square(x):
    ...     calls.append(x)
    ...     return x * x
    >>> square(3), square(3), square([3][0]), len(calls)
    (9, 9, 9, 1)
    """

    def decorate(fn):
        cached = lru_cache(maxsize=maxsize, typed=True)(fn)

        @wraps(fn)
        def call(*args, **kwargs):
            try:
                hash((args, tuple(sorted(kwargs.items()))))
            except TypeError:
                return fn(*args, **kwargs)
            return cached(*args, **kwargs)

        call.cache_clear = cached.cache_clear
        call.cache_info = cached.cache_info
        return call

    return decorate
