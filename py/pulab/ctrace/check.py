"""Static typing of a parsed program for one target (C99 6.3, 6.5).

Every expression node gets ``ctype``: the C type of its value after the
integer promotions and the usual arithmetic conversions; binary operators
that convert their operands first also get ``operand_type``.  Types are known
before any value, so ``c ? a : b`` has its type even when a branch is never
evaluated.  Also found here: which variables are *inputs* (read before the
code gives them a value).

Examples
--------
>>> from .parser import parse
>>> from .types import TARGETS
>>> prog = parse("Uint16 v; long x = v * 10;")
>>> checked = check(prog, TARGETS["c28x"])
>>> checked.inputs, prog.statements[1].items[0][1].ctype.name
(['v'], 'unsigned int')
"""

from __future__ import annotations

from .errors import TraceError
from .parser import (Assign, Binary, Call, Cast, Cond, Decl, ExprStmt, If, IncDec,
                     Logical, Num, Program, Unary, Var)
from .types import Target, common_type, promote

__all__ = ["check", "Checked", "Symbol"]


class Symbol:
    """A declared variable: its spelling, C type, and whether it has an initializer."""

    __slots__ = ("name", "spelling", "ctype", "initialized", "line", "column")

    def __init__(self, name, spelling, ctype, initialized, line, column) -> None:
        self.name, self.spelling, self.ctype, self.initialized = name, spelling, ctype, \
            initialized
        self.line, self.column = line, column


class Checked:
    """A typed program: ``symbols`` (name → Symbol, in declaration order) and ``inputs``."""

    __slots__ = ("program", "target", "symbols", "inputs")

    def __init__(self, program: Program, target: Target, symbols: dict, inputs: list) -> None:
        self.program, self.target, self.symbols, self.inputs = program, target, symbols, inputs


def _type_of(target: Target, spelling: str, node) -> object:
    try:
        return target.type_named(spelling)
    except KeyError:
        raise TraceError(node.line, node.column,
                         f"{spelling} does not exist on {target.name}") from None


class _Checker:
    def __init__(self, target: Target) -> None:
        self.target = target
        self.int = target.types["int"]
        self.long = target.types["long"]
        self.symbols: dict = {}
        self.assigned: set = set()
        self.inputs: list = []

    def symbol(self, var: Var) -> Symbol:
        sym = self.symbols.get(var.name)
        if sym is None:
            raise TraceError(var.line, var.column, f"{var.name} is not declared (declare it "
                             f"with its type, e.g. 'Uint16 {var.name};')")
        return sym

    def read(self, var: Var) -> None:
        if var.name not in self.assigned and var.name not in self.inputs:
            self.inputs.append(var.name)

    def statement(self, s) -> None:
        if isinstance(s, Decl):
            for var, init in s.items:
                ctype = _type_of(self.target, s.type_name, s)
                if var.name in self.symbols:
                    prev = self.symbols[var.name]
                    raise TraceError(var.line, var.column, f"{var.name} is already declared "
                                     f"at {prev.line}:{prev.column}")
                if init is not None:
                    self.expr(init)
                self.symbols[var.name] = Symbol(var.name, s.type_name, ctype, init is not None,
                                                var.line, var.column)
                var.ctype = ctype
                if init is not None:
                    self.assigned.add(var.name)
        elif isinstance(s, ExprStmt):
            self.expr(s.expr)
        elif isinstance(s, If):
            self.expr(s.test)
            self.statement(s.then)
            if s.other is not None:
                self.statement(s.other)
        else:
            for inner in s.statements:
                self.statement(inner)

    def expr(self, e) -> object:
        t = self._expr(e)
        e.ctype = t
        return t

    def _expr(self, e) -> object:
        target = self.target
        if isinstance(e, Num):
            for name in e.ctype:
                t = target.types[name]
                if e.value <= t.max:
                    return t
            raise TraceError(e.line, e.column, f"{e.text} is too large for every integer "
                             f"type of its kind ({', '.join(e.ctype)})")
        if isinstance(e, Var):
            sym = self.symbol(e)
            self.read(e)
            return sym.ctype
        if isinstance(e, Unary):
            t = self.expr(e.operand)
            return self.int if e.op == "!" else promote(target, t)
        if isinstance(e, Binary):
            lt, rt = self.expr(e.left), self.expr(e.right)
            if e.op in ("<<", ">>"):
                e.operand_type = promote(target, lt)
                return e.operand_type
            e.operand_type = common_type(target, lt, rt)
            return self.int if e.op in ("<", ">", "<=", ">=", "==", "!=") else e.operand_type
        if isinstance(e, Logical):
            self.expr(e.left)
            self.expr(e.right)
            return self.int
        if isinstance(e, Cond):
            self.expr(e.test)
            return common_type(target, self.expr(e.then), self.expr(e.other))
        if isinstance(e, Cast):
            self.expr(e.operand)
            return _type_of(target, e.type_name, e)
        if isinstance(e, Assign):
            sym = self.symbol(e.target)
            vt = self.expr(e.value)
            e.target.ctype = sym.ctype
            if e.op != "=":
                self.read(e.target)
                e.operand_type = promote(target, sym.ctype) if e.op in ("<<=", ">>=") \
                    else common_type(target, sym.ctype, vt)
            self.assigned.add(e.target.name)
            return sym.ctype
        if isinstance(e, IncDec):
            sym = self.symbol(e.target)
            self.read(e.target)
            e.target.ctype = sym.ctype
            e.operand_type = common_type(target, sym.ctype, self.int)
            self.assigned.add(e.target.name)
            return sym.ctype
        if isinstance(e, Call):
            for a in e.args:
                self.expr(a)
            return self.long
        raise AssertionError(type(e).__name__)  # the parser makes no other node


def check(program: Program, target: Target) -> Checked:
    """Type every node of ``program`` for ``target``; find declared symbols and inputs.

    Raises
    ------
    TraceError
        An undeclared or twice-declared name, a type the target lacks, a constant
        too large, an annotation naming no variable.
    """
    c = _Checker(target)
    for s in program.statements:
        c.statement(s)
    for note in program.notes.values():
        if note.name not in c.symbols:
            raise TraceError(note.line, note.column, f"the annotation names {note.name}, "
                             "which is not declared")
    return Checked(program, target, c.symbols, c.inputs)
