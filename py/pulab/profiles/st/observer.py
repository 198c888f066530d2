"""ST MCSDK's state observer (STO) and PLL integers: GAIN1/GAIN2 (C2/C4), F2, PLL gains.

Default: the Motor Control Workbench's own rule, which ST does not publish, reconstructed
from the printed integers of 13 public MCSDK projects (tests/data/headers/st/
observer_sets.json names each repository, path and commit, and which macro each hits).
With a = 1 − RS·T/LS (the current model's pole), T = 1/f_reg::

    GAIN1 = F1·K1,  K1 = −(3/4)·(1 + a)
    GAIN2 = F2·K2,  K2 = 3·(4 − a)/(16·c3),  c3 = E·T/(LS·MAX_CURRENT),
                    E = MAX_BEMF_VOLTAGE's argument rounded to nearest (not truncated)
    F2 = the largest power of two ≤ 16384 keeping GAIN2 in int16
    PLL_KP_GAIN = 532·N·p/f_reg        over PLL_KPDIV = 16384
    PLL_KI_GAIN = 376832·N·p/f_reg²    over PLL_KIDIV = 65535 (LOG2 → 16)

N = MAX_APPLICATION_SPEED_RPM, p the pole pairs.  K1, K2 place the error poles below at
z = a/4 and 1/4: the open-loop poles (a, and 1 of the back-EMF integrator) divided by 4.
The PLL gains grow with the electrical top speed N·p/60 (the constants are bracketed by
the headers: 532.000..532.015 and 345·65536/60 within ±0.07 %).  The CORDIC observer's
CORD_F1, CORD_F2, CORD_GAIN1, CORD_GAIN2 equal F1, F2, GAIN1, GAIN2 in the three collected
headers that print both (guojie12/PMSM-FOC, valentinognev/STM32_MCSDK_Project, two sets);
it has no PLL.  ``profiles.st.observer_design``
= true replaces this rule by pulab's design described next.


The observer as ``STO_PLL_CalcElAngle`` runs it, per axis in current and back-EMF digits
(sto_pll_speed_pos_fdbk.c, public MCSDK copies found by exact-string search; path not pinned)::

    F1·î' = F1·î − C1·î + C2·(î − i) + C5·v − C3·ê
    F2·ê' = F2·ê + C4·(î − i)            (+ the ω·ê cross term, C6)

so with c_k = C_k/F1 (k = 1, 2, 3) and c4 = C4/F2 its error poles are the roots of
``z² − (2 − c1 + c2)·z + (1 − c1 + c2) + c3·c4``.  C1, C3, C5 are parameters_conversion.h's
(:mod:`pulab.profiles.st.scaling`); GAIN1 (= C2) and GAIN2 (= C4) are the Workbench's, whose
rule ST does not publish (ST community threads 4378 and 817925 ask for it).  The rule above aims
at z = a/4 and 1/4, but K2 uses the rounded back-EMF where C3 truncates it, so the loop as
stored sits elsewhere (dronectl/g431-mcsdk: z = 0.057 and 0.435 for an aim of 0.243 and 0.25,
:func:`poles`).  With ``profiles.st.observer_design`` pulab places the two poles at the images e^{sT} of s² + 2ζω0·s + ω0² (``observer.bemf_f0_hz``, ``observer.bemf_damping``)::

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
from .scaling import constants as _constants, max_current

__all__ = ["observer", "poles", "workbench"]

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


_WB_SRC = derived("the Motor Control Workbench's rule, reconstructed from 13 public MCSDK "
                  "projects' drive_parameters.h (tests/data/headers/st/observer_sets.json)")

#: PLL_KP_GAIN·f_reg/(N·p) and PLL_KI_GAIN·f_reg²/(N·p) of the Workbench (module docstring)
_KP_PER, _KI_PER = 532.0, 345.0 * 65536.0 / 60.0


def workbench(rs: float, ls: float, f_reg: float, e_max_v: float, i_max_a: float,
              n_max_rpm: float, pp: int) -> dict:
    """The Workbench's real-valued K1, K2 and PLL gains (before F1/F2 and the divisors).

    Parameters
    ----------
    rs : float
        RS, Ω.
    ls : float
        LS, H.
    f_reg : float
        Control rate PWM_FREQUENCY/REGULATION_EXECUTION_RATE, Hz.
    e_max_v : float
        MAX_BEMF_VOLTAGE's argument N·1.2·Ke·√2/(1000·√3), V (rounded to nearest here).
    i_max_a : float
        MAX_CURRENT, A.
    n_max_rpm : float
        MAX_APPLICATION_SPEED_RPM.
    pp : int
        Pole pairs.

    Returns
    -------
    dict
        ``k1``, ``k2`` (GAIN1/F1, GAIN2/F2), ``kp``, ``ki`` (PLL_KP_GAIN, PLL_KI_GAIN before
        rounding).

    Examples
    --------
    dronectl/g431-mcsdk's motor (printed: GAIN1 −24217 with F1 16384, PLL 213 and 8):

    >>> w = workbench(0.35, 6e-4, 20000, 15.68, 3.3 / (2 * 0.003 * 9.14), 4000, 2)
    >>> round(w["k1"] * 16384, 1), round(w["kp"], 1), round(w["ki"], 2)
    (-24217.6, 212.8, 7.54)
    """
    t = 1.0 / f_reg
    a = 1.0 - rs * t / ls
    c3 = math.floor(e_max_v + 0.5) * t / (ls * i_max_a)
    fe = n_max_rpm * pp
    return {"k1": -0.75 * (1.0 + a), "k2": 3.0 * (4.0 - a) / (16.0 * c3) if c3 > 0 else None,
            "kp": _KP_PER * fe / f_reg, "ki": _KI_PER * fe / (f_reg * f_reg)}


def _workbench_constants(ctx: dict, opt: dict, c: dict, out: dict) -> dict:
    f1, f_reg = opt["f1"], round(1.0 / ctx["ts"])
    w = workbench(ctx["rs"], ctx["lq"], f_reg, c["MAX_BEMF_VOLTAGE"]["ideal"], max_current(opt),
                  60.0 * ctx["f_base"] / ctx["pp"], ctx["pp"])
    out["GAIN1"] = fixed("GAIN1", w["k1"] * f1, 16, 0, 1.0 / f1, "", "F1·(−3/4)·(2 − RS·T/LS)",
                         _WB_SRC, fmt="int16_t")
    if w["k2"] is not None:
        f2 = opt.get("f2") or pow2_divisor(w["k2"])
        out["F2"] = fixed("F2", f2, 16, 0, 1.0, "", "largest power of two ≤ 16384 with GAIN2 "
                          "in int16", _WB_SRC, fmt="int16_t")
        out["GAIN2"] = fixed("GAIN2", w["k2"] * f2, 16, 0, 1.0 / f2, "",
                             "F2·3·(4 − a)/(16·round(E)·T/(LS·MAX_CURRENT))", _WB_SRC,
                             fmt="int16_t")
    # the Workbench prints PLL_KIDIV as 65535; ST's LOG2 macro maps it to 16 (a shift by 16)
    for name, div, x, expr in (("PLL_KP_GAIN", 16384, w["kp"], "532·N·p/f_reg"),
                               ("PLL_KI_GAIN", 65535, w["ki"], "376832·N·p/f_reg²")):
        out[name] = fixed(name, x, 16, 0, 1.0 / (div + (div & 1)), "", expr, _WB_SRC,
                          fmt=f"int16_t / {div}")
        out[name.replace("_GAIN", "DIV")] = fixed(name.replace("_GAIN", "DIV"), div, 16, 0, 1.0,
                                                  "", "as the Workbench prints it", _WB_SRC,
                                                  fmt="uint16_t", signed=False)
    return out


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
    if not opt.get("observer_design"):
        return _workbench_constants(ctx, opt, c, out)
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
