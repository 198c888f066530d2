"""JSON-in, JSON-out entry points for the web worker (one call per request).

Errors never escape as exceptions: bad input comes back as
``{"ok": false, "field": ..., "message": ..., "message_zh": ..., "code": ..., "params": ...}``
(:class:`pulab.schema.errors.InputError` as data, its texts from :mod:`pulab.schema.catalog`).

Examples
--------
>>> import json
>>> json.loads(run_json('{"motor": {}}'))["field"]
'motor.rated_voltage_v'
>>> json.loads(qcalc_json('{"value": 0.5, "format": "Q0.15"}'))["result"]["raw"]
16384
"""

from __future__ import annotations

import json
import math
import re

from .schema.errors import InputError
from .schema.validate import key_path, shown
from .schema.jsontext import parse
from .fixedpoint.qformat import OVERFLOWS, ROUNDINGS, decode, encode, parse_format
from .export import c_header, sim_csv
from .report import report, report_steps
from .analyses.slices import finish
from .schema.textnum import ascii_text, parse_int, parse_real

__all__ = ["run_json", "run_json_steps", "qcalc", "qcalc_json", "export_json", "sweep_json", "batch_json",
           "trace_json", "trace_examples_json", "vendors_json", "course_json"]


def _fail(e: InputError) -> str:
    return json.dumps({"ok": False, "field": e.field, "message": e.message,
                       "message_zh": e.message_zh, "code": e.code, "params": _strict(e.params)},
                      allow_nan=False)


def _strict(v):
    """Params as strict JSON: a non-finite float (a user's 1e999 quoted back) becomes its text."""
    if isinstance(v, float) and not math.isfinite(v):
        return repr(v)
    if isinstance(v, dict):
        return {k: _strict(x) for k, x in v.items()}
    return v


def run_json(text: str) -> str:
    """``report`` on a JSON string; returns ``{"ok": true, "report": {...}}`` or an error."""
    return finish(run_json_steps(text))


def run_json_steps(text: str):
    """:func:`run_json` in slices: a generator that yields None between slices of the simulation
    and returns the same JSON text; closing it cancels the computation."""
    try:
        out = yield from report_steps(parse(text))
        return json.dumps({"ok": True, "report": out}, allow_nan=False)
    except InputError as e:
        return _fail(e)


def qcalc(req: dict) -> dict:
    """The standalone Q-format calculator.

    Parameters
    ----------
    req : dict
        ``format`` (``Qm.n``/``UQm.n``, ``Qn`` with ``word_bits`` (default 16), or an
        IQmath name ``iqN``/``_IQN``: Q N in a 32-bit long), and either ``value`` (a real
        number or its text, full-width digits allowed, to encode with ``rounding`` and
        ``overflow``) or ``raw`` (an integer or its text: decimal, ``0x…``, ``0b…``, to
        decode; for a signed format a reading above its maximum up to 2^word_bits − 1 is
        the register's bit pattern, taken as two's complement and flagged
        ``unsigned_register``).

    Returns
    -------
    dict
        ``format`` (name, word_bits, frac_bits, signed, min, max, resolution) and
        ``result`` (raw, hex, value, error, flags).
    """
    if not isinstance(req, dict):
        raise InputError("qcalc", code="not_object", got=shown(req))
    name = req.get("format", "")
    if not isinstance(name, str):
        raise InputError("qcalc.format", code="not_string", got=shown(name))
    name = ascii_text(name)
    word_bits = req.get("word_bits")
    if word_bits is not None and (isinstance(word_bits, bool) or not isinstance(word_bits, int)):
        raise InputError("qcalc.word_bits", code="not_integer", got=shown(word_bits))
    iq = re.fullmatch(r"_?iq(\d*)", name, re.I)
    if iq:
        # TI IQmath: _iqN / _IQN is a 32-bit long with N fractional bits (GLOBAL_Q = 24).
        name = f"Q{iq[1] or 24}"
        word_bits = 32 if word_bits is None else word_bits
    if word_bits is None and re.fullmatch(r"U?Q\d+", name, re.I):
        word_bits = 16  # a short name like Q15 means a 16-bit word unless told otherwise
    try:
        fmt = parse_format(name, word_bits)
    except (ValueError, TypeError):
        if re.fullmatch(r"U?Q\d+(\.\d+)?", name, re.I):
            raise InputError("qcalc.format", code="q_too_wide", name=name,
                             bits=word_bits or 64) from None
        raise InputError("qcalc.format", code="not_q_format", got=shown(req.get("format", ""))) from None
    rounding = req.get("rounding", "nearest")
    overflow = req.get("overflow", "saturate")
    if rounding not in ROUNDINGS:
        raise InputError("qcalc.rounding", code="not_choice", choices=", ".join(ROUNDINGS),
                         got=shown(rounding))
    if overflow not in OVERFLOWS:
        raise InputError("qcalc.overflow", code="not_choice", choices=", ".join(OVERFLOWS),
                         got=shown(overflow))
    if req.get("raw") is not None:
        raw = parse_int(req["raw"], "qcalc.raw")
        flags = []
        if fmt.signed and fmt.raw_max < raw < (1 << fmt.word_bits):
            # A register reading (40000, 0x8000) is the word's bit pattern: two's complement.
            raw -= 1 << fmt.word_bits
            flags.append("unsigned_register")
        if not fmt.raw_min <= raw <= fmt.raw_max:
            hi = (1 << fmt.word_bits) - 1 if fmt.signed else fmt.raw_max
            raise InputError("qcalc.raw", code="raw_range_for", lo=fmt.raw_min, hi=hi, fmt=fmt.name)
        res = {"raw": raw, "value": decode(raw, fmt), "error": 0.0, "flags": flags}
    else:
        x = parse_real(req.get("value"), "qcalc.value")
        try:
            e = encode(x, fmt, rounding, overflow)
        except OverflowError:
            raise InputError("qcalc.value", code="q_outside", value=x, fmt=fmt.name,
                             lo=fmt.min_value, hi=fmt.max_value) from None
        res = {"raw": e.raw, "value": e.value, "error": e.error, "flags": e.flags}
    mask = (1 << fmt.word_bits) - 1
    res["hex"] = f"0x{res['raw'] & mask:0{(fmt.word_bits + 3) // 4}X}"
    return {"format": {"name": fmt.name, "word_bits": fmt.word_bits, "frac_bits": fmt.frac_bits,
                       "signed": fmt.signed, "min": fmt.min_value, "max": fmt.max_value,
                       "resolution": fmt.resolution},
            "result": res}


