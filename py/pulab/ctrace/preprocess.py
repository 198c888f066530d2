"""The C preprocessor as compilers run it, on :mod:`pulab.ctrace.lexer` tokens.

- ``#define`` object-like and function-like macros (parameters, ``...``/``__VA_ARGS__``,
  ``#`` stringizing, ``##`` pasting), ``#undef``; expansion follows C99 6.10.3 (a macro
  is not re-expanded inside its own expansion; arguments are expanded before they are
  substituted, except next to ``#``/``##``);
- ``#if``/``#ifdef``/``#ifndef``/``#elif``/``#else``/``#endif`` with ``defined NAME``,
  ``defined(NAME)`` and integer constant expressions (C99 6.10.1: names left after
  expansion are 0; evaluated in 64-bit ``intmax_t``), so include guards work;
- ``#include <stdint.h>`` defines the exact-width limits (``INT16_MAX``, ``INT32_MIN``,
  ``UINT16_MAX`` …), ``<stdbool.h>`` ``true``/``false``; other headers are listed in
  :attr:`Preprocessed.unresolved` (their contents are not known unless pasted);
- IQmath's conversion macros as TI's IQmathLib.h defines them (unless the code defines
  them): ``_IQ(A)``/``_IQN(A)`` of a floating constant folded to the integer the compiler
  makes, ``_IQtoIQN``, ``_IQNtoIQ``, ``_IQtoQN``, ``_QNtoIQ``, ``_IQmpy2``…``_IQmpy64``,
  ``_IQdiv2``…``_IQdiv64``;
- ``#pragma``, ``#line``, the null directive are skipped; ``#error`` is an error;
- user definitions (``-D NAME[=VALUE]``) come first, as on a compiler's command line.

Every token an expansion produces carries the position of the macro use (from its name
to its closing parenthesis), so errors and the trace point at the line written.

Limits (one-line :class:`TraceError` when exceeded): :data:`MAX_EXPANDED_TOKENS` tokens
after expansion, :data:`MAX_MACRO_DEPTH` macros nested in one expansion,
:data:`MAX_IF_DEPTH` nested conditionals.

Examples
--------
>>> pre = preprocess(tokenize("#define SQ(x) ((x)*(x))\\n#if SQ(3) == 9\\ny = SQ(a+1);\\n#endif"))
>>> " ".join(t.text for t in pre.tokens[:-1])
'y = ( ( a + 1 ) * ( a + 1 ) ) ;'
"""

from __future__ import annotations

import re
import struct
from collections import deque

from .errors import TraceError
from .lexer import Token, beyond_64_bits, integer_digits, quoted, tokenize

__all__ = ["preprocess", "Preprocessed", "parse_define", "MAX_EXPANDED_TOKENS",
           "MAX_MACRO_DEPTH", "MAX_IF_DEPTH", "STANDARD_HEADERS"]

#: More tokens after macro expansion are refused (bounds time and memory of any paste).
MAX_EXPANDED_TOKENS = 200_000
#: Macros nested deeper inside one expansion are refused.
MAX_MACRO_DEPTH = 64
#: Conditionals (#if … #endif) nested deeper are refused.
MAX_IF_DEPTH = 64

_NAME = re.compile(r"[A-Za-z_]\w*\Z")
#: IQmath's conversion family as TI's IQmathLib.h defines it (fixed-point build):
#: _IQ(A)/_IQN(A) = (long)((A) * 2.0**N), _IQtoIQN/_IQtoQN(A) = (long)(A) >> (GLOBAL_Q - N)
#: (<< when N > GLOBAL_Q), _IQNtoIQ/_QNtoIQ the reverse, _IQmpyK(A) = (A) << log2 K,
#: _IQdivK(A) = (A) >> log2 K.
_IQ_BUILTIN = re.compile(r"_IQ(?P<n>[1-9]|[12][0-9]|30)?\Z|_I?Q(?P<from>[1-9]|[12][0-9]|30)toIQ\Z"
                         r"|_IQtoI?Q(?P<to>[1-9]|[12][0-9]|30)\Z|_IQ(?P<op>mpy|div)"
                         r"(?P<k>2|4|8|16|32|64)\Z")
