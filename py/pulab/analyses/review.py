"""The graded design review: every finding with a severity, the value concerned and what to change.

Severities: ``error`` (the firmware computes a wrong number or the drive cannot work
as designed), ``warning`` (works, but an experienced engineer would change it),
``note`` (worth knowing).  The thresholds are data (:data:`THRESHOLDS`), stated in
docs/contract.md, so the text and the test use the same numbers.

Checks:

- each firmware constant (``vendor.*``): the C code's error against the exact value
  from the same raw integers (seed 1.4, 2.2); any wrap or Uint16 store change is an error;
- each raw integer converted from SI: the rounding to the firmware unit;
- the current-PI integers pm_kp (Q12), pm_ki (Q16): their rounding (seed 2.2-9);
- the current loop's phase margin with the loop delay (the firmware gains, the loop
  analysis' discrete model and its delay-aware design for the advice);
- f_b against the rated frequency, compared on the firmware integers FullFreq01 and
  FreqRated01 (what FreqPer is computed from), not on the typed floats;
- voltage headroom: back-EMF at f_b, and R·I and ω·L·I at rated current, against the
  firmware's voltage limit pm_maxout_vol (seed 2.2-1);
- with a PLL simulation: lock and the angle error after lock (pulab.analyses.sim.metrics);
- with a current-loop simulation: wraps and saturations of the shipped firmware's integer
  current PI (``sim.current.by_profile``; Inovance's run does not count them).

Examples
--------
>>> grade(0.05, THRESHOLDS["quantization_pct"]), grade(-1.5, THRESHOLDS["quantization_pct"])
(None, 'warning')
"""

from __future__ import annotations

import math

from ..schema.catalog import render
from ..schema.errors import InputError
from ..schema import vendors
from ..schema.fields import FIELDS
from ..profiles.inovance.code import RAW_FIELDS, raw_source

__all__ = ["THRESHOLDS", "SEVERITIES", "grade", "review", "headroom"]

SQRT3 = math.sqrt(3.0)
SQRT2 = math.sqrt(2.0)

SEVERITIES = ("error", "warning", "note")
#: The form label (en, zh) of each input a finding may point at (the vendors' options:
#: :func:`_label`).
_LABELS = {fd.path: fd.label for fd in FIELDS if fd.label[0]}
#: The SI unit of each input (what a finding's text prints a value in).
_UNITS = {fd.path: fd.unit for fd in FIELDS}
#: The design choice behind what only the vendor's code decides: which firmware to ship.
_FIRMWARE = "conventions.firmware"
#: Lower bounds of each severity (|value| ≥ bound); docs/contract.md "Design review".
THRESHOLDS = {
    # relative error of a raw integer or a PI integer (a rounding of the user's value), in %
    "quantization_pct": {"note": 0.1, "warning": 1.0, "error": 5.0},
    # relative error of a firmware constant against the exact value of the same raw integers,
    # in %: a property of the vendor's code, graded by what it costs
    "constant_pct": {"note": 0.1, "warning": 10.0, "error": 50.0},
    # phase margin of the current loop's firmware gains with the loop delay, degrees (below)
    "phase_margin_deg": {"warning": 45.0, "error": 20.0},
    # needed / available voltage (line RMS)
    # needed / available voltage (line RMS): a warning at the rated point or when the
    # back-EMF alone exceeds the limit below the rated frequency, a note above it
    "voltage_ratio": {"warning": 1.0},
    # PLL angle error after lock, degrees
    "pll_steady_deg": {"note": 0.5, "warning": 2.0},
    # spread of the back-EMF that a datasheet's Ke, Kv, kT, ψ imply, in % of the one used:
    # kT is often printed hot or at rated current and Ke cold (magnets lose about 0.1 %/K),
    # while a mixed-up convention is 41 % (RMS/peak) or 73 % (line/phase)
    "bemf_spread_pct": {"note": 0.0, "warning": 10.0, "error": 25.0},
}

