"""Pair choosers: which two sensors measure the target at the next step, by the paper's
strategies (the pair bound of Theorem 4) or by other criteria.

The strategies of Section V-A score a pair by Theorem 4's bound at the estimate
:math:`\\hat x` with the setup's :math:`u_{\\max}`,

.. math::

    \\underline{C}^{-1}_{ij} = \\sqrt{\\frac{\\lambda_{\\min}(G_{ij})}
    {\\lambda_{\\max}(G_{ij}) + u_{\\max}^2}}, \\qquad
    G_{ij} = \\begin{bmatrix} v_i^T \\\\ v_j^T \\end{bmatrix}^T
             \\begin{bmatrix} v_i^T \\\\ v_j^T \\end{bmatrix},

where :math:`v_i` is :math:`\\hat x - p_i` rescaled to its Mahalanobis length
:math:`d_i = \\sqrt{v^T \\Sigma^{-1} v}` in the estimate's covariance (``metric="mahalanobis"``,
the published runs) or left Euclidean. They differ in their candidates:

``"best-pair"``
    strategy (1), all pairs;
``"best-partner"``
    strategy (2), the pairs of a fixed sensor (``setup.anchor``, the paper's :math:`s_2`);
``"fixed-pair"``
    strategy (3), one pair (``setup.fixed_pair``, the paper's :math:`(s_2, s_1)`).

Beyond the paper, :data:`CRITERIA` choose among all pairs by the classical criteria of optimal
experimental design on the filter's information at its next update,

.. math::

    J_{ij} = (\\Sigma^-)^{-1} + H_{ij}^T R^{-1} H_{ij}, \\qquad
    \\Sigma^- = \\Sigma + Q, \\qquad
    H_{ij} = \\begin{bmatrix} (\\hat x - p_i)^T \\\\ (\\hat x - p_j)^T \\end{bmatrix},

exactly the quantities of the filter's next update (the measurement is the half squared range,
so its Jacobian rows are :math:`(\\hat x - p_i)^T`, and :math:`R` is the setup's measurement
noise of the pair):

``"d-optimal"``
    maximise :math:`\\det J_{ij}`;
``"a-optimal"``
    minimise :math:`\\operatorname{tr} J_{ij}^{-1} = \\operatorname{tr} J_{ij} / \\det J_{ij}`;
``"e-optimal"``
    maximise :math:`\\lambda_{\\min}(J_{ij}) = \\det J_{ij} / \\lambda_{\\max}(J_{ij})` with
    :math:`\\lambda_{\\max} = \\tfrac12 \\operatorname{tr} J + \\sqrt{\\tfrac14 (J_{00} - J_{11})^2
    + J_{01}^2}` (no cancellation);
``"exact-icn"``
    an oracle that knows the target's actual control: maximise the exact
    :math:`C^{-1}` of :math:`[(\\hat x - p_i)^T; (\\hat x - p_j)^T; u^T]`, where :math:`u` is the
    control in the observability matrix the sensors face at this step, the move
    :math:`u_{k-1} = o_k - o_{k-1}` that brought the target to :math:`o_k` (zero at step 1;
    the control of :attr:`~obslib.tracking.TrackingResult.true_icn`);
``"random"``
    a uniformly random pair, drawn from ``pair_draws`` of the run's seed.

The logged bound of every run stays the paper's pair bound of the chosen pair (the setup's
metric), so all runs compare with Fig. 6. Ties keep the first maximum in ``(i, j)`` order (the
smallest pair). :class:`PairChooser` evaluates the choice for many runs at once without per-step
validation, with the same arithmetic for one run or many: a run takes the same decisions alone
(:func:`~obslib.tracking.simulate`) or batched with others.
"""

from __future__ import annotations

import numpy as np

from .._kernels import pair_kernel
from .._validate import as_choice, as_covariances, as_float_array, as_instance
from .model import inverse_condition, pair_index

__all__ = [
    "STRATEGIES",
    "CRITERIA",
    "NAMES",
    "candidates",
    "PairChooser",
    "choose_pairs",
]

#: The paper's three strategies (Section V-A).
STRATEGIES = ("best-pair", "best-partner", "fixed-pair")

