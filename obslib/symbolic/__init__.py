r"""SymPy derivations for the two-sensor closed form (Theorem 4) and its extremes (Theorem 5).

The paper states the pair bound in polar form (Theorem 4, Eq. (9)):

.. math::

   C^{-1}(O_{ij}(o, u_o)) = \sqrt{\frac{1 + \alpha^2 - S}{1 + \alpha^2 + S + 2 u^2 / d_{io}^2}},

   S = \sqrt{1 + \alpha^4 + 2 \alpha^2 \cos 2\theta_{ji}}, \qquad \alpha = d_{jo} / d_{io},

and proves it (appendix, proof of Theorem 4) from :math:`O_{ij}(o)^T O_{ij}(o)` written in
Cartesian coordinates (Eq. (32)) and in the polar coordinates of Eq. (8). Theorem 5 locates its
extremes from derivatives printed in its proof. This package rebuilds every one of those objects
with SymPy, so that the notebook on the pair's closed form and the tests can compare the paper's
printed expressions with the derived ones. Its modules follow the paper:

* :mod:`obslib.symbolic.gram`: the matrix :math:`O_{ij}^T O_{ij}` in Cartesian and polar form
  and its eigenvalues (roots of the characteristic polynomial), next to the appendix's printed
  versions (``printed_*``); :func:`pythagorean_remainder` decides trigonometric polynomial
  identities exactly (remainder modulo :math:`\cos^2 + \sin^2 = 1`).
* :mod:`obslib.symbolic.theorem4`: Eq. (9) in :math:`\alpha`, :math:`\theta` and :math:`q =
  u_{\max} / d_{io}` (:func:`theorem4_bound`), the reduction of the eigenvalue ratio to it
  (:func:`polar_ratio`), the residuals against the paper (:func:`theorem4_residuals`), and
  :func:`vanishes_with_radicals`, which proves an expression with nested square roots
  identically zero by polynomial remainders.
* :mod:`obslib.symbolic.theorem5`: the derivatives :func:`dbound_dtheta`,
  :func:`dbound_dalpha`, their factored forms, the stationarity condition Eq. (34), the paper's
  printed derivatives (``printed_*``) and the maximising :math:`\alpha` for a fixed
  :math:`\theta` in closed form (:func:`alpha_star_squared`, not in the paper).
* :mod:`obslib.symbolic.theorem1`: the Weyl inequalities of the proof of Theorem 1 for 2x2
  symmetric matrices, each next to an equivalent triangle inequality.
* :mod:`obslib.symbolic.evaluation`: :func:`lambdify_expr` turns an expression into a NumPy (or
  mpmath) function, :func:`latex_eq` displays one.

All expressions are built on the package's symbols (:data:`OX`, ..., :data:`Q`) and cached.
Identities are established by polynomial arithmetic (``expand``, ``cancel``, ``sympy.Poly``
remainders), not by the heuristic ``sympy.simplify``: an expansion that returns 0 is a proof.

Examples
--------
>>> from obslib.symbolic import (closed_forms_hold, max_value_exact,
...                              theorem4_residuals)
>>> (theorem4_residuals()["ratio"], max_value_exact(),
...  closed_forms_hold()["dalpha"])
(0, 0, True)
"""

from ._common import (
    ALPHA,
    C_SYM,
    CARTESIAN_ARGS,
    D_IO,
    D_JO,
    D_SYM,
    OX,
    OY,
    PIX,
    PIY,
    PJX,
    PJY,
    POLAR_ARGS,
    RATIO_ARGS,
    S_SYM,
    THETA,
    THETA_I,
    THETA_J,
    Q,
    U,
)  # fmt: skip
from .evaluation import lambdify_expr, latex_eq
from .gram import (
    cartesian_eigenvalues,
    cartesian_gram,
    discriminant_cartesian,
    eigenvalues,
    polar_eigenvalues,
    polar_gram,
    polar_substitution,
    printed_cartesian_gram,
    printed_eigenvalues,
    printed_polar_gram,
    pythagorean_remainder,
    relative_rows,
)  # fmt: skip
from .theorem1 import weyl_2x2_slacks
from .theorem4 import (
    bound_from_eigenvalues,
    cartesian_ratio_values,
    polar_ratio,
    pull_out_of_roots,
    ratio_substitution,
    theorem4_bound,
    theorem4_radicand,
    theorem4_residuals,
    vanishes_with_radicals,
)  # fmt: skip
from .theorem5 import (
    alpha_star_closed,
    alpha_star_squared,
    bound_halfpi_piecewise,
    closed_forms_hold,
    dbound_dalpha,
    dbound_dalpha_closed,
    dbound_dtheta,
    dbound_dtheta_at_zero,
    dbound_dtheta_closed,
    max_value_exact,
    printed_dbound_dalpha,
    printed_dbound_dalpha_halfpi,
    printed_max_halfpi,
    printed_stationarity_alpha,
    stationarity_alpha,
    stationarity_alpha_at_1,
)  # fmt: skip

__all__ = [
    "OX", "OY", "PIX", "PIY", "PJX", "PJY", "U", "D_IO", "D_JO", "THETA_I", "THETA_J",
    "ALPHA", "THETA", "Q", "S_SYM", "C_SYM", "D_SYM", "CARTESIAN_ARGS", "POLAR_ARGS", "RATIO_ARGS",
    "relative_rows", "cartesian_gram", "printed_cartesian_gram", "polar_substitution",
    "polar_gram", "printed_polar_gram", "eigenvalues", "cartesian_eigenvalues", "polar_eigenvalues",
    "printed_eigenvalues", "pythagorean_remainder", "polar_ratio", "vanishes_with_radicals",
    "pull_out_of_roots", "stationarity_alpha_at_1", "max_value_exact", "theorem4_residuals",
    "closed_forms_hold",
    "bound_from_eigenvalues", "ratio_substitution", "cartesian_ratio_values",
    "discriminant_cartesian", "theorem4_bound", "theorem4_radicand", "dbound_dtheta",
    "dbound_dtheta_closed", "dbound_dtheta_at_zero", "dbound_dalpha", "dbound_dalpha_closed",
    "stationarity_alpha",
    "printed_stationarity_alpha", "printed_dbound_dalpha", "printed_dbound_dalpha_halfpi",
    "printed_max_halfpi", "bound_halfpi_piecewise", "alpha_star_squared", "alpha_star_closed",
    "weyl_2x2_slacks", "lambdify_expr", "latex_eq",
]  # fmt: skip
