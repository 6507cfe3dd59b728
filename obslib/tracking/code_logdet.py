"""The authors' team greedy on :math:`\\log\\det(O_l^T O_l)` as their code evaluates it:
the arithmetic that decides what the greedy does with the first, singular sensor of a team.

For a team of one sensor :math:`O_l^T O_l` is singular. In exact arithmetic its
:math:`\\log\\det` is :math:`-\\infty`; the code's floating point gives something else:

- the determinant is an LU factorisation's (LAPACK's ``dgetrf`` with partial pivoting, its
  update fused into one multiply-add, :func:`code_logdet_det`), which leaves the rounding
  residue of the singular matrix: zero, a tiny positive number or a tiny negative one;
- the logarithm of a negative number is complex, :math:`\\log\\lvert d \\rvert + i\\pi`, and
  that of an empty team's determinant is 0 (MATLAB's :math:`\\det` of a 0 x 0 matrix is 1);
- each round's pick is the first entry, in column order, equal to MATLAB's
  ``max(max(table))`` of the gains (:func:`matlab_table_max`), where the sensors already taken
  have zero gains: by value among real numbers, by magnitude and phase angle where an entry is
  complex.

:func:`logdet_rounds` runs the greedy for one instance in the code's arithmetic, without the
fused update, or exactly; the assignments ``"logdet-teams"``, ``"logdet-teams-as-run"`` and
``"logdet-teams-exact"`` of :mod:`~obslib.tracking.assigners` run it at every step.
"""

from __future__ import annotations

import numpy as np

from .._validate import as_bool, as_choice, as_float_array, as_points, check_distinct

__all__ = ["ARITHMETICS", "fused_multiply_add", "code_logdet_det", "matlab_table_max",
           "logdet_rounds"]

def _two_product(a, b):
    """``a * b = p + e`` exactly (Dekker's product with Veltkamp's split; no overflow)."""
    p = a * b
    t = 134217729.0 * a  # 2^27 + 1
    ah = t - (t - a)
    al = a - ah
    t = 134217729.0 * b
    bh = t - (t - b)
    bl = b - bh
    e = ((ah * bh - p) + ah * bl + al * bh) + al * bl
    return p, e


def fused_multiply_add(a, b, c):
    """``a * b + c`` with one rounding where the product and ``c`` cancel (the exact sum then
    is ``c + p + e`` with ``c + p`` exact, Sterbenz's lemma), and within a unit in the last
    place elsewhere: the fused multiply-add of an optimised LAPACK's update, elementwise.

    Examples
    --------
    >>> x = 1.0 + 2.0**-30
    >>> float(fused_multiply_add(x, x, -(x * x)))  # the rounding error, 2^-60
    8.673617379884035e-19
    """
    a, b, c = (as_float_array(v, name) for v, name in ((a, "a"), (b, "b"), (c, "c")))
    for v, name in ((a, "a"), (b, "b"), (c, "c")):
        if not np.isfinite(v).all():
            raise ValueError(f"{name} must be finite")
    try:
        np.broadcast_shapes(a.shape, b.shape, c.shape)
    except ValueError:
        raise ValueError("a, b and c must broadcast together") from None
    return fma(a, b, c)


def fma(a, b, c):
    """:func:`fused_multiply_add` without checks (the determinant's worker)."""
    p, e = _two_product(a, b)
    s = p + c
    bb = s - p
    t = (p - (s - bb)) + (c - bb)
    return s + (t + e)