#: For each firmware constant: the design choice that moves its quantization (None: only the
#: vendor's code does) and the catalog entry saying what it costs.
_CONSTANT_COST = {"Rpm": (None, "cost.rpm"), "LD": ("drive.base_freq_hz", "cost.inductance"),
                  "LQ": ("drive.base_freq_hz", "cost.inductance"),
                  "FreqPer": ("drive.base_freq_hz", "cost.freq"),
                  "FluxRotor": ("drive.base_freq_hz", "cost.freq"),
                  "pm_maxout_vol": ("drive.udc_v", "cost.voltage"),
                  "maxu": ("drive.udc_v", "cost.voltage")}


def grade(value: float, bounds: dict) -> str | None:
    """The severity whose bound |value| reaches (the most severe), or None."""
    for sev in SEVERITIES:
        if sev in bounds and abs(value) >= bounds[sev]:
            return sev
    return None


def _label(field: str) -> tuple:
    """The form label (en, zh) of ``field``, a vendor's option too; empty when it has none."""
    if field in _LABELS:
        return _LABELS[field]
    option = vendors.option_field(field)
    return option.label if option is not None else ("", "")


def _finding(out: list, severity: str | None, code: str, key: str, field: str,
             value, text: str | None = None, /, **params) -> None:
    """Add a finding; its words are catalog entry ``finding.<text or code>`` with ``params``."""
    if severity is None:
        return
    entry = f"finding.{text or code}"
    label = _label(field)
    params = {**params, "label": label[0] or field}
    params_zh = {**params, "label": label[1] or field}
    out.append({"severity": severity, "code": code, "key": key, "field": field,
                "label": label[0] or field, "label_zh": label[1] or field,
                "value": value, "message": render(entry, params, "en"),
                "message_zh": render(entry, params_zh, "zh")})


def headroom(n: dict, vendor: dict) -> dict:
    """Voltage needed at rated current against the firmware's voltage limit (line RMS, V).

    Steady state with i_d = 0 and i_q = I_n (RMS phase quantities, seed 1.2-3):
    u_q = R·I + ω·ψ, u_d = −ω·L_q·I, U_LL = √3·|u|, with ψ = E_LL/(√3·ω_n) (RMS).

    Parameters
    ----------
    n : dict — normalized input
    vendor : dict — vendor results (``pm_maxout_vol.si`` is the limit, V line RMS)

    Returns
    -------
    dict
        ``limit_v`` (pm_maxout_vol in V line RMS), ``udc_limit_v`` (U_dc/√2, before the
        firmware's truncation), ``bemf_fb_v`` (back-EMF at f_b), ``need_rated_fn_v`` and
        ``need_rated_fb_v`` (at rated current, rated frequency and f_b),
        ``field_weakening_from_hz`` (frequency where the back-EMF alone reaches the limit,
        null when not below f_b), ``field_weakening`` (bool: needed below f_b at rated
        current).

    Examples
    --------
    >>> n = {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
    ...      "rs_ohm": 1.39, "lq_h": 0.00253, "bemf_v": 110}, "drive": {"base_freq_hz": 400,
    ...      "udc_v": 311}}
    >>> h = headroom(n, {"pm_maxout_vol": {"si": 219.0}})
    >>> round(h["bemf_fb_v"], 1), round(h["field_weakening_from_hz"], 1), h["field_weakening"]
    (220.0, 398.2, True)
    """
    m, d = n["motor"], n["drive"]
    psi = m["bemf_v"] / (SQRT3 * 2.0 * math.pi * m["rated_freq_hz"])
    i = m["rated_current_a"]

    def need(f: float) -> float:
        w = 2.0 * math.pi * f
        return SQRT3 * math.hypot(m["rs_ohm"] * i + w * psi, w * m["lq_h"] * i)

    # Inovance's own limit when it is the firmware shipped and holds this drive; else the
    # physical one, U_dc/√2.
    inovance = n.get("conventions", {}).get("firmware", "inovance") == "inovance"
    limit = vendor["pm_maxout_vol"]["si"] if inovance and "pm_maxout_vol" in vendor \
        else d["udc_v"] / SQRT2
    f_b = d["base_freq_hz"]
    bemf_fb = m["bemf_v"] * f_b / m["rated_freq_hz"]
    f_fw = limit / m["bemf_v"] * m["rated_freq_hz"]
    return {"limit_v": limit, "udc_limit_v": d["udc_v"] / SQRT2, "bemf_fb_v": bemf_fb,
            "need_rated_fn_v": need(m["rated_freq_hz"]), "need_rated_fb_v": need(f_b),
            "field_weakening_from_hz": f_fw if f_fw < f_b else None,
            "field_weakening": need(f_b) > limit}


