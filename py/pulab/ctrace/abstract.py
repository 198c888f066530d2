"""The tracer's evaluator over a box of inputs: every value as an interval, every flag a "may".

:class:`BoxEvaluator` is :class:`~pulab.ctrace.evaluate.Evaluator` with each scalar value an
:class:`~pulab.fixedpoint.interval.ICInt` ``[lo, hi]`` of its C type instead of one integer.
The statements, places, calls and conversions are the tracer's own code; only the operators
are replaced by their interval versions, computed from the exact integer bounds and then
converted with C's modulo rule, so every value the tracer computes for a point of the box
lies in the interval and every flag it raises there is raised here (sound by construction).

Control flow that the box does not decide:

- ``if`` and ``?:`` run both sides, each with the condition's variables narrowed
  (``x > 100`` makes ``x`` at least 101 on the true side), and join the memories (the hull
  of each variable; a variable set on one side only may be unset);
- ``&&`` / ``||`` evaluate the right side on a copy and join;
- ``switch`` runs every label the value can reach (and ``default``) on a copy and joins;
- a ``return`` on one side is kept with its memory and joined at the function's end;
- a loop test, an index, a ``break`` or ``continue`` on one side, or a pointer that
  differs between the sides raise :class:`Split`: the caller splits the box (a box of
  one point always decides, as it is the concrete trace).

A run records, per statement (line, column), the failure kinds it may raise
(:data:`FAILURES`) and the hull of the value it computes.

Examples
--------
>>> from .tracing import compile_code
>>> checked = compile_code("int16 a; int16 b; int16 s = a + b;", "arm")
>>> ev = BoxEvaluator.over(checked, {"a": (0, 20000), "b": (0, 20000)}, 24)
>>> rec = ev.run_box()[(1, 19)]
>>> rec["lo"], rec["hi"], sorted(rec["kinds"])  # the values stored: 40000 wraps
(-32768, 32767, ['conversion'])
"""

from __future__ import annotations

import math

from ..fixedpoint.cint import CType, convert, trunc_div
from ..fixedpoint.interval import ICInt
from .check import VOID
from .errors import TraceError
from .evaluate import Evaluator, _Jump, _Return
from .iqmath import iq_value
from .parser import Binary, Cast, Cond, If, Label, Logical, Member, Num, Unary, Var

__all__ = ["BoxEvaluator", "Split", "FAILURES", "decide"]

#: The failure kinds a statement is proven free of, in the order reports list them: the
#: tracer's flags that mean a changed value (signed overflow, unsigned wrap, a value-changing
#: conversion, a shift count out of range), then its run-time errors (a zero divisor, an index
#: outside its array, any other error the trace stops at).
FAILURES = ("signed_overflow", "unsigned_wrap", "conversion", "shift_count",
            "division_by_zero", "index", "error")

#: An integer type wide enough for every exact intermediate (a 64 × 64-bit product).
_WIDE = CType("exact", 160, True)
_COMPARES = ("<", ">", "<=", ">=", "==", "!=")
_NEGATED = {"<": ">=", ">=": "<", ">": "<=", "<=": ">", "==": "!=", "!=": "=="}


class Split(Exception):
    """The box does not decide a loop test, an index, a case or a join: split it.

    ``reads``: the places the undecided statement had read (a hint of which input to split).
    """

    def __init__(self, reads=()) -> None:
        super().__init__()
        self.reads = set(reads)


class _Dead(Exception):
    """Every path through here returned or stopped."""


class _Stop(Exception):
    """A failure every point of the box meets stops the run (the trace stops there too)."""


#: A variable set on one side of an undecided branch only.
_MAYBE = object()


def decide(v):
    """True, False, or None when the interval holds both zero and a non-zero value."""
    if isinstance(v, ICInt):
        if v.lo == v.hi == 0:
            return False
        return True if v.lo > 0 or v.hi < 0 else None
    if isinstance(v, int):
        return v != 0
    return v is not None  # a pointer: a path, or None for null


def _point(v: int, t: CType) -> ICInt:
    return ICInt(v, v, t)


def _fit(lo: int, hi: int, t: CType) -> tuple:
    """The exact interval ``[lo, hi]`` converted to ``t`` (C99 6.3.1.3, modulo 2**bits);
    and whether some value changed."""
    if t.name == "_Bool":
        one = lo > 0 or hi < 0
        v = ICInt(1, 1, t) if one else ICInt(0, 0, t) if lo == hi == 0 else ICInt(0, 1, t)
        return v, not (0 <= lo and hi <= 1)
    if t.min <= lo and hi <= t.max:
        return ICInt(lo, hi, t), False
    w = ICInt(lo, hi, _WIDE).cast(t)
    return ICInt(w.lo, w.hi, t), True


