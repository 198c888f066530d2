"""Vendor profiles: the same motor and drive in five vendors' scaling (docs/contract.md).

One package per vendor — :mod:`.inovance` (the seed's code, via
:mod:`pulab.profiles.inovance.code`), :mod:`.ti`, :mod:`.nxp`, :mod:`.st`,
:mod:`.microchip` — each with the members of :class:`pulab.profiles.vendor.Vendor`, listed
once in :mod:`pulab.profiles.registry`.
This module composes them: the ``profiles`` input section checked (:func:`options`), every
profile's constants, bases and status (:func:`profiles`), and one profile's header
(:func:`header`).

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

from ..schema.errors import InputError
from ..schema.validate import object_fields, value
from . import limits, registry
from .context import context, context_of
from .vendor import provided

__all__ = ["MODULES", "context", "context_of", "options", "profiles", "bases_table", "header"]

#: Each vendor by name: :data:`pulab.profiles.registry.VENDORS` itself.
MODULES = registry.VENDORS


def _option(name: str, option, v):
    path = f"profiles.{name}.{option.key}"
    v = value(option.field(name), v)
    if option.power_of_two and v & (v - 1):
        raise InputError(path, code="power_of_two", got=v)
    return v


def options(section, ctx: dict) -> dict:
    """The ``profiles`` input section checked, every vendor's defaults filled in.

    Raises
    ------
    InputError
        Naming ``profiles.NAME.KEY`` for an unknown or bad value.
    """
    given = object_fields(section, "profiles", registry.names())
    out = {}
    for v in registry.vendors():
        sec = object_fields(given.get(v.NAME), f"profiles.{v.NAME}", [o.key for o in v.OPTIONS])
        out[v.NAME] = {o.key: _option(v.NAME, o, sec[o.key]) if o.key in sec else o.default(ctx)
                       for o in v.OPTIONS}
    return out


def bases_table(name: str, ctx: dict, p: dict) -> dict:
    """The conventions of one profile side by side: words and the numeric bases (SI)."""
    v = registry.get(name)
    u, i, l_b = v.bases(ctx, p["inputs"])
    return {**v.CONVENTIONS, "zh": v.CONVENTIONS_ZH, "U_b": u, "I_b": i,
            "Z_b": u / i, "L_b": l_b, "kp_per_unit_of_1_ohm": i / u}


def profiles(ctx: dict, opts: dict, names: tuple | None = None) -> dict:
    """Every profile (or those in ``names``): ``inputs`` (options used), ``constants``,
    ``bases``, ``files`` and ``status`` (:func:`pulab.profiles.limits.status`: what this
    firmware cannot hold).

    Each profile is a lens that fails on its own: a constant that does not fit its word is
    a problem of that profile, never an error of the report.
    """
    out = {}
    for name in names or registry.names():
        v = registry.get(name)
        p = v.profile(ctx, opts[name])
        obs = provided(v, "observer")
        if obs is not None and ctx.get("observer") is not None:
            added = obs(ctx, opts[name])
            p["constants"].update(added)
            p["observer_constants"] = list(added)
        p["bases"] = bases_table(name, ctx, p)
        p["files"] = v.FILES
        problems = p.pop("problems", [])
        scales = tuple(o.key for o in v.OPTIONS if o.kind != "flag")
        problems = problems + [limits.constant_problem(name, c, scales)
                               for c in p["constants"].values()
                               if "out_of_range" in c["flags"] or "saturate" in c["flags"]]
        p["status"] = limits.status(problems)
        out[name] = p
    return out


def header(r: dict, name: str) -> str:
    """The C header of one profile, in that vendor's naming and layout.

    Parameters
    ----------
    r : dict
        A report computed with a ``profiles`` section.
    name : str
        A vendor (:func:`pulab.profiles.registry.names`); Inovance's header is the report's
        own (:func:`pulab.profiles.inovance.header.c_header`).
    """
    return registry.get(name).header(r["profiles"][name], context_of(r), r)
