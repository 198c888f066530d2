"""Vendor profiles: the same motor and drive in five vendors' scaling (docs/contract.md).

One module per vendor — :mod:`.inovance` (the seed's code, via :mod:`pulab.profiles.inovance_code`),
:mod:`.ti`, :mod:`.nxp`, :mod:`.st`, :mod:`.microchip` — each with the same small
interface: ``OPTIONS`` (its hardware inputs, their defaults and form labels), ``CONVENTIONS`` and
``CONVENTIONS_ZH`` (its base choices, in words, English and Chinese), ``bases(ctx, opt)``
(its voltage, current and inductance bases in SI), ``profile(ctx, opt)`` (its constants),
``gain_fields``/``gain_range``/``gains_to_ints``/``ints_to_gains`` (its current-loop
integers, for the translator) and, except Inovance, ``header(p, ctx)``.

Profiles are computed only when the input has a ``profiles`` section (``{}`` asks for
all five with defaults), so a plain report stays as fast as before.

Examples
--------
>>> from pulab import report
>>> r = report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4},
...     "profiles": {}})
>>> sorted(r["profiles"])
['inovance', 'microchip', 'nxp', 'st', 'ti']
>>> r["profiles"]["microchip"]["constants"]["KIP"]["format"]
'Q15'
"""

from __future__ import annotations

from ..model.bases import flux_linkage
from ..schema.catalog import VENDOR_NAMES
from ..schema.errors import InputError
from ..schema.fields import Field
from ..schema.validate import integer, object_fields, shown, value
from . import inovance, limits, microchip, nxp, st, ti
from .common import SQRT2

__all__ = ["NAMES", "MODULES", "OPTION_LABELS", "context", "context_of", "options", "profiles", "bases_table",
           "header"]

NAMES = ("inovance", "ti", "nxp", "st", "microchip")
MODULES = {"inovance": inovance, "ti": ti, "nxp": nxp, "st": st, "microchip": microchip}
#: ``profiles.NAME.KEY`` → the option's form label (en, zh), the vendor's name first: what the
#: vendors panel shows at the field and what a message names it by.
OPTION_LABELS = {f"profiles.{name}.{opt[0]}": tuple(f"{v} · {w}" for v, w in
                                                 zip(VENDOR_NAMES[name], opt[3]))
                 for name in NAMES for opt in MODULES[name].OPTIONS}

_INTEGERS = {"global_q": (1, 30), "f1": (1, 32767), "tf_kpdiv": (1, 32768),
             "tf_kidiv": (1, 32768)}
_BOOLEANS = {"trapezoidal", "round_u_max"}
#: Every other option: a positive number in the input's plausibility range.
_OPTION_NUMBER = Field("profiles.NAME.OPTION", "number", sign=">0", lo=1e-9, hi=1e9)


def context(n: dict, raw: dict, vendor: dict, pi: dict, problems: list = ()) -> dict:
    """Everything a profile needs from the normalized input and the report, in SI.

    Parameters
    ----------
    n : dict
        The normalized input (:func:`pulab.schema.inputs.normalize`).
    raw, vendor : dict
        The Inovance raw integers and results (:mod:`pulab.profiles.inovance_code`).
    pi : dict
        The report's ``current_pi``; its SI kp [V/A], ki [V/(A·s)] per axis are the
        gains every profile stores (a V/A ratio is the same in peak and RMS).
    problems : list
        What the Inovance firmware cannot hold (``firmware.inovance.problems``).
    """
    m, d = n["motor"], n["drive"]
    return {"rs": m["rs_ohm"], "ld": m["ld_h"], "lq": m["lq_h"], "pp": m["pole_pairs"],
            "i_rated": m["rated_current_a"], "u_rated": m["rated_voltage_v"],
            "f_rated": m["rated_freq_hz"], "bemf_v": m["bemf_v"], "f_base": d["base_freq_hz"],
            "udc": d["udc_v"], "ts": d["ts_s"], "i_fs": 2.0 * SQRT2 * m["rated_current_a"],
            "psi_peak": flux_linkage("peak", m["bemf_v"], m["rated_freq_hz"]),
            "psi_rms": flux_linkage("rms", m["bemf_v"], m["rated_freq_hz"]),
            "u_limit": d["udc_v"] / SQRT2,
            "gains": {a: (pi[a]["kp"], pi[a]["ki"]) for a in ("d", "q")},
            "vendor": vendor, "raw": raw, "inductance_unit": n["conventions"]["inductance_unit"],
            "firmware_problems": list(problems)}


