"""Numerical kernels shared by the core modules and the studies: pair bounds, inverse condition
numbers and Theorem 8's measures, computed scale-free.

The callers validate their input (:mod:`obslib._validate`); these functions assume finite
arrays of the right shape.

Scale
-----
The paper's ratios (``C^{-1}``, Theorem 1's bound, the pair bounds, the measures' rank) do not
depend on the unit of length, but their formulas square the coordinates (Gram matrices) or raise
them to the fourth power (Cauchy-Binet determinants), which overflows for lengths beyond about
``1e77`` and underflows below ``1e-77``. Every kernel therefore first brings each scene into
:data:`SAFE_RANGE` by a power of two (:func:`pow2_scale`). Multiplying by a power of two is exact
in binary floating point, so a scene already inside the range is computed with exactly the same
arithmetic as without the rescaling (factor 1), and one outside it is computed as the same scene
in another unit.
"""

from __future__ import annotations

from itertools import combinations

import numpy as np

__all__ = [
    "SAFE_RANGE",
    "pow2_scale",
    "rescale",
    "pair_kernel",
    "normalise",
    "normalise_rows",
    "mahalanobis_rescale",
    "gram_parts",
    "ratio_from_gram",
    "inverse_condition",
    "matmul_rows",
    "tr_det",
    "lambda_max",
    "measure_from_tr_det",
]

#: Magnitudes (largest absolute coordinate of a scene) computed without rescaling. Within it,
#: fourth powers of ``N`` rows summed stay between ``2**-480`` and ``2**490`` for any practical
#: ``N``: far from overflow and from the subnormal range.
SAFE_RANGE = (2.0**-120, 2.0**120)


def pow2_scale(maxabs, even: bool = False) -> np.ndarray:
    """A power of two ``p`` per entry of ``maxabs`` with ``maxabs / p`` in ``[1, 2)``.

    ``p = 1`` where ``maxabs`` is 0 or inside :data:`SAFE_RANGE`, so those scenes are computed
    exactly as before. With ``even``, ``p`` is a power of four (its square root is exact) and
    ``maxabs / p`` is in ``[1, 4)``. ``p`` is at most ``2**1023``, always finite.
    """
    m = np.asarray(maxabs, dtype=float)
    _, e = np.frexp(m)
    e = e - 1  # maxabs = f 2^e with f in [1, 2)
    if even:
        e = e - (e & 1)
    inside = (m == 0) | ((m >= SAFE_RANGE[0]) & (m <= SAFE_RANGE[1]))
    return np.where(inside, 1.0, np.ldexp(1.0, np.where(inside, 0, e)))


def rescale(x: np.ndarray, p: np.ndarray) -> np.ndarray:
    """``x / p`` (``p`` from :func:`pow2_scale`, already shaped to broadcast); ``x`` itself when
    every ``p`` is 1, the common case, so ordinary scenes cost no copy."""
    return x if (p == 1.0).all() else x / p


def pair_kernel(xi, yi, xj, yj, u2):
    """Pair bound from the rows ``(xi, yi)`` and ``(xj, yj)``, broadcasting; ``u2 = u_max^2``.

    The nonzero eigenvalues of ``O^T O`` equal those of the Gram matrix
    ``[[r_i, c], [c, r_j]]`` (``r = ||v||^2``, ``c = v_i . v_j``), so
    ``lambda_max = (r_i + r_j)/2 + sqrt(((r_i - r_j)/2)^2 + c^2)`` without cancellation and
    ``lambda_min = det / lambda_max`` with ``det = (v_i x v_j)^2`` (Lagrange's identity), hence
    ``bound = |v_i x v_j| / sqrt(lambda_max (lambda_max + u_max^2))`` (Theorem 4, Eq. (9)).

    Every caller goes through this function with rows normalised by :func:`normalise`, so equal
    geometry gives equal weights. The arithmetic is done in place to keep memory traffic low (it
    is the hot loop of the assignment algorithms). ``u2`` may be ``inf`` (a speed bound beyond
    the float range relative to the rows): the bound is then 0, its limit.
    """
    ri = xi * xi + yi * yi
    rj = xj * xj + yj * yj
    cross = np.multiply(xi, yj)
    cross -= yi * xj
    dot = np.multiply(xi, xj)
    dot += yi * yj
    half = np.subtract(ri, rj)
    half *= 0.5
    half *= half
    dot *= dot
    dot += half
    np.sqrt(dot, out=dot)
    lmax = np.add(ri, rj, out=half)
    lmax *= 0.5
    lmax += dot  # lambda_max
    cross *= cross  # det = lambda_min * lambda_max
    den = np.add(lmax, u2, out=dot)
    den *= lmax
    # den = 0 only if both rows are 0 in this unit: a sensor 2**-1000 times closer to the target
    # than another (beyond the float range); its cross product is then 0 too, and stays 0.
    np.divide(cross, den, out=cross, where=den > 0)
    np.sqrt(cross, out=cross)
    return cross


