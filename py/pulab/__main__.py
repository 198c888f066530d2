"""Command line: ``python -m pulab report INPUT.json [--format json|text]``.

Bad input: exit status 2 and one line ``error: FIELD: MESSAGE`` on stderr.
"""

from __future__ import annotations

import argparse
import json
import sys

from .errors import InputError
from .jsontext import parse
from .report import format_text, report


def main(argv: list | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m pulab",
                                description="Per-unit and Q-format report for a PMSM drive.")
    sub = p.add_subparsers(dest="command", required=True)
    rp = sub.add_parser("report", help="print the report for an input JSON file ('-' = stdin)")
    rp.add_argument("input")
    rp.add_argument("--format", choices=("json", "text"), default="json")
    args = p.parse_args(argv)
    try:
        if args.input == "-":
            data = sys.stdin.buffer.read()
        else:
            with open(args.input, "rb") as f:
                data = f.read()
    except OSError as e:
        print(f"error: input: cannot read {args.input!a}: {e.strerror}", file=sys.stderr)
        return 2
    try:
        r = report(parse(data.decode("utf-8")))
    except UnicodeDecodeError as e:
        print(f"error: input: not UTF-8 text (byte {e.start})", file=sys.stderr)
        return 2
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