def _option(name: str, key: str, v):
    path = f"profiles.{name}.{key}"
    if key in _BOOLEANS:
        if not isinstance(v, bool):
            raise InputError(path, code="not_flag", got=shown(v))
        return v
    if key in _INTEGERS:
        v = integer(v, path, *_INTEGERS[key])
        if key.startswith("tf_") and v & (v - 1):
            raise InputError(path, code="power_of_two", got=v)
        return v
    return value(_OPTION_NUMBER, v, path)


def options(section, ctx: dict) -> dict:
    """The ``profiles`` input section checked, every vendor's defaults filled in.

    Raises
    ------
    InputError
        Naming ``profiles.NAME.KEY`` for an unknown or bad value.
    """
    given = object_fields(section, "profiles", NAMES)
    out = {}
    for name in NAMES:
        spec = MODULES[name].OPTIONS
        sec = object_fields(given.get(name), f"profiles.{name}", [k for k, *_ in spec])
        out[name] = {k: _option(name, k, sec[k]) if k in sec else default(ctx)
                     for k, default, *_ in spec}
    return out


def bases_table(name: str, ctx: dict, p: dict) -> dict:
    """The conventions of one profile side by side: words and the numeric bases (SI)."""
    u, i, l_b = MODULES[name].bases(ctx, p["inputs"])
    return {**MODULES[name].CONVENTIONS, "zh": MODULES[name].CONVENTIONS_ZH, "U_b": u, "I_b": i,
            "Z_b": u / i, "L_b": l_b, "kp_per_unit_of_1_ohm": i / u}


def profiles(ctx: dict, opts: dict, names: tuple | None = None) -> dict:
    """Every profile (or those in ``names``): ``inputs`` (options used), ``constants``,
    ``bases``, ``files`` and ``status`` (:func:`pulab.profiles.limits.status`: what this
    firmware cannot hold).

    Each profile is a lens that fails on its own: a constant that does not fit its word is
    a problem of that profile, never an error of the report.
    """
    out = {}
    for name in names or NAMES:
        p = MODULES[name].profile(ctx, opts[name])
        p["bases"] = bases_table(name, ctx, p)
        p["files"] = MODULES[name].FILES
        problems = ctx["firmware_problems"] if name == "inovance" else []
        scales = tuple(k for k, *_ in MODULES[name].OPTIONS if k not in _BOOLEANS)
        problems = problems + [limits.constant_problem(name, c, scales)
                               for c in p["constants"].values()
                               if "out_of_range" in c["flags"] or "saturate" in c["flags"]]
        p["status"] = limits.status(problems)
        out[name] = p
    return out


def context_of(r: dict) -> dict:
    """:func:`context` rebuilt from a finished report (which carries every piece of it)."""
    return context(r["input"], r["vendor"]["raw"],
                   {k: v for k, v in r["vendor"].items() if k != "raw"}, r["current_pi"],
                   r["firmware"]["inovance"]["problems"])


def header(r: dict, name: str) -> str:
    """The C header of one profile, in that vendor's naming and layout.

    Parameters
    ----------
    r : dict
        A report computed with a ``profiles`` section.
    name : {'inovance', 'ti', 'nxp', 'st', 'microchip'}
        Inovance's header is the report's own (:func:`pulab.export.c_header`).
    """
    if name not in NAMES:
        raise InputError("profile", code="not_choice", choices=", ".join(NAMES), got=shown(name))
    problems = r["firmware"]["inovance"]["problems"]
    if name == "inovance" and problems:
        raise InputError("profile", code="profile_unrepresentable", profile=name,
                         reason={"code": problems[0]["code"],
                                                      "params": problems[0]["params"]})
    if name == "inovance":
        from ..export import c_header
        return c_header(r)
    return MODULES[name].header(r["profiles"][name], context_of(r))
