"""The intuition's data, numbers and tables of the chapter on how the assignment algorithms
scale.

:func:`pair_ceiling` computes what the intuition draws; each ``glue_*`` function formats one
result of the chapter (the work counts of :func:`obslib.tools.bench.evaluation_counts`, the
measured times of ``book/data/scaling_times.json``) and glues it under the names the chapter's
prose uses.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from obslib import pair_bounds
from obslib.formatting import count, listing, number, percent
from obslib.tools.bench import literal_count

from ..glue import glue_texts
from ..tables import numbered_table

__all__ = ["pair_ceiling", "glue_intuition", "glue_work", "glue_same_picks", "glue_wall_time"]


def pair_ceiling(seed: int, n_sensors: int = 200, n_targets: int = 100) -> dict:
    """One target of a uniform instance (``n_sensors`` and ``n_targets`` in a square of side
    100, drawn from ``numpy.random.default_rng([seed, n_sensors])``): every pair's bound
    against the ratio of the pair's nearer to farther distance, its ceiling.

    Returns
    -------
    dict
        ``ratio`` and ``bound`` (one per pair), the target's ``tenth``-best bound, and the
        numbers of sensors and pairs.
    """
    rng = np.random.default_rng([seed, n_sensors])
    S, T = rng.uniform(0, 100, (n_sensors, 2)), rng.uniform(0, 100, (n_targets, 2))
    W0 = pair_bounds(S, T[:1], 1.0)[:, :, 0]
    ii, jj = np.triu_indices(len(S), 1)
    dist = np.linalg.norm(S - T[0], axis=1)
    ratio = np.minimum(dist[ii], dist[jj]) / np.maximum(dist[ii], dist[jj])
    bound = W0[ii, jj]
    return {"ratio": ratio, "bound": bound, "tenth": np.sort(bound)[-10],
            "n_sensors": len(S), "n_pairs": int(ii.size)}


def glue_intuition(ceiling: dict, lit_N: int = 2000, lit_L: int = 1000) -> None:
    """The intuition's instance (:func:`pair_ceiling`): its sensors and pairs, the share of pairs
    whose ceiling reaches the tenth-best bound, and the pair bounds the literal Algorithm 1
    evaluates at ``lit_N`` sensors and ``lit_L`` targets.

    Parameters
    ----------
    ceiling : dict
        :func:`pair_ceiling`.
    lit_N, lit_L : int
        The size of the literal algorithm's example.
    """
    glue_texts(
        ceil_N=number(ceiling["n_sensors"]),
        ceil_pairs=number(ceiling["n_pairs"]),
        ceil_frac=percent(float(np.mean(ceiling["ratio"] >= ceiling["tenth"]))),
        lit_N=number(lit_N),
        lit_L=number(lit_L),
        lit_big=number(float(literal_count(lit_N, lit_L))),
    )


def glue_work(counts: dict) -> None:
    """The pair bounds evaluated on one instance of each size (``tab-09-work``): one pass over
    all weights, the greedy, their ratio, the relaxed matching and the literal Algorithm 1; and
    from which size on the relaxed matching evaluates more than the greedy.

    Parameters
    ----------
    counts : dict
        :func:`obslib.tools.bench.evaluation_counts`: ``{algorithm: (N, counts)}``.
    """
    lit_counts = dict(zip(*counts["literal Algorithm 1"]))
    rel_counts = {int(n): int(c) for n, c in zip(*counts["relaxed matching"])}
    n_g, c_g = counts["greedy (geometry)"]
    one = np.array([n * (n - 1) // 2 * (n // 2) for n in n_g])
    greedy = {int(n): int(c) for n, c in zip(n_g, c_g)}
    both = sorted(set(rel_counts) & set(greedy))
    # the smallest size from which on the matching evaluates more bounds than the greedy
    more = [n for k, n in enumerate(both) if all(rel_counts[m] > greedy[m] for m in both[k:])]
    n_rel = both[-1]
    rows = pd.DataFrame(
        {"$L$": [number(int(n // 2)) for n in n_g],
         "one pass": [number(int(x)) for x in one],
         "greedy": [number(int(x)) for x in c_g],
         "greedy / one pass": [number(float(x)) for x in c_g / one],
         "relaxed matching": [number(rel_counts[int(n)]) if int(n) in rel_counts else "\u2013"
                              for n in n_g],
         "literal Algorithm 1": [number(int(lit_counts[n])) if n in lit_counts else "\u2013"
                                 for n in n_g]},
        index=pd.Index(n_g, name="$N$"),
    )
    glue_texts(
        tab_work=numbered_table(
            rows, "Pair bounds evaluated on one uniform instance of each size.", "tab-09-work"),
        n_big=number(int(n_g[-1])),
        frac_big=percent(float(c_g[-1] / one[-1])),
        small_ratio=number(float(c_g[0] / one[0])),
        n_small=number(int(n_g[0])),
        rel_from=number(more[0]) if more else "no size",
        n_rel=number(n_rel),
        rel_over_greedy=number(rel_counts[n_rel] / greedy[n_rel]),
        rel_frac=percent(rel_counts[n_rel] / (n_rel * (n_rel - 1) // 2 * (n_rel // 2))),
    )


def glue_same_picks(same: int, n_instances: int) -> None:
    """On how many instances the greedy and the literal Algorithm 1 make the same picks.

    Parameters
    ----------
    same, n_instances : int
        The instances with the same picks, of those compared.
    """
    glue_texts(same=count(int(same), of=n_instances))


def glue_wall_time(measured: dict) -> None:
    """The measured wall times: the machine, the repeats, the greedy's speed-up on the literal
    algorithm, and the largest sizes the greedy and the exact optimum reached.

    Parameters
    ----------
    measured : dict
        ``book/data/scaling_times.json``: ``machine``, ``repeat`` and the ``times`` of each
        algorithm.
    """
    t = measured["times"]
    g = dict(zip(t["greedy (geometry)"]["N"], t["greedy (geometry)"]["seconds"]))
    rel = dict(zip(t["relaxed matching"]["N"], t["relaxed matching"]["seconds"]))
    lit = dict(zip(t["literal Algorithm 1"]["N"], t["literal Algorithm 1"]["seconds"]))
    opt = dict(zip(t["exact optimum"]["N"], t["exact optimum"]["seconds"]))
    n_cmp = max(set(g) & set(lit))
    parts = [p.strip() for p in measured["machine"].split(",")]
    glue_texts(
        machine=f"{parts[0]}, {listing(parts[1:])}" if len(parts) > 1 else parts[0],
        repeat=number(int(measured.get("repeat", 1))),
        n_cmp=number(int(n_cmp)),
        speedup=number(float(lit[n_cmp] / g[n_cmp])),
        n_max=number(int(max(g))),
        l_max=number(int(max(g)) // 2),
        t_max=number(float(g[max(g)])),
        n_opt=number(int(max(opt))),
        t_opt=number(float(opt[max(opt)])),
        n_rel_t=number(int(max(rel))),
        t_rel=number(float(rel[max(rel)])),
        t_rel_g=number(float(g[max(rel)])),
    )
