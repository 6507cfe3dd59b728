"""Input validation shared by the public functions.

Every public function of :mod:`obslib` checks its input at the boundary with these functions,
so that bad input fails with a :class:`ValueError` that names the offending argument, sensor or
target instead of propagating NaN or failing deep inside NumPy. One contract:

- every error is a :class:`ValueError`; an argument of the wrong type (a bool, a complex number,
  text or ``None`` where a number is expected, ``2.5`` where an integer is) raises
  :class:`ArgumentTypeError`, which is both a :class:`TypeError` and a :class:`ValueError`;
- every ``as_*`` function takes ``(value, name, ...)`` and returns the clean value; every
  ``check_*`` function takes validated arrays and returns nothing.
"""

from __future__ import annotations

import numpy as np

from ._kernels import mahalanobis_rescale

__all__ = ["ArgumentTypeError", "MissingFileError", "as_float_array", "as_points", "as_point",
           "as_u_max", "as_cov", "as_int", "as_bool", "as_eps", "as_positive", "as_nonnegative",
           "as_real", "as_str", "as_path", "as_names", "as_argv", "as_mapping", "as_callable",
           "as_sequence", "as_ints", "as_triples", "as_int_range", "broadcast", "as_rank_rtol",
           "as_measure_name", "as_weights", "as_real_array", "as_covariances", "as_noise_table",
           "as_instance", "as_choice", "check_spd_any_scale", "check_spd2", "check_distinct",
           "check_not_on_targets", "check_differences", "check_pair_sizes",
           "check_maximisable", "check_scene_batch", "as_stack", "as_u_max_stack",
           "validated_vectors", "vectors_between"]


class MissingFileError(FileNotFoundError, ValueError):
    """A path argument that names no file: both a :class:`FileNotFoundError` and, like every
    other bad input of the library, a :class:`ValueError`."""


class ArgumentTypeError(TypeError, ValueError):
    """An argument of the wrong type (a bool, complex number, string or None where a real number
    is expected). Both a :class:`TypeError` and, like every other bad input of the library, a
    :class:`ValueError` (as NumPy's ``AxisError`` is both a ValueError and an IndexError)."""


def as_float_array(x, name: str) -> np.ndarray:
    """``x`` as a float array; booleans, complex numbers, strings and ``None`` are refused.

    NumPy would silently turn ``True`` into 1.0 (also inside a list of numbers, ``[0.5, True]``),
    drop the imaginary part of a complex number, read the text ``"1.5"`` of an object array as a
    number, and read the masked entries of a masked array as numbers; here each is an error
    naming ``name`` (a :class:`TypeError` too, but for the mask).

    Examples
    --------
    >>> as_float_array([[0.5, 1.0], [True, 2.0]], "sensors")
    Traceback (most recent call last):
    ...
    obslib._validate.ArgumentTypeError: sensors must be numeric, got a bool: ...
    """
    if x is None:
        raise ArgumentTypeError(f"{name} must be numeric, got None")
    if isinstance(x, np.ma.MaskedArray) and np.ma.is_masked(x):
        raise ValueError(f"{name} is a masked array with masked entries, which NumPy would read "
                         "as numbers; fill them (x.filled(value)) or leave them out")
    if isinstance(x, (list, tuple)):  # NumPy would turn a bool among numbers into 0 or 1
        got = _bad_kind(x)
        if got:
            raise ArgumentTypeError(f"{name} must be numeric, got {got}: {x!r:.80}")
    arr = np.asarray(x)
    if arr.dtype.kind == "O":
        got = _bad_kind(arr)
        if got:  # float() would read "1.5" and True
            raise ArgumentTypeError(f"{name} must be numeric, got {got}: {x!r:.80}")
        try:
            arr = np.asarray(x, dtype=float)
        except OverflowError:
            raise ValueError(f"{name} has an integer beyond the float range") from None
        except (TypeError, ValueError) as exc:
            raise ArgumentTypeError(f"{name} must be numeric: {exc}") from None
    if arr.dtype.kind == "b":
        raise ArgumentTypeError(f"{name} must be numeric, got booleans")
    if arr.dtype.kind == "c":
        raise ArgumentTypeError(f"{name} must be real, got complex numbers")
    if arr.dtype.kind not in "iuf":
        raise ArgumentTypeError(f"{name} must be numeric, got dtype {arr.dtype}")
    return arr.astype(float, copy=False)


