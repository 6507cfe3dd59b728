"""The notebooks' parameters: their one source, the profiles that override them, and their ranges.

The paper's values
    Each notebook's first code cell, tagged ``parameters``, holds the values it runs with by
    default: the paper's (Sec. V) and, for audits the paper does not have, our chosen sizes. That
    cell is their only copy. :func:`defaults` reads it (``NAME = literal`` lines, the form
    papermill injects over) and :func:`params` adds a profile's overrides; the ledger
    (:mod:`obslib.claims`) and the runner read parameters through them. The notebooks are found in
    ``notebooks/`` of the checkout obslib is installed from (``make`` installs it editable), or in
    the folder named by the environment variable ``OBSLIB_NOTEBOOKS``; without them
    :func:`defaults` raises an error that says so. (Packaging a copy of the values would bring
    back the second source they had before.)

Profiles
    ``PROFILES[profile][notebook]`` lists only the parameters that profile changes: ``paper``
    changes none, ``quick`` shrinks the sizes for previews and for the ledger in the tests.

Accepted values
    ``RANGES[notebook][parameter]`` declares, for every parameter of every notebook, the values
    with which the notebook runs to the end: a :class:`Range` (closed, for a number and for each
    entry of a list; the type is that of the default), a :class:`Choice` of strings or a
    :class:`File`. ``CONSTRAINTS[notebook]`` adds the conditions between parameters (or on a whole
    list), each a Python expression over the parameter names with the reason for it.
    :func:`validated_parameters` enforces both before any notebook runs; a test runs every notebook
    at the boundary values of each range. Sizes (seeds, instances, trials) have no upper limit
    unless the work grows faster than in proportion to them; the exponential ones are bounded, alone
    and together.
"""

from __future__ import annotations

import ast
import copy
import json
import math
import os
from dataclasses import dataclass
from pathlib import Path

from . import tracking
from ._validate import MissingFileError, as_mapping, as_path, as_str

__all__ = ["PROFILES", "RANGES", "CONSTRAINTS", "Range", "Choice", "File", "Constraint",
           "notebook_dir", "defaults", "parameter_cell", "params", "profile_names",
           "validated_parameters"]

#: Environment variable naming the folder of the notebooks, for an install without its checkout.
NOTEBOOKS_ENV = "OBSLIB_NOTEBOOKS"


# --------------------------------------------------------------------------------------------
# Declarations
# --------------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Range:
    """Closed range ``[lo, hi]`` of a number (or of each entry of a list); ``None``: unbounded.

    ``why`` says why the range is narrower than the type allows, for the error message.
    """

    lo: float | None = None
    hi: float | None = None
    why: str = ""


@dataclass(frozen=True)
class Choice:
    """One of the strings ``options`` (or, for a list, a list of them)."""

    options: tuple
    why: str = ""


@dataclass(frozen=True)
class File:
    """A path to an existing file, relative to the notebooks' folder."""

    why: str = ""


@dataclass(frozen=True)
class Constraint:
    """``expr`` holds: Python over the parameter names and ``len``, ``min``, ``max``, ``sorted``,
    ``set``, ``all``, ``abs``; ``why`` says why, for the error message."""

    expr: str
    why: str = ""

    def names(self) -> list[str]:
        """The parameters ``expr`` reads, in order of appearance."""
        calls = {"len", "min", "max", "sorted", "set", "all", "abs"}
        found = [(n.col_offset, n.id) for n in ast.walk(ast.parse(self.expr))
                 if isinstance(n, ast.Name) and n.id not in calls]
        return list(dict.fromkeys(name for _, name in sorted(found)))

    def holds(self, values: dict) -> bool:
        env = {"len": len, "min": min, "max": max, "sorted": sorted, "set": set, "all": all,
               "abs": abs}
        return bool(eval(self.expr, {"__builtins__": {}, **env}, dict(values)))  # our own text


