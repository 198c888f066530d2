"""Time-domain simulations for the report's ``"sim"`` section.

Pure standard library (runs in a bare Pyodide).  :func:`pulab.report` calls
:func:`validate` on the input's ``"sim"`` and :func:`simulate` on the finished
report, so every motor, drive and gain number comes from the report itself.

Modules, one concept each:

- :mod:`.plant` — PMSM dq model (seed 1.2-3), exact zero-order-hold discretization;
- :mod:`.current` — current loop: SI float, per-unit float, vendor fixed point;
- :mod:`.vendor_loop` — TI's, NXP's, ST's and Microchip's integer PI (each vendor's ``pi``);
- :mod:`.code_loop` — the user's C routine as the controller (``sim.current.code``);
- :mod:`.pll` — PLL: SI, per unit, int16 angle (Q15 of π), naive gains;
- :mod:`.metrics` — rise/settling/overshoot, lock detection;
- :mod:`.inputs` — validation and defaults;
- :mod:`.linalg` — the small matrix exponential;
- :mod:`.bench` — ``python -m pulab.analyses.sim.bench`` prints steps per second.

Output (all SI: A, V phase, rad, electrical rad/s; time series decimated to at
most :data:`MAX_POINTS` samples, metrics from the full-rate series)::

    {"current": {"t": [...],
                 "variants": {"si"|"pu"|"fixed": {"id", "iq", "ud", "uq": [...]}},
                 "metrics": {"si"|"pu"|"fixed": {"rise_time_s", "overshoot_pct",
                                                 "settling_time_s", "steady_state_error_a",
                                                 "saturation_time_s"},
                             "fixed_vs_si_max_abs_a", "fixed_vs_si_max_lsb", "fixed_wraps",
                             "first_order_rise_time_s", "wc_ts", "rise_time_deviation_pct"}},
     "pll": {"t": [...], "variants": {"si"|"pu"|"q15"|"naive":
                                      {"theta", "theta_hat", "omega_hat": [...]}},
             "metrics": {"si"|"pu"|"q15"|"naive": {"locked", "lock_time_s",
                                                   "speed_error_hz", "max_angle_error_deg"}}}}

Metrics that do not exist for a run (e.g. never settled) are ``null``.  ``fixed`` is the
Inovance firmware's PI (seed 2.2): when that firmware cannot compute its voltage limits for
this drive (``firmware.inovance``), ``fixed`` is absent, ``fixed_vs_si_*`` are null and the
float variants, which always run, clamp at U_dc/√2.  ``current.by_profile`` holds TI's,
NXP's, ST's and Microchip's own integer PI (:mod:`.vendor_loop`), each with its metrics and
its count of wraps and saturations, or the problems that keep it from running.
``current.code`` (only with the input ``sim.current.code``) is the user's C routine in the
loop (:mod:`.code_loop`; docs/contract.md, "Your code in the loop").
"""

from __future__ import annotations

import math

from . import current as _current
from . import pll as _pll
from ..slices import finish
from .inputs import validate
from .metrics import pll_metrics, step_metrics

__all__ = ["validate", "simulate", "simulate_steps", "decimate_indices", "MAX_POINTS"]

#: Time series in the JSON output are decimated to at most this many samples.
MAX_POINTS = 400


