"""Random C snippets and input vectors for the compiler cross-check (never imports pulab).

A :class:`Case` is C code in the subset pulab's tracer reads: declarations of
the inputs (no initializer), then a body of statements over random expression
trees of every supported operator and type.  The same text goes to the tracer
and, wrapped by ``ctrace_compilers``, to a real compiler.  Seeded: the same
seed gives the same cases and vectors.
"""

from __future__ import annotations

import random
from dataclasses import dataclass, field

__all__ = ["Case", "generate_case", "random_vector", "TYPES", "TYPE_BITS"]

# spelling → (bits on avr/c28x, bits on arm, signed on avr, signed on arm)
TYPES = {
    "Uint16": (16, 16, False, False), "int16": (16, 16, True, True),
    "Int16": (16, 16, True, True), "Uint32": (32, 32, False, False),
    "int32": (32, 32, True, True), "Ulong": (32, 32, False, False), "Long": (32, 32, True, True),
    "Uint": (16, 32, False, False), "Int": (16, 32, True, True),
    "int16_t": (16, 16, True, True), "uint16_t": (16, 16, False, False),
    "int32_t": (32, 32, True, True), "uint32_t": (32, 32, False, False),
    "int64_t": (64, 64, True, True), "uint64_t": (64, 64, False, False),
    "int64": (64, 64, True, True), "Uint64": (64, 64, False, False),
    "unsigned": (16, 32, False, False), "short": (16, 16, True, True),
    "unsigned short": (16, 16, False, False), "int": (16, 32, True, True),
    "long": (32, 32, True, True), "unsigned long": (32, 32, False, False),
    "long long": (64, 64, True, True), "unsigned long long": (64, 64, False, False),
    "unsigned int": (16, 32, False, False),
    "int8_t": (8, 8, True, True), "uint8_t": (8, 8, False, False),
    "char": (8, 8, True, False), "signed char": (8, 8, True, True),
    "unsigned char": (8, 8, False, False), "_iq": (32, 32, True, True),
}


def TYPE_BITS(spelling: str, target: str) -> tuple:
    """(bits, signed) of a spelling on 'avr' or 'arm'."""
    b16, b32, s16, s32 = TYPES[spelling]
    return (b16, s16) if target == "avr" else (b32, s32)


_BINARY = ["+", "-", "*", "/", "%", "<<", ">>", "&", "|", "^", "<", ">", "<=", ">=", "==",
           "!=", "&&", "||"]
_COMPOUND = ["+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="]
_SUFFIXES = ["", "", "", "U", "L", "UL", "LL", "ULL", "u", "l", "lu"]
_INTERESTING = [0, 1, 2, 3, 5, 7, 10, 12, 15, 16, 24, 100, 255, 1000, 4096, 18597, 32767,
                32768, 65535, 65536, 2147483647, 2147483648, 4294967295]


@dataclass
class Case:
    """Declarations without initializer ``decls`` [(spelling, name)], statements ``body``,
    every variable in ``outputs``; ``inputs`` names the declared variables the vectors set
    (None: all of them)."""

    decls: list
    body: str
    outputs: list = field(default_factory=list)
    inputs: list | None = None

    def input_decls(self) -> list:
        return [d for d in self.decls if self.inputs is None or d[1] in self.inputs]

    def code(self) -> str:
        """The text the tracer reads: one declaration per input, then the body."""
        return "".join(f"{t} {n};\n" for t, n in self.decls) + self.body


def _literal(rng: random.Random) -> str:
    v = rng.choice(_INTERESTING) if rng.random() < 0.7 else rng.randrange(0, 1 << 31)
    suffix = rng.choice(_SUFFIXES)
    form = rng.random()
    if form < 0.25:
        text = hex(v)
    elif form < 0.3 and v:
        text = "0" + oct(v)[2:]
    else:
        text = str(v)
    return text + suffix


