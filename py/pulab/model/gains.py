"""Current-loop PI and PLL gains in SI, per unit and vendor integers (seed 2, 3).

Current PI (seed 2.1-4, 2.2-9), kp in Ω and ki in Ω/s as phase quantities::

    kp_pu = kp·I_b/U_b          pm_kp = round(kp_pu·2^12)        (Q12)
    ki_pu = ki·I_b/U_b          pm_ki = round(ki_pu·Ts·2^16)     (Q16, Ts folded in)

The seed writes the same with the line voltage and line-valued gains
(k·√3 / (√3·U_b)); both give the same integers.

PLL (seed 3.1-6, 3.2-5)::

    kp = 2ζω_n, ki = ω_n², kp_pu = kp·θ_b/ω_b, ki_pu = ki·θ_b/ω_b,
    integrator gain ω_b/θ_b (= 2·f_b for θ_b = π)

Examples
--------
>>> g = pll_gains(50.0, 0.5 ** 0.5, 2 * 3.141592653589793 * 220, 3.141592653589793)
>>> round(g["integrator_gain"], 9)
440.0
"""

from __future__ import annotations

import math

from ..schema.errors import InputError
from ..fixedpoint.qformat import round_half_away

__all__ = ["current_pi_si", "gains_from_integers", "current_pi", "pi_integer_ideals", "pll_gains",
           "INT32_MIN",
           "INT32_MAX"]

INT32_MIN, INT32_MAX = -(1 << 31), (1 << 31) - 1


def current_pi_si(method: str, rs_ohm: float, l_h: float, bandwidth_hz: float,
                  damping: float, kp: float | None = None,
                  ki: float | None = None) -> tuple[float, float]:
    """SI gains (kp [Ω], ki [Ω/s]) for one axis.

    Parameters
    ----------
    method : {'bandwidth', 'damping', 'manual'}
        ``bandwidth``: pole-zero cancellation, kp = ω_c·L, ki = ω_c·R_s, so the
        closed loop is first order with bandwidth ω_c = 2π·bandwidth_hz.
        ``damping``: the PI zero is kept and the closed loop is a second-order
        system with natural frequency ω_0 = 2π·bandwidth_hz and damping ζ:
        kp = 2ζω_0·L − R_s, ki = ω_0²·L.
        ``manual``: kp, ki as given.  (Firmware integers as input: see
        :func:`gains_from_integers`.)
    rs_ohm : float > 0, ohms ; l_h : float > 0, henries
    bandwidth_hz : float > 0, hertz ; damping : float > 0
    """
    if method == "bandwidth":
        w = 2.0 * math.pi * bandwidth_hz
        return w * l_h, w * rs_ohm
    if method == "damping":
        w = 2.0 * math.pi * bandwidth_hz
        k = 2.0 * damping * w * l_h - rs_ohm
        if k <= 0:
            raise InputError("current_loop.bandwidth_hz", code="damping_kp_low", kp=k)
        return k, w * w * l_h
    return float(kp), float(ki)


def gains_from_integers(pm_kp: int, pm_ki: int, u_b: float, i_b: float,
                        ts_s: float) -> tuple[float, float]:
    """SI gains (kp [Ω], ki [Ω/s]) that firmware integers pm_kp (Q12), pm_ki (Q16) stand for.

    The inverse of seed 2.2-9: kp = pm_kp/2^12·U_b/I_b, ki = pm_ki/(2^16·Ts)·U_b/I_b.

    >>> kp, ki = gains_from_integers(4096, 65536, 10.0, 1.0, 1e-4)
    >>> kp, round(ki)
    (10.0, 100000)
    """
    return pm_kp / 4096.0 * u_b / i_b, pm_ki / 65536.0 / ts_s * u_b / i_b


def _int32(x: float, what: str) -> int:
    v = round_half_away(x)
    if not INT32_MIN <= v <= INT32_MAX:
        raise InputError("current_loop", code="long_overflow", what=what, value=v)
    return v


def pi_integer_ideals(kp_pu: float, ki_pu: float, ts_s: float) -> tuple[float, float]:
    """The exact values pm_kp and pm_ki round (seed 2.2-9): kp_pu·2^12 (Q12), ki_pu·Ts·2^16 (Q16).

    >>> pi_integer_ideals(0.5, 100.0, 1e-4)
    (2048.0, 655.36)
    """
    return kp_pu * 4096.0, ki_pu * ts_s * 65536.0


def current_pi(kp: float, ki: float, l_h: float, u_b: float, i_b: float, ts_s: float) -> dict:
    """Per-unit and vendor-integer form of one axis' gains, and back from the integers.

    Parameters
    ----------
    kp : float > 0, ohms ; ki : float > 0, ohms per second (phase quantities)
    l_h : float > 0, henries — the axis inductance, for the implied bandwidth
    u_b : float > 0, volts ; i_b : float > 0, amperes — the voltage/current bases
    ts_s : float > 0, seconds — control period

    Returns
    -------
    dict
        ``kp, ki, kp_pu, ki_pu, pm_kp, pm_ki, from_integers``.

    Examples
    --------
    >>> g = current_pi(1.885, 4712.4, 6e-4, 17 / 3 ** 0.5, 1.5, 1e-4)
    >>> g["pm_kp"], g["pm_ki"]
    (1180, 4720)
    """
    kp_pu, ki_pu = kp * i_b / u_b, ki * i_b / u_b
    kp_ideal, ki_ideal = pi_integer_ideals(kp_pu, ki_pu, ts_s)
    pm_kp = _int32(kp_ideal, "pm_kp")
    pm_ki = _int32(ki_ideal, "pm_ki")
    kp_back, ki_back = gains_from_integers(pm_kp, pm_ki, u_b, i_b, ts_s)
    return {"kp": kp, "ki": ki, "kp_pu": kp_pu, "ki_pu": ki_pu, "pm_kp": pm_kp, "pm_ki": pm_ki,
            "from_integers": {"kp": kp_back, "ki": ki_back,
                              "bandwidth_hz": kp_back / (2.0 * math.pi * l_h)}}


def pll_gains(bandwidth_hz: float, damping: float, w_b: float, theta_b: float) -> dict:
    """PLL PI gains in SI and per unit, and the per-unit integrator gain.

    Parameters
    ----------
    bandwidth_hz : float > 0, hertz — natural frequency ω_n/2π
    damping : float > 0
    w_b : float > 0, rad/s — speed base ω_b = 2π·f_b
    theta_b : float > 0, rad — angle base (π or 2π)
    """
    wn = 2.0 * math.pi * bandwidth_hz
    kp, ki = 2.0 * damping * wn, wn * wn
    return {"kp": kp, "ki": ki, "kp_pu": kp * theta_b / w_b, "ki_pu": ki * theta_b / w_b,
            "integrator_gain": w_b / theta_b, "wn": wn}
