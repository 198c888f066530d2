"""Loop design as firmware runs it: discrete margins, delays, PLL, speed loop.

Pure standard library (runs in a bare Pyodide).  When the input has an
``"analysis"`` object (``{}`` = every default), :func:`pulab.report` calls
:func:`analyze` on the finished report; the output is the report's ``"loop"``
section (docs/contract.md, "Loop analysis").

Modules, one concept each:

- :mod:`.polynomial` — real polynomials and their roots (Aberth);
- :mod:`.discrete` — margins, crossovers, bandwidth, poles, Bode of L(z);
- :mod:`.pi` — the firmware PI as C(z);
- :mod:`.current` — current-loop plant with delays, design with the delay;
- :mod:`.pll` — scaled and naive PLL loops;
- :mod:`.speed` — mechanical bases, speed PI in SI/pu/Q format, its margins;
- :mod:`.speed_response` — speed step and load step, float and fixed point;
- :mod:`.robust` — margins of the nominal gains on a drifted plant (temperature,
  saturation, bus, tolerances), the safe bandwidth band;
- :mod:`.inputs` — validation and defaults.

Examples
--------
>>> from pulab import report
>>> r = report({"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5,
...     "rated_freq_hz": 220, "rs_ohm": 1.5, "ld_h": 6e-4, "lq_h": 6e-4,
...     "bemf_v": 12, "pole_pairs": 4}, "drive": {"udc_v": 24, "ts_s": 1e-4},
...     "analysis": {}})
>>> round(r["loop"]["current"]["d"]["phase_margin_deg"], 2)
55.15
>>> r["loop"]["pll"]["naive"]["gain_margin_db"] < 0
True
"""

from __future__ import annotations

import math

from ...schema.errors import InputError
from ...model.gains import current_pi
from . import current as _current
from . import pll as _pll
from . import robust as _robust
from . import speed as _speed
from .discrete import bode, curve, forget, log_frequencies, unit_circle, values
from .inputs import validate

__all__ = ["validate", "analyze", "warnings", "BODE_POINTS"]

#: Frequency points per Bode plot.
BODE_POINTS = 400


def _current_axis(report: dict, cfg: dict, axis: str, l_h: float) -> dict:
    m, ts = report["input"]["motor"], report["input"]["drive"]["ts_s"]
    g = report["current_pi"][axis]
    out = {"kp": g["kp"], "ki": g["ki"],
           **_current.axis_loop(m["rs_ohm"], l_h, ts, g["kp"], g["ki"], cfg["delay"])}
    back = g["from_integers"]
    out["firmware"] = {"pm_kp": g["pm_kp"], "pm_ki": g["pm_ki"], "kp": back["kp"],
                       "ki": back["ki"],
                       **_current.axis_loop(m["rs_ohm"], l_h, ts, back["kp"], back["ki"],
                                            cfg["delay"])}
    return out


def _design_axis(report: dict, cfg: dict, l_h: float, target: float) -> dict:
    m, ts, b = report["input"]["motor"], report["input"]["drive"]["ts_s"], report["base"]
    rs, delay, by = m["rs_ohm"], cfg["delay"], cfg["design"]
    kp, ki = _current.design(rs, l_h, ts, delay, by, target)
    g = current_pi(kp, ki, l_h, b["U_b"], b["I_b"], ts)
    out = {k: g[k] for k in ("kp", "ki", "kp_pu", "ki_pu", "pm_kp", "pm_ki")}
    out.update(_current.axis_loop(rs, l_h, ts, kp, ki, delay))
    back = g["from_integers"]
    out["firmware"] = _current.axis_loop(rs, l_h, ts, back["kp"], back["ki"], delay)
    if by == "bandwidth":
        w_c = 2.0 * math.pi * target
    else:
        w_c = math.radians(90.0 - target) / _current.dead_time(ts, delay)
    cont = {"kp": w_c * l_h, "ki": w_c * rs, "crossover_hz_design": w_c / (2.0 * math.pi),
            **_current.axis_loop(rs, l_h, ts, w_c * l_h, w_c * rs, delay)}
    pm, bw = cont["phase_margin_deg"], cont["bandwidth_hz"]
    cont["phase_margin_error_deg"] = pm - target if by == "phase_margin" and pm is not None \
        else None
    cont["bandwidth_error_pct"] = 100.0 * (bw - target) / target if by == "bandwidth" and \
        bw is not None else None
    out["continuous"] = cont
    return out


