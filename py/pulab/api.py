"""JSON-in, JSON-out entry points for the web worker (one call per request).

Every request goes through :func:`call_json` (or :func:`call_json_steps`, the same in
slices): one parser (:func:`pulab.schema.jsontext.parse`, its size and nesting limits) and
one dispatch key, ``kind`` (:data:`KINDS`).  There is no other entry point: a kind that
used to be chosen by a key of the request (``op``, ``action``) is named by ``kind`` itself
(``sweep.plan``, ``vendors.header`` …).

Errors never escape as exceptions: bad input comes back as
``{"ok": false, "field": ..., "message": ..., "message_zh": ..., "code": ..., "params": ...}``
(:class:`pulab.schema.errors.InputError` as data, its texts from :mod:`pulab.schema.catalog`).

Examples
--------
>>> import json
>>> json.loads(call_json("report", '{"motor": {}}'))["field"]
'motor.rated_voltage_v'
>>> json.loads(call_json("qcalc", '{"value": 0.5, "format": "Q0.15"}'))["result"]["raw"]
16384
>>> json.loads(call_json("qcalc.encode", "{}"))["field"]
'kind'
>>> req = {"input": {}, "x": {"path": "motor.rs_ohm", "start": 1, "stop": 2, "n": 3}}
>>> json.loads(call_json("sweep.plan", json.dumps(req)))["plan"]["x"]["values"]
[1.0, 1.5, 2.0]
>>> json.loads(call_json("sweep.chunk", json.dumps({**req, "start": 0, "count": 2})))[
...     "chunk"]["points"]["error"][0]
'motor.rated_voltage_v: is required (or give datasheet.dc_bus_v)'
>>> r = json.loads(call_json("trace", '{"code": "Uint16 v; long x = v*10;", "set": {"v": 6554}}'))
>>> r["vars"]["x"]["value"], r["target"]
(4, 'c28x')
>>> json.loads(call_json("trace", '{"code": "x = 1 +;"}'))["message"]
"1:8: expected a value, got ';'"
>>> [e["id"] for e in json.loads(call_json("trace.examples", "{}"))["examples"]][:2]
['rpm', 'ld']
"""

from __future__ import annotations

import json
import math
from dataclasses import fields, is_dataclass

from .schema.errors import InputError
from .schema.validate import key_path, shown
from .schema.jsontext import parse
from .schema.textnum import parse_int
from .export import c_header, sim_csv
from .qcalc import qcalc
from .report import report, report_steps, require_pmsm
from .analyses.slices import finish

__all__ = ["KINDS", "call_json", "call_json_steps"]


def _fail(e: InputError) -> str:
    reply = {"ok": False, "field": e.field, "message": e.message, "message_zh": e.message_zh,
             "code": e.code, "params": _strict(e.params)}
    # An error that declares fields (the tracer's: where in the code, what the code offers
    # instead) carries those that are set; testing for the class would import the tracer.
    if is_dataclass(e):
        reply.update((f.name, getattr(e, f.name)) for f in fields(e)
                     if getattr(e, f.name) is not None)
    return json.dumps(reply, allow_nan=False)


def _strict(v):
    """Params as strict JSON: a non-finite float (a user's 1e999 quoted back) becomes its text."""
    if isinstance(v, float) and not math.isfinite(v):
        return repr(v)
    if isinstance(v, dict):
        return {k: _strict(x) for k, x in v.items()}
    return v


# ---- the handlers: a parsed request → the reply's fields ----------------------------------

def _report_steps(req):
    return {"report": (yield from report_steps(req))}


def _export_input(req) -> dict:
    return report(req.get("input") if isinstance(req, dict) else None)


def _export(what: str):
    def handler(req) -> dict:
        r = _export_input(req)
        if what == "header":
            require_pmsm(r["input"])
            return {"text": c_header(r)}
        if "sim" not in r or what[4:] not in r["sim"]:
            raise InputError("sim", code="no_simulation", kind=what[4:])
        return {"text": sim_csv(r, what[4:])}
    return handler


def _sweep_plan(req):
    from .analyses import sweep as sw  # imported on first use: report-only pages stay lean
    return sw.make_plan(req)


