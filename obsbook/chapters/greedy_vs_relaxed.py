"""The example, numbers and tables of the chapter on the greedy against the relaxed matching
(Section V-C, Fig. 8).

:func:`example` picks the instance the intuition draws; each ``glue_*`` function formats one
result of :mod:`obslib.studies.greedy_vs_relaxed` and glues it under the names the chapter's
prose uses.
"""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from obslib import (
    greedy_pair_assignment,
    optimal_pair_assignment,
    pair_bounds,
    relaxed_pair_assignment,
)
from obslib._format import count, fixed, number, percent, span
from obslib.studies.greedy_vs_relaxed import fig8_instance
from obslib.studies.published import FIG8_PUBLISHED_L20

from ..glue import glue_texts
from ..prose import sensor_math, triple_math
from ..tables import numbered_table

__all__ = ["example", "glue_parameters", "glue_example", "glue_fig8", "glue_optimum",
           "glue_ordered", "glue_extended"]


def example(seed: int, side: float, u_max: float, n_trials: int = 30) -> tuple:
    """Of Fig. 8's first ``n_trials`` trials with two targets (seed ``seed``, square of side
    ``side``, pair bounds for ``u_max``), the one where the greedy, the optimum and the relaxed
    value lie farthest apart (the largest of the smaller of the two gaps).

    Returns
    -------
    tuple
        ``(sensors, targets, W, assignments)``: the instance, its pair weights, and the greedy,
        optimal and relaxed assignments by name.
    """
    best = None
    for trial in range(n_trials):
        S, T = fig8_instance(2, trial, seed, side)
        W = pair_bounds(S, T, u_max)
        res = {"greedy": greedy_pair_assignment(W), "optimal": optimal_pair_assignment(W),
               "relaxed": relaxed_pair_assignment(W)}
        margin = min(res["optimal"].value - res["greedy"].value,
                     res["relaxed"].value - res["optimal"].value)
        if best is None or margin > best[0]:
            best = (margin, S, T, W, res)
    return best[1:]


def glue_parameters(L_max: int, trials: int, optimum_max_L: int) -> None:
    """Fig. 8's sizes: the largest number of targets, the trials per size, and the largest
    size whose optimum is computed.

    Parameters
    ----------
    L_max, trials, optimum_max_L : int
        The chapter's parameters.
    """
    glue_texts(p_Lmax=number(L_max), p_trials=number(trials), p_optL=number(optimum_max_L))


