"""Memory said up front: the limits of the arrays the library builds, and the estimates that
refuse, before anything large is allocated, a call that would exceed them.

``pair_bounds`` and the literal greedy build the weight tensor ``(N, N, L)`` (at most
:data:`MAX_WEIGHT_BYTES`); the geometry-based solvers never build it but hold every target's
normalised rows and candidate pairs (at most :data:`MAX_GEOMETRY_BYTES`, estimated by
:func:`geometry_bytes`). Each refusal says the size and what to do instead.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MAX_WEIGHT_BYTES", "check_weight_memory", "check_upper_weights_memory",
           "MAX_GEOMETRY_BYTES", "GEOMETRY_BYTES", "geometry_bytes", "check_geometry_memory"]


#: Largest weight tensor ``(N, N, L)`` of float64 the library materialises: 1 GiB. Computing it
#: takes about five arrays of that size at the peak, so about 5 GiB of memory.
MAX_WEIGHT_BYTES = 1 << 30


def check_weight_memory(n: int, n_targets: int) -> None:
    """Refuse, before allocating, a weight tensor ``(N, N, L)`` over :data:`MAX_WEIGHT_BYTES`."""
    need = 8 * n * n * n_targets
    if need > MAX_WEIGHT_BYTES:
        raise ValueError(
            f"the (N, N, L) = ({n}, {n}, {n_targets}) weight tensor needs {need / 2**30:.1f} GiB "
            f"(about {5 * need / 2**30:.0f} GiB to compute), over the limit of "
            f"{MAX_WEIGHT_BYTES / 2**30:.0f} GiB; use the geometry-based path, e.g. "
            "greedy_pair_assignment(sensors=..., targets=..., u_max=...) or "
            "relaxed_pair_assignment(sensors=..., targets=..., u_max=...), which never builds it"
        )


def check_upper_weights_memory(n: int, n_targets: int) -> None:
    """Refuse, before allocating, the weights of the pairs ``i < j`` for every target, ``(L, P)``,
    over :data:`MAX_WEIGHT_BYTES` (half the weight tensor)."""
    need = 8 * n_targets * (n * (n - 1) // 2)
    if need > MAX_WEIGHT_BYTES:
        raise ValueError(
            f"the (L, P) = ({n_targets}, {n * (n - 1) // 2}) array of pair weights needs "
            f"{need / 2**30:.1f} GiB, over the limit of {MAX_WEIGHT_BYTES / 2**30:.0f} GiB; "
            "upper_pair_weight_blocks(sensors, targets, u_max) yields it a block at a time")


#: Largest memory the geometry-based pair solvers may take, estimated before they allocate
#: anything of size ``N x L``: 4 GiB.
MAX_GEOMETRY_BYTES = 4 << 30

#: Bytes of a geometry-based solver's memory: per sensor and target (the normalised rows
#: ``x, y``), per sensor (one target's search: angles, order, bins, candidate buffers), per
#: target squared (each target's candidate pairs, at least ``L`` of them for the relaxed matching
#: and twice as many edges for both of its variants, or the greedy's lists) and a fixed part.
#: Measured peaks (tracemalloc) at ``N`` from 50 to 100,000 and ``L`` from 2 to 2,500 lie
#: between 0.4 and 0.95 of these estimates.
GEOMETRY_BYTES = {"row": 16, "sensor": 1024, "fixed": 1 << 20, "greedy": 16, "relaxed": 160,
                  "relaxed, both": 288}


def geometry_bytes(n: int, n_targets: int, what: str) -> int:
    """Estimated peak memory of a geometry-based solver ``what`` (a key of
    :data:`GEOMETRY_BYTES`: ``"greedy"``, ``"relaxed"``, ``"relaxed, both"``) at ``N, L``.

    Examples
    --------
    >>> round(geometry_bytes(10_000, 5_000, "greedy") / 2**30, 2)  # GiB
    1.13
    """
    b = GEOMETRY_BYTES
    return b["row"] * n * n_targets + b["sensor"] * n + b[what] * n_targets**2 + b["fixed"]


def check_geometry_memory(n: int, n_targets: int, what: str, solver: str) -> None:
    """Refuse, before allocating, a geometry-based solve whose memory (:func:`geometry_bytes`)
    exceeds :data:`MAX_GEOMETRY_BYTES`, saying how much it needs and what fits instead.

    Examples
    --------
    >>> check_geometry_memory(1_000_000, 1_000, "greedy", "greedy_pair_assignment")
    Traceback (most recent call last):
    ...
    ValueError: greedy_pair_assignment from geometry needs about 15.9 GiB for ...
    """
    need = geometry_bytes(n, n_targets, what)
    limit = MAX_GEOMETRY_BYTES
    if need <= limit:
        return
    b = GEOMETRY_BYTES
    n_fit = (limit - b["fixed"] - b[what] * n_targets**2) // (b["row"] * n_targets + b["sensor"])
    # the largest L with b[what] L^2 + b["row"] N L + b["sensor"] N + b["fixed"] <= limit
    c, lin, const = b[what], b["row"] * n, b["sensor"] * n + b["fixed"] - limit
    l_fit = int((-lin + np.sqrt(float(lin) ** 2 - 4.0 * c * const)) / (2 * c)) if const < 0 else 0
    fits = []
    if n_fit >= 2 * n_targets:
        fits.append(f"N = {n_fit:,} sensors with these {n_targets:,} targets")
    if l_fit >= 1:
        fits.append(f"L = {l_fit:,} targets with these {n:,} sensors")
    fit = (f"; at most {' or '.join(fits)} fit" if fits else
           "; no scene of this many sensors or targets fits")
    raise ValueError(
        f"{solver} from geometry needs about {need / 2**30:.1f} GiB for N = {n:,} sensors and "
        f"L = {n_targets:,} targets ({b['row']} bytes per sensor and target for the normalised "
        f"rows, {b[what]} per target squared for the candidate pairs), over the limit of "
        f"{limit / 2**30:.0f} GiB (obslib._memory.MAX_GEOMETRY_BYTES){fit}; beyond that, split "
        "the scene into regions solved apart (an approximation of the whole problem)"
    )
