"""Named parameter sets for the notebooks and the claims ledger.

``paper`` holds each notebook's defaults: the paper's parameters (Sec. V)
and, for audits the paper does not have, our chosen sizes. It must equal the notebook's tagged
``parameters`` cell (a test checks this). ``quick`` shrinks the sizes for fast previews and for
the ledger in tests. A profile lists only the parameters it changes; the rest are the defaults.
"""

from __future__ import annotations

import copy

__all__ = ["PROFILES", "RANGES", "params", "profile_names", "check_parameters"]

PROFILES: dict[str, dict[str, dict]] = {
    "paper": {
        "01_model_and_bound": {
            "seed": 0,
            "n_scenes": 2000,
            "n_controls": 64,
            "n_trials_thm3": 20000,
            "u_max": 1.0,
            "n_radii": 40,
            "n_angles": 180,
        },
        "02_pair_closed_form": {
            "seed": 0,
            "u_max": 1.0,
            "d_io": 1.0,
            "alpha_max": 5.0,
            "paper_step": 0.1,
            "fine_alpha_per_unit": 100,
            "fine_theta_quarter": 180,
            "contour_levels": [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7],
            "u_over_d_curves": [0.25, 0.5, 1.0, 2.0],
            "n_theta_curve": 179,
            "n_rational_points": 200,
            "digits": 50,
            "n_random_points": 2000,
            "n_weyl": 20000,
        },
        "03_greedy_unique_pairs": {
            "seed": 0,
            "n_instances": 2000,
            "targets_min": 2,
            "targets_max": 4,
            "extra_max": 2,
            "u_max": 1.0,
            "search_sensors": 6,
            "search_targets": 3,
            "n_starts": 20,
            "n_steps": 300,
        },
        "04_submodularity": {
            "seed": 0,
            "u_max": 1.0,
            "n_instances": 2000,
            "n_sensors": 6,
            "eps": 1.0,
            "min_size": 2,
            "n_tiny": 500,
        },
        "05_two_sensors_tracking": {
            "seed": 0,
            "n_seeds": 200,
            "steps": 315,
            "u_max": 3.0,
            "noise_std": 0.5,
            "q": 0.5,
            "r": 0.5,
            "p0": 0.5,
            "metric": "mahalanobis",
            "anim_every": 8,
            "anim_dpi": 100,
        },
        "06_adversarial_target": {
            "seed": 0,
            "n_seeds": 50,
            "steps": 315,
            "u_max": 0.1,
            "noise_std": 0.5,
            "n_seeds_strong": 10,
            "n_radii": 10,
            "n_angles": 180,
        },
        "07_greedy_vs_relaxed": {
            "seed": 0,
            "L_max": 20,
            "trials": 30,
            "u_max": 1.0,
            "side": 100.0,
            "optimum_max_L": 6,
            "L_extended": [50, 100, 150, 200],
            "trials_extended": 3,
        },
        "08_general_assignment": {
            "seed": 0,
            "n_targets": 5,
            "N_min": 20,
            "N_max": 50,
            "trials": 30,
            "eps": 1.0,
            "side": 100.0,
            "eps_values": [1e-06, 1.0, 10000.0],
            "compare_N": [20, 35, 50],
            "compare_trials": 30,
            "n_tiny": 500,
        },
        "09_scaling": {
            "times_file": "../book/data/scaling_times.json",
            "seed": 0,
            "greedy_sizes": [20, 50, 100, 200, 400, 800],
            "literal_sizes": [20, 50, 100, 200],
            "relaxed_sizes": [20, 50, 100, 200, 400],
        },
        "10_criteria": {
            "seed": 0,
            "n_seeds": 200,
            "metrics": ["mahalanobis", "euclidean"],
            "loss_threshold": 0.5,
            "times_file": "../book/data/criteria_times.json",
            "assign_targets": [2, 5],
            "assign_seeds": 200,
            "assign_steps": 50,
            "assign_side": 100.0,
            "assign_u_max": 1.0,
            "assign_noise_std": 0.5,
            "assign_p0": 1.0,
            "assign_loss": 0.5,
        },
        "11_unchecked_statements": {
            "seed": 0,
            "n_seeds_typical": 1000,
            "jitter_fractions": [1e-06, 1e-05, 0.0001, 0.001, 0.01, 0.1],
            "n_jitter": 200,
            "n_geometries": 2000,
            "n_refine": 200,
            "u_max": 1.0,
            "n_3dm": 40,
            "solver_L": [5, 10, 15, 20],
            "time_budget": 60.0,
            "problem3_L": [2, 5, 10, 20],
            "problem3_trials": 30,
            "n_seeds_disc": 100,
            "n_radii": 10,
            "n_angles": 180,
        },
    },
    "quick": {
        "01_model_and_bound": {
            "n_scenes": 200,
            "n_trials_thm3": 2000,
            "n_radii": 10,
            "n_angles": 60,
        },
        "02_pair_closed_form": {
            "fine_alpha_per_unit": 20,
            "fine_theta_quarter": 30,
            "n_theta_curve": 35,
            "n_rational_points": 20,
            "n_random_points": 200,
            "n_weyl": 2000,
        },
        "03_greedy_unique_pairs": {"n_instances": 300, "n_starts": 4, "n_steps": 100},
        "04_submodularity": {"n_instances": 200, "n_sensors": 5, "n_tiny": 50},
        "05_two_sensors_tracking": {"n_seeds": 20, "anim_every": 15},
        "06_adversarial_target": {"n_seeds": 10, "n_seeds_strong": 2, "n_radii": 3, "n_angles": 36},
        "07_greedy_vs_relaxed": {"trials": 5, "optimum_max_L": 4, "L_extended": [50], "trials_extended": 1},
        "08_general_assignment": {"trials": 5, "compare_trials": 3, "n_tiny": 50},
        "09_scaling": {
            "greedy_sizes": [20, 100, 400],
            "literal_sizes": [20, 50],
            "relaxed_sizes": [20, 100],
        },
        "10_criteria": {"n_seeds": 20, "assign_targets": [2, 3], "assign_seeds": 20,
                        "assign_steps": 20},
        "11_unchecked_statements": {
            "n_seeds_typical": 100, "n_jitter": 20, "n_geometries": 200, "n_refine": 40, "n_3dm": 10,
            "solver_L": [3, 6], "time_budget": 2.0, "problem3_L": [2, 5], "problem3_trials": 5,
            "n_seeds_disc": 10, "n_radii": 3, "n_angles": 36,
        },
    },
}


