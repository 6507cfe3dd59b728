"""The ledger records of notebook 02 (obslib.claims.pair_closed_form) at the quick profile.

Each status is asserted against evidence recomputed here independently of obslib.pair_form and
obslib.symbolic: plain NumPy/SciPy on the paper's printed formulas and on O^T O.
"""

import json
from dataclasses import asdict

import numpy as np
import pytest
from scipy.optimize import minimize, minimize_scalar

import obslib as ob
import obslib.claims.pair_closed_form as cp
from obslib.claims import evaluate, registry
from obslib.claims.quotes import found

IDS = (
    "thm4", "fig2-max", "thm5", "thm5-alpha-not-1", "thm1-weyl-step",
    "thm1-proof-dual-weyl-range", "thm4-proof-matrix", "thm5-proof-dtheta",
    "thm5-proof-dalpha-halfpi", "thm5-proof-dalpha", "thm5-proof-dalpha-min",
)  # fmt: skip


@pytest.fixture(scope="module")
def findings():
    return {r.id: r for r in evaluate("quick", ids=IDS)}


def test_records_are_registered_with_their_notebook(findings):
    reg = registry()
    for i in IDS:
        assert reg[i].notebook == "02_pair_closed_form" and reg[i].kind == "paper"
        assert reg[i].where and reg[i].statement and reg[i].paper
        assert found(reg[i].quote), f"{i}: the quote is not the paper's"
        assert findings[i].ours and findings[i].summary
    json.dumps([asdict(r) for r in findings.values()], default=float)  # the CLI's --json


def test_params_come_from_the_profiles():
    from obslib.profiles import params

    quick, paper = params(cp.NOTEBOOK, "quick"), params(cp.NOTEBOOK, "paper")
    assert quick["n_random_points"] < paper["n_random_points"]
    with pytest.raises(ValueError):
        evaluate("nonsense", ids=["thm4"])


def theorem4(a, t, q):
    """Eq. (9) exactly as printed."""
    S = np.sqrt(1 + a**4 + 2 * a**2 * np.cos(2 * t))
    with np.errstate(invalid="ignore"):  # 1 + a^2 - S may round below 0 where the bound is 0
        return np.sqrt((1 + a**2 - S) / (1 + a**2 + S + 2 * q**2))


def test_thm4_status(findings):
    rng = np.random.default_rng(11)
    worst = 0.0
    for _ in range(300):
        o, pi, pj = rng.uniform(-5, 5, size=(3, 2))
        u = rng.uniform(0, 3)
        O = np.array([o - pi, o - pj])
        lam = np.linalg.eigvalsh(O.T @ O)
        direct = np.sqrt(max(lam[0], 0) / (lam[1] + u * u))
        di, dj = np.linalg.norm(pi - o), np.linalg.norm(pj - o)
        t = np.arctan2(*(pj - o)[::-1]) - np.arctan2(*(pi - o)[::-1])
        if direct > 1e-3:
            worst = max(worst, abs(direct - theorem4(dj / di, t, u / di)))
    assert worst < 1e-10
    assert findings["thm4"].status == "reproduced"


def test_fig2_max_status(findings):
    a = np.arange(0, 501) / 100
    t = np.linspace(-np.pi, np.pi, 721)
    A, T = np.meshgrid(a, t)
    Z = np.nan_to_num(theorem4(A, T, 1.0))
    k, l = np.unravel_index(Z.argmax(), Z.shape)
    assert a[l] == 1.0 and abs(abs(t[k]) - np.pi / 2) < 1e-12
    assert Z.max() == pytest.approx(1 / np.sqrt(2), abs=1e-12)
    # the paper's grid misses +-pi/2, so its maximum is lower
    tp = -np.pi + 0.1 * np.arange(63)
    Zp = np.nan_to_num(theorem4(*np.meshgrid(np.arange(51) / 10, tp), 1.0))
    assert Zp.max() < 0.701
    assert findings["fig2-max"].status == "reproduced"


