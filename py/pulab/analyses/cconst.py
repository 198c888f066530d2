"""A ``#define``'s value as the target's compiler folds it: C constant expressions over the
tokens the tracer's preprocessor (:mod:`pulab.ctrace.preprocess`) expands a macro to.

The tracer evaluates integer statements; a vendor header is mostly floating constants
(``(0.35)``, ``((float32_t)(15.0f))``, ``(uint16_t)((65536.0 * RSHUNT * G)/VREF)``), so this
module is the small adapter the header decoder needs, reading the tracer's tokens and types
(:data:`pulab.ctrace.TARGETS`) without changing them:

- integer constants typed as C99 6.4.4.1 says (``int``, then ``long`` … for decimal; the
  unsigned types too for hex/octal; suffixes ``u``, ``l``, ``ll``), the usual arithmetic
  conversions of the target (16-bit ``int`` on C28x and dsPIC), ``/`` and ``%`` toward zero,
  signed overflow shown as the wrap and flagged;
- floating constants: ``f`` makes an IEEE single (every operation on two singles is rounded
  to single, as the compiler does), else a double (the target's ``double_bits``);
- casts to any type name the tracer knows (``int16_t``, ``Uint16``, ``float32_t``, ``_iq``…);
  a float converted to an integer truncates toward zero, and a value outside the type is
  flagged (C leaves it undefined; the wrap of its truncation is shown);
- unary ``+ - ~ !``, binary arithmetic, shifts, comparisons, bitwise and logical operators,
  ``?:`` and ``,``.

A name left after expansion is an unknown macro: the value is None and the names are listed,
never guessed.

Examples
--------
>>> from pulab.ctrace.lexer import tokenize
>>> def value(text, target="arm"):
...     return evaluate(tokenize(text)[:-1], target).value
>>> value("(uint16_t)((65536.0 * 0.003 * 9.14)/3.3)"), value("40000 * 2", "c28x")
(544, 80000)
>>> value("(int16_t)40000"), value("0.1f + 0.2f") == 0.30000001192092896
(-25536, True)
>>> r = evaluate(tokenize("RS / LS")[:-1], "arm")
>>> r.value, r.unknown
(None, ['RS', 'LS'])
"""

from __future__ import annotations

import math
import re
import struct

from ..ctrace.types import TARGETS, common_type, promote
from ..fixedpoint.cint import CType, convert, trunc_div

__all__ = ["Value", "evaluate", "NotConstant", "FLOAT_TYPES", "MAX_NESTING"]

#: Parentheses nested deeper are refused (bounds the recursion of any paste).
MAX_NESTING = 48

#: Floating type names and their width in bits (``double`` and ``long double`` follow the
#: target's ``double_bits``; TI's and NXP's typedefs are singles).
FLOAT_TYPES = {"float": 32, "float32_t": 32, "float_t": 32, "float32": 32, "float64_t": 64,
               "float64": 64, "double": None, "long double": None}
_INT = re.compile(r"(0[xX][0-9a-fA-F]+|0[bB][01]+|[0-9]+)([uUlL]*)\Z")
_FLT = re.compile(r"([0-9]*\.?[0-9]*(?:[eE][-+]?[0-9]+)?)([fFlL]?)\Z")
_PREC = {"||": 1, "&&": 2, "|": 3, "^": 4, "&": 5, "==": 6, "!=": 6, "<": 7, ">": 7,
         "<=": 7, ">=": 7, "<<": 8, ">>": 8, "+": 9, "-": 9, "*": 10, "/": 10, "%": 10}
_TYPE_WORDS = frozenset({"signed", "unsigned", "char", "short", "int", "long", "const",
                         "volatile"})


class NotConstant(Exception):
    """The tokens are no constant expression (``reason`` says why)."""

    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


class Value:
    """A folded constant: ``value`` (int or float; None when names are unknown), its C
    ``type`` spelling, ``unknown`` (names left after expansion) and ``flags`` (``overflow``:
    a signed result wrapped; ``conversion``: a cast or conversion changed the value)."""

    __slots__ = ("value", "type", "unknown", "flags")

    def __init__(self, value, ctype: str, unknown: list, flags: list) -> None:
        self.value, self.type, self.unknown, self.flags = value, ctype, unknown, flags


def _f32(x: float) -> float:
    if math.isinf(x) or math.isnan(x) or abs(x) > 3.4028234663852886e38:
        return x if not math.isfinite(x) else math.copysign(math.inf, x)
    return struct.unpack("<f", struct.pack("<f", x))[0]


class _Unknown(Exception):
    pass


