"""Execute the book's notebooks with papermill.

``make book`` runs every notebook in place at its default parameters (the tagged
``parameters`` cell) and prints one line per notebook with its run time::

    python -m obslib.run --in-place

Reruns with other parameters never touch the committed notebooks; they write to
``_build/runs/<profile>/`` (or ``_build/runs/custom/`` with ``-p`` overrides)::

    python -m obslib.run --profile quick                # every notebook, quick profile
    python -m obslib.run --profile quick 01             # one notebook, by number or stem
    python -m obslib.run -p n_scenes 500 -p seed 3 01   # explicit overrides

After execution the runner strips what changes from run to run or machine to machine
(papermill's timestamps, the Python patch version), so that re-running an unchanged notebook
leaves ``git status`` clean.
"""

from __future__ import annotations

import argparse
import ast
import json
import os
import sys
import time
from pathlib import Path

__all__ = ["ROOT", "NOTEBOOK_DIR", "RUNS_DIR", "notebooks", "resolve", "execute", "main"]

ROOT = Path(__file__).resolve().parent.parent
NOTEBOOK_DIR = ROOT / "notebooks"
RUNS_DIR = ROOT / "_build" / "runs"
TIMES_FILE = ROOT / "_build" / "execution_times.json"
KERNEL = "python3"


def notebooks() -> list[Path]:
    """The book's notebooks, in paper order (by file name)."""
    return sorted(NOTEBOOK_DIR.glob("[0-9][0-9]_*.ipynb"))


def resolve(names) -> list[Path]:
    """Notebook paths from names: a number prefix (``01``), a stem, or a path."""
    if not names:
        return notebooks()
    found = []
    for name in names:
        p = Path(name)
        if p.suffix == ".ipynb" and p.exists():
            found.append(p.resolve())
            continue
        hits = [nb for nb in notebooks() if nb.stem == name or nb.stem.startswith(f"{name}_")]
        if len(hits) != 1:
            known = ", ".join(nb.stem for nb in notebooks())
            raise ValueError(f"no single notebook matches {name!r}; known: {known}")
        found.append(hits[0])
    return found


def _literal(text: str):
    """``-p`` values: Python literals (``3``, ``0.5``, ``[1, 2]``, ``'a'``) or a bare string."""
    try:
        return ast.literal_eval(text)
    except (ValueError, SyntaxError):
        return text


def _clean(path: Path) -> None:
    """Drop run-specific metadata so that identical results give identical files."""
    import nbformat

    nb = nbformat.read(path, as_version=4)
    nb.metadata.pop("papermill", None)
    nb.metadata.get("language_info", {}).pop("version", None)
    for cell in nb.cells:
        cell.metadata.pop("papermill", None)
        cell.metadata.pop("execution", None)
        tags = [t for t in cell.metadata.pop("tags", []) if t != "papermill-error-cell-tag"]
        if tags:
            cell.metadata["tags"] = tags
    nbformat.write(nb, path)


def execute(src: Path, dst: Path, parameters: dict | None = None) -> float:
    """Execute ``src`` into ``dst`` with papermill; return the wall time in seconds.

    ``parameters`` override the notebook's ``parameters`` cell; every name must exist there.
    """
    import papermill as pm

    parameters = dict(parameters or {})
    if parameters:
        declared = pm.inspect_notebook(str(src))
        unknown = sorted(set(parameters) - set(declared))
        if unknown:
            raise ValueError(
                f"{src.name} has no parameter(s) {unknown}; its parameters: {sorted(declared)}"
            )
    dst.parent.mkdir(parents=True, exist_ok=True)
    os.environ.setdefault("PYTHONHASHSEED", "0")
    t0 = time.perf_counter()
    pm.execute_notebook(
        str(src),
        str(dst),
        parameters=parameters,
        kernel_name=KERNEL,
        progress_bar=False,
        cwd=str(src.parent),
    )
    elapsed = time.perf_counter() - t0
    _clean(dst)
    return elapsed


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m obslib.run",
        description="Execute notebooks with papermill (see the module docstring).",
    )
    ap.add_argument("names", nargs="*", help="notebooks: number (01), stem or path; default all")
    ap.add_argument("--in-place", action="store_true", help="run at defaults over the committed notebooks")
    ap.add_argument("--profile", help="named parameter profile (obslib.profiles), e.g. quick")
    ap.add_argument("-p", nargs=2, action="append", metavar=("NAME", "VALUE"), default=[],
                    help="override one parameter (repeatable)")
    args = ap.parse_args(argv)

    from .profiles import PROFILES, params

    if args.in_place and (args.profile or args.p):
        ap.error("--in-place runs the defaults; reruns with --profile or -p go to _build/runs/")
    if args.profile and args.profile not in PROFILES:
        ap.error(f"unknown profile {args.profile!r}; known: {sorted(PROFILES)}")
    overrides = {name: _literal(value) for name, value in args.p}
    try:
        paths = resolve(args.names)
    except ValueError as exc:
        ap.error(str(exc))
    if not args.in_place and not args.profile and not overrides:
        ap.error("say --in-place (make book), --profile NAME or -p NAME VALUE")

    label = args.profile or "custom"
    if args.profile and overrides:
        label = f"{args.profile}-custom"
    times = {}
    for nb in paths:
        if args.in_place:
            dst, parameters = nb, {}
        else:
            dst = RUNS_DIR / label / nb.name
            parameters = {}
            if args.profile and nb.stem in PROFILES["paper"]:
                parameters = params(nb.stem, args.profile)
            parameters.update(overrides)
        try:
            dt = execute(nb, dst, parameters)
        except Exception as exc:  # papermill raises PapermillExecutionError with the traceback
            print(f"{nb.name:40s} FAILED", flush=True)
            print(exc, file=sys.stderr)
            return 1
        times[nb.name] = round(dt, 2)
        where = "" if args.in_place else f"  -> {dst.relative_to(ROOT)}"
        print(f"{nb.name:40s} {dt:7.1f} s{where}", flush=True)
    if args.in_place:
        TIMES_FILE.parent.mkdir(parents=True, exist_ok=True)
        old = json.loads(TIMES_FILE.read_text()) if TIMES_FILE.exists() else {}
        old.update(times)
        TIMES_FILE.write_text(json.dumps(old, indent=1, sort_keys=True) + "\n")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
