"""The firmware integers of a scaling profile for one input, each with its state.

A sweep (:mod:`pulab.analyses.sweep`) evaluates thousands of inputs; for each it needs
every integer the firmware stores, how far it is from the exact value, and
whether the firmware got it at all.  Each integer is named by its JSON path in
the report (``vendor.LD``, ``current_pi.d.pm_ki``) and gets one status:

``ok``
    computed; only rounding or truncation error;
``zero``
    the integer is 0 while its exact value is not: all resolution is lost
    (e.g. ``pm_ki`` rounds to 0 and the integral action is gone);
``store``
    the store into Uint16 changed the number (it wrapped modulo 2^16);
``wrap``
    an intermediate result wrapped around its C type;
``div0``
    the firmware divides by zero on the way (e.g. ``m_BaseL`` = 0 for LD);
``invalid``
    the input itself is refused (a raw value outside Uint16, a non-positive
    value, …) — not a firmware state, but where the family ends.

Profiles select the set of integers.  ``inovance`` (alias ``vendor``) is the
seed's Inovance C2000 code: the ``vendor`` results of seed 1.4 and 2.2 and the
current-PI integers of seed 2.2-9.  Any other name is looked up in the report's
``profiles.NAME.constants``, through the full report.

Examples
--------
>>> e = evaluate({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> ld = e["integers"]["vendor.LD"]
>>> ld["status"], ld["value"], round(ld["error_pct"], 3), e["intermediates"]["m_BaseL"]
('ok', 1045, 0.64, 94)
>>> e = evaluate({"motor": {"rated_voltage_v": 17, "rated_current_a": 130,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4}})
>>> e["integers"]["vendor.LD"]["status"], e["intermediates"]["m_BaseL"]
('div0', 0)
"""

from __future__ import annotations

from ..schema.errors import InputError
from ..model.gains import pi_integer_ideals
from ..schema.inputs import normalize
from ..schema.validate import shown
from ..report import current_pi_section, input_bases, input_raw, report
from ..profiles.inovance.code import RAW_SCALE, VENDOR_READS, VENDOR_RESULTS

__all__ = ["evaluate", "integer_names", "profile_name", "STATUSES", "DEFAULT_PROFILE",
           "INOVANCE_NAMES", "RAW_ONLY_NAMES"]

#: Every status, from harmless to the end of the family (the order ranks worst cases).
STATUSES = ("ok", "zero", "store", "wrap", "div0", "invalid")
DEFAULT_PROFILE = "inovance"
_ALIASES = {"vendor": "inovance"}

#: Integers whose status and value are functions of the raw firmware inputs alone.
RAW_ONLY_NAMES = frozenset(f"vendor.{name}" for name in VENDOR_RESULTS)
_PI_NAMES = tuple(f"current_pi.{axis}.{k}" for axis in ("d", "q") for k in ("pm_kp", "pm_ki"))
#: The integers of the seed's Inovance code, by report path.
INOVANCE_NAMES = tuple(f"vendor.{name}" for name in VENDOR_RESULTS) + _PI_NAMES


def profile_name(name: str | None) -> str:
    """The canonical profile name (``vendor`` and None mean ``inovance``)."""
    name = name or DEFAULT_PROFILE
    return _ALIASES.get(name, name)


def _state(value: int, ideal: float, flags) -> str:
    if "wrap" in flags:
        return "wrap"
    if "store" in flags:
        return "store"
    return "zero" if value == 0 and ideal != 0 else "ok"


def _computed(value: int, ideal: float, error_pct: float, flags) -> dict:
    return {"status": _state(value, ideal, flags), "value": value, "ideal": ideal,
            "error_pct": error_pct, "message": None, "message_zh": None}


def _failed(e: InputError) -> dict:
    status = "div0" if e.code == "firmware_div0" else "invalid"
    return {"status": status, "value": None, "ideal": None, "error_pct": None,
            "message": f"{e.field}: {e.message}", "message_zh": f"{e.field}: {e.message_zh}"}


def _pi_integers(n: dict, out: dict, names) -> None:
    try:
        pi = current_pi_section(n, input_bases(n))
    except InputError as e:  # damping design with kp ≤ 0, or an integer beyond int32
        out.update((name, _failed(e)) for name in names)
        return
    ts_s = n["drive"]["ts_s"]
    for name in names:
        _, axis, key = name.split(".")
        g = pi[axis]
        ideal = dict(zip(("pm_kp", "pm_ki"), pi_integer_ideals(g["kp_pu"], g["ki_pu"], ts_s)))[key]
        out[name] = _computed(g[key], ideal, 100.0 * (g[key] - ideal) / ideal, ())


