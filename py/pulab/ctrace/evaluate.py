"""Running a typed program: every intermediate value as the target computes it.

The integer arithmetic is :mod:`pulab.fixedpoint.cint`'s (``+ - * /`` and shifts through
:class:`~pulab.fixedpoint.cint.CInt`, conversions through :func:`~pulab.fixedpoint.cint.wrap_to`);
this module adds the C operators cint has no use for and names the flags:

``signed_overflow``
    a signed result did not fit its type: undefined behaviour in ISO C; the value
    shown is the two's-complement wrap the hardware (and ``gcc -fwrapv``) gives;
``unsigned_wrap``
    an unsigned result was reduced modulo 2**bits (defined behaviour, often a bug);
``conversion``
    a conversion (assignment, cast, argument, operand to an unsigned common type,
    IQmath's 64 → 32-bit result) changed the value;
``truncation``
    ``/`` or ``>>`` (or ``_IQmpy``'s shift) discarded non-zero bits;
``shift_count``
    a shift count < 0 or ≥ the width: undefined; the value shown is that of a full
    shift (0, or −1 for a negative value shifted right) — CPUs differ (x86 masks the count);
``saturate``
    ``_IQsat``/``__IQsat`` clamped the value, or ``_IQrsmpy``, ``_IQdiv``, ``_IQmag``
    saturated their result;
``not_bit_exact``
    an IQmath call whose last bits TI's closed library decides (``_IQdiv``, ``_IQsqrt``,
    ``_IQsin``…): the value is the correctly rounded one, not necessarily TI's
    (:mod:`pulab.ctrace.iqmath`).

Division or remainder by zero raises :class:`TraceError` at the divisor.

Examples
--------
>>> from .check import check
>>> from .parser import parse
>>> from .types import TARGETS
>>> checked = check(parse("Uint16 v; long x = v * 10;"), TARGETS["c28x"])
>>> ev = Evaluator(checked, {"v": 6554}, 24)
>>> steps = ev.run()
>>> ev.values["x"], steps[1]["terms"][0]["flags"]
(4, ['unsigned_wrap'])
"""

from __future__ import annotations

import re

from ..fixedpoint.cint import CInt, CType, convert, trunc_div, wrap_to
from .check import (ArrT, Checked, PtrT, StructT, VOID, describe, leaves, linked, pointee,
                    same_layout)
from .errors import TraceError
from .iqmath import iq_value
from .parser import (Assign, Binary, Block, Call, Cast, Cond, Decl, ExprStmt, If, IncDec,
                     Index, InitList, Jump, Label, Logical, Loop, Member, NodeVisitor, Num,
                     Return, Switch, Unary, Var)

__all__ = ["Evaluator", "hex_of", "FLAGS", "MAX_STEPS", "MAX_CALL_DEPTH"]

#: Statements executed in one run (loops included); more is an error at the statement.
MAX_STEPS = 10_000
#: Calls nested deeper are refused (recursion is refused anyway).
MAX_CALL_DEPTH = 32

#: Every flag a step can carry, in the order the page lists them.
FLAGS = ("signed_overflow", "unsigned_wrap", "conversion", "truncation", "shift_count",
         "saturate", "not_bit_exact")

_COMPARE = {"<": int.__lt__, ">": int.__gt__, "<=": int.__le__, ">=": int.__ge__,
            "==": int.__eq__, "!=": int.__ne__}


def hex_of(value: int, bits: int) -> str:
    """Two's-complement hex of ``value`` in ``bits`` bits.

    >>> hex_of(-1, 16), hex_of(4, 32)
    ('0xFFFF', '0x00000004')
    """
    return f"0x{value & ((1 << bits) - 1):0{bits // 4}X}"


def _overflow(t) -> str:
    return "signed_overflow" if t.signed else "unsigned_wrap"


