"""The seed's vendor blocks over intervals of raw integers: what the family prover
(:mod:`pulab.analyses.prove`) still evaluates by hand.

The report, the simulations and every concrete point run the seed's C itself
(:mod:`pulab.profiles.inovance_code`); this module keeps the statements' interval version
(:class:`~pulab.fixedpoint.interval.ICInt` through the operators of
:mod:`pulab.fixedpoint.cint`) and the error bound built on its floors, until the prover
runs the same C through the tracer's interval evaluator (:mod:`pulab.ctrace.abstract`).
Each statement's text is the C line it evaluates.

>>> from pulab.fixedpoint.interval import ICInt
>>> b = Block()
>>> VENDOR_CODE["FreqPer"](b, {"FreqRated01": ICInt(100, 200, UINT16),
...                            "FullFreq01": ICInt(22000, 22000, UINT16)}, "10uH")
ICInt(148, 297, Uint16, [])
>>> b.trace[-1]["code"]
'gMotorInfo.FreqPer = ((Ulong)gMotorInfo.FreqRated01<<15)/gBasePar.FullFreq01;'
"""

from __future__ import annotations

import math

from ..fixedpoint.cint import INT32, UINT16, UINT32, CDivisionByZero, CInt, CType
from ..profiles.inovance_code import SQRT3, TWO_PI
from ..schema.errors import InputError

__all__ = ["Block", "VENDOR_CODE", "error_bound"]


class Block:
    """Runs the statements of one vendor code block and records the trace."""

    def __init__(self) -> None:
        self.trace: list[dict] = []

    def let(self, code: str, var: str, ctype: CType, expr: CInt, meaning: str,
            extra_flags: tuple = ()) -> CInt:
        """Assign ``expr`` to a variable of ``ctype``, as the C assignment converts it."""
        stored = expr.cast(ctype)
        flags = set(expr.flags) | set(extra_flags)
        if stored.value != expr.value:
            # Conversion into the destination: for gMotorExtPer.* (Uint16) the
            # firmware silently keeps the value modulo 65536.
            flags.add("store" if ctype == UINT16 else "wrap")
        self.trace.append({"code": code, "var": var, "type": ctype.name,
                           "value": stored.value, "meaning": meaning,
                           "flags": sorted(flags)})
        return stored.clean()

    def result(self, q: int, ideal: float, si: float, unit: str) -> dict:
        last = self.trace[-1]
        flags = sorted({f for s in self.trace for f in s["flags"]})
        value = last["value"]
        return {"value": value, "ideal": ideal, "q": q, "type": last["type"], "si": si,
                "unit": unit,
                "error_pct": 0.0 if ideal == 0 else 100.0 * (value - ideal) / ideal,
                "flags": flags, "trace": self.trace}


def _u16(raw: dict, name: str) -> CInt:
    v = raw[name]
    # A prover passes an interval of the parameter (pulab.fixedpoint.interval), already a CInt.
    return v if isinstance(v, CInt) else CInt(v, UINT16)


def _divide(a: CInt, b: CInt, field: str, why: str) -> CInt:
    try:
        return a // b
    except CDivisionByZero:
        raise InputError(f"raw.{field}", code="firmware_div0", why=why) from None


def _rpm_code(b: Block, raw: dict) -> None:
    m = b.let("m_UData = ((Ulong)gMotorExtInfo.RsPm * (Ulong)gMotorInfo.Current)"
              "/gMotorInfo.Voltage;", "m_UData", UINT32,
              _divide(_u16(raw, "RsPm").cast(UINT32) * _u16(raw, "Current").cast(UINT32),
                      _u16(raw, "Voltage"), "Voltage", "Voltage = 0"),
              "R_s[mΩ]·I_b[0.01 A]/U_LL[V] = 10^5/√3 · R_pu")
    b.let("gMotorExtPer.Rpm = ((Ulong)m_UData * 18597)>>14;", "gMotorExtPer.Rpm", UINT16,
          (m * CInt(18597, INT32).cast(UINT32)) >> 14, "R_pu·2^16 (Q16)")


def _base_l_steps(b: Block, raw: dict) -> CInt:
    m = b.let("m_BaseL = ((Ulong)gMotorInfo.Voltage * 3678)/gMotorInfo.Current;",
              "m_BaseL", UINT32,
              _divide(_u16(raw, "Voltage").cast(UINT32) * CInt(3678, INT32).cast(UINT32),
                      _u16(raw, "Current"), "Current", "Current = 0"),
              "U_LL·3678/I_b[0.01 A]")
    return b.let("m_BaseL = ((Ulong)m_BaseL * 5000)/gBasePar.FullFreq01; //Q15",
                 "m_BaseL", UINT32,
                 _divide(m * CInt(5000, INT32).cast(UINT32), _u16(raw, "FullFreq01"),
                         "FullFreq01", "FullFreq01 = 0"),
                 "≈ 2·10^4·L_b[H]; 3678 ≈ 2·10^4/(√3·π)")


