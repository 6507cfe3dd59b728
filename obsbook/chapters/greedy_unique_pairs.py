"""The numbers and tables of the chapter on greedy unique pairs (Section IV-A, Algorithm 1 and
Theorem 6).

Each ``glue_*`` function formats the result of one step of the chapter and glues it under the
names its prose uses; :func:`charging_table` lays out the charging argument of Theorem 6's proof.
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from obslib._format import count, number, percent, setting
from obslib.assignment import greedy_pair_assignment_literal
from obslib.claims.assignment import NEAR_THIRD
from obslib.studies import assignment as experiments
from obslib.studies import greedy_tightness as tightness

from ..glue import glue_texts
from ..prose import pair_math, triple_math
from ..tables import numbered_table

__all__ = ["charging_table", "glue_intuition", "glue_example", "glue_charging",
           "glue_greedy_vs_optimum", "glue_worst", "glue_tight"]


def charging_table(rounds) -> pd.DataFrame:
    """Theorem 6's charging argument as a table: per round the greedy's pick and each optimal
    triple charged to it, with their values.

    Parameters
    ----------
    rounds : list of dict
        :func:`obslib.studies.assignment.charging`.
    """
    rows = []
    for k, r in enumerate(rounds, start=1):
        charged = list(zip(r["charged"], r["charged_w"])) or [(None, None)]
        for n, (t, w) in enumerate(charged):
            rows.append({  # the round and its pick on the round's first row only
                "round": str(k) if n == 0 else "",
                "greedy pick (its ω)":
                    f"{triple_math(r['pick'])} ({number(r['w'])})" if n == 0 else "",
                "triple of the optimum charged (its ω)":
                    "none" if t is None else f"{triple_math(t)} ({number(w)})",
                "worth no more than the pick": "–" if w is None else
                ("yes" if w <= r["w"] + 1e-12 else "no"),
            })
    return pd.DataFrame(rows)


def glue_intuition(W, greedy, optimum) -> None:
    """The intuition's instance: the greedy's first pick, the optimal triples it blocks, and
    the two totals.

    Parameters
    ----------
    W : ndarray, shape (N, N, L)
        The pair weights.
    greedy, optimum : obslib.PairAssignment
        The greedy's and the optimum's assignments of ``W``.
    """
    first = experiments.charging(W, greedy.triples, optimum.triples)[0]
    glue_texts(
        i_pick=number(first["w"]),
        i_blocked=" and ".join(number(w) for w in first["charged_w"]),
        i_n_blocked=count(len(first["charged"])),
        i_left=number(greedy.value - first["w"]),
        i_greedy=number(greedy.value),
        i_opt=number(optimum.value),
        i_ratio=number(greedy.value / optimum.value),
    )


def glue_example(W, greedy, optimum, relaxed) -> None:
    """The example's three assignments (``tab-03-example``), whether the literal Algorithm 1
    picks the same, and how much of the optimum the greedy gets.

    Parameters
    ----------
    W : ndarray, shape (N, N, L)
        The pair weights.
    greedy, optimum, relaxed : obslib.PairAssignment
        The assignments of the greedy, the exact optimum and the relaxed matching.
    """
    n_targets = W.shape[2]
    results = {"greedy (Algorithm 1)": greedy, "exact optimum": optimum,
               "relaxed (Problem 3)": relaxed}
    example = pd.DataFrame({"target": [f"$t_{{{l + 1}}}$" for l in range(n_targets)]
                            + ["total ω"]})
    for name, res in results.items():
        by_target = {l: pair_math(i, j) for i, j, l in res.triples}
        example[name] = [by_target.get(l, "–") for l in range(n_targets)] + [number(res.value)]
    same = greedy_pair_assignment_literal(W).triples == greedy.triples
    shared = len(set(greedy.triples) & set(optimum.triples))
    glue_texts(
        tab_03_example=numbered_table(
            example, "The example's three assignments: the pair of sensors of each target, and "
            "the total value.", "tab-03-example"),
        literal_same="makes the same picks in the same order" if same else "makes different picks",
        ex_ratio=number(greedy.value / optimum.value),
        ex_shared=count(shared, of=n_targets),
    )


def glue_charging(charges, greedy) -> None:
    """The charging argument on the example (``tab-03-charging``).

    Parameters
    ----------
    charges : list of dict
        :func:`obslib.studies.assignment.charging` of the greedy against the optimum.
    greedy : obslib.PairAssignment
        The greedy's assignment.
    """
    glue_texts(
        tab_03_charging=numbered_table(
            charging_table(charges), "Theorem 6's charging argument on the example: the "
            "greedy's picks in order, and the triples of the optimum charged to each.",
            "tab-03-charging"),
        ch_max=count(max(len(r["charged"]) for r in charges)),
        ch_total=number(sum(sum(r["charged_w"]) for r in charges)),
        ch_greedy=number(greedy.value),
    )


def glue_greedy_vs_optimum(study, targets_min: int, targets_max: int, extra_max: int) -> None:
    """The greedy against the exact optimum on random instances: the ratio's summary and the
    table by size (``tab-03-sizes``).

    Parameters
    ----------
    study : obslib.studies.assignment.GreedyStudy
        The study's result.
    targets_min, targets_max, extra_max : int
        The sizes drawn: :math:`L` from ``targets_min`` to ``targets_max``, :math:`N` from
        :math:`2L` to :math:`2L` + ``extra_max``.
    """
    ratio = study.ratio
    by_size = pd.DataFrame({"N": study.n_sensors, "L": study.n_targets, "ratio": ratio})
    by_size = by_size.groupby(["L", "N"])["ratio"].agg(["size", "min", "mean"]).reset_index()
    sizes = pd.DataFrame({
        "targets $L$": by_size["L"].astype(int), "sensors $N$": by_size["N"].astype(int),
        "instances": [number(int(n)) for n in by_size["size"]],
        "smallest ratio": [number(float(v)) for v in by_size["min"]],
        "mean ratio": [number(float(v)) for v in by_size["mean"]]})
    mean_by_L = pd.Series(ratio).groupby(study.n_targets).mean()
    glue_texts(
        n_inst=number(ratio.size),
        t_min=setting(targets_min),
        t_max=setting(targets_max),
        n_range=f"$2L$ to $2L + {setting(extra_max)}$",
        q_level=percent(0.95),
        ratio_min=number(float(ratio.min())),
        ratio_median=number(float(np.median(ratio))),
        ratio_q05=number(float(np.quantile(ratio, 0.05))),  # 95% of them above
        ratio_optimal=percent(float(np.mean(ratio >= 1 - 1e-12))),
        tab_03_sizes=numbered_table(
            sizes, "Greedy over optimum on the random instances, by size.", "tab-03-sizes"),
        mean_Lmin=number(float(mean_by_L.iloc[0])),
        mean_Lmax=number(float(mean_by_L.iloc[-1])),
    )


def glue_worst(W, greedy, optimum, worst_ratio: float, search_sensors: int, search_targets: int,
               n_starts: int, n_steps: int) -> None:
    """The worst layout the local search finds: its ratio, its charging argument
    (``tab-03-worst``), and the near-tight layout kept for every rerun.

    Parameters
    ----------
    W : ndarray, shape (N, N, L)
        The pair weights of the layout found.
    greedy, optimum : obslib.PairAssignment
        The greedy's and the optimum's assignments of ``W``.
    worst_ratio : float
        The ratio the search found.
    search_sensors, search_targets, n_starts, n_steps : int
        The search's sizes: sensors and targets of the layouts, restarts and moves per restart.
    """
    charges = experiments.charging(W, greedy.triples, optimum.triples)
    # the layout the search finds at the paper's sizes, kept so that every rerun judges the same
    S0, T0 = tightness.tight_witness()
    margin = tightness.first_pick_margin(S0, T0, tightness.TIGHT_U_MAX)
    glue_texts(
        n_starts=number(n_starts),
        n_steps=number(n_steps),
        n_s=number(search_sensors),
        n_t=number(search_targets),
        worst_ratio=number(worst_ratio),
        worst_greedy=number(greedy.value),
        worst_opt=number(optimum.value),
        worst_blocked=count(len(charges[0]["charged"])),
        tab_03_worst=numbered_table(
            charging_table(charges), "The charging argument at the worst layout found: the "
            "greedy's picks in order, and the triples of the optimum charged to each.",
            "tab-03-worst"),
        witness_ratio=number(margin["ratio"]),
        witness_margin=number(margin["relative_margin"]),
        near_third=setting(NEAR_THIRD),
    )


def glue_tight(eps: float, greedy, optimum) -> None:
    """The tight instance of Theorem 6: the greedy's and the optimum's totals and their ratio.

    Parameters
    ----------
    eps : float
        The instance's small weight.
    greedy, optimum : obslib.PairAssignment
        The greedy's and the optimum's assignments.
    """
    glue_texts(
        tight_eps=setting(eps),
        tight_greedy=number(greedy.value, 4),
        tight_opt=number(optimum.value),
        tight_ratio=number(greedy.value / optimum.value, 4),
    )
