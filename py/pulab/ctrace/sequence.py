"""Sequences: the entry function called N times, as the firmware calls it every control period.

The memory the firmware keeps between calls is kept here too: globals, ``static`` locals and
the objects the entry's pointer parameters point to (a PI's integrator, a filter's state).
Inputs are given once before call 0 (``inputs``, the CLI's ``--set``) and per call from a
table (one row per call, columns = input names): a row sets its columns before its call, a
column left out (an empty CSV cell, a missing JSON key) keeps the carried value.  A by-value
parameter is the caller's copy: its last given value, whatever the callee did to it.

Examples
--------
>>> code = "int acc; int step(int e) { acc += e; return acc; }"
>>> r = trace_sequence(code, "c28x", entry="step", inputs={"acc": 0},
...                    table=[{"e": 20000}, {}, {"e": -5}])
>>> [c["return"]["value"] for c in r["calls"]], r["first_event"]
([20000, -25536, -25541], {'call': 1, 'line': 1, 'kind': 'signed_overflow', 'name': 'acc'})
>>> read_table("e,p.k\\r\\n1,0x10\\r\\n,-2\\r\\n", "csv")
[{'e': '1', 'p.k': '0x10'}, {'p.k': '-2'}]
"""

from __future__ import annotations

import csv
import io
import json

from ..schema.errors import InputError
from ..schema.validate import shown
from .errors import TraceError
from .evaluate import FLAGS, Evaluator
from .generate import generate
from .macro_entry import entry_macros
from .tracing import DEFAULT_GLOBAL_Q, compile_code, input_values, result_vars, run_error

__all__ = ["trace_sequence", "run_sequence", "read_table", "MAX_CALLS", "MAX_SEQUENCE_STEPS",
           "EVENT_KINDS"]

#: More calls in one sequence are refused (each call's ``vars`` is in the output).
MAX_CALLS = 10_000
#: Statements executed over all the calls of a sequence (each call has the single trace's
#: own limit too); more is an error naming the call that reached it.
MAX_SEQUENCE_STEPS = 1_000_000
#: The flags that make a call's ``first_event``: a wrap (an unsigned result reduced, or a
#: conversion that changed the value), a signed overflow, a clamp by ``_IQsat``/``__IQsat`` or
#: an IQmath call that saturated (``_IQrsmpy``, ``_IQdiv``, ``_IQmag``).
EVENT_KINDS = ("signed_overflow", "unsigned_wrap", "conversion", "saturate")


def read_table(text: str, kind: str) -> list:
    """Rows of a per-call input table: ``kind`` ``"csv"`` (a header row of input names, then
    one row per call; LF or CRLF; an empty cell is left out) or ``"jsonl"`` (one JSON object
    per line; blank lines skipped).  Cells stay text (or JSON integers): the tracer checks
    them against the code.

    >>> read_table('{"e": 5}\\n\\n{"e": "0x7FFF", "k": null}\\n', "jsonl")
    [{'e': 5}, {'e': '0x7FFF'}]
    """
    if kind == "csv":
        reader = csv.reader(io.StringIO(text.replace("\r\n", "\n")))
        header = next(reader, None)
        if not header or any(not h.strip() for h in header):
            raise InputError("inputs", code="trace_table_header")
        names = [h.strip() for h in header]
        rows = []
        for i, cells in enumerate(reader):
            if not cells or all(not c.strip() for c in cells) and len(cells) <= 1:
                continue  # a blank line
            if len(cells) > len(names):
                raise InputError(f"inputs[{len(rows)}]", code="trace_table_cells",
                                 row=i + 2, n=len(cells), names=len(names))
            rows.append({n: c.strip() for n, c in zip(names, cells) if c.strip()})
        return rows
    if kind != "jsonl":
        raise InputError("inputs", code="not_choice", choices="csv, jsonl", got=shown(kind))
    rows = []
    for i, line in enumerate(text.splitlines()):
        if not line.strip():
            continue
        try:
            row = json.loads(line)
        except ValueError:
            raise InputError(f"inputs[{len(rows)}]", code="trace_table_json", row=i + 1) \
                from None
        if not isinstance(row, dict):
            raise InputError(f"inputs[{len(rows)}]", code="trace_table_json", row=i + 1)
        rows.append({k: v for k, v in row.items() if v is not None})
    return rows


def _row_values(checked, row, k: int) -> dict:
    if not isinstance(row, dict):
        raise InputError(f"inputs[{k}]", code="not_object", got=shown(row))
    try:
        return input_values(checked, row)
    except InputError as e:
        raise InputError(f"inputs[{k}]", code="trace_table_cell", call=k,
                         reason={"code": e.code, "params": e.params}) from None


