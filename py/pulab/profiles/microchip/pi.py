"""Microchip's integer current PI: one step in the arithmetic of its public code, and the
controller the fixed-point simulation closes the loop with (:mod:`pulab.analyses.sim.vendor_loop`).

The step is a pure function of integers (the controller state, the reference and the feedback,
the gains and limits), written in the C constructs of the vendor's public code: the same word
sizes, shifts, casts, saturating calls and order; it counts every wrap and saturation in ``ev``
(:mod:`pulab.fixedpoint.counted`).  The public file read (never copied):

Microchip AN1160 ``pi.c`` ``CalcPI`` (JakyHou/SZCCW :
  AN1160_PIC32MM0064GPL036_MCLV_MCHV.X/pi.c; the C form of AN1078's ``CalcPI``): Q15
  gains, int32 ``qdSum``, output ``(int16_t)(U >> 15)`` clamped, anti-windup
  ``Sum += Ki·Err − Kc·Exc``.  A gain above 1 is stored in fewer fractional bits
  (KIP_Q < 15) and multiplied back by 2^(15 − KIP_Q), the DKNP shift of MCAF's
  ``foc_params.h``; AN1160's own CalcPI has no such shift.
"""

from __future__ import annotations

from functools import partial

from ...fixedpoint.counted import limit, wrap
from ...fixedpoint.qformat import round_half_away

__all__ = ["step", "controller"]


def step(state: tuple, ref: int, fb: int, kp: int, ki: int, kc: int, out_max: int,
         out_min: int, kp_shift: int, ki_shift: int, ev: dict) -> tuple:
    """One ``CalcPI`` call (PIC32: int is 32 bits).

    Parameters
    ----------
    state : (qdSum,)
    ref, fb : int, Q15 of I_b — qInRef, qInMeas
    kp, ki, kc : int — qKp, qKi (Q(15 − shift)), qKc (Q15)
    out_max, out_min : int, Q15 of V_b — qOutMax, qOutMin
    kp_shift, ki_shift : int ≥ 0 — 15 − KIP_Q, 15 − KII_Q (DKNP, DKNI)
    ev : dict — event counts, updated

    Returns
    -------
    ((qdSum,), qOut)
    """
    total = state[0]
    err = wrap(ref - fb, 16, ev)  # int16_t currentError = qInRef − qInMeas
    u = wrap(wrap(err * kp, 32, ev) * (1 << kp_shift), 32, ev)
    u = wrap(u + total, 32, ev)
    out_temp = wrap(u >> 15, 16, ev)  # int16_t outTemp = (int32_t)(U >> 15)
    out = limit(out_temp, out_min, out_max, ev, "output_limit")
    u = wrap(wrap(err * ki, 32, ev) * (1 << ki_shift), 32, ev)
    exc = wrap(out_temp - out, 16, ev)
    u = wrap(u - exc * kc, 32, ev)
    return (wrap(total + u, 32, ev),), out


def controller(p: dict, umax: float, udc: float) -> dict:
    """The controller of :func:`pulab.analyses.sim.vendor_loop.controllers` for profile ``p``
    (output limit ``umax``, V phase peak; DC bus ``udc``, V)."""
    o, c = p["inputs"], p["constants"]
    v_lsb = o["voltage_base_v"] / 32768.0
    hi = min(32767, round_half_away(umax / v_lsb))
    bound = partial(step, kp=c["KIP"]["value"], ki=c["KII"]["value"], kc=32767,
                    out_max=hi, out_min=-hi, kp_shift=15 - c["KIP"]["q"],
                    ki_shift=15 - c["KII"]["q"])
    return {"i_lsb": o["current_base_a"] / 32768.0, "fb_bits": 16, "u_lsb": v_lsb,
            "out_limit": hi, "steps": {"d": bound, "q": bound},
            "start": lambda v: (max(-hi, min(hi, round_half_away(v / v_lsb))) << 15,),
            "held": lambda s: s[0] >> 15}