def _constants(f: list, vendor: dict, unit: str) -> None:
    q = THRESHOLDS["constant_pct"]
    for name, res in vendor.items():
        if name == "raw":
            continue
        key = f"vendor.{name}.value"
        field, cost = _CONSTANT_COST[name]
        if "unit_uH" in res["flags"]:
            field = "conventions.inductance_unit"
        if {"wrap", "store"} & set(res["flags"]):
            _finding(f, "error", "constant_wrap", key, field or _FIRMWARE, res["value"],
                     name=name, value=res["value"], ideal=res["ideal"],
                     why={"code": cost, "params": {"pct": res["error_pct"]}})
        else:
            _finding(f, grade(res["error_pct"], q), "constant_error", key, field or _FIRMWARE,
                     res["error_pct"], name=name, value=res["value"], pct=res["error_pct"],
                     ideal=res["ideal"], why={"code": cost, "params": {"pct": res["error_pct"]}})


def _raw_rounding(f: list, n: dict, raw: dict) -> None:
    """Inovance's parameter units: the motor's values are not design choices, so the
    finding points at the inductance unit (LD/LQ in 10 µH) or at the firmware profile.
    Graded only when Inovance is shipped; else a note naming it, as another firmware's limits."""
    unit = n["conventions"]["inductance_unit"]
    shipped = n["conventions"]["firmware"] == "inovance"
    for name in RAW_FIELDS:
        if name in n["raw"] or name not in raw:  # typed, or beyond the firmware: firmware.*
            continue
        path, scale = raw_source(name, unit)
        section, key = path.split(".")
        si = n[section][key]
        si_unit = _UNITS[path]
        exact = si * scale
        finer = name in ("LD", "LQ") and unit == "10uH"
        field = "conventions.inductance_unit" if finer else _FIRMWARE
        count = "1 µH" if name in ("LD", "LQ") and unit == "uH" else _PARAMETER_UNITS[name]
        fix = {"code": "fix.inductance_unit" if finer else "fix.parameter_unit",
               "params": {"unit": count}}
        if not shipped:
            field = _FIRMWARE
            fix = {"code": "fix.parameter_unit_unshipped",
                   "params": {"unit": count, "vendor": {"vendor": "inovance"},
                              "shipped": {"vendor": n["conventions"]["firmware"]}}}
        if raw[name] == 0:
            _finding(f, "error" if shipped else "note", "raw_zero", f"vendor.raw.{name}", field, 0, name=name,
                     path={"label": path}, si=si, si_unit=si_unit, fix=fix)
            continue
        pct = 100.0 * (raw[name] - exact) / exact
        sev = grade(pct, THRESHOLDS["quantization_pct"])
        _finding(f, sev if shipped or sev is None else "note", "raw_rounding",
                 f"vendor.raw.{name}", field, pct, name=name, value=raw[name], path={"label": path},
                 si=si, si_unit=si_unit, pct=pct, fix=fix)


def _bemf_check(f: list, n: dict) -> None:
    """Several of Ke, Kv, kT, ψ on one datasheet: how far apart their back-EMFs are."""
    check = n.get("datasheet", {}).get("bemf_check")
    if check is None:
        return
    spread = check["spread_pct"]
    sev = grade(spread, THRESHOLDS["bemf_spread_pct"])
    listed = ", ".join(f"{_SYMBOLS[s['field']]} {s['bemf_v']:.4g} V" for s in check["sources"])
    _finding(f, sev, "bemf_spread", "datasheet.bemf_check.spread_pct", "datasheet.bemf_from",
             spread, spread=spread, rpm=check["rated_speed_rpm"], listed=listed,
             used=_SYMBOLS[check["used"]],
             why={"code": f"bemf_spread.{sev}", "params": {}})