def run_sequence(checked, calls: int, table: list | None = None, inputs: dict | None = None,
                 global_q: int | None = None, zero_unset: bool = False,
                 gen: dict | None = None) -> dict:
    """:func:`trace_sequence` for code already compiled by
    :func:`~pulab.ctrace.tracing.compile_code` (with an entry)."""
    if checked.entry is None:
        raise InputError("entry", code="trace_calls_entry")
    if table is not None and len(table) != calls:
        raise InputError("inputs", code="trace_table_rows", rows=len(table), calls=calls)
    generated = None
    if gen:
        made, generated = generate(checked, gen, calls)
        for k, row in enumerate(table or ()):
            both = next((n for n in generated if isinstance(row, dict) and n in row), None)
            if both is not None:
                raise InputError(f"gen.{both}", code="trace_gen_table", name=both, call=k)
        table = [{**row, **g} if isinstance(row, dict) else row for row, g in zip(table, made)] \
            if table else made
    gq = checked.program.global_q or global_q or DEFAULT_GLOBAL_Q
    first = input_values(checked, inputs or {}, zero_unset)
    rows = [_row_values(checked, row, k) for k, row in enumerate(table or ())]
    # the caller's copies of the by-value parameters: the last value given to each
    params = [p.key for p in checked.entry.params if p.key in checked.symbols]
    caller = {k: v for k, v in first.items() if k in params}
    ev = None
    out, event = [], None
    state: set = set()  # every name given or written so far: listed after every call
    executed = 0
    for k in range(calls):
        given = dict(first) if k == 0 else {}
        if rows:
            given.update(rows[k])
        caller.update((n, given[n]) for n in params if n in given)
        given.update(caller)
        try:
            if ev is None:
                ev = Evaluator(checked, given, gq, record=False)
                ev.watch = EVENT_KINDS
                ev.run()
            else:
                ev.again(given)
        except TraceError as e:
            if e.line is None or calls == 1:
                raise
            raise TraceError(e.line, e.column, e.field, code="trace_in_call", call=k,
                             reason=e.reason_error()) from None
        executed += ev.count
        if executed > MAX_SEQUENCE_STEPS:
            raise InputError("calls", code="trace_sequence_steps", call=k,
                             limit=MAX_SEQUENCE_STEPS)
        if ev.event is not None and event is None:
            event = {"call": k, "line": ev.event[0], "kind": ev.event[1], "name": ev.event[2]}
        names = set(given) | (set(ev.names) if zero_unset and k == 0 else set())
        state |= names | ev.written
        vars_ = result_vars(checked, ev, names, state)
        out.append({"return": vars_.get("return"), "vars": vars_,
                    "flags": sorted(ev.seen, key=FLAGS.index)})
    result = {"ok": True, "target": checked.target.name, "global_q": gq,
              "entry": checked.entry.name,
              "functions": [f for f in checked.functions if f not in checked.program.macros],
              "macros": entry_macros(checked.program),
              "unresolved_includes": list(checked.program.unresolved),
              "inputs": ev.names, "calls": out, "first_event": event}
    if generated is not None:
        result["generated"] = generated
    return result


def trace_sequence(code: str, target: str = "c28x", calls: int | None = None,
                   table: list | None = None, inputs: dict | None = None,
                   global_q: int | None = None, defines=None, entry: str | None = None,
                   zero_unset: bool = False, undefines=None, gen: dict | None = None) -> dict:
    """Call ``entry`` ``calls`` times with the firmware's memory kept between the calls.

    Parameters
    ----------
    code, target, global_q, defines, entry, zero_unset, undefines
        As for :func:`~pulab.ctrace.trace` (``entry`` is required).
    calls : int in 1..MAX_CALLS, optional
        How many calls (default: the table's row count; without a table, 1).
    table : list of dict, optional
        Row k (input name → value, as ``inputs``) is given before call k; its length must
        be ``calls``.  :func:`read_table` reads CSV and JSON lines.
    inputs : dict, optional
        Input name → value, given once before call 0 (the CLI's ``--set``).
    gen : dict, optional
        Input name → generator spec (:mod:`pulab.ctrace.generate`: ``"sine:amp=1000,
        period=200"``…): that input's value before every call, generated; not also a column of
        ``table``.

    Returns
    -------
    dict
        :func:`~pulab.ctrace.trace`'s header (``target``, ``global_q``, ``entry``,
        ``functions``, ``macros``, ``unresolved_includes``, ``inputs``), ``calls`` (per call:
        ``return`` — the result as ``vars.return``, None for a void or struct result, whose
        fields are ``vars["return.FIELD"]`` — ``vars`` as the trace's after the call, and
        ``flags``, the union over the call's steps) and ``first_event``
        ``{"call", "line", "kind", "name"}`` (the first flag of :data:`EVENT_KINDS`; ``call``
        from 0; ``name`` the variable the statement stores, else its text) or None.  With
        ``gen``, ``generated``: per generated input ``{"spec", "type", "values" (per call),
        "clamped" (how many values were held at the type's limit), "first_clamped"}``.

    Raises
    ------
    TraceError
        As :func:`~pulab.ctrace.trace`; a run-time error in call k is ``trace_in_call``
        (``call`` k, the error as ``reason``, at its line and column); a table row at fault
        has the field ``inputs[k]``; a row count other than ``calls`` is ``trace_table_rows``.
    """
    try:
        if calls is None:
            calls = len(table) if isinstance(table, list) else 1
        if isinstance(calls, bool) or not isinstance(calls, int) or not 1 <= calls <= MAX_CALLS:
            raise InputError("calls", code="integer_range", lo=1, hi=MAX_CALLS,
                             got=shown(calls))
        if table is not None and not isinstance(table, list):
            raise InputError("inputs", code="trace_table_list", got=shown(table))
        if global_q is not None and (isinstance(global_q, bool) or not isinstance(global_q, int)
                                     or not 1 <= global_q <= 30):
            raise InputError("global_q", code="integer_range", lo=1, hi=30,
                             got=shown(global_q))
        if entry is None:
            raise InputError("entry", code="trace_calls_entry")
        checked = compile_code(code, target, defines, global_q, entry, undefines)
    except InputError as e:
        raise TraceError.of(e) from None
    try:
        return run_sequence(checked, calls, table, inputs, global_q, zero_unset, gen)
    except InputError as e:
        raise run_error(e, checked, inputs) from None
