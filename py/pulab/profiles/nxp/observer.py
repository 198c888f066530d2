"""NXP MCAT's sensorless constants: back-EMF observer in d-q, tracking observer, start-up.

MCAT's formulas (Masmiseim36/nxpSDK : middleware/motor_control/freemaster/pmsm_frac/mcat/src/
JS_functions/inner_PoSpeBemfDQ.js, ``clickCalculateBemfDqObsrv``), with ω_max = 2π·p·N_max/60,
N_max = 60·f_base/p::

    M1_BEMF_DQ_KP_GAIN = (2ζω0·L_d − R_s)·I_max/E_max          ACC32
    M1_BEMF_DQ_KI_GAIN = L_d·ω0²·T_s·I_max/E_max               ACC32
    M1_TO_KP_GAIN·2^M1_TO_KP_SHIFT = 2ζω_t/ω_max               FRAC16 mantissa + shift
    M1_TO_KI_GAIN·2^M1_TO_KI_SHIFT = ω_t²·T_s/ω_max
    M1_OL_START_RAMP_INC = ramp/N_max·T_s                       FRAC32
    M1_OL_START_I = I_start/I_max,  M1_MERG_SPEED_TRH = N_merge/N_max   FRAC16

Read in the MCAT-generated headers (tests/data/headers/nxp/observer_README.md), where the
JavaScript above is older than the generator:

- ``M1_TO_SPEED_IIR_B0/B1/A1`` are FRAC32(b0/2), FRAC32(b1/2), FRAC32(−a1/2) of the bilinear
  first-order low-pass at the corner ``observer.speed_filter_hz`` (the JSON's
  ``sensorlessTrackObsrvIIRSpeedCutOff``; the old JavaScript: 0.8·half the speed-loop rate,
  scaled by 4/IIRxCoefsScale = 1/2 — the same halving);
- ``M1_MERG_COEFF`` = (coeff/100)·p·N_merge·T_s/60 (FRAC16): reconstructed, no public file
  states it; it reproduces the linix (p = 2: 0.0025) and the Teknic (p = 4: 0.005) headers,
  both coeff 150 %, N_merge 500 rpm, T_s 100 µs.  The 2020 MCAT wrote
  (coeff/100)·60/(p·N_merge)/T_s/2/32768 instead (the JavaScript's);
- ``M1_N_MIN`` = N_min/N_max, ``M1_E_BLOCK_TRH`` = E_block/E_max (FRAC16).

The tracking observer's three gains are :func:`tracking`'s, which the encoder's observer
(``M1_POSPE_TO_…``, :mod:`pulab.profiles.nxp.appconfig`) shares.

FRAC16(x) and FRAC32(x) truncate toward zero and saturate (RTCESL mlib_types.h), like ACC32.
The observer's own scales (``M1_I_SCALE`` …) and the theta gain are in
:func:`pulab.profiles.nxp.scaling.constants`.
"""

from __future__ import annotations

import math

from ..common import SOURCES, TWO_PI, derived, fixed, mantissa_shift
from .scaling import _acc32, _scales

__all__ = ["observer", "tracking"]

_APPCONFIG = ("MCAT-generated m1_pmsm_appconfig.h headers (tests/data/headers/nxp/"
              "observer_README.md)")


def _frac(name, x, bits, per_unit, unit, expr, source):
    return fixed(name, x, bits, bits - 1, per_unit, unit, expr, source, rounding="zero",
                 clamps=True, fmt=f"FRAC{bits}")


def _gain_shift(name, k, per_unit, unit, expr, source) -> dict:
    """A FRAC16 mantissa with its shift, and the shift as a constant of its own."""
    mant, shift = mantissa_shift(k, f"nxp.{name}_SHIFT")
    gain = fixed(f"{name}_GAIN", mant, 16, 15, per_unit, unit, f"{expr} = mantissa·2^shift",
                 source, rounding="zero", clamps=True, fmt=f"FRAC16 · 2^{shift}", shift=shift)
    return {f"{name}_GAIN": gain,
            f"{name}_SHIFT": fixed(f"{name}_SHIFT", shift, 16, 0, 1.0, "", f"shift of {expr}",
                                   source, fmt="int16")}


