"""TI's ACI current model (controlSUITE math blocks, ``CUR_CONST_MACRO``), in IQ24.

The ACI sensored-FOC projects compute the current model's constants at start-up in C
``float`` (``cur_const.h``) and store them with ``_IQ()``::

    Tr = Lr/Rr;  Kr = Ts/Tr;  Kt = 1/(Tr*2*PI*fb);  K = Ts*fb      (float32 fields)
    cm1.Kr = _IQ(cm1_const.Kr);  …                                  (long)(x·2^24)

so each integer is the C cast of a float32 result: ``Tr``, ``Kr`` and ``K`` are float
operations; ``Kt`` is computed in double (``PI`` is a double literal) and rounded to float
once.  Kr = T_s/τ_r is the flux update's gain, Kt = 1/(τ_r·ω_b) the slip's per-unit gain
(ω_sl* = Kt·i_q*/i_m*), K = T_s·f_b the angle step per per-unit speed.

>>> a = {"rr_ohm": 0.4, "lr_h": 0.0615}
>>> n = {"drive": {"ts_s": 1e-4, "base_freq_hz": 50.0}}
>>> c = acim(a, n)["constants"]
>>> c["Kr"]["value"], c["Kt"]["value"], c["K"]["value"]
(10912, 347340, 83886)
"""

from __future__ import annotations

import math
import struct

from ..common import fixed

__all__ = ["acim", "SOURCE", "GLOBAL_Q"]

SOURCE = ("asm-jaime/aci_vector_control_F28035_DRV8301 : headers_math_blocks_4.3/cur_const.h "
          "(CUR_CONST_MACRO; _IQ() of each result at start-up)")
#: The projects' GLOBAL_Q (the TI profile's default option).
GLOBAL_Q = 24
#: The macro's PI (a double literal).
_PI = 3.14159265358979


def _f32(x: float) -> float:
    return struct.unpack("<f", struct.pack("<f", x))[0]


def acim(a: dict, n: dict) -> dict:
    """TI's current-model constants for the ``acim`` section ``a`` of the normalized input
    ``n``: the C float results (``ideal``: the exact reals) cast to IQ24 toward zero."""
    rr, lr = _f32(a["rr_ohm"]), _f32(a["lr_h"])
    ts, fb = _f32(n["drive"]["ts_s"]), _f32(n["drive"]["base_freq_hz"])
    tr = _f32(lr / rr)
    stored = {"Kr": _f32(ts / tr), "Kt": _f32(1.0 / (tr * 2.0 * _PI * fb)), "K": _f32(ts * fb)}
    tau_r, t_s, f_b = a["lr_h"] / a["rr_ohm"], n["drive"]["ts_s"], n["drive"]["base_freq_hz"]
    exact = {"Kr": (t_s / tau_r, "T_s/τ_r"), "Kt": (1.0 / (tau_r * 2.0 * math.pi * f_b), "1/(τ_r·ω_b)"),
             "K": (t_s * f_b, "T_s·f_b")}
    out = {}
    for k, (ideal, expr) in exact.items():
        value = int(stored[k] * 2 ** GLOBAL_Q)   # (long)(A·2^24): toward zero
        out[k] = fixed(k, ideal, 32, GLOBAL_Q, 1.0, "pu", expr, SOURCE, rounding="zero",
                       fmt=f"IQ{GLOBAL_Q}", value=value)
    return {"constants": out,
            "not_covered": "the flux estimator's K1…K8 (aci_fe_const.h) and the speed "
                           "estimator's constants (aci_se_const.h)",
            "not_covered_zh": "磁链估计器的 K1…K8（aci_fe_const.h）与速度估计器的常数"
                              "（aci_se_const.h）"}
