"""Validation and defaults for the report input (docs/contract.md).

Bad input never becomes a number: every problem raises
:class:`pulab.schema.errors.InputError` naming the JSON path of the field.

Examples
--------
>>> inp = normalize({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> inp["drive"]["base_freq_hz"], inp["conventions"]["base"], inp["current_loop"]["method"]
(220.0, 'rms', 'bandwidth')
>>> normalize({"motor": {}})
Traceback (most recent call last):
...
pulab.schema.errors.InputError: motor.rated_voltage_v: is required
"""

from __future__ import annotations

import math
import sys

from ..model import datasheet as _datasheet
from .errors import InputError
from ..profiles.inovance_code import RAW_FIELDS

__all__ = ["normalize", "object_fields", "real", "shown", "key_path", "DEFAULT_CURRENT_BANDWIDTH_HZ", "DEFAULT_PLL_BANDWIDTH_HZ",
           "DEFAULT_DAMPING", "SECTIONS"]

DEFAULT_CURRENT_BANDWIDTH_HZ = 500.0
DEFAULT_PLL_BANDWIDTH_HZ = 50.0
DEFAULT_DAMPING = math.sqrt(0.5)

#: Allowed keys of each section; a typo must not fall back to a default silently.
SECTIONS = {
    "motor": ("rated_voltage_v", "rated_current_a", "rated_freq_hz", "rs_ohm", "ld_h",
              "lq_h", "bemf_v", "pole_pairs"),
    "drive": ("base_freq_hz", "udc_v", "ts_s"),
    "conventions": ("base", "base_voltage_v", "base_current_a", "angle_base",
                    "inductance_unit"),
    "current_loop": ("method", "bandwidth_hz", "damping", "kp", "ki", "pm_kp", "pm_ki"),
    "pll": ("bandwidth_hz", "damping"),
    "raw": RAW_FIELDS,
}
#: Plausibility limits (SI) that also keep every derived number finite.
_LIMITS = {"ts_s": (1e-9, 1.0), "damping": (1e-3, 100.0)}

#: The largest integer a float holds (anything above rounds to inf or raises).
_FLOAT_MAX_INT = int(sys.float_info.max)

_CHOICES = {
    "conventions.base": ("rms", "peak", "custom"),
    "conventions.angle_base": ("pi", "2pi"),
    "conventions.inductance_unit": ("10uH", "uH"),
    "current_loop.method": ("bandwidth", "damping", "manual", "integers"),
}


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
    """A JSON object with only ``allowed`` keys, nulls dropped (absent = null).

    Shared by every input section, here and in :mod:`pulab.analyses.sim.inputs`.
    """
    if v is None:
        return {}
    if not isinstance(v, dict):
        raise InputError(path, f"must be an object, got {shown(v)}")
    for key in v:
        if key not in allowed:
            raise InputError(key_path(path, key), f"unknown field (expected one of: "
                             f"{', '.join(allowed)})")
    return {k: x for k, x in v.items() if x is not None}


def real(v, path: str) -> float:
    """A JSON number as a finite float; booleans are not numbers."""
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise InputError(path, f"must be a number, got {shown(v)}")
    # A JSON integer literal can exceed the float range (309 digits); it is no finite number.
    if isinstance(v, int) and abs(v) > _FLOAT_MAX_INT:
        raise InputError(path, "must be finite")
    v = float(v)
    if not math.isfinite(v):
        raise InputError(path, "must be finite")
    return v


def _section(inp: dict, name: str) -> dict:
    return object_fields(inp.get(name), name, SECTIONS[name])


def _number(sec: dict, section: str, key: str, default=None) -> float:
    path = f"{section}.{key}"
    if key not in sec:
        if default is None:
            raise InputError(path, "is required")
        return float(default)
    v = real(sec[key], path)
    if v <= 0:
        raise InputError(path, f"must be > 0, got {v:g}")
    lo, hi = _LIMITS.get(key, (1e-9, 1e9))
    if not lo <= v <= hi:
        raise InputError(path, f"must be between {lo:g} and {hi:g}, got {v:g}")
    return v


def _choice(sec: dict, section: str, key: str, default: str) -> str:
    path = f"{section}.{key}"
    v = sec.get(key, default)
    if v not in _CHOICES[path]:
        raise InputError(path, f"must be one of {', '.join(_CHOICES[path])}, got {shown(v)}")
    return v


def _integer(v, path: str, lo: int, hi: int) -> int:
    if isinstance(v, bool) or not isinstance(v, (int, float)) or \
            (isinstance(v, float) and not v.is_integer()):
        raise InputError(path, f"must be an integer, got {shown(v)}")
    v = int(v)
    if not lo <= v <= hi:
        raise InputError(path, f"must be {lo}..{hi}, got {shown(v)}")
    return v


