"""Translator: one vendor's current-loop integers → SI → every other vendor's integers.

Given the firmware integers of one profile (e.g. Inovance ``pm_kp``/``pm_ki``, TI
``Kp_Iq``/``Ki_Iq`` in IQ24) for one axis, the translator

1. decodes them to SI (kp [V/A], ki [V/(A·s)]) with that profile's scaling;
2. encodes the SI gains into every other profile (``profiles``: value, ideal,
   error and what the stored integer means back in SI — what rounding loses);
3. runs the chain source → … → source through every profile in the registry's order
   (:mod:`pulab.profiles.registry`: inovance → ti → nxp → st → microchip), rotated to
   start at the source, each step encoding the previous step's stored integers' SI
   meaning (``chain``), so the losses accumulate as they would when a port is ported again.

Each chain step moves kp by at most one LSB of that step's format (half an LSB
when it rounds to nearest) and ki by one LSB plus ki·|Δkp|/kp (TI's series Ki
multiplies the stored Kp); ``lsb`` in each step gives that bound in SI.

Examples
--------
>>> from pulab.profiles.translate import translate
>>> inp = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}}
>>> t = translate(inp, "inovance", "q", {"pm_kp": 1180, "pm_ki": 4720})
>>> t["profiles"]["ti"]["values"]
{'Kp_Iq': 5590671, 'Ki_Iq': 4194304}
>>> t["round_trip"]["values"]
{'pm_kp': 1180, 'pm_ki': 4720}
"""

from __future__ import annotations

from ..schema.errors import InputError
from ..schema.validate import integer, object_fields, shown
from ..report import report, require_pmsm
from . import options, registry
from .context import context_of

__all__ = ["translate"]


def _encode(name: str, kp: float, ki: float, ctx: dict, opts: dict, axis: str) -> dict:
    recs = registry.VENDORS[name].gains_to_ints(kp, ki, ctx, opts[name], axis)
    kp_rec, ki_rec = recs.values()
    return {"values": {k: r["value"] for k, r in recs.items()}, "constants": recs,
            "si": {"kp": kp_rec["si"], "ki": ki_rec["si"]},
            "loss_pct": {"kp": 100.0 * (kp_rec["si"] - kp) / kp,
                         "ki": 100.0 * (ki_rec["si"] - ki) / ki if ki else 0.0},
            "lsb": {"kp": kp_rec["scale"] / 2.0 ** kp_rec["q"],
                    "ki": ki_rec["scale"] / 2.0 ** ki_rec["q"]}}


def translate(inp: dict, source: str, axis: str, values) -> dict:
    """Translate one profile's current-loop integers into every profile.

    Parameters
    ----------
    inp : dict
        The report input (motor, drive, and optionally ``profiles`` hardware inputs).
    source : str
        A vendor (:func:`pulab.profiles.registry.names`).
    axis : {'d', 'q'}
    values : dict
        The source profile's two integers by their vendor names
        (``gain_fields(axis)`` of that profile's module, e.g. ``{"Kp_Iq": …, "Ki_Iq": …}``).

    Raises
    ------
    InputError
        Naming ``translate.from``, ``translate.axis`` or ``translate.values.NAME``.
    """
    mod = registry.get(source, "translate.from")
    if axis not in ("d", "q"):
        raise InputError("translate.axis", code="not_choice", choices="d, q", got=shown(axis))
    kp_name, ki_name = mod.gain_fields(axis)
    given = object_fields(values, "translate.values", (kp_name, ki_name))
    lo, hi = mod.gain_range(axis)
    ints = {}
    for k in (kp_name, ki_name):
        if k not in given:
            raise InputError(f"translate.values.{k}", code="required")
        ints[k] = integer(given[k], f"translate.values.{k}", lo, hi)
    if ints[kp_name] == 0:
        raise InputError(f"translate.values.{kp_name}", code="zero")
    # The report without profiles gives the SI context; only the options are needed here,
    # not the five profiles' constants (which cost ten times the rest in Pyodide).
    r = report({k: v for k, v in inp.items() if k != "profiles"})
    require_pmsm(r["input"])
    ctx = context_of(r)
    opts = options(inp.get("profiles"), ctx)
    kp, ki = mod.ints_to_gains(ints[kp_name], ints[ki_name], ctx, opts[source], axis)
    names = registry.names()
    out = {"from": source, "axis": axis, "given": ints, "si": {"kp": kp, "ki": ki},
           "profiles": {name: _encode(name, kp, ki, ctx, opts, axis) for name in names}}
    start = names.index(source)
    order = [names[(start + i) % len(names)] for i in range(1, len(names) + 1)]
    chain, k_p, k_i = [], kp, ki
    for prev, name in zip([source] + order, order):
        try:
            step = _encode(name, k_p, k_i, ctx, opts, axis)
        except ZeroDivisionError:  # kp rounded to 0 in `prev`, and TI's series Ki = ki·T/kp
            raise InputError(f"translate.values.{kp_name}", code="chain_kp_zero",
                             profile=prev) from None
        step["profile"] = name
        step["drift_pct"] = {"kp": 100.0 * (step["si"]["kp"] - kp) / kp,
                             "ki": 100.0 * (step["si"]["ki"] - ki) / ki if ki else 0.0}
        chain.append(step)
        k_p, k_i = step["si"]["kp"], step["si"]["ki"]
    out["chain"] = chain
    back = chain[-1]["values"]
    out["round_trip"] = {"values": back, "delta": {k: back[k] - ints[k] for k in ints}}
    return out