def profile_names() -> list[str]:
    """Names of the known profiles.

    Examples
    --------
    >>> profile_names()
    ['paper', 'quick']
    """
    return list(PROFILES)


def params(notebook: str, profile: str = "paper") -> dict:
    """Parameters of ``notebook`` (its stem, e.g. ``"01_model_and_bound"``) under ``profile``.

    The ``paper`` values updated by the profile's overrides.

    Examples
    --------
    >>> params("05_two_sensors_tracking", "quick")["n_seeds"]
    20
    """
    if profile not in PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    if notebook not in PROFILES["paper"]:
        raise ValueError(f"no parameters for notebook {notebook!r}; known: {list(PROFILES['paper'])}")
    out = copy.deepcopy(PROFILES["paper"][notebook])
    out.update(PROFILES[profile].get(notebook, {}))
    return out


# --------------------------------------------------------------------------------------------
# Accepted values of the notebooks' parameters
# --------------------------------------------------------------------------------------------

#: Range of each parameter beyond its type (the type is that of the notebook's default):
#: ``(lower, upper, lower_open)`` for numbers and for the entries of lists, a tuple of choices
#: for strings. Parameters not listed accept any value of their type.
RANGES: dict[str, tuple] = {
    "seed": (0, None, False),
    **{name: (1, None, False) for name in (
        "n_scenes", "n_controls", "n_trials_thm3", "n_radii", "n_angles", "fine_alpha_per_unit",
        "fine_theta_quarter", "n_theta_curve", "n_rational_points", "digits", "n_random_points",
        "n_weyl", "n_instances", "targets_min", "targets_max", "search_sensors", "search_targets",
        "n_starts", "n_steps", "n_sensors", "n_seeds", "steps", "anim_every", "anim_dpi",
        "n_seeds_strong", "L_max", "trials", "optimum_max_L", "trials_extended", "n_targets",
        "N_min", "N_max", "compare_trials", "n_tiny", "L_extended", "compare_N", "greedy_sizes",
        "literal_sizes", "relaxed_sizes", "assign_targets", "assign_seeds",
        "assign_steps", "n_seeds_typical", "n_jitter", "n_geometries", "n_refine", "n_3dm", "solver_L",
        "problem3_L", "problem3_trials", "n_seeds_disc")},
    "extra_max": (0, None, False),
    "min_size": (0, None, False),
    "u_max": (0.0, None, False),
    "noise_std": (0.0, None, False),
    "u_over_d_curves": (0.0, None, False),
    **{name: (0.0, None, True) for name in (
        "d_io", "alpha_max", "paper_step", "q", "r", "p0", "side", "eps", "eps_values", "loss_threshold",
        "assign_side", "assign_p0", "assign_loss", "time_budget", "jitter_fractions")},
    "assign_u_max": (0.0, None, False),
    "assign_noise_std": (0.0, None, False),
    "contour_levels": (0.0, 1.0, True),
    "metric": ("mahalanobis", "euclidean"),
    "metrics": ("mahalanobis", "euclidean"),
}

