"""Benchmarks that print ratios: ``python -m obslib.bench assignment``.

Absolute times depend on the machine; the ratios are what the project tracks. Each benchmark
prints its readable lines and progress on standard error and one JSON object, alone, on standard
output.

``assignment``
    ``greedy_over_one_pass``: the greedy (Algorithm 1 from geometry) at ``N = 2000``,
    ``L = 1000``, over one vectorised evaluation of every pair bound for every target with the
    same kernel (target <= 2). ``literal_over_greedy``: Algorithm 1 as printed (recomputing all
    weights each round, vectorised per round) over the greedy at ``N = 400``, ``L = 200``
    (target >= 100). ``peak_rss_gb``: the process's peak resident memory (target < 4). With
    ``--sensors N --targets L`` only the greedy from geometry runs, once, at that size:
    ``greedy_s`` and ``peak_rss_gb`` (targets at ``N = 10,000``, ``L = 5,000``: 30 s, 2 GB).
    Progress goes to stderr, the JSON line to stdout.

``scaling``
    Wall time of each assignment algorithm against ``N`` (``L = N / 2``), with the machine's
    description. The scaling notebook plots ``book/data/scaling_times.json``: measured times are
    committed data, so ``make book`` stays deterministic.

``criteria``
    Microseconds per pair evaluation of the bound and of each classical criterion of the
    criteria notebook (:func:`obslib.studies.criteria.criterion_scores`), batched over many
    estimates and for a single estimate, with the machine's description. That notebook reads
    ``book/data/criteria_times.json``: measured times are committed data, so ``make book`` stays
    deterministic.

``tracking``
    The closed loop of many targets with the unique-pair greedy (``--sensors``, ``--targets``;
    default 1000 and 100): ``step_ms``, ``step_over_greedy`` (target at most 1.5) and
    ``steps_per_s``, from :mod:`obslib.tools.bench_tracking`.

``book``
    ``exec_s``: executing every notebook at its default parameters one at a time (papermill, one
    kernel per notebook, into a scratch folder); ``floor_s``: executing the same number of
    trivial notebooks the same way, the fixed cost of a kernel per notebook, each one just
    before a notebook; ``exec_over_floor`` their ratio. ``stack_floor_s``: as many
    minimal notebooks of this book, each importing the stack every notebook starts with
    (matplotlib, NumPy, pandas, myst-nb's ``glue``, ``obslib``, ``obsbook.setup()``) and
    showing one small figure; ``stack_over_floor`` is
    what that start costs before any content, and ``exec_over_stack`` what the notebooks cost over
    it (a regression guard: at most 3.5). The notebooks also run ``jobs`` at a time as ``make book``
    runs them (``--jobs``, default the cores available), longest first by their times alone:
    ``parallel_s`` is that wall time and ``parallel_speedup`` is ``exec_s`` over it (target at
    least 1.6 on two cores).
    ``--profile quick`` runs the notebooks at the ``quick`` profile's tiny sizes instead: what
    the same notebooks, figures and derivations cost with almost no computation.

Progress goes to standard error (on a terminal). ``--write FILE`` (scaling, criteria) also stores
the JSON, indented, in ``FILE``; it is checked before any work (a missing directory, an
unwritable path, a FIFO or a device is a command-line error, exit status 2) and written at the
end, atomically (:mod:`obslib._io`); a write that fails then is a one-line error, exit status 1.
The book's committed data (``book/data/``) is refused unless ``--update-book`` says so: the
notebooks read it, so replacing it changes their outputs, and nbval fails until ``make book``
has re-executed them. A stop (Ctrl-C, SIGTERM, SIGHUP) ends a benchmark with one line and the
exit status ``128 +`` the signal's number.
"""

from __future__ import annotations

import argparse
import json
import resource
import sys
import time

import numpy as np

from .._io import command, write_or_report, write_output
from .._validate import (
    as_argv,
    as_bool,
    as_int,
    as_ints,
    as_mapping,
    as_nonnegative,
    as_points,
    as_str,
)
from . import ROOT