#: Other pair choosers, beyond the paper: optimal design on the filter's information, an oracle
#: that knows the target's control, and a random pair.
CRITERIA = ("d-optimal", "a-optimal", "e-optimal", "exact-icn", "random")

#: Every name :func:`~obslib.tracking.simulate` and the batch engine accept.
NAMES = STRATEGIES + CRITERIA


def candidates(setup, strategy: str) -> np.ndarray:
    """Which pairs (in ``(i, j)`` order, ``model.pair_index``) a strategy
    chooses among, ``(P,)`` bool.

    Best pair and the :data:`CRITERIA`: all; best partner: the pairs containing the anchor (in
    the order of the partner's index); fixed pair: that pair alone.

    Examples
    --------
    Of the 15 pairs of six sensors, the anchor is in 5:

    >>> from obslib.tracking import PAPER_CIRCLE
    >>> from obslib.tracking.choosers import candidates
    >>> [int(candidates(PAPER_CIRCLE, s).sum())
    ...  for s in ("best-pair", "best-partner", "fixed-pair")]
    [15, 5, 1]
    """
    from .setup import TrackingSetup

    as_instance(setup, TrackingSetup, "setup")
    as_choice(strategy, NAMES, "strategy")
    ii, jj = pair_index(setup.n_sensors)
    if strategy == "fixed-pair":
        i, j = sorted(setup.fixed_pair)
        return (ii == i) & (jj == j)
    if strategy == "best-partner":
        return (ii == setup.anchor) | (jj == setup.anchor)
    return np.ones(ii.size, dtype=bool)


def mahalanobis_sq(vx, vy, p00, p01, p10, p11):
    """:math:`v^T \\Sigma^{-1} v` for :math:`\\Sigma = [[p_{00}, p_{01}], [p_{10}, p_{11}]]`
    (broadcasting), from the adjugate:
    :math:`(p_{11} v_x^2 - (p_{01} + p_{10}) v_x v_y + p_{00} v_y^2) / \\det \\Sigma`.

    Where :math:`\\det \\Sigma` is not a normal floating-point number (a covariance of scale
    1e-160 has a determinant that underflows), numerator and determinant are evaluated with
    :math:`\\Sigma` divided by its largest entry, which leaves the ratio unchanged.

    Examples
    --------
    :math:`\\Sigma = \\operatorname{diag}(4, 1)`, :math:`v = (2, 1)`: :math:`4/4 + 1/1 = 2`.

    >>> from obslib.tracking.choosers import mahalanobis_sq
    >>> float(mahalanobis_sq(2.0, 1.0, 4.0, 0.0, 0.0, 1.0))
    2.0
    """
    dm2 = p11 * (vx * vx)
    dm2 -= (p01 + p10) * (vx * vy)
    dm2 += p00 * (vy * vy)
    det = p00 * p11 - p01 * p10
    small = ~(np.abs(det) >= 1e-290) | ~(np.abs(det) <= 1e290)
    if small.any():
        top = np.maximum(np.maximum(np.abs(p00), np.abs(p11)), np.abs(p01))
        top = np.where(small, top, 1.0)
        q00, q01, q10, q11 = p00 / top, p01 / top, p10 / top, p11 / top
        num = q11 * (vx * vx) - (q01 + q10) * (vx * vy) + q00 * (vy * vy)
        alt = num / (q00 * q11 - q01 * q10) / top
        dm2 = np.where(small, alt, dm2)
        dm2 = np.array(dm2, dtype=float)
        return dm2
    dm2 /= det
    return dm2


