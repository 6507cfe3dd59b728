"""How robust are the ledger's verdicts to the parameters the paper fixed?

For a claim, :func:`verdict_robustness` re-evaluates its check, a pure function of its
parameters, with one parameter of its notebook changed at a time from those of a base profile
(``paper`` by default: the paper's parameters). The dimensions are the target's speed
bound ``u_max``, the measurement noise ``noise_std``, the distance metric of the pair bound
(``metric``) and the Monte Carlo size (the notebook's number of seeds, instances or trials). A
dimension applies to a claim when its notebook has that parameter (the metric: the tracking
notebooks 05 and 06). Claims about the numbers of one published run are not varied in the
parameters that run was made with (:data:`FIXED_BY_PUBLISHED_RUN`).

Each variant records its status and whether the whole finding (the sentence and the evidence) is
the base's: a verdict that *holds* was earned again by different numbers; an *unchanged* finding
does not depend on the parameter at all.

:func:`describe` says, per claim and dimension, over which range its verdict holds; the report
renders that as a table and the command line prints :func:`robustness_table`. The result is
stored as data (:func:`write_json`, :func:`read_json`) by
``python -m obslib.claims --robustness --write obslib/data/robustness.json`` (:data:`DATA`) and
read by the report and the chapters, whose verdicts carry its caveats (:func:`caveats`). Only
claims of the paper (kind ``"paper"``) have verdicts to vary; the other kinds are not among
them.
"""

from __future__ import annotations

import json
from pathlib import Path

from .._io import write_output
from .._validate import as_mapping, as_names, as_path, as_sequence, as_str
from ..profiles import RANGES, profile_names
from ..studies import adversarial_target, two_sensors_tracking
from ._ledger import _record, evaluate, registry, resolve

__all__ = ["DATA", "caveat", "caveats",
           "DIMENSIONS", "SIZE_KEYS", "TRACKING_NOTEBOOKS", "FIXED_BY_PUBLISHED_RUN", "HEADERS",
           "default_ids", "verdict_robustness", "describe", "robustness_table", "to_json",
           "write_json", "read_json"]

#: Per dimension, the factors applied to the default (numbers) or the values tried (metric).
DIMENSIONS = {
    "u_max": (0.25, 0.5, 2.0, 4.0),
    "noise_std": (0.25, 0.5, 2.0, 4.0),
    "metric": ("mahalanobis", "euclidean"),
    "size": (0.5, 2.0),
}

#: The stored study, computed at the paper's values (``python -m obslib.claims --robustness
#: --write`` writes it here by default).
DATA = Path(__file__).resolve().parents[1] / "data" / "robustness.json"

#: Parameter names that set a notebook's Monte Carlo size, in order of preference.
SIZE_KEYS = ("n_seeds", "n_instances", "trials", "n_scenes")

#: Notebooks of the tracking experiments (Sections V-A and V-B).
TRACKING_NOTEBOOKS = (two_sensors_tracking.NOTEBOOK, adversarial_target.NOTEBOOK)

#: Claims about the numbers of one published run -> the dimensions fixed by that run (its own
#: speed bound, noise and metric: a run made with other values is another run).
#: ``fig7-figure-data`` is decided by the replay alone, so no parameter of its notebook enters.
FIXED_BY_PUBLISHED_RUN = {
    "fig6-figure-data": ("u_max", "noise_std", "metric"),
    "fig7-figure-data": ("u_max", "noise_std", "metric", "size"),
}

def _base_iv(base) -> str:
    """A profile to start from (a name of :func:`obslib.profiles.profile_names`)."""
    if as_str(base, "base") not in profile_names():
        raise ValueError(f"base: unknown profile {base!r}; known: {profile_names()}")
    return base


def _rows_iv(rows) -> list:
    """Rows of :func:`verdict_robustness`: dicts with ``id``, ``base`` and ``variants``."""
    rows = as_sequence(rows, "rows")
    for r in rows:
        if not (isinstance(r, dict) and isinstance(r.get("id"), str)
                and isinstance(r.get("base"), str) and isinstance(r.get("variants"), dict)):
            raise ValueError(f"rows must be rows of verdict_robustness (dicts with id, base and "
                             f"variants), got {r!r}")
    return rows


