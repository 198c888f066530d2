"""ST MCSDK's state observer (STO) and PLL integers: GAIN1/GAIN2 (C2/C4), F2, PLL gains.

The observer as ``STO_PLL_CalcElAngle`` runs it, per axis in current and back-EMF digits
(sto_pll_speed_pos_fdbk.c, public MCSDK copies found by exact-string search; path not pinned)::

    F1·î' = F1·î − C1·î + C2·(î − i) + C5·v − C3·ê
    F2·ê' = F2·ê + C4·(î − i)            (+ the ω·ê cross term, C6)

so with c_k = C_k/F1 (k = 1, 2, 3) and c4 = C4/F2 its error poles are the roots of
``z² − (2 − c1 + c2)·z + (1 − c1 + c2) + c3·c4``.  C1, C3, C5 are parameters_conversion.h's
(:mod:`pulab.profiles.st.scaling`); GAIN1 (= C2) and GAIN2 (= C4) are the Workbench's, which
publishes no rule (ST community thread 4378, 2025 thread 817925 ask for it; the Workbench
placed dronectl/g431-mcsdk's at z = 0.435 and 0.057, :func:`poles`).  pulab places the two poles
at the images e^{sT} of s² + 2ζω0·s + ω0² (``observer.bemf_f0_hz``, ``observer.bemf_damping``)::

    c2 = z1 + z2 − 2 + c1,    c4 = (z1·z2 − z1 − z2 + 1)/c3

F2 = the largest power of two ≤ 16384 keeping GAIN2 in int16 (``profiles.st.f2`` overrides).
The PLL (``STO_ExecutePLL``) is a PI from E·sin(θ − θ̂) in back-EMF digits to the speed in
digits per period (65536 = 2π): its loop gain grows with the back-EMF E.  pulab sizes it at
the lowest closed-loop speed (``observer.min_speed_rpm``) for ``observer.tracking_f0_hz``,
``observer.tracking_damping``::

    PLL_KP_GAIN/PLL_KPDIV = 2ζω_t/K,   PLL_KI_GAIN/PLL_KIDIV = ω_t²/(K·f)   (divisors ≤ 32768),
    K = E_min·32768/MAX_BEMF_VOLTAGE·2π·f/65536

Examples
--------
>>> [round(z.real, 4) for z in poles(477 / 16384, -24217 / 16384, 340 / 16384, 26260 / 1024)]
[0.0573, 0.4355]
"""

from __future__ import annotations

import cmath
import math

from ..common import TWO_PI, derived, fixed, pow2_divisor
from .scaling import constants as _constants

__all__ = ["observer", "poles"]

_SRC = derived("pole placement of the STO error loop (the Workbench's GAIN1/GAIN2 rule is not "
               "public); the loop is sto_pll_speed_pos_fdbk.c STO_PLL_CalcElAngle")
_NARROW = ("sto_pll_speed_pos_fdbk.h STO_PLL_Handle_t: int16_t hC1..hC5 (public MCSDK copies "
           "found by exact-string search; path not pinned)")
_PLL_SRC = derived("PLL PI sized at the lowest closed-loop speed (the Workbench's rule is not "
                   "public); the loop is sto_pll_speed_pos_fdbk.c STO_ExecutePLL")


def poles(c1: float, c2: float, c3: float, c4: float) -> list:
    """The STO's two error poles (complex), sorted by real part, for c_k as above."""
    b, c = 2.0 - c1 + c2, (1.0 - c1 + c2) + c3 * c4
    r = cmath.sqrt(b * b - 4.0 * c)
    return sorted([(b - r) / 2.0, (b + r) / 2.0], key=lambda z: (z.real, z.imag))


def _placed(f0_hz: float, zeta: float, ts: float) -> tuple:
    """z1 + z2 and z1·z2 of the images of s² + 2ζω0·s + ω0² (both real)."""
    w0 = TWO_PI * f0_hz
    r = cmath.sqrt(complex(zeta * zeta - 1.0)) * w0
    z1, z2 = cmath.exp((-zeta * w0 + r) * ts), cmath.exp((-zeta * w0 - r) * ts)
    return (z1 + z2).real, (z1 * z2).real


def observer(ctx: dict, opt: dict) -> dict:
    """GAIN1, GAIN2, F2 and the PLL integers for the settings ``ctx['observer']``."""
    s = ctx.get("observer")
    if s is None:
        return {}
    c = _constants(ctx, opt)
    f1, f_reg = opt["f1"], round(1.0 / ctx["ts"])
    c1, c3 = c["C1"]["value"] / f1, c["C3"]["value"] / f1
    out = {}
    # STO_PLL_Handle_t keeps C1..C5 in int16_t hC1..hC5 (the macros are int32_t; the handle's
    # initializer narrows them, and the firmware wraps): one beyond int16 is shown as hC<k>
    for k in ("C1", "C3", "C5"):
        if not -32768 <= c[k]["value"] <= 32767:
            out[f"h{k}"] = fixed(f"h{k}", c[k]["value"], 16, 0, c[k]["si"] / c[k]["value"],
                                 c[k]["unit"], f"{k} narrowed into the handle's int16_t h{k}",
                                 _NARROW, fmt="int16_t")
    total, prod = _placed(s["bemf_f0_hz"], s["bemf_damping"], ctx["ts"])
    c2 = total - 2.0 + c1
    out["GAIN1"] = fixed("GAIN1", c2 * f1, 16, 0, 1.0 / f1, "", "F1·(z1 + z2 − 2 + C1/F1)", _SRC,
                         fmt="int16_t")
    if c3 <= 0.0:  # C3 truncated to 0: the back-EMF does not reach the current model
        return out
    c4 = (prod - total + 1.0) / c3
    f2 = opt.get("f2") or pow2_divisor(c4)
    out["F2"] = fixed("F2", f2, 16, 0, 1.0, "", "largest power of two ≤ 16384 with GAIN2 in int16",
                      _SRC, fmt="int16_t")
    out["GAIN2"] = fixed("GAIN2", c4 * f2, 16, 0, 1.0 / f2, "", "F2·(z1·z2 − z1 − z2 + 1)/(C3/F1)",
                         _SRC, fmt="int16_t")
    e_v = s["min_speed_rpm"] * ctx["pp"] * math.pi / 30.0 * ctx["psi_peak"]
    bemf_max = c["MAX_BEMF_VOLTAGE"]["value"]
    if bemf_max <= 0:
        return out
    k = e_v * 32768.0 / bemf_max * TWO_PI * f_reg / 65536.0
    wt = TWO_PI * s["tracking_f0_hz"]
    kp, ki = 2.0 * s["tracking_damping"] * wt / k, wt * wt / (k * f_reg)
    # hKpDivisor/hKiDivisor are uint16_t powers of two (the shift build uses their log2)
    for name, div, x, per in (("PLL_KP_GAIN", pow2_divisor(kp, largest=32768), kp, k),
                              ("PLL_KI_GAIN", pow2_divisor(ki, largest=32768), ki, k * f_reg)):
        out[name] = fixed(name, x, 16, div.bit_length() - 1, per, "", f"gain at the back-EMF of "
                          "observer.min_speed_rpm", _PLL_SRC, fmt=f"int16_t / {div}")
        out[name.replace("_GAIN", "DIV")] = fixed(name.replace("_GAIN", "DIV"), div, 16, 0, 1.0,
                                                  "", "largest power of two ≤ 32768 fitting int16",
                                                  _PLL_SRC, fmt="uint16_t", signed=False)
    return out