SEED = Range(0, 2**32 - 1, "a 32-bit seed")
COUNT = Range(1)
PAIRED = Range(2, why="the paired tests compare runs")
METRICS = Choice(tracking.METRICS)
DATA_FILE = File("a JSON file written by the benchmark command")
#: Notebook 03's exact optimum is a dynamic program over the 2^N sets of N = 2L + extra sensors.
EXACT = "the exact optimum runs over the 2^N sets of N = 2 L + extra <= 16 sensors"
#: Notebook 03's check of Theorem 6 on weights of both signs enumerates every assignment of
#: N = 2 L sensors: 113,400 at L = 5, 7,484,400 at L = 6.
SIGNED = ("the check on weights of both signs enumerates every assignment of N = 2 L sensors "
          "to L targets (113,400 at L = 5)")

#: Notebook 08 compares the teams that the targets get.
TEAMS = "the even split compares the teams of two targets or more"

RANGES: dict[str, dict[str, object]] = {
    "01_model_and_bound": {
        "seed": SEED, "n_controls": COUNT, "n_trials_thm3": COUNT,
        "n_scenes": Range(4, why="the rank audit's scenes alternate three with a control and "
                                 "one without"),
        "u_max": Range(1e-3, 1e3, "the worked example divides by u_max"),
        "n_radii": Range(2, why="the figures contour a polar grid"),
        "n_angles": Range(4, why="the figures contour a polar grid"),
    },
    "02_pair_closed_form": {
        "seed": SEED,
        "u_max": Range(0.0, 1e3),
        "d_io": Range(1e-3, 1e3, "Fig. 2 is drawn at q = u_max / d_io"),
        "alpha_max": Range(1.0, 100.0, "the alpha axis must hold the maximum at alpha = 1"),
        "paper_step": Range(0.01, 1.0, "the step of Fig. 2's grid, drawn as a surface"),
        "fine_alpha_per_unit": Range(1, 1000),
        "fine_theta_quarter": Range(1, 1000),
        "contour_levels": Range(0.01, 0.99, "the bound lies in [0, 1]"),
        "u_over_d_curves": Range(0.0, 100.0),
        "n_theta_curve": Range(2), "n_rational_points": COUNT,
        "digits": Range(20, 1000, "the exact checks need twice double precision"),
        "n_random_points": COUNT, "n_weyl": COUNT,
    },
    "03_greedy_unique_pairs": {
        "seed": SEED, "n_instances": COUNT,
        "targets_min": Range(1, 5, SIGNED),
        "targets_max": Range(1, 5, SIGNED),
        "extra_max": Range(0, 4, EXACT),
        "u_max": Range(0.0, 1e3),
        "search_sensors": Range(2, 12, "the search solves the exact optimum at every step"),
        "search_targets": Range(1, 6, "the search solves the exact optimum at every step"),
        "n_starts": COUNT, "n_steps": Range(0),
    },
    "04_submodularity": {
        "seed": SEED, "u_max": Range(0.0, 1e3), "n_instances": COUNT,
        "n_sensors": Range(2, 10, "all 2^N subsets of every instance are compared"),
        "eps": Range(1e-6, 1e6, "log det(eps I + O^T O) stays finite: 1e-300 underflows"),
        "min_size": Range(0, 2, "sets of fewer sensors are left out; omega needs two"),
        "n_tiny": COUNT,
    },
    "05_two_sensors_tracking": {
        "seed": SEED, "n_seeds": COUNT,
        "steps": Range(71, 10_000, "the switch rates around k = 50 are read over the "
                       "transitions k = 30 to 70 and compared with the rest"),
        "u_max": Range(1e-3, 1e3), "noise_std": Range(0.0, 10.0),
        "q": Range(1e-6, 1e3), "r": Range(1e-6, 1e3), "p0": Range(1e-6, 1e3),
        "metric": METRICS, "anim_every": COUNT, "anim_dpi": Range(20, 300),
    },
    "06_adversarial_target": {
        "seed": SEED, "n_seeds": COUNT, "steps": Range(2, 10_000), "u_max": Range(1e-3, 10.0),
        "noise_std": Range(0.0, 10.0), "n_seeds_strong": COUNT, "n_radii": COUNT,
        "n_angles": Range(3),
    },
    "07_greedy_vs_relaxed": {
        "seed": SEED, "L_max": Range(2, 200, "the ratios are read from L = 2 on"),
        "trials": COUNT, "u_max": Range(0.0, 1e3), "side": Range(1e-3, 1e6),
        "optimum_max_L": Range(0, 8, "the exact optimum's work grows as 4^L"),
        "L_extended": Range(1, 400), "trials_extended": COUNT,
    },
    "08_general_assignment": {
        "seed": SEED, "n_targets": Range(2, 20, TEAMS), "N_min": Range(2, 200, TEAMS),
        "N_max": Range(2, 200, TEAMS),
        "trials": Range(2, why="the teams' spread over trials needs two of them"),
        "eps": Range(1e-6, 1e6), "side": Range(1e-3, 1e6),
        "eps_values": Range(1e-6, 1e6), "compare_N": Range(2, 200, TEAMS), "compare_trials": COUNT,
        "n_tiny": COUNT,
    },
    "09_scaling": {
        "times_file": DATA_FILE, "seed": SEED, "greedy_sizes": Range(2, 4000),
        "literal_sizes": Range(2, 800), "relaxed_sizes": Range(2, 1000),
    },
    "10_criteria": {
        "seed": SEED, "n_seeds": PAIRED, "metrics": METRICS, "loss_threshold": Range(1e-3, 1e3),
        "times_file": DATA_FILE, "assign_targets": Range(1, 10), "assign_seeds": PAIRED,
        "assign_steps": Range(2, 1000), "assign_side": Range(1.0, 1e4),
        "assign_u_max": Range(1e-3, 10.0, "the tracking engine needs u_max > 0; targets faster "
                              "than 10 per step outrun their filters, which then diverge"),
        "assign_noise_std": Range(1e-3, 10.0, "the filter needs measurement noise"),
        "assign_p0": Range(1e-6, 1e3), "assign_loss": Range(1e-3, 1e3),
    },
    "11_unchecked_statements": {
        "seed": SEED, "n_seeds_typical": COUNT, "jitter_fractions": Range(
            1e-12, 1.0, "the jitters are drawn on a log scale, where 0 has no place"),
        "n_jitter": COUNT, "n_geometries": COUNT, "n_refine": COUNT, "u_max": Range(1e-3, 1e3),
        "n_3dm": COUNT, "solver_L": Range(1, 40), "time_budget": Range(0.1, 3600.0),
        "problem3_L": Range(1, 200), "problem3_trials": COUNT, "n_seeds_disc": COUNT,
        "n_radii": COUNT, "n_angles": Range(3),
    },
    "12_many_targets": {
        "seed": SEED, "n_seeds": PAIRED,
        "net_sensors": Range(2, 400, "the pair greedy's work per step grows as N^2, and so "
                             "does the team greedies' (N rounds over N sensors)"),
        "net_targets": COUNT, "net_scenes": PAIRED, "net_steps": Range(2),
        "anim_every": COUNT, "anim_dpi": Range(20, 300),
    },
}