def normalise(v: np.ndarray, u) -> tuple:
    """Scale each target's rows ``v[:, l]`` by ``1 / max_i ||v_il||``; return them and ``u_max^2``
    in the same unit, shape ``(L,)``.

    The pair bound is invariant under scaling rows and ``u_max`` together; the scaled squares in
    :func:`pair_kernel` are far from overflow and underflow whatever the units. The arithmetic is
    :func:`normalise_rows`' (on the coordinates of ``v`` laid out target by target), so both
    layouts give the same rows bit for bit.
    """
    x, y, u2 = normalise_rows(v[..., 0].T, v[..., 1].T, u)
    return np.stack([x.T, y.T], axis=-1), u2


def normalise_rows(x: np.ndarray, y: np.ndarray, u, out=None) -> tuple:
    """:func:`normalise` for rows given by their coordinates ``x, y``, shape ``(L, N)`` (target
    ``l``'s rows are ``x[l], y[l]``); returns the scaled ``x, y`` (new arrays, or ``out``, a pair
    of arrays of that shape to write them to) and ``u_max^2``.

    A target's rows are first brought into :data:`SAFE_RANGE` by a power of two (exact), so the
    norms cannot overflow; ``u_max`` too large to square in the new unit becomes ``inf``
    (bound 0).
    """
    n_targets = x.shape[0]
    if x.shape[1] == 0:
        with np.errstate(over="ignore"):
            return x, y, np.broadcast_to(np.asarray(u, dtype=float) ** 2, (n_targets,)).copy()
    # max |x| as max(max x, -min x): the same number without an array of |x|
    top = np.maximum(np.maximum(x.max(axis=1), -x.min(axis=1)),
                     np.maximum(y.max(axis=1), -y.min(axis=1)))
    p = pow2_scale(top)  # (L,)
    x, y = rescale(x, p[:, None]), rescale(y, p[:, None])
    sq = x * x
    sq += y * y
    scale = np.sqrt(sq.max(axis=1))
    with np.errstate(over="ignore"):
        u = np.broadcast_to(np.asarray(u, dtype=float), (n_targets,)) / p
        u2 = u**2 / scale**2
    if out is None:
        return x / scale[:, None], y / scale[:, None], u2
    np.divide(x, scale[:, None], out=out[0])
    np.divide(y, scale[:, None], out=out[1])
    return out[0], out[1], u2


def pair_series(v: np.ndarray, pairs: np.ndarray, u) -> np.ndarray:
    """Theorem 4's bound of the pair ``pairs[k]`` at each point ``k``, ``(K,)``, from the rows
    ``v`` ``(N, K, 2)`` of every sensor to every point (validated by the caller): each point's
    rows normalised by :func:`normalise`, then :func:`pair_kernel` of its pair only."""
    v, u2 = normalise(v, u)
    k = np.arange(v.shape[1])
    vi, vj = v[pairs[:, 0], k], v[pairs[:, 1], k]
    return pair_kernel(vi[:, 0], vi[:, 1], vj[:, 0], vj[:, 1], u2)


def mahalanobis_rescale(v: np.ndarray, cov: np.ndarray) -> tuple:
    """Vectors of ``v`` ``(N, L, 2)`` with their Euclidean direction and Mahalanobis length.

    ``d_il = sqrt(v^T Sigma_l^{-1} v)``. Returns ``(w, unit)``: ``w[:, l] * unit[l]`` are the
    rescaled vectors, with ``unit`` a power of two per target so that ``w`` cannot overflow (1
    for scenes and covariances inside :data:`SAFE_RANGE`, where ``w`` is the result itself).
    """
    pv = pow2_scale(np.abs(v).max(axis=(0, 2)) if v.shape[0] else np.zeros(v.shape[1]))
    pc = pow2_scale(np.abs(cov).max(axis=(1, 2)), even=True)  # sqrt(pc) exact
    vs = rescale(v, pv[None, :, None])
    prec = np.linalg.inv(rescale(cov, pc[:, None, None]))
    d_maha2 = np.einsum("nlk,lkm,nlm->nl", vs, prec, vs)
    d_eucl2 = np.einsum("nlk,nlk->nl", vs, vs)
    w = vs * np.sqrt(d_maha2 / d_eucl2)[..., None]
    with np.errstate(over="ignore"):  # inf: the true lengths are beyond the float range
        return w, pv / np.sqrt(pc)


