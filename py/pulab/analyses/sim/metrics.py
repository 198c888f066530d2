"""Step-response and PLL metrics, computed on the full-rate series.

Every function returns plain floats, bools or ``None`` (a metric that does not
exist for the run, e.g. no settling within it) — never NaN or infinity, as the
contract requires.

Examples
--------
>>> t = [0.0, 1.0, 2.0, 3.0]
>>> rise_time(t, [0.0, 0.5, 1.0, 1.0], 1.0)      # 10 % at t = 0.2, 90 % at 1.8
1.6
"""

from __future__ import annotations

import math

__all__ = ["crossing", "rise_time", "overshoot_pct", "settling_time", "steady_state_error",
           "step_metrics", "wrapped_error", "pll_metrics", "LOCK_DEG", "LOCK_WINDOW"]

#: PLL lock: |θ − θ̂| below this, in degrees …
LOCK_DEG = 2.0
#: … over this final fraction of the run.
LOCK_WINDOW = 0.2


def crossing(t: list, y: list, level: float, sign: float = 1.0) -> float | None:
    """First time y crosses ``level`` going in the direction of ``sign``, interpolated.

    Parameters
    ----------
    t, y : lists of float of equal length (s, any unit)
    level : float
    sign : ±1.0 — +1 for an upward crossing of a positive step, −1 for a negative step

    Returns
    -------
    float or None
        Linear interpolation between the two samples that bracket the crossing.
    """
    for k, v in enumerate(y):
        if sign * (v - level) >= 0.0:
            if k == 0:
                return t[0]
            y0 = y[k - 1]
            return t[k - 1] + (t[k] - t[k - 1]) * (level - y0) / (v - y0)
    return None


def rise_time(t: list, y: list, ref: float) -> float | None:
    """10–90 % rise time toward ``ref`` from 0, interpolated between samples.

    Parameters
    ----------
    t : list of float, s ; y : list of float ; ref : float ≠ 0, the final value

    Returns
    -------
    float ≥ 0 or None (90 % never reached), seconds
    """
    s = 1.0 if ref > 0 else -1.0
    t10 = crossing(t, y, 0.1 * ref, s)
    t90 = crossing(t, y, 0.9 * ref, s)
    if t10 is None or t90 is None:
        return None
    return t90 - t10


def overshoot_pct(y: list, ref: float) -> float:
    """Peak overshoot beyond ``ref`` in percent of |ref| (0 when there is none)."""
    s = 1.0 if ref > 0 else -1.0
    peak = max(s * v for v in y)
    return max(0.0, 100.0 * (peak - abs(ref)) / abs(ref))


def settling_time(t: list, y: list, ref: float, band: float = 0.02) -> float | None:
    """Time after which |y − ref| ≤ band·|ref| for the rest of the run (2 % by default).

    The exit from the band is interpolated between the last sample outside it and
    the next one.  None when the last sample is still outside.
    """
    tol = band * abs(ref)
    last = None
    for k in range(len(y) - 1, -1, -1):
        if abs(y[k] - ref) > tol:
            last = k
            break
    if last is None:
        return t[0]
    if last == len(y) - 1:
        return None
    y0, y1 = y[last] - ref, y[last + 1] - ref
    edge = tol if y0 > 0 else -tol
    return t[last] + (t[last + 1] - t[last]) * (edge - y0) / (y1 - y0) if y1 != y0 else t[last]


def steady_state_error(y: list, ref: float, window: float = 0.1) -> float:
    """ref − mean(y) over the last ``window`` fraction of the samples (≥ 1 sample)."""
    m = max(1, int(len(y) * window))
    tail = y[-m:]
    return ref - math.fsum(tail) / len(tail)


def step_metrics(t: list, y: list, ref: float, sat: list, ts: float) -> dict:
    """All step-response metrics of one variant.

    Parameters
    ----------
    t : list of float, s ; y : list of float, A — the stepped axis current
    ref : float ≠ 0, A ; sat : list of bool — output at its limit at t_k
    ts : float > 0, s — control period, the time each sample stands for

    Returns
    -------
    dict
        ``rise_time_s, overshoot_pct, settling_time_s, steady_state_error_a,
        saturation_time_s``.
    """
    return {"rise_time_s": rise_time(t, y, ref),
            "overshoot_pct": overshoot_pct(y, ref),
            "settling_time_s": settling_time(t, y, ref),
            "steady_state_error_a": steady_state_error(y, ref),
            "saturation_time_s": sum(sat) * ts}


def wrapped_error(theta: list, theta_hat: list) -> list:
    """θ − θ̂ wrapped into [−π, π], rad."""
    return [math.remainder(a - b, 2.0 * math.pi) for a, b in zip(theta, theta_hat)]


def pll_metrics(t: list, theta: list, omega: list, theta_hat: list, omega_hat: list) -> dict:
    """Lock, lock time, speed error and maximum angle error of one PLL run.

    Parameters
    ----------
    t : list of float, s ; theta, theta_hat : lists of float, rad
    omega, omega_hat : lists of float, electrical rad/s

    Returns
    -------
    dict
        ``locked`` (|θ − θ̂| < 2° at every sample of the last 20 %),
        ``lock_time_s`` (the first time from which the error stays below 2° to
        the end; None when not locked), ``speed_error_hz`` (mean of ω̂ − ω over
        the last 20 %, electrical Hz), ``max_angle_error_deg`` (over the whole
        run, including the acquisition), ``steady_angle_error_deg`` (the largest
        |θ − θ̂| over the last 20 %, after lock: what the loop tracks with, without the
        cold-start transient).
    """
    err = [abs(e) for e in wrapped_error(theta, theta_hat)]
    lim = math.radians(LOCK_DEG)
    n = len(t)
    start = min(n - 1, int(math.floor(n * (1.0 - LOCK_WINDOW))))
    locked = all(e < lim for e in err[start:])
    lock_time = None
    if locked:
        k = n - 1
        while k > 0 and err[k - 1] < lim:
            k -= 1
        lock_time = t[k]
    dw = [a - b for a, b in zip(omega_hat[start:], omega[start:])]
    speed_err = math.fsum(dw) / len(dw) / (2.0 * math.pi)
    if not math.isfinite(speed_err):
        speed_err = None
    return {"locked": locked, "lock_time_s": lock_time, "speed_error_hz": speed_err,
            "max_angle_error_deg": math.degrees(max(err)),
            "steady_angle_error_deg": math.degrees(max(err[start:]))}
