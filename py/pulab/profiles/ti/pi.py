"""TI's integer current PI: one step in the arithmetic of its public code, and the
controller the fixed-point simulation closes the loop with (:mod:`pulab.analyses.sim.vendor_loop`).

The step is a pure function of integers (the controller state, the reference and the feedback,
the gains and limits), written in the C constructs of the vendor's public code: the same word
sizes, shifts, casts, saturating calls and order; it counts every wrap and saturation in ``ev``
(:mod:`pulab.fixedpoint.counted`).  The public file read (never copied):

TI MotorWare ``pi.h`` ``PI_run_series`` (a public copy found by exact-string search; the
  search tool does not name its repository) with IQmath ``IQmathLib.h``:
  ``Up = _IQmpy(Kp, Error)``, ``Ui = _IQsat(Ui + _IQmpy(Ki, Up), outMax, outMin)``,
  ``Out = _IQsat(Up + Ui + ffwd, outMax, outMin)``; ``_IQmpy`` is the 64-bit product
  shifted right by GLOBAL_Q, kept in 32 bits.

Examples
--------
>>> ev = {}
>>> step((0,), 1 << 24, 0, 1 << 23, 1 << 20, 1 << 24, -(1 << 24), 24, ev)
((524288,), 8912896)
"""

from __future__ import annotations

import math
from functools import partial

from ...fixedpoint.counted import limit, wrap

__all__ = ["step", "controller"]


def _iqmpy(a: int, b: int, q: int, ev: dict) -> int:
    # (long)(((long long)a * b) >> GLOBAL_Q): the shift floors, the cast keeps 32 bits.
    return wrap((a * b) >> q, 32, ev)


def step(state: tuple, ref: int, fb: int, kp: int, ki: int, out_max: int, out_min: int,
         q: int, ev: dict) -> tuple:
    """One ``PI_run_series`` call (feed-forward 0).

    Parameters
    ----------
    state : (Ui,) — the integral, _iq
    ref, fb : int, _iq — reference and feedback (per unit of I_FS in IQ(q))
    kp, ki : int, _iq — Kp and the series Ki
    out_max, out_min : int, _iq — the limits of the integral and the output
    q : int in 1..30 — GLOBAL_Q
    ev : dict — event counts, updated

    Returns
    -------
    ((Ui,), out) — the new state and the output, _iq (per unit of V_FS)
    """
    error = wrap(ref - fb, 32, ev)
    up = _iqmpy(kp, error, q, ev)
    ui = limit(wrap(state[0] + _iqmpy(ki, up, q, ev), 32, ev), out_min, out_max, ev,
                "integral_limit")
    out = limit(wrap(up + ui, 32, ev), out_min, out_max, ev, "output_limit")
    return (ui,), out


def controller(p: dict, umax: float, udc: float) -> dict:
    """The controller of :func:`pulab.analyses.sim.vendor_loop.controllers` for profile ``p``
    (output limit ``umax``, V phase peak; DC bus ``udc``, V)."""
    o, c = p["inputs"], p["constants"]
    q = o["global_q"]
    one = float(1 << q)
    v_lsb = o["full_scale_voltage_v"] / one
    # _IQ() of a limit beyond the word is undefined in C; the word's end is what can be held.
    hi = min((1 << 31) - 1, math.trunc(umax / v_lsb))
    steps = {a: partial(step, kp=c[f"Kp_I{a}"]["value"], ki=c[f"Ki_I{a}"]["value"],
                        out_max=hi, out_min=-hi, q=q) for a in ("d", "q")}
    return {"i_lsb": o["full_scale_current_a"] / one, "fb_bits": 32, "u_lsb": v_lsb,
            "out_limit": hi, "steps": steps,
            "start": lambda v: (max(-hi, min(hi, math.trunc(v / v_lsb))),),
            "held": lambda s: s[0]}