_FLOAT = re.compile(r"([0-9]+\.?[0-9]*(?:[eE][-+]?[0-9]+)?)([fFlL]?)\Z")
_DIRECTIVE = re.compile(r"#\s*(\w*)(.*)", re.S)
#: A comment (group 1), or a string or character literal a comment cannot start inside.
_COMMENT_OR_QUOTE = re.compile(r'(/\*.*?\*/|//[^\n]*)|"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'',
                               re.S)


def _limits() -> dict:
    d = {}
    for bits in (8, 16, 32, 64):
        suffix = "LL" if bits == 64 else ""
        d[f"INT{bits}_MAX"] = f"{(1 << bits - 1) - 1}{suffix}"
        # Written as C headers do: -MAX - 1 keeps the constant's type signed.
        d[f"INT{bits}_MIN"] = f"(-{(1 << bits - 1) - 1}{suffix} - 1)"
        d[f"UINT{bits}_MAX"] = f"{(1 << bits) - 1}U{'LL' if bits == 64 else ''}"
    return d


#: What the standard headers this subset knows define (their type names are built in).
STANDARD_HEADERS = {
    "stdint.h": _limits(),
    "stdbool.h": {"bool": "_Bool", "true": "1", "false": "0",
                  "__bool_true_false_are_defined": "1"},
    "stddef.h": {},
    "limits.h": {},  # per target: see preprocess(limits=…)
    # headers known to include <stdint.h> (avr-libc's <avr/io.h> through <inttypes.h>)
    "inttypes.h": _limits(),
    "avr/io.h": _limits(),
}


class Preprocessed:
    """Tokens after preprocessing, ``global_q`` from ``#define GLOBAL_Q``, the
    ``unresolved`` include names (in order) and the ``macros`` defined at the end."""

    __slots__ = ("tokens", "global_q", "unresolved", "macros")

    def __init__(self, tokens: list, global_q, unresolved: list, macros: dict) -> None:
        self.tokens, self.global_q, self.unresolved, self.macros = tokens, global_q, \
            unresolved, macros


class _Macro:
    __slots__ = ("name", "params", "variadic", "body")

    def __init__(self, name: str, params, variadic: bool, body: list) -> None:
        self.name, self.params, self.variadic, self.body = name, params, variadic, body


_new = tuple.__new__  # builds a Token without NamedTuple's slow keyword path
_NO_HIDE: frozenset = frozenset()  # the macros a source token may expand: all
_TEXT_TOKENS: dict = {}


def _tokens(text: str) -> list:
    """Tokens of a fixed text the expansion inserts (cached: the same few texts recur)."""
    toks = _TEXT_TOKENS.get(text)
    if toks is None:
        toks = _TEXT_TOKENS[text] = tokenize(text)[:-1] if len(_TEXT_TOKENS) < 512 else None
        if toks is None:
            return tokenize(text)[:-1]
    return toks


def _body_tokens(text: str, at: Token, what: str) -> list:
    """Tokens of directive text, positioned on the directive's line."""
    toks: list = []
    # A comment is one blank (C99 5.1.1.2 phase 3), whatever '#' it holds.
    text = _COMMENT_OR_QUOTE.sub(lambda m: " " if m[1] else m[0], text)
    # '#' and '##' are operators inside a directive (the lexer reads '#' as a new directive).
    for piece in re.split(r"(##|#)", text):
        if piece in ("#", "##"):
            toks.append(Token("op", piece, at.line, at.column, at.start, at.end))
            continue
        try:
            toks.extend(_tokens(piece))  # cached: a header's definitions recur on every run
        except TraceError as e:
            raise TraceError.at(at, "trace_in_directive", what=what,
                                reason=e.reason_error()) from None
    if any(t.kind in ("directive", "annotation") for t in toks):
        raise TraceError.at(at, "trace_directive_text", what=what)
    return [t._replace(line=at.line, column=at.column, start=at.start, end=at.end) for t in toks]