def gram_parts(r: np.ndarray):
    """``det`` (Cauchy-Binet sum of squared cross products) and ``tr`` of ``O^T O``, stacked."""
    x, y = r[..., 0], r[..., 1]
    a, b = np.triu_indices(r.shape[-2], 1)
    cross = x[..., a] * y[..., b] - y[..., a] * x[..., b]
    det = np.einsum("...k,...k->...", cross, cross)
    tr = np.einsum("...k,...k->...", x, x) + np.einsum("...k,...k->...", y, y)
    return det, tr


def ratio_from_gram(det, tr):
    """``sqrt(det) / lambda_max`` with ``lambda_max = tr/2 + sqrt((tr/2)^2 - det)``; 0 if
    ``tr = 0``."""
    half = np.multiply(tr, 0.5)
    disc = np.asarray(half * half - det)  # a fresh array of the broadcast shape
    np.maximum(disc, 0.0, out=disc)
    np.sqrt(disc, out=disc)
    lmax = np.asarray(disc + half)
    np.sqrt(det, out=disc)
    zero = lmax <= 0
    if zero.any():
        lmax[zero] = 1.0
        disc[zero] = 0.0
    disc /= lmax
    return disc if disc.ndim else float(disc)


#: Up to this many rows the inverse condition number uses the closed form, beyond it the SVD.
CLOSED_FORM_MAX_ROWS = 8


def inverse_condition(stack: np.ndarray) -> np.ndarray:
    """``sigma_min / sigma_max`` of each ``(m, 2)`` matrix in ``stack`` (..., m, 2) (Eq. (6)).

    For ``G = O^T O`` (2 x 2), ``sigma_min / sigma_max = sqrt(lambda_min / lambda_max)
    = sqrt(det G) / lambda_max`` with ``det G = sum_{k < l} (r_k x r_l)^2`` (Cauchy-Binet: a sum
    of non-negative terms, accurate for nearly parallel rows) and
    ``lambda_max = tr/2 + sqrt((tr/2)^2 - det)`` (no cancellation). For more than
    :data:`CLOSED_FORM_MAX_ROWS` rows the pairs outnumber the SVD's work and the SVD is used.
    A matrix with fewer than two rows has rank < 2, so its ratio is 0. Each matrix is first
    brought into :data:`SAFE_RANGE` (the ratio does not depend on the unit).
    """
    m = stack.shape[-2]
    if m < 2:
        return np.zeros(stack.shape[:-2])
    p = pow2_scale(np.abs(stack).max(axis=(-2, -1)))
    stack = rescale(stack, p[..., None, None])
    if m > CLOSED_FORM_MAX_ROWS:
        sv = np.linalg.svd(stack, compute_uv=False)
        top = sv[..., 0]
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(top > 0, sv[..., -1] / np.where(top > 0, top, 1.0), 0.0)
    return ratio_from_gram(*gram_parts(stack))


#: Largest ``rows * inner * columns`` of one matrix product in :func:`matmul_rows`.
GEMM_BLOCK = 1 << 18