class _Gen:
    def __init__(self, rng: random.Random, names: list) -> None:
        self.rng = rng
        self.names = names

    def leaf(self) -> str:
        if self.rng.random() < 0.6 and self.names:
            return self.rng.choice(self.names)
        return _literal(self.rng)

    def expr(self, depth: int) -> str:
        rng = self.rng
        if depth <= 0 or rng.random() < 0.2:
            return self.leaf()
        k = rng.random()
        if k < 0.55:
            op = rng.choice(_BINARY)
            left = self.expr(depth - 1)
            if op in ("<<", ">>"):
                r = rng.random()
                right = str(rng.randrange(0, 16)) if r < 0.7 else \
                    f"({self.expr(depth - 1)} & 15)" if r < 0.9 else self.expr(depth - 1)
            elif op in ("/", "%") and rng.random() < 0.4:
                right = f"({self.expr(depth - 1)} | 1)"
            else:
                right = self.expr(depth - 1)
            return f"({left} {op} {right})"
        if k < 0.65:
            return f"{rng.choice(['-', '~', '!', '+'])}{self.paren(depth - 1)}"
        if k < 0.8:
            return f"({rng.choice(list(TYPES))}){self.paren(depth - 1)}"
        if k < 0.87:
            return f"({self.expr(depth - 1)} ? {self.expr(depth - 1)} : {self.expr(depth - 1)})"
        r = rng.random()
        a, b = self.expr(depth - 1), self.expr(depth - 1)
        if r < 0.3:
            return f"_IQmpy({a}, {b})"
        if r < 0.5:
            return f"_IQ{rng.randrange(1, 31)}mpy({a}, {b})"
        if r < 0.7:
            return f"__IQmpy({a}, {b}, {rng.randrange(0, 31)})"
        hi = self.expr(depth - 1)
        return f"{rng.choice(['_IQsat', '__IQsat'])}({a}, {hi}, {b})"

    def paren(self, depth: int) -> str:
        e = self.expr(depth)
        return e if e.startswith("(") and e.endswith(")") else f"({e})"


def generate_case(rng: random.Random, index: int) -> Case:
    """One random snippet: 1–4 inputs, 2–5 statements over expression trees of depth ≤ 3."""
    types = list(TYPES)
    decls = [(rng.choice(types), f"in{index}_{k}") for k in range(rng.randrange(1, 5))]
    names = [n for _, n in decls]
    outputs = list(decls)
    g = _Gen(rng, names)
    lines = []
    temps = 0
    for _ in range(rng.randrange(2, 6)):
        r = rng.random()
        if r < 0.45 or not names:
            t, n = rng.choice(types), f"t{index}_{temps}"
            temps += 1
            lines.append(f"{t} {n} = {g.expr(3)};")
            names.append(n)
            outputs.append((t, n))
        elif r < 0.75:
            op = rng.choice(_COMPOUND)
            rhs = str(rng.randrange(0, 16)) if op in ("<<=", ">>=") and rng.random() < 0.8 \
                else g.expr(2)
            lines.append(f"{rng.choice(names)} {op} {rhs};")
        elif r < 0.87:
            lines.append(f"{rng.choice(names)} = {g.expr(3)};")
        elif r < 0.93:
            v = rng.choice(names)
            lines.append(rng.choice([f"{v}++;", f"++{v};", f"{v}--;", f"--{v};"]))
        else:
            lines.append(f"if ({g.expr(2)}) {rng.choice(names)} = {g.expr(2)}; "
                         f"else {rng.choice(names)} = {g.expr(2)};")
    return Case(decls, "\n".join(lines) + "\n", outputs)


def random_vector(rng: random.Random, case: Case, target: str) -> dict:
    """Input values biased to the edges of each input's type on ``target``."""
    out = {}
    for spelling, name in case.input_decls():
        bits, signed = TYPE_BITS(spelling, target)
        lo, hi = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if signed else (0, (1 << bits) - 1)
        r = rng.random()
        if r < 0.3:
            v = rng.choice([0, 1, lo, hi, lo + 1, hi - 1, -1 if signed else 2])
        elif r < 0.55:
            v = rng.randrange(-300, 300) if signed else rng.randrange(0, 300)
        elif r < 0.7:
            p = rng.randrange(0, bits - (1 if signed else 0))
            v = (1 << p) + rng.choice([-1, 0, 1])
        else:
            v = rng.randrange(lo, hi + 1)
        out[name] = min(max(v, lo), hi)
    return out