CONSTRAINTS: dict[str, tuple[Constraint, ...]] = {
    "02_pair_closed_form": (
        Constraint("contour_levels == sorted(set(contour_levels))",
                   "contour levels increase"),
        Constraint("paper_step <= alpha_max / 2", "the published grid needs two steps in alpha"),
        Constraint("alpha_max <= 1000 * paper_step",
                   "the published grid is drawn as a surface: at most 1000 steps in alpha"),
        Constraint("alpha_max * fine_alpha_per_unit * fine_theta_quarter <= 1_000_000",
                   "the fine grid's 4 alpha_max fine_alpha_per_unit fine_theta_quarter points "
                   "take about 1 GB at this limit"),
    ),
    "03_greedy_unique_pairs": (
        Constraint("targets_min <= targets_max"),
        Constraint("2 * search_targets <= search_sensors",
                   "each target needs a pair of its own"),
    ),
    "04_submodularity": (
        Constraint("n_instances * 2 ** n_sensors <= 4_096_000",
                   "every subset of every instance is held at once: 0.4 GB for 2000 instances "
                   "of 10 sensors"),
    ),
    "08_general_assignment": (
        Constraint("N_min <= N_max"),
        Constraint("n_targets <= N_min and n_targets <= min(compare_N)",
                   "every target needs a sensor"),
    ),
    "12_many_targets": (
        Constraint("2 * net_targets <= net_sensors",
                   "the unique-pair assignments give every target a pair of its own"),
    ),
}