def _sweep(op: str):
    def handler(req) -> dict:
        from .analyses import sweep as sw
        if op == "sweep":
            return {"sweep": sw.sweep(req)}
        plan = _sweep_plan(req)
        if op == "plan":
            return {"plan": sw.describe(plan)}
        if op == "chunk":
            return {"chunk": sw.chunk(plan, req.get("start", 0), req.get("count"))}
        summaries = req.get("summaries")
        if not isinstance(summaries, list):
            raise InputError("sweep.summaries", code="summaries_list")
        return {"summary": sw.merge(plan, summaries)}
    return handler


def _batch(req) -> dict:
    from .analyses import batch as bt  # imported on first use: report-only pages stay lean
    if not isinstance(req, dict):
        raise InputError("batch", code="not_object", got=shown(req))
    try:
        columns, rows = bt.read_table(req.get("csv"))
        start, count = req.get("start", 0), req.get("count", len(rows))
        for name, v, hi in (("start", start, len(rows)), ("count", count, None)):
            if isinstance(v, bool) or not isinstance(v, int) or v < 0 or (hi is not None and v > hi):
                raise InputError(f"batch.{name}", code="integer_range", lo=0,
                                 hi=hi if hi is not None else "N", got=shown(v))
        names = bt.output_columns(columns)
        out = bt.batch_rows(req["csv"], start, count)
    except InputError:
        raise
    except ValueError as e:
        raise InputError("input", code="json_invalid", detail=" ".join(str(e).split())) from None
    return {"total": len(rows), "columns": names,
            "rows": [[r.get(n, "") for n in names] for r in out],
            "csv": bt.to_csv(names, out, start == 0)}


_TRACE_KEYS = ("code", "target", "set", "global_q", "define", "undefine", "entry", "zero_unset")
_PROVE_KEYS = _TRACE_KEYS + ("range", "budget")
_SEQUENCE_KEYS = _TRACE_KEYS + ("calls", "table", "gen")


def _request_object(req, keys: tuple) -> None:
    """A request that is a JSON object of ``keys`` only (the first unknown key, sorted, named)."""
    if not isinstance(req, dict):
        raise InputError("input", code="not_object", got=shown(req))
    unknown = set(req) - set(keys)
    if unknown:
        raise InputError(key_path("", sorted(unknown, key=str)[0]), code="unknown_field",
                         expected=", ".join(keys))


def _trace_request(req, keys: tuple) -> tuple:
    """The checked fields of a tracer request: (code, defines, sets, zero_unset)."""
    _request_object(req, keys)
    zero_unset = req.get("zero_unset", False)
    if not isinstance(zero_unset, bool):
        raise InputError("zero_unset", code="not_flag", got=shown(zero_unset))
    defines = req.get("define") or []
    if not isinstance(defines, list):
        raise InputError("define", code="trace_define_list")
    sets = req.get("set") or {}
    if not isinstance(sets, dict):
        raise InputError("set", code="not_object", got=shown(sets))
    return req.get("code", ""), defines, sets, zero_unset


def _undefines(req) -> list:
    undefines = req.get("undefine") or []
    if not isinstance(undefines, list):
        raise InputError("undefine", code="trace_define_list")
    return undefines


def _trace(req) -> dict:
    """One call, or with ``calls``/``table``/``gen`` a sequence of calls
    (:func:`pulab.ctrace.sequence.trace_sequence`)."""
    from .ctrace import trace
    if isinstance(req, dict) and ("calls" in req or "table" in req or "gen" in req):
        from .ctrace.sequence import trace_sequence
        code, defines, sets, zero_unset = _trace_request(req, _SEQUENCE_KEYS)
        reply = trace_sequence(code, req.get("target", "c28x"), req.get("calls"),
                               req.get("table"), sets, req.get("global_q"), defines,
                               req.get("entry") or None, zero_unset, _undefines(req),
                               req.get("gen"))
        reply.pop("ok", None)
        return reply
    code, defines, sets, zero_unset = _trace_request(req, _TRACE_KEYS)
    reply = trace(code, req.get("target", "c28x"), sets, req.get("global_q"), defines,
                  req.get("entry") or None, zero_unset, _undefines(req))
    reply.pop("ok", None)
    return reply


