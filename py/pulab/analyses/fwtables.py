"""What firmware stores for MTPA and field weakening, each checked against the exact curve.

Every table here is an integer (or float32) routine evaluated for **every input digit** of its
range against the exact curve of :mod:`pulab.analyses.envelope` (the MTPA root, and the field-
weakening trajectory on the current circle, solved per digit), so ``error_bound`` is the largest
error the firmware can make, not a sample.

- :func:`generic_mtpa`, :func:`generic_fw`: N breakpoints, Q``q`` of the current limit, uniform
  in the input digit, linear interpolation (C division toward zero) or a step (hold).
- :func:`microchip_fw`: Microchip AN1078's 18-entry field-weakening curve (``qFwCurve``, speed in
  electrical rpm, index ``(speed − FWONSPEED) >> SPEED_INDEX_CONST``; microchip-pic-avr-solutions/
  lvmc-dspic33ck256mp508-an1078 : lvmc-dspic33ck256mp508-an1078/fdweak.c and userparms.h; pmsm.c
  sets the speed reference in electrical rpm, ENDSPEED_ELECTR … MAXIMUMSPEED_ELECTR).
- :func:`ti_mtpa`: TI's MTPA (``kconst`` = 0.25·ψ/(L_q − L_d), i_d = K − √(K² + I_s²/2), float32;
  anyway-blows/ti-c2000-motor-control-sdk : libraries/control/mtpa/source/mtpa.c and
  libraries/control/mtpa/include/mtpa.h).
- :func:`pi_fw`: a voltage-loop field weakening (ST MCSDK ``FW_CalcCurrRef``, Cuixudong/BLDC_DRV :
  firmware/FOC/foc_f405/MCSDK_v5.4.4-Full/MotorControl/MCSDK/MCLib/Any/Src/flux_weakening_ctrl.c;
  TI ``FWC_computeCurrentAngle``, libraries/control/fwc/include/fwc.h; NXP ``AMCLIB_CtrlFluxWkng``,
  Masmiseim36/nxpSDK : middleware/rtcesl/CM4F_RTCESL_4.5_IAR/AMCLIB/Include/
  AMCLIB_CtrlFluxWkng_FLT.h, held at MCAT's M1_CLOOP_LIMIT): no table, so its constants
  as integers versus their ideal, and the d current its voltage reference settles to versus the
  exact trajectory.
- :func:`microchip_ff`: Microchip's feed-forward law (a lossless one-inductance formula), its
  steady state at full current against the exact trajectory.

Examples
--------
>>> from pulab.analyses.envelope import Limits
>>> m = Limits(3.6, 0.036, 0.051, 0.545, 3, 540 / 3 ** 0.5, 4.3 * 2 ** 0.5)
>>> t = generic_mtpa(m, 8, 15, "linear")
>>> t["values"][:3], round(t["error_bound"], 5)
([0, -109, -435], 0.00505)
"""

from __future__ import annotations

import math
import struct

from . import envelope
from .envelope import (RPM, Limits, base_speed, best_torque, max_speed, mtpa, mtpa_id,
                       _st_digits_per_a, _vendor_options)

__all__ = ["analyze", "fw_id", "generic_mtpa", "generic_fw", "microchip_fw", "microchip_fw_id",
           "ti_mtpa", "ti_fwc", "st_fw", "nxp_fw", "microchip_ff", "pi_fw"]


def _speed_on_circle(m: Limits, th: float) -> float:
    """Electrical rad/s at which the current I·(cos θ, sin θ) needs exactly the voltage limit."""
    i_d, i_q = m.i * math.cos(th), m.i * math.sin(th)
    a = (m.lq * i_q) ** 2 + (m.ld * i_d + m.psi) ** 2
    b = 2.0 * (-(m.r * i_d) * m.lq * i_q + m.r * i_q * (m.ld * i_d + m.psi))
    c = (m.r * m.i) ** 2 - m.v * m.v
    return (-b + math.sqrt(max(b * b - 4.0 * a * c, 0.0))) / (2.0 * a)


