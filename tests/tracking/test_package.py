"""The package obslib.tracking: its public names and the direction of its imports."""

from __future__ import annotations

import subprocess
import sys

from obslib import tracking as tr


def test_public_names_resolve():
    for name in tr.__all__:
        assert getattr(tr, name) is not None, name
    assert tr.STRATEGIES == ("best-pair", "best-partner", "fixed-pair")
    assert set(tr.CRITERIA) == {"d-optimal", "a-optimal", "e-optimal", "exact-icn", "random"}


def test_importing_tracking_pulls_in_neither_matplotlib_nor_the_studies():
    code = ("import sys, obslib.tracking; "
            "print(any(m == 'matplotlib' or m.startswith('obslib.studies') or "
            "m.startswith('obslib.viz') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"
