"""Independent oracle for the firmware tables of the report's "fw" section; writes
tests/golden/fw_tables/*.json.

    .venv/bin/python tests/oracle/fw_tables_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/fw_tables_oracle.py --check  # exit 1 if any file is stale

Never imports pulab. Every input digit at once in numpy: the exact MTPA i_d of each q-current
digit from the quadratic ψ·i_d + (L_d − L_q)·(i_d² − i_q²) = 0 in long double (the other root
form than pulab's); the exact field-weakening i_d of each speed digit by a vectorised bisection
on the current angle of "|v| ≤ V" (pulab: Newton on a closed-form speed); the tables' integers
built and read back by this file's own code (C division toward zero, Microchip's Q15() macro
and its >> SPEED_INDEX_CONST routine, numpy float32 for TI's MTPA). Motors: the interior
motors of tests/oracle/fw_oracle.py, with the ST and Microchip scalings stated in each input.
"""

from __future__ import annotations

import copy
import math
import sys
from pathlib import Path

import numpy as np

from fw_oracle import CASES, params
from fw_oracle import mtpa as fw_mtpa
from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "fw_tables"
REL, ABS = 1e-6, 1e-12
Q, N = 15, 8


def mtpa_id(P, iq):
    r, ld, lq, psi, p, v, i = P
    a = np.longdouble(ld - lq)
    iq = np.asarray(iq, dtype=np.longdouble)
    if a == 0:
        return np.zeros_like(iq, dtype=float)
    disc = np.longdouble(psi) ** 2 + 4 * a * a * iq * iq
    # a·id² + ψ·id − a·iq² = 0, the root through the origin
    return np.asarray((-psi + np.sqrt(disc)) / (2 * a), dtype=float)


def vsq(P, w, i_d, i_q):
    r, ld, lq, psi, p, v, i = P
    return (r * i_d - w * lq * i_q) ** 2 + (r * i_q + w * (ld * i_d + psi)) ** 2


def mtpa_at_limit(P):
    """(i_d, i_q) of the MTPA point on |i| = I: i_q by bisection on i_d(i_q)² + i_q² = I²."""
    i = P[6]
    lo, hi = 0.0, i
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if float(mtpa_id(P, mid)) ** 2 + mid * mid < i * i else (lo, mid)
    return float(mtpa_id(P, lo)), lo


def fw_id(P, w):
    """Field-weakening i_d on the current circle at each electrical speed of ``w``: the largest
    current angle below which |v| > V (bisection between the MTPA angle and π)."""
    i, v = P[6], P[5]
    d0, q0 = mtpa_at_limit(P)
    lo = np.full(np.shape(w), math.atan2(q0, d0))
    hi = np.full(np.shape(w), math.pi)
    below = vsq(P, w, i * np.cos(lo), i * np.sin(lo)) <= v * v
    for _ in range(80):
        mid = (lo + hi) / 2
        ok = vsq(P, w, i * np.cos(mid), i * np.sin(mid)) <= v * v
        hi = np.where(ok, mid, hi)
        lo = np.where(ok, lo, mid)
    th = np.where(below, math.atan2(q0, d0), hi)
    return i * np.cos(th)


def base_w(P):
    d0, q0 = mtpa_at_limit(P)
    lo, hi = 0.0, 1.0
    while vsq(P, hi, d0, q0) < P[5] ** 2:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if vsq(P, mid, d0, q0) < P[5] ** 2 else (lo, mid)
    return lo


def max_w(P):
    r, ld, lq, psi, p, v, i = P
    return math.sqrt(v * v - (r * i) ** 2) / (psi - ld * i)


