"""The Inovance C2000 normalization code of seed 1.4 and 2.2, bit-exact, as a trace.

Each result is computed statement by statement with :mod:`pulab.fixedpoint.cint`, so the
integer after every statement is the one the firmware holds, with the wrap and
truncation it suffers.  Each result also carries ``ideal``, the exact real
value the code approximates from the same raw inputs, and ``si``, what the
integer means back in SI units for this motor.

Raw inputs are the firmware's Uint16 parameters:

========== ===================================== ==============
name       meaning                               unit
========== ===================================== ==============
Voltage    rated line-to-line RMS voltage        1 V
Current    rated RMS current                     0.01 A
FullFreq01 base (maximum) frequency f_b          0.01 Hz
FreqRated01 rated frequency                      0.01 Hz
RsPm       stator resistance per phase           1 mΩ
LD, LQ     d/q inductance                        0.01 mH (or 1 µH)
BemfVolt   back-EMF line RMS at rated frequency  0.1 V
uDCFilter  DC bus voltage                        0.1 V
========== ===================================== ==============

Examples
--------
>>> raw = {"Voltage": 17, "Current": 150, "RsPm": 1500, "FullFreq01": 22000}
>>> r = rpm(raw)
>>> r["value"], round(r["ideal"], 1)        # seed 1.4-1, 1.4-2
(15022, 15023.6)
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..fixedpoint.cint import INT32, UINT16, UINT32, CDivisionByZero, CInt, CType
from ..schema.errors import InputError
from ..schema.fields import RAW_FIELDS
from ..fixedpoint.qformat import iqsat, round_half_away

__all__ = [
    "RAW_FIELDS", "RAW_SCALE", "raw_source", "raw_value", "raw_split", "raw_from_si",
    "round_half_away", "vendor_split",
    "rpm", "inductance", "freq_per", "flux_rotor", "max_output_voltage",
    "vendor_results", "error_bound", "VENDOR_RESULTS", "VENDOR_READS", "VENDOR_CODE", "Block",
    "current_pi_step", "PiStep", "to_si",
]

SQRT3 = math.sqrt(3.0)
TWO_PI = 2.0 * math.pi

#: The SI input each raw firmware field (the schema's RAW_FIELDS) comes from, and SI → raw scale.
RAW_SCALE = {
    "Voltage": ("motor.rated_voltage_v", 1.0),
    "Current": ("motor.rated_current_a", 100.0),
    "FullFreq01": ("drive.base_freq_hz", 100.0),
    "FreqRated01": ("motor.rated_freq_hz", 100.0),
    "RsPm": ("motor.rs_ohm", 1000.0),
    "LD": ("motor.ld_h", None),  # depends on the inductance unit
    "LQ": ("motor.lq_h", None),
    "BemfVolt": ("motor.bemf_v", 10.0),
    "uDCFilter": ("drive.udc_v", 10.0),
}
#: SI henry → raw LD/LQ for each inductance unit.
INDUCTANCE_SCALE = {"10uH": 1e5, "uH": 1e6}


def raw_source(name: str, inductance_unit: str) -> tuple[str, float]:
    """The SI input path a raw field comes from and the SI → raw scale factor."""
    path, scale = RAW_SCALE[name]
    return path, scale if scale is not None else INDUCTANCE_SCALE[inductance_unit]


def raw_value(name: str, si_value: float, inductance_unit: str) -> int:
    """The raw integer of field ``name`` for its SI value (before the Uint16 range check).

    >>> raw_value("Current", 69.475, "10uH"), raw_value("Current", 69.47500000000001, "10uH")
    (6947, 6948)
    """
    return round_half_away(float(si_value) * raw_source(name, inductance_unit)[1])


def raw_split(si: dict, inductance_unit: str, given: dict) -> tuple[dict, dict]:
    """Firmware integers from SI inputs, split into those a Uint16 parameter holds and those
    it cannot; values in ``given`` override.

    Parameters
    ----------
    si : dict
        Flat mapping from the SI field path (``motor.rs_ohm`` …) to its value.
    inductance_unit : {'10uH', 'uH'}
    given : dict
        Raw values the user entered directly.

    Returns
    -------
    raw : dict
        name → integer in 0..65535.
    outside : dict
        name → integer the SI value needs but Uint16 cannot hold (a limit of the firmware,
        not of the motor).

    Raises
    ------
    InputError
        Naming ``raw.NAME`` when a value the user typed is outside Uint16.

    Examples
    --------
    >>> raw, outside = raw_split({"drive.base_freq_hz": 3266.67}, "10uH", {})  # doctest: +SKIP
    """
    raw, outside = {}, {}
    for name in RAW_FIELDS:
        path = RAW_SCALE[name][0]
        v = given[name] if name in given else raw_value(name, si[path], inductance_unit)
        if 0 <= v <= 0xFFFF:
            raw[name] = v
        elif name in given:
            raise InputError(f"raw.{name}", code="raw_outside_given", value=v)
        else:
            outside[name] = v
    return raw, outside


def raw_from_si(si: dict, inductance_unit: str, given: dict) -> dict:
    """Firmware integers from SI inputs, every one required to fit (see :func:`raw_split`).

    Raises
    ------
    InputError
        Naming ``raw.NAME`` when a value is outside Uint16 (0..65535).
    """
    raw, outside = raw_split(si, inductance_unit, given)
    for name, v in outside.items():
        raise InputError(f"raw.{name}", code="raw_outside_from", value=v,
                         source=RAW_SCALE[name][0])
    return raw


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


def _bases(raw: dict) -> tuple[float, float, float]:
    """U_b (phase RMS), I_b and f_b as the firmware's raw values define them (seed 1.4-13);
    NaN for a parameter the firmware does not hold (no result that needs it is computed)."""
    return (raw.get("Voltage", math.nan) / SQRT3, raw.get("Current", math.nan) / 100.0,
            raw.get("FullFreq01", math.nan) / 100.0)


def rpm(raw: dict) -> dict:
    """Stator resistance per unit, Q16 (seed 1.4-1, 1.4-2)."""
    if raw["Current"] == 0:
        # The C code computes 0, but per unit of Z_b = U_b/0 the number means nothing.
        raise InputError("raw.Current", code="firmware_div0", why="Z_b = U_b/I_b with Current = 0")
    b = Block()
    _rpm_code(b, raw)
    u_b, i_b, _ = _bases(raw)
    z_b = u_b / i_b if i_b else math.inf
    ideal = (raw["RsPm"] / 1000.0) / z_b * 65536.0
    return b.result(16, ideal, b.trace[-1]["value"] / 65536.0 * z_b, "Ω")


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


def inductance(raw: dict, axis: str, unit: str = "10uH") -> dict:
    """d- or q-axis inductance per unit, Q13 (seed 1.4-3 … 1.4-15).

    With ``unit='uH'`` the raw value is taken in µH, which is what the seed
    assumed; the code was written for 0.01 mH, so the result is 10× the Q13
    value — the seed's "×10" puzzle — and is flagged ``unit_uH``.
    """
    name = "LD" if axis == "d" else "LQ"
    b = Block()
    _inductance_code(b, raw, name, unit)
    u_b, i_b, f_b = _bases(raw)
    l_b = u_b / (TWO_PI * f_b * i_b) if f_b * i_b else math.inf
    l_si = raw[name] * (1e-6 if unit == "uH" else 1e-5)
    ideal = l_si / l_b * 8192.0
    return b.result(13, ideal, b.trace[-1]["value"] / 8192.0 * l_b, "H")


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


def freq_per(raw: dict) -> dict:
    """Rated frequency per unit, Q15."""
    b = Block()
    _freq_per_code(b, raw)
    ideal = raw["FreqRated01"] / raw["FullFreq01"] * 32768.0
    return b.result(15, ideal, b.trace[-1]["value"] / 32768.0 * raw["FullFreq01"] / 100.0,
                    "Hz")


def _freq_per_code(b: Block, raw: dict) -> CInt:
    return b.let("gMotorInfo.FreqPer = ((Ulong)gMotorInfo.FreqRated01<<15)/gBasePar.FullFreq01;",
          "gMotorInfo.FreqPer", UINT16,
          _divide(_u16(raw, "FreqRated01").cast(UINT32) << 15, _u16(raw, "FullFreq01"),
                  "FullFreq01", "FullFreq01 = 0"),
          "f_n/f_b·2^15 (Q15)")


def flux_rotor(raw: dict, freq_per_value: int) -> dict:
    """Permanent-magnet flux per unit, Q12 (seed 1.4-23 … 1.4-25)."""
    b = Block()
    _flux_code(b, raw, CInt(freq_per_value, UINT16))
    ideal = (raw["BemfVolt"] / 10.0) / raw["Voltage"] * raw["FullFreq01"] \
        / raw["FreqRated01"] * 4096.0
    u_b, _, f_b = _bases(raw)
    psi_b = u_b / (TWO_PI * f_b)
    return b.result(12, ideal, b.trace[-1]["value"] / 4096.0 * psi_b, "Wb")


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


def max_output_voltage(raw: dict) -> tuple[dict, dict]:
    """pm_maxout_vol (Q12) and maxu (Q24), seed 2.2-1, 2.2-2."""
    b = Block()
    mo = _max_vol_code(b, raw)
    ideal = (raw["uDCFilter"] / 10.0 / math.sqrt(2.0)) / raw["Voltage"] * 4096.0
    vol = b.result(12, ideal, mo.value / 4096.0 * raw["Voltage"], "V")
    b2 = Block()
    _maxu_code(b2, mo)
    maxu = b2.result(24, ideal * 4096.0, b2.trace[-1]["value"] / 16777216.0 * raw["Voltage"],
                     "V")
    return vol, maxu


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


#: Each vendor result of seed 1.4 and 2.2, in report order, computed from the raw integers
#: alone (with the blocks it reads, e.g. FluxRotor reads FreqPer), so one can be computed
#: without the others — a sweep bisecting one integer's boundary needs only that one.
VENDOR_RESULTS = {
    "Rpm": lambda raw, unit: rpm(raw),
    "LD": lambda raw, unit: inductance(raw, "d", unit),
    "LQ": lambda raw, unit: inductance(raw, "q", unit),
    "FreqPer": lambda raw, unit: freq_per(raw),
    "FluxRotor": lambda raw, unit: flux_rotor(raw, freq_per(raw)["value"]),
    "pm_maxout_vol": lambda raw, unit: max_output_voltage(raw)[0],
    "maxu": lambda raw, unit: max_output_voltage(raw)[1],
}


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


#: The raw fields each vendor result reads (the C statements of its block and the blocks it
#: reads), so a caller may reuse a result while these stay the same.
VENDOR_READS = {
    "Rpm": ("RsPm", "Current", "Voltage"),
    "LD": ("Voltage", "Current", "FullFreq01", "LD"),
    "LQ": ("Voltage", "Current", "FullFreq01", "LQ"),
    "FreqPer": ("FreqRated01", "FullFreq01"),
    "FluxRotor": ("BemfVolt", "Voltage", "FreqRated01", "FullFreq01"),
    "pm_maxout_vol": ("uDCFilter", "Voltage"),
    "maxu": ("uDCFilter", "Voltage"),
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


def vendor_results(raw: dict, inductance_unit: str) -> dict:
    """Every vendor result of seed 1.4 and 2.2, keyed as in the report contract."""
    return {name: f(raw, inductance_unit) for name, f in VENDOR_RESULTS.items()}


def vendor_split(raw: dict, inductance_unit: str) -> tuple[dict, dict]:
    """The vendor results the firmware can compute from ``raw``, and why the others cannot be.

    A result is left out when a raw field it reads is missing from ``raw`` (it did not fit
    Uint16) or when its C code divides by zero.

    Returns
    -------
    results : dict
        name → result, as :func:`vendor_results`.
    failed : dict
        name → :class:`InputError` (``raw.NAME``, the field that stops it).
    """
    results, failed = {}, {}
    for name, f in VENDOR_RESULTS.items():
        missing = [k for k in VENDOR_READS[name] if k not in raw]
        if missing:
            failed[name] = InputError(f"raw.{missing[0]}", code="raw_missing", name=missing[0])
            continue
        try:
            results[name] = f(raw, inductance_unit)
        except InputError as e:
            failed[name] = e
    return results, failed


def to_si(name: str, value: int, raw: dict, inductance_unit: str = "10uH") -> float:
    """What a firmware integer means in SI for this motor (the inverse of ``ideal``).

    >>> round(to_si("Rpm", 15022, {"Voltage": 17, "Current": 150, "FullFreq01": 22000}), 4)
    1.4998
    """
    u_b, i_b, f_b = _bases(raw)
    if name == "Rpm":
        return value / 65536.0 * u_b / i_b
    if name in ("LD", "LQ"):
        return value / 8192.0 * u_b / (TWO_PI * f_b * i_b)
    if name == "FreqPer":
        return value / 32768.0 * f_b
    if name == "FluxRotor":
        return value / 4096.0 * u_b / (TWO_PI * f_b)
    if name == "pm_maxout_vol":
        return value / 4096.0 * raw["Voltage"]
    if name == "maxu":
        return value / 16777216.0 * raw["Voltage"]
    raise ValueError(f"unknown vendor result {name!r}")


class PiStep(NamedTuple):
    """State after one vendor current-PI update."""

    integral: int
    out: int
    flags: frozenset


def current_pi_step(integral: int, error: int, kp: int, ki: int, maxu: int,
                    maxout: int, trace: list | None = None) -> PiStep:
    """One update of the vendor current PI (seed 2.2), all arithmetic in 32-bit long.

    Parameters
    ----------
    integral : int, Q24 (per unit of rated line voltage)
    error : int, Q12 current error (per unit of rated current)
    kp : int, Q12 ; ki : int, Q16 (the "new" integral gain, Ts folded in)
    maxu : int, Q24 ; maxout : int, Q12
    trace : list, optional
        When given, one step per C statement is appended (as in vendor results).

    Returns
    -------
    PiStep
        New integral (Q24), output voltage (Q12) and the flags raised
        (``wrap``, ``truncation``, ``saturate``).

    Examples
    --------
    >>> current_pi_step(0, 410, 1000, 3000, 1 << 24, 4096)
    PiStep(integral=76875, out=118, flags=frozenset({'truncation'}))
    """
    e = CInt(error, INT32)
    # minu = -maxu and -pm_maxout_vol are long negations: -(-2^31) wraps to -2^31 (a maxu
    # that wrapped in its own shift), so the limits come from the C, not from Python's -x.
    minu = -CInt(maxu, INT32)
    s = CInt(integral, INT32) + ((e * CInt(ki, INT32)) >> 4)
    integ = iqsat(s.value, maxu, minu.value)
    d = (CInt(integ, INT32) + e * CInt(kp, INT32)) >> 12
    minout = -CInt(maxout, INT32)
    out = iqsat(d.value, maxout, minout.value)
    if trace is not None:
        for code, value, flags, meaning in (
                ("pm_integral_d = pm_integral_d + (pm_error_id * pm_ki_d >> 4); //Q24,28-4",
                 s.value, s.flags, "integral + Δi·ki (Q12·Q16 = Q28, >>4 → Q24)"),
                ("pm_integral_d = __IQsat(pm_integral_d, maxu, minu);", integ,
                 {"saturate"} if integ != s.value else set(), "∈ [−maxu, maxu]"),
                ("data1 = (pm_integral_d + pm_error_id * pm_kp_d)>>12;", d.value, d.flags,
                 "(Q24 + Q12·Q12) >> 12 → Q12"),
                ("data1 = __IQsat(data1, pm_maxout_vol, -pm_maxout_vol);", out,
                 {"saturate"} if out != d.value else set(), "∈ [−pm_maxout_vol, pm_maxout_vol]"),
                ("pm_ud = data1;", out, set(), "u_d/U_LL·2^12 (Q12)")):
            trace.append({"code": code, "var": code.split(" =")[0], "type": "long",
                          "value": value, "meaning": meaning, "flags": sorted(flags)})
    flags = set(s.flags | d.flags | minu.flags | minout.flags)
    if integ != s.value or out != d.value:
        flags.add("saturate")
    return PiStep(integ, out, frozenset(flags))
