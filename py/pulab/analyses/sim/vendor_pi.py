"""The current PI of TI, NXP, ST and Microchip in each vendor's own integer arithmetic.

One step function per vendor, a pure function of integers (the controller state, the
reference and the feedback, the gains and limits), written in the C constructs of the
vendor's public code: the same word sizes, the same shifts (arithmetic, flooring), the
same casts (a 32-bit wrap, an int16 truncation), the same saturating library calls, the
same order.  Each also counts every wrap and saturation it meets in ``ev`` (a dict of
event name → count):

``wrap``
    a C integer operation overflowed and wrapped (two's complement, as the targets do);
``saturate``
    a saturating operation (a library call, an overflow guard) clipped its result;
``integral_limit``, ``output_limit``
    the integral or the output was held at the limit the code is given.

The public files read (never copied) for each form:

TI MotorWare ``pi.h`` ``PI_run_series`` (a public copy found by exact-string search; the
  search tool does not name its repository) with IQmath ``IQmathLib.h``:
  ``Up = _IQmpy(Kp, Error)``, ``Ui = _IQsat(Ui + _IQmpy(Ki, Up), outMax, outMin)``,
  ``Out = _IQsat(Up + Ui + ffwd, outMax, outMin)``; ``_IQmpy`` is the 64-bit product
  shifted right by GLOBAL_Q, kept in 32 bits.
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
ST MCSDK ``pid_regulator.c`` ``PI_Controller`` (public copies found by exact-string search)
  with the limits of ``mc_config.c`` (dronectl/g431-mcsdk : Src/mc_config.c): int16 gains,
  int32 integral with its overflow guard, ±INT16_MAX·TF_KIDIV integral limits, ±INT16_MAX
  output, back-calculation ``wIntegralTerm += wDischarge``.  The default build (arithmetic
  shifts by log2 of the divisors) is simulated, not the FULL_MISRA_C_COMPLIANCY build
  that divides (one LSB apart on negative values, :func:`pulab.profiles.st.pi_first_output`).
Microchip AN1160 ``pi.c`` ``CalcPI`` (JakyHou/SZCCW :
  AN1160_PIC32MM0064GPL036_MCLV_MCHV.X/pi.c; the C form of AN1078's ``CalcPI``): Q15
  gains, int32 ``qdSum``, output ``(int16_t)(U >> 15)`` clamped, anti-windup
  ``Sum += Ki·Err − Kc·Exc``.  A gain above 1 is stored in fewer fractional bits
  (KIP_Q < 15) and multiplied back by 2^(15 − KIP_Q), the DKNP shift of MCAF's
  ``foc_params.h``; AN1160's own CalcPI has no such shift.

Examples
--------
>>> ev = {}
>>> ti_step((0,), 1 << 24, 0, 1 << 23, 1 << 20, 1 << 24, -(1 << 24), 24, ev)
((524288,), 8912896)
>>> st_step((0,), 100, 0, 9456, 2364, 14, 14, 32767 * 16384, ev)
((236400,), 71)
"""

from __future__ import annotations

__all__ = ["EVENTS", "ti_step", "nxp_step", "st_step", "microchip_step", "wrap", "saturate"]

#: Event names, in the order they are reported.
EVENTS = ("wrap", "saturate", "integral_limit", "output_limit")

_I32_MAX = (1 << 31) - 1


def _count(ev: dict, name: str) -> None:
    ev[name] = ev.get(name, 0) + 1


def wrap(x: int, bits: int, ev: dict) -> int:
    """x kept in a signed ``bits`` word (two's complement); a change counts as a ``wrap``."""
    half = 1 << (bits - 1)
    y = ((x + half) & ((half << 1) - 1)) - half
    if y != x:
        _count(ev, "wrap")
    return y


def saturate(x: int, bits: int, ev: dict) -> int:
    """x clipped to a signed ``bits`` word; a clip counts as a ``saturate``."""
    hi = (1 << (bits - 1)) - 1
    if x > hi or x < -hi - 1:
        _count(ev, "saturate")
        return hi if x > hi else -hi - 1
    return x


def _limit(x: int, lo: int, hi: int, ev: dict, name: str) -> int:
    if x > hi:
        _count(ev, name)
        return hi
    if x < lo:
        _count(ev, name)
        return lo
    return x


def _iqmpy(a: int, b: int, q: int, ev: dict) -> int:
    # (long)(((long long)a * b) >> GLOBAL_Q): the shift floors, the cast keeps 32 bits.
    return wrap((a * b) >> q, 32, ev)


def ti_step(state: tuple, ref: int, fb: int, kp: int, ki: int, out_max: int, out_min: int,
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
    ui = _limit(wrap(state[0] + _iqmpy(ki, up, q, ev), 32, ev), out_min, out_max, ev,
                "integral_limit")
    out = _limit(wrap(up + ui, 32, ev), out_min, out_max, ev, "output_limit")
    return (ui,), out


def nxp_step(state: tuple, ref: int, fb: int, kp: int, ki: int, upper: int, lower: int,
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
    acc = _limit(saturate(acc + inc, 32, ev), lower << 16, upper << 16, ev, "integral_limit")
    out = _limit(saturate(prop + acc, 32, ev) >> 16, lower, upper, ev, "output_limit")
    return (acc, e), out


def st_step(state: tuple, ref: int, fb: int, kp: int, ki: int, kp_log: int, ki_log: int,
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
            _count(ev, "saturate")
        elif total >= 0 and integ < 0 and term < 0:
            total = -_I32_MAX
            _count(ev, "saturate")
        integ = _limit(total, -integral_limit, integral_limit, ev, "integral_limit")
    out = wrap((prop >> kp_log) + (integ >> ki_log), 32, ev)
    discharge = 0
    if out > 32767:
        discharge, out = 32767 - out, 32767
        _count(ev, "output_limit")
    elif out < -32767:
        discharge, out = -32767 - out, -32767
        _count(ev, "output_limit")
    integ = wrap(integ + discharge, 32, ev)
    return (integ,), out


def microchip_step(state: tuple, ref: int, fb: int, kp: int, ki: int, kc: int, out_max: int,
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
    out = _limit(out_temp, out_min, out_max, ev, "output_limit")
    u = wrap(wrap(err * ki, 32, ev) * (1 << ki_shift), 32, ev)
    exc = wrap(out_temp - out, 16, ev)
    u = wrap(u - exc * kc, 32, ev)
    return (wrap(total + u, 32, ev),), out