def c_lookup(values, step, k):
    """Linear interpolation in C integers, vectorised over digits ``k``."""
    vals = np.asarray(values, dtype=np.int64)
    j = np.minimum(k // step, len(values) - 2)
    num = (vals[j + 1] - vals[j]) * (k - j * step)
    return vals[j] + np.sign(num) * (np.abs(num) // step)


def generic(P, end_rpm):
    i, p = P[6], P[4]
    lsb = i / 2 ** Q
    kmax = min(math.floor(mtpa_at_limit(P)[1] / lsb), 2 ** Q - 1)
    step = kmax // (N - 1)
    vals = [int(np.rint(mtpa_id(P, j * step * lsb) / lsb)) for j in range(N)]
    k = np.arange(kmax + 1)
    err = np.abs(c_lookup(vals, step, k) * lsb - mtpa_id(P, k * lsb)).max()
    out = {"generic": {"values": vals, "error_bound": float(err), "x_step_digits": step,
                       "x_last_digit": kmax}}
    x_lsb = end_rpm / 2 ** Q * p * 2 * math.pi / 60
    k0 = math.ceil(base_w(P) / x_lsb)
    k1 = math.floor(min(end_rpm * p * 2 * math.pi / 60, max_w(P)) / x_lsb)
    step = (k1 - k0) // (N - 1)
    vals = [int(np.rint(float(fw_id(P, np.array([(k0 + j * step) * x_lsb]))[0]) / lsb))
            for j in range(N)]
    vals = [max(-32768, min(32767, x)) for x in vals]
    k = np.arange(k0, k1 + 1)
    err = np.abs(c_lookup(vals, step, k - k0) * lsb - fw_id(P, k * x_lsb)).max()
    out["generic_fw"] = {"values": vals, "error_bound": float(err), "x_first_digit": k0,
                         "x_last_digit": k1, "x_step_digits": step}
    return out


def q15(x):
    v = math.trunc(32768.0 * x - 0.5) if x < 0 else math.trunc(32767.0 * x + 0.5)
    return ((v + 32768) & 0xFFFF) - 32768


def microchip(P, end_rpm, ib):
    p = P[4]
    to_erpm = 60 / (2 * math.pi)
    on = math.ceil(base_w(P) * to_erpm)
    top = math.floor(min(end_rpm * p, max_w(P) * to_erpm))
    shift = 0
    while on + (17 << shift) < top:
        shift += 1
    ys = fw_id(P, np.array([(on + (j << shift)) / to_erpm for j in range(18)]))
    curve = [q15(float(y) / ib) for y in ys]
    s = np.arange(on, min(top, on + (17 << shift) - 1) + 1)
    idx = (s - on) >> shift
    c = np.asarray(curve, dtype=np.int64)
    d = c[idx] - c[idx + 1]
    got = c[idx] - ((d * (s - ((idx << shift) + on))) >> shift)
    err = np.abs(got * (ib / 32768) - fw_id(P, s / to_erpm)).max()
    return {"values": curve, "fwonspeed": on, "speed_index_const": shift,
            "error_bound": float(err), "flags": ["speed_beyond_int16"] if s[-1] > 32767 else []}


def ti(P):
    r, ld, lq, psi, p, v, i = P
    f = np.float32
    k = f(0.25) * (f(psi) / (f(lq) - f(ld)))
    iss = np.linspace(0, i, 4097).astype(np.float32)
    got = k - np.sqrt(k * k + f(0.5) * (iss * iss))
    # exact MTPA i_d at magnitude I_s: K − √(K² + I_s²/2) in long double, K exact; the identity
    # with fw_oracle's MTPA (a dense scan of the current angle) checked at three magnitudes
    kk = np.longdouble(psi) / (4 * np.longdouble(lq - ld))
    exact = kk - np.sqrt(kk * kk + iss.astype(np.longdouble) ** 2 / 2)
    for j in (1024, 2048, 4096):
        assert abs(float(exact[j]) - fw_mtpa(P, float(iss[j]))[0]) < 1e-7 * i
    return {"kconst": float(k),
            "error_sampled": float(np.abs(got.astype(np.longdouble) - exact).max())}


def held_max_rpm(P, v_held, id_min):
    """The highest speed at which full current with i_d = id_min needs no more than v_held."""
    r, ld, lq, psi, p, v, i = P
    d = max(id_min, -i)
    q = math.sqrt(i * i - d * d)
    lo, hi = 0.0, 1.0
    while vsq(P, hi, d, q) < v_held ** 2:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if vsq(P, mid, d, q) < v_held ** 2 else (lo, mid)
    return lo * 60 / (2 * math.pi * p)


def steady(P, v_held, id_min, end_rpm):
    """The d-current command of a voltage loop holding v_held (≥ id_min) against the exact one,
    at 101 speeds from the lower base speed to the end: the largest difference, and the speed to
    which it holds full current."""
    r, ld, lq, psi, p, v, i = P
    Ph = (r, ld, lq, psi, p, v_held, i)
    top = min(end_rpm * p * 2 * math.pi / 60, max_w(P))
    w = np.linspace(min(base_w(Ph), base_w(P)), top, 101)
    held = np.maximum(fw_id(Ph, w), id_min)
    return {"error_bound": float(np.abs(held - fw_id(P, w)).max()),
            "max_speed_rpm": held_max_rpm(P, v_held, id_min)}


def st(P, udc, dpa, end_rpm):
    v, i = P[5], P[6]
    max_module = min(32767, math.floor(32767 * v / (udc / math.sqrt(3))))
    ref = 985 * max_module // 1000
    nominal = min(32767, math.floor(i * dpa))
    return {"values": [985, max_module, ref, -nominal, 3000, 5000, 32768, 32768],
            **steady(P, ref * udc / (math.sqrt(3) * 32767), -nominal / dpa, end_rpm)}


def nxp(P, udc, end_rpm):
    """FRAC16(0.9) = 29491 of U_DCB/√3 held; MCAT's float 0.9/1.73205 printed to 12 decimals."""
    return {"values": [29491, float(f"{0.9 / 1.73205:.12f}")],
            **steady(P, 29491 / 32768 * udc / math.sqrt(3), -P[6], end_rpm)}


def ti_fwc(P, udc, end_rpm):
    """VsRef = float32(0.98f·0.576)·V_dc; the current angle at most 10° past the q axis, or the
    MTPA angle when larger."""
    vref = float(np.float32(float(np.float32(0.98)) * 0.576)) * udc
    return steady(P, vref, min(-P[6] * math.sin(math.radians(10)), mtpa_at_limit(P)[0]), end_rpm)


def microchip_ff(P, end_rpm):
    """Microchip's feed-forward law (K_e = ψ, L_s = L_d, V_FW = V, clamp [−I, 0]) at full current:
    the fixed point i_d = law(ω, √(I² − i_d²)) by a vectorised bisection over 101 speeds from base
    to the end, against the exact i_d."""
    r, ld, lq, psi, p, v, i = P
    w = np.linspace(base_w(P), min(end_rpm * p * 2 * math.pi / 60, max_w(P)), 101)
    lo, hi = np.full(w.shape, -i), np.zeros(w.shape)

    def g(d):
        arg = (v / w) ** 2 - (ld * np.sqrt(np.maximum(i * i - d * d, 0))) ** 2
        law = np.clip((-psi + np.sqrt(np.maximum(arg, 0))) / ld, -i, 0)
        return np.where(arg < 0, -1.0, law - d)
    for _ in range(100):
        mid = (lo + hi) / 2
        up = g(mid) > 0
        lo, hi = np.where(up, mid, lo), np.where(up, hi, mid)
    d = np.where(g(np.zeros(w.shape)) >= 0, 0.0,
                 np.where(g(np.full(w.shape, -i)) <= 0, -i, (lo + hi) / 2))
    return {"error_bound": float(np.abs(d - fw_id(P, w)).max())}


def expected(inp):
    P = params(inp)
    p = P[4]
    wm = max_w(P)
    end_rpm = min(inp["analysis"]["fw"]["speed_max_rpm"], wm * 60 / (2 * math.pi * p))
    out = generic(P, end_rpm)
    out["microchip_fw"] = microchip(P, end_rpm, inp["profiles"]["microchip"]["current_base_a"])
    out["ti_mtpa"] = ti(P)
    s = inp["profiles"]["st"]
    out["st_fw"] = st(P, inp["drive"]["udc_v"],
                      65536 * s["rshunt_ohm"] * s["amplification_gain"] / s["adc_reference_v"],
                      end_rpm)
    out["nxp_fw"] = nxp(P, inp["drive"]["udc_v"], end_rpm)
    out["ti_fwc"] = ti_fwc(P, inp["drive"]["udc_v"], end_rpm)
    out["microchip_ff"] = microchip_ff(P, end_rpm)
    return out


def build():
    files = {}
    for name, case in CASES:
        P = params(case)
        if P[1] == P[2]:
            continue
        inp = copy.deepcopy(case)
        i = P[6]
        inp["analysis"]["fw"]["speed_max_rpm"] = 1.2 * max_w(P) * 60 / (2 * math.pi * P[4])
        # ST: 16384 digits at the current limit; Microchip: I_b = 2·I
        inp["profiles"] = {"st": {"adc_reference_v": 3.3, "amplification_gain": 1.0,
                                  "rshunt_ohm": 3.3 / (4 * i)},
                           "microchip": {"current_base_a": 2 * i}}
        files[f"{name}.json"] = {"input": inp, "expected": expected(inp),
                                 "compare": {"rel": REL, "ti_bound_covers_sampled": True}}
    return files


def main(argv):
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