def test_thm5_status(findings):
    for q in (0.5, 1.0, 2.0):
        best = max(
            (minimize(lambda x: -ob.pair_bound_polar(abs(x[0]), x[1], q), x0, method="Nelder-Mead",
                      options={"xatol": 1e-10, "fatol": 1e-14, "maxiter": 4000})
             for x0 in ([0.5, 1.0], [2.0, -2.0], [1.2, 1.8], [3.0, 0.5])),
            key=lambda r: -r.fun,
        )
        assert -best.fun == pytest.approx(1 / np.sqrt(1 + q * q), abs=1e-8)
        assert abs(abs(best.x[0]) - 1) < 1e-4 and abs(abs(best.x[1]) - np.pi / 2) < 1e-4
        assert ob.pair_bound_polar(1e7, 0.7, q) < 1e-6
        assert ob.pair_bound_polar(2.0, 0.0, q) == 0 and ob.pair_bound_polar(0.0, 0.7, q) == 0
    assert findings["thm5"].status == "reproduced"


def test_thm5_alpha_not_1_status(findings):
    def argmax(theta, q):
        return minimize_scalar(lambda x: -ob.pair_bound_polar(x, theta, q), bounds=(0, 20),
                               method="bounded", options={"xatol": 1e-10}).x

    assert all(argmax(t, 1.0) > 1.001 for t in (0.3, 1.0, 2.5))
    assert all(abs(argmax(t, 0.0) - 1) < 1e-6 for t in (0.3, 1.0, 2.5))  # stationary target
    assert findings["thm5-alpha-not-1"].status == "partly"


def test_weyl_status(findings):
    rng = np.random.default_rng(5)
    M = rng.normal(size=(2000, 2, 2, 2))
    M = M + np.swapaxes(M, -1, -2)
    X, Y = M[:, 0], M[:, 1]
    lx, ly, ls = (np.linalg.eigvalsh(Z) for Z in (X, Y, X + Y))
    tol = 1e-12
    assert (ls[:, 0] >= lx[:, 0] + ly[:, 0] - tol).all()
    assert (ls[:, 1] <= lx[:, 1] + ly[:, 1] + tol).all()
    assert (ls[:, 0] <= np.minimum(lx[:, 0] + ly[:, 1], lx[:, 1] + ly[:, 0]) + tol).all()
    assert (ls[:, 1] >= np.maximum(lx[:, 0] + ly[:, 1], lx[:, 1] + ly[:, 0]) - tol).all()
    assert findings["thm1-weyl-step"].status == "reproduced"
    # printed range i + j - r <= r with r = 2 admits i = j = 1, index 0
    assert any(i + j - 2 < 1 for i in (1, 2) for j in (1, 2) if i + j - 2 <= 2)
    assert findings["thm1-proof-dual-weyl-range"].status == "partly"


def test_erratum_thm4_matrix_status(findings):
    o, pi, pj = np.zeros(2), np.array([1.0, 2.0]), np.array([3.0, 1.0])
    O = np.array([o - pi, o - pj])
    printed = np.array([
        [(o[0] - pi[0]) ** 2, (o[0] - pj[0]) * (o[1] - pi[1])],
        [(o[1] - pi[1]) * (o[0] - pj[0]), (o[1] - pj[1]) ** 2],
    ])
    assert not np.allclose(printed, O.T @ O)
    assert (printed != O.T @ O).all()
    assert findings["thm4-proof-matrix"].status == "refuted"


def test_erratum_thm5_dtheta_status(findings):
    h = 1e-7
    for a, q in ((0.5, 1.0), (2.0, 0.3)):
        right = (ob.pair_bound_polar(a, h, q) - ob.pair_bound_polar(a, 0.0, q)) / h
        left = (ob.pair_bound_polar(a, 0.0, q) - ob.pair_bound_polar(a, -h, q)) / h
        assert right > 0.1 and left < -0.1  # a corner: no zero derivative at theta = 0
        assert right == pytest.approx(a / np.sqrt((1 + a * a) * (1 + a * a + q * q)), rel=1e-5)
    assert findings["thm5-proof-dtheta"].status == "partly"


