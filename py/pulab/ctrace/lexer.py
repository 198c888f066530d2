"""Tokens of the C subset, each with its source position.

Line splices (backslash-newline) are blanks, also ending a ``//`` comment, which
then goes on over the next line, as in a compiler; a leading byte-order mark is a
blank.  Comments are dropped except the ``// @q`` annotations (see
:mod:`pulab.ctrace.parser`), which come back as ``annotation`` tokens;
preprocessor lines come back whole as ``directive`` tokens.

Examples
--------
>>> [(t.kind, t.text) for t in tokenize("x += 0x1FUL; // note")]
[('name', 'x'), ('op', '+='), ('number', '0x1FUL'), ('op', ';'), ('end', '')]
"""

from __future__ import annotations

import re
from typing import NamedTuple

from .errors import TraceError

__all__ = ["Token", "tokenize", "MAX_SOURCE_CHARS"]

#: Longer pastes are refused (a whole generated controller, header and source, fits).
MAX_SOURCE_CHARS = 300_000

_OPERATORS = sorted("""<<= >>= ... -> ++ -- << >> <= >= == != && || += -= *= /= %= &= ^= |=
    + - * / % & | ^ ~ ! < > = ? : ; , ( ) { } [ ] .""".split(), key=len, reverse=True)

# Most frequent first; blanks after a token are consumed with it (half the loop's iterations).
_TOKEN = re.compile(r"""(?:
    (?P<name>[A-Za-z_][A-Za-z_0-9]*)
  | (?P<space>(?:[ \t\r\f\v]|\\\r?\n)+)
  | (?P<number>(?:0[xX][0-9a-fA-F]+|0[bB][01]+|[0-9]+)(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?[A-Za-z_0-9]*)
  | (?P<directive>\#(?:\\\r?\n|/\*.*?\*/|//(?:\\\r?\n|[^\n])*|[^\n/]|/(?![*/]))*)
  | (?P<string>"(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*')
  | (?P<annotation>//[ \t]*@q\b[^\n]*)
  | (?P<comment>//(?:\\\r?\n|[^\n])*|/\*.*?\*/)
  | (?P<unclosed>/\*)
  | (?P<op>""" + "|".join(re.escape(o) for o in _OPERATORS) + r""")
  | (?P<newline>\n)
  | (?P<bad>.)
)[ \t\r\f\v]*""", re.S | re.X)
_SKIP = frozenset({"space", "newline", "comment"})
_new = tuple.__new__


class Token(NamedTuple):
    """One token: ``kind`` in name, number, op, directive, annotation, end."""

    kind: str
    text: str
    line: int
    column: int
    start: int
    end: int


def tokenize(source: str) -> list:
    """Split ``source`` into tokens; raises :class:`TraceError` at the first bad character."""
    if len(source) > MAX_SOURCE_CHARS:
        raise TraceError(1, 1, code="trace_code_length", limit=MAX_SOURCE_CHARS)
    if source[:1] == "\ufeff":
        source = " " + source[1:]  # a UTF-8 byte-order mark, kept as one column
    tokens: list = []
    line, line_start = 1, 0
    append = tokens.append
    for m in _TOKEN.finditer(source):
        kind = m.lastgroup
        pos = m.start()
        if kind == "space" or kind == "comment":
            # A line splice (backslash-newline) is blank; one ending a // comment continues it.
            text = m.group(kind)
            if "\n" in text:
                line += text.count("\n")
                line_start = pos + text.rfind("\n") + 1
            continue
        if kind == "newline":
            line += 1
            line_start = pos + 1
            continue
        text = m.group(kind)
        if kind not in _SKIP:
            if kind == "bad":
                raise TraceError(line, pos - line_start + 1, code="trace_character",
                                 char=repr(text))
            if kind == "unclosed":
                raise TraceError(line, pos - line_start + 1, code="trace_comment_open")
            if kind == "directive" and source[line_start:pos].strip():
                raise TraceError(line, pos - line_start + 1, code="trace_character",
                                 char="'#'")
            # tuple.__new__ skips NamedTuple's Python-level __new__ (a third of the lexer's time).
            append(_new(Token, (kind, text, line, pos - line_start + 1, pos, pos + len(text))))
        if kind != "number" and kind != "name" and kind != "op":
            nls = text.count("\n")
            if nls:
                line += nls
                line_start = pos + text.rfind("\n") + 1
    n = len(source)
    tokens.append(Token("end", "", line, n - line_start + 1, n, n))
    return tokens


#: Significant digits that still fit 64 bits, per base.
_MAX_DIGITS = {2: 64, 8: 22, 10: 20, 16: 16}


def integer_digits(digits: str) -> tuple:
    """(digits without a prefix, base) of an integer constant's digits (``0x1F``, ``017``, ``9``)."""
    if digits[:2] in ("0x", "0X", "0b", "0B"):
        return digits[2:], 16 if digits[1] in "xX" else 2
    return digits, 8 if len(digits) > 1 and digits[0] == "0" else 10


def beyond_64_bits(body: str, base: int) -> bool:
    """More significant digits than any 64-bit value has: too large for every C type, and
    never converted (Python refuses decimal strings past 4300 digits)."""
    return len(body.lstrip("0")) > _MAX_DIGITS[base]


def quoted(text: str) -> str:
    """A token as a message shows it: whole up to 40 characters, else its ends and length."""
    return text if len(text) <= 40 else f"{text[:16]}…{text[-8:]} ({len(text)} characters)"
