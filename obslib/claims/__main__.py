"""Command line: ``python -m obslib.claims [--profile P] [--id ID ...] [--json] [--write FILE]``.

Prints one line per entry of the ledger (id, kind, status, its one sentence), or with
``--json`` every field of every entry. ``--write FILE`` stores the JSON there instead of printing
it. At the paper's parameters every record carries the caveat of the stored robustness study.

With ``--robustness`` it re-evaluates the claims of the paper with one parameter changed at a
time (:func:`obslib.claims.robustness.verdict_robustness`, from the paper's parameters unless
``--profile`` says otherwise) and prints the table, or stores the data with ``--write FILE.json``
(the report and the chapters read ``obslib/data/robustness.json``; about ten minutes on two
cores).
"""

from __future__ import annotations

import argparse
import json
import sys

from .._io import OutputPathError, as_output_path, command, write_or_report
from .._validate import as_argv
from ..profiles import profile_names
from . import as_json, evaluate, registry, robustness

PROG = "python -m obslib.claims"


def parse_args(argv=None) -> argparse.Namespace:
    """Parse and check the command line; bad ids, profiles and paths are argparse errors (exit 2).

    Examples
    --------
    >>> parse_args(["--id", "thm1"]).ids
    ['thm1']
    """
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--profile", default=None, choices=profile_names(),
                    help="parameter profile (default: paper)")
    ap.add_argument("--id", action="append", dest="ids", help="only this entry (repeatable)")
    ap.add_argument("--json", action="store_true", help="print every field as JSON")
    ap.add_argument("--write", help="store the JSON (or with --robustness the data) in this file")
    ap.add_argument("--robustness", action="store_true",
                    help="vary u_max, noise, metric and sizes one at a time for the claims that "
                    "are partly or refuted and the tracking claims")
    args = ap.parse_args(as_argv(argv))
    if args.profile is None:
        args.profile = "paper"
    if args.ids:
        known = list(registry())
        unknown = [i for i in args.ids if i not in known]
        if unknown:
            ap.error(f"unknown claim id(s) {unknown}; known: {', '.join(known)}")
    if args.write is not None:
        try:
            args.write = as_output_path(args.write)
        except OutputPathError as exc:
            ap.error(f"--write {exc}")
        if args.write.suffix != ".json":
            ap.error(f"--write {args.write}: the data file must end in .json")
    return args


@command(PROG)
def main(argv=None) -> int:
    """Command line entry point: re-check the entries and print or store them; returns the exit
    status (1 if the file of ``--write`` cannot be written, after a one-line error).

    Examples
    --------
    >>> main(["--id", "thm1"])  # doctest: +SKIP
    """
    args = parse_args(argv)
    if args.robustness:
        rows = robustness.verdict_robustness(args.ids, base=args.profile)
        if args.write:
            if not write_or_report(PROG, args.write, robustness.to_json(rows, args.profile)):
                return 1
            print(f"{args.write}: {len(rows)} claims")
        elif args.json:
            print(robustness.to_json(rows, args.profile), end="")
        else:
            print(robustness.robustness_table(rows), end="")
        return 0
    caveats = robustness.caveats() if args.profile == "paper" else {}
    records = evaluate(args.profile, args.ids, caveats=caveats)
    if args.write or args.json:
        text = json.dumps(as_json(records), indent=1, default=float) + "\n"
        if args.write:
            if not write_or_report(PROG, args.write, text):
                return 1
            print(f"{args.write}: {len(records)} entries")
        else:
            sys.stdout.write(text)
    else:
        for r in records:
            said = r.summary + (f" {r.caveat}" if r.caveat else "")
            print(f"{r.id:28s} {r.kind:6s} {r.status:11s} {said}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
