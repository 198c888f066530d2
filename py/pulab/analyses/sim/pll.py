"""PLL angle tracking (seed 3): SI, per unit, int16 angle, and the naive scaling.

Structure, identical in all variants (seed figure 2.2-1)::

    e[k]    = wrap(θ[k] − θ̂[k])                phase detector
    I[k]    = I[k−1] + ki·T_s·e[k]              PI, vendor order: integral first
    ω̂[k]    = I[k] + kp·e[k]
    θ̂[k+1]  = θ̂[k] + g·T_s·ω̂[k]                integrator, gain g

Phase detector: the **wrapped difference** into [−π, π), not sin(θ − θ̂).  It
is linear up to ±180°, needs no sine table, and for the int16 angle it is the
16-bit subtraction itself: ``(int16)(θ − θ̂)`` wraps exactly at ±π.  Near lock
both detectors are the same to first order.

Variants (``kp = 2ζω_n``, ``ki = ω_n²`` from the report, seed 3.1):

``si``
    θ in rad, ω in rad/s, g = 1.
``pu``
    e_pu = e/θ_b, ω_pu = ω/ω_b, gains kp_pu = kp·θ_b/ω_b, ki_pu = ki·θ_b/ω_b
    (seed 3.1-6), integrator gain g = ω_b/θ_b (= 2·f_b for θ_b = π, seed 3.2-5).
    The same loop as ``si``, to rounding.
``q15``
    Integers as a C2000 would run them, always with θ_b = π:

    - angles: int16, 32768 ↔ π (Q15 of π), so the wrap-around at ±π *is* the
      16-bit overflow.  θ̂ is kept in an int32 accumulator with 2^31 ↔ π whose
      upper 16 bits are the int16 θ̂; the low 16 bits keep the fraction of a
      Q15 LSB that the per-period increment has (without them the truncated
      increment would make a speed error of up to 1 LSB per period, ~0.07 % at
      the seed's 220 Hz and 10 kHz);
    - ω̂ and the integral: int32 Q24 per unit of ω_b → ±128 pu of headroom
      (f_b is the drive's maximum frequency, so |ω| ≤ 1 pu in use);
    - kp: Q24 of kp_pu, ki: Q24 of ki_pu·T_s (T_s folded in as in the current
      PI's pm_ki), products Q15·Q24 in int64 then ``>> 15`` (as IQmath's
      ``_IQmpy`` does with its 64-bit product), saturated to int32;
    - integrator gain: G = round(2·f_b·T_s·2^23) (Q23), Δacc = (ω̂·G) >> 16, int64
      product, the accumulator wrapping in int32.

``naive``
    Per-unit signals and the integrator correctly scaled by ω_b/θ_b (the angle
    follows the real speed), but the PI gains left in SI (kp, ki, not ×θ_b/ω_b).
    The loop gain is ω_b/θ_b = 2·f_b times too high: the mistake of seed 3
    ("如果不采用上述方式进行标幺化, 那么锁相环 PLL 压根无法稳定").  With the
    seed's numbers kp·T_s·2·f_b ≈ 19.5, far beyond the discrete stability limit 2.

Input: θ(t) = θ_step + ω·t + π·ramp·t² (ramp in Hz/s); the estimator starts
cold at θ̂ = 0, ω̂ = 0, so θ_step is the initial phase error (the angle steps at
t = 0) and the loop must acquire both phase and speed.
"""

from __future__ import annotations

import math
from array import array

from ...schema.errors import InputError
from ..slices import SLICE_STEPS, finish
from ...fixedpoint.qformat import round_half_away
from .inputs import periods

__all__ = ["input_angle", "run_float", "run_q15", "run", "run_float_steps", "run_q15_steps",
           "run_steps", "input_angle_steps", "q15_gains", "MAX_STEPS"]

#: Upper bound on the number of periods of one run.
MAX_STEPS = 500_000

_TWO_PI = 2.0 * math.pi
_I32_MAX, _I32_MIN = (1 << 31) - 1, -(1 << 31)


def _wrap(x: float) -> float:
    """x wrapped into [−π, π]; math.remainder is exact."""
    return math.remainder(x, _TWO_PI)


