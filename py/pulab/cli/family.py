"""The family subcommands, ``sweep`` and ``batch``, and the file reading every command shares.

::

    pulab sweep INPUT.json --x motor.rated_current_a=1:200:1000 [--y PATH=A:B:N:log]
                [--profile inovance] [--format text|json|csv]
    pulab batch motors.csv [--output out.csv]

Exit status: 0 when everything computed; 2 with one line ``error: FIELD: MESSAGE`` on
stderr when the input as a whole is unusable; ``batch`` exits 1 when some rows were
reported as errors (one stderr line each, ``row N: FIELD: MESSAGE``; every other row is
still in the output).
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import sys

from ..schema.errors import InputError
from ..schema.jsontext import parse
from ..schema.validate import shown

__all__ = ["add_family_commands", "read_text", "read_json", "parse_axis", "format_sweep_text",
           "sweep_csv"]


def read_text(path: str) -> str:
    """The text of a file, or of stdin for ``-``; InputError naming ``input`` if unreadable.

    Read as bytes and decoded here, so a file that is not UTF-8 is one error line, and the
    file name is ASCII-escaped so that no name can split that line.
    """
    try:
        if path == "-":
            data = sys.stdin.buffer.read()
        else:
            with open(path, "rb") as f:
                data = f.read()
    except OSError as e:
        raise InputError("input", code="cannot_read", path=ascii(path), why=e.strerror) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as e:
        raise InputError("input", code="not_utf8", byte=e.start) from None


def read_json(path: str):
    """The JSON value in a file (``-`` = stdin); InputError naming ``input`` if unreadable."""
    return parse(read_text(path))


def write_result(r, fmt: str, text) -> None:
    """A subcommand's result on stdout: ``text(r)`` for ``--format text``, else indented
    strict JSON (non-ASCII kept)."""
    if fmt == "text":
        sys.stdout.write(text(r))
    else:
        json.dump(r, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
        sys.stdout.write("\n")


def parse_axis(text: str, field: str) -> dict:
    """``PATH=START:STOP[:N][:log|linear]`` → a sweep axis.

    >>> parse_axis("motor.rated_voltage_v=0.1:1000:500:log", "sweep.x")
    {'path': 'motor.rated_voltage_v', 'start': 0.1, 'stop': 1000.0, 'n': 500, 'scale': 'log'}
    """
    path, _, rng = text.partition("=")
    parts = rng.split(":")
    try:
        if not path or not 2 <= len(parts) <= 4:
            raise ValueError
        axis = {"path": path.strip(), "start": float(parts[0]), "stop": float(parts[1])}
        for p in parts[2:]:
            if p in ("log", "linear"):
                axis["scale"] = p
            else:
                axis["n"] = int(p)
    except ValueError:
        raise InputError(field, code="axis_syntax", got=shown(text)) from None
    return axis


def _fmt(v) -> str:
    return "—" if v is None else f"{v:.6g}" if isinstance(v, float) else str(v)


def format_sweep_text(s: dict) -> str:
    """Readable boundaries, worst cases and per-integer counts of a sweep result."""
    x, y = s["x"], s["y"]
    lines = [f"Sweep of {x['path']} from {_fmt(x['values'][0])} to {_fmt(x['values'][-1])} "
             f"({len(x['values'])} points, {x['scale']})"
             + (f" × {y['path']} from {_fmt(y['values'][0])} to {_fmt(y['values'][-1])} "
                f"({len(y['values'])} points, {y['scale']})" if y else "")
             + f", profile {s['profile']}", ""]
    sm = s["summary"]
    lines.append("Boundaries (bisected on the firmware integers; 'at' is the first value with "
                 "the new status)")
    for b in sm["boundaries"]:
        changes = ", ".join(f"{k} {a} → {c}" for k, (a, c) in
                            {**b["raw"], **b["intermediates"]}.items())
        other = f" at {y['path'] if b['axis'] == 'x' else x['path']} = {_fmt(b['other'])}" \
            if b["other"] is not None else ""
        lines.append(f"  {b['name']:<22} {b['from']:>7} → {b['to']:<7} {b['path']} = "
                     f"{b['at']!r} (last {b['from']}: {b['before']!r}){other}"
                     + (f"  [{changes}]" if changes else ""))
    if not sm["boundaries"]:
        lines.append("  none: every integer keeps one status over the whole range")
    lines += ["", "Worst case per integer"]
    for w in sm["worst"]:
        where = f"{x['path']} = {_fmt(w['x'])}" + (f", {y['path']} = {_fmt(w['y'])}" if y else "")
        lines.append(f"  {w['name']:<22} {w['status']:<7} error {_fmt(w['error_pct'])} %  "
                     f"value {_fmt(w['value'])}  at {where}")
    lines += ["", "Points per status, and with |error| ≥ 0.1 / 1 / 5 %"]
    for name, st in sm["per_integer"].items():
        counts = "  ".join(f"{k} {v}" for k, v in st["counts"].items() if v)
        over = " / ".join(str(v) for v in st["over_pct"].values())
        lines.append(f"  {name:<22} {counts}   |error| ≥ thresholds: {over}   max "
                     f"{_fmt(st['max_abs_error_pct'])} %")
    return "\n".join(lines) + "\n"


def sweep_csv(s: dict) -> str:
    """One CSV row per point: the axes, the point's error, each integer's value, error, status."""
    pts = s["points"]
    names = s["names"]
    inter = list(pts["intermediates"])
    head = [s["x"]["path"]] + ([s["y"]["path"]] if s["y"] else []) + ["error"] + \
        [f"{n}.{k}" for n in names for k in ("value", "error_pct", "status")] + inter
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(head)
    for k in range(len(pts["x"])):
        row = [repr(pts["x"][k])] + ([repr(pts["y"][k])] if s["y"] else []) + \
            [pts["error"][k] or ""]
        for n in names:
            c = pts["integers"][n]
            row += ["" if c[key][k] is None else repr(c[key][k]) if key == "error_pct"
                    else c[key][k] for key in ("value", "error_pct", "status")]
        row += ["" if pts["intermediates"][i][k] is None else pts["intermediates"][i][k]
                for i in inter]
        w.writerow(row)
    return buf.getvalue()


def _run_sweep(args) -> int:
    from ..analyses.sweep import sweep
    try:
        req = {"input": read_json(args.input), "x": parse_axis(args.x, "sweep.x"),
               "profile": args.profile}
        if args.y:
            req["y"] = parse_axis(args.y, "sweep.y")
        s = sweep(req)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    if args.format == "json":
        json.dump(s, sys.stdout, ensure_ascii=False, allow_nan=False)
        sys.stdout.write("\n")
    elif args.format == "csv":
        sys.stdout.write(sweep_csv(s))
    else:
        sys.stdout.write(format_sweep_text(s))
    return 0


def _run_batch(args) -> int:
    from ..analyses.batch import batch_rows, output_columns, read_table, to_csv
    try:
        text = read_text(args.input)
        columns, _ = read_table(text)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    rows = batch_rows(text)
    out = to_csv(output_columns(columns), rows)
    if args.output:
        with open(args.output, "w", encoding="utf-8", newline="") as f:
            f.write(out)
    else:
        sys.stdout.write(out)
    bad = [r for r in rows if r["error"]]
    for r in bad:
        print(f"row {r['row']}: {r['error']}", file=sys.stderr)
    return 1 if bad else 0


def add_family_commands(sub: argparse._SubParsersAction) -> None:
    """Add ``sweep`` and ``batch`` to the CLI's subcommands (each sets ``run``)."""
    sp = sub.add_parser("sweep", help="every firmware integer over a range of one or two inputs")
    sp.add_argument("input", help="the base input JSON ('-' = stdin)")
    sp.add_argument("--x", required=True, metavar="PATH=START:STOP[:N][:log]")
    sp.add_argument("--y", metavar="PATH=START:STOP[:N][:log]", help="a second input (2-D map)")
    sp.add_argument("--profile", default="inovance")
    sp.add_argument("--format", choices=("text", "json", "csv"), default="text")
    sp.set_defaults(run=_run_sweep)
    bp = sub.add_parser("batch", help="a CSV of motors → their integers, errors and findings")
    bp.add_argument("input", help="the motor CSV ('-' = stdin)")
    bp.add_argument("--output", "-o", help="write the CSV here instead of stdout")
    bp.set_defaults(run=_run_batch)