def scaled_rows(vx, vy, c, maha):
    """The rows of the pair bound, :math:`v = \\hat x - p_i` ``(M, K)`` for ``M`` estimates and
    ``K`` sensors, rescaled in place to their Mahalanobis length where ``maha`` ``(M,)`` is set
    (covariance entries ``c = (p00, p01, p10, p11)``, each ``(M,)``) and divided by the longest
    row of each estimate, as :func:`obslib.pair_bounds` normalises (the bound is invariant under
    scaling the rows and :math:`u_{\\max}` together).

    Returns
    -------
    vx, vy : ndarray, shape (M, K)
    inv : ndarray, shape (M,)
        :math:`1 / \\text{scale}^2`, the factor of :math:`u_{\\max}^2`.

    Examples
    --------
    Euclidean rows :math:`(3, 4)` and :math:`(0, 1)` are divided by the longer one's length 5:

    >>> import numpy as np
    >>> from obslib.tracking.choosers import scaled_rows
    >>> vx, vy = np.array([[3.0, 0.0]]), np.array([[4.0, 1.0]])
    >>> c = (np.ones(1), np.zeros(1), np.zeros(1), np.ones(1))
    >>> vx, vy, inv = scaled_rows(vx, vy, c, np.array([False]))
    >>> vx.round(12).tolist(), vy.round(12).tolist(), inv.round(12).tolist()
    ([[0.6, 0.0]], [[0.8, 0.2]], [0.04])
    """
    e2 = vx * vx + vy * vy
    if not (e2 > 0).all():
        raise ValueError("an estimate is not finite or sits on a sensor")
    if maha.any():
        dm2 = mahalanobis_sq(vx, vy, *(x[:, None] for x in c))
        n2 = np.where(maha[:, None], dm2, e2)
        f = np.sqrt(n2 / e2)
        vx *= f
        vy *= f
    else:
        n2 = e2
    inv = 1.0 / _row_max(n2)  # 1 / scale^2
    sc = np.sqrt(inv)[:, None]
    vx *= sc
    vy *= sc
    return vx, vy, inv


def _row_max(a) -> np.ndarray:
    """``a.max(axis=1)`` for a few columns, as an elementwise maximum over them (the same
    values; 7 us against 40 us for 1000 rows of 6)."""
    m = a[:, 0].copy()
    for c in range(1, a.shape[1]):
        np.maximum(m, a[:, c], out=m)
    return m