class _Fold:
    """Recursive descent over one expansion; a value is (number, type) where type is a
    :class:`CType` or an int (the float's width in bits)."""

    def __init__(self, toks: list, target) -> None:
        self.toks, self.i, self.t = toks, 0, target
        self.dbl = target.double_bits
        self.unknown: list = []
        self.flags: list = []
        self.depth = 0

    # -- helpers -----------------------------------------------------------------------
    def peek(self, k: int = 0) -> str:
        j = self.i + k
        return self.toks[j].text if j < len(self.toks) else ""

    def take(self, text: str) -> None:
        if self.peek() != text:
            raise NotConstant(f"expected {text!r}, got {self.peek() or 'the end'!r}")
        self.i += 1

    def flag(self, what: str) -> None:
        if what not in self.flags:
            self.flags.append(what)

    def int_type(self, name: str) -> CType:
        return self.t.type_named(name)

    def to_int(self, v, t, ct: CType) -> int:
        if isinstance(t, int):  # float → integer: toward zero; outside the type undefined
            if not math.isfinite(v):
                raise NotConstant("a non-finite float converted to an integer")
            n = int(v)
            if not ct.min <= n <= ct.max and ct.name != "_Bool":
                self.flag("conversion")
            return convert(n, ct)
        out = convert(v, ct)
        if out != v and ct.name != "_Bool":
            self.flag("conversion")
        return out

    def to_float(self, v, t, bits: int) -> float:
        x = float(v)
        return _f32(x) if bits == 32 else x

    def arith(self, a, b) -> tuple:
        """The usual arithmetic conversions: (a, b, result type)."""
        (va, ta), (vb, tb) = a, b
        if isinstance(ta, int) or isinstance(tb, int):
            bits = max(x for x in (ta, tb) if isinstance(x, int))
            return self.to_float(va, ta, bits), self.to_float(vb, tb, bits), bits
        ct = common_type(self.t, ta, tb)
        return convert(va, ct), convert(vb, ct), ct

    def result(self, v, t) -> tuple:
        if isinstance(t, int):
            return (_f32(v) if t == 32 else v), t
        out = convert(v, t)
        if out != v:
            self.flag("overflow" if t.signed else "unsigned_wrap")
        return out, t

    # -- grammar -----------------------------------------------------------------------
    def run(self) -> tuple:
        if not self.toks:
            raise NotConstant("the macro is empty")
        v = self.comma()
        if self.i != len(self.toks):
            raise NotConstant(f"unexpected {self.peek()!r}")
        return v

    def comma(self):
        v = self.cond()
        while self.peek() == ",":
            self.i += 1
            v = self.cond()
        return v

    def cond(self):
        c = self.binary(1)
        if self.peek() != "?":
            return c
        self.i += 1
        a = self.comma()
        self.take(":")
        b = self.cond()
        if a is None or b is None or c is None:
            return None
        if isinstance(a[1], int) or isinstance(b[1], int) or a[1] != b[1]:
            va, vb, t = self.arith(a, b)
            a, b = (va, t), (vb, t)
        return a if c[0] else b

    def binary(self, level: int):
        if level > 10:
            return self.unary()
        left = self.binary(level + 1)
        while _PREC.get(self.peek()) == level:
            op = self.peek()
            self.i += 1
            right = self.binary(level + 1)
            left = None if left is None or right is None else self.apply(op, left, right)
        return left

    def apply(self, op: str, a, b):
        if op in ("&&", "||"):
            x, y = a[0] != 0, b[0] != 0
            return int(x and y if op == "&&" else x or y), self.int_type("int")
        if op in ("<<", ">>"):
            if isinstance(a[1], int) or isinstance(b[1], int):
                raise NotConstant(f"{op} of a floating value")
            t = promote(self.t, a[1])
            n = b[0]
            if not 0 <= n < t.bits:
                raise NotConstant(f"shift count {n} out of range")
            v = convert(a[0], t)
            return self.result(v << n if op == "<<" else v >> n, t)
        va, vb, t = self.arith(a, b)
        if op in ("==", "!=", "<", ">", "<=", ">="):
            r = {"==": va == vb, "!=": va != vb, "<": va < vb, ">": va > vb,
                 "<=": va <= vb, ">=": va >= vb}[op]
            return int(r), self.int_type("int")
        if op in ("&", "|", "^", "%") and isinstance(t, int):
            raise NotConstant(f"{op} of a floating value")
        if op in ("/", "%") and vb == 0:
            raise NotConstant("division by zero")
        if isinstance(t, int):
            r = va + vb if op == "+" else va - vb if op == "-" else va * vb if op == "*" \
                else va / vb
            return self.result(r, t)
        r = {"+": lambda: va + vb, "-": lambda: va - vb, "*": lambda: va * vb,
             "/": lambda: trunc_div(va, vb), "%": lambda: va - vb * trunc_div(va, vb),
             "&": lambda: va & vb, "|": lambda: va | vb, "^": lambda: va ^ vb}[op]()
        return self.result(r, t)

    def cast_type(self):
        """The type named inside the parentheses at the cursor, or None (not a cast)."""
        j, words = self.i + 1, []
        while j < len(self.toks) and self.toks[j].kind == "name":
            words.append(self.toks[j].text)
            j += 1
        if not words or j >= len(self.toks) or self.toks[j].text != ")":
            return None
        words = [w for w in words if w not in ("const", "volatile")]
        spelling = " ".join(words)
        if spelling in FLOAT_TYPES:
            bits = FLOAT_TYPES[spelling] or self.dbl
            self.i = j + 1
            return bits
        if len(words) > 1 and not set(words) <= _TYPE_WORDS:
            return None
        if set(words) <= _TYPE_WORDS:
            base = [w for w in words if w not in ("signed", "int")] or ["int"]
            if base == ["unsigned"]:
                base = ["unsigned", "int"]
            spelling = " ".join(base).replace("unsigned int", "unsigned int")
            if "unsigned" in words and "unsigned" not in base:
                spelling = "unsigned " + spelling
        try:
            ct = self.int_type(spelling)
        except KeyError:
            return None
        self.i = j + 1
        return ct

    def unary(self):
        tok = self.toks[self.i] if self.i < len(self.toks) else None
        if tok is None:
            raise NotConstant("the expression ends early")
        text = tok.text
        if text in ("+", "-", "~", "!"):
            self.i += 1
            v = self.unary()
            if v is None:
                return None
            x, t = v
            if text == "!":
                return int(x == 0), self.int_type("int")
            if isinstance(t, int):
                if text == "~":
                    raise NotConstant("~ of a floating value")
                return (-x if text == "-" else x), t
            t = promote(self.t, t)
            x = convert(x, t)
            return self.result(-x if text == "-" else (~x if text == "~" else x), t)
        if text == "(":
            self.depth += 1
            if self.depth > MAX_NESTING:
                raise NotConstant(f"nested deeper than {MAX_NESTING} parentheses")
            try:
                return self.paren()
            finally:
                self.depth -= 1
        self.i += 1
        if tok.kind == "number":
            return self.number(text)
        if tok.kind == "name":
            return self.name(text)
        raise NotConstant(f"{text!r} in a constant expression")

    def paren(self):
        ct = self.cast_type()
        if ct is not None:
            v = self.unary()
            if v is None:
                return None
            if isinstance(ct, int):
                return self.to_float(v[0], v[1], ct), ct
            return self.to_int(v[0], v[1], ct), ct
        self.i += 1
        v = self.comma()
        self.take(")")
        return v

    def name(self, text: str):
        if text == "sizeof":
            raise NotConstant("sizeof is not folded")
        if text not in self.unknown:
            self.unknown.append(text)
        if self.peek() == "(":  # an unknown function-like macro: skip its arguments
            depth = 0
            while self.i < len(self.toks):
                depth += {"(": 1, ")": -1}.get(self.peek(), 0)
                self.i += 1
                if depth == 0:
                    break
        return None

    def number(self, text: str):
        m = _INT.match(text)
        if m:
            digits, suffix = m[1], m[2].lower()
            base = 16 if digits[:2].lower() == "0x" else 2 if digits[:2].lower() == "0b" else \
                8 if len(digits) > 1 and digits[0] == "0" else 10
            body = digits[2:] if base in (16, 2) else digits
            if base == 8 and set(body) & set("89"):
                raise NotConstant(f"{text} is not an octal number")
            n = int(body, base)
            unsigned = "u" in suffix
            longs = suffix.count("l")
            ladder = ["int", "long", "long long"][min(longs, 2):]
            for name in ladder:
                for u in ((True,) if unsigned else (False, True) if base != 10 else (False,)):
                    ct = self.int_type(("unsigned " if u else "") + name)
                    if ct.min <= n <= ct.max:
                        return n, ct
            raise NotConstant(f"{text} fits no integer type")
        m = _FLT.match(text)
        if m and m[1] not in ("", "."):
            bits = 32 if m[2] in ("f", "F") else self.dbl
            return self.to_float(float(m[1]), bits, bits), bits
        raise NotConstant(f"{text!r} is not a number")


def evaluate(tokens: list, target: str = "arm") -> Value:
    """Fold the expanded tokens of one macro on ``target`` (a key of
    :data:`pulab.ctrace.TARGETS`).

    Raises
    ------
    NotConstant
        The tokens are no constant expression (syntax, division by zero, ``sizeof``).
    """
    f = _Fold(tokens, TARGETS[target])
    try:
        v = f.run()
    except RecursionError:  # a long chain of unary operators or ?: (parentheses are counted)
        raise NotConstant("nested too deep") from None
    if v is None:
        return Value(None, None, f.unknown, f.flags)
    x, t = v
    if isinstance(t, int):
        name = "float" if t == 32 else "double"
        return Value(x, name, [], f.flags)
    return Value(x, t.name, [], f.flags)