def default_ids(base: str = "quick") -> list[str]:
    """Claims of the paper whose verdict is partly or refuted at ``base``, and every tracking
    claim of the paper.

    Examples
    --------
    The claim that :math:`\\alpha^* \\ne 1` is judged "partly" at ``quick``
    (:func:`verdict_robustness` shows it), so it is among them:

    >>> from obslib.claims.robustness import default_ids
    >>> ids = default_ids("quick")
    >>> "thm5-alpha-not-1" in ids, len(ids) == len(set(ids))
    (True, True)
    """
    return [r.id for r in evaluate(_base_iv(base)) if r.kind == "paper"
            and (r.status in ("partly", "refuted") or r.notebook in TRACKING_NOTEBOOKS)]


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


def _finding(rec) -> str:
    """The whole finding of a record as text (sentence and evidence), to tell unchanged ones."""
    table = None if rec.table is None else [rec.table.columns, rec.table.rows]
    return rec.ours + "\n" + json.dumps([rec.evidence, table], sort_keys=True, default=repr)


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
        Per claim: ``id``, ``notebook``, ``base`` (its status at ``base``), ``variants``:
        dimension -> list of ``(label, status, unchanged)`` (``unchanged``: the whole finding is
        the base's), and ``fixed``: the dimensions not varied because the claim is about a
        published run made with them (:data:`FIXED_BY_PUBLISHED_RUN`). Claims whose notebook
        has no parameters in the profiles get no variants.

    Examples
    --------
    One claim, one dimension: the four factors of :data:`DIMENSIONS` applied to ``u_max``:

    >>> from obslib.claims.robustness import DIMENSIONS, verdict_robustness
    >>> row = verdict_robustness(ids=["thm5-alpha-not-1"], dimensions=["u_max"])[0]
    >>> row["id"], len(row["variants"]["u_max"]) == len(DIMENSIONS["u_max"])
    ('thm5-alpha-not-1', True)
    """
    base = _base_iv(base)
    dims = list(DIMENSIONS) if dimensions is None else list(as_names(dimensions, "dimensions"))
    unknown = [d for d in dims if d not in DIMENSIONS]
    if unknown:
        raise ValueError(f"dimensions: unknown {unknown}; known: {list(DIMENSIONS)}")
    ids = default_ids(base) if ids is None else list(as_names(ids, "ids"))
    reg = registry()
    missing = [i for i in ids if i not in reg]
    if missing:
        raise ValueError(f"unknown claim id(s): {missing}")
    rows = []
    for cid in ids:
        c = reg[cid]
        p = resolve(cid, base)
        rec = _record(c, c.check(p))
        fixed = [d for d in FIXED_BY_PUBLISHED_RUN.get(cid, ()) if d in dims]
        row = {"id": cid, "notebook": c.notebook, "base": rec.status, "variants": {},
               "fixed": fixed}
        if c.notebook in RANGES:
            for dim, options in _variants(p, c.notebook).items():
                if dim not in dims or dim in fixed:
                    continue
                got = []
                for label, key, value in options:
                    r = _record(c, c.check({**p, key: value}))
                    got.append((label, r.status, _finding(r) == _finding(rec)))
                row["variants"][dim] = got
        rows.append(row)
    return rows


#: Column headers of the robustness table: what is varied and the values tried (MyST).
#:
#: :meta hide-value:
HEADERS = {
    "u_max": r"$u_{\max}$ $\times$ 0.25, 0.5, 2, 4",
    "noise_std": r"noise $\sigma$ $\times$ 0.25, 0.5, 2, 4",
    "metric": "distances: the other metric",
    "size": r"seeds or instances $\times$ 0.5, 2",
}

#: The same headers in plain text, for the command line.
PLAIN_HEADERS = {"u_max": "u_max x0.25-4", "noise_std": "noise x0.25-4", "metric": "metric",
                 "size": "size x0.5, x2"}


def _value(label: str) -> str:
    """A variant's label as text: ``x0.25`` -> ``×0.25``, ``n_seeds x2`` -> ``×2``,
    ``euclidean`` -> ``Euclidean``."""
    last = label.split()[-1]
    return "×" + last[1:] if last.startswith("x") else last.capitalize()


def _cell(base: str, got, fixed: bool = False) -> str:
    if fixed:
        return "fixed by the published run"
    if not got:
        return "n/a"
    changed = [(label, status) for label, status, *_ in got if status != base]
    if not changed:
        same = all(len(g) > 2 and g[2] for g in got)
        return "unchanged finding" if same else "holds"
    return "; ".join(f"{status} at {_value(label)}" for label, status in changed)


def describe(row: dict, status: str | None = None) -> tuple[str, list[str]]:
    """One claim's row of the robustness table: its verdict and one cell per dimension.

    A cell reads ``holds`` when the verdict is the same at every value tried, ``unchanged
    finding`` when not even the finding changes, names the verdict where it changes
    (``refuted at ×2``), reads ``n/a`` where the experiment has no such parameter and ``fixed by
    the published run`` where the claim is about a run made with that value.

    Parameters
    ----------
    row : dict
        A row of :func:`verdict_robustness` (or of the stored data).
    status : str, optional
        The verdict to show (default the row's base verdict); where it differs from the base,
        the text names both.

    Examples
    --------
    >>> row = {"id": "c1", "base": "partly",
    ...        "variants": {"u_max": [("x0.5", "partly"), ("x2", "refuted")]}}
    >>> describe(row)
    ('partly', ['refuted at ×2', 'n/a', 'n/a', 'n/a'])
    >>> describe(row, "refuted")[0]
    'refuted (partly in the stored study)'
    """
    (row,) = _rows_iv([row])
    if status is not None:
        as_str(status, "status")
    shown = status or row["base"]
    verdict = shown if shown == row["base"] else f"{shown} ({row['base']} in the stored study)"
    cells = [_cell(row["base"], row["variants"].get(d), d in row.get("fixed", ()))
             for d in DIMENSIONS]
    return verdict, cells


#: How a factor of a parameter reads in a caveat.
_FACTORS = {"0.25": "a quarter of", "0.5": "half", "2": "twice", "4": "four times"}

#: What each Monte Carlo size counts, in words.
_SIZE_WORDS = {"n_seeds": "the noise seeds", "n_instances": "the instances", "trials": "the trials",
               "n_scenes": "the scenes"}


def _changed_words(dim: str, label: str) -> str:
    """One variant in words: ``with a quarter of $u_{\\max}$``, ``with Euclidean distances``."""
    if dim == "metric":
        return f"with {label.capitalize()} distances"
    last = label.split()[-1]
    factor = _FACTORS.get(last[1:], f"{last[1:]} times")
    if dim == "u_max":
        return f"with {factor} " + r"$u_{\max}$"
    if dim == "noise_std":
        return f"with {factor} the measurement noise"
    return f"with {factor} {_SIZE_WORDS.get(label.split()[0], 'the Monte Carlo size')}"


def caveat(row: dict, status: str | None = None) -> str:
    """The sentence a verdict carries when the robustness study changes it, or ``""``.

    Says the verdict at the base parameters and, grouped by verdict, every change of one
    parameter that gives another.

    Examples
    --------
    >>> row = {"id": "c1", "base": "reproduced",
    ...        "variants": {"u_max": [("x0.25", "refuted"), ("x2", "reproduced")],
    ...                     "metric": [("euclidean", "refuted")],
    ...                     "size": [("n_seeds x0.5", "partly")]}}
    >>> import textwrap
    >>> print(textwrap.fill(caveat(row), 60))
    Reproduced at the paper's values; refuted with a quarter of
    $u_{\\max}$ and with Euclidean distances; partly with half
    the noise seeds.
    >>> same = {"u_max": [("x2", "partly")]}
    >>> caveat({"id": "c2", "base": "partly", "variants": same})
    ''
    """
    (row,) = _rows_iv([row])
    base = status or row["base"]
    by_status: dict = {}
    for dim in DIMENSIONS:
        for label, st, *_ in row["variants"].get(dim, ()):
            if st != base:
                by_status.setdefault(st, []).append(_changed_words(dim, label))
    if not by_status:
        return ""
    parts = []
    for st, changes in by_status.items():
        words = changes[0] if len(changes) == 1 else ", ".join(changes[:-1]) + " and " + changes[-1]
        parts.append(f"{st} {words}")
    return f"{base.capitalize()} at the paper's values; " + "; ".join(parts) + "."


def caveats(data: dict | None = None) -> dict:
    """Id -> caveat sentence (:func:`caveat`) of every row of the stored study whose verdict
    changes (default: the data of :data:`DATA`, when it was computed at the paper's values)."""
    if data is None:
        if not DATA.exists():
            return {}
        data = read_json(DATA)
    if as_mapping(data, "data").get("base") != "paper":
        return {}
    return {row["id"]: text for row in _rows_iv(data["rows"]) if (text := caveat(row))}


def robustness_table(rows, statuses=None) -> str:
    """Plain text: one line per claim, per dimension whether its verdict holds (see
    :func:`describe`); the command line prints it.

    Examples
    --------
    >>> rows = [{"id": "c1", "base": "partly",
    ...          "variants": {"u_max": [("x0.5", "partly"), ("x2", "refuted")]}}]
    >>> print(robustness_table(rows), end="")
    claim  verdict  u_max x0.25-4  noise x0.25-4  metric  size x0.5, x2
    c1     partly   refuted at ×2  n/a            n/a     n/a
    """
    rows = _rows_iv(rows)
    statuses = {} if statuses is None else as_mapping(statuses, "statuses")
    table = [["claim", "verdict"] + [PLAIN_HEADERS[d] for d in DIMENSIONS]]
    for r in rows:
        verdict, cells = describe(r, (statuses or {}).get(r["id"]))
        table.append([r["id"], verdict] + cells)
    widths = [max(len(line[i]) for line in table) for i in range(len(table[0]))]
    return "".join("  ".join(c.ljust(w) for c, w in zip(line, widths)).rstrip() + "\n"
                   for line in table)


def to_json(rows, base: str = "quick") -> str:
    """The text of the stored data: :func:`verdict_robustness`'s rows with the base profile and
    the dimensions tried (:func:`read_json` reads it back).

    Examples
    --------
    >>> data = json.loads(to_json([{"claim": "x", "holds": True}]))
    >>> data["base"], data["rows"], set(data["dimensions"]) == set(DIMENSIONS)
    ('quick', [{'claim': 'x', 'holds': True}], True)
    """
    rows = as_sequence(rows, "rows")
    if not all(isinstance(r, dict) for r in rows):
        raise ValueError("rows must be a list of dicts")
    data = {"base": _base_iv(base), "dimensions": {k: list(v) for k, v in DIMENSIONS.items()},
            "rows": rows}
    try:
        return json.dumps(data, indent=1) + "\n"
    except (TypeError, ValueError):
        raise ValueError("rows must hold JSON values (numbers, text, lists, dicts)") from None


def write_json(rows, path, base: str = "quick") -> bool:
    """Store :func:`to_json` at ``path`` (:func:`obslib._io.write_output`: atomic, and untouched
    when it already holds the same data); returns whether anything was written."""
    text = to_json(rows, base)
    return write_output(as_path(path, "path"), text)


def read_json(path) -> dict:
    """The data of :func:`write_json`: ``base``, ``dimensions`` and ``rows``.

    Examples
    --------
    >>> import tempfile
    >>> from pathlib import Path
    >>> path = Path(tempfile.mkdtemp()) / "robustness.json"
    >>> write_json([{"claim": "x"}], path, base="paper")
    True
    >>> data = read_json(path)
    >>> data["base"], data["rows"]
    ('paper', [{'claim': 'x'}])
    >>> _ = path.write_text("[1, 2]")
    >>> read_json(path)
    Traceback (most recent call last):
    ...
    ValueError: ...: not a robustness data file (keys base, dimensions, rows)
    """
    path = as_path(path, "path")
    try:
        data = json.loads(path.read_text())
    except (OSError, ValueError) as exc:
        raise ValueError(f"path {path}: not a robustness data file ({exc})") from None
    if not isinstance(data, dict) or not {"base", "dimensions", "rows"} <= set(data):
        raise ValueError(f"path {path}: not a robustness data file (keys base, dimensions, rows)")
    return data
