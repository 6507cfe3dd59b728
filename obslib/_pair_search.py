"""Each target's heaviest sensor pairs from geometry, found without evaluating most pairs: the
search behind the greedy and the relaxed matching of :mod:`obslib.assignment` (and, for weights
given, the greedy's heads from them, :class:`WeightHeads`).

A pair's weight (Theorem 4's bound, :func:`obslib._kernels.pair_kernel`) is at most the inverse
condition number of its two rows :math:`a, b` (:math:`\\sqrt{\\lambda_{\\min}/\\lambda_{\\max}}` of
their Gram matrix; the control only adds to :math:`\\lambda_{\\max}`). Writing
:math:`b = s R_{90^\\circ + \\varphi} a` (:math:`s = |b|/|a|`, :math:`R` a rotation), the Gram
matrix has trace :math:`|a|^2 (1 + s^2)` and determinant :math:`|a|^4 s^2 \\cos^2\\varphi`, so that
ratio is at least :math:`\\tau` if and only if

.. math::

    2 s |\\cos\\varphi| \\ge \\frac{2\\tau}{1 + \\tau^2}\\,(1 + s^2).

As :math:`1 + s^2 \\ge 2 s`, this forces :math:`|\\sin\\varphi| \\le (1 - \\tau^2)/(1 + \\tau^2)`,
and :math:`\\tau \\le s \\le 1/\\tau`: the second row of a pair of weight :math:`\\ge \\tau > 0`
lies within :math:`\\delta = \\arcsin((1 - \\tau^2)/(1 + \\tau^2)) < 90^\\circ` of the first row
turned by :math:`+90^\\circ` (when :math:`\\cos\\varphi > 0`) or :math:`-90^\\circ`, in which case
the first lies within :math:`\\delta` of the second turned by :math:`+90^\\circ`. With a target's
rows sorted by angle, each pair of weight :math:`\\ge \\tau` is therefore found exactly once among
the rows in the window :math:`[\\theta + 90^\\circ - \\delta, \\theta + 90^\\circ + \\delta]` of
each row's angle :math:`\\theta` (read off angle bins), screened by the distance bound
:math:`\\text{weight}^2 \\le r_{\\min} / (r_{\\max} + u^2)` before the kernel runs. Near the top
(:math:`\\tau` close to 1, :math:`\\delta \\approx 1 - \\tau`) a window holds about
:math:`N \\delta / \\pi` rows, so a target's best pairs cost :math:`O(N \\log N)` instead of
:math:`O(N^2)`. Every pruning test is widened by a relative margin (:data:`_MARGIN`) far above
rounding, so no pair the kernel weighs at or above :math:`\\tau` is missed.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._kernels import mahalanobis_rescale, normalise_rows, pair_kernel
from ._validate import as_cov, as_points, as_u_max, check_distinct, vectors_between

__all__ = ["Geometry", "geometry_iv", "rows_of", "target_rows", "PairSearch", "GeometryHeads",
           "WeightHeads", "keep_top"]

#: Margin (relative) added to every pruning test, so that rounding in the angles, squared lengths
#: and the kernel never drops a pair the kernel would weigh at or above the threshold.
_MARGIN = 1e-9

#: A search returns at most about this many times ``k`` pairs (the heaviest, and their ties).
_KEEP = 1024

#: Largest number of candidate pairs handled in one vectorised block (memory: about 100 bytes each).
_BLOCK = 1 << 20

#: Pairs weighed at a time when every pair is: small blocks, whose temporaries the allocator
#: reuses (blocks of a million pairs cost 0.85 million page faults, 1.2 s of system time, at
#: ``N = 10,000``, ``L = 5,000``).
_ALL_BLOCK = 1 << 16

#: Pairs the kernel weighs at a time: its temporaries (64 KB each) stay below the sizes the
#: allocator hands back to the system between calls (kernel calls on up to a million pairs at
#: once cost a million page faults, 1.1 s of system time, at ``N = 10,000``, ``L = 5,000``).
_KERNEL_BLOCK = 1 << 13


def keep_top(a, b, w, k):
    """The pairs among ``(a, b, w)`` whose weight is at least the ``k``-th largest (ties kept)."""
    if w.size <= k:
        return a, b, w
    kth = np.partition(w, w.size - k)[w.size - k]
    keep = w >= kth
    return a[keep], b[keep], w[keep]


class PairSearch:
    """Pair weights of the targets' normalised rows ``x, y`` ``(L, N)`` (``u2`` ``(L,)``),
    computed on demand; ``n_evaluations`` counts the weights computed."""

    def __init__(self, x, y, u2):
        self.x, self.y, self.u2 = x, y, u2
        self.n_evaluations = 0
        self._buffers = {}

    def weights(self, l, a, b):
        """Weights of the pairs ``(a[k], b[k])`` for target ``l``, :data:`_KERNEL_BLOCK` at a
        time."""
        x, y, u2 = self.x[l], self.y[l], self.u2[l]
        self.n_evaluations += a.size
        w = np.empty(a.size)
        for s in range(0, a.size, _KERNEL_BLOCK):
            sa, sb = a[s:s + _KERNEL_BLOCK], b[s:s + _KERNEL_BLOCK]
            w[s:s + _KERNEL_BLOCK] = pair_kernel(x[sa], y[sa], x[sb], y[sb], u2)
        if not np.isfinite(w).all():  # validation and normalisation exclude it; never feed a NaN on
            raise RuntimeError(f"a pair weight of target {l} is not finite")
        return w

    def best(self, l, idx, k, tau=None):
        """At least the ``k`` heaviest pairs over the sensors ``idx`` for target ``l``.

        Returns ``(a, b, w, floor)``: every pair over ``idx`` of weight ``>= floor`` (in no
        particular order), at least ``k`` of them unless ``floor`` is ``-inf`` (then they are all
        the pairs). ``tau`` is a first threshold to try (default from the number of sensors);
        it is lowered (``1 - tau`` doubled) until ``k`` pairs reach it.
        """
        m = idx.size
        if m * (m - 1) // 2 <= 4 * k:
            return self._all(l, idx, k)
        x, y = self.x[l, idx], self.y[l, idx]
        theta = np.arctan2(y, x)
        order = np.argsort(theta)
        # two turns, so that every window is one contiguous range of positions
        theta = np.concatenate([theta[order], theta[order] + 2.0 * np.pi])
        idx = np.concatenate([idx[order], idx[order]])
        r = x[order] ** 2 + y[order] ** 2
        r = np.concatenate([r, r])
        # angle bins of width 2 pi / nb over the two turns: a window is a range of bins
        nb = 2 * m
        scale = nb / (2.0 * np.pi)
        bins = np.minimum(((theta + np.pi) * scale).astype(np.int64), 2 * nb - 1)
        start = np.zeros(2 * nb + 1, dtype=np.int64)
        np.cumsum(np.bincount(bins, minlength=2 * nb), out=start[1:])
        # the k-th heaviest pair of a uniform scene lies near 1 - 3 sqrt(k) / m
        eps = 4.0 * np.sqrt(k) / m if tau is None else max(1.0 - tau, 1.0 / m)
        while True:
            tau = 1.0 - eps
            if tau <= 0.05:  # the windows would hold nearly every pair
                return self._all(l, idx[:m], k)
            a, b, w = self._window(l, idx, theta, r, start, scale, tau)
            if w.size > _KEEP * k:
                a, b, w = keep_top(a, b, w, _KEEP * k)
                return a, b, w, float(w.min())
            if w.size >= k:
                return a, b, w, tau
            eps *= 2.0

    def _window(self, l, idx, theta, r, start, scale, tau):
        """Every pair of weight ``>= tau`` over the ``m`` sensors ``idx[:m]``, by the angular
        windows of the module's lemma: the rows in the bins overlapping each row's window (rows
        sorted by angle ``theta`` and repeated a turn later, squared lengths ``r``, first
        position of each angle bin ``start``), screened by the distance bound, then the
        kernel."""
        m = idx.size // 2
        kappa = (1.0 - tau * tau) / (1.0 + tau * tau) * (1 + _MARGIN)
        delta = np.arcsin(min(1.0, kappa)) + _MARGIN
        top = start.size - 1
        centre = theta[:m] + (0.5 * np.pi + np.pi)  # + pi: bins count from -pi
        lo = start[np.clip(((centre - delta) * scale).astype(np.int64), 0, top)]
        hi = start[np.clip(((centre + delta) * scale).astype(np.int64) + 1, 0, top)]
        counts = hi - lo
        t2 = tau * tau * (1 - _MARGIN)
        u2 = self.u2[l]
        out_a, out_b, out_w = [], [], []
        ends = np.cumsum(counts)
        begin = 0
        while begin < m:
            base = ends[begin - 1] if begin else 0
            stop = max(begin + 1, int(np.searchsorted(ends, base + _BLOCK, side="right")))
            size = int(ends[stop - 1] - base)
            rows = begin + np.flatnonzero(counts[begin:stop])
            if rows.size:
                p, q = self._candidates(rows, counts[rows], lo[rows], size)
                # the bins hold a few rows beyond the exact window, which the kernel weighs
                # below tau: testing the angle first costs more than it saves (0.46 ms of
                # 1.3 ms per search at N = 10,000)
                rp = np.take(r, p, out=self._scratch("rp", size, float))
                rq = np.take(r, q, out=self._scratch("rq", size, float))
                near = np.minimum(rp, rq, out=self._scratch("near", size, float))
                far = np.maximum(rp, rq, out=rp)
                far += u2
                far *= t2
                keep = np.greater_equal(near, far, out=self._scratch("keep", size, bool))
                p, q = idx[p[keep]], idx[q[keep]]
                w = self.weights(l, p, q)
                hit = w >= tau
                out_a.append(p[hit])
                out_b.append(q[hit])
                out_w.append(w[hit])
            begin = stop
        if not out_w:
            return idx[:0], idx[:0], np.zeros(0)
        return np.concatenate(out_a), np.concatenate(out_b), np.concatenate(out_w)

    def _candidates(self, rows, c, lo, size):
        """Positions ``(p, q)`` of the candidate pairs: row ``rows[k]`` with the ``c[k]`` rows
        from ``lo[k]`` on (``size`` in all), as ``np.repeat`` would give them, built by cumulative
        sums in reused buffers: fresh arrays of this size for every search cost more in page
        faults (7.7 s of system time at N = 10,000, L = 5,000) than the search itself."""
        first = np.cumsum(c) - c  # where each row's candidates start
        p = self._scratch("p", size, np.int64)
        p.fill(0)
        p[first] = np.diff(rows, prepend=0)
        np.cumsum(p, out=p)
        q = self._scratch("q", size, np.int64)
        q.fill(1)
        q[first[1:]] = lo[1:] - (lo[:-1] + c[:-1] - 1)
        q[0] = lo[0]
        np.cumsum(q, out=q)
        return p, q

    def _scratch(self, name, size, dtype):
        """A buffer of ``size`` elements, kept between calls (grown by doubling)."""
        buf = self._buffers.get(name)
        if buf is None or buf.size < size:
            buf = self._buffers[name] = np.empty(max(size, 2 * (0 if buf is None else buf.size)),
                                                 dtype)
        return buf[:size]

    def _all(self, l, idx, k):
        """Every pair over ``idx``, a block of rows at a time (about :data:`_ALL_BLOCK` pairs),
        keeping the heaviest ``_KEEP * k`` and their ties."""
        m = idx.size
        a = b = np.zeros(0, dtype=np.int64)
        w = np.zeros(0)
        i0 = 0
        while i0 < m - 1:
            # rows i0..i1-1 with their partners j > i: (m - 1 - i) pairs each
            i1 = i0 + 1
            while i1 < m - 1 and (i1 - i0 + 1) * (2 * m - i0 - i1 - 2) // 2 <= _ALL_BLOCK:
                i1 += 1
            c = m - 1 - np.arange(i0, i1)
            p, q = self._candidates(np.arange(i0, i1), c, np.arange(i0 + 1, i1 + 1), int(c.sum()))
            sa, sb = idx[p], idx[q]
            a, b, w = keep_top(np.concatenate([a, sa]), np.concatenate([b, sb]),
                               np.concatenate([w, self.weights(l, sa, sb)]), _KEEP * k)
            i0 = i1
        return a, b, w, (-np.inf if w.size == m * (m - 1) // 2 else float(w.min()))


class Geometry(NamedTuple):
    """A validated scene (:func:`geometry_iv`): sensors ``s`` ``(N, 2)``, targets ``t``
    ``(L, 2)``, speed bounds ``u`` ``(L,)`` and covariances ``cov`` ``(L, 2, 2)`` or ``None``."""

    s: np.ndarray
    t: np.ndarray
    u: np.ndarray
    cov: np.ndarray | None

    @property
    def sizes(self) -> tuple:
        """``(N, L)``."""
        return self.s.shape[0], self.t.shape[0]


def geometry_iv(sensors, targets, u_max, cov) -> Geometry:
    """The scene checked as :func:`obslib._validate.vectors_between` checks it, and by it where a
    difference may overflow or a sensor sits on a target, so errors name the same sensor and
    target; nothing of size ``N x L`` is allocated."""
    s, t = as_points(sensors, "sensors"), as_points(targets, "targets")
    n_targets = t.shape[0]
    check_distinct(s)
    with np.errstate(over="ignore"):
        reach = np.abs(s).max(initial=0.0) + np.abs(t).max(initial=0.0)
    on = np.isin(t[:, 0] + 1j * t[:, 1], s[:, 0] + 1j * s[:, 1])
    if not np.isfinite(reach) or on.any():
        vectors_between(s, t, cov)  # raises, naming the sensor and the target
    if cov is not None:
        cov = as_cov(cov, n_targets)
    u = np.broadcast_to(as_u_max(u_max, n_targets), (n_targets,))
    return Geometry(s, t, u, cov)


def rows_of(g: Geometry):
    """The rows ``o_l - p_i`` of every target of the validated scene ``g``, normalised per target
    as :func:`obslib.pair_bounds` normalises them: ``x, y`` ``(L, N)`` and ``u_max^2`` ``(L,)`` in
    the same unit, the input of :func:`obslib._kernels.pair_kernel`.

    Computed a block of targets at a time, so that the memory is that of ``x, y`` (the
    ``(N, L, 2)`` array of differences and its temporaries never exist at once: at ``N = 10,000``,
    ``L = 5,000`` they took 2.4 GB).
    """
    s, t, u, cov = g
    n, n_targets = g.sizes
    x, y, u2 = np.empty((n_targets, n)), np.empty((n_targets, n)), np.empty(n_targets)
    # blocks of 256 KB stay in cache: 0.3 s at N = 10,000, L = 5,000, against 0.8 s for 8 MB
    step = max(1, (1 << 15) // max(n, 1))
    for l0 in range(0, n_targets, step):
        blk = slice(l0, min(l0 + step, n_targets))
        unit = 1.0
        with np.errstate(over="ignore"):  # u_max / unit may exceed the float range: inf, bound 0
            if cov is None:  # o_l - p_i, as vectors_between computes it
                dx, dy = t[blk, 0, None] - s[None, :, 0], t[blk, 1, None] - s[None, :, 1]
            else:
                v, unit = mahalanobis_rescale(t[None, blk, :] - s[:, None, :], cov[blk])
                dx, dy = v[..., 0].T, v[..., 1].T
            _, _, u2[blk] = normalise_rows(dx, dy, u[blk] / unit, out=(x[blk], y[blk]))
    return x, y, u2


def target_rows(sensors, targets, u_max, cov):
    """:func:`rows_of` the scene, validated by :func:`geometry_iv`."""
    return rows_of(geometry_iv(sensors, targets, u_max, cov))


class GeometryHeads:
    """The heads Algorithm 1's kernel (:func:`obslib.assignment.greedy_pairs_batch`) asks for, of
    one instance, from geometry: per target, the list of its pairs of weight at least ``floor``
    over the sensors free when it was filled (:meth:`PairSearch.best`, at least ``k`` of them),
    in greedy order.

    Sensors only leave, so while the list holds a pair of free sensors, the first such pair is
    the target's best; when none is left, the list is refilled over the free sensors with a
    lower threshold.
    """

    def __init__(self, search, n_targets, k, bar=None):
        self.search, self.k, self.bar = search, k, bar  # bar: ticks once per target's first fill
        empty = (np.zeros(0), np.zeros(0, np.int64), np.zeros(0, np.int64))
        self.lists = [empty] * n_targets
        self.pos = [0] * n_targets
        self.floor = [None] * n_targets  # None: never filled

    def heads(self, b, l, free):
        out = np.array([self._head(int(t), free[0]) for t in l.tolist()]).reshape(-1, 3)
        return out[:, 0], out[:, 1].astype(np.int64), out[:, 2].astype(np.int64)

    def _head(self, l, free):
        (w, i, j), pos = self.lists[l], self.pos[l]
        for _ in range(2):  # a fresh list holds free sensors only: at most one refill
            step = 4
            while pos < w.size:  # the first pair of free sensors, in chunks that double
                ok = free[i[pos:pos + step]] & free[j[pos:pos + step]]
                first = int(ok.argmax())
                if ok[first]:
                    self.pos[l] = pos = pos + first
                    return w[pos], i[pos], j[pos]
                pos += step
                step *= 2
            floor = self.floor[l]
            if floor == -np.inf:  # the list held every pair: none is free
                break
            tau = None if floor is None else 1.0 - 2.0 * (1.0 - floor)
            a, b, w, self.floor[l] = self.search.best(l, np.flatnonzero(free), self.k, tau)
            if floor is None and self.bar is not None:
                self.bar.update()
            i, j = np.minimum(a, b), np.maximum(a, b)
            order = np.argsort(-w, kind="stable")
            ws = w[order]
            if (ws[1:] == ws[:-1]).any():  # equal weights: by (i, j) (1.4 s of 8.9 if always)
                order = np.lexsort((j, i, -w))
                ws = w[order]
            w, i, j = self.lists[l] = ws, i[order], j[order]
            pos = 0
        self.pos[l] = pos
        return -np.inf, 0, 0


class WeightHeads:
    """The heads Algorithm 1's kernel (:func:`obslib.assignment.greedy_pairs_batch`) asks for,
    from weights ``w`` ``(B, P, L)`` of the pairs ``(ii, jj)``, ``ii < jj`` in
    ``numpy.triu_indices`` order: a masked ``argmax`` over the pairs (the first maximum is the
    smallest ``(i, j)``)."""

    def __init__(self, w, ii, jj):
        self.w, self.ii, self.jj = w, ii, jj

    @classmethod
    def of(cls, arr):
        """The heads of one instance's validated weights ``arr`` ``(N, N, L)``."""
        ii, jj = np.triu_indices(arr.shape[0], 1)
        return cls(arr[ii, jj][None], ii, jj)

    def heads(self, b, l, free):
        P = self.ii.size
        out_w = np.empty(b.size)
        out_i, out_j = np.empty(b.size, np.int64), np.empty(b.size, np.int64)
        step = max(1, (1 << 22) // max(P, 1))  # rows per block: about 4M weights
        for s in range(0, b.size, step):
            bs, ls = b[s:s + step], l[s:s + step]
            fb = free[bs]
            rows = np.where(fb[:, self.ii] & fb[:, self.jj], self.w[bs, :, ls], -np.inf)
            p = rows.argmax(axis=1)
            out_w[s:s + step] = rows[np.arange(bs.size), p]
            out_i[s:s + step], out_j[s:s + step] = self.ii[p], self.jj[p]
        return out_w, out_i, out_j
