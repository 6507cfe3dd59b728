r"""The local observability matrix of Section III from its Lie derivatives (Eqs. (3)-(5)).

The system of Eq. (3) is :math:`\dot o = u_o`, :math:`z_i = h_i(o) = \tfrac12 \lVert p_i -
o\rVert^2`. Treating the target's velocity as a fixed drift, :math:`f(o) = u_o`, the Lie
derivatives of a measurement along :math:`f` are :math:`L^0_f h = h`, :math:`L^{k+1}_f h =
\nabla L^k_f h \cdot f`, and the local observability matrix (Hermann and Krener) stacks their
gradients :math:`\nabla L^k_f h_i` (Eq. (4)). :func:`lie_rows` derives them, :func:`printed_rows`
holds the rows Eq. (4) prints, and :func:`one_sensor_rank_condition` the determinant of the
one-sensor matrix :math:`O_i(o, u_o)` behind the rank condition in the proof of Theorem 2. The
same rows for a range measurement :math:`\lVert p_i - o\rVert` (what the authors' later
experiment measures) are :func:`lie_rows` with ``measurement="range"``.

Examples
--------
>>> rows = lie_rows(3)
>>> [list(r) for r in rows]
[[o_x - p_x, o_y - p_y], [u_x, u_y], [0, 0]]
>>> rows_match_printed(3)
True
"""

from __future__ import annotations

from functools import lru_cache

import sympy as sp

from .._validate import as_int, as_str

__all__ = ["O_X", "O_Y", "P_X", "P_Y", "U_X", "U_Y", "MEASUREMENTS", "lie_rows",
           "printed_rows", "rows_match_printed", "one_sensor_rank_condition"]

#: The target's position, a sensor's, and the target's velocity (the drift).
O_X, O_Y, P_X, P_Y, U_X, U_Y = sp.symbols("o_x o_y p_x p_y u_x u_y", real=True)

#: The measurement models: half the squared range (the paper's, Eq. (3)) and the range itself.
MEASUREMENTS = ("half-squared", "range")


def _measurement(measurement: str) -> sp.Expr:
    d2 = (P_X - O_X) ** 2 + (P_Y - O_Y) ** 2
    return d2 / 2 if measurement == "half-squared" else sp.sqrt(d2)


def lie_rows(n: int = 3, measurement: str = "half-squared") -> tuple:
    r"""The gradients :math:`\nabla L^k_f h`, :math:`k = 0, \dots, n - 1`, of one sensor's
    measurement along the drift :math:`f = u_o`, each a SymPy row ``(d/do_x, d/do_y)``
    (simplified).

    Examples
    --------
    >>> lie_rows(2)
    ((o_x - p_x, o_y - p_y), (u_x, u_y))
    >>> lie_rows(0)
    Traceback (most recent call last):
    ...
    ValueError: n must be at least 1, got 0
    """
    return _lie_rows(*_lie_rows_iv(n, measurement))


def _lie_rows_iv(n, measurement) -> tuple:
    n = as_int(n, "n", 1)
    if as_str(measurement, "measurement") not in MEASUREMENTS:
        raise ValueError(f"measurement must be one of {MEASUREMENTS}, got {measurement!r}")
    return n, measurement


@lru_cache(maxsize=8)
def _lie_rows(n: int, measurement: str) -> tuple:
    grad = (O_X, O_Y)
    L = _measurement(measurement)
    rows = []
    for _ in range(n):
        row = tuple(sp.simplify(sp.diff(L, v)) for v in grad)
        rows.append(row)
        L = row[0] * U_X + row[1] * U_Y
    return tuple(rows)


def printed_rows(n: int = 3) -> tuple:
    """The rows Eq. (4) prints for one sensor: ``(o - p)^T``, ``u^T``, then zero rows.

    Examples
    --------
    >>> printed_rows(3)[2]
    (0, 0)
    """
    n = as_int(n, "n", 1)
    rows = [(O_X - P_X, O_Y - P_Y), (U_X, U_Y)] + [(sp.S.Zero, sp.S.Zero)] * max(0, n - 2)
    return tuple(rows[:n])


def rows_match_printed(n: int = 3) -> bool:
    """Whether the derived rows (half the squared range) equal the printed ones, entry by entry
    (differences expanded to zero).

    Examples
    --------
    >>> rows_match_printed(4)
    True
    """
    n = as_int(n, "n", 1)
    return all(sp.expand(a - b) == 0
               for dr, pr in zip(lie_rows(n), printed_rows(n)) for a, b in zip(dr, pr))


def one_sensor_rank_condition() -> tuple[sp.Expr, sp.Expr]:
    r"""``(det, printed)``: the determinant of the one-sensor matrix :math:`O_i(o, u_o) =
    [(o - p_i)^T; u_o^T]` (Eq. (23)), and the difference of the two sides of the condition the
    proof of Theorem 2 prints, :math:`(o_x - p_{ix}) u_{oy} - (o_y - p_{iy}) u_{ox}`. The matrix
    has full rank exactly when ``det`` is not zero; the condition is right when the two are
    equal.

    Examples
    --------
    >>> det, printed = one_sensor_rank_condition()
    >>> det - printed
    0
    """
    m = sp.Matrix([[O_X - P_X, O_Y - P_Y], [U_X, U_Y]])
    return sp.expand(m.det()), sp.expand((O_X - P_X) * U_Y - (O_Y - P_Y) * U_X)