def _trace_prove(req):
    """The code proof (:mod:`pulab.ctrace.prove`), in slices: the tracer's request plus
    ``range`` {NAME: [lo, hi]} and ``budget``."""
    from .ctrace.prove import DEFAULT_BUDGET, prove_code_steps
    code, defines, sets, zero_unset = _trace_request(req, _PROVE_KEYS)
    proof = yield from prove_code_steps(code, req.get("target", "c28x"), req.get("entry") or None,
                                        req.get("range"), sets, defines, req.get("global_q"),
                                        req.get("budget", DEFAULT_BUDGET), zero_unset,
                                        _undefines(req))
    return {"proof": proof}


def _trace_examples(req) -> dict:
    from .ctrace import TARGETS
    from .ctrace.examples import EXAMPLES
    return {"targets": list(TARGETS), "examples": [{"id": k, **v} for k, v in EXAMPLES.items()]}


_AUDIT_KEYS = ("files", "profile", "define")


def _audit(req) -> dict:
    """A vendor's generated headers read back (:func:`pulab.analyses.audit.audit`):
    ``files`` [{"name", "text"}], ``profile`` (optional), ``define`` [NAME[=VALUE]]."""
    from .analyses.audit import audit
    _request_object(req, _AUDIT_KEYS)
    files = req.get("files")
    if not isinstance(files, list) or not files:
        raise InputError("files", code="audit_no_files")
    pairs = []
    for k, f in enumerate(files):
        if not isinstance(f, dict):
            raise InputError(f"files[{k}]", code="not_object", got=shown(f))
        pairs.append((f.get("name") if isinstance(f.get("name"), str) else "", f.get("text")))
    defines = req.get("define") or []
    if not isinstance(defines, list) or not all(isinstance(d, str) for d in defines):
        raise InputError("define", code="trace_define_list")
    profile = req.get("profile")
    return {"audit": audit(pairs, profile if profile not in ("", None) else None, defines)}


def _vendor_input(req) -> dict:
    if not isinstance(req, dict):
        raise InputError("request", code="not_json_object")
    inp = req.get("input")
    if not isinstance(inp, dict):
        raise InputError("input", code="not_json_object")
    return inp


def _vendors(action: str):
    def handler(req) -> dict:
        from . import profiles
        from .profiles.translate import translate
        inp = _vendor_input(req)
        if action == "header":
            name = req.get("profile")
            profiles.registry.get(name)  # before the report: a typo should not cost a report
            require_pmsm(inp)
            r = report({**inp, "profiles": inp.get("profiles") or {}})
            return {"text": profiles.header(r, name)}
        return {"translation": translate(inp, req.get("from"), req.get("axis", "q"),
                                         req.get("values"))}
    return handler


def _prove(op: str):
    """The family proof's kinds (:mod:`pulab.analyses.prove`): ``prove`` (every integer, in
    slices), ``prove.plan`` (the integer names and the raw box), ``prove.integer`` with
    ``name`` (one entry, in slices: a page proves integer by integer to show progress),
    ``prove.summary`` with ``integers`` (the entries → the whole result) and
    ``prove.propose`` (each constant's finest format in its vendor's form,
    :mod:`pulab.analyses.propose`)."""
    def handler(req):
        from .analyses import prove as pv  # imported on first use: report-only pages stay lean
        body = {k: v for k, v in req.items() if k not in ("op", "name", "integers")} \
            if isinstance(req, dict) else req
        if op == "prove":
            return {"proof": (yield from pv.prove_steps(body))}
        problem = pv.make_problem(body)
        if op == "plan":
            return {"plan": {"names": list(problem.names),
                             "raw_box": {k: list(v) for k, v in problem.box.items()}}}
        if op == "integer":
            name = req.get("name")
            if not isinstance(name, str):
                raise InputError("prove.name", code="not_string", got=shown(name))
            return {"integer": (yield from pv.integer_steps(problem, name))}
        if op == "summary":
            entries = req.get("integers")
            if not isinstance(entries, dict) or not all(
                    isinstance(e, dict) and "verdict" in e for e in entries.values()):
                raise InputError("prove.integers", code="not_object", got=shown(entries))
            return {"proof": pv.summary(problem, entries)}
        from .analyses.propose import propose
        return {"proposal": propose(body)}
    return handler


