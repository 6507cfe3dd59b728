"""How robust are the ledger's verdicts to the parameters the paper fixed?

For a claim, :func:`verdict_robustness` re-evaluates its check with one parameter of its notebook
changed at a time, through the parameter profiles of :mod:`obslib.profiles`: a temporary
profile equal to a base profile (``quick`` by default) with that one change, removed afterwards.
The dimensions are the target's speed bound ``u_max``, the measurement noise ``noise_std``, the
distance metric of the pair bound (``metric``) and the Monte Carlo size (the notebook's number of
seeds, instances or trials). A dimension applies to a claim when its notebook has that
parameter (the metric: the tracking notebooks 05 and 06).

:func:`robustness_table` renders the result as one Markdown row per claim, saying over which
range each verdict holds.
"""

from __future__ import annotations

import copy
from contextlib import contextmanager

from ..profiles import PROFILES, params, profile_names

__all__ = ["DIMENSIONS", "SIZE_KEYS", "TRACKING_NOTEBOOKS", "default_ids", "verdict_robustness",
           "robustness_table"]

#: Per dimension, the factors applied to the default (numbers) or the values tried (metric).
DIMENSIONS = {
    "u_max": (0.25, 0.5, 2.0, 4.0),
    "noise_std": (0.25, 0.5, 2.0, 4.0),
    "metric": ("mahalanobis", "euclidean"),
    "size": (0.5, 2.0),
}

#: Parameter names that set a notebook's Monte Carlo size, in order of preference.
SIZE_KEYS = ("n_seeds", "n_instances", "trials", "n_scenes")

#: Notebooks of the tracking experiments (Sections V-A and V-B).
TRACKING_NOTEBOOKS = ("05_two_sensors_tracking", "06_adversarial_target")

_TMP = "_robustness"


@contextmanager
def _profile_with(base: str, notebook: str, key: str, value):
    """A temporary profile: ``base`` with ``notebook``'s ``key`` set to ``value``."""
    table = copy.deepcopy(PROFILES[base])
    table.setdefault(notebook, {})[key] = value
    PROFILES[_TMP] = table
    try:
        yield _TMP
    finally:
        del PROFILES[_TMP]


def default_ids(base: str = "quick") -> list[str]:
    """Claims whose verdict is partly or refuted at ``base``, and every tracking claim.

    Examples
    --------
    The claim that :math:`\\alpha^* \\ne 1` is judged "partly" at ``quick``
    (:func:`verdict_robustness` shows it), so it is among them:

    >>> from obslib.studies.robustness import default_ids
    >>> ids = default_ids("quick")
    >>> "thm5-alpha-not-1" in ids, len(ids) == len(set(ids))
    (True, True)
    """
    from ..claims import evaluate

    return [r.id for r in evaluate(base)
            if r.status in ("partly", "refuted") or r.notebook in TRACKING_NOTEBOOKS]


def _variants(p: dict, notebook: str) -> dict:
    """Dimension -> list of (label, key, value) for the parameters this notebook has."""
    out = {}
    if "u_max" in p and isinstance(p["u_max"], (int, float)):
        out["u_max"] = [(f"x{f:g}", "u_max", p["u_max"] * f) for f in DIMENSIONS["u_max"]]
    if "noise_std" in p:
        out["noise_std"] = [(f"x{f:g}", "noise_std", p["noise_std"] * f)
                            for f in DIMENSIONS["noise_std"]]
    if notebook in TRACKING_NOTEBOOKS:
        cur = p.get("metric", "mahalanobis")
        out["metric"] = [(m, "metric", m) for m in DIMENSIONS["metric"] if m != cur]
    key = next((k for k in SIZE_KEYS if k in p), None)
    if key is not None:
        out["size"] = [(f"{key} x{f:g}", key, max(2, int(round(p[key] * f))))
                       for f in DIMENSIONS["size"]]
    return out


def verdict_robustness(ids=None, base: str = "quick", dimensions=None) -> list[dict]:
    """Re-evaluate claims with one parameter changed at a time.

    Parameters
    ----------
    ids : iterable of str, optional
        Claim ids (default :func:`default_ids`).
    base : str
        The profile the variations start from.
    dimensions : iterable of str, optional
        A subset of :data:`DIMENSIONS` (default all).

    Returns
    -------
    list of dict
        Per claim: ``id``, ``notebook``, ``base`` (its status at ``base``) and ``variants``:
        dimension -> list of ``(label, status)``. Claims whose notebook has no parameters in the
        profiles get no variants.

    Examples
    --------
    One claim, one dimension: the four factors of :data:`DIMENSIONS` applied to ``u_max``:

    >>> from obslib.studies.robustness import DIMENSIONS, verdict_robustness
    >>> row = verdict_robustness(ids=["thm5-alpha-not-1"], dimensions=["u_max"])[0]
    >>> row["id"], len(row["variants"]["u_max"]) == len(DIMENSIONS["u_max"])
    ('thm5-alpha-not-1', True)
    """
    from ..claims import evaluate, registry

    if base not in profile_names() or base == _TMP:
        raise ValueError(f"unknown profile {base!r}; known: {profile_names()}")
    dims = list(DIMENSIONS) if dimensions is None else list(dimensions)
    unknown = [d for d in dims if d not in DIMENSIONS]
    if unknown:
        raise ValueError(f"unknown dimension(s) {unknown}; known: {list(DIMENSIONS)}")
    ids = default_ids(base) if ids is None else list(ids)
    reg = registry()
    missing = [i for i in ids if i not in reg]
    if missing:
        raise ValueError(f"unknown claim id(s): {missing}")
    rows = []
    for cid in ids:
        nb = reg[cid].notebook
        (rec,) = evaluate(base, ids=[cid])
        row = {"id": cid, "notebook": nb, "base": rec.status, "variants": {}}
        if nb in PROFILES["paper"]:
            for dim, options in _variants(params(nb, base), nb).items():
                if dim not in dims:
                    continue
                got = []
                for label, key, value in options:
                    with _profile_with(base, nb, key, value) as name:
                        (r,) = evaluate(name, ids=[cid])
                    got.append((label, r.status))
                row["variants"][dim] = got
        rows.append(row)
    return rows


def _describe(base: str, got: list) -> str:
    changed = [f"{label}: {status}" for label, status in got if status != base]
    if not changed:
        return "holds (" + ", ".join(label for label, _ in got) + ")"
    return "changes at " + "; ".join(changed)


def robustness_table(rows) -> str:
    """Markdown: one row per claim, per dimension whether its verdict holds over the range.

    Examples
    --------
    >>> from obslib.studies.robustness import robustness_table
    >>> rows = [{"id": "c1", "base": "holds",
    ...          "variants": {"u_max": [("x0.5", "holds"), ("x2", "refuted")]}}]
    >>> print(robustness_table(rows))
    | claim | verdict | u_max | noise_std | metric | size |
    | --- | --- | --- | --- | --- | --- |
    | `c1` | holds | changes at x2: refuted | n/a | n/a | n/a |
    <BLANKLINE>
    """
    dims = list(DIMENSIONS)
    lines = ["| claim | verdict | " + " | ".join(dims) + " |",
             "| --- | --- | " + " | ".join("---" for _ in dims) + " |"]
    for r in rows:
        cells = [_describe(r["base"], r["variants"][d]) if d in r["variants"] else "n/a"
                 for d in dims]
        lines.append(f"| `{r['id']}` | {r['base']} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"
