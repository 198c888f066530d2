"""``python -m pulab trace FILE.c --target c28x [--entry F] --set NAME=VALUE …
[-D NAME[=VALUE]]… [-U NAME]… [--zero-unset] [--global-q N] [--format json|text]
[--calls N] [--inputs TABLE.csv|TABLE.jsonl] [--gen NAME=KIND:PARAM=VALUE,…]… [--prove --range NAME=LO:HI … [--budget N]]``.

Prints the :func:`~pulab.ctrace.trace` JSON on stdout (with ``--calls``, ``--inputs`` or ``--gen``, the
:func:`~pulab.ctrace.sequence.trace_sequence` JSON; with ``--prove``, the
:func:`~pulab.ctrace.prove.prove_code` JSON: exit 0 proven, 1 violated or unknown); bad
code or input exits with status 2 and one line on stderr, ``error: code: LINE:COLUMN:
MESSAGE`` or ``error: set.NAME: MESSAGE``.
"""

from __future__ import annotations

import argparse
import json
import sys

from ..schema.errors import InputError
from ..schema.validate import shown
from ..ctrace.tracing import trace
from ..ctrace.types import TARGETS

__all__ = ["add_trace_parser", "trace_main", "parse_sets", "parse_ranges", "format_text",
           "format_prove_text", "format_sequence_text"]


def add_trace_parser(sub) -> None:
    """Register the ``trace`` subcommand on an argparse subparsers object."""
    tp = sub.add_parser("trace", help="trace C code's integers as a target computes them "
                                      "('-' = stdin)")
    tp.add_argument("code")
    tp.add_argument("--target", default="c28x", help=f"one of {', '.join(TARGETS)} "
                                                     "(default c28x)")
    tp.add_argument("--entry", default=None, metavar="FUNCTION",
                    help="the function of the code to run (its parameters, the fields its "
                         "pointers reach and the globals it reads are the inputs)")
    tp.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                    help="an input value (decimal or 0x hex); repeat for each input "
                         "(p.FIELD or p->FIELD for a field of the struct p points to)")
    tp.add_argument("--zero-unset", action="store_true",
                    help="inputs not set are 0 (else reading one is an error naming them)")
    tp.add_argument("-D", dest="define", action="append", default=[], metavar="NAME[=VALUE]",
                    help="define a macro before the code, as a compiler's -D (VALUE 1 when "
                         "absent); repeat for each")
    tp.add_argument("-U", dest="undefine", action="append", default=[], metavar="NAME",
                    help="remove a macro the target predefines (__GNUC__, __TMS320C2000__ …)")
    tp.add_argument("--calls", type=str, default=None, metavar="N",
                    help="call the entry N times, globals, statics and pointed-to objects kept "
                         "between calls (--set applies once, before call 0)")
    tp.add_argument("--inputs", default=None, metavar="TABLE.csv|TABLE.jsonl",
                    help="per-call inputs: row k sets its columns before call k (an empty "
                         "cell or missing key keeps the carried value)")
    tp.add_argument("--gen", action="append", default=[], metavar="NAME=KIND:PARAM=VALUE,…",
                    help="a generated per-call input: step:at=K[,before=V,after=V], "
                         "ramp:start=S,slope=D[,min=,max=], sine:amp=A,period=P[,offset=,phase=DEG], "
                         "noise:amp=A[,dist=uniform|gauss,seed=S,offset=]; repeat for each input")
    tp.add_argument("--format", choices=("json", "text"), default="json",
                    help="json (default) or text: one line per executed statement")
    tp.add_argument("--global-q", type=str, default=None,
                    help="IQmath GLOBAL_Q, 1..30 (default 24; #define GLOBAL_Q in the code wins)")
    tp.add_argument("--prove", action="store_true",
                    help="prove every statement free of overflow, wrap and conversion loss "
                         "over the --range box (or give a counterexample)")
    tp.add_argument("--range", dest="ranges", action="append", default=[],
                    metavar="NAME=LO:HI", help="with --prove: an input's integer range "
                                               "(repeat for each; the others keep --set)")
    tp.add_argument("--budget", type=str, default=None,
                    help="with --prove: runs allowed (default 3000)")


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


def format_text(result: dict) -> str:
    """The trace as text: a header, then one line per executed statement: position, the
    source, the value it gave (or the branch an ``if`` took) and its flags, each flag with
    the first sub-expression that raised it.

    >>> from pulab.ctrace import trace
    >>> print(format_text(trace("Uint16 v; long x = v * 10;", "c28x", {"v": 6554})))
    target c28x, GLOBAL_Q 24; inputs: v
    1:1   Uint16 v;         v = 6554 (0x199A) input
    1:11  long x = v * 10;  x = 4 (0x00000004)  unsigned_wrap at 1:20 v * 10
    """
    head = f"target {result['target']}, GLOBAL_Q {result['global_q']}; inputs: " + \
        (", ".join(result["inputs"]) or "none")
    lines = [head]
    if result.get("unresolved_includes"):
        lines.append("not known (contents not pasted): " +
                     ", ".join(result["unresolved_includes"]))
    if result.get("entry"):
        lines[0] = f"target {result['target']}, GLOBAL_Q {result['global_q']}; entry " \
            f"{result['entry']}; inputs: " + (", ".join(result["inputs"]) or "none")
    _step_lines(result["steps"], lines, "")
    ret = result["vars"].get("return")
    if result.get("entry") and ret is not None:
        lines.append(f"return {ret['value']} ({ret['hex']})")
    for name, r in result.get("rounding", {}).items():
        lines.append(f"rounding {name}: {r['floor']} toward -inf, {r['toward_zero']} toward zero, "
                     f"at most {r['max_lost']:g} LSB")
    return "\n".join(lines)