def test_erratum_thm5_dalpha_halfpi_status(findings):
    q, h = 1.0, 1e-6

    def d(a):
        up = ob.pair_bound_polar(a + h, np.pi / 2, q)
        down = ob.pair_bound_polar(a - h, np.pi / 2, q)
        return (up - down) / (2 * h)

    def printed(a):
        return a * (1 - a * a) / (1 + a * a + abs(1 - a * a) + 2 * q * q) ** 2.5

    for a in (0.2, 0.5, 0.9, 1.5, 3.0):
        assert abs(d(a)) > 0.01  # never zero
        assert abs(d(a) - printed(a)) > 0.01
    assert findings["thm5-proof-dalpha-halfpi"].status == "refuted"


def test_erratum_thm5_dalpha_status(findings):
    theta, q, h = 0.8, 1.0, 1e-6

    def d(a):
        up, down = ob.pair_bound_polar(a + h, theta, q), ob.pair_bound_polar(a - h, theta, q)
        return (up - down) / (2 * h)

    def printed(a):
        c = np.cos(2 * theta)
        S = np.sqrt(1 + a**4 + 2 * a * a * c)
        g = (1 - a * a) * (1 - c) + q * q * (S - (a * a + c))
        return a * g / (1 + a * a + S + 2 * q * q) ** 2.5

    ratios = [d(a) / printed(a) for a in (0.3, 0.7, 2.0)]
    assert max(ratios) / min(ratios) > 1.5  # not the derivative up to a constant
    slope0 = ob.pair_bound_polar(1e-8, theta, q) / 1e-8
    assert slope0 == pytest.approx(abs(np.sin(theta)) / np.sqrt(1 + q * q), rel=1e-6)  # not 0
    # but Eq. (34) (the numerator) vanishes at the true maximiser
    star = minimize_scalar(lambda x: -ob.pair_bound_polar(x, theta, q), bounds=(0, 20),
                           method="bounded", options={"xatol": 1e-12}).x
    assert abs(printed(star)) < 1e-7
    assert findings["thm5-proof-dalpha"].status == "partly"


def test_dalpha_minimum_status(findings):
    """The derivative of the bound in alpha, by central differences of the library's closed form
    of Eq. (9) (not obslib.pair_form.dbound_dalpha): largest at alpha = 0, smallest and
    negative at a finite alpha beyond the maximiser of the bound, and back near 0 at large
    alpha."""
    a = np.geomspace(1e-3, 1e3, 6001)
    h = 1e-7 * np.maximum(a, 1.0)
    for theta, q in ((0.3, 0.0), (1.0, 0.5), (2.2, 1.0), (0.7, 2.0)):
        d = (ob.pair_bound_polar(a + h, theta, q) - ob.pair_bound_polar(a - h, theta, q)) / (2 * h)
        k = int(np.argmin(d))
        assert 0 < k < a.size - 1 and d[k] < -1e-3
        assert d[k] < min(d[0], d[-1]) and abs(d[-1]) < 1e-5
        assert d[0] == pytest.approx(abs(np.sin(theta)) / np.sqrt(1 + q * q), rel=1e-3)
        assert d[0] >= d.max() - 1e-9  # largest at the left end
        star = minimize_scalar(lambda x: -ob.pair_bound_polar(x, theta, q), bounds=(0, 20),
                               method="bounded", options={"xatol": 1e-10}).x
        assert a[k] > star  # the bound falls fastest beyond its maximum
    rec = findings["thm5-proof-dalpha-min"]
    ev = rec.evidence
    assert ev["n_interior_minimum"] == ev["n_cases"] > 0
    assert rec.status == "refuted"