class PairChooser:
    """The strategies' picks for ``R`` runs at once, without per-step validation.

    Built once per batched pass from each run's candidate pairs ``cand`` (``(R, P)`` bool,
    :func:`candidates`) and metric (``maha``, ``(R,)`` bool). Calling it with the runs'
    estimates and covariance entries returns the chosen pair's index (in
    ``model.pair_index`` order) and bound: the rows of
    ``scaled_rows``, then the kernel of :func:`obslib.pair_bounds` for the run's candidate
    pairs only. The pick is the first maximum among the candidates in ``(i, j)`` order.

    Runs of the :data:`CRITERIA` (``kinds``, ``(R,)``: ``"bound"`` for the paper's strategies
    or a criterion's name) choose among all pairs by ``information_scores`` (with the
    setup's ``Q`` and ``R``), ``icn_scores`` or the ``draws`` ``(R, steps + 1)`` of
    ``pair_draws``.

    Runs with a single candidate (the fixed pair) need no scores to choose, and the criteria do
    not compute the bound, so the call leaves their bound out (NaN) (the rows
    ``deferred``); :meth:`deferred_bounds` evaluates it afterwards over whole runs at once.
    """

    def __init__(self, sensors, cand, maha, u2, kinds=None, Q=None, R=None, draws=None):
        self.sx = sensors[:, 0].copy()
        self.sy = sensors[:, 1].copy()
        self.n = n = sensors.shape[0]
        self.ii, self.jj = pair_index(n)
        self.maha = np.asarray(maha, dtype=bool)
        self.u2 = float(u2)
        R_ = cand.shape[0]
        kinds = np.full(R_, "bound", dtype=object) if kinds is None else np.asarray(kinds, object)
        by_bound = kinds == "bound"
        counts = cand.sum(axis=1)
        if (counts == 0).any():
            raise ValueError("a run has no candidate pair")
        self.best = np.empty(R_, dtype=int)
        self.bound = np.full(R_, np.nan)
        self.single = np.flatnonzero(by_bound & (counts == 1))
        self.best[self.single] = np.nonzero(cand[self.single])[1]
        self.multi = np.flatnonzero(by_bound & (counts > 1))
        self.groups = []
        for c in np.unique(counts[self.multi]):
            rows = self.multi[counts[self.multi] == c]
            cidx = np.nonzero(cand[rows])[1].reshape(rows.size, int(c))  # ascending pair index
            loc = np.searchsorted(self.multi, rows)  # rows within the multi-candidate block
            fi = loc[:, None] * n + self.ii[cidx]
            fj = loc[:, None] * n + self.jj[cidx]
            self.groups.append((rows, loc, cidx, fi, fj, np.arange(rows.size)))
        self.maha_multi = self.maha[self.multi]
        # the criteria's rows; their bound, like the single candidates', is evaluated afterwards
        self.criteria = [(c, np.flatnonzero(kinds == c)) for c in CRITERIA if (kinds == c).any()]
        self.deferred = np.flatnonzero(~by_bound | (counts == 1))
        self.Q = None if Q is None else as_float_array(Q, "Q")
        self.W = None if R is None else np.linalg.inv(as_float_array(R, "R"))
        self.draws = draws

    def __call__(self, xx, xy, p00, p01, p10, p11, control=None, k: int = 0):
        """Pick for every run at estimates ``xx, xy`` with covariance entries ``p00 .. p11``
        (each ``(R,)``); ``control`` ``(R, 2)`` is the targets' control for ``"exact-icn"``
        and ``k`` the step (0-based) for ``"random"``. Returns the pair indices and the bounds
        (NaN for the rows of ``deferred``)."""
        if self.groups:
            m = self.multi
            vx = xx[m, None] - self.sx
            vy = xy[m, None] - self.sy
            vx, vy, inv = scaled_rows(vx, vy, (p00[m], p01[m], p10[m], p11[m]), self.maha_multi)
            u2s = self.u2 * inv
            for rows, loc, cidx, fi, fj, ar in self.groups:
                w = pair_kernel(vx.take(fi), vy.take(fi), vx.take(fj), vy.take(fj), u2s[loc, None])
                pick = w.argmax(axis=1)
                self.best[rows] = cidx[ar, pick]
                self.bound[rows] = w[ar, pick]
        elif not (np.isfinite(xx).all() and np.isfinite(xy).all()):
            raise ValueError("an estimate is not finite")
        for name, r in self.criteria:
            if name == "random":
                self.best[r] = self.draws[r, k]
                continue
            hx = xx[r, None] - self.sx  # Jacobian rows (xhat - p_i)^T, (M, N)
            hy = xy[r, None] - self.sy
            if name == "exact-icn":
                self.best[r] = _icn_picks(hx, hy, control[r], self.ii, self.jj)
                continue
            else:
                q = self.Q
                pp = (p00[r] + q[0, 0], p01[r] + q[0, 1], p10[r] + q[1, 0], p11[r] + q[1, 1])
                score = information_scores(name, hx, hy, pp, self.W, self.ii, self.jj)
            self.best[r] = score.argmax(axis=1)  # the first maximum: the smallest (i, j)
        return self.best.copy(), self.bound.copy()

    def deferred_bounds(self, picks, est, cov) -> np.ndarray:
        """The paper's bound of the picks of the ``deferred`` rows (single candidates and
        criteria) over whole runs: ``picks`` ``(len(deferred), T)`` pair indices, ``est``
        ``(R, T, 2)`` and ``cov`` ``(R, T, 2, 2)`` of all runs in; ``(len(deferred), T)`` out."""
        r = self.deferred
        T = est.shape[1]
        k = np.asarray(picks).reshape(-1)
        val = fixed_pair_bound(self.sx, self.sy, self.ii[k], self.jj[k], self.u2,
                               est[r].reshape(-1, 2), cov[r].reshape(-1, 2, 2),
                               np.repeat(self.maha[r], T))
        return val.reshape(r.size, T)


