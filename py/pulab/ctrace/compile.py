"""A checked program compiled once into Python closures: the tracer's evaluator, run fast.

:class:`~pulab.ctrace.evaluate.Evaluator` walks the syntax tree on every run; code that runs
thousands of times (the seed's current-PI update in a simulation, the vendor blocks of every
report) is turned here into one closure per expression and statement instead, with the
evaluator's integer semantics: the same values, the same flags per statement (the union of
its terms' flags, in :data:`~pulab.ctrace.evaluate.FLAGS` order) and the same undefined
behaviour met.  A run that stops (an input or variable read before it has a value, a zero
divisor) gives the statements run so far and where it stopped (:class:`Stopped`);
:func:`run_compiled` then runs the evaluator itself, which raises the tracer's own error.

The straight-line part of the subset compiles: integer declarations, expressions of every
operator, casts, assignments (compound too), ``++``/``--``, ``?:``, ``&&``/``||``, ``if``,
blocks, and IQmath's calls (:mod:`pulab.ctrace.iqmath`).  Functions, loops, ``switch``,
structs, arrays and pointers raise :class:`Uncompilable` (the evaluator runs those).

Examples
--------
>>> from .tracing import compile_code
>>> prog = compiled(compile_code("Uint16 v; long x = v * 10;", "c28x"))
>>> run = prog.run({"v": 6554})
>>> run.values["x"], run.steps[1].flags
(4, ('unsigned_wrap',))
"""

from __future__ import annotations

from ..fixedpoint.cint import CType, convert, trunc_div, wrap_to
from .check import Checked
from .evaluate import FLAGS, MAX_STEPS
from .iqmath import iq_value
from .tracing import DEFAULT_GLOBAL_Q, input_values, run_checked
from .parser import (Assign, Binary, Block, Call, Cast, Cond, Decl, ExprStmt, If, IncDec,
                     Logical, Member, Num, Unary, Var)

__all__ = ["Uncompilable", "Stopped", "Step", "Run", "Compiled", "compiled", "run_compiled"]

_ORDER = {f: i for i, f in enumerate(FLAGS)}
#: Not a step flag: recorded beside them so that :attr:`Run.undefined` sees it.
_DIV_OVERFLOW = "division_overflow"
_UNDEFINED = frozenset({"signed_overflow", "shift_count", _DIV_OVERFLOW})


class Uncompilable(Exception):
    """The program uses a construct the closures do not cover (the evaluator runs it)."""


class _Stop(Exception):
    """Raised inside a statement: an unset read or a zero divisor (the evaluator names it)."""


class Stopped(Exception):
    """A run stopped at top-level statement ``index``; ``steps`` are those run before it."""

    def __init__(self, index: int, steps: list) -> None:
        super().__init__(index)
        self.index, self.steps = index, steps


class Step:
    """One executed statement: its node, the variable it stores (or None), the value, its
    flags (as the evaluator's step lists them) and ``inner``, the flags of the value before
    the statement's final store converted it (``stored``: that conversion changed it)."""

    __slots__ = ("stmt", "var", "value", "raw", "stored")

    def __init__(self, stmt, var, value, raw: list, stored: bool) -> None:
        self.stmt, self.var, self.value, self.raw, self.stored = stmt, var, value, raw, stored

    @property
    def flags(self) -> tuple:
        return tuple(sorted({f for f in self.raw if f != _DIV_OVERFLOW}, key=_ORDER.__getitem__))

    @property
    def inner(self) -> tuple:
        """The flags of the statement's terms other than its final store's conversion."""
        raw = self.raw[:-1] if self.stored else self.raw
        return tuple(sorted({f for f in raw if f != _DIV_OVERFLOW}, key=_ORDER.__getitem__))


class Run:
    """A finished run: ``values`` (every symbol's value, None if never set), ``steps``."""

    __slots__ = ("values", "steps")

    def __init__(self, values: dict, steps: list) -> None:
        self.values, self.steps = values, steps

    @property
    def undefined(self) -> set:
        """The undefined behaviour met, as :attr:`Evaluator.undefined`."""
        return {f for s in self.steps for f in s.raw if f in _UNDEFINED}