def code_logdet_det(g00, g01, g11, fused: bool = True):
    """The determinant of the symmetric ``[[g00, g01], [g01, g11]]`` as the authors' code gets
    it: an LU factorisation with partial pivoting (LAPACK's ``dgetrf``: the pivot is the first
    entry of largest magnitude in the first column, the multiplier the other entry times the
    pivot's reciprocal, the update :math:`u_{22} = a_{22} - l\\, a_{12}` with a fused
    multiply-add, or with two roundings where ``fused`` is false), then the product of the
    pivots with the permutation's sign. For a singular matrix this leaves the rounding residue
    of :math:`u_{22}`: zero, or a tiny number of either sign.

    Examples
    --------
    The Gram matrix of one row is singular in exact arithmetic; its computed determinant is
    zero, or a residue of either sign:

    >>> import numpy as np
    >>> def one_row(x, y):
    ...     return float(code_logdet_det(x * x, x * y, y * y))
    >>> one_row(1.0, 1.0), one_row(5.5, 1.5), one_row(0.5, -1.5)
    (0.0, 5.037636974236648e-15, -3.122502256758253e-17)
    """
    g = [as_float_array(v, name) for v, name in ((g00, "g00"), (g01, "g01"), (g11, "g11"))]
    for v, name in zip(g, ("g00", "g01", "g11")):
        if not np.isfinite(v).all():
            raise ValueError(f"{name} must be finite")
    try:
        np.broadcast_shapes(*(v.shape for v in g))
    except ValueError:
        raise ValueError("g00, g01 and g11 must broadcast together") from None
    return code_det(*g, fused=as_bool(fused, "fused"))


def code_det(g00, g01, g11, fused: bool = True):
    """:func:`code_logdet_det` without checks (the greedy's worker)."""
    g00, g01, g11 = np.broadcast_arrays(*(np.asarray(v, dtype=float) for v in (g00, g01, g11)))
    swap = np.abs(g01) > np.abs(g00)
    p = np.where(swap, g01, g00)
    q = np.where(swap, g11, g01)  # the pivot row's second entry
    c = np.where(swap, g00, g01)
    d = np.where(swap, g01, g11)
    with np.errstate(divide="ignore", invalid="ignore"):
        lm = c * (1.0 / p)
        u = fma(-lm, q, d) if fused else d - lm * q
        det = p * u
    det = np.where(p == 0, 0.0, det)  # a zero column: U has a zero pivot
    return np.where(swap, -det, det)


def _complex_log(det):
    """:math:`\\log` of real numbers as (real, imaginary) parts: :math:`-\\infty` at 0, the
    principal value (imaginary part :math:`\\pi`) below."""
    with np.errstate(divide="ignore", invalid="ignore"):
        re = np.log(np.abs(det))
    im = np.where(det < 0, np.pi, 0.0)
    return re, im


def _column_maxima(re, im, cplx):
    """Each column's maximum ``(cre, cim)`` ``(M, L)`` of the tables ``re + i im``
    ``(M, L, N)`` by MATLAB's rules (NaN where a column has no number): by value in a real
    table, else by magnitude, then phase angle. The angle is computed only for the entries of
    largest magnitude."""
    M, L, N = re.shape
    with np.errstate(invalid="ignore", over="ignore"):
        key = np.where(cplx, re * re + im * im, re)  # magnitude squared: the same order
    top = np.fmax.reduce(key, axis=2)  # NaN ignored
    m, l, i = np.nonzero(key == top[..., None])  # the candidates, NaN excluded
    ang = np.where(cplx[m, 0, 0], np.arctan2(im[m, l, i], re[m, l, i]), 0.0)
    order = np.lexsort((i, -ang, l, m))  # per column: largest angle first, then first entry
    first = np.ones(order.size, dtype=bool)
    first[1:] = (m[order][1:] != m[order][:-1]) | (l[order][1:] != l[order][:-1])
    sel = order[first]
    cre, cim = np.full((M, L), np.nan), np.full((M, L), np.nan)
    cre[m[sel], l[sel]] = re[m[sel], l[sel], i[sel]]
    cim[m[sel], l[sel]] = im[m[sel], l[sel], i[sel]]
    return cre, cim


