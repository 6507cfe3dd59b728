"""The tracking engine: the one step loop of every tracking run in :mod:`obslib`, for one target
or many, one run or many at once.

A *pass* of the engine advances ``F`` extended Kalman filters together (runs times targets, the
filter of target ``l`` of run ``r`` at index ``r L + l``), each entry of their states one NumPy
array (:class:`FilterBank`). Step ``k`` of every run, in the order of the paper's experiments
and of the authors' code:

1. the sensors' choice for step ``k``, made from the current estimates and covariances, is
   logged with the estimates and covariances *before* the step's update;
2. every filter predicts (the random walk :math:`P \\leftarrow P + Q`);
3. the chosen sensors measure the true positions :math:`o_k` (noise entry ``[k - 1, i]`` of the
   run's table for sensor ``i``) and every filter updates (Joseph form,
   :mod:`~obslib.tracking.kalman`);
4. the choice for step ``k + 1`` is made from the posteriors and the targets move to
   :math:`o_{k+1}` (a target that knows the sensors' control, the ``"exact-icn"`` oracle of
   Section V, moves first).

What the choice is and how the targets move is the caller's: pairs of sensors by the paper's
strategies against a circling or adversarial target (:mod:`~obslib.tracking.batch`, one target
per run) or teams of sensors by an assignment among many targets on known paths
(:mod:`~obslib.tracking.targets`). A run never depends on the other runs of its pass.
"""

from __future__ import annotations

import numpy as np

from . import kalman
from .adversary import control_monomials, screened_moves

__all__ = []


def singular_update_message(x, ps, k: int, run: int | None = None,
                            target: int | None = None) -> str:
    """The error of an update whose innovation covariance is singular (see
    :data:`~obslib.tracking.kalman.SINGULAR_RTOL`): estimate ``x``, sensors ``ps``, step
    ``k`` (0-based), and the run and target where there are several.

    Examples
    --------
    >>> singular_update_message([1e10, 7e9], [[0, 0], [1, 1]], 4, run=2)[:45]
    "the filter's update at step 5 of run 2 failed"
    """
    where = (f"step {k + 1}" + ("" if run is None else f" of run {run}")
             + ("" if target is None else f" (target {target})"))
    return (
        f"the filter's update at {where} failed: the innovation covariance H P H^T + R is "
        f"singular in floating point (estimate {np.round(x, 6).tolist()}, sensors "
        f"{np.asarray(ps).tolist()}); the estimate is so far from the sensors, or its covariance "
        "so large, that the Jacobian rows are parallel to rounding. Start the estimate "
        "nearer the target or with a smaller cov0."
    )


def run_steps(steps: int, update, choose, motion, record, move_first: bool = False):
    """The step loop: ``steps`` steps of a pass (see the module docstring).

    ``choose(k, control)`` returns the choice for step ``k + 1`` (0-based ``k``; ``control`` is
    the targets' last move where ``move_first``, else None), ``record(k, choice)`` logs it with
    the filters' states, ``update(k, choice, position)`` predicts and updates every filter with
    the choice's measurements of the true positions ``motion.position(k)``, and
    ``motion.move(k, choice, next_choice)`` moves the targets (``next_choice`` is None where
    ``move_first``). Returns the choice after the last step.

    Examples
    --------
    The order of the calls, for two steps of a target that stands still:

    >>> log = []
    >>> class Still:
    ...     def position(self, k):
    ...         return 0.0
    ...     def move(self, k, choice, nxt):
    ...         log.append(f"move {k}")
    >>> last = run_steps(2, lambda k, c, o: log.append(f"update {k}"),
    ...                  lambda k, u: f"choice {k}", Still(),
    ...                  lambda k, c: log.append(f"log {k}: {c}"))
    >>> log[:3]
    ['log 0: choice 0', 'update 0', 'move 0']
    >>> log[3:]
    ['log 1: choice 1', 'update 1', 'move 1']
    >>> last
    'choice 2'
    """
    choice = choose(0, None)
    for k in range(steps):
        record(k, choice)
        update(k, choice, motion.position(k))
        if move_first:  # the oracle knows the control that brings the target to o_{k+1}
            motion.move(k, choice, None)
            choice = choose(k + 1, motion.control(k))
            continue
        # the next choice depends only on the posterior (a "next-pair" adversary may know it)
        nxt = choose(k + 1, None)
        motion.move(k, choice, nxt)
        choice = nxt
    return choice