def tracking(prefix: str, zeta: float, w0: float, ts: float, w_ref: float, source) -> dict:
    """MCAT's AMCLIB_TrackObsrv gains, each a FRAC16 mantissa with its shift (and the shifts
    as constants of their own): ``{prefix}_KP`` = 2ζω0/ω_ref, ``{prefix}_KI`` = ω0²·T/ω_ref,
    ``{prefix}_THETA`` = T·ω_ref/π, where ω_ref is the speed of the observer's full scale (the
    electrical ω_max for the sensorless observer, the mechanical one for the encoder's).

    >>> g = tracking("M1_POSPE_TO", 1.0, 2 * math.pi * 100, 1e-4, 2 * math.pi * 4400 / 60, "")
    >>> g["M1_POSPE_TO_KP_SHIFT"]["value"], g["M1_POSPE_TO_THETA_SHIFT"]["value"]
    (2, -6)
    """
    return {**_gain_shift(f"{prefix}_KP", 2.0 * zeta * w0 / w_ref, w_ref, "1/s", "2ζω0/ω_ref",
                          source),
            **_gain_shift(f"{prefix}_KI", w0 * w0 * ts / w_ref, w_ref / ts, "1/s²",
                          "ω0²·T/ω_ref", source),
            **_gain_shift(f"{prefix}_THETA", ts * w_ref / math.pi, math.pi / ts, "rad/s",
                          "T·ω_ref/π", source)}


def observer(ctx: dict, opt: dict) -> dict:
    """MCAT's sensorless integers for the settings ``ctx['observer']`` (None: none)."""
    s = ctx.get("observer")
    if s is None:
        return {}
    um, im = _scales(opt)
    em = opt["e_max_v"] if opt["e_max_v"] is not None else um
    ts, rs, ld, pp = ctx["ts"], ctx["rs"], ctx["ld"], ctx["pp"]
    w_max = TWO_PI * ctx["f_base"]
    n_max = 60.0 * ctx["f_base"] / pp
    w0, wt = TWO_PI * s["bemf_f0_hz"], TWO_PI * s["tracking_f0_hz"]
    js, hdr = SOURCES["nxp_bemf"], _APPCONFIG
    out = {
        "M1_BEMF_DQ_KP_GAIN": _acc32("M1_BEMF_DQ_KP_GAIN",
                                     (2.0 * s["bemf_damping"] * w0 * ld - rs) * im / em, em / im,
                                     "V/A", "(2ζω0·L_d − R_s)·I_max/E_max", js),
        "M1_BEMF_DQ_KI_GAIN": _acc32("M1_BEMF_DQ_KI_GAIN", ld * w0 * w0 * ts * im / em,
                                     em / im / ts, "V/(A·s)", "L_d·ω0²·T_s·I_max/E_max", js),
    }
    # M1_TO_THETA_GAIN itself is the profile's (scaling.constants): it is there without observer
    out.update((k, v) for k, v in tracking("M1_TO", s["tracking_damping"], wt, ts, w_max,
                                           js).items() if k != "M1_TO_THETA_GAIN")
    x = TWO_PI * s["speed_filter_hz"] * ts
    b0, a1 = x / (2.0 + x), (x - 2.0) / (2.0 + x)
    for name, v, expr in (("B0", b0 / 2.0, "b0/2"), ("B1", b0 / 2.0, "b1/2"),
                          ("A1", -a1 / 2.0, "−a1/2")):
        out[f"M1_TO_SPEED_IIR_{name}"] = _frac(
            f"M1_TO_SPEED_IIR_{name}", v, 32, 2.0, "",
            f"{expr}, bilinear low-pass at observer.speed_filter_hz", hdr)
    out["M1_OL_START_RAMP_INC"] = _frac("M1_OL_START_RAMP_INC",
                                        s["startup_ramp_rpm_per_s"] / n_max * ts, 32,
                                        n_max / ts, "rpm/s", "ramp/N_max·T_s", js)
    out["M1_OL_START_I"] = _frac("M1_OL_START_I", s["startup_current_a"] / im, 16, im, "A",
                                 "I_start/I_max", js)
    out["M1_MERG_SPEED_TRH"] = _frac("M1_MERG_SPEED_TRH", s["merging_speed_rpm"] / n_max, 16,
                                     n_max, "rpm", "N_merge/N_max", js)
    per = pp * s["merging_speed_rpm"] * ts / 60.0
    out["M1_MERG_COEFF"] = _frac("M1_MERG_COEFF", s["merging_coeff_pct"] / 100.0 * per, 16,
                                 100.0 / per, "%", "(coeff/100)·p·N_merge·T_s/60",
                                 derived("reconstructed from two MCAT headers, " + hdr))
    out["M1_N_MIN"] = _frac("M1_N_MIN", s["min_speed_rpm"] / n_max, 16, n_max, "rpm",
                            "N_min/N_max", hdr)
    out["M1_E_BLOCK_TRH"] = _frac("M1_E_BLOCK_TRH", s["e_block_v"] / em, 16, em, "V",
                                  "E_block/E_max", hdr)
    return out