#: Each Inovance raw parameter's unit (one count).
_PARAMETER_UNITS = {"Voltage": "1 V", "Current": "0.01 A", "FullFreq01": "0.01 Hz",
                    "FreqRated01": "0.01 Hz", "RsPm": "1 mΩ", "LD": "0.01 mH", "LQ": "0.01 mH",
                    "BemfVolt": "0.1 V", "uDCFilter": "0.1 V"}
#: The symbol a datasheet prints for each back-EMF source (the same in both languages).
_SYMBOLS = {"datasheet.ke_v_per_krpm": "Ke", "datasheet.ke_v_s_per_rad": "Ke",
            "datasheet.kv_rpm_per_v": "Kv", "datasheet.kt_nm_per_a": "kT",
            "datasheet.psi_wb": "ψ"}


def _pi(f: list, n: dict, pi: dict) -> None:
    loop = n["current_loop"]
    field = "current_loop.pm_ki" if loop["method"] == "integers" else "drive.ts_s"
    for axis in ("d", "q"):
        g = pi[axis]
        if g["pm_ki"] == 0:
            _finding(f, "error", "pi_zero", f"current_pi.{axis}.pm_ki", field, 0, axis=axis)
        for k in ("kp", "ki"):
            if g[f"pm_{k}"] == 0 or loop["method"] == "integers":
                continue  # given integers are exact by definition
            pct = 100.0 * (g["from_integers"][k] - g[k]) / g[k]
            _finding(f, grade(pct, THRESHOLDS["quantization_pct"]), "pi_rounding",
                     f"current_pi.{axis}.pm_{k}", "current_loop.bandwidth_hz", pct, axis=axis,
                     k=k, value=g[f"pm_{k}"], pct=pct)


def _phase_margin(f: list, n: dict, pi: dict) -> None:
    """The current loop's firmware gains with the loop delay: the same discrete model and
    delay-aware design as the loop analysis (:mod:`pulab.analyses.loop.current`)."""
    from .loop import current as _current  # the review's only loop computation
    m, ts = n["motor"], n["drive"]["ts_s"]
    analysis = n.get("analysis") or {}
    delay = analysis.get("delay", "computation_pwm")
    target = analysis.get("target_phase_margin_deg", 60.0)
    worst = None
    for axis, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        back = pi[axis]["from_integers"]
        if back["kp"] <= 0:
            continue  # pm_kp rounds to 0: pi_rounding says so
        mg = _current.axis_loop(m["rs_ohm"], l_h, ts, back["kp"], back["ki"], delay)
        pm = mg["phase_margin_deg"] if mg["stable"] else -math.inf
        if pm is not None and (worst is None or pm < worst[1]):
            worst = (axis, pm, l_h)
    limit = THRESHOLDS["phase_margin_deg"]
    if worst is None or worst[1] >= limit["warning"]:
        return
    axis, pm, l_h = worst
    method = n["current_loop"]["method"]
    field = {"bandwidth": "current_loop.bandwidth_hz", "damping": "current_loop.bandwidth_hz",
             "manual": "current_loop.kp", "integers": "current_loop.pm_kp"}[method]
    sev = "error" if pm < limit["error"] else "warning"
    text = "phase_margin_unstable" if math.isinf(pm) else "phase_margin"
    try:
        kp, ki = _current.design(m["rs_ohm"], l_h, ts, delay, "phase_margin", target)
        fix = {"code": "finding.phase_margin_fix", "params": {
            "target": target, "ok_hz": kp / (2.0 * math.pi * l_h), "kp": kp, "ki": ki}}
    except (InputError, ArithmeticError):
        # No gain reaches the target (or the plant's pole underflows): say what to lower.
        fix = {"code": "finding.phase_margin_lower", "params": {}}
    _finding(f, sev, "phase_margin", f"current_pi.{axis}.pm_kp", field,
             None if math.isinf(pm) else pm, text, axis=axis, pm=pm, limit=limit["warning"],
             delay=delay, fix=fix)


