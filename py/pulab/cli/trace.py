"""``python -m pulab trace FILE.c --target c28x --set NAME=VALUE … [--global-q N]``.

Prints the :func:`~pulab.ctrace.trace` JSON on stdout; bad code or input exits
with status 2 and one line on stderr, ``error: code: LINE:COLUMN: MESSAGE`` or
``error: set.NAME: MESSAGE``.
"""

from __future__ import annotations

import argparse
import json
import sys

from ..schema.errors import InputError
from ..schema.validate import shown
from ..ctrace.tracing import trace
from ..ctrace.types import TARGETS

__all__ = ["add_trace_parser", "trace_main", "parse_sets"]


def add_trace_parser(sub) -> None:
    """Register the ``trace`` subcommand on an argparse subparsers object."""
    tp = sub.add_parser("trace", help="trace C code's integers as a target computes them "
                                      "('-' = stdin)")
    tp.add_argument("code")
    tp.add_argument("--target", default="c28x", help=f"one of {', '.join(TARGETS)} "
                                                     "(default c28x)")
    tp.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="an input value (decimal or 0x hex); repeat for each input")
    tp.add_argument("--global-q", type=str, default=None,
                    help="IQmath GLOBAL_Q, 1..30 (default 24; #define GLOBAL_Q in the code wins)")


def parse_sets(items: list) -> dict:
    """``["a=1", "b=0x10"]`` → ``{"a": "1", "b": "0x10"}``; the values are checked by trace.

    >>> parse_sets(["gMotorInfo.Voltage=17"])
    {'gMotorInfo.Voltage': '17'}
    """
    out = {}
    for item in items:
        name, eq, value = item.partition("=")
        if not eq or not name.strip():
            raise InputError("set", code="set_syntax", got=shown(item))
        out[name.strip()] = value
    return out


def trace_main(args: argparse.Namespace) -> int:
    """Run the ``trace`` subcommand; returns the exit status."""
    try:
        if args.code == "-":
            code = sys.stdin.read()
        else:
            with open(args.code, encoding="utf-8") as f:
                code = f.read()
    except (OSError, UnicodeDecodeError) as e:
        print(f"error: code: cannot read {args.code}: {getattr(e, 'strerror', None) or e}",
              file=sys.stderr)
        return 2
    try:
        gq = None
        if args.global_q is not None:
            try:
                gq = int(args.global_q)
            except ValueError:
                raise InputError("global_q", code="integer_range", lo=1, hi=30,
                                 got=shown(args.global_q)) from None
        result = trace(code, args.target, parse_sets(args.set), gq)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    json.dump(result, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
    sys.stdout.write("\n")
    return 0
