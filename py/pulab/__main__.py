"""Command line: ``python -m pulab report INPUT.json [--format json|text]``, ``sweep``, ``batch``.

Bad input: exit status 2 and one line ``error: FIELD: MESSAGE`` on stderr.
"""

from __future__ import annotations

import argparse
import json
import sys

from .errors import InputError
from .commands import add_family_commands, read_json
from .report import format_text, report


def main(argv: list | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m pulab",
                                description="Per-unit and Q-format report for a PMSM drive.")
    sub = p.add_subparsers(dest="command", required=True)
    rp = sub.add_parser("report", help="print the report for an input JSON file ('-' = stdin)")
    rp.add_argument("input")
    rp.add_argument("--format", choices=("json", "text"), default="json")
    add_family_commands(sub)
    args = p.parse_args(argv)
    if hasattr(args, "run"):
        return args.run(args)
    try:
        r = report(read_json(args.input))
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    if args.format == "text":
        sys.stdout.write(format_text(r))
    else:
        json.dump(r, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
        sys.stdout.write("\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
