"""Parser of the C subset: statements, expressions, ``#define`` constants, ``// @q`` notes.

The subset is what firmware scaling code is made of:

- declarations ``[const|static|volatile] TYPE name [= expr] {, name [= expr]};`` with
  the C spellings and firmware names of :mod:`pulab.ctrace.types`, and the names that
  ``typedef INTEGER-TYPE NAME;`` makes (a typedef name stands for its integer type);
- expression statements: assignments, compound assignments, ``++``/``--``;
- ``if (…) … else …`` and ``{ … }`` (one flat scope: a name is declared once);
- every C integer operator, casts, ``?:``, integer constants (decimal, hex, octal,
  binary, suffixes ``U``, ``L``, ``LL``), names with dots (``gMotorInfo.Voltage``
  is one variable) and the IQmath calls ``_IQmpy``, ``_IQNmpy``, ``__IQmpy(a,b,q)``,
  ``_IQsat``, ``__IQsat``;
- the preprocessor of :mod:`pulab.ctrace.preprocess` (macros, ``#if`` family,
  standard headers; ``#define GLOBAL_Q n`` also sets IQmath's Q);
- annotations ``// @q NAME Qn [base=NUMBER [UNIT]]``: the variable holds a Qn number
  (real = value/2**n) whose per-unit base is NUMBER UNIT, so its SI value is real·base.

Everything else (loops, functions, pointers, floating point) is refused with a
:class:`TraceError` naming line and column.

Examples
--------
>>> prog = parse("Uint16 v = 17; // @q v Q0 base=1 V\\n v *= 10;")
>>> [type(s).__name__ for s in prog.statements], prog.notes["v"].unit
(['Decl', 'ExprStmt'], 'V')
"""

from __future__ import annotations

import re

from .errors import TraceError
from .lexer import Token, tokenize
from .preprocess import preprocess
from .types import BASE_TYPE_WORDS, TARGETS

__all__ = ["parse", "Program", "QNote", "Num", "Var", "Unary", "Binary", "Logical", "Cond",
           "Cast", "Assign", "IncDec", "Call", "Decl", "ExprStmt", "If", "Block",
           "IQ_FUNCTIONS", "MAX_DEPTH", "MAX_HEIGHT", "ALL_TYPE_NAMES"]

#: Deeper nesting of parentheses, unary operators and blocks is refused, and so are
#: expression trees taller than MAX_HEIGHT (recursion guards: pasted garbage must not crash).
MAX_DEPTH = 100
MAX_HEIGHT = 200

#: Every type spelling of every target (a spelling one target lacks is refused by the checker).
ALL_TYPE_NAMES = frozenset(n for t in TARGETS.values() for n in t.types)
_QUALIFIERS = frozenset({"const", "static", "volatile", "register", "extern", "auto", "inline",
                         "__inline", "__inline__"})
_FLOATING = frozenset({"float", "double"})
_UNSUPPORTED = frozenset({"for", "while", "do", "switch", "case", "return", "goto", "break",
                          "continue", "struct", "union", "enum", "sizeof",
                          "float", "double", "void", "default"})
_IQ_N = re.compile(r"_IQ([1-9]|[12][0-9]|30)mpy")
#: The IQmath calls understood, with their argument counts.
IQ_FUNCTIONS = {"_IQmpy": 2, "__IQmpy": 3, "_IQsat": 3, "__IQsat": 3}

_PRECEDENCE = {op: level for level, ops in enumerate(
    [("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="),
     ("<<", ">>"), ("+", "-"), ("*", "/", "%")]) for op in ops}