def matlab_table_max(re, im) -> np.ndarray:
    """Per table, where the authors' code finds its round's pick: ``[row, col] =
    find(T == max(max(T)))``, the first match, of the gains ``T = re + i im`` ``(M, L, N)``
    (an ``N x L`` table per run, stored target-major as MATLAB stores its columns). Returns the
    flat index ``l N + i`` of the pick, ``(M,)``.

    MATLAB's rules: ``max`` ignores NaN; it compares real numbers by value and, in an array
    with any entry of non-zero imaginary part, every entry by magnitude, then by phase angle.
    ``max(T)`` takes the maximum of each column; MATLAB drops a zero imaginary part from a
    result, so where every column maximum is real the second ``max`` compares them by value.
    ``find`` then returns the first entry equal to that maximum in column order (smallest
    target, then smallest sensor).

    Examples
    --------
    A real table: the largest value wins. One entry of non-zero imaginary part makes each
    column's maximum be chosen by magnitude (-36 and -40); both are real, so the larger value
    wins:

    >>> import numpy as np
    >>> # targets 0, 1 (outer), sensors 0, 1 (inner)
    >>> re = np.array([[[-36.0, 2.0], [-30.0, -40.0]]])
    >>> int(matlab_table_max(re, np.zeros_like(re))[0])  # target 0, sensor 1
    1
    >>> im = np.array([[[0.0, np.pi], [0.0, 0.0]]])
    >>> int(matlab_table_max(re, im)[0])  # target 0, sensor 0
    0
    """
    re, im = as_float_array(re, "re"), as_float_array(im, "im")
    if re.ndim != 3 or re.shape != im.shape or 0 in re.shape:
        raise ValueError(f"re and im must be tables of one shape (M, L, N), got {re.shape} and "
                         f"{im.shape}")
    return table_max(re, im)


def table_max(re, im) -> np.ndarray:
    """:func:`matlab_table_max` without checks (the greedy's worker)."""
    M, L, N = re.shape
    cplx = (im != 0).any(axis=(1, 2))[:, None, None]
    cre, cim = _column_maxima(re, im, cplx)
    cplx2 = (np.nan_to_num(cim) != 0).any(axis=1)[:, None, None]
    vre, vim = _column_maxima(cre[:, None, :], cim[:, None, :], cplx2)
    equal = (re == vre[:, :, None]) & (im == vim[:, :, None])
    return equal.reshape(M, -1).argmax(axis=1)


def logdet_labels(S, x, exact: bool, fused: bool = True):
    """The code's greedy (module docstring) for ``M`` runs: the labels of the sensors each
    target won and of the rounds it won, each ``(M, N)``."""
    with np.errstate(invalid="ignore"):  # -inf - (-inf): a NaN gain, which the max ignores
        return _logdet_rounds(S, x, exact, fused)


