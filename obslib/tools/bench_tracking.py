"""The closed-loop benchmark: ``python -m obslib.bench tracking --sensors N --targets L``.

Many targets tracked with the unique-pair greedy (:func:`obslib.tracking.simulate_targets` on a
:func:`obslib.tracking.network_scene` of ``N`` sensors and ``L`` targets): each step assigns
the sensors by Algorithm 1 from the filters' estimates and updates every target's filter. The
benchmark reports ``step_ms``, the median wall time of one step of the loop
(:func:`obslib.tracking.step_times`: the filters' updates and the next assignment), and
``greedy_ms``, the median time of the greedy alone (:func:`obslib.greedy_pair_assignment` from
geometry) on the same estimates of the same run, each step's once; ``step_over_greedy`` is their
ratio (target at most 1.5 at ``N = 1000``, ``L = 100``: the loop adds little to the
assignment) and ``steps_per_s`` what the step time allows. Progress goes to standard error.
"""

from __future__ import annotations

import sys
import time

import numpy as np

from .._validate import as_int

__all__ = ["STEP_OVER_GREEDY_TARGET", "bench_tracking"]

#: The most ``step_over_greedy`` may be.
STEP_OVER_GREEDY_TARGET = 1.5


def bench_tracking(sensors: int = 1000, targets: int = 100, steps: int = 25, repeat: int = 2,
                   seed: int = 0) -> dict:
    """Time the closed loop of ``targets`` targets among ``sensors`` sensors over ``steps``
    steps (the first ``steps - 1`` timed), and the greedy alone on the same estimates; the two
    alternate ``repeat`` times, so that a change of the machine's load reaches both.

    Returns
    -------
    dict
        ``sensors``, ``targets``, ``steps`` (timed), ``step_ms``, ``greedy_ms``,
        ``step_over_greedy`` and ``steps_per_s``.

    Examples
    --------
    >>> import contextlib, io
    >>> with contextlib.redirect_stdout(io.StringIO()):  # the readable lines
    ...     r = bench_tracking(20, 5, steps=4, repeat=1)
    >>> sorted(r)  # doctest: +NORMALIZE_WHITESPACE
    ['greedy_ms', 'sensors', 'step_ms', 'step_over_greedy', 'steps', 'steps_per_s',
     'targets']
    """
    from .. import assignment, tracking

    n = as_int(sensors, "sensors", 2)
    L = as_int(targets, "targets", 1)
    if n < 2 * L:
        raise ValueError(f"sensors = {n} < 2 targets = {2 * L}: the unique-pair greedy needs "
                         "two sensors per target")
    steps = as_int(steps, "steps", 2)
    repeat = as_int(repeat, "repeat", 1)
    seed = as_int(seed, "seed", 0)
    print(f"closed loop: N = {n} sensors, L = {L} targets, {steps} steps, {repeat} times",
          file=sys.stderr, flush=True)
    setup = tracking.network_scene(n, L, steps=steps, seed=seed)
    tracking.step_times(setup.first(2), "unique-pairs", seed)  # warm up (imports, caches)
    S = setup.sensor_array
    times, greedy = [], []
    for _ in range(repeat):
        t, run = tracking.step_times(setup, "unique-pairs", seed)
        times += t.tolist()
        for k in range(1, steps):  # the estimates step k's assignment was made from
            t0 = time.perf_counter()
            assignment.greedy_pair_assignment(sensors=S, targets=run.estimate[k],
                                              u_max=setup.u_max)
            greedy.append(time.perf_counter() - t0)
    times = np.array(times)
    step_s, greedy_s = float(np.median(times)), float(np.median(greedy))
    ratio = step_s / greedy_s
    met = "met" if ratio <= STEP_OVER_GREEDY_TARGET else "MISSED"
    print(f"step   {1e3 * step_s:8.2f} ms  (median of {times.size}; assignment and updates)",
          flush=True)
    print(f"greedy {1e3 * greedy_s:8.2f} ms  (median of {len(greedy)}; the assignment alone)",
          flush=True)
    print(f"step_over_greedy {ratio:6.3f}  target <= {STEP_OVER_GREEDY_TARGET}: {met}; "
          f"{1 / step_s:.1f} steps per second", flush=True)
    return {
        "sensors": n,
        "targets": L,
        "steps": int(times.size),
        "step_ms": round(1e3 * step_s, 3),
        "greedy_ms": round(1e3 * greedy_s, 3),
        "step_over_greedy": round(ratio, 3),
        "steps_per_s": round(1 / step_s, 2),
    }
