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

:func:`random_scenes` draws scene by scene (a list of :class:`Scene`);
:func:`random_scene_batch` draws the same kinds array by array into one padded
:class:`SceneBatch`, for the vectorised audits of :mod:`obslib.studies.model_and_bound`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ._validate import (
    ArgumentTypeError,
    as_float_array,
    as_instance,
    as_int,
    as_int_range,
    as_names,
    as_positive,
    as_str,
    check_scene_batch,
)

__all__ = [
    "Scene",
    "random_scene",
    "random_scenes",
    "SCENE_KINDS",
    "SceneBatch",
    "random_scene_batch",
]

SCENE_KINDS = ("generic", "collinear", "near-parallel", "spread")


@dataclass(frozen=True)
class Scene:
    """One random scene: ``sensors`` (N, 2), ``target`` (2,), ``u_max`` and its ``kind``.

    Examples
    --------
    >>> Scene(sensors=np.zeros((1, 2)), target=np.ones(2), u_max=1.0,
    ...       kind="generic").kind
    'generic'
    """

    sensors: np.ndarray
    target: np.ndarray
    u_max: float
    kind: str


def random_scene(
    rng: np.random.Generator, n_sensors: int, kind: str = "generic", scale: float = 1.0
) -> Scene:
    """Draw one scene of the given ``kind`` at length ``scale`` from ``rng``.

    Examples
    --------
    >>> s = random_scene(np.random.default_rng(0), 3)
    >>> s.sensors.shape, s.kind
    ((3, 2), 'generic')
    """
    rng, n_sensors, kind, scale = _random_scene_iv(rng, n_sensors, kind, scale)
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


def _random_scene_iv(rng, n_sensors, kind, scale) -> tuple:
    """A NumPy generator, at least one sensor, a kind of :data:`SCENE_KINDS`, a positive
    scale."""
    rng = as_instance(rng, np.random.Generator, "rng")
    if as_str(kind, "kind") not in SCENE_KINDS:
        raise ValueError(f"kind must be one of {SCENE_KINDS}, got {kind!r}")
    return rng, as_int(n_sensors, "n_sensors", 1), kind, as_positive(scale, "scale")