class FilterBank:
    """The states of ``F`` extended Kalman filters: estimate ``xx, xy`` and covariance entries
    ``p00, p01, p10, p11``, each ``(F,)``, with one ``Q`` (nested 2 x 2) for all."""

    def __init__(self, x0, P0, Q):
        x0 = np.asarray(x0, dtype=float)
        P0 = np.asarray(P0, dtype=float)
        self.xx, self.xy = x0[:, 0].copy(), x0[:, 1].copy()
        self.p00, self.p01 = P0[:, 0, 0].copy(), P0[:, 0, 1].copy()
        self.p10, self.p11 = P0[:, 1, 0].copy(), P0[:, 1, 1].copy()
        self.Q = Q

    def covariance(self):
        return self.p00, self.p01, self.p10, self.p11

    def estimates(self) -> np.ndarray:
        """``(F, 2)``."""
        return np.stack([self.xx, self.xy], axis=-1)

    def covariances(self) -> np.ndarray:
        """``(F, 2, 2)``."""
        return np.stack(self.covariance(), axis=-1).reshape(-1, 2, 2)

    def predict(self):
        """The predicted covariance entries (the state is not changed)."""
        return kalman.predict_entries(self.covariance(), self.Q)

    def update_pairs(self, P, s0x, s0y, s1x, s1y, z0, z1, R) -> None:
        """Every filter with the half squared ranges ``z0, z1`` of its two sensors, from the
        predicted covariance ``P`` (Section V; raises ``kalman.SingularInnovation``)."""
        (self.xx, self.xy), P = kalman.update_pair_entries(
            (self.xx, self.xy), P, (s0x, s0y), (s1x, s1y), (z0, z1), R)
        self.p00, self.p01, self.p10, self.p11 = P

    def update_teams(self, P, owner, sensor_xy, truth_xy, noise, R, measurement) -> None:
        """The filters with the measurements of their teams, from the predicted covariance
        entries ``P``; a filter without a sensor keeps its prediction.

        The measurements are listed sorted by ``owner`` ``(M,)``, the filter they update:
        ``sensor_xy`` ``(M, 2)`` the sensor's position, ``truth_xy`` ``(M, 2)`` the target's
        true position, ``noise`` ``(M,)`` the noise added to the true measurement. Filters with
        equal team sizes are updated together (``kalman.update_stacked``; pairs of half squared
        ranges by Section V's closed form, ``kalman.update_pair_entries``); raises
        ``kalman.SingularInnovation`` with ``ok`` over the filters.
        """
        self.p00, self.p01, self.p10, self.p11 = (np.array(p, dtype=float)
                                                  for p in np.broadcast_arrays(*P))
        F = self.xx.size
        counts = np.bincount(owner, minlength=F)
        start = np.cumsum(counts) - counts
        for m in np.unique(counts[counts > 0]):
            f = np.flatnonzero(counts == m)
            at = start[f][:, None] + np.arange(m)  # (G, m): this group's measurements
            ps = sensor_xy[at]  # (G, m, 2)
            _, ztrue = kalman.measurement_rows(truth_xy[at[:, 0]], ps, measurement)
            z = ztrue + noise[at]
            try:
                if m == 2 and measurement == "half-squared-range":
                    r = float(R)
                    (xx, xy), Pc = kalman.update_pair_entries(
                        (self.xx[f], self.xy[f]),
                        (self.p00[f], self.p01[f], self.p10[f], self.p11[f]),
                        (ps[:, 0, 0], ps[:, 0, 1]), (ps[:, 1, 0], ps[:, 1, 1]),
                        (z[:, 0], z[:, 1]), ((r, 0.0), (0.0, r)))
                    xn = np.stack([xx, xy], axis=-1)
                    Pn = np.stack(Pc, axis=-1).reshape(-1, 2, 2)
                else:
                    x = np.stack([self.xx[f], self.xy[f]], axis=-1)
                    Pg = np.stack([self.p00[f], self.p01[f], self.p10[f], self.p11[f]],
                                  axis=-1).reshape(-1, 2, 2)
                    H, h = kalman.measurement_rows(x, ps, measurement)
                    xn, Pn = kalman.update_stacked(x, Pg, H, z - h, R)
            except kalman.SingularInnovation as e:
                ok = np.ones(F, dtype=bool)
                ok[f[~e.ok]] = False
                raise kalman.SingularInnovation(ok) from None
            self.xx[f], self.xy[f] = xn[:, 0], xn[:, 1]
            self.p00[f], self.p01[f] = Pn[:, 0, 0], Pn[:, 0, 1]
            self.p10[f], self.p11[f] = Pn[:, 1, 0], Pn[:, 1, 1]