def _base_frequency(f: list, raw: dict) -> None:
    # On the integers the firmware divides (FreqPer = FreqRated01·2^15/FullFreq01), so a
    # typed 633.33 Hz vs 633.333 Hz that both store 63333 is no finding.
    if {"FullFreq01", "FreqRated01"} <= raw.keys() and raw["FullFreq01"] < raw["FreqRated01"]:
        _finding(f, "warning", "base_below_rated", "vendor.FreqPer.value", "drive.base_freq_hz",
                 raw["FullFreq01"], full=raw["FullFreq01"], rated=raw["FreqRated01"])


def _voltage(f: list, h: dict, n: dict) -> None:
    lim = h["limit_v"]
    f_b = n["drive"]["base_freq_hz"]

    def ratio(need: float) -> float | None:
        # A zero limit (U_dc below the firmware's resolution) exceeds any need: no finite ratio.
        return need / lim if lim > 0 else None

    if lim <= 0 or ratio(h["need_rated_fn_v"]) > THRESHOLDS["voltage_ratio"]["warning"]:
        # Above U_dc/√2 no firmware reaches the rated point; above only the firmware's
        # truncated limit it is the vendor code that costs the difference.
        physical = h["need_rated_fn_v"] > h["udc_limit_v"]
        _finding(f, "warning" if physical else "note", "voltage_rated",
                 "review.headroom.need_rated_fn_v", "drive.udc_v", ratio(h["need_rated_fn_v"]),
                 None if physical else "voltage_rated_firmware", need=h["need_rated_fn_v"],
                 limit=lim, udc_limit=h["udc_limit_v"])
    if h["field_weakening_from_hz"] is not None:
        # Above the rated frequency, field weakening is the usual constant-power range;
        # below it the motor cannot reach its rated speed without it.
        below_rated = h["field_weakening_from_hz"] < n["motor"]["rated_freq_hz"]
        _finding(f, "warning" if below_rated else "note", "voltage_bemf", "review.headroom.bemf_fb_v", "drive.base_freq_hz",
                 ratio(h["bemf_fb_v"]), f_b=f_b, bemf=h["bemf_fb_v"], limit=lim,
                 from_hz=h["field_weakening_from_hz"])
    elif h["field_weakening"]:
        _finding(f, "note", "voltage_fb", "review.headroom.need_rated_fb_v", "drive.base_freq_hz",
                 ratio(h["need_rated_fb_v"]), f_b=f_b, need=h["need_rated_fb_v"], limit=lim)


def _pll(f: list, sim: dict | None) -> None:
    if not sim or "pll" not in sim:
        return
    for variant in ("q15", "pu", "si"):
        m = sim["pll"]["metrics"].get(variant)
        if m is None:
            continue
        key = f"sim.pll.metrics.{variant}"
        if not m["locked"]:
            _finding(f, "error", "pll_unlocked", f"{key}.locked", "pll.bandwidth_hz", False,
                     key=key)
        elif m.get("steady_angle_error_deg") is not None:
            x = m["steady_angle_error_deg"]
            _finding(f, grade(x, THRESHOLDS["pll_steady_deg"]), "pll_steady",
                     f"{key}.steady_angle_error_deg", "pll.bandwidth_hz", x, key=key, value=x)
        return  # the firmware's variant when present, else the next one


