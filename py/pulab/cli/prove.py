"""The ``prove`` subcommand: every firmware integer of a product family, proven or broken.

::

    pulab prove INPUT.json --range motor.rated_current_a=1:60 --range drive.base_freq_hz=100:400
                [--profile inovance|ti|nxp|st|microchip] [--budget N] [--propose]
                [--format json|text]

INPUT.json is the base motor; each ``--range PATH=LO:HI`` makes that input range over
``[LO, HI]`` (:mod:`pulab.analyses.prove`); ``--propose`` adds each constant's finest format
in its vendor's form (:mod:`pulab.analyses.propose`).  Exit status: 0 when every integer is proven,
1 when one is violated (its counterexample is in the JSON) or unknown, 2 with one line
``error: FIELD: MESSAGE`` on stderr when the request is unusable.
"""

from __future__ import annotations

import json
import sys

from ..schema.errors import InputError
from ..schema.validate import shown
from .family import read_json, write_result

__all__ = ["add_prove_parser", "parse_range", "format_prove_text"]


def add_prove_parser(sub) -> None:
    p = sub.add_parser("prove", help="prove every firmware integer in range over a box of "
                                     "inputs, or give a motor that breaks one")
    p.add_argument("input", help="the base input JSON ('-' = stdin)")
    p.add_argument("--range", dest="ranges", action="append", default=[],
                   metavar="PATH=LO:HI", help="an input's range (repeat for each input)")
    p.add_argument("--profile", default=None,
                   help="inovance (the seed's code; the default), ti, nxp, st or microchip "
                        "(that vendor's constants)")
    p.add_argument("--budget", type=int, default=None, help="boxes per integer (default 4000)")
    p.add_argument("--propose", action="store_true",
                   help="propose each constant's finest format in the vendor's own form "
                        "(GLOBAL_Q, FRAC16 + shift, power-of-two divisor, Q) proven over the box")
    p.add_argument("--format", choices=("json", "text"), default="json")
    p.set_defaults(run=_run)


def parse_range(text: str) -> tuple:
    """``PATH=LO:HI`` → (path, [lo, hi]).

    >>> parse_range("motor.rs_ohm=0.5:2")
    ('motor.rs_ohm', [0.5, 2])
    >>> parse_range("raw.Current=100:400")
    ('raw.Current', [100, 400])
    """
    path, _, rng = text.partition("=")
    parts = rng.split(":")
    try:
        if not path.strip() or len(parts) != 2:
            raise ValueError
        # A raw or integer input keeps its integers as the JSON would.
        ends = [int(p) if p.strip().lstrip("+-").isdigit() else float(p) for p in parts]
    except ValueError:
        raise InputError("prove.ranges", code="prove_range_syntax", got=shown(text)) from None
    return path.strip(), ends


def format_prove_text(r: dict) -> str:
    """One line per integer: verdict, proven range against its word, counterexample."""
    lines = [f"Proof over {', '.join(f'{p} ∈ [{lo:g}, {hi:g}]' for p, (lo, hi) in r['ranges'].items())}"
             f": {r['verdict'].upper()}", ""]
    for name, e in r["integers"].items():
        rng = "—" if e["range"] is None else f"[{e['range'][0]}, {e['range'][1]}]"
        word = "" if e["word"] is None else f" of {e['type']} [{e['word'][0]}, {e['word'][1]}]"
        line = f"  {name:<22} {e['verdict']:<8} {rng}{word}"
        if e.get("headroom_bits"):
            line += f"  (+{e['headroom_bits']} fractional bits would still fit)"
        if e["verdict"] == "violated":
            line += f"  {e['kind']} at raw {e['raw']}: {e['statement']}"
        elif e["verdict"] == "unknown":
            line += f"  proven for {100 * e['proven_fraction']:.1f} % of the box"
        lines.append(line)
    if r["not_analysed"]:
        lines += ["", "Not analysed: " + ", ".join(r["not_analysed"])]
    if "proposal" in r:
        lines += [""] + _proposal_lines(r["proposal"])
    if "counterexample" in r:
        lines += ["", f"Counterexample ({r['first_violated']}):",
                  json.dumps(r["counterexample"], ensure_ascii=False)]
    return "\n".join(lines) + "\n"


def _proposal_lines(p: dict) -> list:
    """The proposal in the vendor's form, one line per constant."""
    if p["profile"] == "ti":
        return [f"Proposed GLOBAL_Q: {p['global_q']} (the finest proven over the box)"]
    if p["profile"] == "inovance":
        return ["Fixed formats (the seed's code); headroom of each proven integer:"] + [
            f"  {k:<22} +{e['headroom_bits']} bits" for k, e in p["integers"].items()]
    lines = [f"Proposed formats ({p['form']}), finest that holds over the box:"]
    for k, e in p["constants"].items():
        if e is None:
            lines.append(f"  {k:<28} not enclosed within the budget")
        elif e["holds"]:
            lines.append(f"  {k:<28} {e['format']:<16} integers [{e['range'][0]}, "
                         f"{e['range'][1]}], worst error ≤ {e['worst_error_pct']:.3g} % "
                         f"(now {e['current']})")
        elif e["impossible"]:
            lines.append(f"  {k:<28} no {p['form']} holds: motors of the box take "
                         f"[{e['witnessed'][0]:.4g}, {e['witnessed'][1]:.4g}]")
        else:
            lines.append(f"  {k:<28} none found: the enclosure [{e['real_range'][0]:.4g}, "
                         f"{e['real_range'][1]:.4g}] is too wide (one may exist)")
    if p.get("divisors"):
        lines.append("  divisors: " + ", ".join(f"{k.upper()} = {v}"
                                               for k, v in p["divisors"].items()))
    return lines


def _run(args) -> int:
    from ..analyses.prove import prove
    try:
        req = {"input": read_json(args.input), "ranges": {}}
        for text in args.ranges:
            path, ends = parse_range(text)
            req["ranges"][path] = ends
        if args.profile is not None:
            req["profile"] = args.profile
        if args.budget is not None:
            req["budget"] = args.budget
        r = prove(req)
        if args.propose:
            from ..analyses.propose import propose
            r["proposal"] = propose(req, r)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    write_result(r, args.format, format_prove_text)
    return 0 if r["verdict"] == "proven" else 1
