"""Example code for the tracer: the seed's Inovance blocks and a TI IQmath line.

The Inovance statements are quoted from the seed (§1.4.1 eq. 1.4-1/1.4-2,
§1.4.2 eq. 1.4-3 … 1.4-6, §1.4.3 eq. 1.4-23 … 1.4-25, §2.2 eq. 2.2-2 and the PI
update), with the seed's typo ``Votage`` corrected; the FreqPer line is the one
:mod:`pulab.profiles.inovance.code` runs, and the PI block sets ``minu = -maxu`` (the seed's
lower limit, left implicit there).  Each input variable is named as in the firmware, so
the page prefills it from the report's ``raw`` integers.

Examples
--------
>>> from .tracing import trace
>>> r = trace(EXAMPLES["rpm"]["code"], "c28x", {"gMotorExtInfo.RsPm": 1500,
...           "gMotorInfo.Current": 150, "gMotorInfo.Voltage": 17})
>>> r["vars"]["gMotorExtPer.Rpm"]["value"]     # seed 1.4-1
15022
"""

from __future__ import annotations

__all__ = ["EXAMPLES"]

_RPM = """\
// seed 1.4.1: stator resistance per unit, Q16 (eq. 1.4-1, 1.4-2)
Uint16 gMotorExtInfo.RsPm;      // 1 mΩ
Uint16 gMotorInfo.Current;      // 0.01 A
Uint16 gMotorInfo.Voltage;      // 1 V
Ulong m_UData;
Uint16 gMotorExtPer.Rpm;        // @q gMotorExtPer.Rpm Q16
m_UData = ((Ulong)gMotorExtInfo.RsPm * (Ulong)gMotorInfo.Current)/gMotorInfo.Voltage;
gMotorExtPer.Rpm = ((Ulong)m_UData * 18597)>>14;
"""

_LD = """\
// seed 1.4.2: d-axis inductance per unit, Q13 (eq. 1.4-3 ... 1.4-6)
Uint16 gMotorInfo.Voltage, gMotorInfo.Current, gBasePar.FullFreq01;
Uint16 gMotorExtInfo.LD;        // 0.01 mH
Ulong m_BaseL, m_Ulong;
Uint16 gMotorExtPer.LD;         // @q gMotorExtPer.LD Q13
m_BaseL = ((Ulong)gMotorInfo.Voltage * 3678)/gMotorInfo.Current;
m_BaseL = ((Ulong)m_BaseL * 5000)/gBasePar.FullFreq01; //Q15
m_Ulong = ((Ulong)gMotorExtInfo.LD <<14) + (m_BaseL >>1);
m_Ulong = m_Ulong / m_BaseL;
gMotorExtPer.LD = m_Ulong / 10; // Q13
"""

_FLUX = """\
// seed 1.4.3: rotor flux per unit, Q12 (eq. 1.4-23 ... 1.4-25)
Uint16 gMotorInfo.FreqRated01, gBasePar.FullFreq01;   // 0.01 Hz
Uint16 gMotorExtInfo.BemfVolt;  // 0.1 V
Uint16 gMotorInfo.Voltage;      // 1 V
Uint16 gMotorInfo.FreqPer;      // @q gMotorInfo.FreqPer Q15
Ulong m_Ulong;
Uint16 gMotorExtPer.FluxRotor;  // @q gMotorExtPer.FluxRotor Q12
gMotorInfo.FreqPer = ((Ulong)gMotorInfo.FreqRated01<<15)/gBasePar.FullFreq01;
m_Ulong = ((Long)gMotorExtInfo.BemfVolt <<12) / (gMotorInfo.Voltage *10); //Q12
gMotorExtPer.FluxRotor = (m_Ulong << 15) / gMotorInfo.FreqPer; //Q12
"""

_MAXU = """\
// seed 2.2: voltage limit, Q12 and Q24 (eq. 2.2-2)
Uint16 gUDC.uDCFilter;          // 0.1 V
Uint16 gMotorInfo.Voltage;      // 1 V
long data1, pm_maxout_vol, maxu;  // @q pm_maxout_vol Q12
data1 = ((long)gUDC.uDCFilter * 2316L)>>15; // Udc/sqrt(2)/10
pm_maxout_vol = (data1<<12)/gMotorInfo.Voltage;
maxu = (long)pm_maxout_vol<<12;
"""

_PI = """\
// seed 2.2: one current-PI update (error Q12, kp Q12, ki Q16, integral Q24)
long pm_integral_d, pm_error_id, pm_kp_d, pm_ki_d, maxu, pm_maxout_vol;
long minu, data1, pm_ud;
minu = -maxu;                   // the integral's lower limit
pm_integral_d = pm_integral_d + (pm_error_id * pm_ki_d >> 4); //Q24,28-4
pm_integral_d = __IQsat(pm_integral_d, maxu, minu);
data1 = (pm_integral_d + pm_error_id * pm_kp_d)>>12;
data1 = __IQsat(data1, pm_maxout_vol, -pm_maxout_vol);
pm_ud = data1;
"""

_IQ = """\
// TI IQmath: _IQmpy is the 64-bit product >> GLOBAL_Q (floor), then 32 bits
#define GLOBAL_Q 24
_iq gain, err;                  // @q gain Q24
_iq out = _IQmpy(gain, err);    // @q out Q24
long floor_shift = err >> 12;   // ">>" rounds toward -inf ...
long trunc_div = err / 4096;    // ... "/" toward zero: one LSB apart for negative err
Uint16 Voltage;
long wraps_on_c28x = Voltage * 10;  // 16-bit int on C28x, 32-bit on ARM
"""

#: Name → {"title", "code"}; titles in English and Chinese for the page.
EXAMPLES = {
    "rpm": {"title": "Inovance: stator resistance Rpm (seed 1.4.1)",
            "title_zh": "汇川：定子电阻 Rpm（种子 1.4.1）", "code": _RPM},
    "ld": {"title": "Inovance: inductance LD (seed 1.4.2)",
           "title_zh": "汇川：电感 LD（种子 1.4.2）", "code": _LD},
    "flux": {"title": "Inovance: rotor flux FluxRotor (seed 1.4.3)",
             "title_zh": "汇川：转子磁链 FluxRotor（种子 1.4.3）", "code": _FLUX},
    "maxu": {"title": "Inovance: voltage limit maxu (seed 2.2)",
             "title_zh": "汇川：电压限幅 maxu（种子 2.2）", "code": _MAXU},
    "pi": {"title": "Inovance: current PI update (seed 2.2)",
           "title_zh": "汇川：电流 PI 更新（种子 2.2）", "code": _PI},
    "iqmath": {"title": "TI IQmath _IQmpy, >> vs /, and a 16-bit product",
               "title_zh": "TI IQmath _IQmpy、>> 与 / 的差别、16 位乘积", "code": _IQ},
}