def _pi_arithmetic(f: list, sim: dict | None, shipped: str, vendor: dict) -> None:
    """The shipped firmware's integer current PI in the simulated step: a wrap gives a wrong
    voltage (error), a saturating operation that clipped loses the value (warning); the
    designed output and integral limits are not findings."""
    cur = (sim or {}).get("current", {})
    wraps = cur.get("metrics", {}).get("fixed_wraps") if shipped == "inovance" else None
    if wraps:
        key = "sim.current.metrics.fixed_wraps"
        # A maxu that wrapped in its own shift (a high bus over a low rated voltage) leaves
        # the integral no room: the bus is the input to change, not the bandwidth.
        field = "drive.udc_v" if "wrap" in vendor.get("maxu", {}).get("flags", ()) else \
            "current_loop.bandwidth_hz"
        _finding(f, "error", "pi_wrap", key, field, wraps, "pi_wrap_fixed",
                 count=wraps, key=key)
        return
    run = cur.get("by_profile", {}).get(shipped)
    if not run or not run["ran"]:
        return
    key = f"sim.current.by_profile.{shipped}.events"
    for event, severity in (("wrap", "error"), ("saturate", "warning")):
        count = run["events"][event]
        if count:
            _finding(f, severity, f"pi_{event}", f"{key}.{event}", "current_loop.bandwidth_hz",
                     count, profile={"vendor": shipped}, count=count, key=key)


def _robust(f: list, loop: dict | None) -> None:
    """The nominal gains lose a margin on the hot, saturated or low-bus motor: a warning whose
    remedy is the designed bandwidth (the safe band is in the message)."""
    if not loop or loop.get("robust") is None:
        return
    from .loop.robust import losses
    for name, value, params in losses(loop["robust"]):
        _finding(f, "warning", "robust_margin", f"loop.robust.{name}", "current_loop.bandwidth_hz",
                 value, **params)


def _firmware(f: list, firmware: dict, shipped: str) -> None:
    """A firmware that cannot hold the motor: a warning for the one shipped, a note for others."""
    for name, st in firmware.items():
        if st["representable"]:
            continue
        p = st["problems"]
        results = sorted({r for x in p for r in x["results"]})
        # a raw input or a division the code cannot do: integers missing; else words too small
        missing = any(x["code"].startswith("limit.") for x in p)
        # words too small: the advice rescales them by the profile's options, so the link goes
        # to the first of those on the vendors panel
        scales = [] if missing else p[0]["params"]["option_labels"]
        field = scales[0]["label"] if isinstance(scales, list) and scales else _FIRMWARE
        _finding(f, "warning" if name == shipped else "note", "unrepresentable",
                 f"firmware.{name}", field, name,
                 None if missing else "unrepresentable_constants",
                 profile=name, profile_name={"vendor": name},
                 # the firmware's own parameter names (FullFreq01 …), not JSON paths
                 fields=", ".join(x["field"].rsplit(".", 1)[-1] for x in p),
                 results=", ".join(results), advice={"code": p[0]["code"] + "_advice"
                 if p[0]["code"].startswith("limit.") else "limit.constant_advice",
                 "params": p[0]["params"]})


#: Limits of the board's findings (echoed in ``review.thresholds.board`` when a board is given).
BOARD_THRESHOLDS = {
    # rated peak current / largest measurable current: below it resolution is lost; at or
    # above 1 the ADC clips
    "adc_use": {"warning": 0.25, "error": 1.0},
    # the fit a suggested gain aims at (share of the measurable current)
    "adc_fit": 0.8,
    # dead-time voltage error / the voltage needed at 10 % rated speed and rated current
    "deadtime_share": {"warning": 0.2},
    # duty-cycle resolution, bits
    "duty_bits": {"warning": 10.0},
}


