"""The code style, checked by ruff with the rules of ``pyproject.toml`` (``[tool.ruff]``)."""

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: What ruff checks: the library, the book's helpers, the tests, the Sphinx extensions and the
#: notebooks' code cells (ruff reads ``.ipynb`` files cell by cell).
CHECKED = ("obslib", "obsbook", "tests", "book/_ext", "notebooks")


def test_ruff_check_passes():
    ruff = Path(sys.executable).with_name("ruff")
    proc = subprocess.run([str(ruff), "check", "--no-cache", *CHECKED], cwd=ROOT,
                          capture_output=True, text=True)
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_the_notebooks_are_checked():
    # ruff lists the notebooks among the files it checks (none is excluded in pyproject.toml)
    ruff = Path(sys.executable).with_name("ruff")
    proc = subprocess.run([str(ruff), "check", "--no-cache", "--show-files", "notebooks"],
                          cwd=ROOT, capture_output=True, text=True)
    listed = {Path(line).name for line in proc.stdout.splitlines()}
    assert {p.name for p in (ROOT / "notebooks").glob("*.ipynb")} <= listed, proc.stdout