def matmul_rows(x: np.ndarray, w: np.ndarray) -> np.ndarray:
    """``x @ w`` for a 2-D ``x``, in blocks of rows.

    The products here are thin (a few dozen inner terms): a multi-threaded BLAS spends more on
    waking and spinning its threads than on the arithmetic, and steals the core the rest of the
    computation runs on. Blocks of at most :data:`GEMM_BLOCK` multiply-adds stay below
    OpenBLAS's threading threshold. Measured on two cores with the default BLAS threads: a
    ``(2000, 15) @ (15, 64)`` product takes 0.4 ms blocked against 8 ms whole, ``(20000, 15) @
    (15, 64)`` 3 ms against 8 ms. The result equals ``x @ w`` to rounding, not bit for bit: BLAS
    chooses its summation order by CPU and block shape (a test bounds the difference).
    """
    if x.ndim != 2:
        return x @ w
    step = max(1, GEMM_BLOCK // max(1, w.shape[0] * w.shape[1]))
    if x.shape[0] <= step:
        return x @ w
    out = np.empty((x.shape[0], w.shape[1]))
    for i in range(0, x.shape[0], step):
        np.matmul(x[i:i + step], w, out=out[i:i + step])
    return out


def tr_det(vectors: np.ndarray, masks: np.ndarray):
    """``tr``, ``det``, ``lambda_max`` of ``sum_{k in S} v_k v_k^T`` for each row ``S`` of
    ``masks``.

    ``vectors`` has shape ``(..., M, 2)`` and ``masks`` ``(K, M)``; the results have shape
    ``(..., K)``. The determinant is the Cauchy-Binet sum of squared cross products. The caller
    keeps ``vectors`` inside :data:`SAFE_RANGE`.
    """
    m = masks.astype(float)
    sq = np.einsum("...mk,...mk->...m", vectors, vectors)
    tr = matmul_rows(sq, m.T)
    n = vectors.shape[-2]
    if n >= 2:
        a, b = np.array(list(combinations(range(n), 2))).T
        cross = vectors[..., a, 0] * vectors[..., b, 1] - vectors[..., a, 1] * vectors[..., b, 0]
        det = matmul_rows(cross * cross, (m[:, a] * m[:, b]).T)
    else:
        det = np.zeros_like(tr)
    return tr, det, lambda_max(tr, det)


def lambda_max(tr, det):
    """Largest eigenvalue ``tr/2 + sqrt((tr/2)^2 - det)`` of a symmetric positive semidefinite 2 x 2
    matrix from its trace and determinant (no cancellation: both terms are non-negative)."""
    half = 0.5 * tr
    return half + np.sqrt(np.maximum(half * half - det, 0.0))


def measure_from_tr_det(name: str, tr, det, lmax, eps: float, rank_rtol: float, p=None):
    """Theorem 8's measure ``name`` of ``G = A + eps I`` from ``tr``, ``det``, ``lambda_max`` of
    ``A = O^T O`` (see :mod:`obslib.measures` for the conventions).

    With ``p`` (a power of two per instance, broadcasting against ``tr``), ``tr``, ``det``,
    ``lambda_max`` and ``eps`` are those of the scene in the unit ``p`` (rows divided by ``p``)
    and the result is converted back to the original unit; ``eps`` may then be an array. A
    result beyond the float range in the original unit raises :class:`ValueError`.
    """
    if name == "trace":
        out = tr + 2.0 * eps
        return out if p is None else _back(out * (p * p), name)
    with np.errstate(divide="ignore", invalid="ignore"):
        full = det > (rank_rtol * lmax) ** 2  # sigma_min / sigma_max > rank_rtol, and A != 0
    if name == "rank":
        return np.where(full, 2.0, np.where(tr > 0, 1.0, 0.0))
    det_g = det + eps * tr + eps * eps
    tr_g = tr + 2.0 * eps
    if p is None:
        if eps == 0.0:
            det_g = np.where(full, det_g, 0.0)
    else:
        det_g = np.where(np.asarray(eps) == 0.0, np.where(full, det_g, 0.0), det_g)
    with np.errstate(divide="ignore", invalid="ignore"):
        if name == "logdet":
            out = np.where(det_g > 0, np.log(np.where(det_g > 0, det_g, 1.0)), -np.inf)
            return out if p is None else out + 4.0 * np.log(p)
        inv = np.where(det_g > 0, tr_g / np.where(det_g > 0, det_g, 1.0), np.inf)
    if p is not None:
        with np.errstate(over="ignore"):
            inv = _back(np.where(np.isinf(inv), inv, inv / (p * p)), name, singular=np.isinf(inv))
    return inv if name == "trace_inverse" else -inv


def _back(values, name, singular=None):
    """Raise if converting a measure back to the original unit overflowed."""
    over = np.isinf(values) if singular is None else np.isinf(values) & ~singular
    if over.any():
        raise ValueError(f"the {name} of these sensors and target overflows the float range "
                         "(coordinates or eps too large or too small); use another unit of length")
    return values