def as_points(points, name: str = "sensors", *, min_count: int = 0) -> np.ndarray:
    """Return ``points`` as a float array of shape ``(n, 2)``.

    Raises
    ------
    ValueError
        If the array is not two-dimensional with two columns, has fewer than
        ``min_count`` rows, or any coordinate is NaN or infinite (the message names
        the first offending row).
    """
    arr = as_float_array(points, name)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"{name} must have shape (n, 2), got {arr.shape}")
    if arr.shape[0] < min_count:
        raise ValueError(f"{name} needs at least {min_count} point(s), got {arr.shape[0]}")
    if not np.isfinite(arr).all():  # one reduction; the offending row is looked up on failure only
        k = int(np.flatnonzero(~np.isfinite(arr).all(axis=1))[0])
        singular = name[:-1] if name.endswith("s") else name
        raise ValueError(f"{singular} {k} has a non-finite coordinate: {arr[k].tolist()}")
    return arr


def as_point(point, name: str = "target") -> np.ndarray:
    """Return one point as a float array of shape ``(2,)`` (finite)."""
    arr = as_float_array(point, name)
    if arr.shape != (2,):
        raise ValueError(f"{name} must have shape (2,), got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} has a non-finite coordinate: {arr.tolist()}")
    return arr


def as_u_max(u_max, n_targets: int | None = None) -> np.ndarray:
    """Return ``u_max`` as a float array (scalar, or one value per target).

    ``u_max`` is the bound on the target's control input, ``||u_o|| <= u_max``, so it must
    be finite and non-negative. With ``n_targets`` given, a vector of that length is accepted.
    """
    arr = as_float_array(u_max, "u_max")
    if arr.ndim == 1 and n_targets is not None:
        if arr.shape[0] != n_targets:
            raise ValueError(
                f"u_max must be a scalar or have one value per target ({n_targets}), "
                f"got shape {arr.shape}"
            )
    elif arr.ndim != 0:
        raise ValueError(f"u_max must be a scalar, got shape {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"u_max must be finite, got {arr.tolist()}")
    if (arr < 0).any():
        where = "" if arr.ndim == 0 else f" for target {int(np.flatnonzero(arr < 0)[0])}"
        raise ValueError(f"u_max must be non-negative{where}, got {arr.tolist()}")
    return arr


def as_cov(cov, n_targets: int) -> np.ndarray:
    """Return covariances as an array of shape ``(L, 2, 2)``, each symmetric positive definite.

    A single ``(2, 2)`` matrix is shared by all targets.
    """
    arr = as_float_array(cov, "cov")
    if arr.shape == (2, 2):
        arr = np.broadcast_to(arr, (n_targets, 2, 2))
    if arr.shape != (n_targets, 2, 2):
        raise ValueError(f"cov must have shape (2, 2) or ({n_targets}, 2, 2), got {arr.shape}")
    # vectorised checks; on failure, the first offending target gets the detailed message
    finite = np.isfinite(arr).all(axis=(1, 2))
    with np.errstate(invalid="ignore", over="ignore"):
        sym, pd = _spd2_flags(arr)
    bad = ~(finite & sym & pd)
    if bad.any():
        l = int(np.flatnonzero(bad)[0])
        check_spd2(arr[l], f"cov of target {l}")
    return arr


def _spd2_flags(arr: np.ndarray):
    """Symmetric and positive definite flags of 2x2 matrices ``(..., 2, 2)``, independent of scale.

    Each matrix is divided by its largest absolute entry first, so a covariance of scale
    ``1e-170`` (determinant ``1e-340``, below the float range) or ``1e170`` is judged like the
    same matrix of scale 1. Symmetric: off-diagonal entries equal to ``1e-12`` relative.
    Positive definite: Sylvester's criterion on the normalised matrix.
    """
    top = np.abs(arr).max(axis=(-2, -1))
    m = arr / np.where(top > 0, top, 1.0)[..., None, None]
    sym = np.abs(m[..., 0, 1] - m[..., 1, 0]) <= 1e-12
    pd = (m[..., 0, 0] > 0) & (m[..., 0, 0] * m[..., 1, 1] - m[..., 0, 1] * m[..., 1, 0] > 0)
    return sym, pd


def check_spd2(m: np.ndarray, name: str) -> None:
    """Raise unless the 2x2 array ``m`` is finite, symmetric and positive definite (any scale)."""
    m = np.asarray(m, dtype=float)
    if not np.isfinite(m).all():
        raise ValueError(f"{name} has a non-finite entry: {m.tolist()}")
    sym, pd = _spd2_flags(m)
    if not sym:
        raise ValueError(f"{name} is not symmetric: {m.tolist()}")
    if not pd:
        raise ValueError(f"{name} is not positive definite: {m.tolist()}")


def check_distinct(sensors: np.ndarray) -> None:
    """Raise if two sensors share a position (the paper assumes distinct sensors)."""
    n = sensors.shape[0]
    if n < 2:
        return
    order = np.lexsort((sensors[:, 1], sensors[:, 0]))
    s = sensors[order]
    same = (s[1:] == s[:-1]).all(axis=1)
    if same.any():
        k = int(np.flatnonzero(same)[0])
        i, j = sorted((int(order[k]), int(order[k + 1])))
        raise ValueError(f"sensors {i} and {j} coincide at {sensors[i].tolist()}")


def check_not_on_targets(diff: np.ndarray) -> None:
    """Raise if a sensor sits on a target; ``diff[i, l] = o_l - p_i`` has shape ``(N, L, 2)``."""
    on = (diff == 0).all(axis=-1)
    if on.any():
        i, l = (int(v) for v in np.argwhere(on)[0])
        raise ValueError(f"sensor {i} coincides with target {l} (zero distance)")


def check_differences(diff: np.ndarray, what: str = "target") -> None:
    """Raise if a difference ``o_l - p_i`` overflowed (coordinates near the float limit)."""
    bad = ~np.isfinite(diff).all(axis=-1)
    if bad.any():
        i, l = (int(v) for v in np.argwhere(bad)[0])
        raise ValueError(
            f"sensor {i} and {what} {l} are too far apart: their difference overflows "
            "(coordinates out of the float range; use a larger unit of length)"
        )


def _bad_kind(value) -> str | None:
    """What makes ``value`` not a real number (or nested sequence of them): ``"a bool"``,
    ``"a complex number"``, ``"text"``, or None."""
    if isinstance(value, np.ndarray):
        kind = value.dtype.kind
        if kind == "O":
            return next(filter(None, map(_bad_kind, value.ravel())), None)
        return {"b": "a bool", "c": "a complex number", "U": "text", "S": "text"}.get(kind)
    if isinstance(value, (bool, np.bool_)):
        return "a bool"
    if isinstance(value, (complex, np.complexfloating)):
        return "a complex number"
    if isinstance(value, (str, bytes)):
        return "text"
    if isinstance(value, (list, tuple)):
        return next(filter(None, map(_bad_kind, value)), None)
    return None


def as_real_array(value, name: str, what: str) -> np.ndarray:
    """``value`` as a float array, or a named error saying it must be ``what``: an
    :class:`ArgumentTypeError` for text, bools and complex numbers (which ``float`` would coerce
    silently or drop), a :class:`ValueError` for the rest (ragged nesting, ``None``).

    Examples
    --------
    >>> as_real_array([1, 2.5], "x", "real numbers")
    array([1. , 2.5])
    >>> as_real_array([1, True], "x", "numbers")
    Traceback (most recent call last):
    ...
    obslib._validate.ArgumentTypeError: x must be numbers, got a bool: [1, True]
    """
    got = _bad_kind(value)
    if got:
        raise ArgumentTypeError(f"{name} must be {what}, got {got}: {value!r}")
    try:
        return np.asarray(value, dtype=float)
    except (TypeError, ValueError) as exc:
        raise ValueError(f"{name} must be {what}: {exc}") from None


def check_spd_any_scale(m: np.ndarray, name: str, max_scale: float) -> None:
    """:func:`check_spd2` on ``m`` divided by its largest entry, so that a positive definite
    matrix of any scale passes (its determinant may underflow or overflow in floating point);
    entries over ``max_scale`` (the largest scale the tracking filter can carry) are refused."""
    if not np.isfinite(m).all():
        raise ValueError(f"{name} has a non-finite entry: {m.tolist()}")
    top = float(np.abs(m).max())
    if top == 0:
        raise ValueError(f"{name} is not positive definite: {m.tolist()}")
    try:
        check_spd2(m / top, name)  # scaled: a determinant of any scale stays representable
    except ValueError as exc:
        raise ValueError(f"{str(exc).split(': [')[0]}: {m.tolist()}") from None
    if top > max_scale:
        raise ValueError(
            f"{name} has entries of scale {top:.3g}; the filter's innovation covariance "
            f"H P H^T + R would overflow: keep entries below {max_scale:g}"
        )


def as_covariances(cov, n: int, max_scale: float, name: str = "cov") -> np.ndarray:
    """Covariances as an ``(n, 2, 2)`` array (one ``(2, 2)`` is shared), each finite, symmetric
    and positive definite at any scale up to ``max_scale`` (checked divided by its largest
    entry, so that a determinant that underflows does not reject it), or a named ValueError.

    Examples
    --------
    A shared covariance is broadcast; a tiny one is accepted; an indefinite one is not:

    >>> import numpy as np
    >>> as_covariances(np.eye(2), 3, 1e100).shape
    (3, 2, 2)
    >>> as_covariances(1e-200 * np.eye(2), 1, 1e100).shape
    (1, 2, 2)
    >>> as_covariances([[1.0, 2.0], [2.0, 1.0]], 1, 1e100)
    Traceback (most recent call last):
    ...
    ValueError: cov 0 is not positive definite: [[1.0, 2.0], [2.0, 1.0]]
    """
    c = as_real_array(cov, name, "real 2x2 matrices")
    if c.shape == (2, 2):
        c = np.broadcast_to(c, (n, 2, 2))
    if c.shape != (n, 2, 2):
        raise ValueError(f"{name} must have shape (2, 2) or ({n}, 2, 2), got {c.shape}")
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        sym, pd = _spd2_flags(c)
    ok = np.isfinite(c).all(axis=(1, 2)) & sym & pd
    if not ok.all():
        k = int(np.flatnonzero(~ok)[0])
        check_spd_any_scale(c[k], f"{name} {k}", max_scale)
    return c


def as_noise_table(noise, shape: tuple) -> np.ndarray:
    """A measurement-noise table as a finite float ``(steps, sensors)`` array of ``shape``, or a
    ValueError naming the first non-finite entry or the wrong shape.

    Examples
    --------
    >>> import numpy as np
    >>> table = np.zeros((2, 6))
    >>> as_noise_table(table, (2, 6)).shape
    (2, 6)
    >>> table[1, 3] = np.nan
    >>> as_noise_table(table, (2, 6))
    Traceback (most recent call last):
    ...
    ValueError: noise of sensor 3 at step 2 is not finite
    """
    t = as_real_array(noise, "noise", "a real (steps, sensors) table")
    if t.shape != tuple(shape):
        raise ValueError(f"noise table must have shape {tuple(shape)} (steps, sensors), "
                         f"got {t.shape}")
    bad = ~np.isfinite(t)
    if bad.any():
        k, i = (int(v) for v in np.argwhere(bad)[0])
        raise ValueError(f"noise of sensor {i} at step {k + 1} is not finite")
    return t


def as_instance(value, cls: type, name: str):
    """``value`` if it is a ``cls``, else a ValueError naming ``name``.

    Examples
    --------
    >>> as_instance("circle", dict, "base")
    Traceback (most recent call last):
    ...
    ValueError: base must be a dict, got str
    """
    if not isinstance(value, cls):
        raise ValueError(f"{name} must be a {cls.__name__}, got {type(value).__name__}")
    return value


def as_choice(value, known, what: str) -> str:
    """``value`` if it is one of the names ``known``; an :class:`ArgumentTypeError` for a
    non-string, a ValueError naming ``what`` and the known names otherwise.

    Examples
    --------
    >>> as_choice("d-optimal", ("d-optimal", "random"), "strategy")
    'd-optimal'
    >>> as_choice("worst-pair", ("d-optimal", "random"), "strategy")
    Traceback (most recent call last):
    ...
    ValueError: unknown strategy 'worst-pair'; known: ('d-optimal', 'random')
    """
    if not isinstance(value, str):
        raise ArgumentTypeError(f"{what} must be a string, one of {tuple(known)}; got {value!r}")
    if value not in known:
        raise ValueError(f"unknown {what} {value!r}; known: {tuple(known)}")
    return value


def as_int(value, name: str, minimum: int | None = None) -> int:
    """An integer argument: ``int`` or NumPy integer (not bool, not ``2.0``), at least
    ``minimum``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise ArgumentTypeError(f"{name} must be an integer, got {value!r}")
    if minimum is not None and value < minimum:
        raise ValueError(f"{name} must be at least {minimum}, got {value}")
    return int(value)


def as_bool(value, name: str) -> bool:
    """A flag: ``True`` or ``False`` only (a string such as ``"no"`` would be truthy)."""
    if not isinstance(value, (bool, np.bool_)):
        raise ArgumentTypeError(f"{name} must be True or False, got {value!r}")
    return bool(value)


def _as_real(value, name: str) -> float:
    if isinstance(value, (bool, np.bool_)) or value is None:
        raise ArgumentTypeError(f"{name} must be a real number, got {value!r}")
    arr = as_float_array(value, name)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar, got shape {arr.shape}")
    return float(arr)


def as_positive(value, name: str) -> float:
    """A finite positive real parameter (a length, a step, a scale)."""
    x = _as_real(value, name)
    if not np.isfinite(x) or x <= 0:
        raise ValueError(f"{name} must be finite and positive, got {value!r}")
    return x


def as_nonnegative(value, name: str) -> float:
    """A finite non-negative real parameter (a speed bound, a ratio that may be 0)."""
    x = _as_real(value, name)
    if not np.isfinite(x) or x < 0:
        raise ValueError(f"{name} must be finite and non-negative, got {value!r}")
    return x


def as_str(value, name: str) -> str:
    """A string argument (a name, a label, a format); anything else is an
    :class:`ArgumentTypeError`."""
    if not isinstance(value, str):
        raise ArgumentTypeError(f"{name} must be a string, got {value!r}")
    return value


def as_path(value, name: str, exists: bool = False):
    """A path argument (``str`` or ``os.PathLike``) as a :class:`pathlib.Path`; with ``exists``,
    the path of an existing file (else :class:`MissingFileError`)."""
    import os
    from pathlib import Path

    if not isinstance(value, (str, os.PathLike)):
        raise ArgumentTypeError(f"{name} must be a path, got {value!r}")
    path = Path(value)
    if exists and not path.is_file():
        raise MissingFileError(f"{name} {path}: no such file")
    return path


def as_names(value, name: str, known=None) -> tuple:
    """A sequence of strings (not one string), each one of ``known`` if given."""
    if isinstance(value, (str, bytes)) or not isinstance(value, (list, tuple, np.ndarray)):
        raise ArgumentTypeError(f"{name} must be a list of names, got {value!r}")
    out = tuple(value.tolist() if isinstance(value, np.ndarray) else value)
    for v in out:
        if not isinstance(v, str):
            raise ArgumentTypeError(f"{name} must be a list of names, got {v!r} in it")
        if known is not None and v not in known:
            raise ValueError(f"{name}: unknown name {v!r}; known: {tuple(known)}")
    return out


def as_argv(argv) -> list | None:
    """A command line (``None``: ``sys.argv[1:]``) as a list of strings."""
    if argv is None:
        return None
    if isinstance(argv, (str, bytes)) or not isinstance(argv, (list, tuple)) or not all(
            isinstance(a, str) for a in argv):
        raise ArgumentTypeError(f"argv must be a list of strings, got {argv!r}")
    return list(argv)


def as_mapping(value, name: str) -> dict:
    """A mapping argument as a ``dict``."""
    from collections.abc import Mapping

    if not isinstance(value, Mapping):
        raise ArgumentTypeError(f"{name} must be a mapping, got {value!r}")
    return dict(value)


def as_callable(value, name: str):
    """A function argument."""
    if not callable(value):
        raise ArgumentTypeError(f"{name} must be callable, got {value!r}")
    return value


def as_real(value, name: str) -> float:
    """A finite real number (any sign)."""
    x = _as_real(value, name)
    if not np.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def as_ints(value, name: str, minimum: int | None = None) -> list:
    """A non-empty list of integers (each at least ``minimum``), e.g. the sizes of a sweep."""
    if isinstance(value, np.ndarray) and value.ndim == 1:
        value = value.tolist()
    if isinstance(value, range):
        value = list(value)
    out = [as_int(v, name, minimum) for v in as_sequence(value, name)]
    if not out:
        raise ValueError(f"{name} must not be empty")
    return out


def as_int_range(value, name: str, minimum: int | None = None) -> tuple:
    """An integer range ``(lo, hi)``, both inclusive, with ``minimum <= lo <= hi``."""
    if not (isinstance(value, (tuple, list)) and len(value) == 2):
        raise ValueError(f"{name} must be a pair (lo, hi), got {value!r}")
    lo, hi = as_int(value[0], name, minimum), as_int(value[1], name, minimum)
    if hi < lo:
        raise ValueError(f"{name} must have lo <= hi, got {value!r}")
    return lo, hi


def as_triples(triples, W: np.ndarray, name: str = "triples") -> list:
    """Triples ``(i, j, l)`` of integers that index the weights ``W`` ``(N, N, L)``."""
    if W.ndim != 3 or W.shape[0] != W.shape[1]:
        raise ValueError(f"W must have shape (N, N, L), got {W.shape}")
    out = []
    for t in as_sequence(triples, name):
        if not (isinstance(t, (tuple, list)) and len(t) == 3 and all(
                isinstance(a, (int, np.integer)) and not isinstance(a, bool) for a in t)):
            raise ArgumentTypeError(f"{name} must be triples (i, j, l) of integers, got {t!r}")
        if not (0 <= t[0] < W.shape[0] and 0 <= t[1] < W.shape[0] and 0 <= t[2] < W.shape[2]):
            raise ValueError(f"{name}: {tuple(t)} is outside W of shape {W.shape}")
        out.append(tuple(int(a) for a in t))
    return out


def as_sequence(value, name: str) -> list:
    """A list or tuple argument (not a string), as a list."""
    if isinstance(value, (str, bytes)) or not isinstance(value, (list, tuple)):
        raise ArgumentTypeError(f"{name} must be a list, got {value!r}")
    return list(value)


def broadcast(arrays: dict) -> list:
    """The arrays ``{name: array}`` broadcast to one shape, or a ValueError naming them."""
    try:
        return np.broadcast_arrays(*arrays.values())
    except ValueError:
        shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in arrays.items())
        raise ValueError(f"the shapes of {shapes} do not broadcast together") from None


def as_eps(eps) -> float:
    """Prior information ``eps >= 0`` (finite) of Theorem 8's measures."""
    e = _as_real(eps, "eps")
    if not np.isfinite(e) or e < 0:
        raise ValueError(f"eps must be finite and non-negative, got {eps!r}")
    return e


def as_rank_rtol(rank_rtol) -> float:
    """Relative threshold of the numerical rank, in ``[0, 1)``."""
    r = _as_real(rank_rtol, "rank_rtol")
    if not (np.isfinite(r) and 0 <= r < 1):
        raise ValueError(f"rank_rtol must be in [0, 1), got {rank_rtol!r}")
    return r


def as_measure_name(name, known) -> str:
    """One of the measure names ``known``."""
    return as_choice(name, known, "measure")


def as_weights(W) -> np.ndarray:
    """Pair weights ``W`` ``(N, N, L)``: finite, non-negative, symmetric in ``i, j``.

    The solvers read only ``W[i, j, l]`` with ``i < j``; the diagonal ``W[i, i, l]`` is ignored
    (``pair_bounds`` puts zeros there). Negative weights are refused: the problems are stated
    for non-negative weights (the pair bounds), and with negative ones "assign a pair" and
    "leave the target unassigned" are no longer comparable, so the solvers would disagree.
    """
    arr = as_float_array(W, "W")
    if arr.ndim != 3 or arr.shape[0] != arr.shape[1]:
        raise ValueError(f"W must have shape (N, N, L), got {arr.shape}")
    if not np.isfinite(arr).all():
        i, j, l = (int(v) for v in np.argwhere(~np.isfinite(arr))[0])
        raise ValueError(f"W[{i}, {j}, {l}] is not finite")
    if (arr < 0).any():
        i, j, l = (int(v) for v in np.argwhere(arr < 0)[0])
        raise ValueError(
            f"W[{i}, {j}, {l}] = {float(arr[i, j, l])!r} is negative; pair weights must be >= 0"
        )
    if not np.array_equal(arr, arr.transpose(1, 0, 2)):
        i, j, l = (int(v) for v in np.argwhere(arr != arr.transpose(1, 0, 2))[0])
        raise ValueError(f"W must be symmetric in its first two indices (pair weights): "
                         f"W[{i}, {j}, {l}] != W[{j}, {i}, {l}]")
    return arr


def as_stack(x, name: str, min_ndim: int) -> np.ndarray:
    """A finite float array of shape ``(..., 2)`` (``min_ndim = 1``) or ``(..., N, 2)`` (``2``)."""
    arr = as_float_array(x, name)
    if arr.ndim < min_ndim or arr.shape[-1] != 2:
        raise ValueError(f"{name} must have shape (..., {'N, ' if min_ndim > 1 else ''}2), "
                         f"got {arr.shape}")
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} has a non-finite coordinate")
    return arr


