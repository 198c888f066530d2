"""NXP's integer current PI: one step in the arithmetic of its public code, and the
controller the fixed-point simulation closes the loop with (:mod:`pulab.analyses.sim.vendor_loop`).

The step is a pure function of integers (the controller state, the reference and the feedback,
the gains and limits), written in the C constructs of the vendor's public code: the same word
sizes, shifts, casts, saturating calls and order; it counts every wrap and saturation in ``ev``
(:mod:`pulab.fixedpoint.counted`).  The public file read (never copied):

NXP RTCESL ``GFLIB_CtrlPIpAW_F16`` (Masmiseim36/nxpSDK :
  middleware/rtcesl/CM4F_RTCESL_4.5_IAR/GFLIB/Include/GFLIB_CtrlPIp_A32.h): ACC32 gains
  (Q16.15), a frac32 integral accumulator, the previous error ``f16InErrK_1``, frac16
  limits; the library itself ships as object code, so the arithmetic inside is pulab's
  reading of its documented form (saturating frac32 products and sums, the accumulator
  held within the limits, output = upper half of the frac32 sum).  The error is
  ``MLIB_SubSat_F16(req, meas)`` as NXP's FOC code computes it.  With ``trapezoidal`` the
  integral adds Ki·(e(k) + e(k−1)) (Ki = ki·T_s/2), otherwise Ki·e(k) (Ki = ki·T_s): MCAT
  halves Ki for its "Trapezoidal" discretization (``DiscMethodFactor``, Masmiseim36/nxpSDK :
  middleware/motor_control/freemaster/pmsm_frac/mcat/src/JS_functions/inner_CLoop.js).
"""

from __future__ import annotations

import math
from functools import partial

from ...fixedpoint.counted import limit, saturate

__all__ = ["step", "controller"]


def step(state: tuple, ref: int, fb: int, kp: int, ki: int, upper: int, lower: int,
         trapezoidal: bool, ev: dict) -> tuple:
    """One ``GFLIB_CtrlPIpAW_F16`` call with its error ``MLIB_SubSat_F16(ref, fb)``
    (the stop-integration flag clear).

    Parameters
    ----------
    state : (f32IAccK_1, f16InErrK_1)
    ref, fb : int, frac16 of I_max
    kp, ki : int, acc32 (Q16.15) — a32PGain, a32IGain
    upper, lower : int, frac16 of U_max — f16UpperLim, f16LowerLim
    trapezoidal : bool — integrate Ki·(e(k) + e(k−1)) instead of Ki·e(k)
    ev : dict — event counts, updated

    Returns
    -------
    ((f32IAccK_1, f16InErrK_1), out) — out frac16 of U_max
    """
    acc, e_prev = state
    e = saturate(ref - fb, 16, ev)
    # acc32 (Q15) · frac16 (Q15) is Q30; ·2 is the frac32 (Q31) scale.
    prop = saturate(kp * e * 2, 32, ev)
    inc = saturate(ki * ((e + e_prev) if trapezoidal else e) * 2, 32, ev)
    acc = limit(saturate(acc + inc, 32, ev), lower << 16, upper << 16, ev, "integral_limit")
    out = limit(saturate(prop + acc, 32, ev) >> 16, lower, upper, ev, "output_limit")
    return (acc, e), out


def controller(p: dict, umax: float, udc: float) -> dict:
    """The controller of :func:`pulab.analyses.sim.vendor_loop.controllers` for profile ``p``
    (output limit ``umax``, V phase peak; DC bus ``udc``, V)."""
    o, c = p["inputs"], p["constants"]
    v_lsb = o["u_max_v"] / 32768.0
    hi = min(32767, math.trunc(umax / v_lsb))
    steps = {a: partial(step, kp=c[f"M1_{a.upper()}_KP_GAIN"]["value"],
                        ki=c[f"M1_{a.upper()}_KI_GAIN"]["value"], upper=hi, lower=-hi,
                        trapezoidal=o["trapezoidal"]) for a in ("d", "q")}
    return {"i_lsb": o["i_max_a"] / 32768.0, "fb_bits": 16, "u_lsb": v_lsb, "out_limit": hi,
            "steps": steps,
            "start": lambda v: (max(-hi, min(hi, math.trunc(v / v_lsb))) << 16, 0),
            "held": lambda s: s[0] >> 16}