def _step_lines(steps: list, lines: list, indent: str) -> None:
    """One line per step; the steps of a call follow it, indented under the call."""
    pos_w = max((len(f"{s['line']}:{s['column']}") for s in steps), default=0)
    code_w = min(max((len(" ".join(s["code"].split())) for s in steps), default=0), 60)
    for s in steps:
        code = " ".join(s["code"].split())
        if len(code) > 60:
            code = code[:57] + "..."
        if "branch" in s:
            what = f"-> {s['branch']}"
        elif s.get("points_to") is not None:
            what = f"{s['var']} = &{s['points_to']}"
        elif s.get("var") is not None:
            what = f"{s['var']} = {s['value']} ({s['hex']})" if s.get("value") is not None \
                else f"{s['var']} = {{…}}"  # a struct, its fields in vars
        else:
            what = f"= {s['value']} ({s['hex']})" if s.get("value") is not None else ""
        if s.get("input"):
            what += " input"
        notes = []
        for flag in s.get("flags", []):
            term = next((t for t in s.get("terms", []) if flag in t["flags"]), None)
            if term is not None:
                flag += f" at {term['line']}:{term['column']} {' '.join(term['expr'].split())}"
                if flag.startswith("truncation") and "rounding" in term:
                    flag += f" ({term['rounding'].replace('_', ' ')}, {term['lost']:g} LSB lost)"
            notes.append(flag)
        line = f"{s['line']}:{s['column']}".ljust(pos_w) + "  " + code.ljust(code_w) + "  " + what
        if notes:
            line += "  " + "; ".join(notes)
        lines.append(indent + line.rstrip())
        for t in s.get("terms", []):
            if "call" in t:
                value = "" if t["value"] is None else f" = {t['value']} ({t['hex']})"
                lines.append(f"{indent}  call {t['call']}(){value}")
                _step_lines(t["steps"], lines, indent + "    ")


def parse_ranges(items: list) -> dict:
    """``["e=-100:100", "p.Kp=0x10:0x7FFF"]`` → ``{"e": ["-100", "100"], "p.Kp": [...]}``
    (the integers are checked by the proof).

    >>> parse_ranges(["e=-100:100"])
    {'e': ['-100', '100']}
    """
    out = {}
    for item in items:
        name, eq, rng = item.partition("=")
        parts = rng.split(":")
        if not eq or not name.strip() or len(parts) != 2:
            raise InputError("range", code="prove_range_syntax", got=shown(item))
        out[name.strip()] = parts
    return out


def format_prove_text(r: dict) -> str:
    """One line per statement: position, verdict, proven range against its word, the kinds
    of failure and the counterexample."""
    box = ", ".join(f"{k} in [{lo}, {hi}]" for k, (lo, hi) in r["box"].items())
    lines = [f"proof over {box}: {r['verdict'].upper()} ({r['work']} runs, {r['boxes']} boxes)"]
    for s in r["statements"]:
        rng = "-" if s["range"] is None else f"[{s['range'][0]}, {s['range'][1]}]"
        word = "" if s["word"] is None else f" of {s['type']}"
        line = f"{s['line']}:{s['column']}  {s['verdict']:<8} {rng}{word}  {s['code']}"
        if s["verdict"] == "violated":
            line += f"  {', '.join(s['kinds'])} at " + \
                ", ".join(f"{k}={v}" for k, v in s["counterexample"].items())
        elif s["verdict"] == "unknown":
            line += f"  (proven for {100 * s['proven_fraction']:.1f} % of the box)"
        lines.append(line)
    for name, p in r.get("proposals", {}).items():
        if p.get("local"):
            k = p["shift"]
            lines.append(f"@q {name} auto (local): its stores compute {p['computed']}; {p['type']} "
                         + (f"holds them with {k} more fractional bits" if k >= 0 else
                            f"holds them only as value >> {-k} (error <= {p['max_error_lsb']} "
                            "of the present LSB)"))
            continue
        lo, hi = p["range_real"]
        lines.append(f"@q {name} auto over [{lo:g}, {hi:g}]: " + (
            f"Q{p['q']} in {p['type']}, raw {p['raw_range']}, error <= {p['max_error']:g}"
            if p["q"] is not None else "no Q keeps every statement proven"))
    return "\n".join(lines)