def _logdet_rounds(S, x, exact: bool, fused: bool):
    M, L = x.shape[:2]
    N = S.shape[1]
    vx = x[:, None, :, 0] - S[:, :, None, 0]  # rows target - sensor, (M, N, L)
    vy = x[:, None, :, 1] - S[:, :, None, 1]
    rows = np.arange(M)
    g00, g01, g11 = (np.zeros((M, L)) for _ in range(3))  # the teams' O^T O (code)
    det = np.zeros((M, L))  # the teams' exact det (Cauchy-Binet) and increments C
    C = np.zeros((M, N, L))
    size = np.zeros((M, L), dtype=np.int64)
    old_re, old_im = np.zeros((M, L)), np.zeros((M, L))  # log det of the empty team: 0

    def new_logdet(ms, l, i=slice(None)):
        """log det of team ``l[m]`` plus the row of sensor ``i`` (every sensor by default),
        ``(len(ms), N)`` or ``(len(ms),)``."""
        if isinstance(i, slice):
            ax, ay = vx[ms, :, l], vy[ms, :, l]
            sums = (det[ms, l][:, None], g00[ms, l][:, None], g01[ms, l][:, None],
                    g11[ms, l][:, None])
            inc = C[ms, :, l]
        else:
            ax, ay = vx[ms, i, l], vy[ms, i, l]
            sums = (det[ms, l], g00[ms, l], g01[ms, l], g11[ms, l])
            inc = C[ms, i, l]
        if exact:
            d = sums[0] + inc
        else:
            d = code_det(fma(ax, ax, sums[1]), fma(ax, ay, sums[2]), fma(ay, ay, sums[3]),
                         fused)
        return _complex_log(d)

    gain_re, gain_im = np.empty((M, N, L)), np.empty((M, N, L))
    for l in range(L):
        re, im = new_logdet(rows, np.full(M, l))
        gain_re[:, :, l], gain_im[:, :, l] = re - old_re[:, l, None], im - old_im[:, l, None]
    free = np.ones((M, N), dtype=bool)
    picked = np.full((M, N), -1, dtype=np.int64)
    rounds = np.empty((M, N), dtype=np.int64)
    for t in range(N):
        at = table_max(gain_re.transpose(0, 2, 1), gain_im.transpose(0, 2, 1))
        l, i = np.divmod(at, N)
        rounds[:, t] = l
        newly = free[rows, i]
        picked[rows[newly], i[newly]] = l[newly]
        # the team's new O^T O and log det (the value of the table's entry)
        old_re[rows, l], old_im[rows, l] = new_logdet(rows, l, i)
        ax, ay = vx[rows, i, l], vy[rows, i, l]
        g00[rows, l] = fma(ax, ax, g00[rows, l])
        g01[rows, l] = fma(ax, ay, g01[rows, l])
        g11[rows, l] = fma(ay, ay, g11[rows, l])
        det[rows, l] = det[rows, l] + C[rows, i, l]
        cross = vx[rows, :, l] * ay[:, None] - vy[rows, :, l] * ax[:, None]
        C[rows, :, l] = C[rows, :, l] + cross * cross
        size[rows, l] += 1
        free[rows, i] = False
        re, im = new_logdet(rows, l)
        gain_re[rows, :, l] = re - old_re[rows, l][:, None]
        gain_im[rows, :, l] = im - old_im[rows, l][:, None]
        gain_re[~free], gain_im[~free] = 0.0, 0.0  # the table's rows of the taken sensors
    return picked, rounds


#: The arithmetic :func:`logdet_rounds` evaluates the code's measure in.
ARITHMETICS = ("code", "code-unfused", "exact")


def logdet_rounds(sensors, targets, arithmetic: str = "code"):
    """The authors' team greedy on :math:`\\log\\det(O_l^T O_l)` for one instance: which
    sensor each target won, and which rounds.

    ``arithmetic`` is ``"code"`` (the code's floating point, :func:`code_logdet_det`, as
    ``"logdet-teams"`` evaluates it), ``"code-unfused"`` (the same with the LU update rounded
    twice, as an LAPACK without fused multiply-adds would) or ``"exact"`` (singular teams have
    :math:`\\log\\det = -\\infty`).

    Returns
    -------
    picked : ndarray of int, shape (N,)
        The target of each sensor (-1 if it was never won).
    rounds : ndarray of int, shape (N,)
        The target that won round ``r`` (what the authors' script hands to the filters as
        sensor ``r``).

    Examples
    --------
    The later experiment's first step, at its initial estimates:

    >>> from obslib import tracking
    >>> su = tracking.LATER_MULTI_TARGET
    >>> picked, rounds = logdet_rounds(su.sensors, su.estimate0)
    >>> picked.tolist(), rounds.tolist()
    ([0, 1, 1, 2, 2, 2, 1, 0], [0, 1, 0, 1, 2, 2, 1, 2])
    >>> logdet_rounds(su.sensors, su.estimate0, "exact")[0].tolist()
    [0, 0, 0, 0, 0, 0, 0, 0]
    """

    S = as_points(as_float_array(sensors, "sensors"), "sensors", min_count=1)
    T = as_points(as_float_array(targets, "targets"), "targets", min_count=1)
    if not (np.isfinite(S).all() and np.isfinite(T).all()):
        raise ValueError("sensors and targets must be finite")
    check_distinct(S)
    as_choice(arithmetic, ARITHMETICS, "arithmetic")
    picked, rounds = logdet_labels(S[None], T[None], arithmetic == "exact",
                                   arithmetic == "code")
    return picked[0], rounds[0]
