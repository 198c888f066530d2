"""Parser of the C subset: the integer C that firmware scaling code is made of.

What it accepts:

- a script of file-scope declarations and statements, run top to bottom; or function
  definitions with file-scope declarations as their globals, one function (or a
  function-like macro, :mod:`~pulab.ctrace.macro_entry`) chosen as the entry.  Functions
  return an integer, a struct, a pointer or nothing; calls may nest but not recurse;
- declarations ``[qualifiers] TYPE a [= init], *p, t[N];`` with the C spellings and firmware
  names of :mod:`pulab.ctrace.types`, the names ``typedef`` gives integer and struct types,
  ``struct`` types (tagged, typedef'd, nested), ``enum`` constants, one level of pointers,
  arrays with braced initializers; each block has its own scope;
- statements: expressions, ``if``/``else``, blocks, ``for``, ``while``, ``do … while``,
  ``switch`` with its ``case``/``default`` labels at the top of its block, ``break``,
  ``continue``, ``return``;
- every C integer operator (compound assignments, ``++``/``--`` and ``?:`` included), casts
  (to integer types, and pointer casts between the same memory layout), ``.``, ``->``,
  ``[]``, unary ``&`` and ``*``, integer constants (decimal, hex, octal, binary, suffixes
  ``U``, ``L``, ``LL``), calls of the code's functions and the IQmath calls of
  :mod:`pulab.ctrace.iqmath` (``_IQmpy``, ``_IQNrsmpy``, ``_IQsinPU``, ``__IQmpy(a,b,q)``,
  ``_IQsat``, ``__IQsat``, ``_IQabs``, …);
- the preprocessor of :mod:`pulab.ctrace.preprocess` (macros, ``#if`` family,
  standard headers; ``#define GLOBAL_Q n`` also sets IQmath's Q);
- annotations ``// @q NAME Qn [base=NUMBER [UNIT]]``: the variable holds a Qn number
  (real = value/2**n) whose per-unit base is NUMBER UNIT, so its SI value is real·base;
  ``// @q NAME auto``: its Q is to be proposed by the code proof (``q`` None).

Refused, with a :class:`TraceError` naming line and column (a catalog code each): floating
point (constants and objects; a floating or pointer ``typedef`` only where it is used, as
is a definition outside the subset), character and string literals, ``union``, ``goto``,
``sizeof``, bit-fields, pointers to pointers, function pointers, variadic functions,
function and array typedefs, nested function definitions, designated initializers, the
comma operator.  The checker (:mod:`pulab.ctrace.check`) then refuses what is well-formed
but not computable: types a target lacks, names never declared, mismatched types.

The tree: expressions are :class:`Node` subclasses, statements :class:`Stmt` subclasses;
each has ``children()`` (its sub-nodes, in source order), and :class:`NodeVisitor` walks
them (pycparser's ``c_ast.NodeVisitor`` is the model).

Examples
--------
>>> prog = parse("Uint16 v = 17; // @q v Q0 base=1 V\\n v *= 10;")
>>> [type(s).__name__ for s in prog.statements], prog.notes["v"].unit
(['Decl', 'ExprStmt'], 'V')
"""

from __future__ import annotations

import re
import struct

from ..fixedpoint.cint import trunc_div
from .errors import TraceError
from .iqmath import ARITY, IQ_CALL
from .lexer import Token, beyond_64_bits, integer_digits, quoted, tokenize
from .preprocess import preprocess
from .types import BASE_TYPE_WORDS, TARGETS

__all__ = ["parse", "Program", "QNote", "Num", "Var", "Unary", "Binary", "Logical", "Cond",
           "Cast", "FNum", "Assign", "IncDec", "Call", "Member", "Index", "InitList", "Decl", "ExprStmt",
           "If", "Block", "Return", "Loop", "Switch", "Label", "Jump", "FuncDef", "StructDef", "Ptr",
           "Arr", "Unsupported", "NodeVisitor", "float_to_int",
           "constant_value", "MAX_DEPTH", "MAX_HEIGHT", "ALL_TYPE_NAMES"]

#: Deeper nesting of parentheses, unary operators and blocks is refused, and so are
#: expression trees taller than MAX_HEIGHT (recursion guards: pasted garbage must not crash).
MAX_DEPTH = 100
MAX_HEIGHT = 200

#: Every type spelling of every target (a spelling one target lacks is refused by the checker).
ALL_TYPE_NAMES = frozenset(n for t in TARGETS.values() for n in t.types)
_QUALIFIERS = frozenset({"const", "static", "volatile", "register", "extern", "auto", "inline",
                         "__inline", "__inline__"})
_FLOATING = frozenset({"float", "double"})
_UNSUPPORTED = frozenset({"goto", "sizeof", "float", "double"})
#: Words that begin a struct, union or enum type.
_TAGS = frozenset({"struct", "union", "enum"})
#: Compiler attributes and storage words that change no integer result (skipped, with a
#: parenthesized argument list when one follows).
_ATTRIBUTES = frozenset({"__attribute__", "__declspec", "__STATIC_INLINE", "__STATIC_FORCEINLINE",
                         "__INLINE", "__forceinline", "_inline", "__always_inline",
                         "__ramfunc", "RAMFUNC", "__weak", "__WEAK", "__interrupt",
                         "RESTRICT", "restrict", "__restrict", "__restrict__"})
_CONST_OPS = {"+": int.__add__, "-": int.__sub__, "*": int.__mul__,
              "/": trunc_div, "%": lambda a, b: a - b * trunc_div(a, b),
              "<<": int.__lshift__, ">>": int.__rshift__, "&": int.__and__, "|": int.__or__,
              "^": int.__xor__}
#: A decimal floating constant (C99 6.4.4.2): its digits, its suffix.
_FLOAT_LITERAL = re.compile(r"((?:[0-9]+\.[0-9]*|\.[0-9]+)(?:[eE][-+]?[0-9]+)?|[0-9]+[eE][-+]?[0-9]+)"
                            r"([fFlL]?)")
#: TI's intrinsics spelled with two underscores: the IQmath operation and its argument count.
_IQ_INTRINSICS = {"__IQmpy": ("mpy", 3), "__IQsat": ("sat", 3)}

_PRECEDENCE = {op: level for level, ops in enumerate(
    [("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="),
     ("<<", ">>"), ("+", "-"), ("*", "/", "%")]) for op in ops}