def normalize(inp: dict) -> dict:
    """Check the input and return it with every default filled in.

    Parameters
    ----------
    inp : dict
        The report input (contract "Input").

    Returns
    -------
    dict
        Same layout; every optional field present; numbers as float (pole
        pairs and raw values as int); ``raw`` holds only the values given.
        ``motor`` holds the values derived from a ``datasheet`` section, and
        ``datasheet`` (when given) its values and conversions
        (:func:`pulab.model.datasheet.apply`).
    """
    if not isinstance(inp, dict):
        raise InputError("input", "must be a JSON object")
    for key in inp:
        if key not in SECTIONS and key not in ("sim", "datasheet", "profiles", "analysis"):
            raise InputError(key_path("", key), f"unknown section (expected one of: "
                             f"{', '.join(list(SECTIONS) + ['datasheet', 'sim', 'profiles', 'analysis'])})")
    ds = object_fields(inp.get("datasheet"), "datasheet", _datasheet.FIELDS)
    m, conversions, d = _datasheet.apply(ds, _section(inp, "motor"), _section(inp, "drive"))
    c = _section(inp, "conventions")
    cl = _section(inp, "current_loop")
    p = _section(inp, "pll")
    r = _section(inp, "raw")

    derived = {c["field"]: c["from"][0] for c in conversions}
    motor = {}
    for k in SECTIONS["motor"]:
        if k == "pole_pairs":
            continue
        try:
            motor[k] = _number(m, "motor", k)
        except InputError as e:
            if f"motor.{k}" not in derived:
                raise
            # The value came from the datasheet: the error belongs at what the user typed.
            raise InputError(derived[f"motor.{k}"], f"gives motor.{k} = {m[k]:g}, which "
                             f"{e.message}") from None
    if "pole_pairs" not in m:
        raise InputError("motor.pole_pairs", "is required")
    motor["pole_pairs"] = _integer(m["pole_pairs"], "motor.pole_pairs", 1, 1000)

    drive = {"base_freq_hz": _number(d, "drive", "base_freq_hz", motor["rated_freq_hz"]),
             "udc_v": _number(d, "drive", "udc_v"),
             "ts_s": _number(d, "drive", "ts_s")}

    conv = {"base": _choice(c, "conventions", "base", "rms"),
            "angle_base": _choice(c, "conventions", "angle_base", "pi"),
            "inductance_unit": _choice(c, "conventions", "inductance_unit", "10uH"),
            "base_voltage_v": None, "base_current_a": None}
    if conv["base"] == "custom":
        conv["base_voltage_v"] = _number(c, "conventions", "base_voltage_v")
        conv["base_current_a"] = _number(c, "conventions", "base_current_a")
    else:
        for k in ("base_voltage_v", "base_current_a"):
            if k in c:
                raise InputError(f"conventions.{k}", "is only used with base = custom")

    method = _choice(cl, "current_loop", "method", "bandwidth")
    loop = {"method": method,
            "bandwidth_hz": _number(cl, "current_loop", "bandwidth_hz",
                                    DEFAULT_CURRENT_BANDWIDTH_HZ),
            "damping": _number(cl, "current_loop", "damping", DEFAULT_DAMPING),
            "kp": None, "ki": None, "pm_kp": None, "pm_ki": None}
    # Gains given directly belong to one method each; elsewhere they would be ignored silently.
    for k, owner in (("kp", "manual"), ("ki", "manual"), ("pm_kp", "integers"),
                     ("pm_ki", "integers")):
        path = f"current_loop.{k}"
        if method != owner:
            if k in cl:
                raise InputError(path, f"is only used with method = {owner}")
        elif owner == "manual":
            loop[k] = _number(cl, "current_loop", k)
        elif k not in cl:
            raise InputError(path, "is required")
        else:
            loop[k] = _integer(cl[k], path, 1, (1 << 31) - 1)

    pll = {"bandwidth_hz": _number(p, "pll", "bandwidth_hz", DEFAULT_PLL_BANDWIDTH_HZ),
           "damping": _number(p, "pll", "damping", DEFAULT_DAMPING)}

    raw = {k: _integer(v, f"raw.{k}", 0, 0xFFFF) for k, v in r.items()}

    out = {"motor": motor, "drive": drive, "conventions": conv, "current_loop": loop,
           "pll": pll, "raw": raw}
    if ds:
        # Not part of the echoed input (report.input.motor already holds the derived values).
        out["datasheet"] = {"given": ds, "conversions": conversions}
    if inp.get("sim") is not None:
        out["sim"] = inp["sim"]
    if "profiles" in inp:  # checked in pulab.profiles.options: its defaults need the motor
        out["profiles"] = inp["profiles"]
    out["analysis"] = inp.get("analysis")
    return out
