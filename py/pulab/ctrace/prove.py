"""Code proof: per statement of traced C code, no overflow, wrap or conversion loss for every
input in a box — or a concrete input that causes one.

The box (each ranged input ``NAME`` → integers ``[lo, hi]`` of its type; the other inputs keep
one value) is run by :class:`~pulab.ctrace.abstract.BoxEvaluator` (the tracer's own statements
over intervals).  A box is split in two (along an input the undecided statement read, else the
relatively widest) when it does not decide the control flow, or when a statement may fail
there and no counterexample for that statement is known yet; each box that may fail is first
searched for one by running the concrete tracer at its centre and corners (an undecided box:
at its centre).  A counterexample is reported only after the concrete trace at that point
raises the failure on that statement, so ``violated`` is always reproducible, and ``proven``
holds for every point of the box because every interval run is sound.  Work (interval runs +
concrete runs) is capped by ``budget``.  The search itself — largest box first, the budget,
the slices — is :func:`pulab.fixedpoint.boxsearch.search`, the family proof's too
(:mod:`pulab.analyses.prove`); this module gives it what a box of C evaluates to and which
points it traces.

Verdict of a statement: ``violated`` (a counterexample), ``proven`` (every part of the box lies
in a box whose interval run completed without the statement failing there — a box left when the
budget ran out counts with the run of the box it was split from), ``unknown`` (otherwise;
``proven_fraction`` is the share of the box's points, by count, where it is proven so).

Examples
--------
>>> code = "int16 add(int16 a, int16 b) { int16 s = a + b; return s; }"
>>> r = prove_code(code, "arm", "add", {"a": [0, 100], "b": [0, 30000]})
>>> r["verdict"], [s["verdict"] for s in r["statements"]], r["statements"][0]["range"]
('proven', ['proven', 'proven'], [0, 30100])
>>> r = prove_code(code, "arm", "add", {"a": [0, 10000], "b": [0, 30000]})
>>> r["verdict"], r["statements"][0]["kind"], r["counterexample"]
('violated', 'conversion', {'a': 10000, 'b': 30000})
"""

from __future__ import annotations

import math
import random
import re

from ..analyses.slices import finish
from ..fixedpoint.boxsearch import halve, headroom_bits, search, volume
from ..fixedpoint.cint import CType
from ..schema.errors import InputError
from ..schema.validate import key_path, shown
from .abstract import FAILURES, BoxEvaluator, Split
from .errors import TraceError
from .parser import If, Loop, NodeVisitor, Stmt, Switch
from .tracing import DEFAULT_GLOBAL_Q, input_values, compile_code, inputs_for, run_checked

__all__ = ["prove_code", "prove_code_steps", "DEFAULT_BUDGET", "MAX_BUDGET"]

#: Runs (interval runs of a box plus concrete runs of a point) when the request sets none.
DEFAULT_BUDGET = 3000
MAX_BUDGET = 1_000_000
#: Seconds of work between two yields of :func:`prove_code_steps` (a run can be long: a loop).
_SLICE_S = 0.02
#: Corners tried concretely in a box that may fail (all of them up to this many).
_CORNERS = 8


def _ranges(checked, ranges, names: list) -> dict:
    """The box; ``names`` the inputs (with the pointer inputs given, see
    :func:`~pulab.ctrace.tracing.inputs_for`)."""
    if not isinstance(ranges, dict) or not ranges:
        raise InputError("range", code="prove_no_ranges")
    box = {}
    for name, pair in ranges.items():
        path = name.strip().replace("->", ".") if isinstance(name, str) else name
        field = key_path("range", path)
        if path not in names or path in checked.pointers:  # a pointer has no range
            raise InputError(field, code="prove_not_input", inputs=", ".join(
                n for n in names if n not in checked.pointers) or "none")
        if not isinstance(pair, (list, tuple)) or len(pair) != 2:
            raise InputError(field, code="prove_pair", got=shown(pair))
        ends = []
        for v in pair:
            if isinstance(v, str):
                try:
                    v = int(v.strip().replace("_", ""), 0)
                except ValueError:
                    raise InputError(field, code="prove_pair", got=shown(v)) from None
            if isinstance(v, bool) or not isinstance(v, int):
                raise InputError(field, code="prove_pair", got=shown(v))
            ends.append(v)
        lo, hi = ends
        if lo > hi:
            raise InputError(field, code="prove_order", lo=lo, hi=hi)
        t = checked.symbols[path].ctype
        for v in (lo, hi):
            if not t.min <= v <= t.max:
                raise InputError(field, code="integer_range", lo=t.min, hi=t.max, got=v)
        box[path] = (lo, hi)
    return box


