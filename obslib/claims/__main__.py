"""Command line: ``python -m obslib.claims [--profile P] [--id ID ...] [--write FILE | --json]``.

With ``--robustness`` it re-evaluates the claims with one parameter changed at a time
(:func:`obslib.studies.robustness.verdict_robustness`, from the profile ``quick`` unless
``--profile`` says otherwise) and prints the table, or stores the data with ``--write FILE.json``
(the report reads ``book/data/robustness.json``).
"""

from __future__ import annotations

import argparse
import json
import sys
from dataclasses import asdict
from pathlib import Path

from . import evaluate, registry, render_report
from ..profiles import profile_names
from ..studies import robustness as rb
from .report import ROBUSTNESS_FILE


def parse_args(argv=None) -> argparse.Namespace:
    """Parse and check the command line; bad ids, profiles and paths are argparse errors (exit 2).

    Examples
    --------
    >>> parse_args(["--id", "thm1"]).ids
    ['thm1']
    """
    ap = argparse.ArgumentParser(prog="python -m obslib.claims", description=__doc__)
    ap.add_argument("--profile", default=None, choices=profile_names(),
                    help="parameter profile (default: paper; quick with --robustness)")
    ap.add_argument("--id", action="append", dest="ids", help="only this claim (repeatable)")
    ap.add_argument("--write", type=Path, help="write the report page (MyST Markdown) here")
    ap.add_argument("--json", action="store_true", help="print the records as JSON")
    ap.add_argument("--robustness", action="store_true",
                    help="vary u_max, noise, metric and sizes one at a time for the claims that "
                    "are partly or refuted and the tracking claims; --write stores JSON")
    args = ap.parse_args(argv)
    if args.profile is None:
        args.profile = "quick" if args.robustness else "paper"
    if args.ids:
        known = list(registry())
        unknown = [i for i in args.ids if i not in known]
        if unknown:
            ap.error(f"unknown claim id(s) {unknown}; known: {', '.join(known)}")
    if args.write is not None:
        if args.write.is_dir():
            ap.error(f"--write {args.write}: is a directory, give a file name")
        parent = args.write.parent
        if not parent.is_dir():
            ap.error(f"--write {args.write}: directory {parent} does not exist")
    if args.write is not None and args.json:
        ap.error("give --write or --json, not both")
    if args.robustness and args.write is not None and args.write.suffix != ".json":
        ap.error(f"--robustness --write {args.write}: the data file must end in .json")
    return args


def main(argv=None) -> int:
    """Command line entry point: re-check the claims and print or write them; returns 0.

    Examples
    --------
    >>> main(["--id", "thm1"])  # doctest: +SKIP
    """
    args = parse_args(argv)
    if args.robustness:
        rows = rb.verdict_robustness(args.ids, base=args.profile)
        if args.write:
            rb.write_json(rows, args.write, base=args.profile)
            print(f"{args.write}: {len(rows)} claims")
        elif args.json:
            json.dump(rows, sys.stdout, indent=1)
            print()
        else:
            print(rb.robustness_table(rows), end="")
        return 0
    records = evaluate(args.profile, args.ids)
    if args.write:
        robustness = rb.read_json(ROBUSTNESS_FILE) if ROBUSTNESS_FILE.exists() else None
        text = render_report(records, args.profile, robustness=robustness)
        if not args.write.exists() or args.write.read_text() != text:
            args.write.write_text(text)
        print(f"{args.write}: {len(records)} claims")
    elif args.json:
        json.dump([asdict(r) for r in records], sys.stdout, indent=1, default=float)
        print()
    else:
        for r in records:
            print(f"{r.id:24s} {r.status:11s} {r.ours}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