_ASSIGN_OPS = frozenset({"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "^=", "|="})
_SUFFIX = re.compile(r"(?i)(u?(l|ll)?|(l|ll)u)")
_NOTE = re.compile(r"//\s*@q\s+(?P<name>[A-Za-z_][\w.]*)\s+(?P<q>Q(?:\d+\.)?\d+|auto)"
                   r"(?:\s+base=(?P<base>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?))?"
                   r"(?:\s+(?P<unit>\S+))?\s*$")


class _Syntax:
    """What expressions, statements and function definitions share: their sub-nodes."""

    __slots__ = ()
    #: The slots that hold sub-nodes (a node, a list of nodes, or None), in source order.
    CHILDREN: tuple = ()

    def children(self) -> list:
        """The sub-nodes (expressions and statements), in source order."""
        out = []
        for name in self.CHILDREN:
            v = getattr(self, name)
            if type(v) is list:
                out.extend(v)
            elif v is not None:
                out.append(v)
        return out


class NodeVisitor:
    """A walk over the syntax tree (pycparser's ``c_ast.NodeVisitor`` is the model).

    :meth:`visit` calls the subclass's ``visit_<Class>(node)`` (``visit_Cast``, ``visit_Decl``
    …) when it has one, else :meth:`generic_visit`, which visits the node's children; a
    ``visit_`` method that is to go on below its node calls :meth:`generic_visit` itself.
    """

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        cls._methods = {}  # node class -> the method that visits it (the evaluator's hot path)

    _methods: dict = {}

    def visit(self, node):
        kind = type(node)
        method = self._methods.get(kind)
        if method is None:
            method = self._methods[kind] = getattr(type(self), "visit_" + kind.__name__,
                                                   type(self).generic_visit)
        return method(self, node)

    def generic_visit(self, node) -> None:
        for child in node.children():
            self.visit(child)


class Node(_Syntax):
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


class FNum(Node):
    """A floating constant, or a constant expression of them folded by the parser:
    ``value`` is already rounded to its type, ``single`` (binary32: ``float``, or ``double``
    where the target's double is 32 bits) or binary64.  Only a cast to an integer type
    (or a comparison) turns it into an integer; anywhere else the checker refuses it."""

    __slots__ = ("value", "single", "text")

    def __init__(self, value: float, single: bool, text: str) -> None:
        self.value, self.single, self.text = value, single, text


class Var(Node):
    __slots__ = ("name", "sym")

    def __init__(self, name: str) -> None:
        self.name, self.sym = name, None  # sym: the checker's Symbol


class Unary(Node):
    __slots__ = ("op", "operand")
    CHILDREN = ("operand",)

    def __init__(self, op: str, operand: Node) -> None:
        self.op, self.operand = op, operand


class Binary(Node):
    __slots__ = ("op", "left", "right", "operand_type")
    CHILDREN = ("left", "right")

    def __init__(self, op: str, left: Node, right: Node) -> None:
        self.op, self.left, self.right = op, left, right


class Logical(Node):
    __slots__ = ("op", "left", "right")
    CHILDREN = ("left", "right")

    def __init__(self, op: str, left: Node, right: Node) -> None:
        self.op, self.left, self.right = op, left, right


class Cond(Node):
    __slots__ = ("test", "then", "other")
    CHILDREN = ("test", "then", "other")

    def __init__(self, test: Node, then: Node, other: Node) -> None:
        self.test, self.then, self.other = test, then, other


class Cast(Node):
    """``(TYPE)operand``: ``type_name`` a scalar spelling or a :class:`Ptr` descriptor;
    ``from_void`` (set by the checker) when a ``void *`` becomes an object pointer;
    ``folded`` the floating constant a cast to an integer type was folded from (the
    operand is then its integer, truncated toward zero), else None."""

    __slots__ = ("type_name", "operand", "from_void", "folded")
    CHILDREN = ("operand",)

    def __init__(self, type_name, operand: Node, folded: float | None = None) -> None:
        self.type_name, self.operand, self.from_void, self.folded = type_name, operand, \
            False, folded


class Assign(Node):
    __slots__ = ("op", "target", "value", "operand_type")
    CHILDREN = ("target", "value")

    def __init__(self, op: str, target: Var, value: Node) -> None:
        self.op, self.target, self.value = op, target, value


class IncDec(Node):
    __slots__ = ("op", "prefix", "target", "operand_type")
    CHILDREN = ("target",)

    def __init__(self, op: str, prefix: bool, target: Var) -> None:
        self.op, self.prefix, self.target = op, prefix, target


class Call(Node):
    """A call: of a function of the code (``iq`` None), or of IQmath (``iq`` its operation,
    :data:`~pulab.ctrace.iqmath.ARITY`; ``q`` its Q, None for GLOBAL_Q)."""

    __slots__ = ("name", "args", "q", "func", "iq")
    CHILDREN = ("args",)

    def __init__(self, name: str, args: list, q: int | None, iq: str | None = None) -> None:
        self.name, self.args, self.q, self.func, self.iq = name, args, q, None, iq


class Member(Node):
    """``base.field`` or ``base->field`` (``arrow``)."""

    __slots__ = ("base", "field", "arrow", "flat")
    CHILDREN = ("base",)

    def __init__(self, base: Node, field: str, arrow: bool) -> None:
        self.base, self.field, self.arrow, self.flat = base, field, arrow, None


class Index(Node):
    __slots__ = ("base", "index")
    CHILDREN = ("base", "index")

    def __init__(self, base: Node, index: Node) -> None:
        self.base, self.index = base, index


class InitList(Node):
    """A braced initializer ``{a, b, {c}}``."""

    __slots__ = ("items",)
    CHILDREN = ("items",)

    def __init__(self, items: list) -> None:
        self.items = items


class StructDef:
    """A struct type as written: ``fields`` is a list of (name, type descriptor, spelling)."""

    __slots__ = ("name", "fields", "line", "column", "resolved")

    def __init__(self, name: str, line: int, column: int) -> None:
        self.name, self.fields, self.line, self.column = name, None, line, column
        self.resolved = {}  # target name -> the checker's StructT


class Ptr:
    """Type descriptor: pointer to ``to``; ``size`` the N of a parameter written ``T p[N]``."""

    __slots__ = ("to", "size")

    def __init__(self, to, size=None) -> None:
        self.to, self.size = to, size


class Unsupported:
    """Type descriptor of a struct field the subset cannot compute (``float_t ConvFact;``):
    ``reason`` is the error a use of the field raises (a catalog code and its params)."""

    __slots__ = ("reason",)

    def __init__(self, reason: dict) -> None:
        self.reason = reason


class Arr:
    """Type descriptor: array of ``of``, ``size`` a constant expression node or None."""

    __slots__ = ("of", "size")

    def __init__(self, of, size) -> None:
        self.of, self.size = of, size


class Stmt(_Syntax):
    """A statement; ``start``/``end`` span its source text."""

    __slots__ = ("line", "column", "start", "end")

    def at(self, first: Token, last: Token) -> "Stmt":
        self.line, self.column, self.start, self.end = first.line, first.column, first.start, \
            last.end
        return self


class Decl(Stmt):
    """``TYPE a = 1, *p, t[2];``: ``items`` is a list of (Var, initializer or None, type
    descriptor: a scalar spelling, :class:`StructDef`, :class:`Ptr`, :class:`Arr`)."""

    __slots__ = ("type_name", "items", "static")

    def __init__(self, type_name, items: list, static: bool = False) -> None:
        self.type_name, self.items, self.static = type_name, items, static

    def children(self) -> list:
        """Each declared variable, then its initializer (the type descriptors are not
        sub-nodes: an array size is a constant the checker reads)."""
        return [x for var, init, _ in self.items for x in (var, init) if x is not None]


class ExprStmt(Stmt):
    __slots__ = ("expr",)
    CHILDREN = ("expr",)

    def __init__(self, expr: Node) -> None:
        self.expr = expr


class If(Stmt):
    __slots__ = ("test", "then", "other")
    CHILDREN = ("test", "then", "other")

    def __init__(self, test: Node, then: Stmt, other: Stmt | None) -> None:
        self.test, self.then, self.other = test, then, other


class Block(Stmt):
    __slots__ = ("statements",)
    CHILDREN = ("statements",)

    def __init__(self, statements: list) -> None:
        self.statements = statements


class Return(Stmt):
    __slots__ = ("value",)
    CHILDREN = ("value",)

    def __init__(self, value: Node | None) -> None:
        self.value = value


class Loop(Stmt):
    """``for``/``while``/``do``: ``init`` (a statement or None), ``test`` (None = always),
    ``step`` (an expression or None), ``body``; ``kind`` is the keyword."""

    __slots__ = ("kind", "init", "test", "step", "body")
    CHILDREN = ("init", "test", "step", "body")

    def __init__(self, kind: str, init, test, step, body) -> None:
        self.kind, self.init, self.test, self.step, self.body = kind, init, test, step, body


class Switch(Stmt):
    """``switch (test) { case K: … default: … }``: ``body`` is the Block, whose top-level
    statements include the :class:`Label` markers."""

    __slots__ = ("test", "body")
    CHILDREN = ("test", "body")

    def __init__(self, test, body) -> None:
        self.test, self.body = test, body


class Label(Stmt):
    """``case K:`` (``value`` the constant expression node) or ``default:`` (None);
    ``value_int`` is set by the checker (the constant, None for default)."""

    __slots__ = ("value", "value_int")
    CHILDREN = ("value",)

    def __init__(self, value) -> None:
        self.value = value


class Jump(Stmt):
    """``break`` or ``continue``."""

    __slots__ = ("kind",)

    def __init__(self, kind: str) -> None:
        self.kind = kind


class FuncDef(_Syntax):
    """A function definition: ``ret`` (type descriptor or ``"void"``), ``params`` (list of
    (name, type descriptor, spelling, token)), ``body`` (Block)."""

    __slots__ = ("name", "ret", "ret_spelling", "params", "body", "line", "column", "start",
                 "end", "close_line", "close_column")
    CHILDREN = ("body",)

    def __init__(self, name, ret, ret_spelling, params, body, tok) -> None:
        self.name, self.ret, self.ret_spelling, self.params, self.body = name, ret, \
            ret_spelling, params, body
        self.line, self.column, self.start = tok.line, tok.column, tok.start
        self.end = body.end
        self.close_line = self.close_column = 0  # the closing brace, set by the parser


class QNote:
    """A ``// @q`` annotation: Q format and optional per-unit base of one variable."""

    __slots__ = ("name", "q", "base", "unit", "line", "column")

    def __init__(self, name: str, q: int, base: float | None, unit: str, line: int,
                 column: int) -> None:
        self.name, self.q, self.base, self.unit = name, q, base, unit
        self.line, self.column = line, column


class Program:
    """Parsed code: ``statements`` (outside functions), ``functions`` (name → FuncDef, in
    definition order), ``notes`` (name → QNote), ``global_q`` from ``#define``, ``macros``
    (name → the preprocessor's macro, as defined at the end) and ``aliases`` (typedef
    name → type descriptor)."""

    __slots__ = ("source", "statements", "notes", "global_q", "unresolved", "functions",
                 "refused", "macros", "aliases")

    def __init__(self, source: str, statements: list, notes: dict, global_q: int | None,
                 functions: dict | None = None, refused: dict | None = None) -> None:
        self.source, self.statements, self.notes, self.global_q = source, statements, notes, \
            global_q
        self.functions = functions or {}
        #: name -> (TraceError, is a function) of each file-scope definition outside the
        #: subset (the error is raised where the name is used)
        self.refused = refused or {}


def _unknown_type(tok: Token) -> TraceError:
    return TraceError(tok.line, tok.column, code="trace_unknown_type", name=tok.text)


def _got(tok: Token):
    """What was found instead, as a message parameter (the end of the code in words)."""
    return {"code": "trace_end_of_code", "params": {}} if tok.kind == "end" else repr(tok.text)


def _note(tok: Token) -> QNote:
    m = _NOTE.match(tok.text)
    if m is None:
        raise TraceError.at(tok, code="trace_annotation_syntax")
    if m["q"] == "auto":  # the code proof proposes the Q (pulab.ctrace.prove)
        return QNote(m["name"], None, None, "", tok.line, tok.column)
    q = m["q"][1:]
    n = int(q.split(".")[1]) if "." in q else int(q)
    if n > 63:
        raise TraceError.at(tok, code="trace_q_bits", n=n)
    base = float(m["base"]) if m["base"] is not None else None
    if base is not None and not (base == base and abs(base) != float("inf")):
        raise TraceError.at(tok, code="trace_base_finite")
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
        raise TraceError.at(tok, code="trace_float_constant", text=quoted(text))
    digits, suffix = m[1], m[2]
    if not _SUFFIX.fullmatch(suffix) or "lL" in suffix or "Ll" in suffix:
        raise TraceError.at(tok, code="trace_int_suffix", text=quoted(text), suffix=quoted(repr(suffix)))
    cands = _candidates(suffix.lower(), digits[:1] == "0" and len(digits) > 1)
    body, base = integer_digits(digits)
    if base == 8 and not re.fullmatch(r"[0-7]+", digits):
        raise TraceError.at(tok, code="trace_octal", text=quoted(text))
    if beyond_64_bits(body, base):
        raise TraceError.at(tok, code="trace_constant_large", text=quoted(text), types=", ".join(cands))
    return int(body, base), cands


def _candidates(suffix: str, not_decimal: bool) -> list:
    """The C types an integer constant may take, in order (C99 6.4.4.1); ``suffix`` lower case."""
    sizes = ["int", "long", "long long"][suffix.count("l"):]
    if "u" in suffix:
        return ["unsigned " + k for k in sizes]
    if not not_decimal:
        return sizes
    return [c for k in sizes for c in (k, "unsigned " + k)]


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
        self.structs: dict = {}  # struct tag -> StructDef
        self.enums: dict = {}  # enumeration constant -> value
        self.functions: dict = {}  # name -> FuncDef
        self.refused: dict = {}  # name of a file-scope definition outside the subset -> error
        self.loops = 0  # loops around the statement being parsed
        self.switches = 0  # switch statements around it
        self.in_function = False
        self.single_double = False  # the target's double is binary32 (avr-gcc)

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

    def expect(self, text: str, where: str | None = None, **params) -> Token:
        """Take the operator ``text``; else the error names it, where it was expected (a
        ``trace_where_*`` catalog code with ``params``) and what came instead."""
        tok = self.peek()
        if tok.kind == "op" and tok.text == text:
            return self.take()
        if where is None:
            raise TraceError.at(tok, code="trace_expected_bare", token=text, got=_got(tok))
        raise TraceError.at(tok, code="trace_expected", token=text, got=_got(tok),
                            where={"code": f"trace_where_{where}", "params": params})

    def deeper(self) -> None:
        """One more level of recursion: bounds the parser's and the evaluator's stacks."""
        self.depth += 1
        self.height += 1
        if self.depth > MAX_DEPTH:
            raise TraceError.at(self.peek(), code="trace_nested", limit=MAX_DEPTH)

    def shallower(self) -> None:
        self.depth -= 1
        self.height -= 1

    # -- types
    def starts_type(self, k: int = 0) -> bool:
        t = self.peek(k)
        return t.kind == "name" and (t.text in BASE_TYPE_WORDS or t.text in self.type_names
                                     or t.text in _QUALIFIERS or t.text in _TAGS or
                                     t.text in _ATTRIBUTES or t.text == "void")

    def qualifiers(self) -> bool:
        """Skip qualifiers and attributes; True when ``static`` was among them."""
        static = False
        while self.peek().kind == "name":
            w = self.peek().text
            if w in _QUALIFIERS:
                static = static or w == "static"
                self.take()
            elif w in _ATTRIBUTES:
                self.take()
                if self.is_op("("):  # __attribute__((…)), __declspec(…): balanced, ignored
                    self.skip_group()
            else:
                break
        return static

    def skip_group(self) -> None:
        open_tok = self.take()
        level = 1
        while level:
            tok = self.take()
            if tok.kind == "end":
                raise TraceError.at(open_tok, code="trace_paren_open")
            level += (tok.text == "(") - (tok.text == ")")

    def specifiers(self) -> tuple:
        """The type before a declarator: (descriptor, spelling, static).  A descriptor is
        a scalar spelling, ``"void"``, a :class:`StructDef`, or a :class:`Ptr` from a typedef."""
        first = self.peek()
        static = self.qualifiers()
        tok = self.peek()
        if tok.kind == "name" and tok.text in _TAGS:
            desc = self.tagged()
            static = self.qualifiers() or static
            return desc, f"{tok.text} {desc.name}" if isinstance(desc, StructDef) else "int", \
                static
        if tok.kind == "name" and tok.text == "void":
            self.take()
            static = self.qualifiers() or static
            return "void", "void", static
        if tok.kind == "name" and tok.text in self.type_names and \
                tok.text not in BASE_TYPE_WORDS:
            if tok.text in self.floating:
                raise TraceError.at(tok, **self.floating_error(tok.text))
            self.take()
            static = self.qualifiers() or static
            return self.aliases.get(tok.text, tok.text), tok.text, static
        words = []
        while self.peek().kind == "name" and (self.peek().text in BASE_TYPE_WORDS or
                                              self.peek().text in _QUALIFIERS):
            w = self.take().text
            if w in _QUALIFIERS:
                static = static or w == "static"
            else:
                words.append(w)
        if not words:
            if tok.kind == "name" and tok.text in _FLOATING:
                raise TraceError.at(tok, code="trace_not_integer", word=tok.text)
            if tok.kind == "name":
                raise _unknown_type(tok)
            raise TraceError.at(first, code="trace_expected_type")
        sign = [w for w in words if w in ("signed", "unsigned")]
        longs = words.count("long")
        kinds = [w for w in words if w in ("char", "short", "int")]
        if len(sign) > 1 or longs > 2 or len(kinds) > 1 or \
                (kinds and kinds[0] != "int" and longs) or (words.count("int") > 1):
            raise TraceError.at(first, code="trace_not_c_type", words=" ".join(words))
        base = "long long" if longs == 2 else "long" if longs == 1 else \
            (kinds[0] if kinds else "int")
        if sign == ["unsigned"]:
            base = "unsigned " + base
        elif sign == ["signed"] and base == "char":
            base = "signed char"
        static = self.qualifiers() or static
        return base, base, static

    def type_spelling(self):
        """A cast's type: a scalar type's spelling, normalized (``unsigned long int`` →
        ``unsigned long``), or a :class:`Ptr` descriptor."""
        first = self.peek()
        desc, _, _ = self.specifiers()
        while self.is_op("*"):
            self.take()
            desc = Ptr(desc)
            self.qualifiers()
        if isinstance(desc, StructDef) or desc == "void":
            raise TraceError.at(first, code="trace_cast_struct_void")
        return desc

    def tagged(self):
        """``struct [tag] [{ fields }]`` or ``enum [tag] [{ constants }]``."""
        kw = self.take()
        if kw.text == "union":
            raise TraceError.at(kw, code="trace_not_supported", word="union")
        tag = self.take() if self.peek().kind == "name" else None
        if kw.text == "enum":
            if self.is_op("{"):
                self.enumerators()
            return "int"
        if tag is None and not self.is_op("{"):
            raise TraceError.at(kw, code="trace_struct_tag")
        key = tag.text if tag is not None else f"<anonymous at {kw.line}:{kw.column}>"
        sdef = self.structs.get(key)
        if sdef is None:
            sdef = self.structs[key] = StructDef(key, kw.line, kw.column)
        if self.is_op("{"):
            if sdef.fields is not None:
                raise TraceError.at(kw, code="trace_struct_redefined", name=key,
                                    at=f"{sdef.line}:{sdef.column}")
            open_tok = self.take()
            fields: list = []
            names: set = set()
            while not self.is_op("}"):
                if self.peek().kind == "end":
                    raise TraceError.at(open_tok, code="trace_brace_open",
                                        at=f"{open_tok.line}:{open_tok.column}")
                desc, spelling = self.field_specifiers()
                while True:
                    name, d, at = self.declarator(desc)
                    if self.is_op(":"):
                        raise TraceError.at(self.peek(), code="trace_bitfield")
                    if name in names:
                        raise TraceError.at(at, code="trace_field_twice", name=name, struct=key)
                    names.add(name)
                    fields.append((name, d, spelling))
                    if not self.is_op(","):
                        break
                    self.take()
                self.expect(";", "struct_field")
            self.take()
            sdef.fields = fields
        return sdef

    def floating_error(self, name: str) -> dict:
        """The error for a use of a floating-point or pointer typedef: code and params."""
        at, what = self.floating[name]
        return {"code": "trace_typedef_pointer" if what == "a pointer type" else
                "trace_typedef_float", "name": name, "at": f"{at.line}:{at.column}"}

    def field_specifiers(self) -> tuple:
        """A struct field's type: as :meth:`specifiers`, except that a floating or pointer
        typedef (as in a handle beside the integers) is an :class:`Unsupported` field,
        refused where it is used."""
        self.qualifiers()
        tok = self.peek()
        if tok.kind == "name" and (tok.text in self.floating or tok.text in _FLOATING):
            reason = self.floating_error(tok.text) if tok.text in self.floating else \
                {"code": "trace_not_integer", "word": tok.text}
            self.take()
            self.qualifiers()
            return Unsupported(reason), tok.text
        desc, spelling, _ = self.specifiers()
        return desc, spelling

    def enumerators(self) -> None:
        self.take()
        value = -1
        while not self.is_op("}"):
            name = self.take()
            if name.kind != "name":
                raise TraceError.at(name, code="trace_enumerator_name")
            if self.is_op("="):
                self.take()
                value = self.constant(self.conditional(), "trace_const_enum")
            else:
                value += 1
            self.enums[name.text] = value
            if not self.is_op(","):
                break
            self.take()
        self.expect("}", "close_enum")

    def constant(self, node: Node, what: str) -> int:
        return constant_value(node, what)

    def declarator(self, desc) -> tuple:
        """``* const name [N]…``: (name, descriptor, name token)."""
        while self.is_op("*"):
            self.take()
            desc = Ptr(desc)
            self.qualifiers()
        tok = self.peek()
        if self.is_op("("):
            raise TraceError.at(tok, code="trace_function_pointer")
        var = self.var_name()
        sizes = []
        while self.is_op("["):
            self.take()
            size = None if self.is_op("]") else self.conditional()
            self.expect("]", "close_array_size")
            sizes.append(size)
        for size in reversed(sizes):
            desc = Arr(desc, size)
        self.qualifiers()
        return var.name, desc, tok

    # -- statements
    def program(self) -> list:
        out = []
        while self.peek().kind != "end":
            start = self.pos
            try:
                item = self.statement(top=True)
            except TraceError as err:
                # Real files mix integer routines with float helpers: a definition outside
                # the subset is refused when it is used, not when it is pasted.
                skipped = self.skip_definition(start)
                if skipped is None:
                    raise
                self.refused[skipped[0]] = (err, skipped[1])
                continue
            if isinstance(item, FuncDef):
                prev = self.functions.get(item.name)
                if prev is not None:
                    raise TraceError.at(self.tokens[self.pos - 1], code="trace_function_redefined",
                                        name=item.name, at=f"{prev.line}:{prev.column}")
                self.functions[item.name] = item
            elif item is not None:
                out.append(item)
        return out

    def skip_definition(self, start: int) -> str | None:
        """After an error in the file-scope item at ``start``: when it is a function
        definition or a declaration, move past it and return (its name, whether it is a
        function), else None."""
        tokens = self.tokens
        self.depth = self.height = self.loops = self.switches = 0
        self.in_function = False
        i, level, fname, last, frozen = start, 0, None, None, False
        while tokens[i].kind != "end":
            t = tokens[i]
            if t.kind == "name" and level == 0 and not frozen:
                last = t.text
            elif t.kind == "op" and t.text == "=" and level == 0:
                frozen = True  # the declared name came before the initializer
            elif t.kind == "op" and t.text in ("(", "[", "{"):
                if t.text == "{" and level == 0 and fname is not None:
                    break  # a function body
                if t.text == "(" and level == 0 and fname is None and last is not None:
                    fname = last
                level += 1
            elif t.kind == "op" and t.text in (")", "]", "}"):
                level -= 1
            elif t.kind == "op" and t.text == ";" and level == 0:
                self.pos = i + 1
                return (fname, True) if fname is not None and not frozen else \
                    ((last, False) if last is not None else None)
            i += 1
        else:
            return None
        depth = 0
        while tokens[i].kind != "end":
            depth += (tokens[i].text == "{") - (tokens[i].text == "}")
            i += 1
            if depth == 0:
                self.pos = i
                return fname, True
        return None

    def block(self) -> Block:
        tok = self.take()
        self.deeper()
        body = []
        while not self.is_op("}"):
            if self.peek().kind == "end":
                raise TraceError.at(self.peek(), code="trace_brace_open",
                                    at=f"{tok.line}:{tok.column}")
            body.append(self.statement())
        self.take()
        self.shallower()
        return Block(body).at(tok, self.last())

    def body(self) -> Stmt:
        self.deeper()
        s = self.statement()
        self.shallower()
        return s

    def statement(self, top: bool = False):
        tok = self.peek()
        if tok.kind == "op" and tok.text == ";":
            self.take()
            return Block([]).at(tok, tok)
        if tok.kind == "op" and tok.text == "{":
            return self.block()
        word = tok.text if tok.kind == "name" else None
        if word == "if":
            self.take()
            self.expect("(", "after", word="if")
            test = self.expression()
            self.expect(")", "close_condition")
            then = self.body()
            other = None
            if self.peek().kind == "name" and self.peek().text == "else":
                self.take()
                other = self.body()
            return If(test, then, other).at(tok, self.last())
        if word in ("while", "for", "do"):
            return self.loop()
        if word == "switch":
            self.take()
            self.expect("(", "after", word="switch")
            test = self.expression()
            self.expect(")", "close_condition")
            if not self.is_op("{"):
                raise TraceError.at(self.peek(), code="trace_switch_brace")
            self.switches += 1
            body = self.block()
            self.switches -= 1
            return Switch(test, body).at(tok, self.last())
        if word in ("case", "default"):
            self.take()
            if not self.switches:
                raise TraceError.at(tok, code="trace_outside_switch", word=word)
            value = self.conditional() if word == "case" else None
            self.expect(":", "after", word=word)
            return Label(value).at(tok, self.last())
        if word in ("break", "continue"):
            self.take()
            if not self.loops and (word == "continue" or not self.switches):
                raise TraceError.at(tok, code="trace_outside_loop", word=word)
            self.expect(";", "after", word=word)
            return Jump(word).at(tok, self.last())
        if word == "return":
            self.take()
            if not self.in_function:
                raise TraceError.at(tok, code="trace_return_outside")
            value = None if self.is_op(";") else self.expression()
            self.expect(";", "statement_end")
            return Return(value).at(tok, self.last())
        if word == "else":
            raise TraceError.at(tok, code="trace_else_without_if")
        if word in _UNSUPPORTED:
            raise TraceError.at(tok, code="trace_not_supported", word=word)
        if word == "typedef":
            return self.typedef()
        if self.starts_type():
            return self.declaration(top)
        if word is not None and (self.peek(1).kind == "name" or (
                self.is_op("*", 1) and self.tokens[self.pos + 2].kind == "name" and
                self.tokens[self.pos + 3].text in ("=", ",", "["))):
            raise _unknown_type(tok)  # NAME NAME: a declaration with a type never defined
        expr = self.expression()
        self.expect(";", "statement_end")
        return ExprStmt(expr).at(tok, self.last())

    def loop(self) -> Stmt:
        tok = self.take()
        init = step = None
        self.loops += 1
        if tok.text == "do":
            body = self.body()
            w = self.peek()
            if w.text != "while":
                raise TraceError.at(w, code="trace_do_while")
            self.take()
            self.expect("(", "after", word="while")
            test = self.expression()
            self.expect(")", "close_condition")
            self.expect(";", "do_while")
        else:
            self.expect("(", "after", word=tok.text)
            if tok.text == "for":
                if self.is_op(";"):
                    self.take()
                elif self.starts_type():
                    init = self.declaration(False)
                else:
                    first = self.peek()
                    init = ExprStmt(self.expression()).at(first, self.last())
                    self.expect(";", "loop_first")
                test = None if self.is_op(";") else self.expression()
                self.expect(";", "loop_condition")
                step = None if self.is_op(")") else self.expression()
            else:
                test = self.expression()
            self.expect(")", "close_condition")
            body = self.body()
        self.loops -= 1
        return Loop(tok.text, init, test, step, body).at(tok, self.last())

    def declaration(self, top: bool):
        tok = self.peek()
        desc, spelling, static = self.specifiers()
        if self.is_op(";"):  # struct tag { … }; or enum { … };
            self.take()
            return Block([]).at(tok, self.last())
        items = []
        while True:
            name, d, at = self.declarator(desc)
            if self.is_op("("):
                if not top or items:
                    raise TraceError.at(at, code="trace_nested_function", name=name)
                return self.function(tok, at, d, spelling)
            if d == "void":
                raise TraceError.at(at, code="trace_void_object", name=name)
            init = None
            if self.is_op("="):
                self.take()
                init = self.initializer()
            items.append((Var(name).at(at, at), init, d))
            if not self.is_op(","):
                break
            self.take()
        self.expect(";", "declaration_end")
        return Decl(spelling, items, static).at(tok, self.last())

    def initializer(self) -> Node:
        tok = self.peek()
        if not self.is_op("{"):
            return self.assignment()
        self.take()
        self.deeper()
        items = []
        while not self.is_op("}"):
            if self.is_op("."):
                raise TraceError.at(self.peek(), code="trace_designated")
            items.append(self.initializer())
            if not self.is_op(","):
                break
            self.take()
        self.expect("}", "close_brace", at=f"{tok.line}:{tok.column}")
        self.shallower()
        return InitList(items).at(tok, self.last())

    def function(self, first: Token, name_tok: Token, ret, ret_spelling: str):
        """A prototype (skipped: None) or a definition (FuncDef)."""
        open_tok = self.take()
        params = []
        if self.peek().text == "void" and self.is_op(")", 1):
            self.take()
        while not self.is_op(")"):
            if self.is_op("..."):
                raise TraceError.at(self.peek(), code="trace_variadic")
            ptok = self.peek()
            desc, spelling, _ = self.specifiers()
            if self.is_op(",") or self.is_op(")"):
                pname, d, at = "", desc, ptok  # a prototype's unnamed parameter
            else:
                pname, d, at = self.declarator(desc)
            if isinstance(d, Arr):
                d = Ptr(d.of, d.size)  # an array parameter is a pointer (C99 6.7.5.3p7)
            if d == "void":
                raise TraceError.at(at, code="trace_void_param")
            params.append((pname, d, spelling, at))
            if not self.is_op(","):
                break
            self.take()
        self.expect(")", "close_paren", at=f"{open_tok.line}:{open_tok.column}")
        self.qualifiers()
        if self.is_op(";"):
            self.take()
            return None
        if not self.is_op("{"):
            got = self.peek()
            raise TraceError.at(got, code="trace_after_params", name=name_tok.text, got=_got(got))
        if any(not p[0] for p in params):
            raise TraceError.at(name_tok, code="trace_param_name", name=name_tok.text)
        self.in_function = True
        body = self.block()
        self.in_function = False
        f = FuncDef(name_tok.text, ret, ret_spelling, params, body, first)
        f.close_line, f.close_column = self.last().line, self.last().column
        return f

    def typedef(self) -> Stmt:
        """``typedef TYPE NAME {, *NAME};``: NAME becomes another spelling of TYPE."""
        tok = self.take()
        nxt = self.peek()
        # As in rtwtypes.h: float, double and pointer typedefs are harmless until used.
        floating = nxt.kind == "name" and (nxt.text in _FLOATING or (
            nxt.text == "long" and self.peek(1).text == "double"))
        if floating:
            base = "long double" if self.take().text == "long" and self.take() else nxt.text
            spelling = base
        else:
            base, spelling, _ = self.specifiers()
        while True:
            pointer = False
            while self.is_op("*") or (self.peek().kind == "name" and
                                      self.peek().text in _QUALIFIERS):
                pointer = self.take().text == "*" or pointer  # a qualifier after the * too
            name = self.take()
            if name.kind != "name" or name.text in BASE_TYPE_WORDS or name.text in _QUALIFIERS:
                raise TraceError.at(name, code="trace_typedef_name", spelling=spelling,
                                    got=_got(name))
            if self.is_op("(") or self.is_op("["):
                raise TraceError.at(self.peek(), code="trace_typedef_function", name=name.text)
            if isinstance(base, StructDef) and base.name.startswith("<"):
                base.name = name.text  # typedef struct { … } NAME: messages call it NAME
            if pointer and isinstance(base, StructDef):
                self.aliases[name.text] = Ptr(base)
            else:
                self.aliases[name.text] = base
            self.type_names = self.type_names | {name.text}
            if floating or (pointer and not isinstance(base, StructDef)) or base == "void":
                self.floating[name.text] = (name, "a pointer type" if pointer or base == "void"
                                            else "a floating-point type")
            if not self.is_op(","):
                break
            self.take()
        self.expect(";", "declaration_end")
        return Block([]).at(tok, self.last())

    def var_name(self) -> Var:
        tok = self.peek()
        if tok.kind != "name" or tok.text in BASE_TYPE_WORDS or tok.text in _QUALIFIERS:
            raise TraceError.at(tok, code="trace_expected_name", got=_got(tok))
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
            raise TraceError.at(self.peek(), code="trace_comma")
        return e

    def assignment(self) -> Node:
        first = self.peek()
        self.deeper()
        left = self.conditional()
        tok = self.peek()
        if tok.kind == "op" and tok.text in _ASSIGN_OPS:
            if not _is_place(left):
                raise TraceError.at(tok, code="trace_lvalue_left", op=tok.text)
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
        self.expect(":", "conditional")
        other = self.conditional()
        self.shallower()
        if type(test) is FNum:  # a constant condition compares with 0 in its own type
            test = Num(int(test.value != 0), test.text).at(first, first)
            test.ctype = ["int"]
        if type(then) is FNum or type(other) is FNum:
            if not (type(test) is Num and _constant(then) and _constant(other)):
                bad = then if type(then) is FNum else other
                raise TraceError.at(bad, code="trace_float_constant", text=quoted(bad.text))
            single = all(type(x) is not FNum or x.single for x in (then, other))
            pick = then if test.value else other
            value = pick.value if type(pick) is FNum else float(pick.value)
            return FNum(_f32(value) if single else value, single,
                        self.source[first.start:self.last().end]).at(first, self.last())
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
                raise TraceError.at(tok, code="trace_height", limit=MAX_HEIGHT)
            self.deeper()
            right = self.binary(prec + 1)
            self.shallower()
            if (type(left) is FNum or type(right) is FNum) and _constant(left) and \
                    _constant(right):
                left = _fold(tok, left, right).at(first, tokens[self.pos - 1])
                continue
            node = Logical(tok.text, left, right) if tok.text in ("&&", "||") else \
                Binary(tok.text, left, right)
            left = node.at(first, tokens[self.pos - 1])

    def unary(self) -> Node:
        tok = self.tokens[self.pos]
        if tok.text in ("+", "-", "~", "!", "&", "*") and tok.kind == "op":
            self.take()
            self.deeper()
            operand = self.unary()
            self.shallower()
            if tok.text == "&" and not _is_place(operand):
                raise TraceError.at(tok, code="trace_needs_variable", op="&")
            if type(operand) is FNum and tok.text in "+-":
                value = -operand.value if tok.text == "-" else operand.value
                return FNum(value, operand.single, operand.text).at(tok, self.last())
            return Unary(tok.text, operand).at(tok, self.last())
        if tok.text in ("++", "--"):
            self.take()
            self.deeper()
            target = self.unary()
            self.shallower()
            if not _is_place(target):
                raise TraceError.at(tok, code="trace_needs_variable", op=tok.text)
            return IncDec(tok.text, True, target).at(tok, self.last())
        if tok.text == "(" and self.starts_type(1):
            self.take()
            type_name = self.type_spelling()
            self.expect(")", "close_cast")
            self.deeper()
            operand = self.unary()
            self.shallower()
            if type(operand) is FNum and isinstance(type_name, str):
                return float_to_int(type_name, operand, tok, self.last())
            return Cast(type_name, operand).at(tok, self.last())
        return self.postfix()

    def postfix(self) -> Node:
        first = self.peek()
        node = self.primary()
        tokens = self.tokens
        chain = 0
        while True:
            text = tokens[self.pos].text
            if text in ("++", "--"):
                op = self.take()
                if not _is_place(node):
                    raise TraceError.at(op, code="trace_needs_variable", op=op.text)
                node = IncDec(op.text, False, node).at(first, self.last())
            elif text in (".", "->"):
                op = self.take()
                name = self.take()
                if name.kind != "name":
                    raise TraceError.at(name, code="trace_field_name", op=op.text)
                self.deeper()
                chain += 1
                node = Member(node, name.text, op.text == "->").at(first, name)
            elif text == "[":
                self.take()
                self.deeper()
                chain += 1
                index = self.expression()
                self.expect("]", "close_index")
                node = Index(node, index).at(first, self.last())
            else:
                break
        # A chain of fields and indexes counts toward the depth bound while it is parsed.
        self.depth -= chain
        self.height -= chain
        return node

    def primary(self) -> Node:
        tok = self.peek()
        if tok.kind == "number":
            self.take()
            m = _FLOAT_LITERAL.fullmatch(tok.text)
            if m is not None:
                single = m[2] in ("f", "F") or self.single_double
                value = float(m[1])
                return FNum(_f32(value) if single else value, single, tok.text).at(tok, tok)
            value, cands = _int_constant(tok)
            n = Num(value, tok.text).at(tok, tok)
            n.ctype = cands  # resolved to one type by the checker (it knows the target)
            return n
        if tok.kind == "op" and tok.text == "(":
            self.take()
            self.deeper()
            e = self.expression()
            if self.is_op(")"):
                self.take()
            else:
                self.expect(")", "close_paren", at=f"{tok.line}:{tok.column}")
            self.shallower()
            # Keep the parentheses in the shown text.
            e.start, e.end = tok.start, self.last().end
            e.line, e.column = tok.line, tok.column
            return e
        if tok.kind == "name":
            if tok.text in _UNSUPPORTED or tok.text in BASE_TYPE_WORDS or tok.text in _TAGS:
                raise TraceError.at(tok, code="trace_not_here", word=tok.text)
            if self.is_op("(", 1):
                return self.call()
            self.take()
            if tok.text in self.enums:
                n = Num(self.enums[tok.text], tok.text).at(tok, tok)
                n.ctype = ["int"]
                return n
            return Var(tok.text).at(tok, tok)
        raise TraceError.at(tok, code="trace_expected_value", got=_got(tok))

    def call(self) -> Node:
        tok = self.take()
        name = tok.text
        q = None
        op, nargs = _IQ_INTRINSICS.get(name, (None, None))
        m = IQ_CALL.fullmatch(name) if op is None else None
        if m:
            op = m["op"] or m["plain"]
            nargs = ARITY[op]
            q = int(m["n"]) if m["n"] else None
            if op == "toF":  # a float result: outside the integer subset
                raise TraceError.at(tok, code="trace_iq_float", name=name)
        self.take()  # (
        self.deeper()
        args = []
        if not self.is_op(")"):
            while True:
                args.append(self.assignment())
                if not self.is_op(","):
                    break
                self.take()
        self.expect(")", "close_call", name=name)
        self.shallower()
        if op is None:  # a function of the pasted code: resolved by the checker
            return Call(name, args, None).at(tok, self.last())
        if len(args) != nargs:
            raise TraceError.at(tok, code="trace_builtin_arity", name=name, n=nargs, got=len(args))
        if name == "__IQmpy":
            qa = args[2]
            if not isinstance(qa, Num) or not 0 <= qa.value <= 62:
                raise TraceError.at(tok, code="trace_iqmpy_q")
            q = qa.value
            args = args[:2]
        return Call(name, args, q, op).at(tok, self.last())


def _f32(x: float) -> float:
    """``x`` rounded to binary32 (infinite beyond its range, as the hardware rounds)."""
    try:
        return struct.unpack("<f", struct.pack("<f", x))[0]
    except OverflowError:
        return x * float("inf")


def _constant(node: Node) -> bool:
    """A literal the parser can fold: a floating constant or an integer constant."""
    return type(node) is FNum or (type(node) is Num and isinstance(node.ctype, list))


def _fold(tok: Token, left: Node, right: Node) -> Node:
    """``left OP right`` with a floating operand, folded as C evaluates it with
    FLT_EVAL_METHOD 0 (arm-gcc, avr-gcc, TI's cl2000): the integer operand converted,
    ``float`` arithmetic when both are ``float`` (rounded to binary32 after the operation,
    which equals binary32 arithmetic for ``+ - * /``), else ``double``; a comparison or
    ``&&``/``||`` is an ``int`` 0 or 1."""
    op = tok.text
    single = all(type(x) is not FNum or x.single for x in (left, right))
    a, b = (float(x.value) for x in (left, right))
    if single:
        a, b = _f32(a), _f32(b)
    if op in ("<", ">", "<=", ">=", "==", "!=", "&&", "||"):
        value = {"<": a < b, ">": a > b, "<=": a <= b, ">=": a >= b, "==": a == b,
                 "!=": a != b, "&&": a != 0 and b != 0, "||": a != 0 or b != 0}[op]
        n = Num(int(value), op)
        n.ctype = ["int"]
        return n
    if op not in ("+", "-", "*", "/"):
        raise TraceError.at(tok, code="trace_float_operator", op=op)
    if op == "/" and b == 0:
        raise TraceError.at(tok, code="trace_division_zero")
    value = a + b if op == "+" else a - b if op == "-" else a * b if op == "*" else a / b
    text = left.text if type(left) is FNum else right.text
    return FNum(_f32(value) if single else value, single, text)


def float_to_int(type_name: str, operand: FNum, first, last) -> Cast:
    """``(T)constant`` — a cast, or the conversion of an initializer or an assignment — of a
    floating constant to the integer type spelled ``type_name``: the integer the compiler
    folds it to, truncated toward zero (C99 6.3.1.4), as a :class:`Cast` spanning ``first`` to
    ``last`` (tokens or nodes) whose ``folded`` is the constant; out of ``T``'s range is
    refused by the checker (undefined in C).  Negative: ``-N`` (its type is ``N``'s)."""
    v = operand.value
    if v != v or v in (float("inf"), float("-inf")):
        raise TraceError(first.line, first.column, code="trace_float_cast_range",
                         text=quoted(operand.text), value=repr(v), type=type_name)
    n = int(v != 0) if type_name == "_Bool" else int(v)  # int() truncates toward zero
    num = Num(abs(n), str(abs(n))).at(first, last)
    num.ctype = ["int", "long", "long long", "unsigned long long"]
    inner = Unary("-", num).at(first, last) if n < 0 else num
    return Cast(type_name, inner, v).at(first, last)


def constant_value(node: Node, what: str) -> int:
    """The value of an integer constant expression made of numbers and operators
    (array sizes, enumerators); mathematical integers, as the compiler folds them.  ``what``
    is the catalog code of the error when ``node`` is not one (``trace_const_array_size``…)."""
    if isinstance(node, Num):
        return node.value
    if isinstance(node, Unary) and node.op in ("-", "+", "~"):
        v = constant_value(node.operand, what)
        return -v if node.op == "-" else ~v if node.op == "~" else v
    if isinstance(node, Cast):
        return constant_value(node.operand, what)
    if isinstance(node, Binary) and node.op in _CONST_OPS:
        a, b = constant_value(node.left, what), constant_value(node.right, what)
        if node.op in ("/", "%") and b == 0:
            raise TraceError(node.right.line, node.right.column, code="trace_division_zero")
        if node.op in ("<<", ">>") and not 0 <= b < 64:
            raise TraceError(node.right.line, node.right.column, code="trace_shift_by", n=b)
        return _CONST_OPS[node.op](a, b)
    raise TraceError(node.line, node.column, code=what or "trace_const")


def _is_place(node: Node) -> bool:
    """Whether ``node`` designates an object (an lvalue the subset can assign)."""
    return isinstance(node, (Var, Member, Index)) or (isinstance(node, Unary) and
                                                      node.op == "*")


def parse(source: str, type_names: frozenset = ALL_TYPE_NAMES,
          defines: dict | None = None, global_q: int = 24, target=None) -> Program:
    """Parse C code; ``type_names`` are the type spellings the target knows, ``defines``
    the ``-D`` definitions (name → body text, see :mod:`pulab.ctrace.preprocess`),
    ``global_q`` IQmath's Q for ``_IQ(…)`` and its family when the code defines none,
    ``target`` (a :class:`~pulab.ctrace.types.Target`) what ``<limits.h>`` defines.

    Raises
    ------
    TraceError
        At the first thing outside the subset, naming line and column.
    """
    if not isinstance(source, str):
        raise TraceError(1, 1, code="trace_code_text")
    pre = preprocess(tokenize(source), defines, global_q,
                     target.limits() if target is not None else None,
                     target.double_bits if target is not None else 64)
    tokens, notes = _notes(pre.tokens)
    p = _Parser(source, tokens + tokens[-1:])
    p.type_names = type_names
    p.single_double = target is not None and target.double_bits == 32
    prog = Program(source, p.program(), notes, pre.global_q, p.functions, p.refused)
    prog.unresolved = pre.unresolved
    prog.macros, prog.aliases = pre.macros, p.aliases
    return prog