_MEMO: dict = {}
_MEMO_SIZE = 20_000


def _vendor(name: str, raw: dict, unit: str) -> tuple:
    """(state, m_BaseL) of one vendor result, reused while the raw fields it reads repeat.

    A sweep over one input changes few raw fields; the other results (FreqPer when the
    current varies, …) are then computed once instead of at every point.
    """
    # LD and LQ run the same statements on their own raw field: one entry serves both.
    key = ("L" if name in ("LD", "LQ") else name, unit) + tuple(raw[k] for k in VENDOR_READS[name])
    hit = _MEMO.get(key)
    if hit is not None:
        return hit
    try:
        r = VENDOR_RESULTS[name](raw, unit)
        state = _computed(r["value"], r["ideal"], r["error_pct"], r["flags"])
        hit = state, r["trace"][1]["value"] if name in ("LD", "LQ") else None
    except InputError as e:
        hit = _failed(e), None
    if len(_MEMO) >= _MEMO_SIZE:
        _MEMO.clear()
    _MEMO[key] = hit
    return hit


def _inovance(inp: dict, only) -> dict:
    n = normalize(inp)
    raw = input_raw(n)
    unit = n["conventions"]["inductance_unit"]
    names = INOVANCE_NAMES if only is None else only
    out: dict = {}
    base_l = None
    for name in names:
        if name.startswith("vendor."):
            state, m_base_l = _vendor(name[7:], raw, unit)
            out[name] = dict(state)  # the memo keeps its own
            if name == "vendor.LD":
                base_l = m_base_l
    pi_names = [name for name in names if name in _PI_NAMES]
    if pi_names:
        _pi_integers(n, out, pi_names)
    inter = {}
    if "vendor.LD" in out:
        ld = out["vendor.LD"]
        # m_BaseL (seed 1.4-3, 1.4-15) is the step where the inductance resolution goes.
        inter["m_BaseL"] = (base_l if ld["value"] is not None
                            else 0 if "m_BaseL" in ld["message"] else None)
    return {"integers": out, "raw": raw, "intermediates": inter, "inductance_unit": unit,
            "raw_sources": {k: RAW_SCALE[k][0] for k in raw if k not in n["raw"]}}


def _from_report(inp: dict, profile: str, only) -> dict:
    # Profiles are computed only when the input asks (a "profiles" section).
    r = report({**inp, "profiles": inp.get("profiles") or {}})
    constants = r.get("profiles", {}).get(profile, {}).get("constants")
    if constants is None:
        raise InputError("sweep.profile", code="unknown_profile", got=shown(profile))
    out = {}
    for key, c in constants.items():
        name = f"profiles.{profile}.constants.{key}"
        if only is None or name in only:
            out[name] = _computed(c["value"], c["ideal"], c["error_pct"], c.get("flags", ()))
    return {"integers": out, "raw": r["vendor"]["raw"], "intermediates": {},
            "inductance_unit": r["input"]["conventions"]["inductance_unit"], "raw_sources": {}}


def evaluate(inp: dict, profile: str | None = None, only=None) -> dict:
    """Every firmware integer of ``profile`` for one report input.

    Parameters
    ----------
    inp : dict
        A report input (docs/contract.md).
    profile : str, optional
        ``inovance`` (default; alias ``vendor``) or a name under the report's ``profiles``.
    only : sequence of str, optional
        Compute only these integers (report paths); the input is still checked whole.

    Returns
    -------
    dict
        ``integers``: {path: {status, value, ideal, error_pct, message, message_zh}} (value,
        ideal and error_pct are None for ``div0`` and ``invalid``; message is
        ``field: message`` then, message_zh the same in Chinese);
        ``raw``: the raw firmware inputs; ``intermediates``: ``m_BaseL`` for inovance;
        ``inductance_unit``; ``raw_sources``: {raw field: the SI input path it was converted
        from} (fields given directly in ``raw`` are left out).

    Raises
    ------
    pulab.InputError
        When the input itself is invalid (the point is outside the family).
    """
    profile = profile_name(profile)
    if profile == "inovance":
        return _inovance(inp, only)
    return _from_report(inp, profile, only)


def integer_names(inp: dict, profile: str | None = None) -> tuple:
    """The integer names of ``profile`` (report paths), in report order.

    >>> integer_names({})[:2]
    ('vendor.Rpm', 'vendor.LD')
    """
    profile = profile_name(profile)
    if profile == "inovance":
        return INOVANCE_NAMES
    return tuple(_from_report(inp, profile, None)["integers"])