def _board(f: list, n: dict, board: dict | None, psi_peak: float | None = None) -> None:
    """The board's chain against the motor: the ADC range, the dead time, the PWM.

    ``psi_peak``: the stator flux (Wb, phase peak) the dead time's share is judged against;
    None: the PMSM's, from ``motor.bemf_v``."""
    if not board:
        return
    m = n["motor"]
    peak = math.sqrt(2.0) * m["rated_current_a"]
    lim = BOARD_THRESHOLDS
    c, given = board["current"], n["board"].get("current") or {}
    if c is not None:
        use = peak / c["max_a"]
        field = ("board.current.max_a" if c["from"] == "max_a" else
                 "board.current.sensitivity_v_per_a" if given.get("sensitivity_v_per_a") else
                 "board.current.gain")
        if use >= lim["adc_use"]["error"]:
            _finding(f, "error", "board_adc_clip", "board.current.max_a", field, use,
                     peak=peak, max_a=c["max_a"], pct=100.0 * use)
        elif use < lim["adc_use"]["warning"]:
            scale = lim["adc_fit"] / use    # what multiplies the chain's sensitivity
            if field == "board.current.gain":
                fit = f"{given.get('gain') or 1.0:.4g} → {(given.get('gain') or 1.0) * scale:.4g} V/V"
            elif field == "board.current.sensitivity_v_per_a":
                fit = f"{c['sensitivity_v_per_a']:.4g} → {c['sensitivity_v_per_a'] * scale:.4g} V/A"
            else:
                fit = f"±{c['max_a']:.4g} → ±{c['max_a'] / scale:.4g} A"
            _finding(f, "warning", "board_adc_low", "board.current.max_a", field, use,
                     peak=peak, max_a=c["max_a"], pct=100.0 * use, fit=fit,
                     fit_pct=100.0 * lim["adc_fit"])
    p = board["pwm"]
    if p is None:
        return
    if p["deadtime_error_v"] is not None:
        psi = psi_peak if psi_peak is not None else \
            m["bemf_v"] * math.sqrt(2.0 / 3.0) / (2.0 * math.pi * m["rated_freq_hz"])
        need = m["rs_ohm"] * peak + 0.1 * 2.0 * math.pi * m["rated_freq_hz"] * psi
        share = p["deadtime_error_v"] / need
        if share > lim["deadtime_share"]["warning"]:
            _finding(f, "warning", "board_deadtime", "board.pwm.deadtime_error_v",
                     "board.pwm.deadtime_s", share, err=p["deadtime_error_v"], need=need,
                     pct=100.0 * share)
    if p["duty_bits"] is not None and p["duty_bits"] < lim["duty_bits"]["warning"]:
        _finding(f, "warning", "board_duty_bits", "board.pwm.duty_bits", "board.pwm.freq_hz",
                 p["duty_bits"], bits=p["duty_bits"], steps=2.0 ** p["duty_bits"])
    ts = n["drive"]["ts_s"]
    if abs(p["control_period_s"] - ts) > 1e-6 * ts:
        _finding(f, "warning", "board_ts", "board.pwm.control_period_s",
                 "board.pwm.periods_per_control", p["control_period_s"],
                 period=p["control_period_s"], ts=ts)


def _fw(f: list, n: dict, fw: dict | None) -> None:
    """Above base speed: the rated point beyond it, a range drawn beyond the maximum speed, a
    stored table too coarse."""
    if not fw:
        return
    m = n["motor"]
    rated_rpm = m["rated_freq_hz"] * 60.0 / m["pole_pairs"]
    if rated_rpm > fw["base_speed_rpm"] * (1.0 + 1e-9):
        _finding(f, "warning", "fw_rated_beyond_base", "fw.base_speed_rpm", "drive.udc_v",
                 fw["base_speed_rpm"], rated=rated_rpm, base=fw["base_speed_rpm"])
    top, given = fw["max_speed_rpm"], (n.get("analysis") or {}).get("fw") or {}
    if top is not None and given.get("speed_max_rpm") is not None and given["speed_max_rpm"] > top:
        _finding(f, "warning", "fw_beyond_max", "fw.max_speed_rpm", "analysis.fw.speed_max_rpm",
                 top, want=given["speed_max_rpm"], top=top)
    # only the tables whose size analysis.fw.table_points sets (a vendor's has its own)
    for name in ("mtpa_id_of_iq", "fw_id_of_speed", "generic", "generic_fw"):
        t = fw["tables"].get(name)
        if t is not None and t["error_bound"] > 0.01 * fw["current_limit_a"]:
            _finding(f, "note", "fw_table_coarse", f"fw.tables.{name}.error_bound",
                     "analysis.fw.table_points", t["error_bound"], table=name,
                     err=t["error_bound"], pct=100.0 * t["error_bound"] / fw["current_limit_a"],
                     n=len(t["values"]))