def _within(a, t: CType) -> bool:
    """Every value of type ``a`` is one of ``t`` (converting it to ``t`` never changes it)."""
    return type(a) is CType and t.min <= a.min and a.max <= t.max and a.name != "_Bool"


def _overflow(t: CType) -> str:
    return "signed_overflow" if t.signed else "unsigned_wrap"


def _converter(t: CType):
    """``(value, flags) -> value`` converted to ``t`` as an assignment or cast does
    (a changed value appends ``conversion``)."""
    lo, hi = t.min, t.max
    if t.name == "_Bool":
        def conv(v, fl):
            w = convert(v, t)
            if w != v:
                fl.append("conversion")
            return w
        return conv

    def conv(v, fl):
        if lo <= v <= hi:
            return v
        fl.append("conversion")
        return wrap_to(v, t)
    return conv


def _arith(op: str, t: CType):
    """``(a, b, flags) -> a op b`` in ``t`` for operands already of ``t`` (the evaluator's
    ``arith``; a zero divisor stops the run)."""
    lo, hi, over = t.min, t.max, _overflow(t)
    if op in ("+", "-", "*"):
        exact = {"+": int.__add__, "-": int.__sub__, "*": int.__mul__}[op]

        def f(a, b, fl):
            x = exact(a, b)
            if lo <= x <= hi:
                return x
            fl.append(over)
            return wrap_to(x, t)
        return f
    if op == "/":
        def f(a, b, fl):
            if b == 0:
                raise _Stop
            x = trunc_div(a, b)
            if x * b != a:
                fl.append("truncation")
            if lo <= x <= hi:
                return x
            fl.append(over)
            if t.signed:
                fl.append(_DIV_OVERFLOW)
            return wrap_to(x, t)
        return f
    if op == "%":
        def f(a, b, fl):
            if b == 0:
                raise _Stop
            if t.signed and a == lo and b == -1:
                fl += ("signed_overflow", _DIV_OVERFLOW)
                return 0
            return a - trunc_div(a, b) * b
        return f
    if op in ("<<", ">>"):
        return _shift(op, t)
    return {"&": lambda a, b, fl: a & b, "|": lambda a, b, fl: a | b,
            "^": lambda a, b, fl: a ^ b}[op]


def _shift(op: str, t: CType):
    bits, lo, hi, over = t.bits, t.min, t.max, _overflow(t)
    if op == "<<":
        def f(a, n, fl):
            if not 0 <= n < bits:
                fl.append("shift_count")
                return 0
            x = a << n
            if lo <= x <= hi:
                return x
            fl.append(over)
            return wrap_to(x, t)
        return f

    def f(a, n, fl):
        if not 0 <= n < bits:
            fl.append("shift_count")
            return -1 if a < 0 else 0
        if a & ((1 << n) - 1):
            fl.append("truncation")
        return a >> n
    return f


_COMPARE = {"<": lambda a, b: int(a < b), ">": lambda a, b: int(a > b),
            "<=": lambda a, b: int(a <= b), ">=": lambda a, b: int(a >= b),
            "==": lambda a, b: int(a == b), "!=": lambda a, b: int(a != b)}


