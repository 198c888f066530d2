"""The magic constants of the vendor code and what each stands for.

========  =======================  ===========  ===========================
constant  exact value              ≈            used in
========  =======================  ===========  ===========================
18597     2^30·√3/10^5             18597.75     Rpm (seed 1.4-2)
3678      2·10^4/(√3·π)            3675.53      m_BaseL for LD/LQ (1.4-4)
2316      2^15/(10·√2)             2317.05      data1 = U_dc/√2 (2.2-2)
========  =======================  ===========  ===========================

Examples
--------
>>> c = magic_constants()
>>> round(c["2316"]["rel_error"] * 100, 3)
-0.045
"""

from __future__ import annotations

import math

__all__ = ["magic_constants"]


def magic_constants() -> dict:
    """Each constant: value, exact, expression, derivation (en, zh), rel_error, used_in."""
    table = [
        (18597, 2.0 ** 30 * math.sqrt(3.0) / 1e5, "2^30·√3/10^5", "Rpm",
         "RsPm[mΩ]·Current[0.01 A]/Voltage[V] = 10^5·R_s/(√3·Z_b); ×c/2^14 must give "
         "R_s/Z_b·2^16, so c = 2^30·√3/10^5",
         "RsPm[mΩ]·Current[0.01 A]/Voltage[V] = 10^5·R_s/(√3·Z_b)；乘 c 再右移 14 位须得 "
         "R_s/Z_b·2^16，故 c = 2^30·√3/10^5"),
        (3678, 2e4 / (math.sqrt(3.0) * math.pi), "2·10^4/(√3·π)", "LD, LQ",
         "m_BaseL must equal 2·10^4·L_b (L in 0.01 mH, Q14 → /10 → Q13); "
         "L_b = U_LL·10^4/(√3·2π·FullFreq01·Current), so c·5000 = 2·10^8/(2√3·π)",
         "m_BaseL 须等于 2·10^4·L_b（L 以 0.01 mH 计，Q14 → /10 → Q13）；"
         "L_b = U_LL·10^4/(√3·2π·FullFreq01·Current)，故 c·5000 = 2·10^8/(2√3·π)"),
        (2316, 2.0 ** 15 / (10.0 * math.sqrt(2.0)), "2^15/(10·√2)", "pm_maxout_vol",
         "uDCFilter is in 0.1 V; (uDCFilter·c)>>15 must give U_dc/√2 in volts, "
         "so c = 2^15/(10·√2)",
         "uDCFilter 以 0.1 V 计；(uDCFilter·c)>>15 须得以伏为单位的 U_dc/√2，"
         "故 c = 2^15/(10·√2)"),
    ]
    return {str(v): {"value": v, "exact": exact, "expression": expr,
                     "rel_error": (v - exact) / exact, "used_in": used, "derivation": why,
                     "derivation_zh": why_zh}
            for v, exact, expr, used, why, why_zh in table}