def _define(rest: str, at: Token) -> _Macro:
    m = re.match(r"\s*([A-Za-z_]\w*)(\()?", rest)
    if m is None:
        raise TraceError.at(at, "trace_define_name")
    name = m[1]
    if not m[2]:
        return _Macro(name, None, False, _body_tokens(rest[m.end():], at, f"#define {name}"))
    close = rest.find(")", m.end())
    if close < 0:
        raise TraceError.at(at, "trace_define_paren", name=name)
    params = [p.strip() for p in rest[m.end():close].split(",")]
    if params == [""]:
        params = []
    variadic = bool(params) and params[-1] == "..."
    if variadic:
        params[-1] = "__VA_ARGS__"
    for p in params[:len(params) - variadic]:
        if not _NAME.match(p):
            raise TraceError.at(at, "trace_define_param", name=name, param=repr(p))
    if len(set(params)) != len(params):
        raise TraceError.at(at, "trace_define_param_twice", name=name)
    body = _body_tokens(rest[close + 1:], at, f"#define {name}")
    if body and (body[0].text == "##" or body[-1].text == "##"):
        raise TraceError.at(at, "trace_define_paste_edge", name=name)
    return _Macro(name, params, variadic, body)


def parse_define(text: str) -> tuple:
    """``"NAME=VALUE"`` or ``"NAME"`` (a ``-D`` option) → (name, body text); value 1 when absent.

    >>> parse_define("GLOBAL_Q=20"), parse_define("USE_SAT")
    (('GLOBAL_Q', '20'), ('USE_SAT', '1'))
    """
    name, eq, value = text.partition("=")
    name = name.strip()
    head = re.match(r"[A-Za-z_]\w*(\([^)]*\))?\Z", name)
    if head is None:
        raise TraceError(1, 1, field="define", code="trace_define_option", text=repr(text))
    return name, (value if eq else "1")


