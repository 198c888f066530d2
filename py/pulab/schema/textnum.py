"""Numbers as text: typed ones (full-width digits, IME decimal points, hex and binary
integers) read, and physical values written with an SI prefix (:func:`si_text`, from
:mod:`.sitext`).

A Chinese input method types ``１７`` (full-width digits), ``０．５`` or ``０。５``
(full-width full stop, ideographic full stop) and ``－`` (full-width minus).  NFKC
folds the full-width forms to ASCII; the ideographic full stop and the Unicode minus
are mapped by hand.  A decimal comma (``1,5``) is accepted; ``1,500`` could be a
thousands separator and is refused as ambiguous (the page's parser does the same).

Examples
--------
>>> parse_real("０．５", "x"), parse_real("１７", "x"), parse_real("2。5", "x"), parse_real("1,5", "x")
(0.5, 17.0, 2.5, 1.5)
>>> parse_int("0x8000", "raw"), parse_int("０ｘＦＦ", "raw"), parse_int("-12", "raw"), parse_int("0b101", "raw")
(32768, 255, -12, 5)
>>> parse_real("1,500", "x")
Traceback (most recent call last):
...
pulab.schema.errors.InputError: x: must be a number, got '1,500' (ambiguous: a decimal comma or a thousands separator?)
>>> si_text(1.06e-05, "H"), si_text(0.0011, "Ω"), si_text(6.25e-05, "s")
('10.6 µH', '1.1 mΩ', '62.5 µs')
"""

from __future__ import annotations

import re
import unicodedata

from .errors import InputError
from .sitext import si_text
from .validate import real, shown

__all__ = ["ascii_text", "parse_real", "parse_int", "si_text"]

_MAP = str.maketrans({"。": ".", "−": "-", "｡": "."})


def ascii_text(text: str) -> str:
    """Full-width and IME forms folded to ASCII, all white space removed."""
    return re.sub(r"\s+", "", unicodedata.normalize("NFKC", text).translate(_MAP))


def parse_real(v, path: str) -> float:
    """A finite float from a JSON number or a typed string (see the module docstring)."""
    if isinstance(v, bool) or isinstance(v, (int, float)):
        return real(v, path)
    if isinstance(v, str):
        s = ascii_text(v)
        if len(s) > 400:
            raise InputError(path, code="not_number", got=shown(v))
        if re.fullmatch(r"[+-]?\d+,\d{3}", s):
            raise InputError(path, code="number_ambiguous", got=shown(v))
        if re.fullmatch(r"[+-]?\d+,\d+", s):
            s = s.replace(",", ".")
        if not re.fullmatch(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?", s):
            raise InputError(path, code="not_number", got=shown(v))
        return real(float(s), path)
    raise InputError(path, code="not_number", got=shown(v))


def parse_int(v, path: str) -> int:
    """An integer from a JSON integer or a typed string: decimal, ``0x…`` hex, ``0b…`` binary."""
    if isinstance(v, bool):
        raise InputError(path, code="not_integer", got=shown(v))
    if isinstance(v, int):
        return v
    if isinstance(v, float) and v.is_integer():
        return int(v)
    if isinstance(v, str):
        s = ascii_text(v).lower()
        # No register is wider than 64 bits: a longer text is no reading (and int() of thousands
        # of digits would raise).
        m = len(s) <= 80 and re.fullmatch(r"([+-]?)(0x[0-9a-f]+|0b[01]+|\d+)", s)
        if m:
            return int(m[1] + m[2], 0)
    raise InputError(path, code="not_register", got=shown(v))