def fixed_pair_bound(sx, sy, i, j, u2, x, c, maha) -> np.ndarray:
    """Theorem 4's bound of the pair ``(i[m], j[m])`` at estimate ``x[m]`` (covariance ``c[m]``,
    Mahalanobis where ``maha[m]``), ``(M,)``: the rows of ``scaled_rows`` for the pair's two
    sensors only, in chunks that stay in cache.

    Examples
    --------
    With Euclidean distances it is :func:`obslib.pair_bounds` of the pair:

    >>> import numpy as np
    >>> import obslib as ob
    >>> from obslib.tracking.choosers import fixed_pair_bound
    >>> sensors = np.array([[0.0, 0.0], [4.0, 0.0], [1.0, 3.0]])
    >>> x = np.array([[2.0, 1.0]])
    >>> b = fixed_pair_bound(sensors[:, 0], sensors[:, 1], np.array([0]),
    ...                      np.array([2]), 0.25, x, np.eye(2)[None],
    ...                      np.array([False]))
    >>> W = ob.pair_bounds(sensors, x, 0.5)
    >>> bool(np.isclose(b[0], W[0, 2, 0], rtol=1e-12))
    True
    """
    out = np.empty(x.shape[0])
    step = 1 << 14
    for a in range(0, x.shape[0], step):
        sl = slice(a, a + step)
        ie, je = i[sl], j[sl]
        vx = x[sl, 0, None] - np.stack([sx[ie], sx[je]], axis=1)
        vy = x[sl, 1, None] - np.stack([sy[ie], sy[je]], axis=1)
        cs = c[sl]
        vx, vy, inv = scaled_rows(vx, vy, (cs[:, 0, 0], cs[:, 0, 1], cs[:, 1, 0], cs[:, 1, 1]),
                                  maha[sl])
        out[sl] = pair_kernel(vx[:, 0], vy[:, 0], vx[:, 1], vy[:, 1], u2 * inv)
    return out


def pair_draws(seed: int, steps: int, n_pairs: int) -> np.ndarray:
    """The ``"random"`` chooser's picks for the ``steps + 1`` choices of a run (the last is the
    pair after the last step): pair indices uniform on ``0 .. n_pairs - 1``, drawn from
    ``numpy.random.default_rng([1, seed])``, a stream apart from the run's noise table
    (``default_rng(seed)``), so the noise stays common to all strategies.

    Examples
    --------
    >>> d = pair_draws(0, 314, 15)
    >>> d.shape, bool(d.min() >= 0 and d.max() < 15)
    ((315,), True)
    """
    return np.random.default_rng([1, int(seed)]).integers(0, n_pairs, size=steps + 1)


def information_scores(name: str, hx, hy, pp, W, ii, jj) -> np.ndarray:
    """Scores of every pair ``(ii[p], jj[p])`` by an optimal-design criterion, higher is better,
    ``(M, P)``: :math:`\\det J`, :math:`-\\operatorname{tr} J^{-1}` or
    :math:`\\lambda_{\\min}(J)` for ``"d-optimal"``, ``"a-optimal"``, ``"e-optimal"``.

    ``hx, hy`` ``(M, N)`` are the Jacobian rows :math:`(\\hat x - p_i)^T` of every sensor,
    ``pp`` the entries ``(p00, p01, p10, p11)`` of the predicted covariance :math:`\\Sigma^-`
    (each ``(M,)``) and ``W`` ``(2, 2)`` the inverse of the measurement noise :math:`R`
    (row 0 for the pair's sensor ``i``, row 1 for ``j``). Closed forms for 2 x 2 matrices:
    :math:`J = (\\Sigma^-)^{-1} + H^T W H` from the adjugate, then its determinant, trace and
    smallest eigenvalue.

    Examples
    --------
    Prior :math:`\\Sigma^- = I`, unit noise and orthogonal rows give :math:`J = 2 I`:

    >>> import numpy as np
    >>> from obslib.tracking.choosers import information_scores
    >>> hx, hy = np.array([[1.0, 0.0]]), np.array([[0.0, 1.0]])
    >>> pp = (np.ones(1), np.zeros(1), np.zeros(1), np.ones(1))
    >>> ii, jj = np.array([0]), np.array([1])
    >>> [float(information_scores(name, hx, hy, pp, np.eye(2), ii, jj)[0, 0])
    ...  for name in ("d-optimal", "a-optimal", "e-optimal")]
    [4.0, -1.0, 2.0]
    """
    p00, p01, p10, p11 = (x[:, None] for x in pp)
    det_p = p00 * p11 - p01 * p10
    a00, a11, a01 = p11 / det_p, p00 / det_p, -0.5 * (p01 + p10) / det_p
    xi, yi, xj, yj = hx[:, ii], hy[:, ii], hx[:, jj], hy[:, jj]
    w00, w11, w01 = W[0, 0], W[1, 1], 0.5 * (W[0, 1] + W[1, 0])
    j00 = a00 + (w00 * xi * xi + 2 * w01 * xi * xj + w11 * xj * xj)
    j11 = a11 + (w00 * yi * yi + 2 * w01 * yi * yj + w11 * yj * yj)
    j01 = a01 + (w00 * xi * yi + w01 * (xi * yj + xj * yi) + w11 * xj * yj)
    det = j00 * j11 - j01 * j01
    if name == "d-optimal":
        return det
    tr = j00 + j11
    if name == "a-optimal":
        return -(tr / det)
    half = 0.5 * (j00 - j11)
    lmax = 0.5 * tr + np.sqrt(half * half + j01 * j01)
    return det / lmax