class FixedPaths:
    """Targets on known paths: ``truth`` ``(T, steps + 1, L, 2)`` with ``T`` 1 (one path for
    every run) or ``R``; ``position(k)`` is ``(T, L, 2)``."""

    def __init__(self, truth):
        self.truth = truth

    def position(self, k):
        return self.truth[:, k]

    def control(self, k):
        return self.truth[:, k + 1] - self.truth[:, k]

    def move(self, k, choice, nxt):
        pass


class Adversaries:
    """The adversarial targets of ``R`` runs of Section V-B: positions over time and their
    moves.

    Runs with different control sets (``barred``: each run's own set is a contiguous block of
    ``controls``) are screened block by block, each against its own controls only: the pick
    within a block is the one ``adversary.adversary_moves`` makes with the other blocks barred,
    without evaluating them (notebook 06's stronger adversaries: 20 runs with 9 controls next to
    20 with 1801; 0.3 s against 1.7 s for their 315 moves). ``pair_sensors(choice)`` gives the
    ``(R, 2, 2)`` sensors of a choice."""

    def __init__(self, setup, R_, nextpair, controls, barred, pair_sensors):
        self.truth = np.empty((setup.steps + 1, R_, 2))
        self.truth[0] = setup.start
        self.controls = setup.control_array if controls is None else controls
        self.nextpair = nextpair
        self.anynext = bool(nextpair.any())
        self.pair_sensors = pair_sensors
        if barred is None:
            self.blocks = [(None, 0, self.controls, control_monomials(self.controls))]
        else:
            allowed = np.asarray(barred) == 0
            lo = allowed.argmax(axis=1)
            hi = allowed.shape[1] - allowed[:, ::-1].argmax(axis=1)
            if not (allowed.sum(axis=1) == hi - lo).all() or not allowed.any(axis=1).all():
                raise ValueError("each run's controls must be one contiguous block")
            self.blocks = []
            for a, b in sorted(set(zip(lo.tolist(), hi.tolist()))):
                c = self.controls[a:b]
                self.blocks.append((np.flatnonzero((lo == a) & (hi == b)), a, c,
                                    control_monomials(c)))

    def position(self, k):
        return self.truth[k, :, 0], self.truth[k, :, 1]

    def control(self, k):
        return self.truth[k + 1] - self.truth[k]

    def move(self, k, choice, nxt):
        """Move every target after step ``k`` against the sensors of its run's choice (or,
        where the run's adversary is ``"next-pair"``, of the next choice ``nxt``)."""
        eval_ps = self.pair_sensors(choice)
        if self.anynext:
            eval_ps = np.where(self.nextpair[:, None, None], self.pair_sensors(nxt), eval_ps)
        o = self.truth[k]
        if self.blocks[0][0] is None:
            _, _, c, basis = self.blocks[0]
            pick = screened_moves(eval_ps, o, c, basis)
        else:
            pick = np.empty(o.shape[0], dtype=int)
            for rows, a, c, basis in self.blocks:
                pick[rows] = a + screened_moves(eval_ps[rows], o[rows], c, basis)
        self.truth[k + 1] = o + self.controls[pick]
