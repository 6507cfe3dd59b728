"""Every notebook runs to the end at the boundary values of each of its declared ranges.

The runs are slow (178 notebook runs at the quick sizes, 10 to 12 minutes on two cores), so
they are marked ``boundaries``: ``make test`` leaves them out (it checks only that the cases
are accepted) and ``.ci/run`` runs them as a separate step::

    .venv/bin/python -m pytest -m boundaries tests/tools/test_boundaries.py

Each case is the ``quick`` profile with one parameter at one end of its range (for a list, a
one-entry list; for a choice, each option); when that breaks a constraint of the notebook, the
other parameters of the constraint are moved to values that satisfy it (the same value, or an end
of their own range).
"""

from __future__ import annotations

import itertools
from concurrent.futures import ThreadPoolExecutor

import pytest

from obslib import profiles as pr
from obslib.tools import run


def _ends(rule, default) -> list:
    if isinstance(rule, pr.Choice):
        values = list(rule.options)
    elif isinstance(rule, pr.Range):
        values = [v for v in (rule.lo, rule.hi) if v is not None]
        kind = type(default[0]) if isinstance(default, list) else type(default)
        values = [kind(v) if kind in (int, float) else v for v in values]
    else:
        return []
    return [[v] for v in values] if isinstance(default, list) else values


def _valid(notebook: str, values: dict, declared: dict) -> bool:
    try:
        pr.validated_parameters(notebook, values, declared)
    except ValueError:
        return False
    return True


def _fixed(notebook: str, case: dict, name: str, declared: dict) -> dict | None:
    """``case`` with other names of the constraints linked to ``name`` moved so that it is
    accepted, changing as few as it can (their current values are tried first)."""
    if _valid(notebook, case, declared):
        return case
    merged = {**declared, **case}
    linked, grew = {name}, True
    while grew:  # names joined to ``name`` through chains of constraints
        grew = False
        for c in pr.CONSTRAINTS.get(notebook, ()):
            if linked & set(c.names()) and not set(c.names()) <= linked:
                linked |= set(c.names())
                grew = True
    others = sorted(linked - {name})
    options = []
    for n in others:
        cands = [merged[n], case[name]] + _ends(pr.RANGES[notebook].get(n), declared[n])
        options.append([v for v in cands if type(v) is type(declared[n])])
    for combo in sorted(itertools.product(*options),
                        key=lambda combo: sum(v != merged[n] for n, v in zip(others, combo))):
        trial = {**case, **{n: v for n, v in zip(others, combo) if v != merged[n]}}
        if _valid(notebook, trial, declared):
            return trial
    return None


def boundary_cases(notebook: str) -> list[dict]:
    """Parameter sets (quick profile plus boundary values) covering every end of every range."""
    declared = pr.defaults(notebook)
    quick = pr.params(notebook, "quick")
    base = {k: v for k, v in quick.items() if k in pr.PROFILES["quick"].get(notebook, {})}
    cases, seen = [], set()
    for name, rule in pr.RANGES[notebook].items():
        for value in _ends(rule, declared[name]):
            case = _fixed(notebook, {**base, name: value}, name, declared)
            assert case is not None, f"{notebook}: no accepted case with {name} = {value!r}"
            key = repr(sorted(case.items()))
            if key not in seen:
                seen.add(key)
                cases.append(case)
    return cases


def test_boundary_cases_cover_every_end_and_are_accepted():
    for nb in pr.RANGES:
        declared = pr.defaults(nb)
        cases = boundary_cases(nb)
        for name, rule in pr.RANGES[nb].items():
            for value in _ends(rule, declared[name]):
                assert any(c.get(name) == value for c in cases), (nb, name, value)
        for c in cases:
            pr.validated_parameters(nb, c, declared)


@pytest.mark.boundaries
@pytest.mark.parametrize("notebook", list(pr.RANGES))
def test_notebook_runs_at_every_boundary(notebook, tmp_path):
    src = run.NOTEBOOK_DIR / f"{notebook}.ipynb"
    cases = boundary_cases(notebook)
    run.precompile()

    def one(k_case):
        k, case = k_case
        try:
            run.execute(src, tmp_path / f"{k}.ipynb", case)
        except Exception as exc:  # papermill's error holds the cell's traceback
            text = str(exc).strip().splitlines()
            return f"{case}: {text[-1] if text else type(exc).__name__}"
        return None

    with ThreadPoolExecutor(max_workers=run.default_jobs()) as pool:
        failures = [f for f in pool.map(one, enumerate(cases)) if f]
    assert not failures, f"{len(failures)} of {len(cases)} cases fail:\n" + "\n".join(failures)
