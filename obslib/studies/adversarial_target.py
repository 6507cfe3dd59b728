"""The studies of Section V-B (the adversarial target, Fig. 7) that notebook 06 and the claims
ledger share: the runs against the paper's adversary and stronger ones, how the target is
entrapped, and how the pair reacts when the target closes in on a sensor.

Each function computes one thing that both the notebook prints and a claim judges, so the two
cannot drift apart.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from .. import tracking
from .._validate import as_instance, as_int
from ..controls import disc_controls
from ..tracking import BatchResult, TrackingResult, TrackingSetup

__all__ = [
    "NOTEBOOK",
    "adversary_runs",
    "strong_adversary_runs",
    "adversary_variants",
    "entrapment_summary",
    "switch_mechanism",
    "pooled_switch_mechanism",
]

#: The chapter of these studies.
NOTEBOOK = "06_adversarial_target"


def _runs_iv(setup, n_seeds, first_seed) -> tuple:
    as_instance(setup, TrackingSetup, "setup")
    return setup, as_int(n_seeds, "n_seeds", 1), as_int(first_seed, "first_seed", 0)


def adversary_runs(setup: TrackingSetup, n_seeds: int, first_seed: int = 0) -> dict:
    """The three strategies against the adversarial target (Section V-B) over the noise seeds
    ``first_seed, ...`` in one batched pass: strategy -> :class:`~obslib.tracking.BatchResult`
    (cached on the arguments, shared by the chapter and the ledger).

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.studies.adversarial_target import adversary_runs
    >>> runs = adversary_runs(tracking.PAPER_ADVERSARIAL.replace(steps=10), 2)
    >>> list(runs), runs["best-pair"].n_runs
    (['best-pair', 'best-partner', 'fixed-pair'], 2)
    """
    return _adversary_runs(*_runs_iv(setup, n_seeds, first_seed))


@lru_cache(maxsize=8)
def _adversary_runs(setup, n_seeds, first_seed) -> dict:
    return tracking.simulate_many({s: (setup, s) for s in tracking.STRATEGIES},
                                  seeds=range(first_seed, first_seed + n_seeds))


def strong_adversary_runs(setup: TrackingSetup, n_seeds: int, first_seed: int, n_radii: int,
                          n_angles: int) -> dict:
    """The best pair against each adversary of :func:`adversary_variants` (the paper's, and the
    stronger ones), over ``n_seeds`` noise seeds in one batched pass: variant ->
    :class:`~obslib.tracking.BatchResult` (cached on the arguments).

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.studies.adversarial_target import strong_adversary_runs
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=10)
    >>> list(strong_adversary_runs(setup, 2, 0, n_radii=2, n_angles=8))
    ['paper', 'next-pair', 'disc', 'disc, next-pair']
    """
    setup, n_seeds, first_seed = _runs_iv(setup, n_seeds, first_seed)
    return _strong_adversary_runs(setup, n_seeds, first_seed, as_int(n_radii, "n_radii", 1),
                                  as_int(n_angles, "n_angles", 1))


@lru_cache(maxsize=4)
def _strong_adversary_runs(setup, n_seeds, first_seed, n_radii, n_angles) -> dict:
    arms = {name: (v, "best-pair")
            for name, v in adversary_variants(setup, n_radii, n_angles).items()}
    return tracking.simulate_many(arms, seeds=range(first_seed, first_seed + n_seeds))


def adversary_variants(setup: TrackingSetup, n_radii: int, n_angles: int) -> dict:
    """The paper's adversary and stronger ones (Section V-B), as setups.

    ``"paper"``: the setup as given; ``"next-pair"``: the target knows the pair the sensors
    will use next; ``"disc"``: controls on a polar grid of the whole disc ``||u|| <= u_max``
    (``1 + n_radii * n_angles`` controls, :func:`disc_controls`); ``"disc, next-pair"``: both.

    Examples
    --------
    >>> from obslib.tracking import PAPER_ADVERSARIAL
    >>> from obslib.studies.adversarial_target import adversary_variants
    >>> v = adversary_variants(PAPER_ADVERSARIAL, n_radii=2, n_angles=4)
    >>> list(v), len(v["disc"].controls), v["disc, next-pair"].adversary
    (['paper', 'next-pair', 'disc', 'disc, next-pair'], 9, 'next-pair')
    """
    as_instance(setup, tracking.TrackingSetup, "setup")
    disc = disc_controls(setup.u_max, as_int(n_radii, "n_radii", 1),
                         as_int(n_angles, "n_angles", 1))
    return {
        "paper": setup,
        "next-pair": setup.replace(adversary="next-pair"),
        "disc": setup.replace(controls=disc),
        "disc, next-pair": setup.replace(controls=disc, adversary="next-pair"),
    }


def entrapment_summary(batch: BatchResult) -> dict:
    """:func:`~obslib.tracking.entrapment` of every run of a batch, summarised.

    Returns
    -------
    dict
        ``entrapped`` (fraction of runs meeting :data:`~obslib.tracking.ENTRAPMENT_CRITERIA`),
        the largest
        ``max_from_start``, ``reach``, the mean and range of the per-run mean bound, the
        smallest ``icn_min``, the mean ``icn_mean``, mean ``switches`` and ``mean_error``, and
        ``runs`` (the list of :class:`~obslib.tracking.Entrapment`).

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.studies.adversarial_target import entrapment_summary
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=20)
    >>> batch = tracking.simulate_batch(setup, "best-pair", seeds=[0, 1])
    >>> s = entrapment_summary(batch)
    >>> (len(s["runs"]), 0.0 <= s["entrapped"] <= 1.0,
    ...  s["max_from_start"] <= s["reach"])
    (2, True, True)
    """
    as_instance(batch, BatchResult, "batch")
    _ = (batch.true_icn, batch.objective)  # computed once for all runs
    es = [tracking.entrapment(batch.run(b)) for b in range(batch.n_runs)]
    return {
        "entrapped": float(np.mean([tracking.is_entrapped(e) for e in es])),
        "max_from_start": max(e.max_from_start for e in es),
        "reach": es[0].reach,
        "bound_mean": float(np.mean([e.bound_mean for e in es])),
        "bound_mean_range": (min(e.bound_mean for e in es), max(e.bound_mean for e in es)),
        "icn_min": min(e.icn_min for e in es),
        "icn_mean": float(np.mean([e.icn_mean for e in es])),
        "switches": float(np.mean([e.switches for e in es])),
        "mean_error": float(np.mean([e.mean_error for e in es])),
        "runs": es,
    }


def switch_mechanism(result: TrackingResult) -> dict:
    """How the pair reacts when the adversary closes in on a sensor (Fig. 7 caption).

    For each transition ``k -> k + 1``: did the target move closer to one of the two sensors of
    step ``k``'s pair, did the pair switch, and did the switch give the sensors a larger exact
    ``C^{-1}`` (``true_icn[k+1]``) than the value the target aimed at with the old pair
    (``objective[k]``)?

    Returns
    -------
    dict
        ``closer`` (transitions where the target got closer to a sensor of the pair),
        ``switch_if_closer`` and ``switch_if_not`` (switch rates), ``switches``,
        ``raised`` (fraction of switches with ``true_icn[k+1] > objective[k]``) and
        ``mean_gain`` (mean of ``true_icn[k+1] - objective[k]`` over switches).

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.studies.adversarial_target import switch_mechanism
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=20)
    >>> r = tracking.simulate(setup, "best-pair", seed=0)
    >>> m = switch_mechanism(r)
    >>> (m["transitions"], m["switches"] == int(r.switched.sum()),
    ...  0 <= m["closer"] <= 19)
    (19, True, True)
    """
    as_instance(result, TrackingResult, "result")
    s = result.setup.sensor_array
    ps = s[result.pairs]
    before = np.hypot(*(result.truth[:, None, :] - ps).transpose(2, 0, 1)).min(axis=1)
    after_pos = result.truth + result.control
    after = np.hypot(*(after_pos[:, None, :] - ps).transpose(2, 0, 1)).min(axis=1)
    closer = (after < before)[:-1]
    sw = result.switched
    gain = result.true_icn[1:] - result.objective[:-1]
    return {
        "transitions": int(sw.size),
        "closer": int(closer.sum()),
        "switch_if_closer": float(sw[closer].mean()) if closer.any() else float("nan"),
        "switch_if_not": float(sw[~closer].mean()) if (~closer).any() else float("nan"),
        "switches": int(sw.sum()),
        "raised": float((gain[sw] > 0).mean()) if sw.any() else float("nan"),
        "mean_gain": float(gain[sw].mean()) if sw.any() else float("nan"),
    }


def pooled_switch_mechanism(batch: BatchResult) -> dict:
    """:func:`switch_mechanism` pooled over the runs of ``batch``.

    Returns
    -------
    dict
        ``transitions``, ``closer_fraction`` (transitions where the target got closer to a
        sensor of the pair), ``switch_if_closer`` (switch rate after such a move),
        ``switch_fraction`` (all switches over all transitions), ``switches``, ``raised``
        (fraction of switches that leave a higher exact C^-1 than the target aimed at) and
        ``mean_gain``. A rate over no event (no switch, no move closer) is NaN.

    Examples
    --------
    >>> from obslib import tracking
    >>> from obslib.studies.adversarial_target import pooled_switch_mechanism
    >>> setup = tracking.PAPER_ADVERSARIAL.replace(steps=20)
    >>> batch = tracking.simulate_batch(setup, "best-pair", seeds=[0, 1])
    >>> p = pooled_switch_mechanism(batch)
    >>> p["transitions"], p["switches"] == int(batch.switched.sum())
    (38, True)
    """
    as_instance(batch, BatchResult, "batch")
    ms = [switch_mechanism(batch.run(b)) for b in range(batch.n_runs)]
    trans = sum(m["transitions"] for m in ms)
    closer = sum(m["closer"] for m in ms)
    n_sw = sum(m["switches"] for m in ms)

    def pooled(key, weight, total):
        # a run without the event has a NaN rate and weight 0: it adds nothing
        if total == 0:
            return float("nan")
        return sum(m[key] * m[weight] for m in ms if m[weight]) / total

    return {
        "transitions": trans,
        "closer_fraction": closer / trans if trans else float("nan"),
        "switch_if_closer": pooled("switch_if_closer", "closer", closer),
        "switch_fraction": n_sw / trans if trans else float("nan"),
        "switches": n_sw,
        "raised": pooled("raised", "switches", n_sw),
        "mean_gain": pooled("mean_gain", "switches", n_sw),
    }