def as_u_max_stack(u_max, shape) -> np.ndarray:
    """``u_max`` (finite, non-negative) broadcast to ``shape``, one value per scene."""
    u = as_float_array(u_max, "u_max")
    if not np.isfinite(u).all() or (u < 0).any():
        raise ValueError("u_max must be finite and non-negative")
    try:
        return np.broadcast_to(u, shape)
    except ValueError:
        raise ValueError(f"u_max must be a scalar or of shape {shape}, got {u.shape}") from None


def check_pair_sizes(n: int, n_targets: int) -> None:
    """Unique pairs need at least one target and ``N >= 2L`` sensors (Problem 1)."""
    if n_targets < 1:
        raise ValueError("there must be at least one target")
    if n < 2 * n_targets:
        raise ValueError(
            f"unique pairs need N >= 2L sensors; got N = {n} sensors for L = {n_targets} targets"
        )


def check_maximisable(name: str, eps: float, known, maximisable) -> None:
    """A measure the team greedy can maximise: one of ``known``, monotone increasing (in
    ``maximisable``), finite for small teams."""
    as_measure_name(name, known)
    if name not in maximisable:
        raise ValueError(
            f"measure {name!r} decreases as sensors are added; "
            f"maximise one of {tuple(maximisable)} "
            "(e.g. 'neg_trace_inverse' instead of 'trace_inverse')"
        )
    if name in ("logdet", "neg_trace_inverse") and eps <= 0:
        raise ValueError(
            f"measure {name!r} is infinite for teams of fewer than two sensors unless eps > 0; "
            "pass a prior eps > 0"
        )


