"""Named parameter sets for the notebooks and the claims ledger.

``paper`` holds each notebook's defaults: the paper's parameters (``../shared/EXPERIMENTS.md``)
and, for audits the paper does not have, our chosen sizes. It must equal the notebook's tagged
``parameters`` cell (a test checks this). ``quick`` shrinks the sizes for fast previews and for
the ledger in tests. A profile lists only the parameters it changes; the rest are the defaults.
"""

from __future__ import annotations

import copy

__all__ = ["PROFILES", "params", "profile_names"]

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
            "anim_dpi": 50,
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
        "04_submodularity": {"n_instances": 200, "n_sensors": 5},
        "05_two_sensors_tracking": {"n_seeds": 20, "anim_every": 15},
        "06_adversarial_target": {"n_seeds": 10, "n_seeds_strong": 2, "n_radii": 3, "n_angles": 36},
        "07_greedy_vs_relaxed": {"trials": 5, "optimum_max_L": 4, "L_extended": [50], "trials_extended": 1},
        "08_general_assignment": {"trials": 5, "compare_trials": 3, "n_tiny": 50},
        "09_scaling": {
            "greedy_sizes": [20, 100, 400],
            "literal_sizes": [20, 50],
            "relaxed_sizes": [20, 100],
        },
    },
}


def profile_names() -> list[str]:
    """Names of the known profiles."""
    return list(PROFILES)


def params(notebook: str, profile: str = "paper") -> dict:
    """Parameters of ``notebook`` (its stem, e.g. ``"01_model_and_bound"``) under ``profile``.

    The ``paper`` values updated by the profile's overrides.
    """
    if profile not in PROFILES:
        raise ValueError(f"unknown profile {profile!r}; known: {profile_names()}")
    if notebook not in PROFILES["paper"]:
        raise ValueError(f"no parameters for notebook {notebook!r}; known: {list(PROFILES['paper'])}")
    out = copy.deepcopy(PROFILES["paper"][notebook])
    out.update(PROFILES[profile].get(notebook, {}))
    return out