def _hull(values: list):
    """The join of values met on different paths (intervals: the hull)."""
    first = values[0]
    if all(isinstance(v, ICInt) for v in values):
        return ICInt(min(v.lo for v in values), max(v.hi for v in values), first.ctype)
    return first if all(v is first or v == first for v in values) else _MAYBE


def _join(mems: list) -> dict:
    if len(mems) == 1:
        return mems[0]
    keys = set().union(*mems)
    return {k: _hull([m.get(k, _MAYBE) for m in mems]) for k in keys}


def _bitwise(op: str, a: ICInt, b: ICInt) -> tuple:
    """Bounds of ``a & b``, ``a | b``, ``a ^ b`` in two's complement (exact for points)."""
    if a.lo == a.hi and b.lo == b.hi:
        x, y = a.lo, b.lo
        v = x & y if op == "&" else x | y if op == "|" else x ^ y
        return v, v
    for x, y in ((a, b), (b, a)):  # x & -1, x | 0, x ^ 0 are x
        if y.lo == y.hi == (-1 if op == "&" else 0):
            return x.lo, x.hi
    if op == "&" and (a.lo >= 0 or b.lo >= 0):  # a non-negative operand bounds the result
        return 0, min(x.hi for x in (a, b) if x.lo >= 0)
    k = max(max(abs(v) for v in (a.lo, a.hi, b.lo, b.hi)).bit_length(), 1)
    if min(a.lo, b.lo) >= 0:  # both in [0, 2**k): so is the result
        return (max(a.lo, b.lo) if op == "|" else 0), (1 << k) - 1
    return -(1 << k), (1 << k) - 1  # [-2**k, 2**k) is closed under & | ^


