"""The standalone Q-format calculator: a value or a register reading in a Q format.

:func:`qcalc` reads one request (dict → dict, like :func:`pulab.report`); the arithmetic is
:mod:`pulab.fixedpoint.qformat`'s, the texts people type (full-width digits, ``0x…``) are
read by :mod:`pulab.schema.textnum`.  The kind ``qcalc`` of :func:`pulab.api.call_json` is its JSON shell.

Examples
--------
>>> qcalc({"value": 0.5, "format": "Q0.15"})["result"]["raw"]
16384
>>> qcalc({"raw": "0x8000", "format": "Q15"})["result"]["flags"]
['unsigned_register']
"""

from __future__ import annotations

import re

from .fixedpoint.qformat import OVERFLOWS, ROUNDINGS, decode, encode, parse_format
from .schema.errors import InputError
from .schema.textnum import ascii_text, parse_int, parse_real
from .schema.validate import shown

__all__ = ["qcalc"]


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
        raise InputError("qcalc", code="not_object", got=shown(req))
    name = req.get("format", "")
    if not isinstance(name, str):
        raise InputError("qcalc.format", code="not_string", got=shown(name))
    name = ascii_text(name)
    word_bits = req.get("word_bits")
    if word_bits is not None and (isinstance(word_bits, bool) or not isinstance(word_bits, int)):
        raise InputError("qcalc.word_bits", code="not_integer", got=shown(word_bits))
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
            raise InputError("qcalc.format", code="q_too_wide", name=name,
                             bits=word_bits or 64) from None
        raise InputError("qcalc.format", code="not_q_format", got=shown(req.get("format", ""))) from None
    rounding = req.get("rounding", "nearest")
    overflow = req.get("overflow", "saturate")
    if rounding not in ROUNDINGS:
        raise InputError("qcalc.rounding", code="not_choice", choices=", ".join(ROUNDINGS),
                         got=shown(rounding))
    if overflow not in OVERFLOWS:
        raise InputError("qcalc.overflow", code="not_choice", choices=", ".join(OVERFLOWS),
                         got=shown(overflow))
    if req.get("raw") is not None:
        raw = parse_int(req["raw"], "qcalc.raw")
        flags = []
        if fmt.signed and fmt.raw_max < raw < (1 << fmt.word_bits):
            # A register reading (40000, 0x8000) is the word's bit pattern: two's complement.
            raw -= 1 << fmt.word_bits
            flags.append("unsigned_register")
        if not fmt.raw_min <= raw <= fmt.raw_max:
            hi = (1 << fmt.word_bits) - 1 if fmt.signed else fmt.raw_max
            raise InputError("qcalc.raw", code="raw_range_for", lo=fmt.raw_min, hi=hi, fmt=fmt.name)
        res = {"raw": raw, "value": decode(raw, fmt), "error": 0.0, "flags": flags}
    else:
        x = parse_real(req.get("value"), "qcalc.value")
        try:
            e = encode(x, fmt, rounding, overflow)
        except OverflowError:
            raise InputError("qcalc.value", code="q_outside", value=x, fmt=fmt.name,
                             lo=fmt.min_value, hi=fmt.max_value) from None
        res = {"raw": e.raw, "value": e.value, "error": e.error, "flags": e.flags}
    mask = (1 << fmt.word_bits) - 1
    res["hex"] = f"0x{res['raw'] & mask:0{(fmt.word_bits + 3) // 4}X}"
    return {"format": {"name": fmt.name, "word_bits": fmt.word_bits, "frac_bits": fmt.frac_bits,
                       "signed": fmt.signed, "min": fmt.min_value, "max": fmt.max_value,
                       "resolution": fmt.resolution},
            "result": res}
