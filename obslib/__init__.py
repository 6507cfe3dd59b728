"""obslib: the computations of Zhou & Tokekar, "A Lower Bound on Observability for Target
Tracking with Range Sensors and its Application to Sensor Assignment".

Points are rows of NumPy arrays of shape ``(n, 2)``. Every public function validates its
input and raises :class:`ValueError` naming the offending sensor or target.

Modules
-------
The core, in the order of the paper:

observability
    The stacked observability matrix of Section III and its exact inverse condition number.
bounds
    Theorem 1's lower bound, the pair closed form of Theorem 4, the worst-case control.
controls
    The polar grid of controls in the disc that exact-versus-bound comparisons sweep.
pair_form
    Numerics of the pair closed form: grids of the bound, the maximising alpha, Weyl for 2x2.
symbolic
    SymPy derivations of Theorems 4-5 (imported on demand: ``import obslib.symbolic``).
scenes
    Seeded random scenes, including near-degenerate ones.
assignment
    Unique pair assignment: greedy Algorithm 1, relaxed matching, exact optimum (branch and
    bound).
measures
    Theorem 8's measures of the symmetric observability matrix (trace, log det, rank, trace
    inverse).
submodularity
    Exhaustive monotonicity/submodularity checks of set functions; smallest witnesses.
bound_tables
    Theorem 1's bound for every subset of the sensors, as a table or a set function.
teams
    Problem 2: greedy teams for a Theorem 8 measure, and the exact optimum for tiny instances.
tracking
    Section V tracking simulations: EKF (filterpy), strategies, adversarial target, Monte Carlo.
sweep
    Runs a study's independent trials serially or in parallel, with the same numbers.

On top of the core, one module per chapter of the book in each of, named after the chapter's
notebook without its number (``model_and_bound`` for ``01_model_and_bound``, ...):

studies
    The paper's audits and experiments (``studies.model_and_bound``, ``studies.pair_closed_form``,
    ``studies.greedy_unique_pairs``, ...), the topics several chapters share
    (``studies.batch_optimum``, ``studies.replay``, ...) and the published numbers
    (``studies.published``).
viz
    Every matplotlib figure (``viz.model_and_bound``, ``viz.pair_closed_form``, ...) and the
    drawings the chapters share (``viz.style``, ``viz.tracking``).
claims
    The claims ledger: one record per claim of the paper, re-checked with ``studies``.

The experiments' parameters: ``profiles`` (named parameter sets of the notebooks and the ledger).
How a number reads in the book's prose and tables, for the ledger, the figures and the book:
``formatting``.
Repository tooling: ``tools`` (the papermill runner behind ``make book`` and the benchmarks, with
the command lines ``python -m obslib.run`` and ``python -m obslib.bench``). What only the book
needs (the figure and table settings every notebook applies, each chapter's glue and tables) is
kept beside it in the package ``obsbook``, which this library never imports.
"""

from . import tracking  # (ob.tracking.simulate, PAPER_CIRCLE, PAPER_ADVERSARIAL)
from .assignment import (
    PairAssignment,
    greedy_pair_assignment,
    optimal_pair_assignment,
    relaxed_pair_assignment,
)
from .bound_tables import lower_bound_table
from .bounds import lower_bound, pair_bound_polar, pair_bounds, relative_vectors, worst_case_control
from .measures import MEASURES, measure, measure_table, symmetric_observability_matrix
from .observability import inverse_condition_number, observability_matrix, relative_rows
from .submodularity import audit_set_function
from .teams import greedy_team_assignment, optimal_team_assignment

__version__ = "0.1.0"

__all__ = [
    "observability_matrix",
    "inverse_condition_number",
    "relative_rows",
    "lower_bound",
    "pair_bounds",
    "pair_bound_polar",
    "relative_vectors",
    "worst_case_control",
    "PairAssignment",
    "greedy_pair_assignment",
    "relaxed_pair_assignment",
    "optimal_pair_assignment",
    "MEASURES",
    "measure",
    "measure_table",
    "symmetric_observability_matrix",
    "audit_set_function",
    "lower_bound_table",
    "greedy_team_assignment",
    "optimal_team_assignment",
    "tracking",
]

#: Submodules imported on first attribute access (``obslib.claims.evaluate(...)`` works after a
#: bare ``import obslib``) rather than at import time, since they pull in SymPy, papermill etc.
_LAZY = ("claims", "profiles", "tools", "symbolic", "pair_form", "controls", "scenes",
         "studies", "viz", "sweep", "formatting")


def __getattr__(name):
    if name in _LAZY:
        import importlib

        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'obslib' has no attribute {name!r}")
