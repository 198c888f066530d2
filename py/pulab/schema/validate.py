"""The one validator: every input section is checked here, against :mod:`.fields`.

Rules for every field of every section and subcommand: JSON ``null`` equals an
absent field; booleans are not numbers; a number must be finite (an integer
literal beyond the float range too); an unknown key is an error naming its JSON
path; every error is an :class:`~pulab.schema.errors.InputError` with a code.

Examples
--------
>>> read("pll", {"damping": 0.5})
{'bandwidth_hz': 50.0, 'damping': 0.5}
>>> read("drive", {"udc_v": 24, "ts_s": 10 ** 400})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: drive.ts_s: must be finite
>>> read("conventions", {"base_voltage_v": 10})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: conventions.base_voltage_v: is only used with base = custom
"""

from __future__ import annotations

import math
import sys

from .errors import InputError
from .fields import REQUIRED, SECTIONS, Field, section_fields

__all__ = ["read", "value", "real", "integer", "object_fields", "shown", "key_path",
           "children"]

#: The largest integer a float holds (anything above rounds to inf or raises).
_FLOAT_MAX_INT = int(sys.float_info.max)
#: Longest text of a user's value or key quoted in a message (messages stay one short line).
_SHOWN_CHARS = 40


def shown(v) -> str:
    r"""A user's value as quoted in a message: short, one line, never raising.

    ``repr`` escapes newlines, NUL, U+2028 and other unprintable characters; a
    container is named, not printed (its ``repr`` could be huge or recurse), and
    an integer too long to print is given by its size.

    Examples
    --------
    >>> shown("a\u2028b"), shown([1, [2]]), shown({"k": 1}), shown(10 ** 400)
    ("'a\\u2028b'", 'a list', 'an object', 'an integer of 1329 bits')
    """
    if isinstance(v, dict):
        return "an object"
    if isinstance(v, list):
        return "a list"
    if isinstance(v, int) and not isinstance(v, bool) and v.bit_length() > 64:
        return f"an integer of {v.bit_length()} bits"
    text = repr(v)
    return text if len(text) <= _SHOWN_CHARS else text[:_SHOWN_CHARS - 1] + "…"


def key_path(path: str, key) -> str:
    r"""The JSON path of ``key`` inside ``path``, printable on one line.

    A plain key is joined with a dot; an empty key, one with a dot or any
    unprintable character (newline, NUL, U+2028…) is quoted and escaped.

    Examples
    --------
    >>> key_path("motor", "rs_ohm"), key_path("motor", "a\nb"), key_path("", "")
    ('motor.rs_ohm', "motor['a\\nb']", "['']")
    """
    plain = isinstance(key, str) and key.isprintable() and key.strip() and "." not in key and \
        "[" not in key and len(key) <= _SHOWN_CHARS
    if plain:
        return f"{path}.{key}" if path else key
    return f"{path}[{shown(key)}]"


def object_fields(v, path: str, allowed) -> dict:
    """A JSON object with only ``allowed`` keys, nulls dropped (absent = null)."""
    if v is None:
        return {}
    if not isinstance(v, dict):
        raise InputError(path, code="not_object", got=shown(v))
    for key in v:
        if key not in allowed:
            raise InputError(key_path(path, key), code="unknown_field",
                             expected=", ".join(allowed))
    return {k: x for k, x in v.items() if x is not None}