def _draw_iv(n_scenes, seed, n_sensors, scale, kinds, min_scenes):
    """Validated arguments of :func:`random_scenes` and :func:`random_scene_batch`."""
    n_scenes = as_int(n_scenes, "n_scenes", min_scenes)
    seed = as_int(seed, "seed", 0)
    if isinstance(kinds, str):
        raise ArgumentTypeError(
            f"kinds must be a non-empty sequence of names from {SCENE_KINDS}, got {kinds!r}"
        )
    kinds = as_names(kinds, "kinds", SCENE_KINDS)
    if not kinds:
        raise ValueError(f"kinds must be a non-empty sequence of names from {SCENE_KINDS}")
    lo_n, hi_n = as_int_range(n_sensors, "n_sensors", 1)
    sc = as_float_array(scale, "scale")
    if sc.shape != (2,) or not np.isfinite(sc).all() or (sc <= 0).any() or sc[1] < sc[0]:
        raise ValueError(f"scale must be (lo, hi) with 0 < lo <= hi finite, got {scale!r}")
    return n_scenes, seed, (lo_n, hi_n), (float(sc[0]), float(sc[1])), kinds


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

    Examples
    --------
    >>> [s.kind for s in random_scenes(4, seed=0)]
    ['generic', 'collinear', 'near-parallel', 'spread']
    """
    n_scenes, seed, n_sensors, scale, kinds = _draw_iv(
        n_scenes, seed, n_sensors, scale, kinds, 0
    )
    rng = np.random.default_rng(seed)
    lo, hi = np.log10(scale[0]), np.log10(scale[1])
    out = []
    for k in range(n_scenes):
        n = int(rng.integers(n_sensors[0], n_sensors[1] + 1))
        s = float(10.0 ** rng.uniform(lo, hi))
        out.append(random_scene(rng, n, kinds[k % len(kinds)], s))
    return out


@dataclass(frozen=True)
class SceneBatch:
    """Many random scenes as stacked arrays, for vectorised audits.

    Scene ``k`` has ``counts[k]`` sensors, stored in the first rows of ``sensors[k]``; the
    remaining rows are padding (NaN in ``sensors``, zero in :attr:`rows`). A zero row adds
    nothing to ``O(o)^T O(o)``, to its Cauchy-Binet determinant or to its singular values, so
    the padded :attr:`rows` can go straight into the batched functions
    (:func:`obslib.observability.inverse_condition_numbers`, :func:`obslib.bounds.lower_bounds`).

    Examples
    --------
    >>> b = random_scene_batch(4, seed=0, n_sensors=(2, 3))
    >>> len(b), b.rows.shape
    (4, (4, 3, 2))
    """

    sensors: np.ndarray  #: (S, M, 2), NaN beyond ``counts``
    targets: np.ndarray  #: (S, 2)
    u_max: np.ndarray  #: (S,)
    kinds: tuple  #: kind of each scene
    counts: np.ndarray  #: (S,) number of sensors of each scene

    def __len__(self) -> int:
        return self.targets.shape[0]

    @property
    def rows(self) -> np.ndarray:
        """Rows ``o - p_i`` of every scene, shape ``(S, M, 2)``, zero rows as padding."""
        r = self.targets[:, None, :] - self.sensors
        return np.where(self.valid[..., None], r, 0.0)

    @property
    def valid(self) -> np.ndarray:
        """``(S, M)`` mask of the real (non-padding) sensor rows."""
        return np.arange(self.sensors.shape[1])[None, :] < self.counts[:, None]

    def scene(self, k: int) -> Scene:
        """Scene ``k`` as a :class:`Scene` (for the per-scene functions)."""
        return Scene(self.sensors[k, : self.counts[k]].copy(), self.targets[k].copy(),
                     float(self.u_max[k]), self.kinds[k])


def random_scene_batch(
    n_scenes: int,
    seed: int,
    n_sensors: tuple[int, int] = (2, 6),
    scale: tuple[float, float] = (1e-3, 1e4),
    kinds: tuple[str, ...] = SCENE_KINDS,
) -> SceneBatch:
    """``n_scenes`` scenes drawn at once from ``numpy.random.default_rng(seed)``.

    The same distributions as :func:`random_scenes` (kinds cycling through ``kinds``, the number
    of sensors uniform in ``n_sensors``, the scale log-uniform in ``scale``, each kind as in
    :func:`random_scene`), drawn array by array instead of scene by scene, so the stream (and
    hence the scenes) differ from :func:`random_scenes` with the same seed.

    Examples
    --------
    >>> b = random_scene_batch(5, seed=0)
    >>> len(b), int(b.counts.min()) >= 2
    (5, True)
    """
    n_scenes, seed, n_sensors, scale, kinds = _draw_iv(
        n_scenes, seed, n_sensors, scale, kinds, 1
    )
    lo_n, hi_n = n_sensors
    rng = np.random.default_rng(seed)
    S, M = int(n_scenes), hi_n
    counts = rng.integers(lo_n, hi_n + 1, size=S)
    s = 10.0 ** rng.uniform(np.log10(scale[0]), np.log10(scale[1]), size=S)
    kind_of = np.arange(S) % len(kinds)
    names = np.array(kinds)[kind_of]
    targets = rng.uniform(-1.0, 1.0, size=(S, 2)) * s[:, None]
    # every kind's variates are drawn for every scene, then each scene keeps its own kind's
    generic = rng.uniform(-1.0, 1.0, size=(S, M, 2)) * s[:, None, None]
    phi = rng.uniform(0.0, np.pi, size=S)
    direction = np.column_stack([np.cos(phi), np.sin(phi)])
    mags = s[:, None] * 10.0 ** rng.uniform(-4.0, 3.0, size=(S, M))
    angles = rng.uniform(0.0, 2 * np.pi, size=(S, M))
    spread = mags[..., None] * np.stack([np.cos(angles), np.sin(angles)], axis=-1)
    t = rng.uniform(0.05, 1.0, size=(S, M)) * rng.choice([-1.0, 1.0], size=(S, M))
    line = s[:, None, None] * t[..., None] * direction[:, None, :]
    normal = np.column_stack([-direction[:, 1], direction[:, 0]])
    near = line + (1e-9 * s[:, None, None] * rng.standard_normal((S, M))[..., None]
                   * normal[:, None, :])
    offsets = np.select(
        [(names == k)[:, None, None] for k in ("generic", "collinear", "near-parallel")],
        [generic, line, near], spread)
    u_max = s * 10.0 ** rng.uniform(-2.0, 1.0, size=S)
    sensors = targets[:, None, :] + offsets
    sensors[np.arange(M)[None, :] >= counts[:, None]] = np.nan
    return _checked(SceneBatch(sensors, targets, u_max, tuple(names.tolist()), counts))


def _checked(batch: SceneBatch) -> SceneBatch:
    """``batch``, after the checks input scenes get (:func:`obslib._validate.check_scene_batch`):
    a draw of probability zero (a sensor on its target, two coincident sensors) raises."""
    check_scene_batch(batch.sensors, batch.targets, batch.counts)
    return batch