class BoxEvaluator(Evaluator):
    """One run of a checked program over a box of inputs (see the module text).

    Parameters
    ----------
    checked : Checked
    inputs : dict
        Input path → :class:`~pulab.fixedpoint.interval.ICInt` of its type.
    global_q : int in 1..30
    """

    def __init__(self, checked, inputs: dict, global_q: int) -> None:
        super().__init__(checked, inputs, global_q, record=False)
        self.cur: set = set()
        self.records: dict = {}
        self.pending: list = []
        self.current = None
        self.reads: set = set()
        #: The exact interval the statement's last store converted (before C's modulo rule).
        self.stored: tuple | None = None

    @classmethod
    def over(cls, checked, box: dict, global_q: int) -> "BoxEvaluator":
        """An evaluator for ``box`` (input path → (lo, hi) integers of its type; a pointer
        input → (object, object), its one value)."""
        syms = checked.symbols
        return cls(checked, {k: lo if k in checked.pointers else ICInt(lo, hi, syms[k].ctype)
                             for k, (lo, hi) in box.items()}, global_q)

    def run_box(self) -> dict:
        """Run; (line, column) → record ``{"kinds", "lo", "hi", "ctype", "var", "node",
        "exact"}`` of every statement reached (``exact``: the hull of what its last store
        converted, None when it stores nothing).  Raises :class:`Split` when the box does
        not decide."""
        try:
            self.run()
        except _Stop:
            pass
        except _Dead:
            pass
        except _Jump:
            raise Split() from None
        return self.records

    # -- what a statement may raise and the values it computes
    def note(self, node, kinds, value=None, ctype=None, var=None, exact=None) -> None:
        rec = self.records.get((node.line, node.column))
        if rec is None:
            rec = self.records[(node.line, node.column)] = {
                "kinds": set(), "lo": None, "hi": None, "ctype": None, "var": var, "node": node,
                "exact": None}
        if exact is not None:
            e = rec["exact"]
            rec["exact"] = exact if e is None else (min(e[0], exact[0]), max(e[1], exact[1]))
        rec["kinds"].update(k for k in kinds if k in FAILURES)
        if isinstance(value, int):
            value = _point(value, ctype)
        if isinstance(value, ICInt) and isinstance(ctype, CType):
            rec["ctype"] = ctype
            rec["lo"] = value.lo if rec["lo"] is None else min(rec["lo"], value.lo)
            rec["hi"] = value.hi if rec["hi"] is None else max(rec["hi"], value.hi)

    def term(self, node, value, flags: list, **extra) -> None:
        self.cur.update(flags)

    def step(self, stmt, code: str, var, value, ctype, **extra) -> None:
        if extra.get("input"):
            return
        kinds = self.cur | set(extra.get("flags", ()))
        self.cur = set()
        self.reads = set()
        exact, self.stored = self.stored, None
        self.note(stmt, kinds, value, ctype, var, exact)

    def fail(self, kind: str) -> None:
        """Every point of the box fails here: record it on the statement and stop."""
        self.note(self.current, self.cur | {kind})
        self.cur = set()
        raise _Stop()

    # -- control flow
    def truth(self, value) -> bool:
        d = decide(value)
        if d is None:
            raise Split(self.reads)
        return d

    def scalar(self, value) -> int:
        if isinstance(value, ICInt):
            if value.lo != value.hi:
                raise Split(self.reads)
            return value.lo
        return value

    def read(self, path: str, node):
        self.reads.add(path)
        if self.mem.get(path) is _MAYBE:
            raise Split(self.reads)
        return super().read(path, node)

    def statement(self, s) -> None:
        outer, self.current = self.current, s
        try:
            super().statement(s)
        except TraceError as e:
            if e.field.startswith("set."):
                raise  # an input without a value or range: bad input, not a failure
            code = e.reason_error()["code"]
            if code == "trace_steps":
                raise Split() from None  # a loop the box does not bound: smaller boxes may
            self.current = s
            self.fail("index" if code == "trace_index" else "error")
        finally:
            self.current = outer

    def sides(self, test, then, other, run) -> list:
        """Run ``run(then)`` and ``run(other)`` each on its own copy of memory with ``test``
        narrowed to true and to false; the memories after each (a side that returned is
        kept for its function's end).  Raises :class:`_Dead` when no side goes on."""
        base, outs = self.mem, []
        for side, truth in ((then, True), (other, False)):
            self.mem = dict(base)
            if not self.narrow(test, truth):
                continue  # the condition cannot take this value in the box
            try:
                outs.append((run(side), self.mem))
            except _Return as r:
                self.pending[-1].append((r.value, self.mem))
            except (_Dead, _Stop):
                pass
            except _Jump:
                raise Split() from None
        if not outs:
            raise _Dead()
        self.mem = _join([m for _, m in outs])
        return [v for v, _ in outs]

    def visit_If(self, s: If) -> None:
        v = self.eval(s.test)
        d = decide(v)
        taken = ICInt(0, 1, self.int) if d is None else _point(int(d), self.int)
        self.step(s, "if", None, taken, self.int)  # the trace shows the branch taken: 0 or 1
        if d is None:
            self.sides(s.test, s.then, s.other,
                       lambda side: self.statement(side) if side is not None else None)
        elif d:
            self.statement(s.then)
        elif s.other is not None:
            self.statement(s.other)

    def visit_Switch(self, s) -> None:
        """Every label the test's interval can reach runs on its own copy of memory (a plain
        variable tested is narrowed to the label's value), and so does ``default`` (or
        nothing, without one) when some value has no label; the memories are joined."""
        t = s.test.ctype
        v = self.eval(s.test)
        v = v if isinstance(v, ICInt) else _point(v, t)
        body = s.body.statements
        starts, seen, default = [], set(), None
        for i, inner in enumerate(body):
            if type(inner) is Label:
                c = None if inner.value_int is None else convert(inner.value_int, t)
                if c is None:
                    default = i
                elif v.lo <= c <= v.hi and c not in seen:
                    seen.add(c)
                    starts.append((i, c))
        rest = len(seen) < v.hi - v.lo + 1  # values without a label of their own
        self.step(s, "switch", None, v, t)
        if len(starts) == 1 and not rest or not starts and default is not None:
            self.run_case(body, starts[0][0] if starts else default)  # one way for every value
            return
        path = self.peek(s.test)[0] if _pure(s.test) else None
        base, outs = self.mem, []
        for i, c in starts + ([(default, None)] if rest else []):
            self.mem = dict(base)
            if path is not None and c is not None:
                self.mem[path] = _point(c, self.mem[path].ctype)
            if i is None:  # no default: those values run nothing
                outs.append(self.mem)
                continue
            try:
                self.run_case(body, i)
                outs.append(self.mem)
            except _Return as r:
                self.pending[-1].append((r.value, self.mem))
            except (_Dead, _Stop):
                pass
            except _Jump:
                raise Split(self.reads) from None
        if not outs:
            raise _Dead()
        self.mem = _join(outs)

    def narrow(self, test, truth: bool) -> bool:
        """Narrow the variables of ``test`` to the points where it is ``truth``; False when
        there are none.  Only comparisons of variables and constants are narrowed (and ``!``,
        and the conjuncts of a true ``&&`` or a false ``||``)."""
        kind = type(test)
        if kind is Unary and test.op == "!":
            return self.narrow(test.operand, not truth)
        if kind is Logical:
            if (test.op == "&&") == truth:
                return self.narrow(test.left, truth) and self.narrow(test.right, truth)
            return True
        if kind is not Binary or test.op not in _COMPARES:
            return True
        t = test.operand_type
        (pa, a), (pb, b) = self.peek(test.left), self.peek(test.right)
        if a is None or b is None or not (t.min <= min(a.lo, b.lo) and max(a.hi, b.hi) <= t.max):
            return True
        op = test.op if truth else _NEGATED[test.op]
        alo, ahi, blo, bhi = a.lo, a.hi, b.lo, b.hi
        if op == "<":
            ahi, blo = min(ahi, b.hi - 1), max(blo, a.lo + 1)
        elif op == "<=":
            ahi, blo = min(ahi, b.hi), max(blo, a.lo)
        elif op == ">":
            alo, bhi = max(alo, b.lo + 1), min(bhi, a.hi - 1)
        elif op == ">=":
            alo, bhi = max(alo, b.lo), min(bhi, a.hi)
        elif op == "==":
            alo, ahi = max(a.lo, b.lo), min(a.hi, b.hi)
            blo, bhi = alo, ahi
        else:  # !=: only an end that equals the other side's single value goes
            if b.lo == b.hi:
                alo, ahi = alo + (alo == b.lo), ahi - (ahi == b.lo)
            if a.lo == a.hi:
                blo, bhi = blo + (blo == a.lo), bhi - (bhi == a.lo)
        if alo > ahi or blo > bhi:
            return False
        for path, v, lo, hi in ((pa, a, alo, ahi), (pb, b, blo, bhi)):
            if path is not None:
                self.mem[path] = ICInt(lo, hi, v.ctype)
        return True

    def peek(self, e) -> tuple:
        """(path, interval) of a plain variable; (None, interval) of an expression without
        side effects (evaluated again, its flags already counted); else (None, None)."""
        path = e.sym.key if type(e) is Var else \
            e.flat.key if type(e) is Member and e.flat is not None else \
            self.place(e) if type(e) is Member and type(e.base) is Var else None
        if isinstance(path, str):
            v = self.mem.get(path)
            return (path, v) if isinstance(v, ICInt) else (None, None)
        if not _pure(e):
            return None, None
        cur, mem = self.cur, self.mem
        self.cur, self.mem = set(), dict(mem)
        try:
            v = self.eval(e)
        except (Split, TraceError, _Stop):
            v = None
        self.cur, self.mem = cur, mem
        return (None, v) if isinstance(v, ICInt) else (None, None)

    def body(self, f):
        self.pending.append([])
        depth = len(self.active)
        try:
            value = super().body(f)
            self.pending[-1].append((value, self.mem))
        except (_Dead, _Stop):
            pass
        except TraceError as e:  # a path falls off the end of a function that returns a value
            del self.active[depth:]
            if self.pending.pop():
                raise Split() from None  # other paths return: this one may not exist
            raise e
        del self.active[depth:]
        outs = self.pending.pop()
        if not outs:
            raise _Stop()
        self.mem = _join([m for _, m in outs])
        value = None if f.ret is VOID else _hull([v for v, _ in outs])
        if value is _MAYBE:  # paths that return different objects (a handle getter)
            raise Split(self.reads)
        return value

    def call_user(self, e):
        outer = self.cur  # the arguments' conversions belong to the calling statement
        value = super().call_user(e)
        self.cur = outer
        return value

    def aggregate(self, path: str, t, init) -> None:
        outer = set(self.cur)  # the tracer flags nothing in a braced initializer
        super().aggregate(path, t, init)
        self.cur = outer

    # -- values
    def store(self, value, ctype) -> tuple:
        if not isinstance(ctype, CType) or not isinstance(value, (ICInt, int)):
            return value, []
        lo, hi = (value.lo, value.hi) if isinstance(value, ICInt) else (value, value)
        w, changed = _fit(lo, hi, ctype)
        self.stored = (lo, hi)
        if changed:
            self.cur.add("conversion")
        return w, (["conversion"] if changed else [])

    def convert(self, value, t, flags: list):
        lo, hi = (value.lo, value.hi) if isinstance(value, ICInt) else (value, value)
        w, changed = _fit(lo, hi, t)
        if changed and "conversion" not in flags:
            flags.append("conversion")
        return w

    def eval(self, e):
        kind = type(e)
        if kind is Num:
            return _point(e.value, e.ctype)
        if kind is Logical:
            return self.logical(e)
        if kind is Cond:
            return self.conditional(e)
        return super().eval(e)

    def logical(self, e: Logical) -> ICInt:
        go_on = e.op == "&&"  # && evaluates its right side when the left is true, || when false
        a = decide(self.eval(e.left))
        if a is not None and a != go_on:
            v = _point(int(a), self.int)
        else:
            if a is None:
                base = self.mem
                self.mem = dict(base)
                self.narrow(e.left, go_on)
            r = decide(self.eval(e.right))
            rv = (0, 1) if r is None else (int(r), int(r))
            if a is None:
                self.mem = _join([base, self.mem])
                rv = (min(rv[0], int(not go_on)), max(rv[1], int(not go_on)))
            v = ICInt(rv[0], rv[1], self.int)
        self.term(e, v, [])
        return v

    def conditional(self, e: Cond):
        d = decide(self.eval(e.test))
        if d is not None:
            w, flags = self.store(self.eval(e.then if d else e.other), e.ctype)
        else:
            w = _hull(self.sides(e.test, e.then, e.other,
                                 lambda side: self.store(self.eval(side), e.ctype)[0]))
            flags = []
        self.term(e, w, flags)
        return w

    def arith(self, op: str, a, b, t, node) -> tuple:
        a, b = self.convert(a, t, []), self.convert(b, t, [])
        flags: list = []
        if op in ("/", "%"):
            if b.lo == b.hi == 0:
                self.fail("division_by_zero")
            if b.lo <= 0 <= b.hi:
                flags.append("division_by_zero")
        if op in ("+", "-", "*", "/"):
            if op == "+":
                lo, hi = a.lo + b.lo, a.hi + b.hi
            elif op == "-":
                lo, hi = a.lo - b.hi, a.hi - b.lo
            elif op == "*":
                c = [x * y for x in (a.lo, a.hi) for y in (b.lo, b.hi)]
                lo, hi = min(c), max(c)
            else:  # trunc(x / y) is monotone in x, and in y on each sign: the pieces' ends
                ys = [y for y in (b.lo, b.hi, -1, 1) if b.lo <= y <= b.hi and y != 0]
                c = [trunc_div(x, y) for x in (a.lo, a.hi) for y in ys]
                lo, hi = min(c), max(c)
            w, changed = _fit(lo, hi, t)
            return w, flags + ([_overflow(t)] if changed else [])
        if op == "%":
            if t.signed and a.lo == t.min and b.lo <= -1 <= b.hi:
                flags.append("signed_overflow")  # INT_MIN % -1 overflows as INT_MIN / -1 does
            if a.lo == a.hi and b.lo == b.hi:
                r = a.lo - trunc_div(a.lo, b.lo) * b.lo
                return _point(r, t), flags
            m = max(abs(b.lo), abs(b.hi)) - 1  # |a % b| < |b|, with the sign of a
            return ICInt(max(a.lo, -m) if a.lo < 0 else 0, min(a.hi, m) if a.hi > 0 else 0,
                         t), flags
        lo, hi = _bitwise(op, a, b)
        return _fit(lo, hi, t)[0], flags

    def shift(self, op: str, a, count, t) -> tuple:
        a = self.convert(a, t, [])
        c = count if isinstance(count, ICInt) else _point(count, t)
        flags: list = []
        values = []
        if c.lo < 0 or c.hi >= t.bits:  # the tracer shows a full shift: 0, or -1 for >> of < 0
            flags.append("shift_count")
            values += [0] + ([-1] if op == ">>" and a.lo < 0 else [])
        clo, chi = max(c.lo, 0), min(c.hi, t.bits - 1)
        if clo <= chi:  # x << n and x >> n are monotone in x and in n: extremes at corners
            corners = [x << n if op == "<<" else x >> n for x in (a.lo, a.hi) for n in (clo, chi)]
            w, changed = _fit(min(corners), max(corners), t)
            if changed:
                flags.append(_overflow(t))
            values += [w.lo, w.hi]
        return ICInt(min(values), max(values), t), flags

    def binary(self, e: Binary):
        a = self.eval(e.left)
        b = self.eval(e.right)
        t = e.operand_type
        op = e.op
        if op in ("<<", ">>"):
            v, flags = self.shift(op, a, b, t)
        else:
            flags: list = []
            a, b = self.convert(a, t, flags), self.convert(b, t, flags)
            if op in _COMPARES:
                v = self.compare(op, a, b)
            else:
                v, more = self.arith(op, a, b, t, e.right)
                flags += more
        self.term(e, v, flags)
        return v

    def compare(self, op: str, a: ICInt, b: ICInt) -> ICInt:
        if op in (">", ">="):
            a, b, op = b, a, "<" if op == ">" else "<="
        if op == "<":
            d = True if a.hi < b.lo else False if a.lo >= b.hi else None
        elif op == "<=":
            d = True if a.hi <= b.lo else False if a.lo > b.hi else None
        else:
            same = a.lo == a.hi == b.lo == b.hi
            apart = a.hi < b.lo or b.hi < a.lo
            d = None if not (same or apart) else (same if op == "==" else apart)
        return ICInt(0, 1, self.int) if d is None else _point(int(d), self.int)

    def unary(self, e: Unary):
        a = self.eval(e.operand)
        t = e.ctype
        flags: list = []
        if e.op != "!":  # promoted (a no-op on the values); ! tests the operand as it is
            a = self.convert(a, t, [])
        if e.op == "-":
            v, changed = _fit(-a.hi, -a.lo, t)
            if changed:
                flags.append(_overflow(t))
        elif e.op == "~":
            v = _fit(~a.hi, ~a.lo, t)[0]
        elif e.op == "!":
            d = decide(a)
            v = ICInt(0, 1, t) if d is None else _point(int(not d), t)
        else:
            v = a
        self.term(e, v, flags)
        return v

    def call(self, e):
        long_t = self.long
        flags: list = []
        args = [self.convert(self.eval(a), long_t, flags) for a in e.args]
        q = self.global_q if e.q is None else e.q
        one, op = 1 << q, e.iq
        if op == "sat":
            x, hi, lo = args
            if lo.hi <= hi.lo:  # then the clamp is max(lo, min(x, hi)): monotone in each
                v = ICInt(max(lo.lo, min(x.lo, hi.lo)), max(lo.hi, min(x.hi, hi.hi)), long_t)
            else:
                v = ICInt(min(x.lo, hi.lo, lo.lo), max(x.hi, hi.hi, lo.hi), long_t)
        elif op == "abs":
            x = args[0]
            lo, hi = (x.lo, x.hi) if x.lo >= 0 else (-x.hi, -x.lo) if x.hi <= 0 else \
                (0, max(-x.lo, x.hi))
            v, changed = _fit(lo, hi, long_t)
            if changed:
                flags.append("signed_overflow")
        elif op in ("mpy", "rmpy", "rsmpy"):
            x, y = args
            half = 0 if op == "mpy" else one >> 1
            c = [p * r + half for p in (x.lo, x.hi) for r in (y.lo, y.hi)]
            lo, hi = min(c) >> q, max(c) >> q  # floor is monotone
            if op == "rsmpy":
                v = ICInt(max(lo, long_t.min), min(hi, long_t.max), long_t)
            else:
                v, changed = _fit(lo, hi, long_t)
                if changed:
                    flags.append("conversion")
        elif op in ("int", "sqrt"):  # monotone: the ends' values
            x = args[0]
            v = ICInt(iq_value(op, [x.lo], q, long_t.bits)[0],
                      iq_value(op, [x.hi], q, long_t.bits)[0], long_t)
        else:  # the range of the result, whatever the arguments
            lo, hi = {"frac": (1 - one, one - 1), "atan2PU": (0, one),
                      "atan2": (-round(math.pi * one), round(math.pi * one)),
                      "mag": (0, long_t.max), "div": (long_t.min, long_t.max)
                      }.get(op, (-one, one))
            v = ICInt(max(lo, long_t.min), min(hi, long_t.max), long_t)
        self.term(e, v, flags)
        return v


def _pure(e) -> bool:
    """Whether evaluating ``e`` changes nothing (constants, variables, operators, casts)."""
    kind = type(e)
    if kind is Num or kind is Var:
        return True
    if kind is Unary:
        return e.op in "-+~!" and _pure(e.operand)
    if kind is Binary:
        return _pure(e.left) and _pure(e.right)
    if kind is Cast:
        return _pure(e.operand)
    return kind is Member and (e.flat is not None or type(e.base) is Var)


def _overflow(t: CType) -> str:
    return "signed_overflow" if t.signed else "unsigned_wrap"