def qcalc_json(text: str) -> str:
    """``qcalc`` on a JSON string; ``{"ok": true, ...}`` or an error naming the field."""
    try:
        return json.dumps({"ok": True, **qcalc(parse(text, "qcalc"))})
    except InputError as e:
        return _fail(e)


def export_json(text: str) -> str:
    """Exports for the page: ``{"input": {...}, "kind": "header"|"csv_current"|"csv_pll"}``.

    Returns ``{"ok": true, "text": ...}`` or an error naming the field.
    """
    try:
        req = parse(text)
        r = report(req.get("input") if isinstance(req, dict) else None)
        kind = req.get("kind")
        if kind == "header":
            return json.dumps({"ok": True, "text": c_header(r)})
        if kind in ("csv_current", "csv_pll"):
            if "sim" not in r or kind[4:] not in r["sim"]:
                raise InputError("sim", code="no_simulation", kind=kind[4:])
            return json.dumps({"ok": True, "text": sim_csv(r, kind[4:])})
        raise InputError("kind", code="not_choice", choices="header, csv_current, csv_pll",
                         got=shown(kind))
    except InputError as e:
        return _fail(e)


def sweep_json(text: str) -> str:
    """A family sweep (:mod:`pulab.analyses.sweep`) on a JSON string, whole or in chunks.

    The request is a sweep request (``input``, ``x``, optional ``y`` and ``profile``) with
    ``op``: ``"sweep"`` (default: everything at once), ``"plan"`` (the axes and the number
    of points, nothing computed), ``"chunk"`` with ``start`` and ``count`` (those points and
    their summary; a page computes a sweep chunk by chunk to show progress and cancel), or
    ``"merge"`` with ``summaries`` (the chunks' summaries → the sweep's summary).

    Returns ``{"ok": true, ...}`` with ``plan``, ``chunk`` or ``summary``, or an error
    naming the field.

    >>> import json
    >>> req = {"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3}}
    >>> json.loads(sweep_json(json.dumps({**req, "op": "plan"})))["plan"]["x"]["values"]
    [1.0, 1.5, 2.0]
    >>> json.loads(sweep_json(json.dumps({**req, "op": "chunk", "start": 0, "count": 2})))[
    ...     "chunk"]["points"]["error"][0]
    'motor.rated_voltage_v: is required'
    """
    from .analyses import sweep as sw  # imported on first use: report-only pages stay lean
    try:
        req = parse(text, "sweep")
        op = req.get("op", "sweep") if isinstance(req, dict) else None
        if op == "sweep":
            out = {"sweep": sw.sweep(req)}
        else:
            plan = sw.make_plan(req)
            if op == "plan":
                out = {"plan": sw.describe(plan)}
            elif op == "chunk":
                out = {"chunk": sw.chunk(plan, req.get("start", 0), req.get("count"))}
            elif op == "merge":
                summaries = req.get("summaries")
                if not isinstance(summaries, list):
                    raise InputError("sweep.summaries", code="summaries_list")
                out = {"summary": sw.merge(plan, summaries)}
            else:
                raise InputError("sweep.op", code="not_choice", choices="sweep, plan, chunk, merge",
                                 got=shown(op))
        return json.dumps({"ok": True, **out}, allow_nan=False)
    except InputError as e:
        return _fail(e)