def check_scene_batch(sensors, targets, counts) -> None:
    """Validate padded stacked scenes as the per-scene functions would.

    Raises ``ValueError`` naming the scene and sensor for a non-finite coordinate, a sensor on
    the target (zero distance) or two coincident sensors (among the first ``counts[k]`` rows of
    scene ``k``; the padding is not checked).

    Examples
    --------
    >>> from obslib._validate import check_scene_batch
    >>> check_scene_batch([[[0.0, 0.0], [1.0, 1.0]]], [[1.0, 1.0]], [2])
    Traceback (most recent call last):
    ...
    ValueError: scene 0: sensor 1 is on the target (zero distance)
    """
    s = as_float_array(sensors, "sensors")
    t = as_float_array(targets, "targets")
    c = np.asarray(counts)
    if c.dtype.kind not in "iu":
        raise ArgumentTypeError(f"counts must be integers, got dtype {c.dtype}")
    if s.ndim != 3 or s.shape[2] != 2 or t.shape != (s.shape[0], 2) or c.shape != (s.shape[0],):
        raise ValueError(f"need sensors (S, M, 2), targets (S, 2), counts (S,); got "
                         f"{s.shape}, {t.shape}, {c.shape}")
    if (c < 0).any() or (c > s.shape[1]).any():
        raise ValueError(f"counts must lie in [0, {s.shape[1]}]")
    valid = np.arange(s.shape[1])[None, :] < c[:, None]
    finite = np.isfinite(s).all(axis=2)
    if not (finite | ~valid).all() or not np.isfinite(t).all():
        bad = ~np.isfinite(t).all(axis=1) | (valid & ~finite).any(axis=1)
        raise ValueError(f"scene {int(np.flatnonzero(bad)[0])} has a non-finite coordinate")
    zero = valid & (s[..., 0] == t[:, None, 0]) & (s[..., 1] == t[:, None, 1])
    if zero.any():
        k, i = (int(v) for v in np.argwhere(zero)[0])
        raise ValueError(f"scene {k}: sensor {i} is on the target (zero distance)")
    a, b = np.triu_indices(s.shape[1], 1)
    same = (s[:, a, 0] == s[:, b, 0]) & (s[:, a, 1] == s[:, b, 1]) & valid[:, b]
    if same.any():
        k, p = (int(v) for v in np.argwhere(same)[0])
        raise ValueError(f"scene {k}: sensors {int(a[p])} and {int(b[p])} coincide")


def validated_vectors(sensors, targets, cov=None):
    """Validated ``o_l - p_i`` ``(N, L, 2)``, Mahalanobis-rescaled with ``cov``, in units ``(L,)``.

    The true vectors are ``v[:, l] * unit[l]``; ``unit`` is 1 except for a covariance or scene
    outside the safe range (see :func:`obslib._kernels.mahalanobis_rescale`).
    """
    return vectors_between(as_points(sensors, "sensors"), as_points(targets, "targets"), cov)


def vectors_between(s: np.ndarray, t: np.ndarray, cov=None):
    """:func:`validated_vectors` for points that already passed :func:`as_points`: the checks of
    the scene (distinct sensors, finite nonzero differences) and of ``cov``, each done once."""
    check_distinct(s)
    with np.errstate(over="ignore", invalid="ignore"):
        v = t[None, :, :] - s[:, None, :]
    check_differences(v)
    check_not_on_targets(v)
    if cov is None:
        return v, np.ones(t.shape[0])
    return mahalanobis_rescale(v, as_cov(cov, t.shape[0]))