class _Circle:
    """The field-weakening d current on the current circle, solved for one speed after another:
    between the MTPA angle (base speed) and π (the maximum speed) the speed at which the circle
    meets the voltage limit rises with the current angle. Secant steps from the last solution
    extrapolated (the first with the last slope), inside a bisection bracket; done when
    the speed is met to 1e-13 relative (the angle then to ~1e-13 rad, i_d to ~1e-13·I)."""

    def __init__(self, m: Limits):
        self.m = m
        self.lo = math.atan2(*reversed(mtpa(m, m.i)))
        self.w_lo, self.w_hi = _speed_on_circle(m, self.lo), _speed_on_circle(m, math.pi)
        self.th, self.w, self.slope, self.d = self.lo, self.w_lo, 0.0, None

    def _derivative(self, th: float) -> float:
        h = 1e-6
        return (_speed_on_circle(self.m, th + h) - _speed_on_circle(self.m, th - h)) / (2.0 * h)

    def id_at(self, w: float) -> float:
        m = self.m
        if w <= self.w_lo:
            return m.i * math.cos(self.lo)
        if w >= self.w_hi:
            return -m.i
        lo, hi = self.lo, math.pi
        th = min(max(self.th + self.slope * (w - self.w), lo), hi)
        if self.d is None:
            self.d = self._derivative(th)
        prev = None
        for _ in range(200):
            f = _speed_on_circle(m, th) - w
            if abs(f) <= 1e-13 * w:
                break
            if f > 0.0:
                hi = th
            else:
                lo = th
            if prev is not None and th != prev[0] and f != prev[1]:
                self.d = (f - prev[1]) / (th - prev[0])     # the secant's slope
            prev = (th, f)
            nxt = th - f / self.d if self.d > 0.0 else 0.5 * (lo + hi)
            if not lo < nxt < hi:
                nxt = 0.5 * (lo + hi)
            if nxt == th:
                break
            th = nxt
        if w != self.w:
            self.slope = (th - self.th) / (w - self.w)
        self.th, self.w = th, w
        return m.i * math.cos(th)


def fw_id(m: Limits, w: float) -> float:
    """The exact field-weakening d current at electrical rad/s ``w`` (the MTPA one below base
    speed; −I at and beyond the maximum speed), on the current circle.

    >>> m = Limits(3.6, 0.036, 0.051, 0.545, 3, 540 / 3 ** 0.5, 4.3 * 2 ** 0.5)
    >>> round(fw_id(m, 700.0), 6), round(best_torque(m, 700.0)[1], 6)
    (-4.818448, -4.818448)
    """
    return _Circle(m).id_at(w)


def _on_circle_until(m: Limits, w_end: float) -> float:
    """The highest speed ≤ ``w_end`` up to which the largest torque lies on the current circle
    (MTPV beyond it when the characteristic current ψ/L_d is inside the limit)."""
    if m.psi / m.ld > m.i:
        return w_end

    def on(w):
        _, i_d, i_q = best_torque(m, w)
        return math.hypot(i_d, i_q) >= m.i * (1.0 - 1e-7)
    if on(w_end):
        return w_end
    lo, hi = base_speed(m), w_end
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if on(mid) else (lo, mid)
    return lo