def decimate_indices(n: int, max_points: int = MAX_POINTS) -> list:
    """Indices 0..n−1: the first half of the budget at full rate, the rest with a constant stride.

    A step response happens at the start; a constant stride over a long run
    would sample the transient too coarsely to draw it (one point per 50 ms in
    a 20 s run), so the first ``max_points // 2`` samples are kept as they are.

    Parameters
    ----------
    n : int ≥ 1, samples in the full-rate series
    max_points : int ≥ 4

    Returns
    -------
    list of int, increasing, at most ``max_points`` long, ending with n − 1

    Examples
    --------
    >>> decimate_indices(5)
    [0, 1, 2, 3, 4]
    >>> idx = decimate_indices(200001)
    >>> len(idx) <= 400, idx[:3], idx[199:201], idx[-1]
    (True, [0, 1, 2], [199, 1204], 200000)
    """
    if n <= max_points:
        return list(range(n))
    head = max_points // 2
    stride = -(-(n - 1 - head) // (max_points - head - 1))
    idx = list(range(head)) + list(range(head - 1 + stride, n, stride))
    if idx[-1] != n - 1:
        idx.append(n - 1)
    return idx


def _pick(series: list, idx: list) -> list:
    return [series[k] for k in idx]


def _current_section(report: dict, cfg: dict):
    r = yield from _current.run_steps(report, cfg)
    t, ts, ref = r["t"], r["ts"], r["ref_a"]
    key = "id" if r["axis"] == "d" else "iq"
    idx = decimate_indices(len(t))
    variants, metrics = {}, {}
    for name, v in r["variants"].items():
        variants[name] = {k: _pick(v[k], idx) for k in ("id", "iq", "ud", "uq")}
        metrics[name] = step_metrics(t, v[key], ref, v["sat"], ts)
        yield
    si, fx = r["variants"]["si"], r["variants"].get("fixed")
    diff = None if fx is None else _max_diff(fx, si)
    metrics["fixed_vs_si_max_abs_a"] = diff
    metrics["fixed_vs_si_max_lsb"] = None if diff is None else diff / (report["base"]["I_b"] / 4096.0)
    metrics["fixed_wraps"] = None if fx is None else fx["wraps"]
    by_profile = {}
    for name, run in r["by_profile"].items():
        if "problems" in run:
            by_profile[name] = {"ran": False, "problems": run["problems"]}
            continue
        m = step_metrics(t, run[key], ref, run["sat"], ts)
        d = _max_diff(run, si)
        m.update(vs_si_max_abs_a=d, vs_si_max_lsb=d / run["lsb_a"])
        by_profile[name] = {"ran": True, "lsb_a": run["lsb_a"], "events": run["events"],
                            "variant": {k: _pick(run[k], idx) for k in ("id", "iq", "ud", "uq")},
                            "metrics": m}
        yield
    code = r.get("code")
    if code is not None:
        m = step_metrics(t, code[key], ref, code["sat"], ts)
        d = _max_diff(code, si)
        own = None if fx is None else _max_diff(code, fx)
        m.update(vs_si_max_abs_a=d, vs_si_max_lsb=d / code["lsb_a"], vs_fixed_max_abs_a=own)
        code = {"ran": True, "scale": code["scale"], "lsb_a": code["lsb_a"],
                "variant": {k: _pick(code[k], idx) for k in ("id", "iq", "ud", "uq")},
                "ints": {k: _pick(code[k], idx) for k in ("fb_d", "fb_q", "out_d", "out_q")},
                "metrics": m, "events": code["events"], "flags": code["flags"],
                "first_event": code["first_event"], "zeroed": code["zeroed"]}
    # First-order design value (bandwidth design: closed loop 1/(1 + s/ω_c)):
    # t_r = ln(9)/ω_c ≈ 2.2/(2π·bw).  Shown next to the simulated value, deviation included.
    cl = report["input"]["current_loop"]
    first = wc_ts = dev = None
    if cl["method"] == "bandwidth":
        w_c = 2.0 * math.pi * cl["bandwidth_hz"]
        first = 2.2 / w_c
        wc_ts = w_c * ts
        if metrics["si"]["rise_time_s"] is not None:
            dev = 100.0 * (metrics["si"]["rise_time_s"] - first) / first
    metrics["first_order_rise_time_s"] = first
    metrics["wc_ts"] = wc_ts
    metrics["rise_time_deviation_pct"] = dev
    out = {"t": _pick(t, idx), "variants": variants, "metrics": metrics,
           "by_profile": by_profile}
    if code is not None:
        out["code"] = code
    return out


def _max_diff(a: dict, b: dict) -> float:
    """The largest |a − b| over both axes' currents, full rate, A."""
    return max(max(abs(x - y) for x, y in zip(a["id"], b["id"])),
               max(abs(x - y) for x, y in zip(a["iq"], b["iq"])))


def _pll_section(report: dict, cfg: dict):
    r = yield from _pll.run_steps(report, cfg)
    t, theta, omega = r["t"], r["theta"], r["omega"]
    idx = decimate_indices(len(t))
    variants, metrics = {}, {}
    for name, v in r["variants"].items():
        variants[name] = {"theta": _pick(theta, idx), "theta_hat": _pick(v["theta_hat"], idx),
                          "omega_hat": _pick(v["omega_hat"], idx)}
        metrics[name] = pll_metrics(t, theta, omega, v["theta_hat"], v["omega_hat"])
        yield
    return {"t": _pick(t, idx), "variants": variants, "metrics": metrics}


def simulate_steps(report: dict, sim: dict):
    """The ``"sim"`` output section for a finished report.

    Parameters
    ----------
    report : dict
        Output of :func:`pulab.report` (uses ``input``, ``base``, ``pu``,
        ``vendor``, ``current_pi``, ``pll``).
    sim : dict
        The ``"sim"`` input (raw or already passed through :func:`validate`).

    Returns
    -------
    generator — yields None between slices of about SLICE_STEPS periods
    (:mod:`pulab.analyses.slices`), returning ``{"current": {...}, "pll": {...}}`` as in
    the module docstring.

    Raises
    ------
    pulab.InputError
        Naming the ``sim.*`` field (bad value, too many periods, reference
        outside the Q12 range).
    """
    cfg = validate(sim)
    current = yield from _current_section(report, cfg["current"])
    pll = yield from _pll_section(report, cfg["pll"])
    return {"current": current, "pll": pll}


def simulate(report: dict, sim: dict) -> dict:
    """:func:`simulate_steps` run to the end: the same arguments, the same result."""
    return finish(simulate_steps(report, sim))