def _speed_config(report: dict, s: dict) -> dict:
    ts, i_b = report["input"]["drive"]["ts_s"], report["base"]["I_b"]
    s = dict(s)
    if s["ts_s"] is None:
        s["ts_s"] = 10.0 * ts
    ratio = s["ts_s"] / ts
    if abs(ratio - round(ratio)) > 1e-6 * ratio or not 1 <= round(ratio) <= 1000:
        raise InputError("analysis.speed.ts_s", code="speed_ts_multiple", ts=ts, ratio=ratio)
    s["ratio"] = int(round(ratio))
    s["ts_s"] = s["ratio"] * ts
    if s["filter_hz"] is None:
        s["filter_hz"] = 5.0 * s["bandwidth_hz"]
    if s["current_limit_a"] is None:
        s["current_limit_a"] = 2.0 * i_b
    if s["current_limit_a"] >= 8.0 * i_b:
        raise InputError("analysis.speed.current_limit_a", code="speed_limit_q12",
                         value=s["current_limit_a"], limit=8 * i_b)
    return s


def _speed_section(report: dict, s: dict, delay: str, current_bandwidth_hz: float | None) -> dict:
    b, m = report["base"], report["input"]["motor"]
    mech = _speed.mechanical_bases(m["pole_pairs"], b["w_b"], b["P_b"], b["U_b"], b["I_b"],
                                   report["pu"]["psi_r_wb"], s["inertia_kg_m2"])
    out = {"bases": mech,
           "friction_pu": s["friction_nm_s"] * mech["w_mb"] / mech["torque_nm"],
           "ts_s": s["ts_s"], "ratio": s["ratio"], "filter_hz": s["filter_hz"],
           "current_limit_a": s["current_limit_a"],
           **_speed.analyze(s, mech["kt_nm_per_a"], mech["w_mb"], b["I_b"])}
    out["inner_bandwidth_ratio"] = None
    if out["crossover_hz"] is not None and current_bandwidth_hz is not None:
        out["inner_bandwidth_ratio"] = current_bandwidth_hz / out["crossover_hz"]
    if s["response"]:
        from . import speed_response
        out["response"] = speed_response.run(report, s, out, mech, delay)
    return out


def _grid(ts: float, crossovers: list) -> list:
    nyquist = 0.5 / ts
    low = min([1e-3 * nyquist] + [0.01 * f for f in crossovers if f])
    return log_frequencies(low, nyquist, BODE_POINTS)


def _open_closed(samples: list) -> tuple:
    """Bode curves of L and of T = L/(1 + L) from the same samples of L."""
    return curve(samples), curve([v / (1.0 + v) for v in samples])


def _bode(report: dict, cfg: dict, out: dict) -> dict:
    m, ts = report["input"]["motor"], report["input"]["drive"]["ts_s"]
    cur = out["current"]
    f = _grid(ts, [cur[a]["crossover_hz"] for a in ("d", "q")] +
              [cur["design"][a]["crossover_hz"] for a in ("d", "q")])
    z = unit_circle(ts, f)
    # L = C·P: the plant is evaluated once per axis, the PI per gain set
    integrator = [1.0 / (x - 1.0) for x in z]
    current = {"f_hz": f, "open": {}, "closed": {}}
    done: dict = {}     # L_d = L_q: the q curves are the d curves (same numbers, computed once)
    for a, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        plant = None
        for name, g in ((a, cur[a]), (f"{a}_design", cur["design"][a])):
            kp, kits = g["kp"], g["ki"] * ts
            key = (l_h, kp, kits)
            if key not in done:
                if plant is None:
                    plant = values(*_current.plant(m["rs_ohm"], l_h, ts, cfg["delay"]), z)
                samples = [((kp + kits) * x - kp) * i * p for x, i, p in zip(z, integrator, plant)]
                done[key] = _open_closed(samples)
            current["open"][name], current["closed"][name] = done[key]
    p = report["pll"]
    g = report["base"]["w_b"] / report["base"]["theta_b"]
    fp = _grid(ts, [out["pll"]["correct"]["crossover_hz"]])
    pll = {"f_hz": fp, "open": {name: bode(*_pll.loop(p["kp"], p["ki"], ts, gain), ts, fp)
                                for name, gain in (("correct", 1.0), ("naive", g))}}
    result = {"current": current, "pll": pll}
    sp = out.get("speed")
    if sp is not None:
        s = cfg["speed"]
        fs = _grid(sp["ts_s"], [sp["crossover_hz"]])
        num, den = _speed.loop(sp["kp"], sp["ki"], sp["bases"]["kt_nm_per_a"],
                               s["inertia_kg_m2"], s["friction_nm_s"], sp["filter_hz"],
                               sp["ts_s"])
        o, c = _open_closed(values(num, den, unit_circle(sp["ts_s"], fs)))
        result["speed"] = {"f_hz": fs, "open": o, "closed": c}
    return result