def _observer(f: list, obs: dict | None) -> None:
    """Sensorless: an unstable observer loop, a merge below the minimum, speeds the budget says
    the observer cannot see."""
    if not obs:
        return
    s, bud = obs["settings"], obs["budget"]
    for name, field in (("bemf", "observer.bemf_f0_hz"), ("tracking", "observer.tracking_f0_hz")):
        if not obs["design"][name]["stable"]:
            _finding(f, "error", "observer_unstable", f"observer.design.{name}.spectral_radius",
                     field, obs["design"][name]["spectral_radius"],
                     radius=obs["design"][name]["spectral_radius"])
    if s["merging_speed_rpm"] < s["min_speed_rpm"]:
        _finding(f, "warning", "observer_merge_below_min", "observer.settings.merging_speed_rpm",
                 "observer.merging_speed_rpm", s["merging_speed_rpm"],
                 merge=s["merging_speed_rpm"], low=s["min_speed_rpm"])
    low = bud["min_speed_rpm"]
    if low is None:
        _finding(f, "warning", "observer_no_speed", "observer.budget.min_speed_rpm",
                 "observer.snr_min", None, snr=s["snr_min"])
        return
    for key in ("min_speed_rpm", "merging_speed_rpm"):
        if s[key] < low:
            _finding(f, "warning", "observer_below_budget", "observer.budget.min_speed_rpm",
                     f"observer.{key}", low, want=s[key], low=low, snr=s["snr_min"])


def review(n: dict, raw: dict, vendor: dict, pi: dict, sim: dict | None = None,
           loop: dict | None = None, firmware: dict | None = None,
           board: dict | None = None, fw: dict | None = None,
           observer: dict | None = None) -> dict:
    """All findings for one report, most severe first.

    Parameters
    ----------
    n : dict — normalized input ; raw : dict — raw integers used
    vendor : dict — vendor results ; pi : dict — ``current_pi``
    sim : dict or None — the ``sim`` output, for the PLL and integer-PI checks
    loop : dict or None — the ``loop`` output, for the robustness check
    firmware : dict or None — the ``firmware`` output: one finding per firmware that cannot
        hold this motor
    board : dict or None — the ``board`` output: the ADC range, dead time and PWM checks
    fw : dict or None — the ``fw`` output: base and maximum speed, the tables' error bounds
    observer : dict or None — the ``observer`` output: its loops' stability, the merging and
        lowest speeds against the budget's lowest sensorless speed

    Returns
    -------
    dict
        ``findings`` (list of ``{severity, code, key, field, value, message,
        message_zh}``; ``key`` is the report path of the value concerned, ``field`` the
        input to change), ``counts`` per severity, ``thresholds``, ``headroom``.
    """
    f: list = []
    unit = n["conventions"]["inductance_unit"]
    _constants(f, vendor, unit)
    _raw_rounding(f, n, raw)
    _bemf_check(f, n)
    _pi(f, n, pi)
    _phase_margin(f, n, pi)
    _base_frequency(f, raw)
    h = headroom(n, vendor)
    _voltage(f, h, n)
    _pll(f, sim)
    _pi_arithmetic(f, sim, n["conventions"]["firmware"], vendor)
    _robust(f, loop)
    _firmware(f, firmware or {}, n["conventions"]["firmware"])
    _board(f, n, board)
    _fw(f, n, fw)
    _observer(f, observer)
    if unit == "uH":
        _finding(f, "note", "unit_uH", "vendor.LD.value", "conventions.inductance_unit", unit)
    if n["conventions"]["base"] == "custom":
        _finding(f, "note", "custom_bases", "base.U_b", "conventions.base", "custom")
    f.sort(key=lambda x: SEVERITIES.index(x["severity"]))
    return {"findings": f, "counts": {s: sum(x["severity"] == s for x in f) for s in SEVERITIES},
            "thresholds": {**THRESHOLDS, "board": BOARD_THRESHOLDS} if board else THRESHOLDS,
            "headroom": h}