def _course(action: str):
    """The course's exercises (:mod:`pulab.analyses.exercises`; docs/contract.md, "Course")."""
    def handler(req) -> dict:
        from .analyses import exercises
        if action == "spec":
            return {"exercises": exercises.spec()}
        if not isinstance(req, dict):
            raise InputError("request", code="not_json_object")
        if action == "trainees":
            start = parse_int(req.get("start", 1), "start")
            count = parse_int(req.get("count", 10), "count")
            if not 1 <= count <= 200:
                raise InputError("count", code="integer_range", lo=1, hi=200, got=shown(count))
            return {"trainees": [{"n": n, "input": exercises.trainee_input(n)}
                                 for n in range(start, start + count)]}
        inp = _vendor_input(req)
        if action == "answers":
            return {"answers": exercises.answers(inp)}
        return {"result": exercises.check(inp, req.get("id"), req.get("answer"))}
    return handler


#: Every request kind (the one dispatch key) → (the field its unreadable text is named by,
#: its handler: parsed request → the reply's fields).  ``report`` is the one computed in
#: slices (its handler is a generator).
KINDS = {
    "report": ("input", _report_steps),
    "qcalc": ("qcalc", qcalc),
    "export.header": ("input", _export("header")),
    "export.csv_current": ("input", _export("csv_current")),
    "export.csv_pll": ("input", _export("csv_pll")),
    "sweep": ("sweep", _sweep("sweep")),
    "sweep.plan": ("sweep", _sweep("plan")),
    "sweep.chunk": ("sweep", _sweep("chunk")),
    "sweep.merge": ("sweep", _sweep("merge")),
    "batch": ("batch", _batch),
    "trace": ("input", _trace),
    "trace.examples": ("input", _trace_examples),
    "trace.prove": ("input", _trace_prove),
    "vendors.header": ("input", _vendors("header")),
    "vendors.translate": ("input", _vendors("translate")),
    "audit": ("input", _audit),
    **{f"prove.{op}" if op != "prove" else "prove": ("prove", _prove(op))
       for op in ("prove", "plan", "integer", "summary", "propose")},
    "course.spec": ("input", _course("spec")),
    "course.check": ("input", _course("check")),
    "course.answers": ("input", _course("answers")),
    "course.trainees": ("input", _course("trainees")),
}
#: The kinds whose handlers are generators (computed in slices).
_STEPPED = {"report", "prove", "prove.plan", "prove.integer", "prove.summary", "prove.propose",
            "trace.prove"}


def _answer(kind, req):
    """A generator: the JSON reply of ``kind`` on the parsed request ``req``."""
    try:
        if kind not in KINDS:
            raise InputError("kind", code="not_choice", choices=", ".join(KINDS), got=shown(kind))
        handler = KINDS[kind][1]
        out = (yield from handler(req)) if kind in _STEPPED else handler(req)
        return json.dumps({"ok": True, **out}, allow_nan=False)
    except InputError as e:
        return _fail(e)


def call_json_steps(kind: str, text: str):
    """:func:`call_json` in slices: a generator that yields None between slices (of a report's
    simulation; other kinds return at once) and returns the same JSON text; closing it
    cancels the computation."""
    try:
        req = parse(text, KINDS[kind][0] if kind in KINDS else "input")
    except InputError as e:
        return _fail(e)
    return (yield from _answer(kind, req))


def call_json(kind: str, text: str) -> str:
    """The reply of request ``kind`` (a key of :data:`KINDS`) on the JSON ``text``.

    Returns ``{"ok": true, ...}`` with the kind's reply (docs/contract.md, "API"), or
    ``{"ok": false, "field", "message", "message_zh", "code", "params"}``.
    """
    return finish(call_json_steps(kind, text))
