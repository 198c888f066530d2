"""Above base speed: MTPA, the voltage limit, field weakening and the tables firmware stores.

Steady state with R, phase-peak quantities (ψ the phase-peak flux linkage the report derives from
the back-EMF)::

    v_d = R·i_d − ω·L_q·i_q,   v_q = R·i_q + ω·(L_d·i_d + ψ),   |v| ≤ V,   |i| ≤ I
    T = 1.5·p·(ψ·i_q + (L_d − L_q)·i_d·i_q),   P = T·ω/p

MTPA at a current magnitude ``i`` (dT/dβ = 0):
``i_d = (ψ − √(ψ² + 8·ΔL²·i²))/(4·ΔL)``, ΔL = L_q − L_d (``i_d = 0`` when ΔL = 0).
The base speed is where the MTPA point at the current limit reaches the voltage limit (a
quadratic in ω). Above it the largest torque lies on the voltage boundary: on its intersection
with the current circle, or inside the circle (MTPV); it is found on the boundary parametrized
by the voltage angle, refined by bisection (circle) and golden section (MTPV).
The maximum speed is where the voltage limit meets the current limit at i = (−I, 0): with
ψ/L_d > I, ω_max = √(V² − R²I²)/(ψ − L_d·I) (beyond it no current within the limit has positive
torque: |v| grows from that point into i_q > 0). With ψ/L_d ≤ I the characteristic current lies
inside the limit and the speed is unbounded (torque falls towards 0); ``max_speed_rpm`` is null.

Examples
--------
>>> m = {"rs_ohm": 0.75, "ld_h": 1.05e-3, "lq_h": 1.05e-3, "pole_pairs": 4}
>>> psi = 3.8 / (3 ** 0.5 * 2 * 3.141592653589793 * 1000 * 4 / 60)   # MathWorks BLY171D
>>> lim = limits(m, psi, 24 / 3 ** 0.5, 1.8)
>>> round(base_speed(lim) * 60 / (2 * 3.141592653589793) / 4)         # mcb.PMSMSpeeds: 5393
5393
"""

from __future__ import annotations

import math
from typing import NamedTuple

from ..schema.errors import InputError

__all__ = ["Limits", "limits", "mtpa", "mtpa_id", "base_speed", "max_speed", "best_torque",
           "analyze", "voltage_limit", "st_mtpa", "st_mtpa_id"]

RPM = 60.0 / (2.0 * math.pi)
#: Voltage-angle samples of the boundary search (each then refined to rounding); four times
#: more, twice, when the feasible arc slipped between them (it shrinks to a point at the
#: maximum speed).
_SAMPLES = 120
_GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


class Limits(NamedTuple):
    """The motor and its two limits, SI, phase peak."""
    r: float
    ld: float
    lq: float
    psi: float
    p: int
    v: float
    i: float


def limits(motor: dict, psi: float, v: float, i: float) -> Limits:
    return Limits(motor["rs_ohm"], motor["ld_h"], motor["lq_h"], psi, motor["pole_pairs"], v, i)


def voltage_limit(modulation, udc: float) -> float:
    """Phase-peak voltage limit: SVPWM U_dc/√3, sinusoidal U_dc/2, or a number times U_dc."""
    if modulation == "svpwm":
        return udc / math.sqrt(3.0)
    if modulation == "spwm":
        return udc / 2.0
    return float(modulation) * udc


def torque(m: Limits, i_d: float, i_q: float) -> float:
    return 1.5 * m.p * (m.psi * i_q + (m.ld - m.lq) * i_d * i_q)


def volts(m: Limits, w: float, i_d: float, i_q: float) -> float:
    return math.hypot(m.r * i_d - w * m.lq * i_q, m.r * i_q + w * (m.ld * i_d + m.psi))


def mtpa(m: Limits, i: float) -> tuple:
    """(i_d, i_q) of maximum torque per ampere at current magnitude ``i``."""
    dl = m.lq - m.ld
    if dl == 0.0:
        return 0.0, i
    i_d = (m.psi - math.sqrt(m.psi * m.psi + 8.0 * dl * dl * i * i)) / (4.0 * dl)
    return i_d, math.sqrt(max(i * i - i_d * i_d, 0.0))