PROFILES: dict[str, dict[str, dict]] = {
    "paper": {nb: {} for nb in RANGES},
    "quick": {
        "01_model_and_bound": {
            "n_scenes": 200,
            "n_trials_thm3": 2000,
            "n_radii": 10,
            "n_angles": 60,
        },
        "02_pair_closed_form": {
            "fine_alpha_per_unit": 20,
            "fine_theta_quarter": 30,
            "n_theta_curve": 35,
            "n_rational_points": 20,
            "n_random_points": 200,
            "n_weyl": 2000,
        },
        "03_greedy_unique_pairs": {"n_instances": 300, "n_starts": 4, "n_steps": 100},
        "04_submodularity": {"n_instances": 200, "n_sensors": 5, "n_tiny": 50},
        "05_two_sensors_tracking": {"n_seeds": 20, "anim_every": 15},
        "06_adversarial_target": {"n_seeds": 10, "n_seeds_strong": 2, "n_radii": 3, "n_angles": 36},
        "07_greedy_vs_relaxed": {
            "trials": 5,
            "optimum_max_L": 4,
            "L_extended": [50],
            "trials_extended": 1,
        },
        "08_general_assignment": {"trials": 5, "compare_trials": 3, "n_tiny": 50},
        "09_scaling": {
            "greedy_sizes": [20, 100, 400],
            "literal_sizes": [20, 50],
            "relaxed_sizes": [20, 100],
        },
        "10_criteria": {
            "n_seeds": 20,
            "assign_targets": [2, 3],
            "assign_seeds": 20,
            "assign_steps": 20,
        },
        "11_unchecked_statements": {
            "n_seeds_typical": 100,
            "n_jitter": 20,
            "n_geometries": 200,
            "n_refine": 40,
            "n_3dm": 10,
            "solver_L": [3, 6],
            "time_budget": 2.0,
            "problem3_L": [2, 5],
            "problem3_trials": 5,
            "n_seeds_disc": 10,
            "n_radii": 3,
            "n_angles": 36,
        },
        "12_many_targets": {
            "n_seeds": 20,
            "net_sensors": 40,
            "net_targets": 10,
            "net_steps": 30,
            "anim_every": 10,
        },
    },
}


# --------------------------------------------------------------------------------------------
# The paper's values, read from the notebooks
# --------------------------------------------------------------------------------------------

def notebook_dir() -> Path:
    """The folder of the notebooks: ``$OBSLIB_NOTEBOOKS``, else ``notebooks/`` of the checkout.

    Raises
    ------
    FileNotFoundError
        When the folder does not exist (obslib installed without its checkout).

    Examples
    --------
    >>> notebook_dir().name
    'notebooks'
    """
    env = os.environ.get(NOTEBOOKS_ENV)
    folder = Path(env) if env else Path(__file__).resolve().parents[1] / "notebooks"
    if not folder.is_dir():
        raise FileNotFoundError(
            f"the notebooks' parameters cells hold the paper's values, and there is no notebooks "
            f"folder at {folder}: install obslib from its checkout (pip install -e .) or set "
            f"{NOTEBOOKS_ENV} to the checkout's notebooks/ folder")
    return folder


_CELLS: dict = {}  # path -> ((mtime_ns, size), parameters): the ledger asks many times