def _worst(values: list, step: int, count: int, interpolation: str, exact, lsb: float) -> float:
    """max |table(k)·lsb − exact(k)| over the input digits k = 0..count−1 of the generic routine:
    segment j = min(k/step, N−2), ``y[j] + (y[j+1] − y[j])·(k − j·step)/step`` in C integers
    (division toward zero; the last segment extends past its end), or ``y[min(k/step, N−1)]``
    for a step."""
    worst, n = 0.0, len(values)
    for j in range(0, (count - 1) // step + 1):
        first, last = j * step, min((j + 1) * step, count)
        if interpolation == "step":
            y = values[min(j, n - 1)] * lsb
            worst = max(worst, max(abs(y - exact(k)) for k in range(first, last)))
            continue
        s = min(j, n - 2)
        y0, dy, k0 = values[s], values[s + 1] - values[s], s * step
        for k in range(first, last):
            num = dy * (k - k0)
            v = y0 + (num // step if num >= 0 else -(-num // step))
            e = abs(v * lsb - exact(k))
            if e > worst:
                worst = e
    return worst


def _q_of(x: float, lsb: float, flags: list) -> int:
    v = round(x / lsb)
    if not -32768 <= v <= 32767:
        flags.append("out_of_range")
    return max(-32768, min(32767, v))


def _table(quantity, x_lsb, x_unit, k0, step, values, exact_ys, lsb, q, interpolation, worst,
           flags, **extra):
    n = len(values)
    name = "fw_id_of_speed" if x_unit == "rpm" else "mtpa_id_of_iq"
    c = (f"/* {quantity}: breakpoints every {step} input digits from digit {k0} "
         f"({x_lsb:.9g} {x_unit}/digit), Q{q} of the current limit ({lsb:.9g} A/LSB), "
         f"{interpolation} */\n"
         f"static const int16_t {name}[{n}] = {{ {', '.join(map(str, values))} }};")
    return {"quantity": quantity, "c": c, "x": [(k0 + j * step) * x_lsb for j in range(n)],
            "y": exact_ys, "values": values, "format": f"int16 Q{q} of the current limit",
            "scale": lsb, "unit": "A", "x_scale": x_lsb, "x_unit": x_unit,
            "x_first_digit": k0, "x_step_digits": step, "error_bound": worst,
            "error_bound_digits": worst / lsb, "interpolation": interpolation,
            "flags": sorted(set(flags)), **extra}


def generic_mtpa(m: Limits, n: int, q: int, interpolation: str) -> dict:
    """An N-point i_d(i_q) MTPA table, both axes in Q``q`` of the current limit I (LSB I/2^q),
    breakpoints every ``step`` = ⌊K/(N−1)⌋ digits from 0, K the MTPA i_q at I in digits; its
    error is the routine's at every i_q digit 0..K against :func:`~pulab.analyses.envelope.mtpa_id`.
    """
    lsb = m.i / 2.0 ** q
    kmax = min(math.floor(mtpa(m, m.i)[1] / lsb), 2 ** q - 1)
    flags = []
    step = kmax // (n - 1)
    if step < 1:
        step = 1
        flags.append("fewer_digits_than_points")
    ys = [mtpa_id(m, j * step * lsb) for j in range(n)]
    values = [_q_of(y, lsb, flags) for y in ys]
    dl, psi = m.lq - m.ld, m.psi

    def exact(k):   # mtpa_id inlined
        iq = k * lsb
        return -2.0 * dl * iq * iq / (psi + math.sqrt(psi * psi + 4.0 * dl * dl * iq * iq))
    worst = _worst(values, step, kmax + 1, interpolation, exact, lsb)
    return _table("id_a(iq_a)", lsb, "A", 0, step, values, ys, lsb, q, interpolation, worst,
                  flags, x_last_digit=kmax)


def _fw_range(m: Limits, w_end: float, x_lsb: float) -> tuple:
    """(first, last) speed digit of the field-weakening range: base speed up to the end drawn,
    the maximum speed or the start of MTPV, whichever comes first."""
    wmax = max_speed(m)
    top = w_end if wmax is None else min(w_end, wmax)
    return math.ceil(base_speed(m) / x_lsb), math.floor(_on_circle_until(m, top) / x_lsb)


def generic_fw(m: Limits, n: int, q: int, interpolation: str, end_rpm: float) -> dict | None:
    """An N-point i_d(speed) field-weakening table: speed digits of end_rpm/2^q mechanical rpm
    (``end_rpm`` the range drawn), i_d in Q``q`` of I, breakpoints uniform from the first digit
    above base speed; its error is the routine's at every speed digit of the range (base speed to
    the maximum speed, the end drawn or the start of MTPV) against the exact d current on the
    current circle. None when the range holds no digit above base speed."""
    if not end_rpm > 0.0:   # no range (R·I alone exceeds the voltage limit)
        return None
    x_lsb_rpm = end_rpm / 2.0 ** q
    x_lsb = x_lsb_rpm * m.p / RPM
    k0, k1 = _fw_range(m, end_rpm * m.p / RPM, x_lsb)
    if k1 <= k0:
        return None
    lsb = m.i / 2.0 ** q
    flags = [] if m.psi / m.ld > m.i else ["mtpv_not_covered"]
    step = (k1 - k0) // (n - 1)
    if step < 1:
        step = 1
        flags.append("fewer_digits_than_points")
    circle = _Circle(m)
    ys = [circle.id_at((k0 + j * step) * x_lsb) for j in range(n)]
    values = [_q_of(y, lsb, flags) for y in ys]
    circle = _Circle(m)
    worst = _worst(values, step, k1 - k0 + 1, interpolation,
                   lambda k: circle.id_at((k0 + k) * x_lsb), lsb)
    return _table("id_a(speed_rpm)", x_lsb_rpm, "rpm", k0, step, values, ys, lsb, q,
                  interpolation, worst, flags, x_last_digit=k1)


def _q15_macro(x: float) -> int:
    """Microchip's ``Q15()`` macro (general.h): (int16)(32768·x − 0.5) below 0, else
    (int16)(32767·x + 0.5), the cast truncating toward zero."""
    v = int(32768.0 * x - 0.5) if x < 0.0 else int(32767.0 * x + 0.5)
    return ((v + 32768) & 0xFFFF) - 32768


def microchip_fw_id(curve: list, on_speed: int, shift: int, speed: int) -> int:
    """AN1078's ``FieldWeakening(qMotorSpeed)`` (fdweak.c): the first entry up to ``on_speed``,
    then ``curve[i] − ((curve[i] − curve[i+1])·(speed − on_speed − i·2^shift) >> shift)`` with
    ``i = (speed − on_speed) >> shift`` (int16 differences, a 16×16 → 32-bit product).

    >>> microchip_fw_id([0, -1043, -1341], 10000, 10, 10512)   # 0 − (1043·512 >> 10)
    -521
    """
    if speed <= on_speed:
        return curve[0]
    i = (speed - on_speed) >> shift
    d = ((curve[i] - curve[i + 1] + 32768) & 0xFFFF) - 32768
    r = (d * (speed - ((i << shift) + on_speed))) >> shift
    return ((curve[i] - r + 32768) & 0xFFFF) - 32768


def microchip_fw(m: Limits, current_base_a: float, end_rpm: float) -> dict | None:
    """AN1078's 18-entry curve for this motor: ``FWONSPEED`` the base speed in electrical rpm,
    ``SPEED_INDEX_CONST`` the smallest shift whose 17 steps reach the end of the range (base to
    the maximum speed or the end drawn), entries ``NORM_CURRENT(i_d)`` = Q15(i_d/I_b) of the exact
    d current at each breakpoint (``NORM_CURRENT_CONST`` = I_b/32768 A, I_b the Microchip
    profile's current base). The error is the routine's at every electrical rpm from FWONSPEED
    to the end (the shift is chosen so that 17 steps reach it). ``speed_beyond_int16`` when the
    range passes 32767 electrical rpm: ``qMotorSpeed`` is int16 there, so the firmware cannot
    hold those speeds (the bound is that of the routine in wider integers)."""
    p = m.p
    w_to_erpm = RPM
    k0_w, k1_w = _fw_range(m, end_rpm * p / RPM, 1.0 / w_to_erpm)
    on = k0_w
    if k1_w <= on:
        return None
    flags = [] if m.psi / m.ld > m.i else ["mtpv_not_covered"]
    shift = max(0, math.ceil(math.log2((k1_w - on) / 17.0)))
    while on + (17 << shift) < k1_w:
        shift += 1
    if shift > 14:
        flags.append("out_of_range")
    circle = _Circle(m)
    ys = [circle.id_at((on + (j << shift)) / w_to_erpm) for j in range(18)]
    lsb = current_base_a / 32768.0
    curve = [_q15_macro(y / current_base_a) for y in ys]
    if any(abs(y) > current_base_a for y in ys):
        flags.append("out_of_range")
    circle = _Circle(m)
    worst = 0.0
    last = min(k1_w, on + (17 << shift) - 1)
    if last > 32767:
        flags.append("speed_beyond_int16")
    for s in range(on, last + 1):
        e = abs(microchip_fw_id(curve, on, shift, s) * lsb - circle.id_at(s / w_to_erpm))
        worst = max(worst, e)
    c = "\n".join([f"#define FWONSPEED {on}  /* electrical rpm */",
                    f"#define SPEED_INDEX_CONST {shift}",
                    f"#define NORM_CURRENT_CONST {lsb:.9g}"]
                   + [f"#define IDREF_SPEED{j} {v}  /* NORM_CURRENT({y:.6g}) */"
                      for j, (v, y) in enumerate(zip(curve, ys))])
    return {"quantity": "id_a(speed_rpm), Microchip AN1078 FieldWeakening (fdweak.c)", "c": c,
            "x": [(on + (j << shift)) / p for j in range(18)], "y": ys, "values": curve,
            "fwonspeed": on, "speed_index_const": shift, "norm_current_const": lsb,
            "format": "int16 Q15 of I_b (NORM_CURRENT)", "scale": lsb, "unit": "A",
            "x_scale": 1.0 / p, "x_unit": "rpm", "error_bound": worst,
            "error_bound_digits": worst / lsb,
            "interpolation": "AN1078 segments (>> SPEED_INDEX_CONST)",
            "flags": sorted(set(flags))}


def _f32(x: float) -> float:
    return struct.unpack("f", struct.pack("f", x))[0]


_U32 = 2.0 ** -24


def ti_mtpa(m: Limits, samples: int = 4096) -> dict | None:
    """TI's MTPA (``MTPA_computeParameters``, ``MTPA_computeCurrentReference``) in float32.

    K = 0.25·ψ/(L_q − L_d) (``kconst``) and i_d = K − √(K² + 0.5·I_s²), which is the exact MTPA
    root; the error is float32 rounding only. ``error_bound`` is proven for the all-float32 build
    (C28x COFF, where double is 32-bit; EABI computes the radicand in double, which errs less):
    with u = 2⁻²⁴ and ρ the stored K's relative error, |error| ≤ ρ·K + 1.01·(2.5·u·√(K² + I²/2)
    + u·|i_d(I)|), because ∂i_d/∂K ∈ [0, 1), the radicand K·K + 0.5·(I_s·I_s) has two rounded
    products and a rounded sum of positive terms (≤ 2u relative, ×0.5 exact), √ halves that and
    adds u (≤ 2u of √(K² + I_s²/2) in all, 2.5u with margin), and the subtraction adds u of its
    result; ``error_sampled`` is the emulated float32 routine's largest error at ``samples`` + 1
    currents 0..I (at most the bound: tested). The CLA build of mtpa.h writes
    √(K² − 0.5·I_s²): ``cla_error_at_limit_a`` is its error at I (null: the root of a negative
    number, flag ``cla_nan``). None for a surface motor (TI sets K = 0: i_d = 0, exact).
    """
    dl = m.lq - m.ld
    if dl == 0.0:
        return None
    psi32, ld32, lq32 = _f32(m.psi), _f32(m.ld), _f32(m.lq)
    k32 = _f32(0.25 * _f32(psi32 / _f32(lq32 - ld32)))
    k = 0.25 * m.psi / dl
    rho = abs(k32 - k) / k
    rmax = math.sqrt(k * k + 0.5 * m.i * m.i)
    proven = rho * k + 1.01 * (2.5 * _U32 * rmax + _U32 * abs(k - rmax))
    worst = 0.0
    for j in range(samples + 1):
        is32 = _f32(m.i * j / samples)
        s = _f32(_f32(k32 * k32) + _f32(0.5 * _f32(is32 * is32)))
        id32 = _f32(k32 - _f32(math.sqrt(s)))
        worst = max(worst, abs(id32 - mtpa(m, is32)[0]))
    neg = k32 * k32 - 0.5 * m.i * m.i
    flags = [] if neg >= 0.0 else ["cla_nan"]
    cla = None if neg < 0.0 else abs(k32 - math.sqrt(neg) - mtpa(m, m.i)[0])
    return {"quantity": "id_a(is_a), TI MTPA_computeCurrentReference (float32)",
            "c": f"/* kconst = 0.25*flux/(Lq - Ld), computed at run time by "
                 f"MTPA_computeParameters: {k32!r} in float32 (exact {k!r}) */",
            "x": [0.0, m.i], "y": [0.0, mtpa(m, m.i)[0]], "values": [k32],
            "kconst": k32, "kconst_ideal": k, "kconst_error": (k32 - k) / k,
            "format": "float32 kconst (i_d = K − √(K² + I_s²/2))", "scale": None, "unit": "A",
            "error_bound": proven, "error_sampled": worst, "cla_error_at_limit_a": cla,
            "interpolation": "none (closed form)", "flags": flags}


def pi_fw(m: Limits, v_ratio: float, id_min: float, end_w: float, points: int = 101) -> dict:
    """The steady state of a voltage-loop field weakening that holds |v| at ``v_ratio``·V at full
    current, its d-current command limited to ≥ ``id_min`` (its output limit, where it then
    stays), versus the exact trajectory (|v| = V): ``error_bound`` the largest |command − exact
    i_d| at ``points`` speeds uniform from the lower of the two base speeds to the end of the
    range (the maximum speed or the end drawn); ``max_speed_rpm`` the highest speed at which it
    still holds its voltage at full current (where the reduced voltage limit meets the current
    circle at i_d = ``id_min``), ``base_speed_rpm`` where it starts weakening."""
    reduced = m._replace(v=m.v * v_ratio)
    wmax = max_speed(m)
    top = end_w if wmax is None else min(end_w, wmax)
    w0 = base_speed(reduced)
    start = min(w0, base_speed(m))
    exact, held = _Circle(m), _Circle(reduced)
    worst = 0.0
    if top > start:
        for k in range(points):
            w = start + (top - start) * k / (points - 1)
            worst = max(worst, abs(max(held.id_at(w), id_min) - exact.id_at(w)))
    th = math.acos(max(-1.0, min(1.0, id_min / m.i)))
    w_hold = _speed_on_circle(reduced, th)
    return {"v_ratio": v_ratio, "id_min_a": id_min, "base_speed_rpm": w0 * RPM / m.p,
            "max_speed_rpm": w_hold * RPM / m.p, "error_bound": worst, "unit": "A",
            "speed_limited": w_hold < top * (1.0 - 1e-12)}


def _pi_table(quantity, consts: dict, ss: dict, fmt: str, flags: list) -> dict:
    """A voltage-loop field weakening as a table-shaped entry: ``values`` its stored constants
    (``constants``: name → {value, ideal, error, unit}), ``error_bound`` its steady-state d
    current against the exact one, ``steady`` the rest of :func:`pi_fw`; flag ``speed_limited``
    when its voltage reference or output limit stops it below the end of the range."""
    c = "\n".join((f"#define {k} {v['value']}" if isinstance(v["value"], int) else
                    f"#define {k} ({v['value']!r})" if v["value"] == v["ideal"] else
                    f"#define {k} ({v['ideal']!r}f)  /* float32 {v['value']!r} */")
                   if k.isupper() else f"/* {k} = {v['value']!r} */"
                   for k, v in consts.items())
    return {"quantity": quantity, "c": c, "x": [], "y": [],
            "values": [c["value"] for c in consts.values()],
            "constants": consts, "steady": ss, "format": fmt, "scale": None, "unit": "A",
            "error_bound": ss["error_bound"], "interpolation": "none (PI on the voltage)",
            "flags": sorted(set(flags + (["speed_limited"] if ss["speed_limited"] else [])))}


def _const(value, ideal, unit):
    return {"value": value, "ideal": ideal,
            "error": None if not ideal else (value - ideal) / ideal, "unit": unit}


#: ST MC Workbench's flux-weakening defaults (drive_parameters.h: FW_VOLTAGE_REF 985 ‰ of
#: MAX_MODULE, FW_KP_GAIN 3000, FW_KI_GAIN 5000, FW_KPDIV = FW_KIDIV = 32768).
ST_FW = {"FW_VOLTAGE_REF": 985, "FW_KP_GAIN": 3000, "FW_KI_GAIN": 5000, "FW_KPDIV": 32768,
         "FW_KIDIV": 32768}


def st_fw(m: Limits, udc: float, digits_per_a: float, end_w: float) -> dict:
    """ST MCSDK's flux weakening (``FW_CalcCurrRef``): the PI drives |v_qd| (S16, 32767 =
    U_dc/√3) to ``FW_VOLTAGE_REF``·MAX_MODULE/1000 (uint32 division), i_d ≥ ``ID_DEMAG`` =
    −NOMINAL_CURRENT (the current limit in digits). MAX_MODULE = ⌊32767·V/(U_dc/√3)⌋ (at most
    32767). The gains in SI: FW_KP_GAIN/FW_KPDIV current digits per voltage digit."""
    v_digit = udc / (math.sqrt(3.0) * 32767.0)
    max_module = min(32767, math.floor(32767.0 * m.v / (udc / math.sqrt(3.0))))
    ref = ST_FW["FW_VOLTAGE_REF"] * max_module // 1000
    nominal = min(32767, math.floor(m.i * digits_per_a))
    flags = [] if m.i * digits_per_a < 32768 else ["out_of_range"]
    a_per_v = 1.0 / (digits_per_a * v_digit)
    consts = {
        "FW_VOLTAGE_REF": _const(ST_FW["FW_VOLTAGE_REF"], None, "‰ of MAX_MODULE"),
        "MAX_MODULE": _const(max_module, 32767.0 * m.v / (udc / math.sqrt(3.0)), "S16 V"),
        "wVoltLimit_Ref": _const(ref, ST_FW["FW_VOLTAGE_REF"] * max_module / 1000.0, "S16 V"),
        "ID_DEMAG": _const(-nominal, -m.i * digits_per_a, "current digits"),
        "FW_KP_GAIN": _const(ST_FW["FW_KP_GAIN"], None, "/FW_KPDIV"),
        "FW_KI_GAIN": _const(ST_FW["FW_KI_GAIN"], None, "/FW_KIDIV"),
        "FW_KPDIV": _const(ST_FW["FW_KPDIV"], None, ""),
        "FW_KIDIV": _const(ST_FW["FW_KIDIV"], None, ""),
    }
    ss = pi_fw(m, ref * v_digit / m.v, -nominal / digits_per_a, end_w)
    ss["kp_a_per_v"] = ST_FW["FW_KP_GAIN"] / ST_FW["FW_KPDIV"] * a_per_v
    ss["ki_a_per_v"] = ST_FW["FW_KI_GAIN"] / ST_FW["FW_KIDIV"] * a_per_v
    return _pi_table("id_a(|v|), ST FW_CalcCurrRef (flux_weakening_ctrl.c)", consts, ss,
                     "int16/uint32 digits", flags)


#: TI's universal motor-control lab (anyway-blows/ti-c2000-motor-control-sdk :
#: solutions/universal_motorcontrol_lab/common/include/user_mtr1.h: USER_M1_MAX_VS_MAG_PU 0.576
#: of V_dc, USER_M1_FWC_KP 0.0225, USER_M1_FWC_KI 0.00225, USER_M1_FWC_MAX_ANGLE −10°;
#: common/source/motor1_drive.c: VsRef_pu = 0.98·USER_M1_MAX_VS_MAG_PU, VsRef_V = VsRef_pu·V_dc,
#: current angle = max(FWC angle, MTPA angle), FWC angle = 90° − the PI's output).
TI_FWC = {"USER_M1_MAX_VS_MAG_PU": 0.576, "VsRef_pu_factor": 0.98, "USER_M1_FWC_KP": 0.0225,
          "USER_M1_FWC_KI": 0.00225, "USER_M1_FWC_MAX_ANGLE": -10.0}


def ti_fwc(m: Limits, udc: float, end_w: float) -> dict:
    """TI's FWC (``FWC_computeCurrentAngle``): a float32 PI on |V_s| to VsRef = 0.98·0.576·V_dc
    whose output advances the current angle by at most |USER_M1_FWC_MAX_ANGLE|, the MTPA angle
    taken when larger, so at full current i_d ≥ min(−I·sin 10°, MTPA i_d at I): its steady state
    versus the exact trajectory, and the speed that angle limit leaves."""
    # float32 constants (…f literals); USER_M1_MAX_VS_MAG_PU is a double literal, the product
    # 0.98f·(0.576) is double, stored in float32 VsRef_pu
    c = {k: (v if k == "USER_M1_MAX_VS_MAG_PU" else _f32(v)) for k, v in TI_FWC.items()}
    adv = math.radians(-c["USER_M1_FWC_MAX_ANGLE"])
    consts = {k: _const(c[k], v, "") for k, v in TI_FWC.items()}
    vref = _f32(c["VsRef_pu_factor"] * c["USER_M1_MAX_VS_MAG_PU"]) * udc
    ss = pi_fw(m, vref / m.v, min(-m.i * math.sin(adv), mtpa(m, m.i)[0]), end_w)
    return _pi_table("id_a(|v|), TI FWC_computeCurrentAngle (fwc.h)", consts, ss,
                     "float32 constants", [])


#: NXP MCAT's current-loop output limit (M1_CLOOP_LIMIT, 90 % by default): FRAC16(0.9) of
#: U_max = U_DCB/√3 in the fractional build; 0.9/1.73205 of U_DCB in the float build (MCAT's
#: √3 has six digits: Masmiseim36/nxpSDK : boards/hvpkv58f/demo_apps/mc_acim/m1_acim_appconfig.h
#: prints 0.519615484541).
NXP_CLOOP = 0.9


def nxp_fw(m: Limits, udc: float, end_w: float) -> dict:
    """NXP RTCESL ``AMCLIB_CtrlFluxWkng`` (AMCLIB_CtrlFluxWkng_FLT.h: inputs the q-current error,
    the required q voltage and its limit): it weakens while the q voltage sits at the current
    loop's limit, so it settles where |v| = M1_CLOOP_LIMIT·U_DCB/√3, i_d ≥ −I (its PI's lower
    limit at the current limit). The fractional build stores FRAC16(0.9) = ⌊0.9·32768⌋."""
    frac = math.floor(NXP_CLOOP * 32768.0)
    flt = NXP_CLOOP / 1.73205
    consts = {"M1_CLOOP_LIMIT": _const(frac, NXP_CLOOP * 32768.0, "FRAC16 of U_max"),
              "M1_CLOOP_LIMIT_float": _const(flt, NXP_CLOOP / math.sqrt(3.0), "of U_DCB")}
    ss = pi_fw(m, frac / 32768.0 * udc / math.sqrt(3.0) / m.v, -m.i, end_w)
    return _pi_table("id_a(|v|), NXP AMCLIB_CtrlFluxWkng at M1_CLOOP_LIMIT", consts, ss,
                     "FRAC16 / float32", [])


def _mchp_ff_id(m: Limits, ls: float, w: float) -> float:
    """The steady state of Microchip's feed-forward law at full current: the i_d with
    i_d = (−ψ + √((V/ω)² − (L_s·i_q)²))/L_s, clamped to [−I, 0], and i_q = √(I² − i_d²) (its q
    limit), by bisection on i_d (the law's radicand is negative while i_d is too shallow)."""
    def g(i_d):
        i_q = math.sqrt(max(m.i * m.i - i_d * i_d, 0.0))
        arg = (m.v / w) ** 2 - (ls * i_q) ** 2
        if arg < 0.0:
            return -1.0
        return min(max((-m.psi + math.sqrt(arg)) / ls, -m.i), 0.0) - i_d
    lo, hi = -m.i, 0.0
    if g(hi) >= 0.0:
        return 0.0
    if g(lo) <= 0.0:
        return -m.i
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if g(mid) > 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def microchip_ff(m: Limits, end_w: float, points: int = 101) -> dict:
    """Microchip's feed-forward field weakening (flux_control.c, dsPIC33A motor-control
    application, 2024: ``MCAPP_FeedForwardFluxWeakening``, found by exact-string search, index id
    5334745449, repository not named by the search tool): i_d = (−K_e + √((V_FW/ω)² −
    (L_s·i_q)²))/L_s in float, saturated to [IdRefMin, 0], above fwEnableSpeed. A lossless
    surface-motor law with one inductance: evaluated with K_e = ψ, L_s = L_d, V_FW = V,
    IdRefMin = −I, fwEnableSpeed = the base speed, at full current (i_q at its limit
    √(I² − i_d²)), against the exact trajectory at ``points`` speeds from base to the end."""
    wb = base_speed(m)
    wmax = max_speed(m)
    top = end_w if wmax is None else min(end_w, wmax)
    exact = _Circle(m)
    worst = 0.0
    if top > wb > 0.0:
        for k in range(points):
            w = wb + (top - wb) * k / (points - 1)
            worst = max(worst, abs(_mchp_ff_id(m, m.ld, w) - exact.id_at(w)))
    consts = {"Ke": _const(_f32(m.psi), m.psi, "V·s/rad"), "Ls": _const(_f32(m.ld), m.ld, "H"),
              "voltageLimitFW": _const(_f32(m.v), m.v, "V"),
              "IdRefMin": _const(_f32(-m.i), -m.i, "A")}
    ss = {"error_bound": worst, "base_speed_rpm": wb * RPM / m.p, "l_s_is": "L_d",
          "speed_limited": False}
    flags = ["one_inductance"] if m.ld != m.lq else []
    return _pi_table("id_a(speed, iq), Microchip MCAPP_FeedForwardFluxWeakening (float)", consts,
                     ss, "float32 constants", flags)


def analyze(report: dict, cfg: dict) -> dict:
    """The report's ``fw`` section: :func:`pulab.analyses.envelope.analyze` with the generic
    tables and each vendor's storage added to ``tables`` (docs/contract.md, "Output: fw",
    "Output: fw.tables")."""
    fw = envelope.analyze(report, cfg)
    m = envelope.limits(report["input"]["motor"], fw["psi_wb"], fw["voltage_limit_v"],
                        fw["current_limit_a"])
    n, q, how = cfg["table_points"], cfg["table_q"], cfg["interpolation"]
    end_rpm = fw["speed_max_rpm"] if fw["max_speed_rpm"] is None else \
        min(fw["speed_max_rpm"], fw["max_speed_rpm"])
    end_w = end_rpm * m.p / RPM
    out = {"generic": generic_mtpa(m, n, q, how),
           "generic_fw": generic_fw(m, n, q, how, end_rpm),
           "microchip_fw": microchip_fw(m, _vendor_options(report, "microchip")["current_base_a"],
                                        end_rpm),
           "ti_mtpa": ti_mtpa(m), "ti_fwc": ti_fwc(m, report["input"]["drive"]["udc_v"], end_w),
           "nxp_fw": nxp_fw(m, report["input"]["drive"]["udc_v"], end_w),
           "microchip_ff": microchip_ff(m, end_w),
           "st_fw": st_fw(m, report["input"]["drive"]["udc_v"], _st_digits_per_a(report), end_w)}
    fw["tables"].update({k: v for k, v in out.items() if v is not None})
    return fw
