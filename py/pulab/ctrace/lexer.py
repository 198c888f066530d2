"""Tokens of the C subset, each with its source position.

Comments are dropped except the ``// @q`` annotations (see
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

#: Longer pastes are refused (the page keeps the code in the URL).
MAX_SOURCE_CHARS = 100_000

_OPERATORS = sorted("""<<= >>= ... -> ++ -- << >> <= >= == != && || += -= *= /= %= &= ^= |=
    + - * / % & | ^ ~ ! < > = ? : ; , ( ) { } [ ] .""".split(), key=len, reverse=True)

_TOKEN = re.compile(r"""
    (?P<space>[ \t\r\f\v]+)
  | (?P<newline>\n)
  | (?P<annotation>//[ \t]*@q\b[^\n]*)
  | (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<unclosed>/\*)
  | (?P<number>(?:0[xX][0-9a-fA-F]+|0[bB][01]+|[0-9]+)(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?[A-Za-z_0-9]*)
  | (?P<name>[A-Za-z_][A-Za-z_0-9]*)
  | (?P<op>""" + "|".join(re.escape(o) for o in _OPERATORS) + r""")
""", re.S | re.X)


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
        raise TraceError(1, 1, f"code is longer than {MAX_SOURCE_CHARS} characters")
    tokens: list = []
    pos, line, line_start = 0, 1, 0
    at_line_start = True
    n = len(source)
    while pos < n:
        col = pos - line_start + 1
        if at_line_start and source[pos] == "#":
            # A preprocessor line, continued by backslash-newline.
            end = pos
            while True:
                nl = source.find("\n", end)
                if nl < 0:
                    nl = n
                if nl > 0 and source[nl - 1] == "\\" and nl < n:
                    end = nl + 1
                    continue
                break
            text = source[pos:nl]
            tokens.append(Token("directive", text, line, col, pos, nl))
            line += text.count("\n")
            if "\n" in text:
                line_start = pos + text.rfind("\n") + 1
            pos = nl
            continue
        m = _TOKEN.match(source, pos)
        if m is None:
            ch = source[pos]
            raise TraceError(line, col, f"unexpected character {ch!r}")
        kind = m.lastgroup
        text = m.group()
        if kind == "unclosed":
            raise TraceError(line, col, "comment not closed: */ missing")
        if kind in ("newline", "comment", "space"):
            nls = text.count("\n")
            if nls:
                line += nls
                line_start = pos + text.rfind("\n") + 1
                at_line_start = True
        else:
            tokens.append(Token(kind, text, line, col, pos, m.end()))
            at_line_start = kind == "annotation"
        pos = m.end()
    tokens.append(Token("end", "", line, pos - line_start + 1, n, n))
    return tokens