def format_sequence_text(r: dict) -> str:
    """One line per call: its result and flags, then the first event.

    >>> from pulab.ctrace.sequence import trace_sequence
    >>> r = trace_sequence("int a; int f(int e) { a += e; return a; }", "c28x", 2,
    ...                    inputs={"a": 30000, "e": 2000}, entry="f")
    >>> print(format_sequence_text(r))
    target c28x, entry f, 2 calls; inputs: e, a
    call 0  return 32000 (0x7D00)
    call 1  return -31536 (0x84D0)  signed_overflow
    first event: call 1, line 1, signed_overflow, a
    >>> r = trace_sequence("int a; int f(int e) { a = e; return a; }", "c28x", 2,
    ...                    entry="f", gen={"e": "ramp:start=30000,slope=3000"})
    >>> print(format_sequence_text(r).splitlines()[1])
    generated e = ramp:start=30000,slope=3000  (1 values held at the limits of int, first at call 1)
    """
    lines = [f"target {r['target']}, entry {r['entry']}, {len(r['calls'])} calls; inputs: " +
             (", ".join(r["inputs"]) or "none")]
    for name, g in r.get("generated", {}).items():
        lines.append(f"generated {name} = {g['spec']}" + (
            f"  ({g['clamped']} values held at the limits of {g['type']}, first at call "
            f"{g['first_clamped']})" if g["clamped"] else ""))
    for k, c in enumerate(r["calls"]):
        ret = c["return"]
        line = f"call {k}" + (f"  return {ret['value']} ({ret['hex']})"
                              if ret is not None and ret.get("value") is not None else "")
        if c["flags"]:
            line += "  " + ", ".join(c["flags"])
        lines.append(line)
    e = r["first_event"]
    lines.append("first event: none" if e is None else
                 f"first event: call {e['call']}, line {e['line']}, {e['kind']}, {e['name']}")
    return "\n".join(lines)


def _whole(text: str, field: str, hi: int) -> int:
    """A command-line whole number (its range is checked where it is used)."""
    try:
        return int(text)
    except ValueError:
        raise InputError(field, code="integer_range", lo=1, hi=hi, got=shown(text)) from None


def _sequence(code: str, args: argparse.Namespace, gq) -> int:
    from ..ctrace.sequence import MAX_CALLS, read_table, trace_sequence
    calls = None if args.calls is None else _whole(args.calls, "calls", MAX_CALLS)
    table = None
    if args.inputs is not None:
        kind = args.inputs.rpartition(".")[2].lower()
        if kind not in ("csv", "jsonl"):
            raise InputError("inputs", code="trace_table_kind", name=shown(args.inputs))
        try:
            with open(args.inputs, encoding="utf-8-sig", newline="") as f:
                text = f.read()
        except (OSError, UnicodeDecodeError) as e:
            raise InputError("inputs", code="trace_table_read", name=shown(args.inputs),
                             reason=str(getattr(e, "strerror", None) or e)) from None
        table = read_table(text, kind)
    gen = {}
    for item in args.gen:
        name, eq, spec = item.partition("=")
        if not eq or not name.strip():
            raise InputError("gen", code="trace_gen_syntax", got=shown(item))
        gen[name.strip().replace("->", ".")] = spec
    r = trace_sequence(code, args.target, calls, table, parse_sets(args.set), gq, args.define,
                       args.entry, args.zero_unset, args.undefine, gen)
    if args.format == "text":
        sys.stdout.write(format_sequence_text(r) + "\n")
    else:
        json.dump(r, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
        sys.stdout.write("\n")
    return 0


def _prove(code: str, args: argparse.Namespace, gq) -> int:
    from ..ctrace.prove import DEFAULT_BUDGET, MAX_BUDGET, prove_code
    budget = DEFAULT_BUDGET if args.budget is None else _whole(args.budget, "budget", MAX_BUDGET)
    r = prove_code(code, args.target, args.entry, parse_ranges(args.ranges),
                   parse_sets(args.set), args.define, gq, budget, args.zero_unset,
                   args.undefine)
    if args.format == "text":
        sys.stdout.write(format_prove_text(r) + "\n")
    else:
        json.dump(r, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
        sys.stdout.write("\n")
    return 0 if r["verdict"] == "proven" else 1


def trace_main(args: argparse.Namespace) -> int:
    """Run the ``trace`` subcommand; returns the exit status."""
    try:
        if args.code == "-":
            raw = sys.stdin.buffer.read()
        else:
            with open(args.code, "rb") as f:
                raw = f.read()
        try:
            code = raw.decode("utf-8")
        except UnicodeDecodeError:
            # vendor files carry Latin-1/GBK bytes in comments; outside them the lexer refuses
            code = raw.decode("latin-1")
    except OSError as e:
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
        sequence = args.calls is not None or args.inputs is not None or bool(args.gen)
        if args.prove and sequence:
            raise InputError("calls", code="trace_calls_prove")
        if args.prove:
            return _prove(code, args, gq)
        if sequence:
            return _sequence(code, args, gq)
        result = trace(code, args.target, parse_sets(args.set), gq, args.define, args.entry,
                       args.zero_unset, args.undefine)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    if args.format == "text":
        sys.stdout.write(format_text(result) + "\n")
        return 0
    json.dump(result, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
    sys.stdout.write("\n")
    return 0