class Compiled:
    """A :class:`~pulab.ctrace.check.Checked` program without entry function as closures.

    Parameters
    ----------
    checked : Checked
        From :func:`~pulab.ctrace.tracing.compile_code` (never changed here).
    global_q : int in 1..30
        The Q of ``_IQmpy`` when the code does not ``#define GLOBAL_Q``.

    Raises
    ------
    Uncompilable
        A construct outside the straight-line part of the subset.
    """

    def __init__(self, checked: Checked, global_q: int = 24) -> None:
        if checked.entry is not None or checked.functions or checked.pointers:
            raise Uncompilable("functions and pointers")
        self.checked = checked
        self.global_q = checked.program.global_q or global_q
        self.long = checked.target.types["long"]
        statements = checked.program.statements
        if len(statements) > MAX_STEPS:
            raise Uncompilable("too many statements")
        self.record = True
        self.statements = [self.statement(s) for s in statements]
        self.record = False
        self.quiet = [self.statement(s) for s in statements]
        self.names = list(checked.symbols)

    def run(self, inputs: dict) -> Run:
        """Run once with ``inputs`` (path → integer, already valid for the code, as
        :func:`~pulab.ctrace.tracing.input_values` returns them).

        Raises
        ------
        Stopped
            Where the evaluator raises its error (it names the error: :func:`run_compiled`).
        """
        mem: dict = {}
        steps: list = []
        i = 0
        try:
            for st in self.statements:
                st(mem, steps, inputs)
                i += 1
        except (_Stop, KeyError):  # KeyError: a variable read before it has a value
            raise Stopped(i, steps) from None
        return Run({name: mem.get(name) for name in self.names}, steps)

    def values(self, inputs: dict) -> tuple:
        """:meth:`run` without steps, for a simulation's inner loop: (memory: path → value of
        every variable set, flags: every flag the run raised, unordered with repeats).

        Raises
        ------
        Stopped
            As :meth:`run` (its ``steps`` empty).
        """
        mem: dict = {}
        fl: list = []
        i = 0
        try:
            for st in self.quiet:
                st(mem, fl, inputs)
                i += 1
        except (_Stop, KeyError):
            raise Stopped(i, []) from None
        return mem, fl

    # -- statements: each a closure (mem, steps, inputs) appending its steps, or when not
    # recording (mem, flags, inputs) appending its flags to the run's
    def statement(self, s):
        kind = type(s)
        if kind is Decl:
            return self.decl(s)
        if kind is ExprStmt:
            return self.expr_stmt(s)
        if kind is If:
            return self.if_stmt(s)
        if kind is Block:
            inner = [self.statement(x) for x in s.statements]

            def block(mem, steps, inputs):
                for st in inner:
                    st(mem, steps, inputs)
            return block
        raise Uncompilable(kind.__name__)

    def decl(self, s: Decl):
        parts = []
        for var, init, _ in s.items:
            sym = var.sym
            t = sym.ctype
            if type(t) is not CType:
                raise Uncompilable("an object that is not an integer")
            parts.append((sym.key, None if init is None else self.expr(init), _converter(t)))

        if not self.record:
            def quiet(mem, fl, inputs):
                for key, init, conv in parts:
                    if init is None:
                        if key in inputs:
                            mem[key] = inputs[key]
                    else:
                        mem[key] = conv(init(mem, fl), fl)
            return quiet

        def decl(mem, steps, inputs):
            for key, init, conv in parts:
                if init is None:
                    if key in inputs:
                        v = mem[key] = inputs[key]
                        steps.append(Step(s, key, v, [], False))
                    continue
                fl: list = []
                v = init(mem, fl)
                n = len(fl)
                w = mem[key] = conv(v, fl)
                steps.append(Step(s, key, w, fl, len(fl) > n))
        return decl

    def expr_stmt(self, s: ExprStmt):
        e = s.expr
        if not isinstance(e.ctype, CType):
            raise Uncompilable("a void expression")
        if not self.record:
            f = self.expr(e)
            return lambda mem, fl, inputs: f(mem, fl)
        if type(e) is Assign:
            path, value = self.assignment(e)

            def assign(mem, steps, inputs):
                fl: list = []
                w, stored = value(mem, fl)
                steps.append(Step(s, path, w, fl, stored))
            return assign
        f = self.expr(e)
        if type(e) is IncDec:
            path = self.path(e.target)

            def incdec(mem, steps, inputs):
                fl: list = []
                f(mem, fl)
                steps.append(Step(s, path, mem[path], fl, False))
            return incdec

        def expr(mem, steps, inputs):
            fl: list = []
            v = f(mem, fl)
            steps.append(Step(s, None, v, fl, False))
        return expr

    def if_stmt(self, s: If):
        test = self.expr(s.test)
        then = self.statement(s.then)
        other = self.statement(s.other) if s.other is not None else None

        if not self.record:
            def quiet(mem, fl, inputs):
                if test(mem, fl) != 0:
                    then(mem, fl, inputs)
                elif other is not None:
                    other(mem, fl, inputs)
            return quiet

        def if_(mem, steps, inputs):
            fl: list = []
            taken = test(mem, fl) != 0
            steps.append(Step(s, None, int(taken), fl, False))
            if taken:
                then(mem, steps, inputs)
            elif other is not None:
                other(mem, steps, inputs)
        return if_

    # -- expressions: each a closure (mem, flags) -> int
    @staticmethod
    def path(e) -> str:
        if type(e) is Var and e.sym is not None and type(e.ctype) is CType:
            return e.sym.key
        if type(e) is Member and e.flat is not None and type(e.ctype) is CType:
            return e.flat.key
        raise Uncompilable("an object that is not a named integer")

    def expr(self, e):
        kind = type(e)
        if kind is Num:
            n = e.value
            return lambda mem, fl: n
        if kind is Var or kind is Member:
            path = self.path(e)
            return lambda mem, fl: mem[path]  # unset: KeyError, the run stops
        if kind is Binary:
            return self.binary(e)
        if kind is Assign:
            path, value = self.assignment(e)

            def assign(mem, fl):
                return value(mem, fl)[0]
            return assign
        if kind is Cast:
            if type(e.ctype) is not CType:
                raise Uncompilable("a pointer cast")
            operand, conv = self.expr(e.operand), _converter(e.ctype)
            return lambda mem, fl: conv(operand(mem, fl), fl)
        if kind is Unary:
            return self.unary(e)
        if kind is Logical:
            left, right, both = self.expr(e.left), self.expr(e.right), e.op == "&&"

            def logical(mem, fl):
                a = left(mem, fl) != 0
                if both == a:  # && goes on when true, || when false
                    a = right(mem, fl) != 0
                return int(a)
            return logical
        if kind is Cond:
            test, then, other = self.expr(e.test), self.expr(e.then), self.expr(e.other)
            conv = _converter(e.ctype)

            def cond(mem, fl):
                return conv(then(mem, fl) if test(mem, fl) != 0 else other(mem, fl), fl)
            return cond
        if kind is IncDec:
            return self.incdec(e)
        if kind is Call and e.func is None:
            return self.call(e)
        raise Uncompilable(kind.__name__)

    def binary(self, e: Binary):
        left, right, t, op = self.expr(e.left), self.expr(e.right), e.operand_type, e.op
        if op in ("<<", ">>"):
            sh = _shift(op, t)
            return lambda mem, fl: sh(left(mem, fl), right(mem, fl), fl)
        conv = _converter(t)
        if op in _COMPARE:
            cmp = _COMPARE[op]
            return lambda mem, fl: cmp(conv(left(mem, fl), fl), conv(right(mem, fl), fl))
        f = _arith(op, t)
        lo, hi = t.min, t.max
        if _within(e.left.ctype, t) and _within(e.right.ctype, t):  # no conversion: the
            # hot case, with a variable or constant operand read in place
            ln, rn = self.leaf(e.left), self.leaf(e.right)
            if ln and rn:
                (lv, lx), (rv, rx) = ln, rn
                if lv and rv:
                    return lambda mem, fl: f(mem[lx], mem[rx], fl)
                if lv:
                    return lambda mem, fl: f(mem[lx], rx, fl)
                if rv:
                    return lambda mem, fl: f(lx, mem[rx], fl)
            if ln and ln[0]:
                lx = ln[1]
                return lambda mem, fl: f(mem[lx], right(mem, fl), fl)
            if rn and rn[0]:
                rx = rn[1]
                return lambda mem, fl: f(left(mem, fl), mem[rx], fl)
            return lambda mem, fl: f(left(mem, fl), right(mem, fl), fl)

        def binary(mem, fl):
            a = left(mem, fl)
            b = right(mem, fl)
            if not lo <= a <= hi:
                a = conv(a, fl)
            if not lo <= b <= hi:
                b = conv(b, fl)
            return f(a, b, fl)
        return binary

    def leaf(self, e):
        """(True, path) for a named integer, (False, value) for a constant, else None."""
        if type(e) is Num:
            return False, e.value
        if type(e) in (Var, Member):
            return True, self.path(e)
        return None

    def unary(self, e: Unary):
        operand, t, op = self.expr(e.operand), e.ctype, e.op
        if op == "-":
            over = _overflow(t)

            def neg(mem, fl):
                a = -operand(mem, fl)
                v = wrap_to(a, t)
                if v != a:
                    fl.append(over)
                return v
            return neg
        if op == "~":
            return lambda mem, fl: wrap_to(~operand(mem, fl), t)
        if op == "!":
            return lambda mem, fl: int(operand(mem, fl) == 0)
        if op == "+":
            return operand
        raise Uncompilable(f"unary {op}")

    def assignment(self, e: Assign) -> tuple:
        """The target's path and a closure ``(mem, flags) -> (stored, changed by the store)``."""
        path = self.path(e.target)
        value, conv = self.expr(e.value), _converter(e.target.ctype)
        if e.op == "=":
            def assign(mem, fl):
                v = value(mem, fl)
                n = len(fl)
                w = mem[path] = conv(v, fl)
                return w, len(fl) > n
            return path, assign
        ot, op = e.operand_type, e.op[:-1]
        f = _arith(op, ot)
        shift = op in ("<<", ">>")
        oconv = _converter(ot)

        def compound(mem, fl):
            b = value(mem, fl)
            old = mem[path]
            if not shift:
                old, b = oconv(old, fl), oconv(b, fl)
            v = f(old, b, fl)
            n = len(fl)
            w = mem[path] = conv(v, fl)
            return w, len(fl) > n
        return path, compound

    def incdec(self, e: IncDec):
        path, ot, prefix = self.path(e.target), e.operand_type, e.prefix
        f, oconv, conv = _arith("+" if e.op == "++" else "-", ot), _converter(ot), \
            _converter(e.ctype)

        def incdec(mem, fl):
            old = mem[path]
            w = mem[path] = conv(f(oconv(old, fl), 1, fl), fl)
            return w if prefix else old
        return incdec

    def call(self, e: Call):
        if e.iq is None:  # a function of the code: the evaluator runs it
            raise Uncompilable(e.name)
        args = [self.expr(a) for a in e.args]
        conv = _converter(self.long)
        q = self.global_q if e.q is None else e.q
        op, bits = e.iq, self.long.bits

        def iq(mem, fl):
            # the arguments as the library's long, then the operation as the evaluator does it
            v, more = iq_value(op, [conv(a(mem, fl), fl) for a in args], q, bits)
            fl.extend(more)
            return v
        return iq