def batch_json(text: str) -> str:
    """A batch (:mod:`pulab.analyses.batch`) on ``{"csv": text, "start": int, "count": int}``.

    Returns ``{"ok": true, "total": rows, "columns": [...], "rows": [[cell, ...]], "csv":
    text}`` for data rows ``start`` … ``start+count−1`` (``csv`` has the header when
    ``start`` is 0, so the chunks' texts joined are the CLI's output), or an error naming
    the field when the file as a whole is unreadable.  Bad rows come back in their
    ``error`` cell.
    """
    from .analyses import batch as bt  # imported on first use: report-only pages stay lean
    try:
        req = parse(text, "batch")
        if not isinstance(req, dict):
            raise InputError("batch", code="not_object", got=shown(req))
        columns, rows = bt.read_table(req.get("csv"))
        start, count = req.get("start", 0), req.get("count", len(rows))
        for name, v, hi in (("start", start, len(rows)), ("count", count, None)):
            if isinstance(v, bool) or not isinstance(v, int) or v < 0 or (hi is not None and v > hi):
                raise InputError(f"batch.{name}", code="integer_range", lo=0,
                                 hi=hi if hi is not None else "N", got=shown(v))
        names = bt.output_columns(columns)
        out = bt.batch_rows(req["csv"], start, count)
        return json.dumps({"ok": True, "total": len(rows), "columns": names,
                           "rows": [[r.get(n, "") for n in names] for r in out],
                           "csv": bt.to_csv(names, out, start == 0)})
    except InputError as e:
        return _fail(e)
    except ValueError as e:
        return _fail(InputError("input", code="json_invalid", detail=" ".join(str(e).split())))


def trace_json(text: str) -> str:
    """The "Your code" tracer: ``{"code", "target", "set": {NAME: VALUE}, "global_q",
    "define": ["NAME[=VALUE]", …]}`` (``define`` as a compiler's ``-D``).

    Returns :func:`pulab.ctrace.trace`'s result, or ``{"ok": false, "field", "message",
    "message_zh"}`` with ``line`` and ``column`` when the code is at fault, and
    ``inputs`` whenever the code compiled (so the page can offer input fields).

    >>> r = json.loads(trace_json('{"code": "Uint16 v; long x = v*10;", "set": {"v": 6554}}'))
    >>> r["vars"]["x"]["value"], r["target"]
    (4, 'c28x')
    >>> json.loads(trace_json('{"code": "x = 1 +;"}'))["message"]
    "1:8: expected a value, got ';'"
    """
    from .ctrace import TraceError, compile_code, trace_checked
    checked = None
    try:
        req = parse(text)
        if not isinstance(req, dict):
            raise InputError("input", code="not_object", got=shown(req))
        unknown = set(req) - {"code", "target", "set", "global_q", "define"}
        if unknown:
            raise InputError(key_path("", sorted(unknown, key=str)[0]), code="unknown_field",
                             expected="code, target, set, global_q, define")
        defines = req.get("define") or []
        if not isinstance(defines, list):
            raise InputError("define", "must be a list of NAME[=VALUE] texts")
        sets = req.get("set") or {}
        if not isinstance(sets, dict):
            raise InputError("set", code="not_object", got=shown(sets))
        checked = compile_code(req.get("code", ""), req.get("target", "c28x"), defines,
                               req.get("global_q"))
        return json.dumps(trace_checked(checked, sets, req.get("global_q")), allow_nan=False)
    except InputError as e:
        reply = json.loads(_fail(e))
        if isinstance(e, TraceError):
            reply.update(line=e.line, column=e.column)
        if checked is not None:
            reply["inputs"] = checked.inputs
        return json.dumps(reply)


