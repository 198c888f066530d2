"""ST's ACIM GUI (MC SDK for induction motors): ``acim_motor_parameters.h``.

SI floats, printed with 7 decimals; the GUI writes both magnetizing inductances, the
dynamic model's L_m and the steady-state L_ms = 2/3·L_m (``LMS``), and the magnetizing
current as an amplitude: ``IMAGN_A`` = √2·I_m (both public headers in
``tests/data/headers/st/`` print √2 × a round RMS value: 0.7778175 = √2·0.55,
2.3193102 = √2·1.64).

>>> a = {"rs_ohm": 0.6, "rr_ohm": 0.4, "lls_h": 0.009, "llr_h": 0.009, "lm_h": 0.0525,
...      "lms_h": 0.035, "ls_h": 0.0615, "lr_h": 0.0615, "tau_r_s": 0.15375,
...      "tau_s_s": 0.1025, "sigma": 0.27126714, "magnetizing_current_a": 0.55}
>>> n = {"motor": {"rated_voltage_v": 42 * 3 ** 0.5, "rated_freq_hz": 50.0}}
>>> round(acim(a, n)["constants"]["IMAGN_A"]["ideal"], 7)
0.7778175
"""

from __future__ import annotations

import math

from ..common import real

__all__ = ["acim", "SOURCE", "DECIMALS"]

#: Decimals the generator prints (the C compiler rounds that text to a float).
DECIMALS = 7

SOURCE = "novaksta/MEZ-ACIM-FOC : Inc/acim_motor_parameters.h"


def acim(a: dict, n: dict) -> dict:
    """ST's ACIM constants for the ``acim`` section ``a`` of the normalized input ``n``."""
    m = n["motor"]
    rows = (("RS", a["rs_ohm"], "Ω", "R_s"), ("RR", a["rr_ohm"], "Ω", "R_r"),
            ("LLS", a["lls_h"], "H", "L_ls"), ("LLR", a["llr_h"], "H", "L_lr"),
            ("LMS", a["lms_h"], "H", "2/3·L_m"), ("LM", a["lm_h"], "H", "L_m"),
            ("LR", a["lr_h"], "H", "L_lr + L_m"), ("LS", a["ls_h"], "H", "L_ls + L_m"),
            ("TAU_R", a["tau_r_s"], "s", "L_r/R_r"), ("TAU_S", a["tau_s_s"], "s", "L_s/R_s"),
            ("SIGMA", a["sigma"], "", "1 − L_m²/(L_s·L_r)"),
            ("IMAGN_A", math.sqrt(2.0) * a["magnetizing_current_a"], "A", "√2·I_m"),
            ("NOMINAL_PHASE_VOLTAGE", m["rated_voltage_v"] / math.sqrt(3.0), "V",
             "U_LL/√3 (RMS)"),
            ("NOMINAL_FREQ", m["rated_freq_hz"], "Hz", "f_n"))
    return {"constants": {k: real(k, v, u, e, SOURCE, single=True, decimals=DECIMALS) for k, v, u, e in rows},
            "not_covered": "FLUX_K and NOMINAL_CURRENT (board-scaled by CURRENT_CONV_FACTOR), "
                           "the LSO observer's gains (acim_lso_parameters.h: GUI settings)",
            "not_covered_zh": "FLUX_K 与 NOMINAL_CURRENT（按 CURRENT_CONV_FACTOR 随板卡换算）、"
                              "LSO 观测器增益（acim_lso_parameters.h：GUI 设置项）"}
