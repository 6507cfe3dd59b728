"""Run independent trials serially, with joblib, or on a Dask cluster, with identical results.

Every trial function of the studies (``fig8_trial``, ``fig9_trial``) seeds its own generator from
its arguments (``default_rng([seed, size, trial])``), never from a worker or a shared stream, so
the results are the same whatever the backend, worker count or completion order. With
``progress=True`` a tqdm bar of the finished tasks goes to standard error.

What is handed on to joblib and Dask is checked here first, as every argument of the library is
(a ``ValueError`` naming it): ``n_jobs`` only with ``backend="joblib"`` and at least 1 (joblib's
own 0 and negative counts are refused, ``None`` is every core), ``scheduler`` only with
``backend="dask"`` and an address (``"tcp://host:8786"``, ``"host:8786"``) or a
``distributed.Client``, the tasks keyword dictionaries. A scheduler that cannot be reached is a
``ValueError`` naming ``scheduler``.
"""

from __future__ import annotations

import re
import sys
from collections.abc import Callable

from ._validate import ArgumentTypeError, as_bool, as_callable, as_int, as_sequence, as_str

__all__ = ["BACKENDS", "run_sweep"]

BACKENDS = ("serial", "joblib", "dask")

#: A Dask scheduler address: a protocol and a location, or ``host:port``.
_ADDRESS = re.compile(r"^((tcp|tls|inproc|ws|wss|ucx)://\S+|[\w.\-\[\]:]+:\d+)$")


def run_sweep(fn: Callable, tasks: list[dict], backend: str = "serial", n_jobs: int | None = None,
              scheduler=None, progress: bool = False) -> list:
    """``[fn(**t) for t in tasks]``, computed by ``backend``; results in task order.

    Parameters
    ----------
    fn : callable
        A module-level function (picklable), called with each task's keyword arguments.
    tasks : list of dict
        Keyword arguments, named by strings.
    backend : {"serial", "joblib", "dask"}
        ``joblib`` runs ``n_jobs`` local processes (default ``None``: all cores); ``dask``
        submits to the scheduler at ``scheduler`` (an address such as ``"tcp://127.0.0.1:8786"``,
        or a ``distributed.Client``).
    progress : bool
        Show a tqdm bar of the finished tasks on standard error.

    Examples
    --------
    >>> run_sweep(pow, [dict(base=2, exp=k) for k in range(4)])
    [1, 2, 4, 8]
    >>> run_sweep(pow, [], "joblib", n_jobs=0)
    Traceback (most recent call last):
    ...
    ValueError: n_jobs must be at least 1 (None: every core), got 0
    """
    fn, tasks, backend, n_jobs, scheduler, progress = _run_sweep_iv(fn, tasks, backend, n_jobs,
                                                                    scheduler, progress)
    from tqdm import tqdm

    with tqdm(total=len(tasks), desc=getattr(fn, "__name__", "tasks"), unit="task",
              file=sys.stderr, disable=not progress) as bar:
        if backend == "serial":
            out = []
            for t in tasks:
                out.append(fn(**t))
                bar.update(1)
            return out
        if backend == "joblib":
            from joblib import Parallel, delayed

            out = []
            for r in Parallel(n_jobs=-1 if n_jobs is None else n_jobs, return_as="generator")(
                    delayed(fn)(**t) for t in tasks):
                out.append(r)  # in task order, as each arrives
                bar.update(1)
            return out
        return _dask(fn, tasks, scheduler, bar)


def _run_sweep_iv(fn, tasks, backend, n_jobs, scheduler, progress) -> tuple:
    """:func:`run_sweep`'s arguments, each checked before anything is handed to joblib or
    Dask (see the module docstring)."""
    as_callable(fn, "fn")
    if as_str(backend, "backend") not in BACKENDS:
        raise ValueError(f"backend must be one of {BACKENDS}, got {backend!r}")
    progress = as_bool(progress, "progress")
    if n_jobs is not None:
        if backend != "joblib":
            raise ValueError(f"n_jobs applies to backend 'joblib' only, not {backend!r}")
        n_jobs = as_int(n_jobs, "n_jobs")
        if n_jobs < 1:
            raise ValueError(f"n_jobs must be at least 1 (None: every core), got {n_jobs}")
    tasks = as_sequence(tasks, "tasks")
    if not all(isinstance(t, dict) and all(isinstance(k, str) for k in t) for t in tasks):
        raise ArgumentTypeError("tasks must be a list of keyword dicts (named by strings)")
    if backend == "dask":
        scheduler = _scheduler_iv(scheduler)
    elif scheduler is not None:
        raise ValueError(f"scheduler applies to backend 'dask' only, not {backend!r}")
    return fn, tasks, backend, n_jobs, scheduler, progress


def _scheduler_iv(scheduler):
    """A ``distributed.Client``, or a scheduler address (see :data:`_ADDRESS`)."""
    if scheduler is None:
        raise ValueError("backend 'dask' needs scheduler= (an address or a distributed.Client)")
    if isinstance(scheduler, str):
        if not _ADDRESS.match(scheduler):
            raise ValueError(f"scheduler must be an address such as 'tcp://host:8786' or "
                             f"'host:8786', got {scheduler!r}")
        return scheduler
    from distributed import Client

    if not isinstance(scheduler, Client):
        raise ArgumentTypeError(f"scheduler must be an address or a distributed.Client, got "
                                f"{scheduler!r}")
    return scheduler


def _dask(fn, tasks, scheduler, bar) -> list:
    from distributed import Client, as_completed

    try:
        client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
    except OSError as exc:  # refused, unknown host, or no answer within Dask's connect timeout
        raise ValueError(f"scheduler {scheduler!r}: no Dask scheduler answers there ({exc})"
                         ) from None
    try:
        futures = [client.submit(fn, pure=False, **t) for t in tasks]
        for _ in as_completed(futures):
            bar.update(1)
        return client.gather(futures)
    finally:
        if client is not scheduler:
            client.close()
