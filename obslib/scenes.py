"""Seeded random scenes (sensors, target, speed bound) for audits and tests.

A scene is drawn at a log-uniform length scale between ``scale[0]`` and ``scale[1]`` and is
one of four kinds, so that audits cover the near-degenerate geometry where a closed form
can lose accuracy:

``"generic"``
    sensors and target uniform in a square of side ``scale``;
``"collinear"``
    all sensors on one line through the target (``O(o)`` has rank 1);
``"near-parallel"``
    sensors on a line through the target, then moved off it by ``1e-9 * scale``;
``"spread"``
    sensors whose distances to the target differ by up to seven orders of magnitude.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Scene", "random_scene", "random_scenes", "SCENE_KINDS"]

SCENE_KINDS = ("generic", "collinear", "near-parallel", "spread")


@dataclass(frozen=True)
class Scene:
    """One random scene: ``sensors`` (N, 2), ``target`` (2,), ``u_max`` and its ``kind``."""

    sensors: np.ndarray
    target: np.ndarray
    u_max: float
    kind: str


def random_scene(
    rng: np.random.Generator, n_sensors: int, kind: str = "generic", scale: float = 1.0
) -> Scene:
    """Draw one scene of the given ``kind`` at length ``scale`` from ``rng``."""
    if kind not in SCENE_KINDS:
        raise ValueError(f"kind must be one of {SCENE_KINDS}, got {kind!r}")
    if n_sensors < 1:
        raise ValueError(f"n_sensors must be at least 1, got {n_sensors}")
    target = rng.uniform(-scale, scale, size=2)
    if kind == "generic":
        offsets = rng.uniform(-scale, scale, size=(n_sensors, 2))
    else:
        phi = rng.uniform(0.0, np.pi)
        direction = np.array([np.cos(phi), np.sin(phi)])
        if kind == "spread":
            mags = scale * 10.0 ** rng.uniform(-4.0, 3.0, size=n_sensors)
            angles = rng.uniform(0.0, 2 * np.pi, size=n_sensors)
            offsets = mags[:, None] * np.column_stack([np.cos(angles), np.sin(angles)])
        else:
            t = rng.uniform(0.05, 1.0, size=n_sensors) * rng.choice([-1.0, 1.0], size=n_sensors)
            offsets = scale * t[:, None] * direction[None, :]
            if kind == "near-parallel":
                normal = np.array([-direction[1], direction[0]])
                offsets = offsets + 1e-9 * scale * rng.standard_normal(n_sensors)[:, None] * normal
    sensors = target[None, :] + offsets
    u_max = float(scale * 10.0 ** rng.uniform(-2.0, 1.0))
    return Scene(sensors=sensors, target=target, u_max=u_max, kind=kind)


def random_scenes(
    n_scenes: int,
    seed: int,
    n_sensors: tuple[int, int] = (2, 6),
    scale: tuple[float, float] = (1e-3, 1e4),
    kinds: tuple[str, ...] = SCENE_KINDS,
) -> list[Scene]:
    """``n_scenes`` scenes from ``numpy.random.default_rng(seed)``, cycling through ``kinds``.

    The number of sensors is uniform in ``n_sensors`` (inclusive) and the length scale is
    log-uniform in ``scale``.
    """
    rng = np.random.default_rng(seed)
    lo, hi = np.log10(scale[0]), np.log10(scale[1])
    out = []
    for k in range(n_scenes):
        n = int(rng.integers(n_sensors[0], n_sensors[1] + 1))
        s = float(10.0 ** rng.uniform(lo, hi))
        out.append(random_scene(rng, n, kinds[k % len(kinds)], s))
    return out
