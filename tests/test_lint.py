"""The code style, checked by ruff with the rules of ``pyproject.toml`` (``[tool.ruff]``)."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: What ruff checks: the library, the book's helpers, the tests and the Sphinx extensions.
CHECKED = ("obslib", "obsbook", "tests", "book/_ext")


def test_ruff_check_passes():
    ruff = Path(sys.executable).with_name("ruff")
    proc = subprocess.run([str(ruff), "check", "--no-cache", *CHECKED], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr
