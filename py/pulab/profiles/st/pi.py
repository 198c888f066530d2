"""ST's integer current PI: one step in the arithmetic of its public code, and the
controller the fixed-point simulation closes the loop with (:mod:`pulab.analyses.sim.vendor_loop`).

The step is a pure function of integers (the controller state, the reference and the feedback,
the gains and limits), written in the C constructs of the vendor's public code: the same word
sizes, shifts, casts, saturating calls and order; it counts every wrap and saturation in ``ev``
(:mod:`pulab.fixedpoint.counted`).  The public file read (never copied):

ST MCSDK ``pid_regulator.c`` ``PI_Controller`` (public copies found by exact-string search)
  with the limits of ``mc_config.c`` (dronectl/g431-mcsdk : Src/mc_config.c): int16 gains,
  int32 integral with its overflow guard, ±INT16_MAX·TF_KIDIV integral limits, ±INT16_MAX
  output, back-calculation ``wIntegralTerm += wDischarge``.  The default build (arithmetic
  shifts by log2 of the divisors) is simulated, not the FULL_MISRA_C_COMPLIANCY build
  that divides (one LSB apart on negative values, :func:`pulab.profiles.st.pi_first_output`).

Examples
--------
>>> ev = {}
>>> step((0,), 100, 0, 9456, 2364, 14, 14, 32767 * 16384, ev)
((236400,), 71)
"""

from __future__ import annotations

import math
from functools import partial

from ...fixedpoint.counted import count, limit, wrap

__all__ = ["step", "controller"]

_I32_MAX = (1 << 31) - 1


def step(state: tuple, ref: int, fb: int, kp: int, ki: int, kp_log: int, ki_log: int,
         integral_limit: int, ev: dict) -> tuple:
    """One ``PI_Controller`` call (shift build) on the error ``ref − fb`` in digits.

    Parameters
    ----------
    state : (wIntegralTerm,)
    ref, fb : int, current digits (int16)
    kp, ki : int, int16 — hKpGain, hKiGain
    kp_log, ki_log : int — hKpDivisorPOW2, hKiDivisorPOW2 (log2 of TF_KPDIV, TF_KIDIV)
    integral_limit : int — wUpperIntegralLimit = INT16_MAX·TF_KIDIV (the lower is its negative)
    ev : dict — event counts, updated

    Returns
    -------
    ((wIntegralTerm,), out) — out in voltage digits, |out| ≤ INT16_MAX
    """
    integ = state[0]
    err = ref - fb
    prop = wrap(kp * err, 32, ev)
    if ki == 0:
        integ = 0
    else:
        term = wrap(ki * err, 32, ev)
        # The sum wraps in C; the code's own guard then puts it at ±INT32_MAX.
        total = (integ + term + (1 << 31)) % (1 << 32) - (1 << 31)
        if total < 0 and integ > 0 and term > 0:
            total = _I32_MAX
            count(ev, "saturate")
        elif total >= 0 and integ < 0 and term < 0:
            total = -_I32_MAX
            count(ev, "saturate")
        integ = limit(total, -integral_limit, integral_limit, ev, "integral_limit")
    out = wrap((prop >> kp_log) + (integ >> ki_log), 32, ev)
    discharge = 0
    if out > 32767:
        discharge, out = 32767 - out, 32767
        count(ev, "output_limit")
    elif out < -32767:
        discharge, out = -32767 - out, -32767
        count(ev, "output_limit")
    integ = wrap(integ + discharge, 32, ev)
    return (integ,), out


def controller(p: dict, umax: float, udc: float) -> dict:
    """The controller of :func:`pulab.analyses.sim.vendor_loop.controllers` for profile ``p``
    (output limit ``umax``, V phase peak; DC bus ``udc``, V)."""
    o, c = p["inputs"], p["constants"]
    kidiv = o["tf_kidiv"]
    ilim = 32767 * kidiv
    names = {"d": "FLUX", "q": "TORQUE"}
    steps = {a: partial(step, kp=c[f"PID_{names[a]}_KP_DEFAULT"]["value"],
                        ki=c[f"PID_{names[a]}_KI_DEFAULT"]["value"],
                        kp_log=o["tf_kpdiv"].bit_length() - 1, ki_log=kidiv.bit_length() - 1,
                        integral_limit=ilim) for a in ("d", "q")}
    v_lsb = udc / math.sqrt(3.0) / 32768.0
    return {"i_lsb": o["max_current_a"] / 32768.0, "fb_bits": 16, "u_lsb": v_lsb,
            "out_limit": 32767, "steps": steps,
            "start": lambda v: (max(-ilim, min(ilim, math.trunc(v / v_lsb) * kidiv)),),
            "held": lambda s: s[0] >> (kidiv.bit_length() - 1)}