def analyze(report: dict, analysis) -> dict:
    """The report's ``"loop"`` section.

    Parameters
    ----------
    report : dict
        Output of :func:`pulab.report` so far (``input``, ``base``, ``pu``,
        ``current_pi``, ``pll``).
    analysis : dict or None
        The ``"analysis"`` input (raw or already validated).

    Returns
    -------
    dict
        ``delay``, ``current`` (``d``, ``q``, ``design``), ``pll``, ``speed``
        (None unless asked) and, with ``bode``, ``bode``.

    Raises
    ------
    pulab.InputError
        Naming an ``analysis.*`` field.
    """
    cfg = validate(analysis)
    forget()
    m = report["input"]["motor"]
    out = {"delay": cfg["delay"], "current": {}}
    for axis, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        out["current"][axis] = _current_axis(report, cfg, axis, l_h)
    by = cfg["design"]
    target = cfg["target_phase_margin_deg"] if by == "phase_margin" else \
        (cfg["target_bandwidth_hz"] or report["input"]["current_loop"]["bandwidth_hz"] or
         report["current_pi"]["q"]["from_integers"]["bandwidth_hz"])
    design = {"by": by, "target": target,
              "dead_time_s": _current.dead_time(report["input"]["drive"]["ts_s"], cfg["delay"])}
    for axis, l_h in (("d", m["ld_h"]), ("q", m["lq_h"])):
        design[axis] = _design_axis(report, cfg, l_h, target)
    out["current"]["design"] = design
    p = report["pll"]
    out["pll"] = _pll.analyze(p["kp"], p["ki"], report["input"]["drive"]["ts_s"],
                              report["base"]["w_b"] / report["base"]["theta_b"])
    out["speed"] = None
    if cfg["speed"] is not None:
        speed_cfg = _speed_config(report, cfg["speed"])
        cfg["speed"] = speed_cfg
        out["speed"] = _speed_section(report, speed_cfg, cfg["delay"],
                                      out["current"]["q"]["bandwidth_hz"])
    if cfg["robust"] is not None:
        out["robust"] = _robust.analyze(report, cfg["robust"], cfg["delay"])
    if cfg["bode"]:
        out["bode"] = _bode(report, cfg, out)
    return out


def warnings(loop: dict) -> list:
    """Report warnings for loops that are unstable or close to it with the chosen delay, as
    ``(catalog code, params)`` pairs (:mod:`pulab.schema.catalog`)."""
    w = []
    delay = loop["delay"]
    for axis in ("d", "q"):
        for path, r in ((f"loop.current.{axis}", loop["current"][axis]),
                        (f"loop.current.{axis}.firmware", loop["current"][axis]["firmware"])):
            if not r["stable"]:
                w.append(("warning.current_unstable", {"path": path, "delay": delay,
                                                       "radius": r["spectral_radius"]}))
            elif r["phase_margin_deg"] is not None and r["phase_margin_deg"] < 30.0:
                w.append(("warning.current_low_pm", {"path": path, "delay": delay,
                                                      "pm": r["phase_margin_deg"]}))
    sp = loop["speed"]
    if sp is not None:
        if not sp["stable"]:
            w.append(("warning.speed_unstable", {"radius": sp["spectral_radius"]}))
        ratio = sp["inner_bandwidth_ratio"]
        if ratio is not None and ratio < 5.0:
            w.append(("warning.speed_inner_slow", {"ratio": ratio}))
    return w
