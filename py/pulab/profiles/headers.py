"""Shared layout of the vendor headers: one ``#define`` per constant with its comment.

Each comment carries what the C line cannot: the float value the integer stands
for, the ideal value, the quantization error, the SI meaning and the flags.

Examples
--------
>>> from pulab.profiles.common import fixed
>>> c = fixed("KIP", 0.155164, 16, 15, 1.6353, "V/A", "kp/Z_b", "x", fmt="Q15")
>>> print(define("KIP", c))
#define KIP                               5084  /* Q15 = 0.155151 (ideal 0.155164, -0.0081 %) = 0.253719 V/A */
"""

from __future__ import annotations

import struct

__all__ = ["define", "define_float", "guard", "comment"]


def comment(c: dict) -> str:
    """``FORMAT = float (ideal x, error %) = SI unit; flags`` for one constant."""
    if c.get("real"):
        return f"{c['format']}: {c['expression']} = {c['ideal']:.10g} {c['unit']}"
    scale = 2.0 ** (c["shift"] - c["q"])
    flags = f"; {', '.join(c['flags'])}" if c["flags"] else ""
    return (f"{c['format']} = {c['value'] * scale:.6g} (ideal {c['ideal'] * scale:.6g}, "
            f"{c['error_pct']:+.4f} %) = {c['si']:.6g} {c['unit']}{flags}")


def define(name: str, c: dict, ctype: str = "") -> str:
    """``#define NAME value  /* comment */``; a cast ``ctype`` keeps the C type explicit."""
    if c.get("real"):
        v = f"({_shortest(c['value'], c['format'] == 'float32')})"
    else:
        v = f"(({ctype}){c['value']})" if ctype else str(c["value"])
    return f"#define {name:<30} {v:>7}  /* {comment(c)} */"


def _shortest(x: float, single: bool) -> str:
    """The shortest C literal the compiler reads back as ``x`` (with ``f`` for a float)."""
    if not single:
        return repr(x)
    for digits in range(6, 10):
        s = f"{x:.{digits}g}"
        if struct.unpack("<f", struct.pack("<f", float(s)))[0] == x:
            break
    return (s if any(ch in s for ch in ".e") else s + ".0") + "f"


def define_float(name: str, value: float, what: str) -> str:
    """A float input the vendor's header keeps in engineering units."""
    return f"#define {name:<30} ({value!r})  /* {what} */"


def guard(name: str, title: list, body: list) -> str:
    """A complete header: title comment, include guard, <stdint.h>, body."""
    out = ["/* " + title[0]] + [" * " + t for t in title[1:]] + [" */",
           f"#ifndef {name}", f"#define {name}", "", "#include <stdint.h>", ""]
    return "\n".join(out + body + ["", f"#endif /* {name} */", ""])