_ASSIGN_OPS = frozenset({"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "^=", "|="})
_SUFFIX = re.compile(r"(?i)(u?(l|ll)?|(l|ll)u)")
_NOTE = re.compile(r"//\s*@q\s+(?P<name>[A-Za-z_][\w.]*)\s+(?P<q>Q(?:\d+\.)?\d+)"
                   r"(?:\s+base=(?P<base>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))?"
                   r"(?:\s+(?P<unit>\S+))?\s*$")


class Node:
    """An expression: ``start``/``end`` are source offsets, ``ctype`` is set by the checker."""

    __slots__ = ("line", "column", "start", "end", "ctype")

    def at(self, first: Token, last: Token) -> "Node":
        self.line, self.column, self.start, self.end = first.line, first.column, first.start, \
            last.end
        return self


class Num(Node):
    __slots__ = ("value", "text")

    def __init__(self, value: int, text: str) -> None:
        self.value, self.text = value, text


class Var(Node):
    __slots__ = ("name",)

    def __init__(self, name: str) -> None:
        self.name = name


class Unary(Node):
    __slots__ = ("op", "operand")

    def __init__(self, op: str, operand: Node) -> None:
        self.op, self.operand = op, operand


class Binary(Node):
    __slots__ = ("op", "left", "right", "operand_type")

    def __init__(self, op: str, left: Node, right: Node) -> None:
        self.op, self.left, self.right = op, left, right


class Logical(Node):
    __slots__ = ("op", "left", "right")

    def __init__(self, op: str, left: Node, right: Node) -> None:
        self.op, self.left, self.right = op, left, right


class Cond(Node):
    __slots__ = ("test", "then", "other")

    def __init__(self, test: Node, then: Node, other: Node) -> None:
        self.test, self.then, self.other = test, then, other


class Cast(Node):
    __slots__ = ("type_name", "operand")

    def __init__(self, type_name: str, operand: Node) -> None:
        self.type_name, self.operand = type_name, operand


class Assign(Node):
    __slots__ = ("op", "target", "value", "operand_type")

    def __init__(self, op: str, target: Var, value: Node) -> None:
        self.op, self.target, self.value = op, target, value


class IncDec(Node):
    __slots__ = ("op", "prefix", "target", "operand_type")

    def __init__(self, op: str, prefix: bool, target: Var) -> None:
        self.op, self.prefix, self.target = op, prefix, target


class Call(Node):
    __slots__ = ("name", "args", "q")

    def __init__(self, name: str, args: list, q: int | None) -> None:
        self.name, self.args, self.q = name, args, q


class Stmt:
    """A statement; ``start``/``end`` span its source text."""

    __slots__ = ("line", "column", "start", "end")

    def at(self, first: Token, last: Token) -> "Stmt":
        self.line, self.column, self.start, self.end = first.line, first.column, first.start, \
            last.end
        return self


class Decl(Stmt):
    """``TYPE a = 1, b;``: ``items`` is a list of (Var, initializer or None)."""

    __slots__ = ("type_name", "items")

    def __init__(self, type_name: str, items: list) -> None:
        self.type_name, self.items = type_name, items


class ExprStmt(Stmt):
    __slots__ = ("expr",)

    def __init__(self, expr: Node) -> None:
        self.expr = expr


class If(Stmt):
    __slots__ = ("test", "then", "other")

    def __init__(self, test: Node, then: Stmt, other: Stmt | None) -> None:
        self.test, self.then, self.other = test, then, other


class Block(Stmt):
    __slots__ = ("statements",)

    def __init__(self, statements: list) -> None:
        self.statements = statements


class QNote:
    """A ``// @q`` annotation: Q format and optional per-unit base of one variable."""

    __slots__ = ("name", "q", "base", "unit", "line", "column")

    def __init__(self, name: str, q: int, base: float | None, unit: str, line: int,
                 column: int) -> None:
        self.name, self.q, self.base, self.unit = name, q, base, unit
        self.line, self.column = line, column


class Program:
    """Parsed code: ``statements``, ``notes`` (name → QNote), ``global_q`` from ``#define``."""

    __slots__ = ("source", "statements", "notes", "global_q", "unresolved")

    def __init__(self, source: str, statements: list, notes: dict, global_q: int | None) -> None:
        self.source, self.statements, self.notes, self.global_q = source, statements, notes, \
            global_q


def _fail(tok: Token, message: str) -> TraceError:
    return TraceError(tok.line, tok.column, message)


def _note(tok: Token) -> QNote:
    m = _NOTE.match(tok.text)
    if m is None:
        raise _fail(tok, "annotation must read '// @q NAME Qn [base=NUMBER [UNIT]]'")
    q = m["q"][1:]
    n = int(q.split(".")[1]) if "." in q else int(q)
    if n > 63:
        raise _fail(tok, f"Q{n}: at most 63 fraction bits")
    base = float(m["base"]) if m["base"] is not None else None
    if base is not None and not (base == base and abs(base) != float("inf")):
        raise _fail(tok, "base must be a finite number")
    return QNote(m["name"], n, base, m["unit"] or "", tok.line, tok.column)


def _notes(tokens: list) -> tuple:
    """Tokens without the annotations, and the annotations' notes."""
    notes: dict = {}
    out: list = []
    for tok in tokens:
        if tok.kind == "annotation":
            note = _note(tok)
            notes[note.name] = note
        else:
            out.append(tok)
    return out, notes


def _int_constant(tok: Token) -> tuple:
    """Value and C type candidates of an integer constant (C99 6.4.4.1)."""
    text = tok.text
    m = re.fullmatch(r"(0[xX][0-9a-fA-F]+|0[bB][01]+|[0-9]+)([A-Za-z_0-9]*)", text)
    if m is None or "." in text:
        raise _fail(tok, f"{text}: only integer constants are supported (no floating point)")
    digits, suffix = m[1], m[2]
    if not _SUFFIX.fullmatch(suffix) or "lL" in suffix or "Ll" in suffix:
        raise _fail(tok, f"{text}: bad integer suffix {suffix!r}")
    if digits[:2] in ("0x", "0X"):
        value, decimal = int(digits[2:], 16), False
    elif digits[:2] in ("0b", "0B"):
        value, decimal = int(digits[2:], 2), False
    elif len(digits) > 1 and digits[0] == "0":
        if not re.fullmatch(r"[0-7]+", digits):
            raise _fail(tok, f"{text}: bad octal constant")
        value, decimal = int(digits, 8), False
    else:
        value, decimal = int(digits), True
    s = suffix.lower()
    unsigned = "u" in s
    length = s.count("l")
    sizes = ["int", "long", "long long"][length:]
    if unsigned:
        cands = ["unsigned " + k for k in sizes]
    elif decimal:
        cands = sizes
    else:
        cands = [c for k in sizes for c in (k, "unsigned " + k)]
    return value, cands


class _Parser:
    def __init__(self, source: str, tokens: list) -> None:
        self.source = source
        self.tokens = tokens
        self.pos = 0
        self.depth = 0
        self.height = 0  # the tree height on the current path: depth plus left-operand chains
        self.type_names: frozenset = frozenset()
        self.aliases: dict = {}  # typedef name -> the spelling it stands for
        self.floating: dict = {}  # typedef name of float/double/pointer -> (token, what)

    # -- token helpers
    def peek(self, k: int = 0) -> Token:
        return self.tokens[self.pos + k]  # the list ends in two 'end' tokens: k <= 1

    def take(self) -> Token:
        tok = self.tokens[self.pos]
        if tok.kind != "end":
            self.pos += 1
        return tok

    def last(self) -> Token:
        return self.tokens[self.pos - 1]

    def is_op(self, text: str, k: int = 0) -> bool:
        # Only operator tokens have symbol text (names, numbers and directives cannot).
        return self.tokens[self.pos + k].text == text

    def expect(self, text: str, what: str = "") -> Token:
        tok = self.peek()
        if tok.kind == "op" and tok.text == text:
            return self.take()
        got = "end of code" if tok.kind == "end" else repr(tok.text)
        raise _fail(tok, f"expected '{text}'{what}, got {got}")

    def deeper(self) -> None:
        """One more level of recursion: bounds the parser's and the evaluator's stacks."""
        self.depth += 1
        self.height += 1
        if self.depth > MAX_DEPTH:
            raise _fail(self.peek(), f"nested more than {MAX_DEPTH} deep")

    def shallower(self) -> None:
        self.depth -= 1
        self.height -= 1

    # -- types
    def starts_type(self, k: int = 0) -> bool:
        t = self.peek(k)
        return t.kind == "name" and (t.text in BASE_TYPE_WORDS or t.text in self.type_names
                                     or t.text in _QUALIFIERS)

    def type_spelling(self) -> str:
        """A type's spelling, normalized: ``unsigned long int`` → ``unsigned long``."""
        first = self.peek()
        words = []
        while self.peek().kind == "name" and self.peek().text in _QUALIFIERS:
            self.take()
        tok = self.peek()
        if tok.kind == "name" and tok.text in self.type_names and \
                tok.text not in BASE_TYPE_WORDS:
            if tok.text in self.floating:
                at, what = self.floating[tok.text]
                raise _fail(tok, f"{tok.text} is {what} (typedef at {at.line}:{at.column}), "
                                 "not supported")
            self.take()
            while self.peek().kind == "name" and self.peek().text in _QUALIFIERS:
                self.take()
            return self.aliases.get(tok.text, tok.text)
        while self.peek().kind == "name" and (self.peek().text in BASE_TYPE_WORDS or
                                              self.peek().text in _QUALIFIERS):
            w = self.take().text
            if w not in _QUALIFIERS:
                words.append(w)
        if not words:
            raise _fail(first, "expected a type")
        sign = [w for w in words if w in ("signed", "unsigned")]
        longs = words.count("long")
        kinds = [w for w in words if w in ("char", "short", "int")]
        if len(sign) > 1 or longs > 2 or len(kinds) > 1 or \
                (kinds and kinds[0] != "int" and longs) or (words.count("int") > 1):
            raise _fail(first, f"not a C type: {' '.join(words)}")
        base = "long long" if longs == 2 else "long" if longs == 1 else \
            (kinds[0] if kinds else "int")
        if sign == ["unsigned"]:
            return "unsigned " + base
        if sign == ["signed"] and base == "char":
            return "signed char"
        return base

    # -- statements
    def program(self) -> list:
        out = []
        while self.peek().kind != "end":
            out.append(self.statement())
        return out

    def statement(self) -> Stmt:
        tok = self.peek()
        if tok.kind == "op" and tok.text == ";":
            self.take()
            return Block([]).at(tok, tok)
        if tok.kind == "op" and tok.text == "{":
            self.take()
            self.deeper()
            body = []
            while not self.is_op("}"):
                if self.peek().kind == "end":
                    raise _fail(self.peek(), f"'{{' at {tok.line}:{tok.column} is never closed")
                body.append(self.statement())
            self.take()
            self.shallower()
            return Block(body).at(tok, self.last())
        if tok.kind == "name" and tok.text == "if":
            self.take()
            self.expect("(", " after 'if'")
            test = self.expression()
            self.expect(")", " to close the condition")
            self.deeper()
            then = self.statement()
            other = None
            if self.peek().kind == "name" and self.peek().text == "else":
                self.take()
                other = self.statement()
            self.shallower()
            return If(test, then, other).at(tok, self.last())
        if tok.kind == "name" and tok.text == "else":
            raise _fail(tok, "'else' without 'if'")
        if tok.kind == "name" and tok.text in _UNSUPPORTED:
            raise _fail(tok, f"'{tok.text}' is not supported (declarations, assignments, "
                             "if/else only)")
        if tok.kind == "name" and tok.text == "typedef":
            return self.typedef()
        if self.starts_type():
            type_name = self.type_spelling()
            items = []
            while True:
                var = self.var_name("a variable name after the type")
                if self.is_op("("):
                    raise _fail(tok, f"function definition {var.name}(…) is not supported "
                                     "(trace its body's statements)")
                init = None
                if self.is_op("="):
                    self.take()
                    init = self.assignment()
                items.append((var, init))
                if not self.is_op(","):
                    break
                self.take()
            self.expect(";", " at the end of the declaration")
            return Decl(type_name, items).at(tok, self.last())
        expr = self.expression()
        self.expect(";", " at the end of the statement")
        return ExprStmt(expr).at(tok, self.last())

    def typedef(self) -> Stmt:
        """``typedef SCALAR NAME {, NAME};``: NAME becomes another spelling of SCALAR."""
        tok = self.take()
        nxt = self.peek()
        if nxt.kind == "name" and nxt.text in ("struct", "union", "enum"):
            raise _fail(nxt, f"typedef {nxt.text} is not supported (only typedefs of "
                             "integer types)")
        # As in rtwtypes.h: float, double and pointer typedefs are harmless until used.
        floating = nxt.kind == "name" and (nxt.text in _FLOATING or nxt.text == "void" or (
            nxt.text == "long" and self.peek(1).text == "double"))
        if floating:
            base = "long double" if self.take().text == "long" and self.take() else nxt.text
        else:
            base = self.type_spelling()
        while True:
            pointer = False
            while self.is_op("*") or (self.peek().kind == "name" and
                                      self.peek().text in _QUALIFIERS):
                pointer = pointer or self.take().text == "*"
            name = self.take()
            if name.kind != "name" or name.text in BASE_TYPE_WORDS or name.text in _QUALIFIERS:
                raise _fail(name, f"expected a name after typedef {base}, got "
                                  f"{'end of code' if name.kind == 'end' else repr(name.text)}")
            self.aliases[name.text] = base
            self.type_names = self.type_names | {name.text}
            if floating or pointer:
                self.floating[name.text] = (name, "a pointer type" if pointer or base == "void"
                                            else "a floating-point type")
            if not self.is_op(","):
                break
            self.take()
        self.expect(";", " at the end of the declaration")
        return Block([]).at(tok, self.last())

    def var_name(self, what: str) -> Var:
        tok = self.peek()
        if tok.kind != "name" or tok.text in BASE_TYPE_WORDS or tok.text in _QUALIFIERS:
            got = "end of code" if tok.kind == "end" else repr(tok.text)
            raise _fail(tok, f"expected {what}, got {got}")
        tokens = self.tokens
        pos = self.pos + 1
        name = tok.text
        while tokens[pos].text in (".", "->") and tokens[pos + 1].kind == "name":
            name += tokens[pos].text + tokens[pos + 1].text
            pos += 2
        self.pos = pos
        return Var(name).at(tok, tokens[pos - 1])

    # -- expressions
    def expression(self) -> Node:
        e = self.assignment()
        if self.is_op(","):
            raise _fail(self.peek(), "the comma operator is not supported")
        return e

    def assignment(self) -> Node:
        first = self.peek()
        self.deeper()
        left = self.conditional()
        tok = self.peek()
        if tok.kind == "op" and tok.text in _ASSIGN_OPS:
            if not isinstance(left, Var):
                raise _fail(tok, f"'{tok.text}' needs a variable on its left")
            self.take()
            value = self.assignment()
            left = Assign(tok.text, left, value).at(first, self.last())
        self.shallower()
        return left

    def conditional(self) -> Node:
        first = self.peek()
        test = self.binary(0)
        if not self.is_op("?"):
            return test
        self.take()
        self.deeper()
        then = self.expression()
        self.expect(":", " in '?:'")
        other = self.conditional()
        self.shallower()
        return Cond(test, then, other).at(first, self.last())

    def binary(self, min_prec: int) -> Node:
        """Precedence climbing: one call per operator precedence actually used."""
        first = self.peek()
        left = self.unary()
        chain = 0
        tokens = self.tokens
        while True:
            tok = tokens[self.pos]
            prec = _PRECEDENCE.get(tok.text)
            if prec is None or prec < min_prec:
                self.height -= chain
                return left
            self.pos += 1
            chain += 1
            self.height += 1
            if self.height > MAX_HEIGHT:
                raise _fail(tok, f"expression more than {MAX_HEIGHT} operators deep")
            self.deeper()
            right = self.binary(prec + 1)
            self.shallower()
            node = Logical(tok.text, left, right) if tok.text in ("&&", "||") else \
                Binary(tok.text, left, right)
            left = node.at(first, tokens[self.pos - 1])

    def unary(self) -> Node:
        tok = self.tokens[self.pos]
        if tok.text in ("+", "-", "~", "!"):
            self.take()
            self.deeper()
            operand = self.unary()
            self.shallower()
            return Unary(tok.text, operand).at(tok, self.last())
        if tok.text in ("++", "--"):
            self.take()
            self.deeper()
            target = self.unary()
            self.shallower()
            if not isinstance(target, Var):
                raise _fail(tok, f"'{tok.text}' needs a variable")
            return IncDec(tok.text, True, target).at(tok, self.last())
        if tok.text == "(" and self.starts_type(1):
            self.take()
            type_name = self.type_spelling()
            self.expect(")", " to close the cast")
            self.deeper()
            operand = self.unary()
            self.shallower()
            return Cast(type_name, operand).at(tok, self.last())
        return self.postfix()

    def postfix(self) -> Node:
        first = self.peek()
        node = self.primary()
        while self.tokens[self.pos].text in ("++", "--"):
            op = self.take()
            if not isinstance(node, Var):
                raise _fail(op, f"'{op.text}' needs a variable")
            node = IncDec(op.text, False, node).at(first, self.last())
        return node

    def primary(self) -> Node:
        tok = self.peek()
        if tok.kind == "number":
            self.take()
            value, cands = _int_constant(tok)
            n = Num(value, tok.text).at(tok, tok)
            n.ctype = cands  # resolved to one type by the checker (it knows the target)
            return n
        if tok.kind == "op" and tok.text == "(":
            self.take()
            self.deeper()
            e = self.expression()
            self.expect(")", f" to close '(' at {tok.line}:{tok.column}")
            self.shallower()
            # Keep the parentheses in the shown text.
            e.start, e.end = tok.start, self.last().end
            e.line, e.column = tok.line, tok.column
            return e
        if tok.kind == "name":
            if tok.text in _UNSUPPORTED or tok.text in BASE_TYPE_WORDS:
                raise _fail(tok, f"'{tok.text}' is not supported here")
            if self.is_op("(", 1):
                return self.call()
            return self.var_name("a name")
        got = "end of code" if tok.kind == "end" else repr(tok.text)
        raise _fail(tok, f"expected a value, got {got}")

    def call(self) -> Node:
        tok = self.take()
        name = tok.text
        nargs = IQ_FUNCTIONS.get(name)
        q = None
        m = _IQ_N.fullmatch(name)
        if m:
            nargs, q = 2, int(m[1])
        if nargs is None:
            raise _fail(tok, f"unknown function {name}() (supported: _IQmpy, _IQNmpy, "
                             "__IQmpy, _IQsat, __IQsat)")
        self.take()  # (
        self.deeper()
        args = []
        if not self.is_op(")"):
            while True:
                args.append(self.assignment())
                if not self.is_op(","):
                    break
                self.take()
        self.expect(")", f" to close {name}(")
        self.shallower()
        if len(args) != nargs:
            raise _fail(tok, f"{name}() takes {nargs} arguments, got {len(args)}")
        if name == "__IQmpy":
            qa = args[2]
            if not isinstance(qa, Num) or not 0 <= qa.value <= 62:
                raise _fail(tok, "__IQmpy(a, b, q): q must be an integer constant 0..62")
            q = qa.value
            args = args[:2]
        return Call(name, args, q).at(tok, self.last())


def parse(source: str, type_names: frozenset = ALL_TYPE_NAMES,
          defines: dict | None = None, global_q: int = 24) -> Program:
    """Parse C code; ``type_names`` are the type spellings the target knows, ``defines``
    the ``-D`` definitions (name → body text, see :mod:`pulab.ctrace.preprocess`),
    ``global_q`` IQmath's Q for ``_IQ(…)`` and its family when the code defines none.

    Raises
    ------
    TraceError
        At the first thing outside the subset, naming line and column.
    """
    if not isinstance(source, str):
        raise TraceError(1, 1, "code must be text")
    pre = preprocess(tokenize(source), defines, global_q)
    tokens, notes = _notes(pre.tokens)
    p = _Parser(source, tokens + tokens[-1:])
    p.type_names = type_names
    prog = Program(source, p.program(), notes, pre.global_q)
    prog.unresolved = pre.unresolved
    return prog