def icn_scores(hx, hy, control, ii, jj) -> np.ndarray:
    """The exact :math:`C^{-1}` of :math:`[(\\hat x - p_i)^T; (\\hat x - p_j)^T; u^T]` for every
    pair ``(ii[p], jj[p])``, ``(M, P)``: rows ``hx, hy`` ``(M, N)``, controls ``(M, 2)``.

    Examples
    --------
    Orthogonal unit rows and a static target: :math:`C^{-1} = 1`; parallel rows: 0.

    >>> import numpy as np
    >>> from obslib.tracking.choosers import icn_scores
    >>> hx, hy = np.array([[1.0, 0.0, 2.0]]), np.array([[0.0, 1.0, 0.0]])
    >>> ii, jj = np.array([0, 0]), np.array([1, 2])
    >>> icn_scores(hx, hy, np.zeros((1, 2)), ii, jj).round(12).tolist()
    [[1.0, 0.0]]
    """
    M, P = hx.shape[0], ii.size
    stack = np.empty((M, P, 3, 2))
    stack[:, :, 0, 0], stack[:, :, 0, 1] = hx[:, ii], hy[:, ii]
    stack[:, :, 1, 0], stack[:, :, 1, 1] = hx[:, jj], hy[:, jj]
    stack[:, :, 2, :] = as_float_array(control, "control")[:, None, :]
    return inverse_condition(stack)


def _icn_picks(hx, hy, control, ii, jj) -> np.ndarray:
    """``icn_scores(hx, hy, control, ii, jj).argmax(axis=1)`` without the exact value of every
    pair: the screen of ``adversary.adversary_moves``, maximised.

    :math:`C^{-1}` increases with :math:`\\det G / \\operatorname{tr}^2 G` of the stacked rows,
    here :math:`(h_i \\times h_j)^2 + (h_i \\times u)^2 + (h_j \\times u)^2` over
    :math:`(|h_i|^2 + |h_j|^2 + |u|^2)^2` from per-sensor terms; the pairs within ``1e-11`` of
    a row's largest ratio (the screen's rounding is some 1e-15) contain the exact maximiser,
    and only they get ``icn_scores``'s exact value; the first exact maximum wins, as
    ``argmax``. Rows with a non-finite ratio or extreme lengths get every pair's exact
    value. (200 estimates x 15 pairs: 0.3 ms against 1.0 ms.)"""
    u = as_float_array(control, "control")
    ux, uy = u[:, 0, None], u[:, 1, None]
    with np.errstate(all="ignore"):  # extreme scales: such rows take the exact path below
        cu = hx * uy - hy * ux  # h_k x u, (M, N)
        nn = hx * hx + hy * hy
        cross = hx[:, ii] * hy[:, jj] - hy[:, ii] * hx[:, jj]
        tr = nn[:, ii] + nn[:, jj] + (ux * ux + uy * uy)
        q = (cross * cross + cu[:, ii] ** 2 + cu[:, jj] ** 2) / (tr * tr)
    picks = np.empty(hx.shape[0], dtype=int)
    # far from 1 the squares may under- or overflow: those rows take the exact path
    bad = ~np.isfinite(q).all(axis=1) | ~((tr > 1e-100) & (tr < 1e100)).all(axis=1)
    if bad.any():
        picks[bad] = icn_scores(hx[bad], hy[bad], u[bad], ii, jj).argmax(axis=1)
    good = np.flatnonzero(~bad)
    q = q[good]
    rows, kk = np.nonzero(q >= q.max(axis=1, initial=-np.inf)[:, None] - 1e-11)
    r = good[rows]
    stack = np.empty((r.size, 3, 2))
    stack[:, 0, 0], stack[:, 0, 1] = hx[r, ii[kk]], hy[r, ii[kk]]
    stack[:, 1, 0], stack[:, 1, 1] = hx[r, jj[kk]], hy[r, jj[kk]]
    stack[:, 2, :] = u[r]
    exact = inverse_condition(stack)
    order = np.lexsort((kk, -exact, r))  # by row, then value (largest first), then pair index
    first = np.ones(order.size, dtype=bool)
    first[1:] = r[order][1:] != r[order][:-1]
    picks[r[order[first]]] = kk[order[first]]
    return picks


