"""TI's enhanced sliding-mode observer (eSMO) of the universal motor-control lab, in float32.

``ESMO_setParams`` and ``ESMO_updateFilterParams`` (anyway-blows/ti-c2000-motor-control-sdk :
libraries/observers/esmo/source/esmo.c) compute, from the user_mtr1.h macros, the fields the
observer runs with (float32_t in ``ESMO_Obj``, esmo.h)::

    Fdsmopos = exp(−R_s/L_d·T_s)             Gdsmopos = (2·V_sf/I_sf)/R_s·(1 − Fdsmopos)
    Fqsmopos = exp(−R_s/L_q·T_s)             Gqsmopos = (2·V_sf/I_sf)/R_s·(1 − Fqsmopos)
    Kslf     = USER_MOTOR1_BEMF_KSLF_FC_Hz·2π·T_s·f_max          (back-EMF low-pass)
    lpf_a1   = 1/(1 + 2π·USER_MOTOR1_SPEED_LPF_FC_Hz·T_s),  lpf_b0 = 1 − lpf_a1
    thetaDelta = f_max·T_s

V_sf/I_sf = USER_M1_ADC_FULL_SCALE_VOLTAGE_V/USER_M1_ADC_FULL_SCALE_CURRENT_A (the 4096s
cancel), f_max = USER_MOTOR1_FREQ_MAX_HZ (``maxFrequency_Hz``: pulab's
``profiles.ti.full_scale_freq_hz``).  The ADC full scales are the board's (bus ``max_v``,
current ``full_range_a``), else ``full_scale_voltage_v`` and 2·``full_scale_current_a``.

pulab's settings set TI's two filter macros: the back-EMF filter's corner is Kslf/(2π·T_s) =
FC·f_max, so USER_MOTOR1_BEMF_KSLF_FC_Hz = ``observer.bemf_f0_hz``/f_max (TI's 2.0 at
400 Hz is an 800 Hz corner); USER_MOTOR1_SPEED_LPF_FC_Hz = ``observer.speed_filter_hz``.
The PLL (``ESMO_full_run``) is proportional only (``pll_Ki`` = 0): θ += Kp·(Δθ/2π)·f_max·T_s
per period, a first-order loop crossing over at Kp·f_max rad/s, so pulab's ``pll_Kp`` =
2π·``observer.tracking_f0_hz``/f_max (TI schedules it between USER_MOTOR1_PLL_KP_MIN and
_MAX with the speed; their values are tuned by hand, no rule is published).

Each value is the float32 the firmware holds (:func:`pulab.profiles.common.real`), computed
here in double and rounded once (the firmware's float32 arithmetic differs by a few ulp).

Examples
--------
>>> ctx = {"rs": 2.98774099, "ld": 0.008926632, "lq": 0.008926632, "ts": 1 / 15000,
...        "observer": {"bemf_f0_hz": 800.0, "speed_filter_hz": 200.0, "tracking_f0_hz": 15.0}}
>>> opt = {"full_scale_voltage_v": 57.528, "full_scale_current_a": 21.428,
...        "full_scale_freq_hz": 400.0}
>>> c = observer(ctx, opt)
>>> round(c["Fdsmopos"]["value"], 6), round(c["USER_MOTOR1_BEMF_KSLF_FC_Hz"]["value"], 6)
(0.977934, 2.0)
"""

from __future__ import annotations

import math

from ..common import TWO_PI, board_value, derived, real

__all__ = ["observer"]

_ESMO = "anyway-blows/ti-c2000-motor-control-sdk : libraries/observers/esmo/source/esmo.c"
_USER = ("anyway-blows/ti-c2000-motor-control-sdk : solutions/universal_motorcontrol_lab/common/"
         "include/user_mtr1.h")


def _f32(name, x, unit, expr, source):
    return real(name, x, unit, expr, source, single=True)


def observer(ctx: dict, opt: dict) -> dict:
    """The eSMO's float32 fields and TI's two filter macros for ``ctx['observer']``."""
    s = ctx.get("observer")
    if s is None:
        return {}
    ts, rs, f_max = ctx["ts"], ctx["rs"], opt["full_scale_freq_hz"]
    v_adc = board_value(ctx, "bus", "max_v", opt["full_scale_voltage_v"])
    i_adc = board_value(ctx, "current", "full_range_a", 2.0 * opt["full_scale_current_a"])
    base_vi = 2.0 * v_adc / i_adc
    fc = s["bemf_f0_hz"] / f_max
    out = {"USER_MOTOR1_BEMF_KSLF_FC_Hz": _f32(
               "USER_MOTOR1_BEMF_KSLF_FC_Hz", fc, "", "observer.bemf_f0_hz/f_max "
               "(Kslf's corner is FC·f_max)", _USER),
           "USER_MOTOR1_SPEED_LPF_FC_Hz": _f32(
               "USER_MOTOR1_SPEED_LPF_FC_Hz", s["speed_filter_hz"], "Hz",
               "observer.speed_filter_hz", _USER)}
    for axis, l_h in (("d", ctx["ld"]), ("q", ctx["lq"])):
        f = math.exp(-rs / l_h * ts)
        out[f"F{axis}smopos"] = _f32(f"F{axis}smopos", f, "", f"exp(−R_s/L_{axis}·T_s)", _ESMO)
        out[f"G{axis}smopos"] = _f32(f"G{axis}smopos", base_vi / rs * (1.0 - f), "",
                                     f"(2·V_sf/I_sf)/R_s·(1 − F{axis}smopos)", _ESMO)
    out["Kslf"] = _f32("Kslf", fc * TWO_PI * ts * f_max, "", "FC·2π·T_s·f_max", _ESMO)
    a1 = 1.0 / (1.0 + TWO_PI * s["speed_filter_hz"] * ts)
    out["lpf_a1"] = _f32("lpf_a1", a1, "", "1/(1 + 2π·f_lpf·T_s)", _ESMO)
    out["lpf_b0"] = _f32("lpf_b0", 1.0 - a1, "", "1 − lpf_a1", _ESMO)
    out["thetaDelta"] = _f32("thetaDelta", f_max * ts, "", "f_max·T_s", _ESMO)
    out["pll_Kp"] = _f32("pll_Kp", TWO_PI * s["tracking_f0_hz"] / f_max, "",
                         "2π·observer.tracking_f0_hz/f_max",
                         derived(f"crossover of the proportional PLL of {_ESMO} ESMO_full_run"))
    return out