class _Statements(NodeVisitor):
    """Every statement node below the nodes visited, with loop steps, in source order."""

    def __init__(self) -> None:
        self.found: list = []

    def generic_visit(self, node) -> None:
        if isinstance(node, Stmt):  # an expression holds no statement
            self.found.append(node)
            super().generic_visit(node)

    def visit_Loop(self, s: Loop) -> None:
        self.found.append(s)
        if s.init is not None:
            self.visit(s.init)
        if s.step is not None:
            self.found.append(s.step)  # the step expression counts as a statement
        self.visit(s.body)


def _statements(program) -> list:
    """Every statement node of the code (functions included), with loop steps."""
    walk = _Statements()
    for s in program.statements:
        walk.visit(s)
    for f in program.functions.values():
        walk.visit(f.body)
    return walk.found


class _Problem:
    """The compiled code, the box, the fixed inputs and the statements' positions."""

    def __init__(self, checked, box: dict, fixed: dict, global_q: int) -> None:
        self.checked, self.box, self.fixed, self.global_q = checked, box, fixed, global_q
        self.names = list(box)
        self.inputs = checked.inputs  # with the pointer inputs given: set by the caller
        source = checked.program.source
        self.source = source
        self.line_starts = [0] + [m.end() for m in re.finditer("\n", source)]
        self.nodes = {(n.line, n.column): n for n in _statements(checked.program)}

    def text(self, node) -> str:
        src = self.source
        if type(node) is If:
            return f"if ({src[node.test.start:node.test.end]})"
        if type(node) in (Loop, Switch) and node.test is not None:
            return f"{getattr(node, 'kind', 'switch')} ({src[node.test.start:node.test.end]})"
        return " ".join(src[node.start:node.end].split())

    def point_inputs(self, point: dict) -> dict:
        return {**self.fixed, **point}

    def concrete(self, point: dict) -> dict:
        """The failures the tracer shows at ``point``: (line, column) → set of kinds."""
        out: dict = {}
        try:
            ev = run_checked(self.checked, self.point_inputs(point), self.global_q)
        except TraceError as e:
            kind = _error_kind(e)
            key = self.statement_at(e.line, e.column)
            if kind is not None and key is not None:
                out.setdefault(key, set()).add(kind)
            return out

        def walk(steps) -> None:
            for s in steps:
                kinds = {f for f in s["flags"] if f in FAILURES}
                if kinds and not s.get("input"):
                    out.setdefault((s["line"], s["column"]), set()).update(kinds)
                for t in s.get("terms", ()):
                    if "steps" in t:
                        walk(t["steps"])
        walk(ev.steps)
        return out

    def statement_at(self, line: int, column: int):
        """The innermost statement whose text holds the position."""
        if not 1 <= line <= len(self.line_starts):
            return None
        at = self.line_starts[line - 1] + column - 1
        inside = [n for n in self.nodes.values() if n.start <= at < n.end]
        if not inside:
            return None
        n = min(inside, key=lambda n: n.end - n.start)
        return (n.line, n.column)


def _error_kind(e: TraceError):
    code = e.reason_error()["code"]
    if code == "trace_steps":
        return None  # the tracer's statement cap, not a failure of the code
    if code == "trace_index":
        return "index"
    if code in ("trace_division_zero", "trace_remainder_zero"):
        return "division_by_zero"
    return "error"