class _Pre:
    def __init__(self, tokens: list, defines: dict, global_q: int, headers: dict) -> None:
        self.src = iter(tokens)
        self.headers = headers
        self.default_q = global_q
        self.single = False  # the target's double is binary32 (set by preprocess)
        self.macros: dict = {}
        self.global_q = None
        self.unresolved: list = []
        self.defined: set = set()  # every macro name defined, without its edge underscores
        self.conds: list = []  # per open #if: [taking now, some branch taken, #else seen, token]
        self.produced = 0
        self.end = None
        cmdline = Token("directive", "", 1, 1, 0, 0)
        for name, value in defines.items():
            self.define(_define(f"{name} {value}", cmdline), cmdline)

    # -- directives ---------------------------------------------------------------------
    def define(self, mac: _Macro, at: Token) -> None:
        self.macros[mac.name] = mac
        self.defined.add(mac.name.strip("_"))
        if mac.name == "GLOBAL_Q":
            b = mac.body
            if mac.params is not None or len(b) != 1 or not b[0].text.isdigit() or \
                    len(b[0].text) > 2 or not 1 <= int(b[0].text) <= 30:
                raise TraceError.at(at, "trace_global_q")
            self.global_q = int(b[0].text)

    def active(self) -> bool:
        return not self.conds or self.conds[-1][0]

    def directive(self, tok: Token) -> None:
        m = _DIRECTIVE.match(re.sub(r"\\\r?\n", " ", tok.text))
        word, rest = m[1], m[2]
        live = self.active()
        if word in ("if", "ifdef", "ifndef"):
            if len(self.conds) >= MAX_IF_DEPTH:
                raise TraceError.at(tok, "trace_if_depth", limit=MAX_IF_DEPTH)
            take = live and self.condition(word, rest, tok)
            self.conds.append([take, take, False, tok, live])
            return
        if word in ("elif", "else", "endif"):
            if not self.conds:
                raise TraceError.at(tok, "trace_without_if", word=word)
            c = self.conds[-1]
            if word == "endif":
                self.conds.pop()
            elif c[2]:
                raise TraceError.at(tok, "trace_after_else", word=word)
            elif word == "else":
                c[0], c[2] = c[4] and not c[1], True
                c[1] = c[1] or c[0]
            else:
                c[0] = c[4] and not c[1] and self.condition("if", rest, tok)
                c[1] = c[1] or c[0]
            return
        if not live:
            return
        if word == "define":
            self.define(_define(rest, tok), tok)
        elif word == "undef":
            self.macros.pop(rest.split("//")[0].strip(), None)
        elif word == "include":
            self.include(rest, tok)
        elif word == "error":
            raise TraceError.at(tok, "trace_error_directive", rest=rest.rstrip())
        elif word not in ("pragma", "line", "warning", "") or (word == "" and rest.strip()):
            raise TraceError.at(tok, "trace_unknown_directive", word=word or rest.strip()[:20])

    def include(self, rest: str, tok: Token) -> None:
        m = re.match(r'\s*(?:<([^>\n]+)>|"([^"\n]+)")', rest)
        if m is None:
            raise TraceError.at(tok, "trace_include_syntax")
        header = (m[1] or m[2]).strip()
        if header == "IQmathLib.h":  # its conversions are built in; it defines GLOBAL_Q
            if "GLOBAL_Q" not in self.macros:
                self.define(_define(f"GLOBAL_Q {self.default_q}", tok), tok)
            return
        known = self.headers.get(header)
        if known is None:
            if header not in self.unresolved:
                self.unresolved.append(header)
            return
        for name, body in known.items():
            if name not in self.macros:
                self.macros[name] = _Macro(name, None, False, _body_tokens(body, tok, header))

    def condition(self, word: str, rest: str, tok: Token) -> bool:
        toks = _body_tokens(rest, tok, f"#{word}")
        if word != "if":
            if len(toks) != 1 or toks[0].kind != "name":
                raise TraceError.at(tok, "trace_directive_name", word=word)
            return (toks[0].text in self.macros) == (word == "ifdef")
        # defined X / defined(X) are replaced before expansion (C99 6.10.1p1).
        resolved, i = [], 0
        while i < len(toks):
            t = toks[i]
            if t.kind == "name" and t.text == "defined":
                j = i + 1
                paren = j < len(toks) and toks[j].text == "("
                j += paren
                if j >= len(toks) or toks[j].kind != "name" or \
                        (paren and (j + 1 >= len(toks) or toks[j + 1].text != ")")):
                    raise TraceError.at(tok, "trace_defined_name")
                resolved.append(t._replace(kind="number",
                                           text="1" if toks[j].text in self.macros else "0"))
                i = j + 1 + paren
                continue
            resolved.append(t)
            i += 1
        expanded = self.expand_list(resolved)
        if not expanded:
            raise TraceError.at(tok, "trace_if_expression", word=word)
        return _IfExpr(expanded, tok).value() != 0

    # -- expansion ----------------------------------------------------------------------
    def source_tokens(self):
        """The tokens of the active branches, directives run on the way."""
        for tok in self.src:
            if tok.kind == "directive":
                self.directive(tok)
            elif tok.kind == "end":
                if self.conds:
                    raise TraceError.at(self.conds[-1][3], "trace_if_open")
                self.end = tok
                return
            elif self.active():
                yield tok

    def expand_list(self, toks: list) -> list:
        return self.run(deque((t, _NO_HIDE) for t in toks), None)

    def run(self, pending: deque, more) -> list:
        """Expand ``pending`` (then the tokens of iterator ``more``) to the end."""
        out: list = []
        macros = self.macros

        def pull():
            if pending:
                return pending.popleft()
            if more is not None:
                t = next(more, None)
                if t is not None:
                    return t, _NO_HIDE
            return None

        append = out.append
        while True:
            if pending:
                tok, hide = pending.popleft()
            else:
                tok = next(more, None) if more is not None else None
                if tok is None:
                    return out
                hide = _NO_HIDE
            if tok.kind != "name":  # most tokens: nothing to expand
                append(tok)
                continue
            mac = macros.get(tok.text)
            if mac is None and tok.text[:2] in ("_I", "_Q") and _IQ_BUILTIN.match(tok.text):
                nxt = pull()
                if nxt is not None and nxt[0].text == "(" and nxt[0].kind == "op":
                    args, last = self.arguments(_Macro(tok.text, ["A"], False, []), tok, pull)
                    where = (tok.line, tok.column, tok.start, last.end)
                    body = [(_new(Token, (t.kind, t.text) + where), hide)
                            for t in self.iq(tok, args[0])]
                    pending.extendleft(reversed(body))
                    continue
                if nxt is not None:
                    pending.appendleft(nxt)
            if mac is None or tok.text in hide:
                append(tok)
                continue
            if len(hide) >= MAX_MACRO_DEPTH:
                raise TraceError.at(tok, "trace_macro_depth", name=tok.text, limit=MAX_MACRO_DEPTH)
            hs = hide | {mac.name}
            if mac.params is None:
                where = (tok.line, tok.column, tok.start, tok.end)
                body = [(_new(Token, (t.kind, t.text) + where), hs)
                        for t in self.paste(mac.body, tok)]
            else:
                nxt = pull()
                if nxt is None or nxt[0].text != "(" or nxt[0].kind != "op":
                    out.append(tok)  # a function-like macro's name alone is not a use
                    if nxt is not None:
                        pending.appendleft(nxt)
                    continue
                args, last = self.arguments(mac, tok, pull)
                where = (tok.line, tok.column, tok.start, last.end)
                body = [(_new(Token, (t.kind, t.text) + where), hs)
                        for t in self.substitute(mac, args, tok)]
            self.produced += len(body)
            if self.produced > MAX_EXPANDED_TOKENS:
                raise TraceError.at(tok, "trace_macro_tokens", name=tok.text,
                                    limit=MAX_EXPANDED_TOKENS)
            pending.extendleft(reversed(body))

    def iq(self, use: Token, arg: list) -> list:
        """The tokens an IQmath conversion macro stands for (see _IQ_BUILTIN)."""
        m = _IQ_BUILTIN.match(use.text)
        gq = self.default_q
        g = self.macros.get("GLOBAL_Q")
        if g is not None and g.params is None and len(g.body) == 1 and \
                g.body[0].text.isdigit() and len(g.body[0].text) <= 2:
            gq = int(g.body[0].text)
        if m["op"]:
            shift = {"2": 1, "4": 2, "8": 3, "16": 4, "32": 5, "64": 6}[m["k"]]
            return self.text_around("((", arg, f") {'<<' if m['op'] == 'mpy' else '>>'} {shift})")
        if m["from"] or m["to"]:
            # IQN -> IQ: << (GLOBAL_Q - N); IQ -> IQN: >> (GLOBAL_Q - N); negative counts flip.
            k = gq - int(m["from"] or m["to"])
            left = (k >= 0) == bool(m["from"])
            return self.text_around("((long)(", arg, f") {'<<' if left else '>>'} {abs(k)})")
        n = int(m["n"]) if m["n"] else gq
        return self.text_around("((long)(", [], f"{self.fold(use, arg, n)}))")

    def fold(self, use: Token, arg: list, n: int) -> int:
        """(long)(A * 2**n) for a floating constant A, as the compiler folds it: A is
        rounded to its type (binary64, or binary32 with an f suffix), then truncated."""
        arg = self.expand_list(arg)
        sign, i = 1, 0
        while i < len(arg) and arg[i].kind == "op" and arg[i].text in "+-":
            sign = -sign if arg[i].text == "-" else sign
            i += 1
        core = [t for t in arg[i:] if t.text not in ("(", ")")]
        m = _FLOAT.match(core[0].text) if len(core) == 1 and core[0].kind == "number" else None
        if m is not None:
            value = float(m[1])
            if m[2] in ("f", "F") or self.single:
                value = _f32(value)
        else:  # a constant expression such as 4.0/3.0, folded as C does in double
            value = _ConstFloat(arg[i:], use, self.single).value()
        product = sign * value * 2.0 ** n  # * 2**n is exact in binary floating point
        if product != product or product in (float("inf"), float("-inf")):  # no int() of them
            raise TraceError.at(use, "trace_iq_range", name=use.text, value=repr(product))
        scaled = int(product)
        if not -(1 << 31) <= scaled < (1 << 31):
            raise TraceError.at(use, "trace_iq_range", name=use.text, value=scaled)
        return scaled

    def text_around(self, head: str, arg: list, tail: str) -> list:
        return _tokens(head) + list(arg) + _tokens(tail)

    def arguments(self, mac: _Macro, use: Token, pull) -> tuple:
        args: list = [[]]
        depth = 0
        while True:
            item = pull()
            if item is None:
                raise TraceError.at(use, "trace_macro_paren", name=mac.name)
            t = item[0]
            if t.kind == "op" and t.text == ")" and depth == 0:
                break
            if t.kind == "op" and t.text in ("(", ")"):
                depth += 1 if t.text == "(" else -1
            if t.kind == "op" and t.text == "," and depth == 0 and \
                    not (mac.variadic and len(args) == len(mac.params)):
                args.append([])
                continue
            args[-1].append(t)
        if args == [[]] and not mac.params:
            args = []
        if mac.variadic and len(args) == len(mac.params) - 1:
            args.append([])
        if len(args) != len(mac.params):
            raise TraceError.at(use, "trace_macro_args", name=mac.name, n=len(mac.params),
                                got=len(args))
        return args, t

    def substitute(self, mac: _Macro, args: list, use: Token) -> list:
        index = {p: i for i, p in enumerate(mac.params)}
        body = mac.body
        out: list = []
        expanded: dict = {}
        for i, t in enumerate(body):
            k = index.get(t.text) if t.kind == "name" else None
            if t.text == "#" and t.kind == "op" and i + 1 < len(body) and \
                    body[i + 1].text in index:
                continue
            if k is None:
                out.append(t)
                continue
            if i > 0 and body[i - 1].text == "#":
                text = " ".join(a.text for a in args[k]).replace("\\", "\\\\").replace('"', '\\"')
                out.append(t._replace(kind="string", text=f'"{text}"'))
                continue
            if (i > 0 and body[i - 1].text == "##") or \
                    (i + 1 < len(body) and body[i + 1].text == "##"):
                out.extend(args[k] or [t._replace(kind="placemarker", text="")])
                continue
            if k not in expanded:
                expanded[k] = self.expand_list(args[k])
            out.extend(expanded[k])
        return self.paste(out, use)

    def paste(self, toks: list, use: Token) -> list:
        if not any(t.text == "##" and t.kind == "op" for t in toks):
            return [t for t in toks if t.kind != "placemarker"]
        out: list = []
        i = 0
        while i < len(toks):
            t = toks[i]
            if t.kind == "op" and t.text == "##" and out and i + 1 < len(toks):
                left, right = out.pop(), toks[i + 1]
                text = left.text + right.text
                if text == "":
                    out.append(left)
                else:
                    try:
                        new = tokenize(text)[:-1]
                    except TraceError:
                        new = []
                    if len(new) != 1:
                        raise TraceError.at(use, "trace_paste", left=repr(left.text),
                                            right=repr(right.text))
                    out.append(new[0]._replace(line=left.line, column=left.column,
                                               start=left.start, end=left.end))
                i += 2
                continue
            out.append(t)
            i += 1
        return [t for t in out if t.kind != "placemarker"]


