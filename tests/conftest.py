"""Shared test configuration: Hypothesis runs derandomized so every run checks the same cases;
the ledger at the paper's sizes is evaluated once per test run."""

import os
import pickle

import pytest
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


@pytest.fixture(scope="session")
def paper_ledger(tmp_path_factory) -> dict:
    """The ledger at the paper's sizes, with the robustness study's caveats, as the report
    states it: ``{id: record}`` in ledger order (about 80 s on a quiet two-core machine).

    Computed once per test run: under pytest-xdist the first worker to ask evaluates it and
    the others read it from the run's shared temporary folder.
    """
    from obslib._io import locked
    from obslib.claims import evaluate, robustness

    def ledger():
        return {r.id: r for r in evaluate("paper", caveats=robustness.caveats())}

    if not os.environ.get("PYTEST_XDIST_WORKER"):
        return ledger()
    shared = tmp_path_factory.getbasetemp().parent / "paper_ledger.pickle"
    with locked(shared.with_suffix(".lock")):
        if shared.exists():
            return pickle.loads(shared.read_bytes())
        records = ledger()
        shared.write_bytes(pickle.dumps(records))
        return records
