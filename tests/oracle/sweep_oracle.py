"""Independent boundaries of the seed's inductance code, for the sweep tests (never imports pulab).

Written from the seed (1.4-3 … 1.4-6, the C statements) and docs/contract.md only, with
plain Python integers: the firmware's Ulong arithmetic is exact integer arithmetic reduced
modulo 2^32, division truncates, the store into Uint16 keeps the value modulo 2^16.

Where pulab's sweep bisects on doubles, this oracle walks: it scans the raw integer (the
firmware's Current or Voltage) for the first value whose status changes, then finds the
first double of the SI input that converts to that raw integer by stepping with
``math.nextafter`` from (k − ½)/scale — a different method, so the two agree only if both
are right.
"""

from __future__ import annotations

import math

U32 = 1 << 32


def raw_of(si: float, scale: float) -> int:
    """Contract: x = float(si)·scale, round to nearest, ties away from zero."""
    x = float(si) * scale
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


def m_base_l(voltage: int, current: int, full_freq01: int) -> int | None:
    """m_BaseL after its two statements (seed 1.4-3); None when Current = 0."""
    if current == 0 or full_freq01 == 0:
        return None
    m = (voltage * 3678 % U32) // current
    return (m * 5000 % U32) // full_freq01


def ld_status(ld: int, voltage: int, current: int, full_freq01: int) -> str:
    """'div0', 'store' or 'ok' for gMotorExtPer.LD (seed 1.4-5, 1.4-6)."""
    base = m_base_l(voltage, current, full_freq01)
    if not base:
        return "div0"
    m = ((ld << 14) + (base >> 1)) % U32
    value = m // base // 10
    return "store" if value > 0xFFFF else "ok"


def first_status_change(status_of_raw, lo: int, hi: int) -> tuple[int, str, str] | None:
    """The first raw integer in lo..hi whose status differs from lo's: (k, old, new)."""
    first = status_of_raw(lo)
    for k in range(lo + 1, hi + 1):
        s = status_of_raw(k)
        if s != first:
            return k, first, s
    return None


def first_double(k: int, scale: float) -> float:
    """The smallest double v with raw_of(v, scale) ≥ k (for k ≥ 1, increasing conversion)."""
    v = (k - 0.5) / scale
    while raw_of(v, scale) >= k:
        v = math.nextafter(v, -math.inf)
    while raw_of(v, scale) < k:
        v = math.nextafter(v, math.inf)
    return v


def pm_ki(rs_ohm: float, rated_voltage_v: float, rated_current_a: float, ts_s: float,
          bandwidth_hz: float = 500.0) -> int:
    """pm_ki = round(ω_c·Rs·I_b/U_b·Ts·2^16) for the bandwidth design, rms bases (seed 2.2-9)."""
    ki = 2.0 * math.pi * bandwidth_hz * rs_ohm
    x = ki * rated_current_a / (rated_voltage_v / math.sqrt(3.0)) * ts_s * 65536.0
    return int(math.copysign(math.floor(abs(x) + 0.5), x))