__all__ = [
    "one_pass",
    "bench_assignment",
    "bench_book",
    "bench_criteria",
    "bench_scaling",
    "evaluation_counts",
    "literal_count",
    "COUNTED",
    "SCALING_SIZES",
    "EXEC_OVER_STACK_MAX",
    "BOOK_DATA",
    "main",
]

#: The regression guard of ``bench book``: the notebooks at most this many times the minimal
#: notebooks of the book's stack (``exec_over_stack``).
EXEC_OVER_STACK_MAX = 3.5

#: Sizes ``N`` at which :func:`bench_scaling` times each algorithm (``L = N / 2``).
SCALING_SIZES = {
    "greedy (geometry)": [20, 50, 100, 200, 400, 800, 1600, 2000],
    "greedy (from W)": [20, 50, 100, 200, 400],
    "literal Algorithm 1": [20, 50, 100, 200, 400],
    "relaxed matching": [20, 50, 100, 200, 400],
    "exact optimum": [8, 12, 16, 20, 30, 40, 50],
}


def _timed(fn, repeat: int = 1):
    best, out = np.inf, None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def one_pass(sensors, targets, u_max, chunk: int = 1 << 20, progress: bool = False) -> float:
    """Evaluate every pair bound ``i < j`` for every target once, in blocks; return the maximum.

    The reference cost for the greedy: one vectorised sweep of all ``N (N - 1) / 2 * L``
    weights with the kernel of :func:`obslib.pair_bounds`, without keeping them. ``progress``
    shows a tqdm bar over the targets on stderr.

    Examples
    --------
    >>> one_pass([[0, 0], [1, 0], [3, 1]], [[1, 1]], 1.0) >= 0  # in seconds
    True
    """
    sensors, targets = as_points(sensors, "sensors"), as_points(targets, "targets")
    u_max, chunk = as_nonnegative(u_max, "u_max"), as_int(chunk, "chunk", 1)
    as_bool(progress, "progress")
    from tqdm import tqdm

    from ..assignment import upper_pair_weight_blocks

    top = -np.inf
    with tqdm(total=len(targets), desc="one pass", file=sys.stderr, leave=False,
              mininterval=0.5, disable=not progress) as bar:
        for a, b, block in upper_pair_weight_blocks(sensors, targets, u_max, chunk=chunk):
            top = max(top, float(block.max()))
            bar.update(b - a)
    return top