def parameter_cell(path) -> dict:
    """``{name: value}`` of the notebook's tagged ``parameters`` cell (``NAME = literal`` lines).

    Examples
    --------
    >>> parameter_cell(notebook_dir() / "05_two_sensors_tracking.ipynb")["metric"]
    'mahalanobis'
    """
    path = as_path(path, "path", exists=True)
    st = path.stat()
    key = (st.st_mtime_ns, st.st_size)
    if path in _CELLS and _CELLS[path][0] == key:
        return copy.deepcopy(_CELLS[path][1])
    try:
        cells = json.loads(path.read_text())["cells"]
    except (ValueError, KeyError, TypeError, UnicodeDecodeError):
        raise ValueError(f"path {path}: not a notebook (no JSON with cells)") from None
    tagged = [c for c in cells if "parameters" in c.get("metadata", {}).get("tags", [])]
    if len(tagged) != 1 or tagged[0]["cell_type"] != "code":
        raise ValueError(f"{path.name}: needs exactly one code cell tagged 'parameters'")
    out = {}
    for node in ast.parse("".join(tagged[0]["source"])).body:
        if not (isinstance(node, ast.Assign) and len(node.targets) == 1
                and isinstance(node.targets[0], ast.Name)):
            raise ValueError(f"{path.name}: the parameters cell holds only NAME = literal lines "
                             f"(line {node.lineno})")
        try:
            out[node.targets[0].id] = ast.literal_eval(node.value)
        except ValueError:
            raise ValueError(f"{path.name}: the parameters cell holds only NAME = literal lines "
                             f"(line {node.lineno})") from None
    _CELLS[path] = (key, out)
    return copy.deepcopy(out)


def defaults(notebook: str) -> dict:
    """The values of ``notebook`` (its stem) at the paper's parameters, from its parameters cell.

    Examples
    --------
    >>> defaults("05_two_sensors_tracking")["n_seeds"]
    200
    """
    if as_str(notebook, "notebook") not in RANGES:
        raise ValueError(f"no parameters for notebook {notebook!r}; known: {list(RANGES)}")
    path = notebook_dir() / f"{notebook}.ipynb"
    if not path.exists():
        raise MissingFileError(f"{path} is missing: its parameters cell holds the paper's values")
    return parameter_cell(path)


def profile_names() -> list[str]:
    """Names of the known profiles.

    Examples
    --------
    >>> profile_names()
    ['paper', 'quick']
    """
    return list(PROFILES)


def params(notebook: str, profile: str = "paper") -> dict:
    """Parameters of ``notebook`` (its stem, e.g. ``"01_model_and_bound"``) under ``profile``.

    The notebook's parameters cell (:func:`defaults`) updated by the profile's overrides.

    Examples
    --------
    >>> params("05_two_sensors_tracking", "quick")["n_seeds"]
    20
    """
    if as_str(profile, "profile") not in PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    out = defaults(notebook)
    out.update(copy.deepcopy(PROFILES[profile].get(notebook, {})))
    return out


# --------------------------------------------------------------------------------------------
# Checks
# --------------------------------------------------------------------------------------------

def _fmt(x) -> str:
    return f"{x:g}" if isinstance(x, float) else str(x)


def _describe(kind: type, rule) -> str:
    noun = {int: "an integer", float: "a number", str: "a string", bool: "True or False"}[kind]
    if isinstance(rule, Choice):
        text = "one of " + ", ".join(repr(c) for c in rule.options)
    elif isinstance(rule, File):
        text = "the path of an existing file"
    elif rule is None or (rule.lo is None and rule.hi is None):
        text = noun
    elif rule.hi is None:
        text = f"{noun} >= {_fmt(rule.lo)}"
    elif rule.lo is None:
        text = f"{noun} <= {_fmt(rule.hi)}"
    else:
        text = f"{noun} in [{_fmt(rule.lo)}, {_fmt(rule.hi)}]"
    why = getattr(rule, "why", "")
    return f"{text} ({why})" if why and not isinstance(rule, File) else text