def real(v, path: str) -> float:
    """A JSON number as a finite float; booleans are not numbers."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(path, code="not_number", got=shown(v))
    # A JSON integer literal can exceed the float range (309 digits); it is no finite number.
    if isinstance(v, int) and abs(v) > _FLOAT_MAX_INT:
        raise InputError(path, code="not_finite")
    v = float(v)
    if not math.isfinite(v):
        raise InputError(path, code="not_finite")
    return v


def integer(v, path: str, lo: int, hi: int) -> int:
    """A JSON integer (an integral float included) in ``lo..hi``."""
    if isinstance(v, bool) or not isinstance(v, (int, float)) or \
            (isinstance(v, float) and not v.is_integer()):
        raise InputError(path, code="not_integer", got=shown(v))
    v = int(v)
    if not lo <= v <= hi:
        raise InputError(path, code="integer_range", lo=lo, hi=hi, got=shown(v))
    return v


def value(f: Field, v, path: str | None = None):
    """Field ``f``'s given (non-null) JSON value ``v``, checked; ``path`` overrides ``f.path``."""
    path = path or f.path
    if f.kind == "name_or_number" and isinstance(v, str):
        if v not in f.choices:
            raise InputError(path, code="not_name_or_number", choices=", ".join(f.choices),
                             got=shown(v))
        return v
    if f.kind == "pair":
        if not isinstance(v, list) or len(v) != 2:
            raise InputError(path, code="not_pair", got=shown(v))
        low, high = (_number(f, x, f"{path}[{k}]") for k, x in enumerate(v))
        if low > high:
            raise InputError(path, code="pair_order", lo=low, hi=high)
        return [low, high]
    if f.kind == "table":
        return _table(f, v, path)
    if f.kind == "choice":
        if isinstance(v, (dict, list)) or v not in f.choices:
            raise InputError(path, code="not_choice", choices=", ".join(f.choices), got=shown(v))
        return v
    if f.kind == "flag":
        if not isinstance(v, bool):
            raise InputError(path, code="not_flag", got=shown(v))
        return v
    if f.kind == "integer":
        return integer(v, path, int(f.lo), int(f.hi))
    if f.kind == "text":
        if not isinstance(v, str):
            raise InputError(path, code="not_string", got=shown(v))
        if len(v) > f.hi:
            raise InputError(path, code="json_too_long", limit=int(f.hi))
        return v
    if f.kind == "object":
        if not isinstance(v, dict):
            raise InputError(path, code="not_object", got=shown(v))
        return v
    return _number(f, v, path)


def _number(f: Field, v, path: str) -> float:
    """``v`` as a finite number within ``f``'s sign and range."""
    x = real(v, path)
    if f.sign == ">0" and x <= 0:
        raise InputError(path, code="not_positive", value=x)
    if f.sign == ">=0" and x < 0:
        raise InputError(path, code="negative", value=x)
    if f.sign == "!=0" and x == 0:
        raise InputError(path, code="zero")
    lo = f.lo if f.lo is not None else (0.0 if f.sign == ">0" else None)
    above = f.hi is not None and (x > f.hi or (f.hi_open and x == f.hi))
    below = lo is not None and (x < lo or (f.lo_open and x == lo))
    if above or below:
        if lo is None:
            raise InputError(path, code="too_large", hi=f.hi, value=x)
        if f.hi is None:
            raise InputError(path, code="too_small", lo=lo, value=x)
        raise InputError(path, code="out_of_range", lo=lo, hi=f.hi, value=x)
    return x


def _table(f: Field, v, path: str) -> list:
    """A ``table`` field: at least 2 rows, a number per column, the first column increasing."""
    names = ", ".join(name for name, _, _ in f.columns)
    if not isinstance(v, list) or len(v) < 2:
        raise InputError(path, code="not_table", columns=names, got=shown(v))
    cells = [Field(name, "number", unit, sign) for name, unit, sign in f.columns]
    rows: list = []
    for k, row in enumerate(v):
        here = f"{path}[{k}]"
        if not isinstance(row, list) or len(row) != len(cells):
            raise InputError(here, code="not_row", columns=names, got=shown(row))
        out = [_number(c, x, f"{here}[{j}]") for j, (c, x) in enumerate(zip(cells, row))]
        if rows and out[0] <= rows[-1][0]:
            raise InputError(f"{here}[0]", code="not_increasing", column=cells[0].path,
                             value=out[0], before=rows[-1][0])
        rows.append(out)
    return rows


def children(path: str) -> list:
    """Keys of the sections directly inside ``path`` (``""``: the top level)."""
    depth = path.count(".") + 1 if path else 0
    return [s.rsplit(".", 1)[-1] for s in SECTIONS
            if s.count(".") == depth and (not path or s.startswith(path + "."))]


def read(path: str, obj) -> dict:
    """Section ``path`` of the input, checked, every default filled in.

    Fields come back in table order: a given value checked, else the default
    (``None`` for a derived default); a field whose ``only_with`` does not hold
    is ``None`` and an error when given.  Sections inside it come back as given
    (each is read by its own call).
    """
    fields = section_fields(path)
    sec = object_fields(obj, path, [f.key for f in fields] + children(path))
    out: dict = {}
    for f in fields:
        if f.only_with:
            on, want = f.only_with
            if out[on.rsplit(".", 1)[1]] != want:
                if f.key in sec:
                    raise InputError(f.path, code="only_with", key=on.rsplit(".", 1)[1], value=want)
                out[f.key] = None
                continue
        if f.key in sec:
            out[f.key] = value(f, sec[f.key])
        elif f.default is REQUIRED:
            raise InputError(f.path, code="required")
        else:
            out[f.key] = list(f.default) if isinstance(f.default, tuple) else f.default
    for key in children(path):
        if key in sec:
            out[key] = sec[key]
    return out