def input_angle_steps(n: int, ts: float, speed_hz: float, ramp_hz_s: float,
                      step_rad: float):
    """The true angle and speed at t_k = k·T_s, k = 0..n.

    Parameters
    ----------
    n : int ≥ 1 ; ts : float > 0, s
    speed_hz : float, electrical Hz at t = 0 ; ramp_hz_s : float, Hz/s
    step_rad : float, rad — the angle step at t = 0

    Returns
    -------
    generator — yields None every 8·SLICE_STEPS samples (:mod:`pulab.analyses.slices`), returning
    (theta, omega) : arrays of n+1 floats, rad wrapped into [−π, π] and rad/s
    """
    w0 = _TWO_PI * speed_hz
    a = math.pi * ramp_hz_s
    # Arrays, not lists: 8 bytes a sample instead of 32, at 500 000 samples (the cap) per series.
    theta, omega = array("d"), array("d")
    for first in range(0, n + 1, 8 * SLICE_STEPS):
        ks = range(first, min(n + 1, first + 8 * SLICE_STEPS))
        theta.extend(_wrap(step_rad + w0 * (k * ts) + a * (k * ts) ** 2) for k in ks)
        omega.extend(w0 + 2.0 * a * (k * ts) for k in ks)
        yield
    return theta, omega


def input_angle(*args, **kwargs):
    """:func:`input_angle_steps` run to the end: the same arguments, the same result."""
    return finish(input_angle_steps(*args, **kwargs))


def run_float_steps(theta: list, ts: float, kp: float, ki: float, angle_base: float,
                    gain: float):
    """Float PLL on a given input angle (SI, per unit or naive, same code).

    Parameters
    ----------
    theta : list of float, rad — true angle at each sample
    ts : float > 0, s
    kp : float, output units per input unit ; ki : float, per second
    angle_base : float > 0, rad — the detector divides by it (1 for SI, θ_b for pu)
    gain : float > 0 — integrator gain g (1 for SI, ω_b/θ_b for pu)

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returning
    (theta_hat, omega_hat) : arrays of float, rad wrapped into [−π, π] and the PI output
    in its own unit (rad/s for SI, pu for pu and naive).
    """
    th = 0.0
    integ = 0.0
    kits = ki * ts
    gts = gain * ts
    period = _TWO_PI / angle_base
    inv_base = 1.0 / angle_base
    out_th, out_w = array("d"), array("d")
    for k, x in enumerate(theta):
        if k and not k % SLICE_STEPS:
            yield
        out_th.append(th * angle_base)
        e = math.remainder(x * inv_base - th, period)
        integ += kits * e
        w = integ + kp * e
        out_w.append(w)
        # Keep θ̂ wrapped (as the int16 does) so its rounding does not grow with t.
        th = math.remainder(th + gts * w, period)
    return out_th, out_w


def run_float(*args, **kwargs):
    """:func:`run_float_steps` run to the end: the same arguments, the same result."""
    return finish(run_float_steps(*args, **kwargs))


def q15_gains(kp: float, ki: float, w_b: float, f_b: float, ts: float) -> dict:
    """Integer PLL gains for the q15 variant (θ_b = π always).

    Parameters
    ----------
    kp : float, rad/s per rad ; ki : float, rad/s² per rad (SI, seed 3.1-1)
    w_b : float > 0, rad/s ; f_b : float > 0, Hz ; ts : float > 0, s

    Returns
    -------
    dict
        ``kp`` (Q24 of kp·π/ω_b), ``ki`` (Q24 of ki·π/ω_b·T_s), ``g`` (Q23 of
        2·f_b·T_s), each an int32.

    Raises
    ------
    InputError
        ``pll.bandwidth_hz`` when a gain does not fit its int32.
    """
    out = {"kp": round_half_away(kp * math.pi / w_b * 16777216.0),
           "ki": round_half_away(ki * math.pi / w_b * ts * 16777216.0),
           "g": round_half_away(2.0 * f_b * ts * 8388608.0)}
    for name, v in out.items():
        if not _I32_MIN <= v <= _I32_MAX:
            raise InputError("pll.bandwidth_hz", code="pll_q24_overflow", name=name, value=v)
    return out


def run_q15_steps(theta: list, gains: dict):
    """Integer PLL (int16 angle, Q24 speed) on a given input angle.

    Parameters
    ----------
    theta : list of float, rad — true angle, quantized here to int16 (32768 ↔ π)
    gains : dict — from :func:`q15_gains`

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returning
    (theta_in, theta_hat, omega_hat) : arrays of int — int16 input angle, int16
    θ̂ (Q15 of π), int32 ω̂ (Q24 of ω_b)
    """
    kp, ki, g = gains["kp"], gains["ki"], gains["g"]
    acc = 0
    integ = 0
    th_in, th_hat, w_hat = array("q"), array("q"), array("q")
    scale = 32768.0 / math.pi
    for k, x in enumerate(theta):
        if k and not k % SLICE_STEPS:
            yield
        q = round_half_away(x * scale)
        q = ((q + 32768) & 0xFFFF) - 32768                 # +π rounds to 32768 → −32768
        th_in.append(q)
        h = acc >> 16                                      # int16 θ̂: upper half of acc
        th_hat.append(h)
        e = ((q - h + 32768) & 0xFFFF) - 32768             # (int16)(θ − θ̂): the wrap
        integ += (e * ki) >> 15                            # Q15·Q24 >> 15 → Q24
        integ = _I32_MAX if integ > _I32_MAX else _I32_MIN if integ < _I32_MIN else integ
        w = integ + ((e * kp) >> 15)
        w = _I32_MAX if w > _I32_MAX else _I32_MIN if w < _I32_MIN else w
        w_hat.append(w)
        acc = ((acc + ((w * g) >> 16) + 2147483648) & 0xFFFFFFFF) - 2147483648
    return th_in, th_hat, w_hat