def trace_examples_json(text: str = "") -> str:
    """The tracer's example code and targets for the page: ``{"ok": true, "examples": [...],
    "targets": [...]}``; each example has ``id``, ``title``, ``title_zh`` and ``code``.

    >>> [e["id"] for e in json.loads(trace_examples_json())["examples"]][:2]
    ['rpm', 'ld']
    """
    from .ctrace import TARGETS
    from .ctrace.examples import EXAMPLES
    return json.dumps({"ok": True, "targets": list(TARGETS),
                       "examples": [{"id": k, **v} for k, v in EXAMPLES.items()]})


def vendors_json(text: str) -> str:
    """Vendor profiles for the page (docs/contract.md, "Vendor profiles").

    ``{"input": {...}, "action": "header", "profile": NAME}`` → ``{"ok": true, "text": ...}``;
    ``{"input": {...}, "action": "translate", "from": NAME, "axis": "d"|"q",
    "values": {FIELD: int, FIELD: int}}`` → ``{"ok": true, "translation": {...}}``;
    bad input → an error naming the field.

    >>> import json
    >>> req = {"input": {"motor": {}}, "action": "header", "profile": "ti"}
    >>> json.loads(vendors_json(json.dumps(req)))["field"]
    'motor.rated_voltage_v'
    """
    from . import profiles
    from .profiles.translate import translate
    try:
        req = parse(text)
        if not isinstance(req, dict):
            raise InputError("request", code="not_json_object")
        inp = req.get("input")
        if not isinstance(inp, dict):
            raise InputError("input", code="not_json_object")
        action = req.get("action")
        if action == "header":
            name = req.get("profile")
            if name not in profiles.NAMES:
                raise InputError("profile", code="not_choice", choices=", ".join(profiles.NAMES),
                                 got=shown(name))
            r = report({**inp, "profiles": inp.get("profiles") or {}})
            return json.dumps({"ok": True, "text": profiles.header(r, name)})
        if action == "translate":
            t = translate(inp, req.get("from"), req.get("axis", "q"), req.get("values"))
            return json.dumps({"ok": True, "translation": t}, allow_nan=False)
        raise InputError("action", code="not_choice", choices="header, translate",
                         got=shown(action))
    except InputError as e:
        return _fail(e)


def course_json(text: str) -> str:
    """The course's exercises (:mod:`pulab.analyses.exercises`; docs/contract.md, "Course").

    ``{"action": "spec"}`` → ``{"ok": true, "exercises": [...]}``;
    ``{"action": "check", "input": {...}, "id": ID, "answer": A}`` → ``{"ok": true, "result":
    {"id", "state": "correct"|"wrong", "expected", "tolerance"}}``;
    ``{"action": "answers", "input": {...}}`` → ``{"ok": true, "answers": {ID: {...}}}``;
    ``{"action": "trainees", "start": N, "count": K}`` → ``{"ok": true, "trainees": [{"n", "input"}]}``
    (K ≤ 200); bad input → an error naming the field (``exercise.ID`` for an unreadable answer).

    >>> req = {"action": "check", "input": {"motor": {}}, "id": "vendor-rpm", "answer": "1"}
    >>> json.loads(course_json(json.dumps(req)))["field"]
    'motor.rated_voltage_v'
    """
    from .analyses import exercises
    try:
        req = parse(text)
        if not isinstance(req, dict):
            raise InputError("request", code="not_json_object")
        action = req.get("action")
        if action == "spec":
            return json.dumps({"ok": True, "exercises": exercises.spec()})
        if action == "trainees":
            start = parse_int(req.get("start", 1), "start")
            count = parse_int(req.get("count", 10), "count")
            if not 1 <= count <= 200:
                raise InputError("count", code="integer_range", lo=1, hi=200, got=shown(count))
            return json.dumps({"ok": True, "trainees": [{"n": n, "input": exercises.trainee_input(n)}
                                                        for n in range(start, start + count)]})
        if action not in ("check", "answers"):
            raise InputError("action", code="not_choice", choices="spec, check, answers, trainees",
                             got=shown(action))
        inp = req.get("input")
        if not isinstance(inp, dict):
            raise InputError("input", code="not_json_object")
        if action == "answers":
            return json.dumps({"ok": True, "answers": exercises.answers(inp)}, allow_nan=False)
        return json.dumps({"ok": True, "result": exercises.check(inp, req.get("id"), req.get("answer"))},
                          allow_nan=False)
    except InputError as e:
        return _fail(e)
