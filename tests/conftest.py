"""Shared test configuration: Hypothesis runs derandomized so every run checks the same cases."""

import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "obslib",
    derandomize=True,
    deadline=None,
    database=None,
    max_examples=200,
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("thorough", parent=settings.get_profile("obslib"), max_examples=5000)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "obslib"))
