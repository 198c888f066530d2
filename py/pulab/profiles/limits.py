"""What a firmware cannot hold: a profile is a lens on the motor, and a lens can fail alone.

The physics of a report (bases, per-unit values, SI gains, loop analysis, float
simulations) never depends on one firmware's integer ranges.  When a firmware cannot be
given this motor — a Uint16 parameter too small for the value, a division by zero in its
C code — its section of the report says so here, field by field: what the value needs,
what a 16-bit parameter would keep, which of its integers cannot be computed, and what
the user can change (docs/contract.md "Firmware limits").

Examples
--------
>>> p = raw_problem("FullFreq01", 326667, ["LD", "LQ", "FreqPer", "FluxRotor"])
>>> p["field"], p["stored"], p["max_si"]
('raw.FullFreq01', 64523, 655.35)
>>> p["message"][:44]
'FullFreq01 is a Uint16 in 0.01 Hz: it holds '
"""

from __future__ import annotations

import math

from ..schema.catalog import render
from ..schema.errors import InputError
from .inovance.code import RAW_SCALE, INDUCTANCE_SCALE

__all__ = ["RAW_UNITS", "raw_problem", "error_problem", "constant_problem", "inovance", "status"]

#: The unit of each Inovance raw parameter (one count), as the firmware's parameter table has it.
RAW_UNITS = {"Voltage": ("1 V", "V"), "Current": ("0.01 A", "A"),
             "FullFreq01": ("0.01 Hz", "Hz"), "FreqRated01": ("0.01 Hz", "Hz"),
             "RsPm": ("1 mΩ", "Ω"), "LD": ("0.01 mH", "H"), "LQ": ("0.01 mH", "H"),
             "BemfVolt": ("0.1 V", "V"), "uDCFilter": ("0.1 V", "V")}


def _entry(field: str, code: str, params: dict, results: list, advice: str, **extra) -> dict:
    return {"field": field, "code": code, "params": params,
            "message": render(code, params, "en"), "message_zh": render(code, params, "zh"),
            "results": sorted(results), "advice": render(advice, params, "en"),
            "advice_zh": render(advice, params, "zh"), **extra}


def raw_problem(name: str, value: int, results: list, inductance_unit: str = "10uH") -> dict:
    """One raw parameter whose value does not fit its Uint16.

    Parameters
    ----------
    name : str — the raw field (``FullFreq01`` …)
    value : int — the integer the SI input needs
    results : list of str — the vendor results that read it (not computed)
    inductance_unit : {'10uH', 'uH'}

    Returns
    -------
    dict
        ``field``, ``code`` (``limit.uint16``), ``params``, ``message``/``message_zh``,
        ``results``, ``advice``/``advice_zh``, ``value`` (needed), ``stored`` (what a
        16-bit parameter keeps: the value modulo 2^16), ``max_si`` (the largest SI value the
        parameter holds).
    """
    path, scale = RAW_SCALE[name]
    if scale is None:
        scale = INDUCTANCE_SCALE[inductance_unit]
    unit = ("1 µH", "H") if name in ("LD", "LQ") and inductance_unit == "uH" else RAW_UNITS[name]
    stored = value & 0xFFFF
    max_si = round(0xFFFF / scale, 12)
    params = {"name": name, "unit": unit[0], "max": max_si, "si_unit": unit[1], "source": path,
              # the text names that SI field by its form label, in the reader's language
              "source_label": {"label": path}, "si": value / scale, "value": value, "stored": stored,
              "stored_si": stored / scale, "results": ", ".join(sorted(results)) or "—"}
    return _entry(f"raw.{name}", "limit.uint16", params, results, "limit.uint16_advice",
                  value=value, stored=stored, max_si=max_si)


def error_problem(err: InputError, results: list) -> dict:
    """A vendor result the C code cannot compute (a division by zero), as a limit entry."""
    params = {"reason": err.as_dict(), "results": ", ".join(sorted(results))}
    return _entry(err.field, "limit.code", params, results, "limit.code_advice",
                  value=None, stored=None, max_si=None)


def constant_problem(profile: str, c: dict, options: tuple = ()) -> dict:
    """A profile constant that does not fit its word: what the firmware keeps instead, and
    how much to rescale it — fractional bits to drop, or the factor a base must move it by.

    Parameters
    ----------
    profile : str ; c : dict — the constant (:func:`pulab.profiles.common.fixed`)
    options : tuple of str — the profile's numeric options (its bases, full scales, dividers)
    """
    factor = abs(c["ideal"]) / max(abs(c["value"]), 1)
    bits = max(1, math.ceil(math.log2(factor)))
    params = {"path": f"profiles.{profile}.{c['name']}", "profile_name": {"vendor": profile},
              "name": c["name"], "ideal": c["ideal"], "format": c["format"], "value": c["value"],
              "factor": factor, "bits": bits, "q_new": c["q"] - bits,
              "options": ", ".join(f"profiles.{profile}.{k}" for k in options) or "—",
              # the same options by their labels on the vendors panel, in the reader's language
              "option_labels": [{"label": f"profiles.{profile}.{k}"} for k in options] or "—"}
    return _entry(params["path"], "warning.profile_overflow", params, [c["name"]],
                  "limit.constant_advice", value=c["ideal"], stored=c["value"], max_si=None)


def inovance(outside: dict, failed: dict, inductance_unit: str) -> list:
    """The Inovance firmware's limit entries for one motor.

    Parameters
    ----------
    outside : dict — raw name → needed integer outside Uint16 (:func:`.inovance.code.raw_split`)
    failed : dict — vendor result → InputError (:func:`.inovance.code.vendor_split`)
    inductance_unit : {'10uH', 'uH'}
    """
    by_field: dict = {}
    for result, err in failed.items():
        by_field.setdefault(err.field, ([], err))[0].append(result)
    out = []
    for name, value in outside.items():
        results, _ = by_field.pop(f"raw.{name}", ([], None))
        out.append(raw_problem(name, value, results, inductance_unit))
    out += [error_problem(err, results) for results, err in by_field.values()]
    return out


def status(problems: list) -> dict:
    """A firmware's section of ``firmware``: ``representable`` and its ``problems``."""
    return {"representable": not problems, "problems": problems}