def _accepts(kind: type, rule, value):
    """``value`` converted to ``kind`` if it is accepted, else ``None``."""
    if kind is bool:
        return value if isinstance(value, bool) else None
    if isinstance(value, bool):
        return None
    if kind is str:
        if not isinstance(value, str) or not value:
            return None
        if isinstance(rule, Choice) and value not in rule.options:
            return None
        if isinstance(rule, File) and not (notebook_dir() / value).is_file():
            return None
        return value
    if kind is int and not isinstance(value, int):
        return None
    if kind is float:
        if not isinstance(value, (int, float)) or not math.isfinite(value):
            return None
        value = float(value)
    if isinstance(rule, Range):
        if (rule.lo is not None and value < rule.lo) or (rule.hi is not None and value > rule.hi):
            return None
    return value


def _parameter_iv(notebook: str, name: str, value, default, rule):
    if isinstance(default, list):
        kinds = {type(x) for x in default}
        kind = float if float in kinds else (kinds.pop() if len(kinds) == 1 else float)
        ok = isinstance(value, list) and value and all(
            _accepts(kind, rule, x) is not None for x in value)
        if not ok:
            what = _describe(kind, rule).split(" ", 1)[1]  # "integer >= 1", not "an integer"
            raise ValueError(f"notebook {notebook}: parameter {name} = {value!r} is not accepted; "
                             f"expected a non-empty list, each entry {what}")
        return [_accepts(kind, rule, x) for x in value]
    got = _accepts(type(default), rule, value)
    if got is None:
        raise ValueError(f"notebook {notebook}: parameter {name} = {value!r} is not accepted; "
                         f"expected {_describe(type(default), rule)}")
    return got


def validated_parameters(notebook: str, values: dict, defaults: dict | None = None) -> dict:
    """Check parameter ``values`` (overrides) for ``notebook`` against its declarations.

    Parameters
    ----------
    notebook : str
        The notebook's stem.
    values : dict
        Parameter name -> value to inject.
    defaults : dict, optional
        The notebook's declared parameters with their default values (default: its parameters
        cell, :func:`defaults`). Each value must have its default's type (an integer where the
        default is an integer, a number where it is a float, a non-empty list of such where it
        is a list), lie in its :data:`RANGES` entry, and the values together with the defaults
        must satisfy :data:`CONSTRAINTS`.

    Returns
    -------
    dict
        The values, numbers converted to the default's type (``3`` -> ``3.0`` for a float).

    Raises
    ------
    ValueError
        Naming the notebook, the parameter and the accepted values.

    Examples
    --------
    >>> nb = "05_two_sensors_tracking"
    >>> validated_parameters(nb, {"n_seeds": 5, "u_max": 2})
    {'n_seeds': 5, 'u_max': 2.0}
    >>> validated_parameters(nb, {"n_seeds": -5})
    Traceback (most recent call last):
    ...
    ValueError: notebook 05_two_sensors_tracking: ...; expected an integer >= 1
    """
    values = as_mapping(values, "values")
    if defaults is None:
        defaults = globals()["defaults"](notebook)
    defaults = as_mapping(defaults, "defaults")
    unknown = sorted(set(values) - set(defaults))
    if unknown:
        raise ValueError(f"notebook {notebook} has no parameter(s) {unknown}; "
                         f"its parameters: {sorted(defaults)}")
    rules = RANGES.get(notebook, {})
    out = {name: _parameter_iv(notebook, name, value, defaults[name], rules.get(name))
           for name, value in values.items()}
    merged = {**defaults, **out}
    for c in CONSTRAINTS.get(notebook, ()):
        if not c.holds(merged):
            shown = ", ".join(f"{n} = {merged[n]!r}" for n in c.names())
            why = f" ({c.why})" if c.why else ""
            raise ValueError(f"notebook {notebook}: parameters {shown} are not accepted; "
                             f"expected {c.expr}{why}")
    return out