def glue_example(W, assignments: dict) -> None:
    """The intuition's instance: the greedy's picks, the three totals, the optimum's pairs and
    the sensors the relaxed matching uses twice.

    Parameters
    ----------
    W : ndarray, shape (N, N, L)
        The instance's pair weights.
    assignments : dict
        The greedy, optimal and relaxed assignments by name (:func:`example`).
    """
    ex = assignments
    n = W.shape[0]
    used = np.bincount([k for i, j, _ in ex["relaxed"].triples for k in (i, j)], minlength=n)
    shared = [sensor_math(k) for k in np.flatnonzero(used > 1)]
    first = ex["greedy"].triples[0]
    glue_texts(
        n_assign=number(float(math.factorial(40) // 2 ** 20)),
        ex_first=triple_math(first),
        ex_first_w=number(float(W[first])),
        ex_second=triple_math(ex["greedy"].triples[1]),
        ex_g=number(ex["greedy"].value),
        ex_o=number(ex["optimal"].value),
        ex_r=number(ex["relaxed"].value),
        ex_opt_pairs=" and ".join(triple_math(t) for t in ex["optimal"].triples),
        ex_shared=" and ".join(shared) if shared else "no sensor",
    )


def glue_fig8(summary, trials: int, optimum_max_L: int) -> None:
    """Fig. 8's mean totals by number of targets (``tab-07-fig8``), the paper's numbers at
    :math:`L = 20` against ours in standard errors, and the range of greedy over relaxed.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The sweep's summary.
    trials, optimum_max_L : int
        The trials per size, and the largest size whose optimum is computed.
    """
    mean, std, L, ratio = summary.mean, summary.std, summary.L, summary.ratio
    has_opt = L <= optimum_max_L
    rows = pd.DataFrame(
        {
            "greedy": [number(x) for x in mean["greedy"]],
            "relaxed": [number(x) for x in mean["relaxed"]],
            "optimum": [number(x) if h else "\u2013" for x, h in zip(mean["optimum"], has_opt)],
            "greedy / relaxed": [number(x) for x in ratio],
            "greedy / optimum": [number(g / o) if h else "\u2013"
                                 for g, o, h in zip(mean["greedy"], mean["optimum"], has_opt)],
        },
        index=pd.Index(L, name="$L$"),
    )
    # the paper's L = 20 means against ours, in standard errors of our means
    i20 = int(np.flatnonzero(L == 20)[0]) if 20 in L else len(L) - 1
    se = {k: std[k][i20] / math.sqrt(trials) for k in ("greedy", "relaxed")}
    z = max(abs(mean[k][i20] - FIG8_PUBLISHED_L20[k]) / se[k] for k in se)
    glue_texts(
        tab_fig8=numbered_table(
            rows, f"Mean totals over {count(trials)} trials for each number of targets $L$ "
            f"($N = 2L$ sensors); the optimum of Problem 1 is computed up to "
            f"$L = {optimum_max_L}$.", "tab-07-fig8"),
        L_cmp=number(int(L[i20])),
        g20=fixed(mean["greedy"][i20], 2),
        r20=fixed(mean["relaxed"][i20], 2),
        p_g20=fixed(FIG8_PUBLISHED_L20["greedy"], 2),
        p_r20=fixed(FIG8_PUBLISHED_L20["relaxed"], 2),
        z20=number(float(z)),
        ratio_span=span(ratio[1:].min(), ratio[1:].max()) if len(L) > 1 else number(1.0),
        third_margin=number(float((3 * ratio).min())),
    )


def glue_optimum(summary, sweep: dict, L_max: int, optimum_max_L: int) -> None:
    """Where the gap lies: the greedy and the relaxed matching against the exact optimum, over
    the sizes where it is computed and trial by trial with two targets.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The sweep's summary.
    sweep : dict
        :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep`.
    L_max, optimum_max_L : int
        The largest number of targets, and the largest whose optimum is computed.
    """
    mean = summary.mean
    k = min(optimum_max_L, L_max)
    texts = {"opt_L": number(int(k))}
    if k >= 2:
        texts["gopt_lo"] = number(float((mean["greedy"][1:k] / mean["optimum"][1:k]).min()))
        texts["ropt_hi"] = number(float((mean["relaxed"][1:k] / mean["optimum"][1:k]).max()))
    if L_max >= 2 and optimum_max_L >= 2:  # the trials with two targets, one by one
        g2, o2, r2 = (sweep[key][1] for key in ("greedy", "optimum", "relaxed"))
        texts |= {"n2": number(len(g2)),
                  "n2_greedy_opt": count(int(np.sum(g2 >= o2 - 1e-12)), of=len(g2)),
                  "n2_rel_above": count(int(np.sum(r2 > o2 + 1e-12)), of=len(g2))}
    glue_texts(**texts)


def glue_ordered(summary, sweep: dict, trials: int) -> None:
    """Problem 3 as printed (unordered pairs) and as the authors' code solves it (ordered
    pairs), at a few sizes (``tab-07-ordered``), and their largest relative gap.

    Parameters
    ----------
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        The means of both relaxations, ``relaxed`` and ``relaxed_ordered``.
    sweep : dict
        Both relaxations' values trial by trial, one row per number of targets.
    trials : int
        The trials per size.
    """
    mean, L = summary.mean, summary.L
    sel = [a for a, n in enumerate(L) if n == 2 or n % 5 == 0] or list(range(len(L)))
    rel, ordd = sweep["relaxed"], sweep["relaxed_ordered"]
    rows = pd.DataFrame(
        {
            "Problem 3 (mean)": [number(x, 4) for x in mean["relaxed"][sel]],
            "ordered pairs (mean)": [number(x, 4) for x in mean["relaxed_ordered"][sel]],
            "trials where ordered is larger": [
                count(int(np.sum(ordd[a] > rel[a] + 1e-12)), of=trials) for a in sel],
        },
        index=pd.Index(L[sel], name="$L$"),
    )
    gap = np.max(np.abs(mean["relaxed_ordered"] - mean["relaxed"]) / mean["relaxed"])
    glue_texts(
        tab_ordered=numbered_table(
            rows, "The relaxation as printed (unordered pairs) and as the authors' code solves "
            f"it (ordered pairs), {count(trials)} trials for each $L$.", "tab-07-ordered"),
        ordered_gap=percent(float(gap)),
    )


def glue_extended(ext: dict, trials_extended: int, summary) -> None:
    """The greedy and the relaxed matching on larger instances (``tab-07-extended``).

    Parameters
    ----------
    ext : dict
        :func:`obslib.studies.greedy_vs_relaxed.fig8_sweep` at the larger sizes.
    trials_extended : int
        The trials per size.
    summary : obslib.studies.greedy_vs_relaxed.Fig8Summary
        Fig. 8's summary (its ratio at its largest size).
    """
    g_ext, r_ext = ext["greedy"].mean(axis=1), ext["relaxed"].mean(axis=1)
    rows = pd.DataFrame(
        {"$N$": [number(int(2 * n)) for n in ext["L"]],
         "greedy (mean)": [number(x) for x in g_ext],
         "relaxed (mean)": [number(x) for x in r_ext],
         "greedy / relaxed": [number(x) for x in g_ext / r_ext]},
        index=pd.Index(ext["L"], name="$L$"),
    )
    glue_texts(
        tab_ext=numbered_table(
            rows, f"The greedy and the relaxed matching on larger instances, "
            f"{count(trials_extended)} trials each.", "tab-07-extended"),
        ext_ratio_last=number(float(g_ext[-1] / r_ext[-1])),
        ext_L_last=number(int(ext["L"][-1])),
        ratio_L20=number(float(summary.ratio[-1])),
    )
