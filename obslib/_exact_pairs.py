"""Exact solver of Problem 1 (unique pair assignment), behind
:func:`obslib.optimal_pair_assignment`.

Branch and bound on the bound of the linear relaxation: the LP's duals ``y >= 0`` (HiGHS via
``scipy.optimize.linprog``, by column generation: :func:`lp_duals`) turn every assignment's value
into ``1^T y`` minus non-negative losses, which prune the search and fix most variables to 0
(reduced-cost fixing). The plain HiGHS 0-1 program (:func:`milp`) is the fallback for searches
past :data:`MAX_NODES` nodes and the reference of the tests.

Every phase watches the deadline: each HiGHS call gets the time left (and is small: the
restricted LPs of the column generation, the reduced 0-1 program), the local search and the
branch and bound check the clock, and running out raises :class:`Stopped` with the best
assignment found so far and the bound.
"""

from __future__ import annotations

import time

import numpy as np

__all__ = ["solve", "milp", "lp_duals", "pair_rows", "memory_bytes", "check_memory", "Stopped",
           "MAX_NODES",
           "MAX_BYTES", "BYTES_PER_VARIABLE", "SEARCH_BYTES", "MILP_BYTES_PER_VARIABLE",
           "SEARCH_MAX_VARIABLES", "HIGHS_SECONDS_PER_VARIABLE"]


class Stopped(RuntimeError):
    """The solver stopped before proving an optimum, at the deadline (``reason = "time"``) or
    because the last 0-1 program would not fit :data:`MAX_BYTES` (``"memory"``): ``triples`` is
    the best assignment found (complete: one pair per target), ``bound`` an upper bound on the
    optimum (``None`` before the LP gave one)."""

    def __init__(self, triples=None, bound=None, reason="time"):
        super().__init__(f"stopped before a proven optimum ({reason})")
        self.triples, self.bound, self.reason = triples, bound, reason


#: Memory the solver may use beyond ``W``: 2 GiB.
MAX_BYTES = 2 << 30

#: Bytes per pair-target variable (``N (N - 1) / 2 * L`` of them) at the solver's peak beyond
#: ``W``: the ``(P, L)`` weights, losses and LP solution and the temporaries over them
#: (measured: 55 at ``L = 200``, ``N = 400``); the branch and bound's option lists add at most
#: :data:`SEARCH_BYTES`.
BYTES_PER_VARIABLE = 64

#: The branch and bound's option lists at their largest (:data:`SEARCH_MAX_VARIABLES` options,
#: about 110 bytes each, measured).
SEARCH_BYTES = 32 << 20

#: Bytes per variable of the HiGHS 0-1 program the search hands over (measured: 830 at
#: ``L = 100``, ``N = 200``); it runs only if the variables left fit :data:`MAX_BYTES`.
MILP_BYTES_PER_VARIABLE = 900