def _inductance_code(b: Block, raw: dict, name: str, unit: str) -> None:
    base = _base_l_steps(b, raw)
    m = b.let(f"m_Ulong = ((Ulong)gMotorExtInfo.{name} <<14) + (m_BaseL >>1);", "m_Ulong",
              UINT32, (_u16(raw, name).cast(UINT32) << 14) + (base >> 1),
              f"{name}·2^14 + m_BaseL/2")
    if base.value == 0:  # (an interval's value is a pair: its division flags div0 instead)
        # Blame the divisor that made m_BaseL truncate to zero.
        culprit = "Current" if b.trace[0]["value"] == 0 else "FullFreq01"
        raise InputError(f"raw.{culprit}", code="firmware_div0",
                         why="m_BaseL = Voltage·3678/Current·5000/FullFreq01 = 0")
    m = b.let("m_Ulong = m_Ulong / m_BaseL;", "m_Ulong", UINT32, m // base,
              "10·L_pu·2^13")
    b.let(f"gMotorExtPer.{name} = m_Ulong / 10; // Q13", f"gMotorExtPer.{name}", UINT16,
          m // CInt(10, INT32).cast(UINT32),
          "10·L_pu·2^13 (µH ≠ 0.01 mH)" if unit == "uH"
          else "L_pu·2^13 (Q13)", ("unit_uH",) if unit == "uH" else ())


def _freq_per_code(b: Block, raw: dict) -> CInt:
    return b.let("gMotorInfo.FreqPer = ((Ulong)gMotorInfo.FreqRated01<<15)/gBasePar.FullFreq01;",
          "gMotorInfo.FreqPer", UINT16,
          _divide(_u16(raw, "FreqRated01").cast(UINT32) << 15, _u16(raw, "FullFreq01"),
                  "FullFreq01", "FullFreq01 = 0"),
          "f_n/f_b·2^15 (Q15)")


def _flux_code(b: Block, raw: dict, freq_per: CInt) -> None:
    # Voltage*10 is unsigned int (16-bit) arithmetic on C2000, then promoted to long.
    v10 = _u16(raw, "Voltage") * CInt(10, UINT16)
    m = b.let("m_Ulong = ((Long)gMotorExtInfo.BemfVolt <<12) / (gMotorInfo.Voltage *10); //Q12",
              "m_Ulong", UINT32,
              _divide(_u16(raw, "BemfVolt").cast(INT32) << 12, v10, "Voltage",
                      "Voltage*10 ≡ 0 (mod 2^16)"),
              "2π·f_n·ψ_r/U_b·2^12")
    b.let("gMotorExtPer.FluxRotor = (m_Ulong << 15) / gMotorInfo.FreqPer; //Q12",
          "gMotorExtPer.FluxRotor", UINT16,
          _divide(m << 15, freq_per, "FreqRated01",
                  "FreqPer = 0 (FreqRated01·2^15 < FullFreq01, or ≡ 0 mod 2^16)"),
          "ψ_r/ψ_b·2^12 (Q12)")


def _max_vol_code(b: Block, raw: dict) -> CInt:
    d = b.let("data1 = ((long)gUDC.uDCFilter * 2316L)>>15; // Udc/sqrt(2)/10", "data1", INT32,
              (_u16(raw, "uDCFilter").cast(INT32) * CInt(2316, INT32)) >> 15,
              "U_dc/√2 [V] (2316 ≈ 2^15/(10·√2))")
    return b.let("pm_maxout_vol = (data1<<12)/gMotorInfo.Voltage;", "pm_maxout_vol", INT32,
                 _divide(d << 12, _u16(raw, "Voltage"), "Voltage", "Voltage = 0"),
                 "(U_dc/√2)/U_LL·2^12 (Q12)")


def _maxu_code(b: Block, mo: CInt) -> None:
    b.let("maxu = (long)pm_maxout_vol<<12;", "maxu", INT32, mo << 12,
          "(U_dc/√2)/U_LL·2^24 (Q24)")


#: The C statements alone of each vendor result, run on a block ``b`` (its ``trace`` gets one
#: step per statement) over raw integers or over intervals of them
#: (:mod:`pulab.fixedpoint.interval`): the code a prover evaluates is the code the report runs.
VENDOR_CODE = {
    "Rpm": lambda b, raw, unit: _rpm_code(b, raw),
    "LD": lambda b, raw, unit: _inductance_code(b, raw, "LD", unit),
    "LQ": lambda b, raw, unit: _inductance_code(b, raw, "LQ", unit),
    "FreqPer": lambda b, raw, unit: _freq_per_code(b, raw),
    "FluxRotor": lambda b, raw, unit: _flux_code(b, raw, _freq_per_code(Block(), raw)),
    "pm_maxout_vol": lambda b, raw, unit: _max_vol_code(b, raw),
    "maxu": lambda b, raw, unit: _maxu_code(b, _max_vol_code(Block(), raw)),
}