def evaluation_counts(sizes: dict, seed: int = 0) -> dict:
    """Pair weights computed by each algorithm against ``N`` (``L = N / 2``), uniform instances.

    A machine-independent measure of work (wall time is what :func:`bench_assignment` reports).
    ``sizes`` maps a name of :data:`COUNTED` to the ``N`` to run it at; returns
    ``{name: (N array, count array)}``, plus ``"one pass"``, ``N (N - 1) / 2 * L`` at every size.
    The literal algorithm's work does not depend on the data (every round evaluates all pairs of
    the remaining sensors for the remaining targets), so it is :func:`literal_count`, exactly.

    Examples
    --------
    >>> sorted(evaluation_counts({"relaxed matching": [6, 8]}))
    ['one pass', 'relaxed matching']
    """
    sizes = as_mapping(sizes, "sizes")
    for v in sizes.values():
        as_ints(v, "sizes", 2)
    seed = as_int(seed, "seed", 0)
    from ..assignment import greedy_pair_assignment, relaxed_pair_assignment

    algos = {
        "greedy (geometry)": lambda S, T: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0),
        "relaxed matching": lambda S, T: relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0),
    }
    unknown = set(sizes) - set(algos) - {"literal Algorithm 1"}
    if unknown:
        raise ValueError(f"unknown algorithm(s) {sorted(unknown)}; known: {list(algos)}")
    out, every_n = {}, set()
    for name, ns in sizes.items():
        if name == "literal Algorithm 1":
            out[name] = (np.array(ns), np.array([literal_count(n, n // 2) for n in ns]))
            every_n.update(int(n) for n in ns)
            continue
        counts = []
        for n in ns:
            rng = np.random.default_rng([seed, n])
            S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (n // 2, 2))
            counts.append(algos[name](S, T).n_evaluations)
            every_n.add(int(n))
        out[name] = (np.array(ns), np.array(counts))
    ns = np.array(sorted(every_n))
    out["one pass"] = (ns, ns * (ns - 1) // 2 * (ns // 2))
    return out


def literal_count(n_sensors: int, n_targets: int) -> int:
    """Pair weights the literal Algorithm 1 evaluates: ``sum_r C(N - 2r, 2) (L - r)`` over rounds.

    Examples
    --------
    >>> literal_count(4, 2)  # 6 pairs x 2 targets, then 1 pair x 1 target
    13
    """
    n_sensors, n_targets = as_int(n_sensors, "n_sensors", 0), as_int(n_targets, "n_targets", 0)
    if n_sensors < 2 * n_targets:
        raise ValueError(f"n_sensors must be at least 2 n_targets, got {n_sensors}, {n_targets}")
    return sum(
        (n_sensors - 2 * r) * (n_sensors - 2 * r - 1) // 2 * (n_targets - r)
        for r in range(n_targets)
    )


#: Algorithms :func:`evaluation_counts` can run.
COUNTED = ("greedy (geometry)", "literal Algorithm 1", "relaxed matching")


def _peak_rss_gb() -> float:
    """Peak resident memory of this process so far, in GiB (``ru_maxrss`` is in KiB on Linux)."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024**2


def _say(line: str) -> None:
    """A readable line of a benchmark, on stderr with the progress bars (stdout holds the JSON)."""
    print(line, file=sys.stderr, flush=True)


def bench_assignment(n_big: int = 2000, l_big: int = 1000, n_small: int = 400, l_small: int = 200,
                     seed: int = 0, sensors: int | None = None, targets: int | None = None) -> dict:
    """Run the assignment benchmark; returns the JSON-ready dict (see the module docstring).

    With ``sensors`` and ``targets``, only the greedy from geometry runs, once, on a uniform
    scene of that size: ``greedy_s`` its wall time, ``peak_rss_gb`` the process's peak memory.
    Progress (a line per phase and the greedy's bar over its rounds) goes to stderr.

    Examples
    --------
    >>> bench_assignment()  # doctest: +SKIP
    """
    from ..assignment import greedy_pair_assignment, greedy_pair_assignment_literal

    n_big, l_big = as_int(n_big, "n_big", 2), as_int(l_big, "l_big", 1)
    n_small, l_small = as_int(n_small, "n_small", 2), as_int(l_small, "l_small", 1)
    if (sensors is None) != (targets is None):
        raise ValueError("give both sensors and targets, or neither")
    if sensors is not None:
        sensors, targets = as_int(sensors, "sensors", 2), as_int(targets, "targets", 1)
    rng = np.random.default_rng(as_int(seed, "seed", 0))
    if sensors is not None:
        S, T = rng.uniform(0, 100, (sensors, 2)), rng.uniform(0, 100, (targets, 2))
        _say(f"greedy from geometry, N={sensors} L={targets}, one run")
        greedy_s, g = _timed(lambda: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0,
                                                            progress=True))
        _say(f"greedy      N={sensors} L={targets}: {greedy_s:8.2f} s  (value {g.value:.2f}, "
             f"{g.n_evaluations:,} pair weights)")
        return {"n_sensors": sensors, "n_targets": targets, "greedy_s": round(greedy_s, 3),
                "n_evaluations": g.n_evaluations, "peak_rss_gb": round(_peak_rss_gb(), 3)}
    S, T = rng.uniform(0, 100, (n_big, 2)), rng.uniform(0, 100, (l_big, 2))
    _say(f"greedy from geometry, N={n_big} L={l_big}, best of 2")
    greedy_s, g = _timed(lambda: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0,
                                                        progress=True), repeat=2)
    _say(f"greedy      N={n_big} L={l_big}: {greedy_s:8.2f} s  (value {g.value:.2f})")
    _say(f"one pass over every pair bound, N={n_big} L={l_big}")
    one_pass_s, _ = _timed(lambda: one_pass(S, T, 1.0, progress=True))
    _say(f"one pass    N={n_big} L={l_big}: {one_pass_s:8.2f} s")

    S2, T2 = rng.uniform(0, 100, (n_small, 2)), rng.uniform(0, 100, (l_small, 2))
    _say(f"greedy from geometry, N={n_small} L={l_small}, best of 3")
    small_s, g2 = _timed(
        lambda: greedy_pair_assignment(sensors=S2, targets=T2, u_max=1.0), repeat=3
    )
    _say(f"greedy      N={n_small} L={l_small}: {small_s:8.3f} s")
    _say(f"literal Algorithm 1, N={n_small} L={l_small} (every remaining triple, every round)")
    literal_s, lit = _timed(
        lambda: greedy_pair_assignment_literal(sensors=S2, targets=T2, u_max=1.0, progress=True)
    )
    if lit.triples != g2.triples:
        raise AssertionError("the greedy and the literal algorithm disagree")
    _say(f"literal     N={n_small} L={l_small}: {literal_s:8.2f} s")
    return {
        "n_sensors": n_big,
        "n_targets": l_big,
        "greedy_s": round(greedy_s, 3),
        "one_pass_s": round(one_pass_s, 3),
        "greedy_over_one_pass": round(greedy_s / one_pass_s, 4),
        "literal_over_greedy": round(literal_s / small_s, 1),
        "peak_rss_gb": round(_peak_rss_gb(), 3),
    }


def bench_scaling(seed: int = 0, repeat: int = 3) -> dict:
    """Best-of-``repeat`` wall time of each algorithm at the sizes of :data:`SCALING_SIZES`.

    Examples
    --------
    >>> bench_scaling()  # doctest: +SKIP
    """
    seed, repeat = as_int(seed, "seed", 0), as_int(repeat, "repeat", 1)
    from ..assignment import (
        greedy_pair_assignment,
        greedy_pair_assignment_literal,
        optimal_pair_assignment,
        relaxed_pair_assignment,
    )
    from ..bounds import pair_bounds

    algos = {
        "greedy (geometry)": lambda S, T: greedy_pair_assignment(sensors=S, targets=T, u_max=1.0),
        "greedy (from W)": lambda S, T: greedy_pair_assignment(pair_bounds(S, T, 1.0)),
        "literal Algorithm 1": lambda S, T: greedy_pair_assignment_literal(
            sensors=S, targets=T, u_max=1.0
        ),
        "relaxed matching": lambda S, T: relaxed_pair_assignment(sensors=S, targets=T, u_max=1.0),
        "exact optimum": lambda S, T: optimal_pair_assignment(pair_bounds(S, T, 1.0)),
    }
    warm = np.random.default_rng(seed).uniform(0, 100, (8, 2))
    out = {}
    with _progress(sum(len(ns) for ns in SCALING_SIZES.values()), "sizes") as bar:
        for name, ns in SCALING_SIZES.items():
            algos[name](warm, warm[:4] + 0.5)  # imports and first-call costs are not timed
            times = []
            for n in ns:
                bar.set_postfix_str(f"{name} N={n}")
                rng = np.random.default_rng([seed, n])
                S, T = rng.uniform(0, 100, (n, 2)), rng.uniform(0, 100, (n // 2, 2))
                reps = 1 if name == "literal Algorithm 1" and n >= 400 else repeat
                times.append(round(_timed(lambda: algos[name](S, T), reps)[0], 6))
                bar.write(f"{name:22s} N={n:5d} {times[-1]:10.4f} s", file=sys.stderr)
                bar.update(1)
            out[name] = {"N": list(ns), "seconds": times}
    return {
        "machine": _machine(),
        "seed": seed,
        "repeat": repeat,
        "times": out,
    }


def _machine() -> str:
    """The processor (its model name where Linux tells it), cores and versions, for the data."""
    import os
    import platform

    cpu = platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            models = [line.split(":", 1)[1].strip() for line in f if line.startswith("model name")]
        if models:
            cpu = f"{models[0]} ({cpu})"
    except OSError:  # not Linux: the architecture only
        pass
    return (
        f"{cpu}, {os.cpu_count()} cores, Python {platform.python_version()}, numpy {np.__version__}"
    )


def bench_criteria(n_timing: int = 1000, seed: int = 0, repeat: int = 3) -> dict:
    """Cost of one decision per criterion: microseconds per pair, batched over ``n_timing``
    estimates of the six sensors' 15 pairs, and per decision for a single estimate.

    The estimates, covariances and controls are random draws around the paper's six sensors
    (Section V-A); each score is timed best of ``repeat``.

    Examples
    --------
    >>> bench_criteria(20, repeat=1)["per_pair_us"].keys()  # doctest: +SKIP
    """
    n_timing, repeat = as_int(n_timing, "n_timing", 1), as_int(repeat, "repeat", 1)
    seed = as_int(seed, "seed", 0)
    import timeit

    from ..studies.criteria import SCORES, criterion_scores
    from ..tracking import PAPER_CIRCLE

    rng = np.random.default_rng(seed)
    S = PAPER_CIRCLE.sensor_array
    X = rng.uniform(-1.0, 5.0, size=(n_timing, 2))
    A = rng.normal(0.0, 0.3, size=(n_timing, 2, 2))
    C = A @ A.transpose(0, 2, 1) + 0.1 * np.eye(2)
    U = rng.uniform(-2.0, 2.0, size=(n_timing, 2))
    Q = R = 0.5 * np.eye(2)
    n_pairs = len(S) * (len(S) - 1) // 2
    per_pair, per_decision = {}, {}
    with _progress(len(SCORES), "criteria") as bar:
        for name in SCORES:
            def score(b=n_timing, name=name):
                return criterion_scores(name, S, X[:b], C[:b], Q, R, 3.0, control=U[:b])
            bar.set_postfix_str(name)
            score(1)  # first-call costs are not timed
            t_batch = min(timeit.repeat(score, number=5, repeat=repeat)) / 5
            t_one = min(timeit.repeat(lambda: score(1), number=200, repeat=repeat)) / 200
            per_pair[name] = round(1e6 * t_batch / (n_timing * n_pairs), 4)
            per_decision[name] = round(1e6 * t_one, 1)
            bar.write(f"{name:10s} {per_pair[name]:7.3f} us per pair (batched)"
                      f"  {per_decision[name]:6.0f} us per decision (one estimate)",
                      file=sys.stderr)
            bar.update(1)
    return {"machine": _machine(), "seed": seed, "n_timing": n_timing, "repeat": repeat,
            "per_pair_us": per_pair, "per_decision_us": per_decision}


def bench_book(profile: str = "paper", jobs: int | None = None) -> dict:
    """Run the book benchmark; returns the JSON-ready dict (see the module docstring).

    Every notebook runs alone, right after one trivial and one minimal notebook, so that the
    floors and the serial run see the same machine load (on a shared machine the speed drifts
    over a minute by tens of percent): ``floor_s`` sums the trivial runs, ``stack_floor_s`` the
    minimal ones and ``exec_s`` the notebooks. Then all of them run ``jobs`` at a time (default:
    the cores available), longest first by the times just measured, as ``make book`` runs them:
    ``parallel_s`` is that wall time. ``profile`` names the parameters
    (:data:`obslib.profiles.PROFILES`); ``"paper"`` is the notebooks' defaults.

    Examples
    --------
    >>> bench_book("quick")  # doctest: +SKIP
    """
    import tempfile
    from pathlib import Path

    from ..profiles import PROFILES, profile_names
    from .run import Run, default_jobs, execute, execute_all, notebooks, precompile

    if as_str(profile, "profile") not in PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    jobs = default_jobs() if jobs is None else as_int(jobs, "jobs", 1)
    nbs = notebooks()
    precompile()  # as make book does
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        trivial = _scratch_notebook(tmp / "trivial.ipynb", "print(x + 1)")
        stack = _scratch_notebook(tmp / "stack.ipynb", _STACK_NOTEBOOK)
        runs = [Run(nb, tmp / "parallel" / nb.name, dict(PROFILES[profile].get(nb.stem, {})))
                for nb in nbs]
        floor_s = stack_s = 0.0
        alone = {}
        with _progress(len(nbs), "notebooks alone") as bar:
            for k, r in enumerate(runs):
                bar.set_postfix_str(r.notebook.stem)
                floor_s += execute(trivial, tmp / f"trivial_{k}.ipynb")
                stack_s += execute(stack, tmp / f"stack_{k}.ipynb")
                alone[r.notebook.name] = execute(r.notebook, tmp / r.notebook.name, r.parameters)
                bar.write(f"{r.notebook.name:40s} {alone[r.notebook.name]:7.1f} s",
                          file=sys.stderr)
                bar.update(1)
        exec_s = sum(alone.values())
        _say(f"all {len(runs)} notebooks, {jobs} at a time")
        t0 = time.perf_counter()
        execute_all(runs, jobs, progress=None, expected=alone)
        parallel_s = time.perf_counter() - t0
    n = len(nbs)
    _say(f"{n} notebooks {exec_s:.1f} s, {n} trivial notebooks {floor_s:.1f} s, "
         f"{n} minimal notebooks of the book's stack {stack_s:.1f} s")
    _say(f"{n} notebooks {jobs} at a time, longest first: {parallel_s:.1f} s")
    _say(f"{'exec_over_floor':18s} {exec_s / floor_s:6.2f}")
    _say(f"{'stack_over_floor':18s} {stack_s / floor_s:6.2f}")
    for key, value, target in (("exec_over_stack", exec_s / stack_s, EXEC_OVER_STACK_MAX),
                               ("parallel_speedup", exec_s / parallel_s, -1.6)):
        met = value <= target if target > 0 else value >= -target
        rule = f"<= {target}" if target > 0 else f">= {-target} on 2 cores"
        _say(f"{key:18s} {value:6.2f}  target {rule}: {'met' if met else 'MISSED'}")
    return {
        "notebooks": n,
        "profile": profile,
        "jobs": jobs,
        "exec_s": round(exec_s, 2),
        "floor_s": round(floor_s, 2),
        "exec_over_floor": round(exec_s / floor_s, 3),
        "stack_floor_s": round(stack_s, 2),
        "stack_over_floor": round(stack_s / floor_s, 3),
        "exec_over_stack": round(exec_s / stack_s, 3),
        "parallel_s": round(parallel_s, 2),
        "parallel_speedup": round(exec_s / parallel_s, 3),
    }


def _progress(total: int, desc: str):
    """A progress bar on standard error (shown on a terminal only)."""
    from tqdm import tqdm

    return tqdm(total=total, desc=desc, file=sys.stderr, disable=None, dynamic_ncols=True)


def _scratch_notebook(path, code: str):
    """Write a notebook of a ``parameters`` cell (``x = 1``) and ``code`` to ``path``; return it."""
    import nbformat
    from nbformat.v4 import new_code_cell, new_notebook

    from .run import KERNEL

    nb = new_notebook(cells=[new_code_cell("x = 1", metadata={"tags": ["parameters"]}),
                             new_code_cell(code)])
    for k, c in enumerate(nb.cells):
        c.id = f"c{k}"
    nb.metadata["kernelspec"] = {"name": KERNEL, "display_name": "Python 3", "language": "python"}
    write_output(path, nbformat.writes(nb) + "\n")
    return path


#: The smallest notebook of this book: the imports every notebook starts with, and one figure.
_STACK_NOTEBOOK = """\
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd
from myst_nb import glue

import obsbook
import obslib

obsbook.setup()
fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(np.arange(x + 9), label="x")
ax.set_xlabel("step")
ax.set_ylabel("value (m)")
ax.legend()
plt.show()
"""


#: The book's committed data, which the notebooks read: refused by ``--write`` without
#: ``--update-book``.
BOOK_DATA = ROOT / "book" / "data"


def parse_args(argv=None) -> argparse.Namespace:
    """Parse and check the command line; a bad profile or path is an argparse error (exit 2).

    Examples
    --------
    >>> parse_args(["book", "--profile", "quick"]).profile
    'quick'
    >>> data = "book/data/criteria_times.json"
    >>> parse_args(["criteria", "--write", data])  # doctest: +SKIP
    usage: ...
    python -m obslib.bench: error: --write book/data/criteria_times.json: ...
    """
    from .._io import OutputPathError, as_output_path
    from ..profiles import profile_names

    ap = argparse.ArgumentParser(prog="python -m obslib.bench", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument(
        "which", choices=["assignment", "book", "criteria", "scaling", "tracking"],
        help="benchmark to run"
    )
    ap.add_argument("--write", help="scaling, criteria: also store the JSON in this file")
    ap.add_argument("--update-book", action="store_true",
                    help="allow --write to replace the book's data (book/data/); then run "
                    "make book")
    ap.add_argument(
        "--profile",
        default="paper",
        choices=profile_names(),
        help="book: parameter profile of the notebooks (default: paper, their defaults)",
    )
    ap.add_argument("--jobs", type=int, default=None,
                    help="book: notebooks side by side in the parallel runs (default: the cores)")
    ap.add_argument("--sensors", type=int, help="assignment: only the greedy from geometry, with "
                    "this many sensors (and --targets targets); tracking: the sensors "
                    "(default 1000)")
    ap.add_argument("--targets", type=int, help="assignment, tracking: the number of targets "
                    "(tracking: default 100)")
    args = ap.parse_args(as_argv(argv))
    _check_assignment_size(ap, args)
    if args.write is not None:
        if args.which not in ("scaling", "criteria"):
            ap.error("--write applies to the scaling and criteria benchmarks only")
        try:
            args.write = as_output_path(args.write)
        except OutputPathError as exc:
            ap.error(f"--write {exc}")
        book = _in_book_data(args.write)
        if book and not args.update_book:
            ap.error(f"--write {args.write}: the book's data, which its notebooks read; replacing "
                     "it changes their outputs (nbval fails until make book re-executes them). "
                     "Add --update-book to replace it, then run make book")
        if args.update_book and not book:
            ap.error(f"--update-book: --write {args.write} is not the book's data ({BOOK_DATA})")
    elif args.update_book:
        ap.error("--update-book goes with --write book/data/<file>.json")
    if args.profile != "paper" and args.which != "book":
        ap.error("--profile applies to the book benchmark only")
    if args.jobs is not None and (args.which != "book" or args.jobs < 1):
        ap.error("--jobs applies to the book benchmark only and must be at least 1")
    return args


def _in_book_data(path) -> bool:
    """Whether ``path`` (links followed) lies in the book's data folder :data:`BOOK_DATA`."""
    import os
    from pathlib import Path

    real, data = Path(os.path.realpath(path)), Path(os.path.realpath(BOOK_DATA))
    return real == data or data in real.parents


def _check_assignment_size(ap, args) -> None:
    """``--sensors N --targets L``: both or neither, for the assignment benchmark; for the
    tracking benchmark either (defaults 1000 and 100); ``N >= 2L >= 2``."""
    given = (args.sensors is not None, args.targets is not None)
    if any(given) and args.which not in ("assignment", "tracking"):
        ap.error("--sensors and --targets apply to the assignment and tracking benchmarks only")
    if args.which == "tracking":
        args.sensors = 1000 if args.sensors is None else args.sensors
        args.targets = 100 if args.targets is None else args.targets
    elif not any(given):
        return
    elif not all(given):
        ap.error("give both --sensors and --targets")
    if args.targets < 1 or args.sensors < 2 * args.targets:
        ap.error(f"--sensors {args.sensors} --targets {args.targets}: need at least one target "
                 "and at least two sensors per target (N >= 2L)")


@command("python -m obslib.bench")
def main(argv=None) -> int:
    """Command line entry point: run one benchmark and print its JSON; returns the exit status.

    A ``--write`` that fails at the end (a full device, say) is a one-line error, exit status 1.

    Examples
    --------
    >>> main(["assignment"])  # doctest: +SKIP
    """
    args = parse_args(argv)
    if args.which == "assignment":
        result = bench_assignment(sensors=args.sensors, targets=args.targets)
    elif args.which == "book":
        result = bench_book(args.profile, args.jobs)
    elif args.which == "tracking":
        from .bench_tracking import bench_tracking

        result = bench_tracking(args.sensors, args.targets)
    else:
        result = bench_scaling() if args.which == "scaling" else bench_criteria()
    print(json.dumps(result), flush=True)
    if args.write and not write_or_report("python -m obslib.bench", args.write,
                                          json.dumps(result, indent=1) + "\n"):
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
