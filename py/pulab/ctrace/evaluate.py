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
    ``_IQsat``/``__IQsat`` clamped the value.

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

from ..fixedpoint.cint import CInt, trunc_div, wrap_to
from .check import Checked
from .errors import TraceError
from .parser import (Assign, Binary, Block, Call, Cast, Cond, Decl, ExprStmt, If, IncDec,
                     Logical, Num, Unary, Var)

__all__ = ["Evaluator", "hex_of", "FLAGS"]

#: Every flag a step can carry, in the order the page lists them.
FLAGS = ("signed_overflow", "unsigned_wrap", "conversion", "truncation", "shift_count",
         "saturate")

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


class Evaluator:
    """Runs a :class:`~pulab.ctrace.check.Checked` program once.

    Parameters
    ----------
    checked : Checked
    inputs : dict
        Variable name → integer, already range-checked against its type.
    global_q : int in 1..30
        The Q of ``_IQmpy``.
    record : bool
        When False only ``values`` is kept (the compiler cross-check runs many vectors).
    """

    def __init__(self, checked: Checked, inputs: dict, global_q: int, record: bool = True
                 ) -> None:
        self.checked = checked
        self.source = checked.program.source
        self.values: dict = {name: None for name in checked.symbols}
        self.inputs = inputs
        self.global_q = global_q
        self.record = record
        self.terms: list = []
        self.steps: list = []
        #: Undefined behaviour (ISO C) met: signed_overflow, division_overflow, shift_count.
        self.undefined: set = set()
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
                 "hex": hex_of(value, t.bits), "flags": flags}
            d.update(extra)
            self.terms.append(d)

    def step(self, stmt, code: str, var: str | None, value: int, ctype, **extra) -> None:
        if self.record:
            flags = sorted({f for t in self.terms for f in t["flags"]} |
                           set(extra.pop("flags", ())), key=FLAGS.index)
            d = {"line": stmt.line, "column": stmt.column, "code": code, "var": var,
                 "type": ctype.name, "value": value, "hex": hex_of(value, ctype.bits),
                 "flags": flags, "terms": self.terms}
            d.update(extra)
            self.steps.append(d)
        self.terms = []

    # -- statements
    def run(self) -> list:
        """Execute every statement; returns the steps (empty when not recording)."""
        for s in self.checked.program.statements:
            self.statement(s)
        return self.steps

    def statement(self, s) -> None:
        src = self.source
        if isinstance(s, Decl):
            code = src[s.start:s.end]
            for var, init in s.items:
                sym = self.checked.symbols[var.name]
                if init is None:
                    if var.name in self.inputs:
                        v = self.inputs[var.name]
                        self.values[var.name] = v
                        self.step(s, code, var.name, v, sym.ctype, spelling=sym.spelling,
                                  input=True)
                    continue
                v = self.eval(init)
                stored, flags = self.store(v, sym.ctype)
                self.values[var.name] = stored
                self.step(s, code, var.name, stored, sym.ctype, spelling=sym.spelling,
                          flags=flags)
        elif isinstance(s, ExprStmt):
            e = s.expr
            v = self.eval(e)
            var = e.target.name if isinstance(e, (Assign, IncDec)) else None
            extra = {"spelling": self.checked.symbols[var].spelling} if var else {}
            if var and isinstance(e, IncDec) and not e.prefix:
                v = self.values[var]  # the statement's result is the variable, not x++'s value
            self.step(s, src[s.start:s.end], var, v, e.ctype, **extra)
        elif isinstance(s, If):
            v = self.eval(s.test)
            taken = v != 0
            self.step(s, f"if ({src[s.test.start:s.test.end]})", None, int(taken), self.int,
                      branch="then" if taken else ("else" if s.other is not None else "none"))
            if taken:
                self.statement(s.then)
            elif s.other is not None:
                self.statement(s.other)
        elif isinstance(s, Block):
            for inner in s.statements:
                self.statement(inner)

    @staticmethod
    def store(value: int, ctype) -> tuple:
        """Convert to ``ctype`` as an assignment does; flag a changed value."""
        w = wrap_to(value, ctype)
        return w, (["conversion"] if w != value else [])

    # -- expressions
    def eval(self, e) -> int:
        kind = type(e)
        if kind is Num:
            return e.value
        if kind is Var:
            v = self.values[e.name]
            if v is None:
                raise TraceError(e.line, e.column, f"{e.name} is read before it has a value "
                                 "(give it an input value or an initializer)",
                                 field=f"set.{e.name}")
            return v
        if kind is Binary:
            return self.binary(e)
        if kind is Assign:
            return self.assign(e)
        if kind is Cast:
            v = self.eval(e.operand)
            w, flags = self.store(v, e.ctype)
            self.term(e, w, flags)
            return w
        if kind is Unary:
            return self.unary(e)
        if kind is Logical:
            a = self.eval(e.left) != 0
            if (e.op == "&&") == a:  # && continues on true, || on false
                a = self.eval(e.right) != 0
            self.term(e, int(a), [])
            return int(a)
        if kind is Cond:
            branch = e.then if self.eval(e.test) else e.other
            w, flags = self.store(self.eval(branch), e.ctype)
            self.term(e, w, flags)
            return w
        if kind is IncDec:
            return self.incdec(e)
        return self.call(e)

    def arith(self, op: str, a: int, b: int, t, node) -> tuple:
        """``a op b`` in type ``t`` (operands already converted); returns (value, flags)."""
        if op in ("+", "-", "*", "/"):
            if op == "/" and b == 0:
                raise TraceError(node.line, node.column, "division by zero")
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
                raise TraceError(node.line, node.column, "remainder by zero")
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
        self.term(e, v, flags)
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

    def assign(self, e: Assign) -> int:
        name = e.target.name
        t = e.target.ctype
        if e.op == "=":
            stored, flags = self.store(self.eval(e.value), t)
        else:
            b = self.eval(e.value)
            old = self.eval(e.target)
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
        self.values[name] = stored
        self.term(e, stored, flags, var=name)
        return stored

    def incdec(self, e: IncDec) -> int:
        name = e.target.name
        old = self.eval(e.target)
        ot = e.operand_type
        flags: list = []
        v, more = self.arith("+" if e.op == "++" else "-", self.convert(old, ot, flags), 1, ot,
                             e)
        stored, conv = self.store(v, e.ctype)
        flags += more + conv
        self.values[name] = stored
        result = stored if e.prefix else old
        self.term(e, result, flags, var=name)
        return result

    def call(self, e: Call) -> int:
        long_t = self.long
        flags: list = []
        args = [self.convert(self.eval(a), long_t, flags) for a in e.args]
        if e.name in ("_IQsat", "__IQsat"):
            x, hi, lo = args
            v = hi if x > hi else lo if x < lo else x
            if v != x:
                flags.append("saturate")
        else:
            q = self.global_q if e.q is None else e.q
            product = args[0] * args[1]  # exact: the 64-bit product of two longs
            shifted = product >> q       # arithmetic shift: floor, as TI's __IQmpy
            if shifted << q != product:
                flags.append("truncation")
            v, conv = self.store(shifted, long_t)
            flags += conv
        self.term(e, v, flags, **({"q": self.global_q if e.q is None else e.q}
                                  if e.name.endswith("mpy") else {}))
        return v
