"""NXP MCAT's ACIM FOC application: its float constants (``m1_acim_appconfig.h``).

MCAT writes SI floats for the induction motor (no fractional scaling).  Its generator is
not public; each formula below reproduces every printed digit of two public generated
headers (``tests/data/headers/nxp/acim_*.h``; ``tests/py/test_acim.py``)::

    M1_RFO_KR_INV_GAIN       L_r/L_m
    M1_RFO_LS_TOT_LEAK_GAIN  (L_s·L_r − L_m²)/L_m = σ·L_s·L_r/L_m
    M1_RFO_PSI_RA1_GAIN      τ_r/(τ_r + T_s)        (backward Euler of the current model)
    M1_RFO_PSI_RB1_GAIN      L_m·T_s/(τ_r + T_s)
    M1_RFO_TRQ_CNST          1.5·p·L_m/L_r          (amplitude-invariant dq)
    M1_MRAS_SPDCNST          30/(π·p)               (electrical rad/s → rpm)
    M1_D_KP_GAIN             2ζω_0·σ·L_s − R_s      (R_s, not R_σ), the same for q
    M1_D_KI_GAIN             ω_0²·σ·L_s·T_s

with ω_0 = 2π·current_loop.bandwidth_hz and ζ = current_loop.damping.

>>> a = {"lm_h": 0.487, "ls_h": 0.534, "lr_h": 0.534, "tau_r_s": 0.534 / 23.004,
...      "sigma_ls_h": 0.534 - 0.487 ** 2 / 0.534, "rs_ohm": 25.223}
>>> n = {"motor": {"pole_pairs": 2}, "drive": {"ts_s": 1e-4},
...      "current_loop": {"bandwidth_hz": 150.0, "damping": 1.0}}
>>> round(acim(a, n)["constants"]["M1_D_KP_GAIN"]["ideal"], 9)
144.165322099
"""

from __future__ import annotations

import math

from ..common import real

__all__ = ["acim", "SOURCE", "DECIMALS"]

#: Decimals the generator prints (the C compiler rounds that text to a float).
DECIMALS = 12

SOURCE = ("Masmiseim36/nxpSDK : boards/hvpkv58f/demo_apps/mc_acim/m1_acim_appconfig.h "
          "(formula fitted to its printed values)")


def acim(a: dict, n: dict) -> dict:
    """NXP's ACIM constants for the ``acim`` section ``a`` of the normalized input ``n``."""
    lm, ls, lr, tau_r = a["lm_h"], a["ls_h"], a["lr_h"], a["tau_r_s"]
    p, ts = n["motor"]["pole_pairs"], n["drive"]["ts_s"]
    w0, zeta = 2.0 * math.pi * n["current_loop"]["bandwidth_hz"], n["current_loop"]["damping"]
    kp = 2.0 * zeta * w0 * a["sigma_ls_h"] - a["rs_ohm"]
    ki = w0 * w0 * a["sigma_ls_h"] * ts
    rows = (("M1_RFO_KR_INV_GAIN", lr / lm, "", "L_r/L_m"),
            ("M1_RFO_LS_TOT_LEAK_GAIN", (ls * lr - lm * lm) / lm, "H", "(L_s·L_r − L_m²)/L_m"),
            ("M1_RFO_PSI_RA1_GAIN", tau_r / (tau_r + ts), "", "τ_r/(τ_r + T_s)"),
            ("M1_RFO_PSI_RB1_GAIN", lm * ts / (tau_r + ts), "H", "L_m·T_s/(τ_r + T_s)"),
            ("M1_RFO_TRQ_CNST", 1.5 * p * lm / lr, "N·m/(Wb·A)", "1.5·p·L_m/L_r"),
            ("M1_MRAS_SPDCNST", 30.0 / (math.pi * p), "rpm·s/rad", "30/(π·p)"),
            ("M1_D_KP_GAIN", kp, "V/A", "2ζω_0·σL_s − R_s"),
            ("M1_D_KI_GAIN", ki, "V/A", "ω_0²·σL_s·T_s"),
            ("M1_Q_KP_GAIN", kp, "V/A", "2ζω_0·σL_s − R_s"),
            ("M1_Q_KI_GAIN", ki, "V/A", "ω_0²·σL_s·T_s"))
    return {"constants": {k: real(k, v, u, e, SOURCE, single=True, decimals=DECIMALS) for k, v, u, e in rows},
            "not_covered": "M1_RFO_PSI_SA1/SA2 (the stator-flux integrator's cut-off, an MCAT "
                           "setting), the speed PI and the field-weakening gains",
            "not_covered_zh": "M1_RFO_PSI_SA1/SA2（定子磁链积分器的截止频率，MCAT 的设置项）、"
                              "速度 PI 与弱磁增益"}