def _rounding(op: str, a: int, b: int, result: int, flags: list) -> dict:
    """For a result that lost bits: how it rounded (``>>`` toward −∞, ``/`` toward zero,
    C99 6.5.5p6) and by how much, ``lost`` = exact − result in units of the result's LSB
    (``[0, 1)`` for floor; ``(−1, 1)`` toward zero, its sign opposite to the exact value's)."""
    if "truncation" not in flags:
        return {}
    if op == ">>":
        return {"rounding": "floor", "lost": (a - (result << b)) / float(1 << b)}
    return {"rounding": "toward_zero", "lost": (a - result * b) / b}


def _spelling(target) -> str:
    """How the code spells the type of the object ``target`` designates."""
    if isinstance(target, Var):
        return target.sym.spelling
    if isinstance(target, Member):
        if target.flat is not None:
            return target.flat.spelling
        st = target.base.ctype.to if target.arrow else target.base.ctype
        return st.fields[target.field][1]
    if isinstance(target, Index):
        return _spelling(target.base)
    return target.ctype.name


class _Return(Exception):
    def __init__(self, value) -> None:
        self.value = value


class _Jump(Exception):
    def __init__(self, kind: str) -> None:
        self.kind = kind


class Evaluator(NodeVisitor):
    """Runs a :class:`~pulab.ctrace.check.Checked` program once.

    Parameters
    ----------
    checked : Checked
    inputs : dict
        Path (``v``, ``p.hKpGain``, ``*out``) → integer, already range-checked.
    global_q : int in 1..30
        The Q of ``_IQmpy``.
    record : bool
        When False only ``values`` is kept (the compiler cross-check runs many vectors).
    """

    def __init__(self, checked: Checked, inputs: dict, global_q: int, record: bool = True
                 ) -> None:
        self.checked = checked
        self.source = checked.program.source
        self.mem: dict = {}
        self.written: set = set()
        self.values: dict = {}
        self.inputs = inputs
        #: the input names: ``checked.inputs`` with the pointer inputs given pointing there
        self.names = checked.inputs_with({k: v for k, v in inputs.items()
                                          if k in checked.pointers})
        self.unset = [n for n in self.names if n not in inputs]
        self.global_q = global_q
        self.record = record
        self.terms: list = []
        self.steps: list = []
        self.active: list = []
        self.loops: list = []
        self.count = 0
        self.last_path: str | None = None
        #: Undefined behaviour (ISO C) met: signed_overflow, division_overflow, shift_count.
        self.undefined: set = set()
        #: the paths of the ``static`` locals initialized so far (kept across calls)
        self.statics: set = set()
        #: with ``record`` False and ``watch`` a tuple of flags: the flags met (``seen``) and
        #: the first of ``watch`` met (``event``: line, flag, the variable its statement
        #: stores or else the expression's text), in the order the recorded steps list them
        self.watch: tuple = ()
        self.seen: set = set()
        self.event: tuple | None = None
        self._pending: tuple | None = None  # a term's event, named by its statement's step
        self.int = checked.target.types["int"]
        self.long = checked.target.types["long"]

    # -- recording
    def term(self, node, value: int, flags: list, **extra) -> None:
        if "signed_overflow" in flags or "shift_count" in flags:
            self.undefined.update(f for f in flags if f in ("signed_overflow", "shift_count"))
        if self.record:
            t = node.ctype
            d = {"expr": self.source[node.start:node.end], "line": node.line,
                 "column": node.column, "type": t.name, "value": value,
                 "hex": hex_of(value, t.bits) if value is not None else None, "flags": flags}
            d.update(extra)
            self.terms.append(d)
        elif self.watch and flags:
            self.met(node, flags)

    def met(self, node, flags) -> None:
        """Watch mode: flags of a term (a sub-expression, or a call's argument conversions)."""
        self.seen.update(flags)
        if self.event is None and self._pending is None:
            kind = next((f for f in flags if f in self.watch), None)
            if kind is not None:
                self._pending = (len(self.active), node.line, kind,
                                 self.source[node.start:node.end])

    def step(self, stmt, code: str, var: str | None, value: int, ctype, **extra) -> None:
        if not self.record and self.watch:
            flags = extra.get("flags", ())
            self.seen.update(flags)
            pending = self._pending
            if pending is not None and pending[0] == len(self.active):
                self.event, self._pending = (pending[1], pending[2], var or pending[3]), None
            elif self.event is None and pending is None:
                kind = next((f for f in flags if f in self.watch), None)
                if kind is not None:
                    self.event = (stmt.line, kind, var or code)
        if self.record:
            flags = sorted({f for t in self.terms for f in t["flags"]} |
                           set(extra.pop("flags", ())), key=FLAGS.index)
            d = {"line": stmt.line, "column": stmt.column, "code": code, "var": var,
                 "type": ctype.name, "value": value,
                 "hex": hex_of(value, ctype.bits) if value is not None else None,
                 "flags": flags, "terms": self.terms}
            d.update(extra)
            self.steps.append(d)
        self.terms = []

    # Hooks the interval evaluator (pulab.ctrace.abstract) overrides: a value that decides
    # control flow, and one that names a place (an index, a case).
    @staticmethod
    def truth(value) -> bool:
        """Whether a condition's value is true (non-zero, or a non-null pointer)."""
        return value != 0 if isinstance(value, int) else value is not None

    @staticmethod
    def scalar(value) -> int:
        """The one integer an index or a ``switch`` test designates."""
        return value

    # -- memory
    def read(self, path: str, node) -> int:
        v = self.mem.get(path)
        if v is None:
            if path in self.unset and path in self.checked.pointers:
                raise TraceError(node.line, node.column, field=f"set.{path}",
                                 code="trace_unset_pointer", name=path)
            if path in self.unset:
                raise TraceError(node.line, node.column, field=f"set.{path}",
                                 code="trace_unset_input", name=path,
                                 unset=", ".join(self.unset))
            if self.checked.entry is None:
                raise TraceError(node.line, node.column, field=f"set.{path}",
                                 code="trace_unset_global", name=path)
            raise TraceError(node.line, node.column, code="trace_unset_local", name=path)
        return v

    def put(self, path: str, value) -> None:
        self.mem[path] = value
        self.written.add(path)

    # -- statements
    def run(self) -> list:
        """Execute the code (the entry function when there is one); returns the steps
        (empty when not recording)."""
        for s in self.checked.program.statements:
            self.statement(s)
        self.enter()
        return self.steps

    def again(self, inputs: dict) -> list:
        """Run the entry once more on the memory the last run left (globals, ``static``
        locals, what pointer parameters point to), ``inputs`` (validated, as the
        constructor's) given first: the firmware's next control period.  Without an entry the
        statements outside functions run again: a variable declared without an initializer
        keeps its value (a global), one with an initializer is set again.  Returns its steps."""
        self.inputs = inputs
        self.unset = [n for n in self.names if n not in inputs and self.mem.get(n) is None]
        self.steps, self.terms, self.count, self.undefined = [], [], 0, set()
        self.seen, self.event, self._pending = set(), None, None
        self.mem.update(inputs)  # globals; the entry's own inputs get their steps in enter
        if self.checked.entry is None:  # the statements are the period's code
            for s in self.checked.program.statements:
                self.statement(s)
        self.enter()
        return self.steps

    def enter(self) -> None:
        """Call the entry (when there is one), then read every variable's value."""
        f = self.checked.entry
        if f is not None:
            self.written = set()  # what the function writes, not the globals' initializers
            inputs = self.inputs
            for p in f.params:
                if isinstance(p.ctype, PtrT):
                    obj, t, value = pointee(p)
                    self.mem[p.key] = value
                    given = leaves(obj, t, p.spelling)
                    for ptr, obj2, t2, sp in linked(obj, t):
                        self.mem[ptr] = obj2
                        given += leaves(obj2, t2, sp)
                else:
                    given = leaves(p.key, p.ctype, p.spelling)
                for path, t, spelling in given:
                    if path in inputs:
                        self.given(p, f"{spelling} {path}", path, t, spelling)
            self.values["return"] = value = self.body(f)
            if isinstance(f.ret, PtrT) and value is not None and \
                    re.match(r"\*?(\w+)", value)[1] not in self.checked.heads:
                raise TraceError(f.node.close_line, f.node.close_column,
                                 code="trace_return_local", name=f.name, got=value)
        for name in (*self.checked.symbols, *self.checked.pointers):
            self.values[name] = self.mem.get(name)

    def given(self, node, code: str, path: str, t, spelling: str) -> None:
        """Give the input ``path`` its value; a pointer's step names what it points to."""
        v = self.inputs[path]
        self.mem[path] = v
        if isinstance(t, PtrT):
            if self.record:
                self.steps.append({"line": node.line, "column": node.column, "code": code,
                                   "var": path, "type": describe(t), "value": None,
                                   "hex": None, "flags": [], "terms": [], "points_to": v,
                                   "spelling": spelling, "input": True})
            return
        self.step(node, code, path, v, t, spelling=spelling, input=True)

    def block(self, statements) -> None:
        for s in statements:
            self.statement(s)

    def statement(self, s) -> None:
        """Run statement ``s`` (its ``visit_`` method), counted against :data:`MAX_STEPS`."""
        self.count += 1
        if self.count > MAX_STEPS:
            self.too_long(s)
        self.visit(s)

    def visit_Decl(self, s: Decl) -> None:
        code = self.source[s.start:s.end]
        for var, init, _ in s.items:
            sym = var.sym
            t, key = sym.ctype, sym.key
            if s.static and self.active:  # initialized once, before the first call reaches it
                if key in self.statics:
                    continue
                paths = leaves(key, t, sym.spelling)
                self.statics.update([key, *(path for path, _, _ in paths)])
                if init is None:  # zero, as every object of static storage (C99 6.7.8p10)
                    for path, lt, _ in paths:
                        self.mem[path] = 0 if isinstance(lt, CType) else None
                    continue
            if init is None:
                for path, lt, spelling in leaves(key, t, sym.spelling):
                    if path in self.inputs:
                        self.given(s, code, path, lt, spelling)
                    elif self.active:
                        self.mem.pop(path, None)  # a local declared again has no value
                continue
            if isinstance(t, (StructT, ArrT)):
                self.aggregate(key, t, init)
                if self.terms:  # a call or computed elements: keep what they did
                    self.step(s, code, key, None, VOID)
                self.terms = []
                continue
            if isinstance(t, PtrT):
                self.mem[key] = self.eval(init)
                self.terms = []
                continue
            stored, flags = self.store(self.eval(init), t)
            self.put(key, stored)
            self.step(s, code, key, stored, t, spelling=sym.spelling, flags=flags)

    def visit_ExprStmt(self, s: ExprStmt) -> None:
        e = s.expr
        self.last_path = None
        v = self.eval(e)
        var = self.last_path if isinstance(e, (Assign, IncDec)) else None
        if not isinstance(e.ctype, CType):  # a call of a void function, a struct copy
            self.step(s, self.source[s.start:s.end], None, None, VOID)
            return
        extra = {"spelling": _spelling(e.target)} if var else {}
        if var and isinstance(e, IncDec) and not e.prefix:
            v = self.mem[var]  # the statement's result is the variable, not x++'s value
        self.step(s, self.source[s.start:s.end], var, v, e.ctype, **extra)

    def visit_If(self, s: If) -> None:
        v = self.eval(s.test)
        taken = self.truth(v)
        self.step(s, f"if ({self.source[s.test.start:s.test.end]})", None, int(taken), self.int,
                  branch="then" if taken else ("else" if s.other is not None else "none"))
        if taken:
            self.statement(s.then)
        elif s.other is not None:
            self.statement(s.other)

    def visit_Block(self, s: Block) -> None:
        for inner in s.statements:
            self.statement(inner)

    def visit_Label(self, s: Label) -> None:
        pass

    def visit_Return(self, s: Return) -> None:
        f = self.checked.functions[self.active[-1]]
        if s.value is None:
            self.step(s, self.source[s.start:s.end], None, None, VOID)
            raise _Return(None)
        if isinstance(f.ret, PtrT):  # an object's path (a handle getter)
            self.step(s, self.source[s.start:s.end], None, None, VOID)
            raise _Return(self.eval(s.value))
        if isinstance(f.ret, StructT):  # copied out: the callee's frame goes on the next call
            self.copy(f"{f.prefix}return", self.eval(s.value), f.ret)
            self.step(s, self.source[s.start:s.end], "return", None, VOID)
            raise _Return(f"{f.prefix}return")
        stored, flags = self.store(self.eval(s.value), f.ret)
        self.step(s, self.source[s.start:s.end], "return", stored, f.ret, flags=flags)
        raise _Return(stored)

    def visit_Jump(self, s: Jump) -> None:
        raise _Jump(s.kind)


    def visit_Switch(self, s: Switch) -> None:
        """Jump to the matching label (the case constants convert to the promoted type of the
        test, C99 6.8.4.2p5), run on until ``break`` or the end."""
        t = s.test.ctype
        v = self.scalar(self.eval(s.test))
        body = s.body.statements
        start, default = None, None
        for i, inner in enumerate(body):
            if type(inner) is Label:
                if inner.value_int is None:
                    default = i
                elif convert(inner.value_int, t) == v:
                    start = i
                    break
        if start is None:
            start = default
        taken = "none" if start is None else ("default" if start == default else f"case {v}")
        self.step(s, f"switch ({self.source[s.test.start:s.test.end]})", None, v, t,
                  branch=taken)
        if start is None:
            return
        self.run_case(body, start)

    def run_case(self, body: list, start: int) -> None:
        """Run a ``switch`` body from its statement ``start`` until ``break`` or the end."""
        try:
            for inner in body[start:]:
                self.statement(inner)
        except _Jump as j:
            if j.kind != "break":
                raise

    def too_long(self, s) -> None:
        at = self.loops[-1] if self.loops else s  # the loop that runs on, when there is one
        raise TraceError(at.line, at.column, code="trace_steps", limit=MAX_STEPS)

    def visit_Loop(self, s: Loop) -> None:
        self.loops.append(s)
        try:
            self.iterate(s)
        finally:
            self.loops.pop()

    def iterate(self, s: Loop) -> None:
        src = self.source
        if s.init is not None:
            self.statement(s.init)
        head = f"{s.kind} ({src[s.test.start:s.test.end]})" if s.test is not None else \
            f"{s.kind} (;;)"
        first = s.kind == "do"
        while True:
            if not first:
                self.count += 1
                if self.count > MAX_STEPS:
                    self.too_long(s)
                if s.test is not None:
                    taken = self.truth(self.eval(s.test))
                    self.step(s, head, None, int(taken), self.int,
                              branch="loop" if taken else "exit")
                    if not taken:
                        return
            first = False
            try:
                self.statement(s.body)
            except _Jump as j:
                if j.kind == "break":
                    return
            if s.step is not None:
                self.last_path = None
                v = self.eval(s.step)
                if isinstance(s.step, IncDec) and not s.step.prefix:
                    v = self.mem[self.last_path]  # the variable's new value, as for i++;
                self.step(s.step, src[s.step.start:s.step.end], self.last_path, v,
                          s.step.ctype)

    def aggregate(self, path: str, t, init) -> None:
        """Initialize a struct or array: a braced list (the rest is zero, C99 6.7.8p21) or a
        struct value."""
        if not isinstance(init, InitList):
            if isinstance(t, CType):
                stored, flags = self.store(self.eval(init), t)
                self.put(path, stored)
            elif isinstance(t, PtrT):
                self.mem[path] = self.eval(init)
            else:
                self.copy(path, self.eval(init), t)
            return
        if isinstance(t, ArrT):
            parts = [(f"{path}[{i}]", t.of) for i in range(t.n)]
        elif isinstance(t, StructT):
            parts = [(f"{path}.{name}", ft) for name, (ft, _) in t.fields.items()]
        else:
            parts = [(path, t)]
        for i, (p, pt) in enumerate(parts):
            if i < len(init.items):
                self.aggregate(p, pt, init.items[i])
            else:
                for leaf, lt, _ in leaves(p, pt):
                    self.put(leaf, 0 if isinstance(lt, CType) else None)

    def copy(self, dst: str, src: str, t) -> None:
        n = len(src)
        for leaf, _, _ in leaves(src, t):
            self.put(dst + leaf[n:], self.mem.get(leaf))

    @staticmethod
    def store(value: int, ctype) -> tuple:
        """Convert to ``ctype`` as an assignment does; flag a changed value."""
        w = convert(value, ctype)
        return w, (["conversion"] if w != value else [])

    def body(self, f):
        """Run function ``f``'s body (its frame already set up); its return value, None for
        a void function or one that falls off its end (an error unless void)."""
        self.active.append(f.name)
        value = None
        try:
            self.block(f.node.body.statements)
            if f.ret is not VOID:
                raise TraceError(f.node.close_line, f.node.close_column,
                                 code="trace_no_return", name=f.name)
        except _Return as r:
            value = r.value
        self.active.pop()
        return value

    # -- places (lvalues): the path of the object an expression designates
    def place(self, e) -> str:
        kind = type(e)
        if kind is Var:
            return e.sym.key
        if kind is Member:
            if e.flat is not None:
                return e.flat.key
            base = self.eval(e.base) if e.arrow else self.place(e.base)
            if base is None:
                raise TraceError(e.line, e.column, code="trace_null_pointer")
            return f"{base}.{e.field}"
        if kind is Index:
            i = self.scalar(self.eval(e.index))
            bt = e.base.ctype
            if isinstance(bt, ArrT):
                base = self.place(e.base)
                if not 0 <= i < bt.n:
                    raise TraceError(e.index.line, e.index.column, code="trace_index", index=i,
                                     array=base, last=bt.n - 1)
                return f"{base}[{i}]"
            return self.offset(self.eval(e.base), i, e)
        ptr = self.eval(e.operand)  # *p
        return ptr

    def offset(self, ptr: str, i: int, node) -> str:
        """``ptr + i`` inside the array ``ptr`` points into."""
        if i == 0:
            return ptr
        head, bracket, k = ptr[:-1].rpartition("[")
        n = None
        if bracket and ptr.endswith("]"):
            n = self.checked.objects.get(head)
            if n is None:  # an array field of a struct
                t = self.checked.type_at(head)
                n = t.n if isinstance(t, ArrT) else None
        if n is None:
            raise TraceError(node.line, node.column, code="trace_one_object", name=ptr)
        j = int(k) + i
        if not 0 <= j < n:
            raise TraceError(node.line, node.column, code="trace_index", index=j, array=head,
                             last=n - 1)
        return f"{head}[{j}]"

    # -- expressions
    def eval(self, e):
        kind = type(e)
        if kind is Num:
            return e.value
        if kind is Var or kind is Member or kind is Index:
            t = e.ctype
            path = self.place(e)
            if type(t) is CType or isinstance(t, PtrT):
                return self.read(path, e)
            return f"{path}[0]" if isinstance(t, ArrT) else path
        if kind is Binary:
            return self.binary(e)
        if kind is Assign:
            return self.assign(e)
        if kind is Cast:
            v = self.eval(e.operand)
            if isinstance(e.ctype, PtrT):  # the same object; from void * its type is checked
                if e.from_void and v is not None:
                    t = self.checked.type_at(v)
                    if t is None or not same_layout(t, e.ctype.to):
                        raise TraceError(e.line, e.column, code="trace_cast_reinterprets",
                                         cast=" ".join(self.source[e.start:e.end].split()),
                                         src=f"{describe(t)} *" if t else "void *",
                                         dst=describe(e.ctype))
                return v
            w, flags = self.store(v, e.ctype)
            self.term(e, w, flags)
            return w
        if kind is Unary:
            if e.op == "&":
                return self.place(e.operand)
            if e.op == "*":
                path = self.place(e)
                return self.read(path, e) if isinstance(e.ctype, (CType, PtrT)) else path
            return self.unary(e)
        if kind is Logical:
            a = self.truth(self.eval(e.left))
            if (e.op == "&&") == a:  # && continues on true, || on false
                a = self.truth(self.eval(e.right))
            self.term(e, int(a), [])
            return int(a)
        if kind is Cond:
            branch = e.then if self.truth(self.eval(e.test)) else e.other
            w, flags = self.store(self.eval(branch), e.ctype)
            self.term(e, w, flags)
            return w
        if kind is IncDec:
            return self.incdec(e)
        if e.func is not None:
            return self.call_user(e)
        return self.call(e)

    def arith(self, op: str, a: int, b: int, t, node) -> tuple:
        """``a op b`` in type ``t`` (operands already converted); returns (value, flags)."""
        if op in ("+", "-", "*", "/"):
            if op == "/" and b == 0:
                raise TraceError(node.line, node.column, code="trace_division_zero")
            x, y = CInt(a, t), CInt(b, t)
            r = x + y if op == "+" else x - y if op == "-" else x * y if op == "*" else x // y
            flags = []
            if "wrap" in r.flags:
                flags.append(_overflow(t))
                if op == "/" and t.signed:
                    self.undefined.add("division_overflow")
            if "truncation" in r.flags:
                flags.append("truncation")
            return r.value, flags
        if op == "%":
            if b == 0:
                raise TraceError(node.line, node.column, code="trace_remainder_zero")
            # a % b overflows exactly when a / b does (C11 6.5.5p6).
            if t.signed and a == t.min and b == -1:
                self.undefined.add("division_overflow")
                return 0, ["signed_overflow"]
            return a - trunc_div(a, b) * b, []
        if op == "&":
            return a & b, []
        if op == "|":
            return a | b, []
        if op == "^":
            return a ^ b, []
        return self.shift(op, a, b, t)

    def shift(self, op: str, a: int, count: int, t) -> tuple:
        if not 0 <= count < t.bits:
            return (-1 if op == ">>" and a < 0 else 0), ["shift_count"]
        r = CInt(a, t) << count if op == "<<" else CInt(a, t) >> count
        if "wrap" in r.flags:
            return r.value, [_overflow(t)]
        return r.value, (["truncation"] if r.flags else [])

    def convert(self, value: int, t, flags: list) -> int:
        """An operand converted to its operator's type; a changed value is flagged."""
        w = wrap_to(value, t) if not t.min <= value <= t.max else value
        if w != value and "conversion" not in flags:
            flags.append("conversion")
        return w

    def binary(self, e: Binary) -> int:
        a = self.eval(e.left)
        b = self.eval(e.right)
        t = e.operand_type
        op = e.op
        if op in ("<<", ">>"):
            v, flags = self.shift(op, a, b, t)
        else:
            pre: list = []
            a, b = self.convert(a, t, pre), self.convert(b, t, pre)
            if op in _COMPARE:
                v, flags = int(_COMPARE[op](a, b)), pre
            else:
                v, flags = self.arith(op, a, b, t, e.right)
                flags = pre + flags
        self.term(e, v, flags, **_rounding(op, a, b, v, flags))
        return v

    def unary(self, e: Unary) -> int:
        a = self.eval(e.operand)
        t = e.ctype
        flags: list = []
        if e.op == "-":
            v = wrap_to(-a, t)
            if v != -a:
                flags.append(_overflow(t))
        elif e.op == "~":
            v = wrap_to(~a, t)
        elif e.op == "!":
            v = int(a == 0)
        else:
            v = a
        self.term(e, v, flags)
        return v

    def assign(self, e: Assign):
        t = e.target.ctype
        path = self.place(e.target)
        if not isinstance(t, CType):
            value = self.eval(e.value)
            if isinstance(t, PtrT):
                self.mem[path] = value
            else:
                self.copy(path, value, t)
            self.last_path = None
            return value
        if e.op == "=":
            stored, flags = self.store(self.eval(e.value), t)
        else:
            b = self.eval(e.value)
            old = self.read(path, e.target)
            ot = e.operand_type
            op = e.op[:-1]
            if op in ("<<", ">>"):
                v, flags = self.shift(op, old, b, ot)
            else:
                flags = []
                a, b = self.convert(old, ot, flags), self.convert(b, ot, flags)
                v, more = self.arith(op, a, b, ot, e.value)
                flags += more
            stored, more = self.store(v, t)
            flags += [f for f in more if f not in flags]
            extra = _rounding(op, a if op not in ("<<", ">>") else old, b, v, flags)
        self.put(path, stored)
        self.last_path = path
        self.term(e, stored, flags, var=path, **(extra if e.op != "=" else {}))
        return stored

    def incdec(self, e: IncDec) -> int:
        path = self.place(e.target)
        old = self.read(path, e.target)
        ot = e.operand_type
        flags: list = []
        v, more = self.arith("+" if e.op == "++" else "-", self.convert(old, ot, flags), 1, ot,
                             e)
        stored, conv = self.store(v, e.ctype)
        flags += more + conv
        self.put(path, stored)
        self.last_path = path
        result = stored if e.prefix else old
        self.term(e, result, flags, var=path)
        return result

    def call_user(self, e: Call):
        """A call of a function of the code: its statements become the call term's ``steps``."""
        f = e.func
        if f.name in self.active:
            raise TraceError(e.line, e.column, code="trace_recursion", name=f.name)
        if len(self.active) >= MAX_CALL_DEPTH:
            raise TraceError(e.line, e.column, code="trace_call_depth", limit=MAX_CALL_DEPTH)
        flags: list = []
        args = []
        for a, p in zip(e.args, f.params):
            v = self.eval(a)
            if isinstance(p.ctype, CType):
                w, conv = self.store(v, p.ctype)
                if conv and "conversion" not in flags:
                    flags.append("conversion")
                v = w
            elif isinstance(p.ctype, StructT):  # by value: the callee gets a copy
                v = [(leaf[len(v):], self.mem.get(leaf)) for leaf, _, _ in leaves(v, p.ctype)]
            args.append(v)
        mem = self.mem
        statics = self.statics
        for k in [k for k in mem if k.startswith(f.prefix) and k not in statics]:
            del mem[k]  # a fresh frame: the callee's locals have no value yet
        for p, v in zip(f.params, args):
            if isinstance(p.ctype, StructT):
                for suffix, x in v:
                    mem[p.key + suffix] = x
            else:
                mem[p.key] = v
        outer_terms, outer_steps, outer_path = self.terms, self.steps, self.last_path
        self.terms, self.steps = [], []
        value = self.body(f)
        inner = self.steps
        self.terms, self.steps, self.last_path = outer_terms, outer_steps, outer_path
        if self.record:
            t = e.ctype
            scalar = isinstance(t, CType)
            self.terms.append({"expr": self.source[e.start:e.end], "line": e.line,
                               "column": e.column, "type": describe(t),
                               "value": value if scalar else None,
                               "hex": hex_of(value, t.bits) if scalar else None,
                               "flags": flags, "call": f.name, "steps": inner})
        elif self.watch and flags:
            self.met(e, flags)
        return value

    def call(self, e: Call) -> int:
        long_t = self.long
        flags: list = []
        args = [self.convert(self.eval(a), long_t, flags) for a in e.args]
        q = self.global_q if e.q is None else e.q
        v, more = iq_value(e.iq, args, q, long_t.bits)
        flags += more
        if "signed_overflow" in more:  # labs(LONG_MIN)
            self.undefined.add("signed_overflow")
        extra = {}
        if e.iq not in ("sat", "abs"):
            extra["q"] = q
            if e.iq == "mpy":
                extra.update(_rounding(">>", args[0] * args[1], q, args[0] * args[1] >> q, flags))
        self.term(e, v, flags, **extra)
        return v
