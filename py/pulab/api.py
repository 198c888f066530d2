"""JSON-in, JSON-out entry points for the web worker (one call per request).

Errors never escape as exceptions: bad input comes back as
``{"ok": false, "field": ..., "message": ..., "message_zh": ...}``.

Examples
--------
>>> import json
>>> json.loads(run_json('{"motor": {}}'))["field"]
'motor.rated_voltage_v'
>>> json.loads(qcalc_json('{"value": 0.5, "format": "Q0.15"}'))["result"]["raw"]
16384
"""

from __future__ import annotations

import json
import re

from .errors import InputError
from .inputs import shown
from .jsontext import parse
from .qformat import OVERFLOWS, ROUNDINGS, decode, encode, parse_format
from .export import c_header, sim_csv
from .messages import to_zh
from .report import report
from .textnum import ascii_text, parse_int, parse_real

__all__ = ["run_json", "qcalc", "qcalc_json", "export_json"]


def _fail(e: InputError) -> str:
    return json.dumps({"ok": False, "field": e.field, "message": e.message,
                       "message_zh": to_zh(e.message)})


def run_json(text: str) -> str:
    """``report`` on a JSON string; returns ``{"ok": true, "report": {...}}`` or an error."""
    try:
        return json.dumps({"ok": True, "report": report(parse(text))}, allow_nan=False)
    except InputError as e:
        return _fail(e)


def qcalc(req: dict) -> dict:
    """The standalone Q-format calculator.

    Parameters
    ----------
    req : dict
        ``format`` (``Qm.n``/``UQm.n``, ``Qn`` with ``word_bits`` (default 16), or an
        IQmath name ``iqN``/``_IQN``: Q N in a 32-bit long), and either ``value`` (a real
        number or its text, full-width digits allowed, to encode with ``rounding`` and
        ``overflow``) or ``raw`` (an integer or its text: decimal, ``0x…``, ``0b…``, to
        decode; for a signed format a reading above its maximum up to 2^word_bits − 1 is
        the register's bit pattern, taken as two's complement and flagged
        ``unsigned_register``).

    Returns
    -------
    dict
        ``format`` (name, word_bits, frac_bits, signed, min, max, resolution) and
        ``result`` (raw, hex, value, error, flags).
    """
    if not isinstance(req, dict):
        raise InputError("qcalc", "must be an object")
    name = req.get("format", "")
    if not isinstance(name, str):
        raise InputError("qcalc.format", f"must be a string, got {shown(name)}")
    name = ascii_text(name)
    word_bits = req.get("word_bits")
    if word_bits is not None and (isinstance(word_bits, bool) or not isinstance(word_bits, int)):
        raise InputError("qcalc.word_bits", "must be an integer")
    iq = re.fullmatch(r"_?iq(\d*)", name, re.I)
    if iq:
        # TI IQmath: _iqN / _IQN is a 32-bit long with N fractional bits (GLOBAL_Q = 24).
        name = f"Q{iq[1] or 24}"
        word_bits = 32 if word_bits is None else word_bits
    if word_bits is None and re.fullmatch(r"U?Q\d+", name, re.I):
        word_bits = 16  # a short name like Q15 means a 16-bit word unless told otherwise
    try:
        fmt = parse_format(name, word_bits)
    except (ValueError, TypeError):
        if re.fullmatch(r"U?Q\d+(\.\d+)?", name, re.I):
            raise InputError("qcalc.format", f"{name} does not fit {word_bits or 64} word "
                             "bits") from None
        raise InputError("qcalc.format", f"not a Q format: {shown(req.get('format', ''))} "
                         "(use Qm.n, UQm.n, or Qn with word_bits)") from None
    rounding = req.get("rounding", "nearest")
    overflow = req.get("overflow", "saturate")
    if rounding not in ROUNDINGS:
        raise InputError("qcalc.rounding", f"must be one of {', '.join(ROUNDINGS)}")
    if overflow not in OVERFLOWS:
        raise InputError("qcalc.overflow", f"must be one of {', '.join(OVERFLOWS)}")
    if req.get("raw") is not None:
        raw = parse_int(req["raw"], "qcalc.raw")
        flags = []
        if fmt.signed and fmt.raw_max < raw < (1 << fmt.word_bits):
            # A register reading (40000, 0x8000) is the word's bit pattern: two's complement.
            raw -= 1 << fmt.word_bits
            flags.append("unsigned_register")
        if not fmt.raw_min <= raw <= fmt.raw_max:
            hi = (1 << fmt.word_bits) - 1 if fmt.signed else fmt.raw_max
            raise InputError("qcalc.raw", f"must be {fmt.raw_min}..{hi} for {fmt.name}")
        res = {"raw": raw, "value": decode(raw, fmt), "error": 0.0, "flags": flags}
    else:
        x = parse_real(req.get("value"), "qcalc.value")
        try:
            e = encode(x, fmt, rounding, overflow)
        except OverflowError as err:
            raise InputError("qcalc.value", str(err)) from None
        res = {"raw": e.raw, "value": e.value, "error": e.error, "flags": e.flags}
    mask = (1 << fmt.word_bits) - 1
    res["hex"] = f"0x{res['raw'] & mask:0{(fmt.word_bits + 3) // 4}X}"
    return {"format": {"name": fmt.name, "word_bits": fmt.word_bits, "frac_bits": fmt.frac_bits,
                       "signed": fmt.signed, "min": fmt.min_value, "max": fmt.max_value,
                       "resolution": fmt.resolution},
            "result": res}


def qcalc_json(text: str) -> str:
    """``qcalc`` on a JSON string; ``{"ok": true, ...}`` or an error naming the field."""
    try:
        return json.dumps({"ok": True, **qcalc(parse(text, "qcalc"))})
    except InputError as e:
        return _fail(e)


def export_json(text: str) -> str:
    """Exports for the page: ``{"input": {...}, "kind": "header"|"csv_current"|"csv_pll"}``.

    Returns ``{"ok": true, "text": ...}`` or an error naming the field.
    """
    try:
        req = parse(text)
        r = report(req.get("input") if isinstance(req, dict) else None)
        kind = req.get("kind")
        if kind == "header":
            return json.dumps({"ok": True, "text": c_header(r)})
        if kind in ("csv_current", "csv_pll"):
            if "sim" not in r or kind[4:] not in r["sim"]:
                raise InputError("sim", f"the input asks for no {kind[4:]} simulation")
            return json.dumps({"ok": True, "text": sim_csv(r, kind[4:])})
        raise InputError("kind", "must be one of header, csv_current, csv_pll")
    except InputError as e:
        return _fail(e)