def run_q15(*args, **kwargs):
    """:func:`run_q15_steps` run to the end: the same arguments, the same result."""
    return finish(run_q15_steps(*args, **kwargs))


def default_duration(report: dict) -> float:
    """Default run length: 60/(ζ·ω_n) (≈ 15 envelope time constants), at least 2000 periods."""
    ts = report["input"]["drive"]["ts_s"]
    p = report["input"]["pll"]
    return max(2000 * ts, 60.0 / (p["damping"] * _TWO_PI * p["bandwidth_hz"]))


def run_steps(report: dict, cfg: dict):
    """Run the four PLL variants on the same input angle.

    Parameters
    ----------
    report : dict — the report (``input``, ``base``, ``pll``)
    cfg : dict — normalized ``sim.pll`` (:func:`pulab.analyses.sim.validate`)

    Returns
    -------
    generator — yields None every SLICE_STEPS periods (:mod:`pulab.analyses.slices`), returning a dict:
        ``t`` (s), ``theta`` (rad), ``omega`` (rad/s), ``variants``:
        ``si``/``pu``/``q15``/``naive`` → ``theta_hat`` (rad, wrapped),
        ``omega_hat`` (electrical rad/s).

    Raises
    ------
    InputError
        ``sim.pll.duration_s`` for too many periods; ``sim.pll.speed_hz`` or
        ``sim.pll.ramp_hz_per_s`` when the input speed reaches half the control
        frequency (the default speed, rated_freq_hz, included).
    """
    inp, b, g = report["input"], report["base"], report["pll"]
    ts = inp["drive"]["ts_s"]
    w_b, theta_b, f_b = b["w_b"], b["theta_b"], b["f_b"]
    duration = cfg["duration_s"] if cfg["duration_s"] is not None else default_duration(report)
    n = periods(duration, ts, MAX_STEPS, "sim.pll.duration_s")
    speed = cfg["speed_hz"] if cfg["speed_hz"] is not None else inp["motor"]["rated_freq_hz"]
    top = max(abs(speed), abs(speed + cfg["ramp_hz_per_s"] * n * ts))
    if top * ts >= 0.5:
        # An angle sampled at Ts cannot show a speed at or above Nyquist.
        field = "sim.pll.ramp_hz_per_s" if abs(speed) * ts < 0.5 else "sim.pll.speed_hz"
        raise InputError(field, code="input_speed_nyquist", value=top, nyquist=0.5 / ts)
    theta, omega = yield from input_angle_steps(n, ts, speed, cfg["ramp_hz_per_s"],
                                                math.radians(cfg["angle_step_deg"]))
    v = {}
    th, w = yield from run_float_steps(theta, ts, g["kp"], g["ki"], 1.0, 1.0)
    v["si"] = {"theta_hat": th, "omega_hat": w}
    th, w = yield from run_float_steps(theta, ts, g["kp_pu"], g["ki_pu"], theta_b, w_b / theta_b)
    v["pu"] = {"theta_hat": th, "omega_hat": array("d", (x * w_b for x in w))}
    yield  # the unit conversions of 500 000 samples are a slice of their own
    _, th, w = yield from run_q15_steps(theta, q15_gains(g["kp"], g["ki"], w_b, f_b, ts))
    v["q15"] = {"theta_hat": array("d", (x * (math.pi / 32768.0) for x in th)),
                "omega_hat": array("d", (x * (w_b / 16777216.0) for x in w))}
    yield  # the unit conversions of 500 000 samples are a slice of their own
    th, w = yield from run_float_steps(theta, ts, g["kp"], g["ki"], theta_b, w_b / theta_b)
    v["naive"] = {"theta_hat": th, "omega_hat": array("d", (x * w_b for x in w))}
    yield  # the unit conversions of 500 000 samples are a slice of their own
    return {"t": array("d", (k * ts for k in range(n + 1))), "ts": ts, "n": n, "theta": theta,
            "omega": omega, "variants": v}


def run(*args, **kwargs):
    """:func:`run_steps` run to the end: the same arguments, the same result."""
    return finish(run_steps(*args, **kwargs))