def _f32(x: float) -> float:
    """``x`` rounded to binary32 (a 32-bit ``double``, as avr-gcc's)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


class _ConstFloat:
    """``+ - * /`` and parentheses over number literals: an integer operation as C's
    (division toward zero), one with a ``double`` operand in binary64 (binary32 when
    ``single``: the target's double is 32 bits); ``f`` literals refused here (their
    arithmetic precision depends on FLT_EVAL_METHOD)."""

    def __init__(self, toks: list, use: Token, single: bool = False) -> None:
        self.toks, self.pos, self.use = toks, 0, use
        self.round = _f32 if single else float

    def fail(self):
        raise TraceError.at(self.use, "trace_iq_constant", name=self.use.text)

    def value(self) -> float:
        if not self.toks:
            self.fail()
        v = self.sum()
        if self.pos != len(self.toks):
            self.fail()
        return float(v)

    def peek(self) -> str:
        return self.toks[self.pos].text if self.pos < len(self.toks) else ""

    def sum(self):
        v = self.product()
        while self.peek() in ("+", "-"):
            op = self.toks[self.pos].text
            self.pos += 1
            v, w = self.usual(v, self.product())
            v = v + w if op == "+" else v - w
            v = v if isinstance(v, int) else self.round(v)
        return v

    def usual(self, v, w):
        """C's usual arithmetic conversions: an integer beside a double becomes a double
        (rounded to the target's double)."""
        if isinstance(v, int) != isinstance(w, int):
            v, w = (self.round(float(x)) if isinstance(x, int) else x for x in (v, w))
        return v, w

    def product(self):
        v = self.unary()
        while self.peek() in ("*", "/"):
            op = self.toks[self.pos].text
            self.pos += 1
            v, w = self.usual(v, self.unary())
            if op == "*":
                v = v * w
            elif w == 0:
                self.fail()
            elif isinstance(v, int) and isinstance(w, int):
                v = abs(v) // abs(w) * (1 if (v < 0) == (w < 0) else -1)
            else:
                v = self.round(v / w)
            if op == "*" and not isinstance(v, int):
                v = self.round(v)
        return v

    def unary(self):
        t = self.peek()
        if t in ("+", "-"):
            self.pos += 1
            v = self.unary()
            return -v if t == "-" else v
        if t == "(":
            self.pos += 1
            v = self.sum()
            if self.peek() != ")":
                self.fail()
            self.pos += 1
            return v
        tok = self.toks[self.pos] if self.pos < len(self.toks) else None
        if tok is None or tok.kind != "number":
            self.fail()
        self.pos += 1
        m = _FLOAT.match(tok.text)
        if m is not None and m[2] not in ("f", "F") and not re.fullmatch(r"\d+[uUlL]*", tok.text):
            return self.round(float(m[1]))
        if re.fullmatch(r"\d+[uUlL]*", tok.text):
            return int(re.match(r"\d+", tok.text)[0])
        self.fail()


class _IfExpr:
    """An ``#if`` expression over integer tokens, in 64-bit ``intmax_t``."""

    _BIN = {op: lv for lv, ops in enumerate(
        [("||",), ("&&",), ("|",), ("^",), ("&",), ("==", "!="), ("<", ">", "<=", ">="),
         ("<<", ">>"), ("+", "-"), ("*", "/", "%")]) for op in ops}

    def __init__(self, toks: list, at: Token) -> None:
        self.toks, self.i, self.at = toks, 0, at

    def fail(self, code: str, **params):
        return TraceError.at(self.at, "trace_if", reason={"code": code, "params": params})

    def peek(self):
        return self.toks[self.i] if self.i < len(self.toks) else None

    def value(self) -> int:
        v = self.cond()
        if self.peek() is not None:
            raise self.fail("trace_if_unexpected", text=repr(self.peek().text))
        return v

    def cond(self) -> int:
        test = self.binary(0)
        t = self.peek()
        if t is not None and t.text == "?":
            self.i += 1
            a = self.cond()
            t = self.peek()
            if t is None or t.text != ":":
                raise self.fail("trace_if_missing", char=":")
            self.i += 1
            b = self.cond()
            return a if test else b
        return test

    def binary(self, level: int) -> int:
        left = self.unary()
        while True:
            t = self.peek()
            lv = self._BIN.get(t.text) if t is not None and t.kind == "op" else None
            if lv is None or lv < level:
                return left
            self.i += 1
            if t.text == "&&":
                right = self.binary(lv + 1)
                left = int(bool(left) and bool(right))
                continue
            if t.text == "||":
                right = self.binary(lv + 1)
                left = int(bool(left) or bool(right))
                continue
            right = self.binary(lv + 1)
            left = self.apply(t.text, left, right)

    def apply(self, op: str, a: int, b: int) -> int:
        if op in ("/", "%"):
            if b == 0:
                raise self.fail("trace_division_zero")
            q = abs(a) // abs(b) * (1 if (a < 0) == (b < 0) else -1)
            r = a - q * b
            return _wrap(q if op == "/" else r)
        if op in ("<<", ">>"):
            if not 0 <= b < 64:
                raise self.fail("trace_shift_by", n=b)
            return _wrap(a << b if op == "<<" else a >> b)
        return _wrap({"+": a + b, "-": a - b, "*": a * b, "&": a & b, "|": a | b, "^": a ^ b,
                      "==": int(a == b), "!=": int(a != b), "<": int(a < b), ">": int(a > b),
                      "<=": int(a <= b), ">=": int(a >= b)}[op])

    def unary(self) -> int:
        t = self.peek()
        if t is None:
            raise self.fail("trace_if_ends")
        self.i += 1
        if t.kind == "op" and t.text in ("-", "+", "~", "!"):
            v = self.unary()
            return _wrap({"-": -v, "+": v, "~": ~v, "!": int(not v)}[t.text])
        if t.kind == "op" and t.text == "(":
            v = self.cond()
            t = self.peek()
            if t is None or t.text != ")":
                raise self.fail("trace_if_missing", char=")")
            self.i += 1
            return v
        if t.kind == "name":
            return 0  # names left after expansion are 0 (C99 6.10.1p4)
        if t.kind == "number":
            m = re.fullmatch(r"(0[xX][0-9a-fA-F]+|0[bB][01]+|[0-9]+)[uUlL]*", t.text)
            if m is None:
                raise self.fail("trace_if_not_constant", text=t.text)
            body, base = integer_digits(m[1])
            if beyond_64_bits(body, base):
                raise self.fail("trace_constant_large", text=quoted(t.text),
                                types="intmax_t, uintmax_t")
            return _wrap(int(body, base))
        raise self.fail("trace_if_unexpected", text=repr(t.text))


def _wrap(v: int) -> int:
    return ((v + (1 << 63)) & ((1 << 64) - 1)) - (1 << 63)


def preprocess(tokens: list, defines: dict | None = None, global_q: int = 24,
               limits: dict | None = None, double_bits: int = 64) -> Preprocessed:
    """Run the directives of ``tokens`` and expand macros.

    Parameters
    ----------
    tokens : list of Token
        From :func:`~pulab.ctrace.lexer.tokenize` (ending with the ``end`` token).
    defines : dict, optional
        ``-D`` definitions, name (``NAME`` or ``NAME(params)``) → body text.
    global_q : int, optional
        IQmath's GLOBAL_Q for the conversion macros when the code does not define it.
    limits : dict, optional
        What ``<limits.h>`` defines on the target (:meth:`pulab.ctrace.types.Target.limits`);
        without it the header defines nothing.
    double_bits : {64, 32}, optional
        The width of the target compiler's ``double`` (32 on avr-gcc): ``_IQ(…)`` folds its
        constant in that precision, as the compiler does.

    Returns
    -------
    Preprocessed
        ``tokens`` (annotations kept in place, ending with ``end``), ``global_q``,
        ``unresolved`` headers, ``macros``.
    """
    headers = dict(STANDARD_HEADERS, **({"limits.h": limits} if limits else {}))
    pre = _Pre(tokens, defines or {}, global_q, headers)
    pre.single = double_bits == 32
    out = pre.run(deque(), pre.source_tokens())
    out.append(pre.end)
    # A header whose include guard (mc_math.h: MC_MATH_H, __MC_MATH_H__) the paste defines is
    # pasted: not missing.
    missing = [h for h in pre.unresolved
               if re.sub(r"\W", "_", h.rpartition("/")[2]).upper() not in pre.defined]
    return Preprocessed(out, pre.global_q, missing, pre.macros)