def choose_pairs(setup, strategy: str, xhat, cov, control=None):
    """The pair a chooser picks at estimates ``xhat`` ``(B, 2)`` with covariances ``cov``
    ``(B, 2, 2)``, validated (:class:`PairChooser` with one run per estimate).

    ``strategy`` is one of the paper's :data:`STRATEGIES` or a state-based criterion
    (``"d-optimal"``, ``"a-optimal"``, ``"e-optimal"`` with the setup's ``Q`` and ``R``;
    ``"exact-icn"`` with the targets' ``control`` ``(B, 2)``). ``"random"`` has no state-based
    pick: its picks are ``pair_draws`` of the run's seed.

    Returns
    -------
    pairs : ndarray of int, shape (B, 2)
        0-based sensor indices, ``pairs[:, 0] < pairs[:, 1]``.
    bound : ndarray, shape (B,)
        The chosen pair's bound (Theorem 4, the setup's metric).

    Examples
    --------
    >>> import numpy as np
    >>> from obslib.tracking import PAPER_CIRCLE
    >>> x, cov = [[5.5, 3.5]], [0.5 * np.eye(2)]
    >>> pairs, bound = choose_pairs(PAPER_CIRCLE, "best-pair", x, cov)
    >>> pairs.tolist(), bound.round(4).tolist()
    ([[3, 5]], [0.8736])
    >>> # the criteria disagree here
    >>> [choose_pairs(PAPER_CIRCLE, name, x, cov)[0][0].tolist()
    ...  for name in ("d-optimal", "a-optimal", "e-optimal")]
    [[0, 2], [2, 5], [3, 5]]
    """
    from .._validate import as_points
    from .setup import MAX_COV_SCALE, TrackingSetup

    as_instance(setup, TrackingSetup, "setup")
    as_choice(strategy, NAMES, "strategy")
    if strategy == "random":
        raise ValueError("the random chooser has no state-based pick: its picks are "
                         "pair_draws(seed, steps, n_pairs)")
    x = as_points(np.atleast_2d(as_float_array(xhat, "xhat")), "xhat")
    b = x.shape[0]
    if cov is None and setup.metric == "euclidean" and strategy in STRATEGIES:
        c = np.broadcast_to(np.eye(2), (b, 2, 2))
    else:
        c = as_covariances(cov, b, MAX_COV_SCALE)
    if strategy == "exact-icn":
        if control is None:
            raise ValueError("exact-icn needs the targets' control, shape (B, 2)")
        u = as_points(np.atleast_2d(as_float_array(control, "control")), "control")
        if u.shape[0] != b:
            raise ValueError(f"control must have one row per estimate ({b}), got {u.shape[0]}")
    else:
        u = np.zeros((b, 2))
    cand = np.broadcast_to(candidates(setup, strategy), (b, len(pair_index(setup.n_sensors)[0])))
    maha = np.full(b, setup.metric == "mahalanobis")
    kinds = [strategy if strategy in CRITERIA else "bound"] * b
    ch = PairChooser(setup.sensor_array, cand, maha, setup.u_max**2, kinds, setup.Q, setup.R)
    best, bound = ch(x[:, 0].copy(), x[:, 1].copy(), *(c[:, a, e].copy() for a in (0, 1)
                                                      for e in (0, 1)), u, 0)
    if ch.deferred.size:
        bound[ch.deferred] = ch.deferred_bounds(best[ch.deferred, None], x[:, None, :],
                                                c[:, None])[:, 0]
    return np.stack([ch.ii[best], ch.jj[best]], axis=1), bound