def memory_bytes(n: int, n_targets: int) -> int:
    """Peak memory of :func:`solve` beyond ``W`` (without the 0-1 program the search may hand
    over, which runs only within :data:`MAX_BYTES`), estimated from the number of variables."""
    return BYTES_PER_VARIABLE * (n * (n - 1) // 2) * n_targets + SEARCH_BYTES


def _hi_scale(top: float) -> float:
    """Divisor bringing weights of maximum ``top`` near 1 for HiGHS (1 when already in range).

    HiGHS treats ``|c| >= 1e20`` as infinite and has absolute tolerances near 1e-9: weights far
    outside ``[2**-20, 2**20]`` are divided by a power of two first (the optimum does not change).
    """
    return 1.0 if 2.0**-20 <= top <= 2.0**20 else 2.0 ** (np.frexp(top)[1] - 1)


def pair_rows(n, n_targets, ii, jj, keep):
    """Constraint matrix (target rows, then sensor rows) of the variables ``keep``
    (``p * L + l``)."""
    from scipy.sparse import coo_matrix, vstack

    p_of, l_of = keep // n_targets, keep % n_targets
    col = np.arange(keep.size)
    target_rows = coo_matrix((np.ones(keep.size), (l_of, col)), shape=(n_targets, keep.size))
    sensor_rows = coo_matrix(
        (
            np.ones(2 * keep.size),
            (np.concatenate([ii[p_of], jj[p_of]]), np.concatenate([col, col])),
        ),
        shape=(n, keep.size),
    )
    return vstack([target_rows, sensor_rows]).tocsr()


def milp(arr, time_limit=None, keep=None) -> list:
    """Problem 1 as one HiGHS 0-1 program (``scipy.optimize.milp``) over the variables ``keep``
    (indices ``p * L + l``, default all): its optimal triples. The plain formulation, also the
    reference of the tests."""
    from scipy.optimize import Bounds, LinearConstraint
    from scipy.optimize import milp as highs_milp

    n, n_targets = arr.shape[0], arr.shape[2]
    ii, jj = np.triu_indices(n, 1)
    w = arr[ii, jj, :].reshape(-1)  # variable index p * L + l
    if keep is None:
        keep = np.arange(w.size)
    c = -w[keep]
    top = float(-c.min(initial=0.0))
    if top == 0.0:  # every weight is 0: assigning nothing is optimal (HiGHS cannot rank zeros)
        return []
    c = c / _hi_scale(top)
    options = {"mip_rel_gap": 0.0}  # proven optimum, not HiGHS's default 1e-4 relative gap
    if time_limit:
        options["time_limit"] = time_limit
    res = highs_milp(
        c,
        constraints=LinearConstraint(pair_rows(n, n_targets, ii, jj, keep), -np.inf, 1.0),
        integrality=np.ones(keep.size),
        bounds=Bounds(0, 1),
        options=options,
    )
    if res.status == 1:  # HiGHS's time limit
        raise Stopped
    if res.status != 0:
        raise RuntimeError(f"MILP did not reach a proven optimum: {res.message}")
    chosen = keep[res.x > 0.5]
    p_of, l_of = chosen // n_targets, chosen % n_targets
    return sorted(zip(ii[p_of].tolist(), jj[p_of].tolist(), l_of.tolist()), key=lambda t: t[2])


def lp_duals(wmat, n, ii, jj, deadline=None):
    """Duals ``y >= 0`` (target rows, then sensor rows) of Problem 1's LP relaxation and its
    solution ``x`` (indices ``p * L + l``), or ``(None, None)``.

    Any ``y >= 0`` gives valid bounds below; the LP optimum gives the tightest of this form. It
    is found by column generation: HiGHS solves the LP over each target's heaviest pairs
    (:data:`_FIRST_COLUMNS` per target), every variable is priced with the duals (reduced profit
    ``w_pl - y_l - y_i - y_j``), those with a positive reduced profit join, until none is left
    (then the duals are feasible for the whole LP, to HiGHS's tolerance, and optimal). The LPs
    stay small (at ``L = 100``, ``N = 200``: 0.3 s in all, against more than 60 s for the LP
    over all 2 million variables), and each gets the time left before ``deadline``.
    """
    from scipy.optimize import linprog

    n_pairs, n_targets = wmat.shape
    w = wmat.reshape(-1)
    scale = _hi_scale(float(w.max()))
    k = min(n_pairs, _FIRST_COLUMNS)
    first = np.argpartition(-wmat, k - 1, axis=0)[:k]  # (k, L) each target's heaviest pairs
    cols = np.unique((first * n_targets + np.arange(n_targets)).reshape(-1))
    tol = 1e-9 * float(w.max())
    while True:
        left = _remaining(deadline)
        res = linprog(-w[cols] / scale, A_ub=pair_rows(n, n_targets, ii, jj, cols),
                      b_ub=np.ones(n_targets + n), bounds=(0, None), method="highs",
                      options={} if left is None else {"time_limit": left})
        if res.status == 1:
            raise Stopped
        if res.status != 0:
            return None, None
        y = np.maximum(-np.asarray(res.ineqlin.marginals), 0.0) * scale
        yt, ys = y[:n_targets], y[n_targets:]
        profit = wmat - yt[None, :]
        profit -= ys[ii][:, None]
        profit -= ys[jj][:, None]
        profit = profit.reshape(-1)
        profit[cols] = -np.inf  # in the LP already
        new = np.flatnonzero(profit > tol)
        if new.size == 0:
            x = np.zeros(w.size)
            x[cols] = res.x
            return y, x
        if new.size > _ADDED_COLUMNS * n_targets:  # the most profitable ones
            new = new[np.argpartition(-profit[new], _ADDED_COLUMNS * n_targets)[
                :_ADDED_COLUMNS * n_targets]]
        cols = np.union1d(cols, new)


#: Columns per target in the first restricted LP, and at most that many per target added by
#: each round of pricing (speed only).
_FIRST_COLUMNS = 64
_ADDED_COLUMNS = 64


def _repair(arr, assign, free, tol, deadline=None):
    """Local search on a full assignment ``assign`` (``(L, 2)`` sensors per target), in place.

    Moves: re-pair the four sensors of two targets (three pairings, two ways round) and swap one
    sensor of a target for an unused one; the best improving move is applied until none improves
    by more than ``tol``, or until ``deadline`` (``assign`` is then the last improvement).
    """
    n_targets = assign.shape[0]
    la, lb = np.triu_indices(n_targets, 1)
    tl = np.arange(n_targets)
    while deadline is None or time.perf_counter() < deadline:
        a, b = assign[:, 0], assign[:, 1]
        cur = arr[a, b, tl]
        best_gain, best_move = tol, None
        if la.size:
            s1, s2, s3, s4 = a[la], b[la], a[lb], b[lb]
            base = cur[la] + cur[lb]
            for k, (p, q, r, s) in enumerate(((s1, s3, s2, s4), (s1, s4, s2, s3))):
                for flip in (False, True):
                    x, y = ((r, s), (p, q)) if flip else ((p, q), (r, s))
                    gain = arr[x[0], x[1], la] + arr[y[0], y[1], lb] - base
                    m = int(np.argmax(gain))
                    if gain[m] > best_gain:
                        best_gain, best_move = float(gain[m]), ("pair", m, k, flip)
            # swapping whole pairs between the two targets
            gain = arr[s3, s4, la] + arr[s1, s2, lb] - base
            m = int(np.argmax(gain))
            if gain[m] > best_gain:
                best_gain, best_move = float(gain[m]), ("pair", m, 2, False)
        fr = np.flatnonzero(free)
        if fr.size:
            for side in (0, 1):
                keep = assign[:, 1 - side]
                gain = arr[fr[None, :], keep[:, None], tl[:, None]] - cur[:, None]
                m = int(np.argmax(gain))
                if gain.flat[m] > best_gain:
                    best_gain, best_move = float(gain.flat[m]), ("free", m, side, fr)
        if best_move is None:
            return
        kind, m, k, extra = best_move
        if kind == "pair":
            l1, l2 = la[m], lb[m]
            s1, s2, s3, s4 = assign[l1, 0], assign[l1, 1], assign[l2, 0], assign[l2, 1]
            if k == 2:
                new1, new2 = (s3, s4), (s1, s2)
            else:
                p1, p2 = ((s1, s3), (s2, s4)) if k == 0 else ((s1, s4), (s2, s3))
                new1, new2 = (p2, p1) if extra else (p1, p2)
            assign[l1], assign[l2] = new1, new2
        else:
            l, f = divmod(m, extra.size)
            free[assign[l, k]] = True
            assign[l, k] = extra[f]
            free[extra[f]] = False


def _complete(n, n_targets, triples):
    """A full assignment ``(L, 2)`` and the free-sensor mask from partial ``triples``."""
    assign = np.full((n_targets, 2), -1)
    free = np.ones(n, dtype=bool)
    for i, j, l in triples:
        assign[l] = i, j
        free[i] = free[j] = False
    for l in np.flatnonzero(assign[:, 0] < 0):
        i, j = np.flatnonzero(free)[:2]
        assign[l] = i, j
        free[i] = free[j] = False
    return assign, free


#: Nodes the search may visit before handing the reduced model to HiGHS (bounds the time on
#: adversarial instances; random Fig. 8 instances at L = 20 need 700 to 32,000, about 20 us each).
MAX_NODES = 100_000


def solve(arr, deadline, start, bar=None) -> list:
    """Optimal triples of Problem 1 with weights ``arr`` (validated), by branch and bound from
    the assignment ``start`` (Algorithm 1's); ``deadline`` a ``time.perf_counter`` time or None.

    Raises :class:`Stopped` at the deadline, with the best assignment found and the bound;
    ``bar`` (a tqdm bar or None) shows the phase and the gap.
    """
    n, n_targets = arr.shape[0], arr.shape[2]
    state = {"triples": list(start), "value": _value(arr, start), "bound": None}
    try:
        return _solve(arr, deadline, state, bar)
    except Stopped as e:
        search = state.get("search")
        if search is not None and search.value > state["value"]:
            state["triples"], state["value"] = search.best, search.value
        assign, _ = _complete(n, n_targets, state["triples"])  # one pair per target
        triples = [(int(min(a, b)), int(max(a, b)), l) for l, (a, b) in enumerate(assign.tolist())]
        raise Stopped(triples, state["bound"], e.reason) from None


def _phase(bar, name, state):
    if bar is not None:
        bar.set_description(name)
        if state["bound"] is not None:
            bar.set_postfix(gap=f"{state['bound'] - state['value']:.3g}", refresh=False)
        bar.update()


def _solve(arr, deadline, state, bar):
    n, n_targets = arr.shape[0], arr.shape[2]
    ii, jj = np.triu_indices(n, 1)
    wmat = arr[ii, jj, :]  # (P, L)
    if float(wmat.max(initial=0.0)) == 0.0:
        return []
    _phase(bar, "LP relaxation", state)
    y, x = lp_duals(wmat, n, ii, jj, deadline)
    if y is None:
        return milp(arr, _remaining(deadline))
    yt, ys = y[:n_targets], y[n_targets:]
    loss = yt[None, :] + ys[ii][:, None] + ys[jj][:, None] - wmat
    # LP duals are feasible up to HiGHS's tolerance: raise target duals so no loss is negative
    # (any y >= 0 keeps the identity and the bounds valid)
    yt = yt + np.maximum(-loss.min(axis=0), 0.0)
    loss = np.maximum(yt[None, :] + ys[ii][:, None] + ys[jj][:, None] - wmat, 0.0)
    bound = float(yt.sum() + ys.sum())
    state["bound"] = bound
    tol = 1e-10 * bound
    _remaining(deadline)

    # incumbent: Algorithm 1 and the LP's rounding completed in order of loss, each improved by
    # local search (entries above 1/2 share no row, so they form an assignment)
    _phase(bar, "incumbent", state)
    flat_loss, flat_w = loss.reshape(-1), wmat.reshape(-1)
    # candidates in order: the LP's entries above 1/2, then by loss (and weight); an assignment
    # needs at most L of them, so the smallest losses are sorted, not all P L
    few = min(flat_loss.size, 64 * n_targets)
    cand = np.union1d(np.flatnonzero(x >= 0.5), np.argpartition(flat_loss, few - 1)[:few])
    cand = cand[np.lexsort((-flat_w[cand], flat_loss[cand], x[cand] < 0.5))]
    used_t, used_s, picks = np.zeros(n_targets, bool), np.zeros(n, bool), []
    for v in cand.tolist():
        p, l = divmod(v, n_targets)
        i, j = int(ii[p]), int(jj[p])
        if not (used_t[l] or used_s[i] or used_s[j]):
            used_t[l] = used_s[i] = used_s[j] = True
            picks.append((i, j, l))
            if len(picks) == n_targets:
                break
    for triples in (list(state["triples"]), picks):
        assign, free = _complete(n, n_targets, triples)
        _repair(arr, assign, free, tol, deadline)
        val = float(arr[assign[:, 0], assign[:, 1], np.arange(n_targets)].sum())
        if val > state["value"]:
            state["value"] = val
            state["triples"] = [(int(min(a, b)), int(max(a, b)), l)
                                for l, (a, b) in enumerate(assign.tolist())]
        _remaining(deadline)
    best_val, best = state["value"], state["triples"]
    if bound - best_val <= tol:
        return best

    # reduced-cost fixing: a variable whose loss reaches the gap is in no better assignment
    keep = np.flatnonzero(flat_loss < bound - best_val - tol)
    if keep.size <= SEARCH_MAX_VARIABLES:
        _phase(bar, "branch and bound", state)
        keep = keep[np.lexsort((-flat_w[keep], flat_loss[keep]))]
        _remaining(deadline)
        search = _Search(arr, ii, jj, yt, ys, loss, keep, bound, best_val, best, tol, deadline,
                         bar)
        state["search"] = search
        # Search first for assignments within a small gap of the bound, widening it
        # geometrically: a tight floor prunes hard, and an assignment found above it is a
        # near-optimal incumbent for the rest of the search (L = 15: 0.07 s against 0.30 s from
        # the local-search incumbent).
        gap = bound - best_val
        floor = bound - gap / 64
        try:
            while True:
                search.run(max(floor, best_val))
                if search.value > floor or floor <= best_val:
                    break
                floor = bound - 1.5 * (bound - floor)
            return search.best
        except _TooLarge:
            # the incumbent's gap (not the floor's) decides which variables may still matter
            best_val, best = search.value, search.best
            keep = np.flatnonzero(flat_loss < bound - best_val - tol)
            search.tops = search.sops = None  # HiGHS needs the memory more
    # the search cannot finish (past MAX_NODES, or too many variables left): HiGHS's 0-1
    # program over the variables left, if it fits the memory and can start before the deadline
    _phase(bar, "0-1 program (HiGHS)", state)
    if memory_bytes(n, n_targets) + keep.size * MILP_BYTES_PER_VARIABLE > MAX_BYTES:
        raise Stopped(reason="memory")
    budget = None
    if deadline is not None:  # HiGHS reads the model before its clock applies: leave it that
        budget = _remaining(deadline) - HIGHS_SECONDS_PER_VARIABLE * keep.size
        if budget <= 0:
            raise Stopped  # it would still be reading the model at the deadline
    del loss, flat_loss, wmat, flat_w
    alt = milp(arr, budget, keep)
    return alt if _value(arr, alt) > best_val else best


#: Most variables the branch and bound takes on after reduced-cost fixing; beyond, its nodes
#: cost milliseconds each and building its option lists alone takes seconds, so HiGHS's 0-1
#: program takes over at once (speed, and the time limit's resolution).
SEARCH_MAX_VARIABLES = 1 << 18

#: Seconds HiGHS spends per variable reading a 0-1 program beyond its time limit (measured:
#: 2.0 s for 1 million variables, 4.0 s for 2 million, 0.5 to 1 s for 428,000).
HIGHS_SECONDS_PER_VARIABLE = 2e-6


def _remaining(deadline):
    if deadline is None:
        return None
    left = deadline - time.perf_counter()
    if left <= 0:
        raise Stopped
    return left


def _value(arr, triples) -> float:
    return float(sum(arr[i, j, l] for i, j, l in triples))


class _TooLarge(Exception):
    """The search passed :data:`MAX_NODES`."""


#: More options than any branching candidate has (the first candidate always wins).
_NO_OPTIONS = 1 << 62


class _Search:
    """Depth-first branch and bound over targets for :func:`solve`.

    With ``bound = 1^T y`` and losses ``loss[p, l] >= 0``, an assignment's value is ``bound``
    minus the losses of its triples, ``y_l`` of each unassigned target and ``y_i`` of each unused
    sensor. A node (some targets decided) is pruned when its losses so far plus a lower bound on
    the rest leave no room above the incumbent; the rest is bounded both by the smallest option
    of each open target and by half the smallest option of each free sensor (a triple's loss
    split between its two sensors, an unused sensor costing ``y_i``).
    """

    def __init__(self, arr, ii, jj, yt, ys, loss, keep, bound, best_val, best, tol, deadline,
                 bar=None):
        n, n_targets = arr.shape[0], arr.shape[2]
        self.arr, self.bound, self.tol, self.deadline, self.bar = arr, bound, tol, deadline, bar
        self.value, self.best = best_val, best  # the incumbent
        self.best_val = best_val  # the pruning floor: the incumbent's value or above
        self.yt, self.ys = yt.tolist(), ys.tolist()
        self.tops = [[] for _ in range(n_targets)]  # per target, options (loss, l, i, j) by loss
        self.sops = [[] for _ in range(n)]  # per sensor, the same options
        for s in range(0, keep.size, 1 << 14):  # checking the clock between blocks
            _remaining(deadline)
            part = keep[s:s + (1 << 14)]
            p_of, l_of = part // n_targets, part % n_targets
            for lo, l, i, j in zip(loss.reshape(-1)[part].tolist(), l_of.tolist(),
                                   ii[p_of].tolist(), jj[p_of].tolist()):
                opt = (lo, l, i, j)
                self.tops[l].append(opt)
                self.sops[i].append(opt)
                self.sops[j].append(opt)
        self.nodes = 0
        self.n, self.n_targets = n, n_targets

    def run(self, floor):
        """Search for assignments worth more than ``floor`` (at least the incumbent's value)."""
        _remaining(self.deadline)
        self.best_val = max(floor, self.value)
        self._node(frozenset(range(self.n)), frozenset(range(self.n_targets)), 0.0, [])

    def _node(self, sfree, tfree, spent, chosen):
        self.nodes += 1
        if self.nodes > MAX_NODES:
            raise _TooLarge
        if self.nodes % 16 == 0:  # a node costs up to milliseconds at L = 100
            _remaining(self.deadline)
            if self.bar is not None and self.nodes % 1024 == 0:
                self.bar.set_postfix(gap=f"{self.bound - self.value:.3g}", refresh=False)
                self.bar.update()
        if not tfree:
            val = float(sum(self.arr[i, j, l] for i, j, l in chosen))
            if val > self.best_val + self.tol:
                self.best_val = self.value = val
                self.best = list(chosen)
            return
        limit = self.bound - self.best_val - self.tol - spent  # the rest must lose less
        yt, ys, tops, sops = self.yt, self.ys, self.tops, self.sops
        lbt, tmin = 0.0, {}
        for l in tfree:
            m = yt[l]
            for lo, _, a, b in tops[l]:
                if lo >= m:
                    break
                if a in sfree and b in sfree:
                    m = lo
                    break
            tmin[l] = m
            lbt += m
        if lbt >= limit:
            return
        lbs, smin = 0.0, {}
        for i in sfree:
            m = 2.0 * ys[i]
            for lo, l, a, b in sops[i]:
                if lo >= m:
                    break
                if l in tfree and a in sfree and b in sfree:
                    m = lo
                    break
            smin[i] = m
            lbs += m
        if 0.5 * lbs >= limit:
            return

        # An option (loss, l, i, j) fits when its target is open, its sensors are free and it
        # keeps both bounds below the limit: loss + lbt - tmin[l] < limit and
        # loss + (lbs - smin[i] - smin[j]) / 2 < limit. The search branches on the open target,
        # or (when every target has more than 2) the free sensor, with the fewest options that
        # fit, leaving it unassigned (unused) counted when that fits too; a tie keeps the first
        # in the iteration order of tfree (sfree).
        # Early exit: a candidate replaces the best only with strictly fewer options, so its
        # scan stops once its fitting options, plus the spare one, reach the best's number; only
        # the candidates that win get their list built in full. (Speed only, with the plain loops
        # instead of a generator: the search about 1.8 times as fast at L = 20, same nodes.)
        half = 0.5 * lbs
        options, size = None, _NO_OPTIONS  # the best candidate's options, and their number
        for l in tfree:
            room = limit - (lbt - tmin[l])
            spare = yt[l] < room  # target l may be left unassigned
            cap = size - spare  # with that many fitting options, l no longer has fewer
            opts = []
            # tops[l] holds target l's options (by loss), and l is open: the sensors decide
            for opt in tops[l]:
                lo, _, i, j = opt
                if lo >= room:
                    break
                if (i in sfree and j in sfree
                        and lo + half - 0.5 * (smin[i] + smin[j]) < limit):
                    opts.append(opt)
                    if len(opts) >= cap:
                        break
            if len(opts) >= cap:  # not fewer than the best's: dropped
                continue
            if spare:
                opts.append((yt[l], l, -1, -1))
                opts.sort()
            options, size = opts, len(opts)
            if size <= 1:
                break
        if size > 2:  # a sensor may have fewer (worth the scan only then)
            for i in sfree:
                room = 2.0 * limit - (lbs - smin[i])
                spare = 2.0 * ys[i] < room  # sensor i may be left unused
                cap = size - spare  # as for targets
                opts = []
                for opt in sops[i]:
                    lo, l, a, b = opt
                    if lo >= room:
                        break
                    if (l in tfree and a in sfree and b in sfree
                            and lo + lbt - tmin[l] < limit
                            and lo + half - 0.5 * (smin[a] + smin[b]) < limit):
                        opts.append(opt)
                        if len(opts) >= cap:
                            break
                if len(opts) >= cap:
                    continue
                if spare:
                    opts.append((ys[i], -1, i, -1))
                    opts.sort()
                options, size = opts, len(opts)
                if size <= 2:
                    break
        for opt in options:
            if spent + opt[0] >= self.bound - self.best_val - self.tol:  # incumbent improved
                break
            lo, l, i, j = opt
            if l < 0:  # sensor i left unused
                self._node(sfree - {i}, tfree, spent + lo, chosen)
            elif i < 0:  # target l left unassigned
                self._node(sfree, tfree - {l}, spent + lo, chosen)
            else:
                self._node(sfree - {i, j}, tfree - {l}, spent + lo, chosen + [(i, j, l)])


def check_memory(n, n_targets, limit):
    """Refuse, before any work, an exact solve whose estimated memory exceeds ``limit`` bytes."""
    need = memory_bytes(n, n_targets)
    if need <= limit:
        return
    per = BYTES_PER_VARIABLE
    most = max(0, limit - SEARCH_BYTES) // per
    top = 0
    while (top + 1) * (2 * top + 2) * (2 * top + 1) // 2 <= most:
        top += 1
    raise ValueError(
        f"the exact solver would need about {need / 2**30:.1f} GiB for N = {n}, L = {n_targets} "
        f"({n * (n - 1) // 2 * n_targets:,} pair-target variables, {per} bytes each), over the "
        f"limit of {limit / 2**30:.0f} GiB: it fits up to {most:,} variables "
        f"(N (N - 1) / 2 * L), e.g. N = 2L up to L = {top}; for larger instances use "
        "greedy_pair_assignment (within 1/3 of the optimum, Theorem 6) or "
        "relaxed_pair_assignment (an upper bound)")
