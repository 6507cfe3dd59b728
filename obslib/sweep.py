"""Run independent trials serially, with joblib, or on a Dask cluster, with identical results.

Every trial function of the studies (``fig8_trial``, ``fig9_trial``) seeds its own generator from
its arguments (``default_rng([seed, size, trial])``), never from a worker or a shared stream, so
the results are the same whatever the backend, worker count or completion order. With
``progress=True`` a tqdm bar of the finished tasks goes to standard error.
"""

from __future__ import annotations

import sys
from collections.abc import Callable

from ._validate import ArgumentTypeError, as_bool, as_callable, as_int, as_sequence, as_str

__all__ = ["BACKENDS", "run_sweep"]

BACKENDS = ("serial", "joblib", "dask")


def run_sweep(fn: Callable, tasks: list[dict], backend: str = "serial", n_jobs: int | None = None,
              scheduler=None, progress: bool = False) -> list:
    """``[fn(**t) for t in tasks]``, computed by ``backend``; results in task order.

    Parameters
    ----------
    fn : callable
        A module-level function (picklable), called with each task's keyword arguments.
    tasks : list of dict
    backend : {"serial", "joblib", "dask"}
        ``joblib`` runs ``n_jobs`` local processes (default: all cores); ``dask`` submits to the
        scheduler at ``scheduler`` (an address such as ``"tcp://127.0.0.1:8786"``, or a
        ``distributed.Client``).
    progress : bool
        Show a tqdm bar of the finished tasks on standard error.

    Examples
    --------
    >>> run_sweep(pow, [dict(base=2, exp=k) for k in range(4)])
    [1, 2, 4, 8]
    """
    as_callable(fn, "fn")
    if as_str(backend, "backend") not in BACKENDS:
        raise ValueError(f"backend must be one of {BACKENDS}, got {backend!r}")
    as_bool(progress, "progress")
    if n_jobs is not None:
        n_jobs = as_int(n_jobs, "n_jobs")
    tasks = as_sequence(tasks, "tasks")
    if not all(isinstance(t, dict) for t in tasks):
        raise ArgumentTypeError("tasks must be a list of keyword dicts")
    if backend == "dask" and scheduler is None:
        raise ValueError("backend 'dask' needs scheduler= (an address or a distributed.Client)")
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
            for r in Parallel(n_jobs=n_jobs or -1, return_as="generator")(
                    delayed(fn)(**t) for t in tasks):
                out.append(r)  # in task order, as each arrives
                bar.update(1)
            return out
        return _dask(fn, tasks, scheduler, bar)


def _dask(fn, tasks, scheduler, bar) -> list:
    from distributed import Client, as_completed

    client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
    try:
        futures = [client.submit(fn, pure=False, **t) for t in tasks]
        for _ in as_completed(futures):
            bar.update(1)
        return client.gather(futures)
    finally:
        if client is not scheduler:
            client.close()