#: Pairs of parameters whose values must be ordered (first <= second).
ORDERED = (("targets_min", "targets_max"), ("N_min", "N_max"))


def _describe(kind: type, rule) -> str:
    noun = {int: "an integer", float: "a number", str: "a string", bool: "True or False"}[kind]
    if rule is None:
        return noun
    if kind is str:
        return "one of " + ", ".join(repr(c) for c in rule)
    lo, hi, lo_open = rule
    if hi is None:
        return f"{noun} {'>' if lo_open else '>='} {lo}"
    return f"{noun} in {'(' if lo_open else '['}{lo}, {hi}]"


def _accepts(kind: type, rule, value):
    """``value`` converted to ``kind`` if it is accepted, else ``None``."""
    import math

    if kind is bool:
        return value if isinstance(value, bool) else None
    if isinstance(value, bool):
        return None
    if kind is int:
        if not isinstance(value, int):
            return None
    elif kind is float:
        if not isinstance(value, (int, float)) or not math.isfinite(value):
            return None
        value = float(value)
    elif kind is str:
        if not isinstance(value, str) or not value:
            return None
        if rule is not None and value not in rule:
            return None
        return value
    if rule is not None:
        lo, hi, lo_open = rule
        if value < lo or (lo_open and value == lo) or (hi is not None and value > hi):
            return None
    return value


def check_parameters(notebook: str, values: dict, defaults: dict) -> dict:
    """Check parameter ``values`` for ``notebook`` against its declared ``defaults``.

    Parameters
    ----------
    notebook : str
        The notebook's stem, for the messages.
    values : dict
        Parameter name -> value to inject.
    defaults : dict
        The notebook's declared parameters (its ``parameters`` cell) with their default values;
        each value's type must be that of its default (an integer where the default is an
        integer, a number where it is a float, a list of such where it is a list), within
        :data:`RANGES`.

    Returns
    -------
    dict
        The values, numbers converted to the default's type (``3`` -> ``3.0`` for a float).

    Raises
    ------
    ValueError
        Naming the notebook, the parameter and the accepted values.

    Examples
    --------
    >>> nb = "05_two_sensors_tracking"
    >>> check_parameters(nb, {"n_seeds": 5}, {"n_seeds": 200})
    {'n_seeds': 5}
    >>> check_parameters(nb, {"n_seeds": -5}, {"n_seeds": 200})
    Traceback (most recent call last):
    ...
    ValueError: ...n_seeds = -5 is not accepted; expected an integer >= 1
    """
    unknown = sorted(set(values) - set(defaults))
    if unknown:
        raise ValueError(f"notebook {notebook} has no parameter(s) {unknown}; "
                         f"its parameters: {sorted(defaults)}")
    out = {}
    for name, value in values.items():
        default = defaults[name]
        rule = RANGES.get(name)
        if isinstance(default, list):
            kinds = {type(x) for x in default}
            kind = float if float in kinds else (kinds.pop() if len(kinds) == 1 else float)
            ok = isinstance(value, list) and value and all(
                _accepts(kind, rule, x) is not None for x in value)
            if not ok:
                raise ValueError(f"notebook {notebook}: parameter {name} = {value!r} is not accepted; "
                                 f"expected a non-empty list of {_describe(kind, rule)[0:]}"
                                 .replace("list of an ", "list of ").replace("list of a ", "list of "))
            out[name] = [_accepts(kind, rule, x) for x in value]
            continue
        kind = type(default)
        got = _accepts(kind, rule, value)
        if got is None:
            raise ValueError(f"notebook {notebook}: parameter {name} = {value!r} is not accepted; "
                             f"expected {_describe(kind, rule)}")
        out[name] = got
    merged = {**defaults, **out}
    for a, b in ORDERED:
        if a in merged and b in merged and merged[a] > merged[b]:
            raise ValueError(f"notebook {notebook}: parameters {a} = {merged[a]!r} and {b} = "
                             f"{merged[b]!r} are not accepted; expected {a} <= {b}")
    return out
