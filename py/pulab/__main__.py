"""Command line: ``python -m pulab report INPUT.json [--format json|text]``.

Also ``python -m pulab header --profile NAME INPUT.json`` (one vendor's C header) and
``python -m pulab translate --from NAME [--axis d|q] --kp INT --ki INT INPUT.json``
(docs/contract.md, "Vendor profiles").

Bad input: exit status 2 and one line ``error: FIELD: MESSAGE`` on stderr.
"""

from __future__ import annotations

import argparse
import json
import re
import sys

from .errors import InputError
from .inputs import shown
from .jsontext import parse
from .report import format_text, report


def main(argv: list | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m pulab",
                                description="Per-unit and Q-format report for a PMSM drive.")
    sub = p.add_subparsers(dest="command", required=True)
    rp = sub.add_parser("report", help="print the report for an input JSON file ('-' = stdin)")
    rp.add_argument("input")
    rp.add_argument("--format", choices=("json", "text"), default="json")
    hp = sub.add_parser("header", help="print one vendor profile's C header")
    hp.add_argument("--profile", default=None, help="inovance, ti, nxp, st or microchip")
    hp.add_argument("input")
    tp = sub.add_parser("translate", help="one profile's current-loop integers in every profile")
    tp.add_argument("--from", dest="source", default=None)
    tp.add_argument("--axis", default="q")
    tp.add_argument("--kp", default=None)
    tp.add_argument("--ki", default=None)
    tp.add_argument("input")
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
        inp = parse(data.decode("utf-8"))
        if args.command == "header":
            sys.stdout.write(_header(inp, args.profile))
            return 0
        if args.command == "translate":
            json.dump(_translate(inp, args), sys.stdout, indent=1, ensure_ascii=False,
                      allow_nan=False)
            sys.stdout.write("\n")
            return 0
        r = report(inp)
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


def _header(inp, name: str | None) -> str:
    from . import profiles
    if name is None:
        raise InputError("profile", "is required")
    if name not in profiles.NAMES:  # before the report: a typo should not cost a report
        raise InputError("profile",
                         f"must be one of {', '.join(profiles.NAMES)}, got {shown(name)}")
    if not isinstance(inp, dict):
        raise InputError("input", "must be a JSON object")
    return profiles.header(report({**inp, "profiles": inp.get("profiles") or {}}), name)


def _translate(inp, args) -> dict:
    from .profiles import MODULES, NAMES
    from .profiles.translate import translate
    if args.source is None:
        raise InputError("translate.from", "is required")
    if args.source not in NAMES:
        raise InputError("translate.from", f"must be one of {', '.join(NAMES)}, "
                         f"got {shown(args.source)}")
    if not isinstance(inp, dict):
        raise InputError("input", "must be a JSON object")
    names = MODULES[args.source].gain_fields(args.axis) if args.axis in ("d", "q") else ("", "")
    values = {}
    for name, text in zip(names, (args.kp, args.ki)):
        if text is not None:  # absent: translate() names the missing field
            values[name] = int(text) if re.fullmatch(r"[+-]?\d+", text) else text
    return translate(inp, args.source, args.axis, values)


if __name__ == "__main__":
    sys.exit(main())