def _points(box: dict, rng: random.Random, corners: bool = True) -> list:
    """The centre, then corners (all when few, else a sample), of a box."""
    names = list(box)
    pts = [{n: (lo + hi) // 2 for n, (lo, hi) in box.items()}]
    if not corners:
        return pts
    wide = [n for n in names if box[n][0] != box[n][1]]
    if 1 << len(wide) <= _CORNERS:
        masks = range(1 << len(wide))
    else:
        masks = rng.sample(range(1 << len(wide)), _CORNERS) if len(wide) < 60 else \
            [rng.getrandbits(len(wide)) for _ in range(_CORNERS)]
    for m in masks:
        pts.append({n: box[n][(m >> wide.index(n)) & 1] if n in wide else box[n][0]
                    for n in names})
    return pts


def _split(box: dict, root: dict, hint=()) -> tuple:
    """Halve the box along the input widest relative to its whole range, among the inputs
    in ``hint`` (those an undecided statement read) when one of them can be split."""
    wide = [n for n in box if box[n][0] < box[n][1]]
    return halve(box, max([n for n in wide if n in hint] or wide,
                          key=lambda n: (box[n][1] - box[n][0]) / (root[n][1] - root[n][0] + 1)))


def _parse_real(field: str, pair) -> tuple:
    """``[LO, HI]`` in real units (numbers or numeric text) of an ``@q auto`` input."""
    if not isinstance(pair, (list, tuple)) or len(pair) != 2:
        raise InputError(field, code="prove_pair", got=shown(pair))
    ends = []
    for v in pair:
        try:
            x = float(v.strip()) if isinstance(v, str) else float(v)
        except (TypeError, ValueError):
            raise InputError(field, code="prove_pair", got=shown(v)) from None
        if isinstance(v, bool) or not math.isfinite(x):
            raise InputError(field, code="prove_pair", got=shown(v))
        ends.append(x)
    if ends[0] > ends[1]:
        raise InputError(field, code="prove_order", lo=ends[0], hi=ends[1])
    return ends[0], ends[1]


def _round(x: float) -> int:
    """Round half away from zero (C's ``lround``); x·2^n is exact in binary floating point."""
    return int(math.floor(x + 0.5)) if x >= 0 else -int(math.floor(-x + 0.5))


def _raw(real: tuple, n: int) -> tuple:
    return _round(math.ldexp(real[0], n)), _round(math.ldexp(real[1], n))


def prove_code_steps(code: str, target: str = "c28x", entry: str | None = None,
                     ranges: dict | None = None, inputs: dict | None = None, defines=None,
                     global_q: int | None = None, budget: int = DEFAULT_BUDGET,
                     zero_unset: bool = False, undefines=None):
    """:func:`prove_code` in slices: a generator that yields None between slices of runs and
    returns the result; closing it cancels the proof."""
    if isinstance(budget, bool) or not isinstance(budget, int) or not 1 <= budget <= MAX_BUDGET:
        raise InputError("budget", code="integer_range", lo=1, hi=MAX_BUDGET, got=shown(budget))
    checked = compile_code(code, target, defines, global_q, entry, undefines)
    notes = checked.program.notes
    auto = [n for n in checked.inputs if n in notes and notes[n].q is None]
    if not isinstance(ranges, dict):
        ranges = {}
    real = {}
    for name in auto:
        field = key_path("range", name)
        if name not in ranges:
            raise InputError(field, code="prove_auto_range", name=name)
        real[name] = _parse_real(field, ranges[name])
    names = inputs_for(checked, inputs if isinstance(inputs, dict) else {})
    box = _ranges(checked, {k: (v if k not in real else [0, 0]) for k, v in ranges.items()},
                  names)
    sets = {k: v for k, v in (inputs or {}).items()
            if (k.strip().replace("->", ".") if isinstance(k, str) else k) not in box}
    fixed = input_values(checked, sets, zero_unset)
    gq = checked.program.global_q or global_q or DEFAULT_GLOBAL_Q
    pb = _Problem(checked, box, fixed, gq)
    pb.inputs = names
    if not auto:
        out = yield from _search(pb, box, budget)
    else:
        # In declaration order, each the finest Q proven with those before it fixed and those
        # after it at Q0; the proof reported is the one at the formats proposed.
        chosen = {name: 0 for name in auto}
        proposals, out = {}, None
        for name in auto:
            t = checked.symbols[name].ctype
            tried, best = {}, None
            for n in range(62, -1, -1):
                lo, hi = _raw(real[name], n)
                if not (t.min <= lo and hi <= t.max):
                    continue  # the range does not fit the word with n fractional bits
                trial = {**box, **{k: _raw(real[k], q) for k, q in chosen.items()},
                         name: (lo, hi)}
                pb.box = trial
                r = yield from _search(pb, trial, budget)
                tried[n] = r["verdict"]
                if r["verdict"] == "proven":
                    best, out = n, r
                    break
                out = r if best is None else out
            chosen[name] = best if best is not None else 0
            scale = max(abs(real[name][0]), abs(real[name][1]))
            proposals[name] = {
                "q": best, "type": t.name, "bits": t.bits, "signed": t.signed,
                "range_real": list(real[name]),
                "raw_range": list(_raw(real[name], best)) if best is not None else None,
                "max_error": math.ldexp(0.5, -best) if best is not None else None,
                "max_error_pct": 100 * math.ldexp(0.5, -best) / scale
                if best is not None and scale > 0 else None,
                "tried": {str(k): v for k, v in tried.items()}}
        if out is None:  # no Q fits any auto input's word
            pb.box = {**box, **{k: _raw(real[k], 0) for k in auto}}
            out = yield from _search(pb, pb.box, budget)
        out["proposals"] = {**out.get("proposals", {}), **proposals}
        out["real"] = {k: list(v) for k, v in real.items()}
    return out


def _search(pb: _Problem, box: dict, budget: int):
    """The proof over ``box`` (see the module text); a generator, as :func:`prove_code_steps`."""
    checked, fixed, gq = pb.checked, pb.fixed, pb.global_q
    fixed_box = {k: (v, v) for k, v in fixed.items()}
    total = volume(box)
    rng = random.Random(2026)
    stats: dict = {}   # (line, column) → per-statement tally
    cx: dict = {}      # (line, column) → (point, kinds) reproduced by the tracer
    decided = 0        # points in final boxes that ran to the end
    credited = 0       # … and in boxes left to the budget whose enclosing box's run completed
    clean = 0          # points of credited boxes where no statement may fail
    finals = 0

    def stat(key, rec=None) -> dict:
        s = stats.get(key)
        if s is None:
            s = stats[key] = {"lo": None, "hi": None, "ctype": None, "var": None, "may": set(),
                              "failing": 0, "exact": None}
        if rec is not None:
            s["var"] = s["var"] or rec["var"]
            if rec["ctype"] is not None:
                s["ctype"] = rec["ctype"]
        return s

    def account(records: dict, vol: int) -> None:
        """A box whose interval run completed: its statements' ranges and failures (a
        statement it does not reach cannot fail there)."""
        nonlocal credited, clean
        credited += vol
        clean += 0 if any(r["kinds"] for r in records.values()) else vol
        for key, r in records.items():
            s = stat(key, r)
            if r["lo"] is not None:
                s["lo"] = r["lo"] if s["lo"] is None else min(s["lo"], r["lo"])
                s["hi"] = r["hi"] if s["hi"] is None else max(s["hi"], r["hi"])
            if r["exact"] is not None:
                e = s["exact"]
                s["exact"] = r["exact"] if e is None else (min(e[0], r["exact"][0]),
                                                           max(e[1], r["exact"][1]))
            if r["kinds"]:
                s["failing"] += vol
                s["may"].update(r["kinds"])

    def visit(_key, b, _run):
        nonlocal decided, finals
        vol = volume(b)
        work = 1
        hint = ()
        try:
            records = BoxEvaluator.over(checked, {**fixed_box, **b}, gq).run_box()
        except Split as e:
            records, hint = None, e.reads
        failing = {} if records is None else \
            {k: r["kinds"] for k, r in records.items() if r["kinds"]}
        open_fail = [k for k in failing if k not in cx]
        if open_fail or records is None:
            # A box that may fail: its centre and corners; one the run cannot decide: its
            # centre (all of its points when it is the whole box), so that a failure behind
            # an undecided loop or index is found before the box is cut down to points.
            pts = _points(b, rng, bool(open_fail) or vol == total)
            for pt in pts:
                work += 1
                for key, kinds in pb.concrete(pt).items():
                    stat(key)["may"].update(kinds)
                    if key not in cx:
                        cx[key] = (pt, kinds)
            open_fail = [k for k in failing if k not in cx]
        if vol > 1 and (records is None or open_fail):
            # The halves carry this box's run: what holds of them if the budget runs out.
            return work, [(-volume(half), half, records) for half in _split(b, box, hint)]
        finals += 1
        if records is not None:  # else one point the interval run cannot finish (step cap)
            decided += vol
            account(records, vol)
        return work, ()

    work, left = yield from search(box, -total, visit, budget, seconds=_SLICE_S)
    for _, _, b, inherited in left:  # the budget ran out: their enclosing box's run holds
        if inherited is not None:
            account(inherited, volume(b))
    for key in cx:
        stat(key)
    statements = []
    first_cx = None
    for key in sorted(stats):
        s = stats[key]
        node = pb.nodes.get(key)
        t: CType | None = s["ctype"]
        fraction = (credited - s["failing"]) / total
        entry_d = {"line": key[0], "column": key[1],
                   "code": pb.text(node) if node is not None else "", "var": s["var"],
                   "type": t.name if t is not None else None,
                   "word": [t.min, t.max] if t is not None else None,
                   "range": [s["lo"], s["hi"]] if s["lo"] is not None else None,
                   "computed": list(s["exact"]) if s["exact"] is not None else None,
                   "proven_fraction": fraction}
        if key in cx:
            pt, kinds = cx[key]
            entry_d.update(verdict="violated", kinds=[k for k in FAILURES if k in kinds],
                           counterexample=pb.point_inputs(pt))
            if first_cx is None:
                first_cx = entry_d["counterexample"]
        elif credited == total and s["failing"] == 0:
            entry_d.update(verdict="proven", kinds=[])
        else:
            entry_d.update(verdict="unknown", kinds=[k for k in FAILURES if k in s["may"]])
        entry_d["kind"] = entry_d["kinds"][0] if entry_d["kinds"] else None
        entry_d["headroom_bits"] = headroom_bits(entry_d["range"], entry_d["word"]) \
            if entry_d["verdict"] == "proven" and entry_d["range"] is not None and \
            entry_d["var"] is not None else None
        statements.append(entry_d)
    verdicts = {s["verdict"] for s in statements}
    verdict = "violated" if "violated" in verdicts else \
        "proven" if credited == total and verdicts <= {"proven"} else "unknown"
    out = {"verdict": verdict, "target": checked.target.name, "global_q": gq,
           "entry": checked.entry.name if checked.entry is not None else None,
           "inputs": pb.inputs, "box": {k: list(v) for k, v in box.items()},
           "set": fixed, "budget": budget, "work": work, "boxes": finals,
           "decided_fraction": decided / total, "proven_fraction": clean / total,
           "statements": statements}
    if first_cx is not None:
        out["counterexample"] = first_cx
    if credited == total:  # every point's stores are in the hulls: a local's proposal holds
        locals_ = _local_proposals(checked, statements)
        if locals_:
            out["proposals"] = locals_
    return out


def _local_proposals(checked, statements: list) -> dict:
    """For each local ``// @q NAME auto`` that some statement stores: the hull of what its
    stores compute (before conversion, over the whole box) and the shift of its scaling that
    keeps every one of them in its word — k > 0 more fractional bits, or k < 0 to drop (the
    store then holding ``value >> −k``, which loses up to 2^−k − 1 of the current LSB)."""
    out = {}
    for name, note in checked.program.notes.items():
        if note.q is not None or name in checked.inputs or name not in checked.symbols:
            continue
        ends = [s["computed"] for s in statements if s["var"] == name and s["computed"]]
        t = checked.symbols[name].ctype
        if not ends or not isinstance(t, CType):
            continue
        lo, hi = min(e[0] for e in ends), max(e[1] for e in ends)
        if t.min <= lo and hi <= t.max:
            shift = headroom_bits((lo, hi), (t.min, t.max))
        else:
            shift = -1
            while not (t.min <= lo >> -shift and hi >> -shift <= t.max):
                shift -= 1
        out[name] = {"local": True, "type": t.name, "bits": t.bits, "signed": t.signed,
                     "computed": [lo, hi], "shift": shift,
                     "max_error_lsb": (1 << -shift) - 1 if shift < 0 else 0}
    return out


def prove_code(code: str, target: str = "c28x", entry: str | None = None,
               ranges: dict | None = None, inputs: dict | None = None, defines=None,
               global_q: int | None = None, budget: int = DEFAULT_BUDGET,
               zero_unset: bool = False, undefines=None) -> dict:
    """Prove every statement of ``code`` free of overflow, wrap and conversion loss over a box.

    Parameters
    ----------
    code : str
        C code of the tracer's subset (:func:`pulab.ctrace.trace`).
    target : {'c28x', 'avr', 'msp430', 'arm'}
    entry : str, optional
        The function to run (its parameters, ``p.FIELD`` and globals are the inputs).
    ranges : dict
        Input name → ``[lo, hi]``, integers of the input's type (at least one).
    inputs : dict, optional
        Input name → integer for the inputs without a range (as :func:`~pulab.ctrace.trace`'s).
    defines, global_q, zero_unset, undefines
        As for :func:`~pulab.ctrace.trace`.
    budget : int in 1..1000000
        Runs allowed (interval runs of a box + concrete runs of a point).

    Returns
    -------
    dict
        ``verdict`` (``proven`` | ``violated`` | ``unknown``), ``statements`` (per statement
        reached: ``line``, ``column``, ``code``, ``var``, ``type``, ``word`` [min, max],
        ``verdict``, ``kinds`` and ``kind`` (the first) of failure, ``range`` [lo, hi] of
        the value it computes over the part of the box its proof covers, ``computed`` (the
        exact value before its store's conversion), ``proven_fraction``, and
        ``counterexample`` (every input's value) when violated), ``counterexample`` (the
        first statement's), ``proven_fraction`` (the share of the box where no statement
        may fail), ``box``, ``set``, ``work``, ``boxes``, ``decided_fraction``.

    Raises
    ------
    InputError
        Bad code, target, range, input value or budget.
    """
    return finish(prove_code_steps(code, target, entry, ranges, inputs, defines, global_q,
                                   budget, zero_unset, undefines))