def mtpa_id(m: Limits, i_q: float) -> float:
    """The MTPA i_d for a given i_q (any i_q, also beyond the current limit).

    dT/dβ = 0 at fixed magnitude gives ψ·i_d = ΔL·(i_d² − i_q²)... as a quadratic in i_d:
    ``i_d = −2·ΔL·i_q²/(ψ + √(ψ² + 4·ΔL²·i_q²))`` (the root that is 0 at i_q = 0, written
    without cancellation; 0 when ΔL = 0).
    """
    dl = m.lq - m.ld
    return -2.0 * dl * i_q * i_q / (m.psi + math.sqrt(m.psi * m.psi + 4.0 * dl * dl * i_q * i_q))


def st_mtpa_id(segdiv: int, angc: list, ofst: list, iq: int, shift: bool = False) -> int:
    """ST's ``MTPA_CalcCurrRefFromIq`` for a q current ``iq`` in digits (|iq| used): segment
    ``|iq|/SEGDIV`` (at most 7), ``id = ANGC[s]·|iq|/32768 + OFST[s]`` as int16 — the MISRA
    build divides (toward zero), the other shifts ``>> 15`` (toward −∞) (ST MCSDK max_torque_per_ampere.c).

    >>> st_mtpa_id(100, [-3277] * 8, [0] * 8, 150), st_mtpa_id(100, [-3277] * 8, [0] * 8, 150, True)
    (-15, -16)
    """
    iq = abs(iq)
    s = min(iq // segdiv, 7)
    prod = angc[s] * iq
    q = prod >> 15 if shift else (-((-prod) // 32768) if prod < 0 else prod // 32768)
    v = (q + ofst[s]) & 0xFFFF
    return v - 0x10000 if v & 0x8000 else v


def st_mtpa(m: Limits, digits_per_a: float, iq_top: float) -> dict:
    """ST's 8-segment MTPA look-up (``SEGDIV``, ``ANGC[8]``, ``OFST[8]``) for this motor.

    ST publishes the routine, not how MC Workbench fits it; reconstructed as the chords of the
    exact MTPA curve (:func:`mtpa_id`) over eight equal segments ``SEGDIV = ⌈IQMAX/8⌉`` digits,
    ``IQMAX`` the MTPA i_q at the current limit in current digits (``digits_per_a`` =
    65536·R_shunt·G/V_ref). A public MCSDK header's table has the same form (continuous at the
    segment ends within a few digits). The error bound is exact: the routine evaluated for every
    q-current digit 0..IQMAX against the exact curve, for both builds.
    """
    iqmax = min(32767, math.floor(iq_top * digits_per_a))
    segdiv = max(1, -(-iqmax // 8))
    exact = [mtpa_id(m, k * segdiv / digits_per_a) * digits_per_a for k in range(9)]
    angc, ofst, flags = [], [], []
    for k in range(8):
        a = k * segdiv
        slope = (exact[k + 1] - exact[k]) / segdiv
        c = round(slope * 32768.0)
        o = round(exact[k] - c * a / 32768.0)
        if not (-32768 <= c <= 32767 and -32768 <= o <= 32767):
            flags.append("out_of_range")
        angc.append(max(-32768, min(32767, c)))
        ofst.append(max(-32768, min(32767, o)))
    worst = {False: 0.0, True: 0.0}
    for iq in range(iqmax + 1):
        ideal = mtpa_id(m, iq / digits_per_a)
        for shift in worst:
            e = abs(st_mtpa_id(segdiv, angc, ofst, iq, shift) / digits_per_a - ideal)
            worst[shift] = max(worst[shift], e)
    return {"quantity": "id_a(iq_a), ST 8-segment look-up (max_torque_per_ampere.c)",
            "x": [k * segdiv / digits_per_a for k in range(9)],
            "y": [e / digits_per_a for e in exact], "values": angc + ofst,
            "segdiv": segdiv, "iqmax": iqmax, "angc": angc, "ofst": ofst,
            "format": "int16 digits (ANGC·iq/32768 + OFST)", "scale": 1.0 / digits_per_a,
            "unit": "A", "error_bound": worst[False], "error_bound_shift": worst[True],
            "interpolation": "ST segments", "flags": sorted(set(flags)),
            # three macros of ST's drive_parameters.h
            "c": "\n".join([f"#define IQMAX   {iqmax}", f"#define SEGDIV  {segdiv}",
                            f"#define ANGC    {{{','.join(map(str, angc))}}}",
                            f"#define OFST    {{{','.join(map(str, ofst))}}}"])}


def base_speed(m: Limits) -> float:
    """Electrical rad/s where the MTPA point at the current limit meets the voltage limit; 0 when
    the resistance alone needs more than the voltage limit at that current."""
    i_d, i_q = mtpa(m, m.i)
    a = (m.lq * i_q) ** 2 + (m.ld * i_d + m.psi) ** 2
    b = 2.0 * (-(m.r * i_d) * m.lq * i_q + m.r * i_q * (m.ld * i_d + m.psi))
    c = (m.r * m.r) * (i_d * i_d + i_q * i_q) - m.v * m.v
    if c >= 0.0:
        return 0.0
    return (-b + math.sqrt(b * b - 4.0 * a * c)) / (2.0 * a)


def max_speed(m: Limits) -> float | None:
    """Electrical rad/s beyond which no current within the limit gives positive torque; None when
    unbounded (characteristic current ψ/L_d within the current limit)."""
    if m.psi / m.ld <= m.i:
        return None
    if m.r * m.i >= m.v:
        return 0.0
    return math.sqrt(m.v * m.v - (m.r * m.i) ** 2) / (m.psi - m.ld * m.i)


def _current_of(m: Limits, w: float, phi: float) -> tuple:
    """The current whose voltage is V·(cos φ, sin φ) at electrical speed w."""
    vd, vq = m.v * math.cos(phi), m.v * math.sin(phi) - w * m.psi
    det = m.r * m.r + w * w * m.ld * m.lq
    return (m.r * vd + w * m.lq * vq) / det, (-w * m.ld * vd + m.r * vq) / det


def best_torque(m: Limits, w: float) -> tuple:
    """(T, i_d, i_q) of the largest torque at electrical speed ``w`` within both limits, or
    (0, −I, 0) when no current gives positive torque."""
    i_d, i_q = mtpa(m, m.i)
    if volts(m, w, i_d, i_q) <= m.v:
        return torque(m, i_d, i_q), i_d, i_q
    for samples in (_SAMPLES, 4 * _SAMPLES, 16 * _SAMPLES):
        best = _on_the_voltage_limit(m, w, samples)
        if best[0] > 0.0:
            return best
    return _near_the_maximum_speed(m, w)


def _near_the_maximum_speed(m: Limits, w: float) -> tuple:
    """Just below the maximum speed the feasible currents are a sliver of the current circle
    next to (−I, 0), too thin for the samples: the best is where the circle leaves the voltage
    limit, found by bisection on the circle's angle from π (where |v| < V still holds)."""
    def on_circle(a):
        return m.i * math.cos(a), m.i * math.sin(a)
    if volts(m, w, *on_circle(math.pi)) >= m.v:
        return 0.0, -m.i, 0.0
    lo, hi = math.pi, 0.5 * math.pi   # lo feasible; hi (i_d = 0, i_q = I) beyond MTPA's voltage
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if volts(m, w, *on_circle(mid)) < m.v:
            lo = mid
        else:
            hi = mid
    i_d, i_q = on_circle(lo)
    return torque(m, i_d, i_q), i_d, i_q


def _on_the_voltage_limit(m: Limits, w: float, samples: int) -> tuple:
    best = (0.0, -m.i, 0.0)

    def at(phi):
        cd, cq = _current_of(m, w, phi)
        ok = cd * cd + cq * cq <= m.i * m.i and cq >= 0.0
        return ok, torque(m, cd, cq), cd, cq

    step = 2.0 * math.pi / samples
    pts = [at(k * step) for k in range(samples + 1)]
    for k in range(samples):
        (ok0, t0, *_), (ok1, t1, *_) = pts[k], pts[k + 1]
        if ok0 and t0 > best[0]:
            best = pts[k][1:]
        if ok0 != ok1:  # the current circle (or i_q = 0) crossed: bisect to it
            lo, hi = (k * step, (k + 1) * step) if ok0 else ((k + 1) * step, k * step)
            for _ in range(52):
                mid = 0.5 * (lo + hi)
                if at(mid)[0]:
                    lo = mid
                else:
                    hi = mid
            p = at(lo)
            if p[0] and p[1] > best[0]:
                best = p[1:]
    # an interior maximum of the voltage boundary (MTPV): golden section around the best sample
    k = max(range(1, samples), key=lambda j: pts[j][1] if pts[j][0] else -math.inf)
    if pts[k][0] and pts[k - 1][0] and pts[k + 1][0] and pts[k][1] >= max(pts[k - 1][1], pts[k + 1][1]):
        a, b = (k - 1) * step, (k + 1) * step
        for _ in range(60):
            c1, c2 = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
            if at(c1)[1] >= at(c2)[1]:
                b = c2
            else:
                a = c1
        p = at(0.5 * (a + b))
        if p[0] and p[1] > best[0]:
            best = p[1:]
    return best


def _interp(xs: list, ys: list, x: float) -> float:
    if x <= xs[0]:
        return ys[0]
    for k in range(1, len(xs)):
        if x <= xs[k]:
            t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]) if xs[k] > xs[k - 1] else 0.0
            return ys[k - 1] + t * (ys[k] - ys[k - 1])
    return ys[-1]


def _table(name: str, quantity: str, xs: list, exact, scale: float, unit: str,
           dense: list) -> dict:
    """A table of ``len(xs)`` breakpoints stored as Q15 of the current limit, its C array
    ``name``, and its error bound (linear interpolation of the stored integers against the
    exact curve at ``dense``)."""
    ys = [exact(x) for x in xs]
    values = [max(-32768, min(32767, round(y / scale))) for y in ys]
    stored = [v * scale for v in values]
    err = max(abs(_interp(xs, stored, x) - exact(x)) for x in dense) if dense else 0.0
    return {"quantity": quantity, "x": xs, "y": ys, "values": values, "format": "Q15",
            "scale": scale, "unit": unit, "error_bound": err, "interpolation": "linear",
            "c": f"static const int16_t {name}[{len(values)}] = {{ {', '.join(map(str, values))} }};"}


def _vendor_options(report: dict, name: str) -> dict:
    """A vendor profile's options: the report's, else its defaults for this report (the board's
    when given)."""
    from ..profiles import context_of, options
    prof = (report.get("profiles") or {}).get(name)
    return prof["inputs"] if prof is not None else options({}, context_of(report))[name]


def _st_digits_per_a(report: dict) -> float:
    """ST's current digits per ampere, 65536·R_shunt·G/V_ref."""
    o = _vendor_options(report, "st")
    return 65536.0 * o["rshunt_ohm"] * o["amplification_gain"] / o["adc_reference_v"]


def analyze(report: dict, cfg: dict) -> dict:
    """The report's ``fw`` section (docs/contract.md, "Output: fw").

    Parameters
    ----------
    report : dict
        The report so far (``input``, ``mechanical`` not needed).
    cfg : dict
        Normalized ``analysis.fw``.

    Raises
    ------
    InputError
        ``analysis.fw.modulation`` for a limit that leaves no voltage.
    """
    inp = report["input"]
    mo, d = inp["motor"], inp["drive"]
    psi = math.sqrt(2.0 / 3.0) * mo["bemf_v"] / (2.0 * math.pi * mo["rated_freq_hz"])
    i_lim = cfg["current_limit_a"] if cfg["current_limit_a"] is not None else \
        math.sqrt(2.0) * mo["rated_current_a"]
    v_lim = voltage_limit(cfg["modulation"], d["udc_v"])
    if not v_lim > 0.0:
        raise InputError("analysis.fw.modulation", code="fw_no_voltage", value=v_lim)
    m = limits(mo, psi, v_lim, i_lim)
    p, n = m.p, cfg["points"]
    wb, wmax = base_speed(m), max_speed(m)
    to_rpm = RPM / p
    top_rpm = cfg["speed_max_rpm"] if cfg["speed_max_rpm"] is not None else \
        (1.2 * wmax * to_rpm if wmax is not None else 3.0 * wb * to_rpm)
    end_rpm = top_rpm if wmax is None else min(top_rpm, wmax * to_rpm)
    mt = []
    for k in range(n):
        i = m.i * k / (n - 1)
        i_d, i_q = mtpa(m, i)
        mt.append({"iq_a": i_q, "id_a": i_d, "torque_nm": torque(m, i_d, i_q)})
    env = []
    for k in range(n):
        rpm = end_rpm * k / (n - 1)
        w = rpm / to_rpm
        t, i_d, i_q = best_torque(m, w)
        env.append({"speed_rpm": rpm, "torque_nm": t, "power_w": t * w / p, "id_a": i_d,
                    "iq_a": i_q, "v_pk": volts(m, w, i_d, i_q)})
    npts = cfg["table_points"]
    digits_per_a = _st_digits_per_a(report) if m.lq != m.ld else None
    scale = m.i / 32768.0
    iq_top = mtpa(m, m.i)[1]
    iq_x = [iq_top * k / (npts - 1) for k in range(npts)]

    def id_of_iq(iq):
        # the MTPA i_d for a given i_q: i = |(i_d, i_q)| solved by bisection on the magnitude
        lo, hi = iq, m.i
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if mtpa(m, mid)[1] < iq:
                lo = mid
            else:
                hi = mid
        return mtpa(m, 0.5 * (lo + hi))[0]

    tables = {"mtpa_id_of_iq": _table("mtpa_id_of_iq", "id_a(iq_a)", iq_x, id_of_iq, scale, "A",
                                      [iq_top * k / 400 for k in range(401)])}
    if m.lq != m.ld and digits_per_a is not None:
        tables["st_mtpa"] = st_mtpa(m, digits_per_a, iq_top)
    fw_end = end_rpm
    if fw_end > wb * to_rpm:
        sx = [wb * to_rpm + (fw_end - wb * to_rpm) * k / (npts - 1) for k in range(npts)]
        tables["fw_id_of_speed"] = _table(
            "fw_id_of_speed", "id_a(speed_rpm)", sx, lambda s: best_torque(m, s / to_rpm)[1], scale, "A",
            [wb * to_rpm + (fw_end - wb * to_rpm) * k / 100 for k in range(101)])
    # what the page draws in the i_d–i_q plane: the current limit and the voltage limit at
    # three speeds (base, and two above it), each as the currents whose |v| is exactly V
    marks = [wb, 1.5 * wb, 2.0 * wb] if wmax is None else [wb, 0.5 * (wb + wmax), wmax]
    curves = {"circle": {"id_a": [m.i * math.cos(math.pi * k / 90) for k in range(181)],
                         "iq_a": [m.i * math.sin(math.pi * k / 90) for k in range(181)]},
              "ellipses": []}
    for w in marks:
        if w <= 0.0:
            continue
        pts = [_current_of(m, w, 2.0 * math.pi * k / 180) for k in range(181)]
        curves["ellipses"].append({"speed_rpm": w * to_rpm, "id_a": [x[0] for x in pts],
                                   "iq_a": [x[1] for x in pts]})
    return {"voltage_limit_v": v_lim, "current_limit_a": m.i, "psi_wb": psi, "curves": curves,
            "characteristic_current_a": psi / m.ld,
            "base_speed_rpm": wb * to_rpm,
            "max_speed_rpm": None if wmax is None else wmax * to_rpm,
            "speed_max_rpm": top_rpm,
            "mtpa": mt, "envelope": env, "tables": tables}