def _low(step: dict) -> int:
    v = step["value"]
    return v[0] if isinstance(v, tuple) else v


def _floor(low: int, exponent: int):
    """floor(y)/y, raised to ``exponent`` (±1), for every real y ≥ ``low`` (a positive
    integer, the floor's lowest value): floor(y)/y ∈ (1 − 1/low, 1].  None when unbounded."""
    if low < 1 or exponent < 0 and low < 2:
        return None
    f = 1.0 - 1.0 / low
    return (f, 1.0) if exponent > 0 else (1.0, 1.0 / f)


def _ld_factors(trace: list, unit: str) -> list:
    """LD/LQ over its ideal (seed 1.4-3 … 1.4-15): with B = m_BaseL, z = L·2^14/B and
    h = floor(B/2)/B ∈ [1/2 − 1/(2B), 1/2], m = floor(z + h) differs from z by
    (−1/2 − 1/(2B), 1/2]; then floor(m/10); B itself is V·3678·5000/(I·F) times two floors."""
    b1, b, _, m, ld = (_low(s) for s in trace)
    z = m - 0.5  # m ≤ z + 1/2
    if z <= 0 or b < 1:
        return [None]
    k = (1e-6 if unit == "uH" else 1e-5) * 8192.0 * TWO_PI * SQRT3 / 1e4
    c = 16384.0 / (10.0 * 3678.0 * 5000.0) / k
    return [(c, c), _floor(b1, -1), _floor(b, -1),
            (1.0 - (0.5 + 0.5 / b) / z, 1.0 + 0.5 / z), _floor(ld, 1)]


def error_bound(name: str, raw: dict, unit: str):
    """A bound on |error_pct| of vendor result ``name`` (its integer against ``ideal``) for
    every raw point of ``raw`` (integers or intervals,
    :class:`~pulab.fixedpoint.interval.ICInt`); None where a step it runs (FreqPer's too,
    for FluxRotor) may wrap, change a store or divide by zero, or a floor may reach 0.

    Every result is its ideal times a constant (the code's integer constants over the real
    ones: 18597/2^14 for 10^5/(√3·2^16)…) times, per floor of the code, floor(y)/y — in the
    numerator, or in the denominator (FreqPer inside FluxRotor, m_BaseL inside LD) — and, for
    LD/LQ, its rounded division; each floor's lowest value over the box bounds its factor.
    The bound is rounded up by 1e-10 percentage points for the doubles' own rounding.

    >>> from pulab.profiles.inovance_code import freq_per
    >>> raw = {"FreqRated01": 22000, "FullFreq01": 22000}
    >>> error_bound("FreqPer", raw, "10uH") >= abs(freq_per(raw)["error_pct"])
    True
    """
    b = Block()
    VENDOR_CODE[name](b, raw, unit)
    lows = [_low(s) for s in b.trace]
    steps = list(b.trace)
    if name in ("LD", "LQ"):
        factors = _ld_factors(b.trace, unit)
    elif name == "FluxRotor":  # m·2^15/FreqPer: FreqPer's floor divides
        fp = Block()
        _freq_per_code(fp, raw)
        steps += fp.trace  # a FreqPer that wraps is its own failure, but breaks this bound
        factors = [_floor(lows[0], 1), _floor(lows[1], 1), _floor(_low(fp.trace[0]), -1)]
    elif name in ("pm_maxout_vol", "maxu"):  # maxu = pm_maxout_vol·2^12 exactly
        if name == "maxu":
            b = Block()
            _max_vol_code(b, raw)
            steps += b.trace
        c = 2316.0 / 32768.0 * 10.0 * math.sqrt(2.0)
        factors = [(c, c)] + [_floor(_low(s), 1) for s in b.trace]
    else:
        c = 18597.0 / 16384.0 / (SQRT3 * 65536.0 / 1e5) if name == "Rpm" else 1.0
        factors = [(c, c)] + [_floor(v, 1) for v in lows]
    if any(f is None for f in factors) or any({"wrap", "store", "div0"} & set(s["flags"])
                                               for s in steps):
        return None
    lo = math.prod(f[0] for f in factors)
    hi = math.prod(f[1] for f in factors)
    return 100.0 * max(1.0 - lo, hi - 1.0, 0.0) + 1e-10
