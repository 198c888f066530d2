"""Input text to JSON value, with the limits of the contract (docs/contract.md, "Hardening").

JSON itself has no depth limit, but every parser does: nested too deep,
``json.loads`` raises ``RecursionError`` in CPython and can exhaust the
WebAssembly stack in Pyodide.  The deepest valid request is 4 levels
(``{"input": {"sim": {"current": {...}}}}``), so the text is scanned for
depth first and refused beyond :data:`MAX_DEPTH` with an
:class:`pulab.schema.errors.InputError` naming ``input``.

Examples
--------
>>> parse('{"motor": {"rs_ohm": 1.5}}')
{'motor': {'rs_ohm': 1.5}}
>>> parse("[" * 100 + "]" * 100)
Traceback (most recent call last):
...
pulab.schema.errors.InputError: input: nested deeper than 32 levels
>>> parse('{"a": 1,}')
Traceback (most recent call last):
...
pulab.schema.errors.InputError: input: not valid JSON: Expecting property name enclosed in double quotes: line 1 column 9 (char 8)
"""

from __future__ import annotations

import json
import re

from .errors import InputError

__all__ = ["parse", "MAX_DEPTH"]

#: Deepest nesting of arrays and objects accepted in an input text.
MAX_DEPTH = 32

# A string token (possessive, and an unterminated one runs to the end, so the scan
# stays linear on any text) or a bracket.
_TOKEN = re.compile(r'"(?:[^"\\]|\\.)*+(?:"|\\?\Z)|[\[\]{}]', re.S)


def parse(text: str, field: str = "input"):
    """The JSON value of ``text``; bad or too deeply nested text names ``field``.

    Parameters
    ----------
    text : str
        JSON text (strict: no trailing commas; NaN/Infinity are parsed and
        then refused by the field checks as not finite).
    field : str
        JSON path named in the error.

    Raises
    ------
    pulab.InputError
        ``field: not valid JSON: …`` (one line) or ``field: nested deeper than 32 levels``.
    """
    if not isinstance(text, str):
        raise InputError(field, code="json_not_text")
    depth = 0
    for m in _TOKEN.finditer(text):
        c = m[0][0]
        if c == '"':
            continue
        depth += 1 if c in "[{" else -1
        if depth > MAX_DEPTH:
            raise InputError(field, code="json_too_deep", depth=MAX_DEPTH)
    try:
        return json.loads(text)
    except ValueError as e:  # JSONDecodeError, or an integer literal over 4300 digits
        raise InputError(field, code="json_invalid", detail=" ".join(str(e).split())) from None
