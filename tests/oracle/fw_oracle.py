"""Independent oracle for the report's "fw" section; writes tests/golden/fw/*.json.

    .venv/bin/python tests/oracle/fw_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/fw_oracle.py --check  # exit 1 if any file is stale

Never imports pulab. Brute force in numpy instead of pulab's closed forms and boundary search:
the MTPA angle by a dense scan of the current angle (then a parabola through the best three),
the base speed by bisection on |v| of that point, the largest torque at a speed as the maximum
over a polar grid of the whole current disk (every point checked against the voltage limit),
and the maximum speed by bisection on "some grid point with i_q > 0 meets the voltage limit".
The grid costs accuracy, stated in each file's tolerance: torque to 0.5 %, the maximum speed to
0.2 %, the base speed and the MTPA to 1e-9 relative.

Motors (public parameter files): MathWorks Motor Control Blockset ``BLY171D`` (surface; its
documented mcb.PMSMSpeeds base speed 5393 rpm on the DRV8312-C2-KIT at 24 V) and
``Teknic2310P_IPM`` (interior); motulator's 2.2-kW interior PMSM (Aalto-Electric-Drives/motulator
examples: p 3, R 3.6 Ω, L_d 36 mH, L_q 51 mH, ψ_f 0.545 Wb, 4.3 A, 540 V bus); a Formula
Student hub motor (dweggg/Inverter : Control/FOC_DQ0_parameters.m: 10 poles, k_E 18.8 V rms
phase per krpm, L_d 0.12 mH, L_q 0.24 mH, R 0.135 Ω, 105 A peak; its 140-cell battery at a
nominal 3.6 V per cell, 504 V).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np

from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "fw"
REL, ABS = 1e-6, 0.0


def _motor(p, rs, ld, lq, psi_pk, i_pk, f_n, udc):
    """A report input whose back-EMF gives ψ (phase peak) and whose rated current gives I (peak)."""
    e_ll = psi_pk * 2 * math.pi * f_n * math.sqrt(1.5)
    return {"motor": {"rated_voltage_v": udc / math.sqrt(2), "rated_current_a": i_pk / math.sqrt(2),
                      "rated_freq_hz": f_n, "rs_ohm": rs, "ld_h": ld, "lq_h": lq, "bemf_v": e_ll,
                      "pole_pairs": p},
            "drive": {"udc_v": udc, "ts_s": 1e-4}, "analysis": {"fw": {"points": 11, "table_points": 8}}}


def _ke_flux(ke_v_per_krpm_line_peak, p):
    return ke_v_per_krpm_line_peak / (math.sqrt(3) * 2 * math.pi * 1000 * p / 60)


CASES = [
    ("01_mathworks_bly171d", _motor(4, 0.75, 1.05e-3, 1.05e-3, _ke_flux(3.8, 4), 1.8, 4000 * 4 / 60, 24)),
    ("02_mathworks_teknic2310p_ipm", _motor(4, 0.36, 0.2e-3, 0.4e-3, _ke_flux(4.64, 4), 7.1, 6000 * 4 / 60, 24)),
    ("03_motulator_2k2_ipm", _motor(3, 3.6, 0.036, 0.051, 0.545, 4.3 * math.sqrt(2), 75, 540)),
    # k_E in V rms phase-to-neutral per krpm: ψ_pk = √2·k_E/(2π·1000·p/60)
    ("04_fs_hub_ipm", _motor(5, 0.135, 0.12e-3, 0.24e-3,
                             math.sqrt(2) * 18.8 / (2 * math.pi * 1000 * 5 / 60), 105, 20000 * 5 / 60,
                             504)),
]


def params(inp):
    m, d = inp["motor"], inp["drive"]
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    return (m["rs_ohm"], m["ld_h"], m["lq_h"], psi, m["pole_pairs"], d["udc_v"] / math.sqrt(3),
            math.sqrt(2) * m["rated_current_a"])


def torque(P, i_d, i_q):
    r, ld, lq, psi, p, v, i = P
    return 1.5 * p * (psi * i_q + (ld - lq) * i_d * i_q)


def vmag(P, w, i_d, i_q):
    r, ld, lq, psi, p, v, i = P
    return np.hypot(r * i_d - w * lq * i_q, r * i_q + w * (ld * i_d + psi))


def mtpa(P, mag):
    """(i_d, i_q) of the largest torque on the circle |i| = mag: dense scan, then a parabola."""
    if mag == 0:
        return 0.0, 0.0
    b = np.linspace(0, np.pi, 2_000_001)
    t = torque(P, mag * np.cos(b), mag * np.sin(b))
    k = int(np.argmax(t))
    if 0 < k < len(b) - 1:
        y0, y1, y2 = t[k - 1], t[k], t[k + 1]
        h = b[1] - b[0]
        den = y0 - 2 * y1 + y2
        beta = b[k] + (0.5 * h * (y0 - y2) / den if den != 0 else 0.0)
    else:
        beta = b[k]
    return float(mag * np.cos(beta)), float(mag * np.sin(beta))


def base_speed(P):
    i_d, i_q = mtpa(P, P[6])
    lo, hi = 0.0, 1.0
    while vmag(P, hi, i_d, i_q) < P[5]:
        hi *= 2
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if vmag(P, mid, i_d, i_q) < P[5] else (lo, mid)
    return lo


_R = np.linspace(0, 1, 801)[:, None]
_A = np.linspace(0, np.pi, 4001)[None, :]


def best_torque(P, w):
    i_d, i_q = P[6] * _R * np.cos(_A), P[6] * _R * np.sin(_A)
    ok = vmag(P, w, i_d, i_q) <= P[5]
    t = np.where(ok, torque(P, i_d, i_q), -np.inf)
    return max(float(t.max()), 0.0)


def max_speed(P):
    r, ld, lq, psi, p, v, i = P
    if psi / ld <= i:
        return None
    a = np.linspace(1e-6, np.pi, 200001)

    def positive(w):  # some point with i_q > 0 within both limits
        rr = np.linspace(0.0, 1.0, 401)[:, None]
        return bool((vmag(P, w, i * rr * np.cos(a[None, :20000]), i * rr * np.sin(a[None, :20000])) <= v).any()
                    or (vmag(P, w, i * np.cos(a), i * np.sin(a)) <= v).any())
    lo, hi = base_speed(P), base_speed(P) * 2
    while positive(hi):
        hi *= 2
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if positive(mid) else (lo, mid)
    return lo


def expected(inp):
    P = params(inp)
    p = P[4]
    to_rpm = 60 / (2 * math.pi) / p
    wb, wm = base_speed(P), max_speed(P)
    # the speeds drawn: up to 95 % of the maximum speed (both sides then draw the same speeds
    # although their maximum speeds differ by the grid's resolution), or 3 × base when unbounded
    top = 0.95 * wm if wm is not None else 3 * wb
    inp["analysis"]["fw"]["speed_max_rpm"] = top * to_rpm
    mt = [mtpa(P, P[6] * k / 4) for k in range(5)]
    speeds = [top * k / 10 for k in range(11)]
    return {"base_speed_rpm": wb * to_rpm, "max_speed_rpm": None if wm is None else wm * to_rpm,
            "characteristic_current_a": P[3] / P[1],
            "mtpa_id_a": [x[0] for x in mt], "mtpa_iq_a": [x[1] for x in mt],
            "envelope_speed_rpm": [s * to_rpm for s in speeds],
            "envelope_torque_nm": [best_torque(P, s) for s in speeds]}


def build():
    return {f"{n}.json": {"expected": expected(inp), "input": inp,
                          "compare": {"rel": 1e-9, "torque_rel": 5e-3, "max_speed_rel": 2e-3}}
            for n, inp in CASES}


def main(argv):
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
