"""Command line: ``python -m pulab report INPUT.json [--format json|text]``, ``sweep``, ``batch``,
``python -m pulab trace FILE.c --target c28x --set NAME=VALUE …``,
``python -m pulab prove INPUT.json --range PATH=LO:HI …`` (a family proof),
``python -m pulab header --profile NAME INPUT.json`` (one vendor's C header) and
``python -m pulab translate --from NAME [--axis d|q] --kp INT --ki INT INPUT.json``
(docs/contract.md, "Vendor profiles"), ``python -m pulab oembed SITE_URL DIST`` (the panels'
oEmbed descriptions, :mod:`pulab.cli.oembed`) and ``python -m pulab audit FILE…`` (a vendor's
generated headers read back, :mod:`pulab.cli.audit`).

Bad input: exit status 2 and one line ``error: FIELD: MESSAGE`` on stderr
(for code, ``error: code: LINE:COLUMN: MESSAGE``).
"""

from __future__ import annotations

import argparse
import json
import re
import sys

from .schema.errors import InputError
from .cli.family import add_family_commands, read_json, write_result
from .report import format_text, report, require_pmsm
from .cli.trace import add_trace_parser, trace_main
from .cli.robust import add_robust_parser
from .cli.prove import add_prove_parser
from .cli.oembed import add_oembed_parser
from .cli.audit import add_audit_parser


def main(argv: list | None = None) -> int:
    p = argparse.ArgumentParser(prog="python -m pulab",
                                description="Per-unit and Q-format report for a PMSM drive.")
    sub = p.add_subparsers(dest="command", required=True)
    rp = sub.add_parser("report", help="print the report for an input JSON file ('-' = stdin)")
    rp.add_argument("input")
    rp.add_argument("--format", choices=("json", "text"), default="json")
    add_family_commands(sub)
    add_trace_parser(sub)
    add_robust_parser(sub)
    add_prove_parser(sub)
    add_oembed_parser(sub)
    add_audit_parser(sub)
    _add_vendor_commands(sub)
    args = p.parse_args(argv)
    if args.command == "trace":
        return trace_main(args)
    if hasattr(args, "run"):
        return args.run(args)
    try:
        r = report(read_json(args.input))
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    write_result(r, args.format, format_text)
    return 0


def _add_vendor_commands(sub) -> None:
    hp = sub.add_parser("header", help="print one vendor profile's C header")
    hp.add_argument("--profile", default=None, help="inovance, ti, nxp, st or microchip")
    hp.add_argument("input")
    hp.set_defaults(run=_run_vendor)
    tp = sub.add_parser("translate", help="one profile's current-loop integers in every profile")
    tp.add_argument("--from", dest="source", default=None)
    tp.add_argument("--axis", default="q")
    tp.add_argument("--kp", default=None)
    tp.add_argument("--ki", default=None)
    tp.add_argument("input")
    tp.set_defaults(run=_run_vendor)


def _run_vendor(args) -> int:
    try:
        inp = read_json(args.input)
        if args.command == "header":
            sys.stdout.write(_header(inp, args.profile))
        else:
            json.dump(_translate(inp, args), sys.stdout, indent=1, ensure_ascii=False,
                      allow_nan=False)
            sys.stdout.write("\n")
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    return 0


def _header(inp, name: str | None) -> str:
    from . import profiles
    if name is None:
        raise InputError("profile", code="required")
    profiles.registry.get(name)  # before the report: a typo should not cost a report
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    require_pmsm(inp)
    return profiles.header(report({**inp, "profiles": inp.get("profiles") or {}}), name)


def _translate(inp, args) -> dict:
    from .profiles import registry
    from .profiles.translate import translate
    if args.source is None:
        raise InputError("translate.from", code="required")
    vendor = registry.get(args.source, "translate.from")
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    names = vendor.gain_fields(args.axis) if args.axis in ("d", "q") else ("", "")
    values = {}
    for name, text in zip(names, (args.kp, args.ki)):
        if text is not None:  # absent: translate() names the missing field
            # int() refuses over 4300 digits; such text is refused as "must be an integer".
            values[name] = int(text) if re.fullmatch(r"[+-]?\d{1,400}", text) else text
    return translate(inp, args.source, args.axis, values)


if __name__ == "__main__":
    sys.exit(main())