#: Compiled programs by their checked program (a few: the seed's blocks and a page's code).
_CACHE: dict = {}
_KEPT = 16


def compiled(checked: Checked, global_q: int = 24) -> Compiled:
    """The closures of ``checked``, compiled on first use and then kept.

    Raises
    ------
    Uncompilable
        See :class:`Compiled`.
    """
    key = (id(checked), global_q)
    hit = _CACHE.get(key)
    if hit is not None and hit[0] is checked:
        return hit[1]
    prog = Compiled(checked, global_q)
    _CACHE[key] = (checked, prog)  # the checked program is kept alive, so its id stays its own
    while len(_CACHE) > _KEPT:
        del _CACHE[next(iter(_CACHE))]
    return prog


def run_compiled(checked: Checked, inputs: dict, global_q: int | None = None) -> Run:
    """:func:`~pulab.ctrace.tracing.run_checked` through the closures: inputs validated the
    same way, and where the run stops the evaluator runs to raise the tracer's own error.

    >>> from .tracing import compile_code
    >>> checked = compile_code("Uint16 v; Uint16 w = 100 / v;", "c28x")
    >>> run_compiled(checked, {"v": 7}).values["w"]
    14
    >>> run_compiled(checked, {"v": 0})
    Traceback (most recent call last):
    ...
    pulab.ctrace.errors.TraceError: code: 1:28: division by zero
    """
    values = input_values(checked, inputs or {})
    prog = compiled(checked, global_q or DEFAULT_GLOBAL_Q)
    try:
        return prog.run(values)
    except Stopped:
        run_checked(checked, inputs, global_q, record=False)
        raise AssertionError("the evaluator ran where the closures stopped") from None
