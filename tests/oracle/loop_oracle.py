"""Independent oracle for the report's "loop" section; writes tests/golden/loop/*.json.

    .venv/bin/python tests/oracle/loop_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/loop_oracle.py --check  # exit 1 if any file is stale

Never imports pulab.  Gains come from the report oracle next to this file (oracle.py); the
loops are built and measured with python-control (the field's standard library), along a
different route from pulab's:

- plant: control.c2d(1/(L·s + R), T_s, 'zoh') for the delays none/computation (·z⁻¹);
  computation_pwm by lifting: the T_s/2 ZOH state-space (A_h, B_h) from control.c2d applied
  twice per period, the first half with the previous input (a state of its own), turned into
  a transfer function with control.ss2tf, then ·z⁻¹ — pulab writes the modified z-transform
  γ_h·(z + φ_h)/(z²·(z − a)) directly;
- margins: control.stability_margins(returnall=True) (python-control's polynomial method)
  with pulab's documented selection (the crossover with the smallest |PM|, the phase crossover
  with the smallest |GM| in dB); python-control 0.10.2 leaves z = −1 out of the phase
  crossovers, so L(−1) is evaluated here and added when it is real and negative;
- closed-loop poles: control.feedback(L, 1).poles();
- bandwidth: control.frequency_response on a 20 000-point log grid, then scipy's brentq on
  |T(e^{jωT_s})| − |T(1)|/√2 in the first bracket (python-control's own ``bandwidth`` evaluates
  discrete systems at z = jω, so it is not used);
- design by phase margin / bandwidth: brentq over kp of the margin / bandwidth above, with
  ki·T_s = kp·(e^{R·T_s/L} − 1) (the discrete pole-zero cancellation, closed form here);
- Bode points: control.frequency_response at the frequencies of pulab's documented grid
  (400 log-spaced points from min(f_N/1000, f_c,min/100) to f_N = 1/(2·T_s)), every 10th
  point stored.

Each file is {"input": report input incl. "analysis", "expected": {"loop": subset}} — see
tests/golden/README.md, section "Loop analysis".
"""

from __future__ import annotations

import copy
import json
import math
import pathlib
import sys
import warnings

import control
import numpy as np
from scipy.optimize import brentq

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import oracle_report  # noqa: E402
from make_golden import CASES as REPORT_CASES  # noqa: E402

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "loop"
# python-control's frequency responses and margins move in their last digits with the scipy and
# numpy they run on (a Bode magnitude of -2.8394022485e-05 dB changed by 9.6e-13 dB between
# scipy versions): relative 1e-9 with an absolute floor of 1e-9 for values that are zero
# up to rounding.  The pulab tests compare against these files at 1e-6 (test_loop.py).
REL, ABS = 1e-9, 1e-9
BODE_POINTS, BODE_EVERY = 400, 10
warnings.filterwarnings("ignore")


def plant(R, L, ts, delay):
    g = control.tf([1.0], [L, R])
    if delay in ("none", "computation"):
        p = control.c2d(g, ts, "zoh")
        return p if delay == "none" else p * control.tf([1.0], [1.0, 0.0], ts)
    h = control.c2d(control.ss(g), ts / 2.0, "zoh")
    ah, bh, ch = float(h.A[0, 0]), float(h.B[0, 0]), float(h.C[0, 0])
    # state (x, u_prev): x⁺ = ah²·x + ah·bh·u_prev + bh·u ; u_prev⁺ = u
    lifted = control.ss([[ah * ah, ah * bh], [0.0, 0.0]], [[bh], [1.0]], [[ch, 0.0]], [[0.0]], ts)
    return control.ss2tf(lifted) * control.tf([1.0], [1.0, 0.0], ts)


def pi(kp, ki, ts):
    return control.tf([kp + ki * ts, -kp], [1.0, -1.0], ts)


def _tf_eval(sys_, z):
    num = np.asarray(sys_.num[0][0], dtype=float)
    den = np.asarray(sys_.den[0][0], dtype=float)
    return np.polyval(num, z) / np.polyval(den, z)


def measure(loop, ts):
    gm, pm, _, w180, wc, _ = control.stability_margins(loop, returnall=True)
    gm, pm, w180, wc = (np.atleast_1d(np.asarray(x, dtype=float)) for x in (gm, pm, w180, wc))
    nyq = math.pi / ts
    l_nyq = _tf_eval(loop, -1.0)
    if abs(l_nyq.imag) < 1e-12 and l_nyq.real < 0 and not np.any(np.isclose(w180, nyq, rtol=1e-9)):
        gm = np.append(gm, 1.0 / abs(l_nyq))
        w180 = np.append(w180, nyq)
    keep = (wc > 0) & (wc <= nyq * (1 + 1e-12))
    pm, wc = pm[keep], wc[keep]
    keep = (w180 > 0) & (w180 <= nyq * (1 + 1e-12))
    gm, w180 = gm[keep], w180[keep]
    out = {"phase_margin_deg": None, "crossover_hz": None, "gain_margin_db": None,
           "phase_crossover_hz": None}
    if pm.size:
        i = int(np.argmin(np.abs(pm)))
        out["phase_margin_deg"], out["crossover_hz"] = float(pm[i]), float(wc[i] / (2 * math.pi))
    if gm.size:
        db = 20.0 * np.log10(gm)
        i = int(np.argmin(np.abs(db)))
        out["gain_margin_db"], out["phase_crossover_hz"] = float(db[i]), float(w180[i] / (2 * math.pi))
    cl = control.feedback(loop, 1)
    poles = sorted((complex(p) for p in cl.poles()), key=lambda p: (p.real, p.imag))
    radius = max(abs(p) for p in poles)
    out["poles"] = [[p.real, p.imag] for p in poles]
    out["stable"] = bool(radius < 1.0)
    out["bandwidth_hz"] = bandwidth(cl, ts) if radius < 1.0 else None
    return out


def bandwidth(cl, ts):
    t0 = abs(_tf_eval(cl, 1.0))
    nyq = math.pi / ts
    w = np.logspace(math.log10(nyq) - 8, math.log10(nyq), 20000)
    mag = np.abs(_tf_eval(cl, np.exp(1j * w * ts)))
    below = np.nonzero(mag < t0 / math.sqrt(2.0))[0]
    if not below.size:
        return None
    i = int(below[0])
    f = lambda x: abs(_tf_eval(cl, np.exp(1j * x * ts))) - t0 / math.sqrt(2.0)  # noqa: E731
    return brentq(f, w[i - 1], w[i], xtol=1e-14, rtol=1e-15) / (2 * math.pi)


def current_loop(R, L, ts, kp, ki, delay):
    return pi(kp, ki, ts) * plant(R, L, ts, delay)


def design(R, L, ts, delay, by, target):
    ratio = (math.exp(R * ts / L) - 1.0) / ts        # ki/kp for the PI zero at a = e^{−R·T_s/L}

    def score(kp):
        m = measure(current_loop(R, L, ts, kp, kp * ratio, delay), ts)
        return (m["phase_margin_deg"] - target) if by == "phase_margin" else \
            (m["bandwidth_hz"] - target)
    # kp = x·L/T_s puts the crossover near θ = x rad per sample
    lo = 0.02 * L / ts if by == "phase_margin" else 0.1 * 2 * math.pi * target * L
    hi = 2.0 * lo
    while (score(hi) > 0) if by == "phase_margin" else (score(hi) < 0):
        lo, hi = hi, hi * 2.0
    kp = brentq(score, lo, hi, xtol=1e-15, rtol=1e-14)
    return kp, kp * ratio


def dead_time(ts, delay):
    return ts * {"none": 0.5, "computation": 1.5, "computation_pwm": 2.0}[delay]


def bode_samples(loop, ts, f):
    resp = control.frequency_response(loop, 2 * math.pi * np.asarray(f))
    mag = np.atleast_1d(np.squeeze(resp.magnitude))
    ph = np.atleast_1d(np.squeeze(resp.phase))
    idx = list(range(0, len(f), BODE_EVERY)) + [len(f) - 1]
    return {"index": idx, "magnitude_db": [float(20 * math.log10(mag[i])) for i in idx],
            "phase_deg": [float(math.degrees(ph[i])) for i in idx]}


def grid(ts, crossovers):
    nyq = 0.5 / ts
    low = min([1e-3 * nyq] + [0.01 * f for f in crossovers if f])
    return [low * math.exp(math.log(nyq / low) * k / (BODE_POINTS - 1)) for k in range(BODE_POINTS)]


def expected_loop(inp):
    rep = oracle_report({k: v for k, v in inp.items() if k != "analysis"})
    a = inp.get("analysis") or {}
    delay = a.get("delay", "computation_pwm")
    by = a.get("design", "phase_margin")
    motor, ts = inp["motor"], inp["drive"]["ts_s"]
    R = motor["rs_ohm"]
    B = rep["base"]
    out = {"delay": delay, "current": {}}
    for axis, L in (("d", motor["ld_h"]), ("q", motor["lq_h"])):
        g = rep["current_pi"][axis]
        m = measure(current_loop(R, L, ts, g["kp"], g["ki"], delay), ts)
        back = g["from_integers"]
        m["firmware"] = measure(current_loop(R, L, ts, back["kp"], back["ki"], delay), ts)
        out["current"][axis] = m
    if by == "phase_margin":
        target = float(a.get("target_phase_margin_deg", 60.0))
    else:
        target = float(a.get("target_bandwidth_hz") or
                       (inp.get("current_loop") or {}).get("bandwidth_hz") or 500.0)
    des = {"by": by, "target": target, "dead_time_s": dead_time(ts, delay)}
    for axis, L in (("d", motor["ld_h"]), ("q", motor["lq_h"])):
        kp, ki = design(R, L, ts, delay, by, target)
        d = {"kp": kp, "ki": ki, **measure(current_loop(R, L, ts, kp, ki, delay), ts)}
        if by == "bandwidth":
            wc = 2 * math.pi * target
        else:
            wc = math.radians(90.0 - target) / dead_time(ts, delay)
        d["continuous"] = {"kp": wc * L, "ki": wc * R,
                           **measure(current_loop(R, L, ts, wc * L, wc * R, delay), ts)}
        des[axis] = d
    out["current"]["design"] = des
    p = rep["pll"]
    g_naive = B["w_b"] / B["theta_b"]
    out["pll"] = {}
    for name, gain in (("correct", 1.0), ("naive", g_naive)):
        loop = pi(p["kp"], p["ki"], ts) * control.tf([gain * ts], [1.0, -1.0], ts)
        out["pll"][name] = {**measure(loop, ts), "kp_ts_gain": p["kp"] * ts * gain}
    # boundary: the loop gain factor that puts a closed-loop pole on z = −1, times kp·T_s
    k = 10 ** (out["pll"]["correct"]["gain_margin_db"] / 20.0)
    out["pll"]["boundary_kp_ts_gain"] = k * p["kp"] * ts
    s = a.get("speed")
    speed_loop = None
    if s is not None:
        pp = motor["pole_pairs"]
        psi = rep["pu"]["psi_r_wb"]
        w_mb = B["w_b"] / pp
        kt = B["P_b"] / (B["U_b"] * B["I_b"]) * pp * psi
        J, Bf = s["inertia_kg_m2"], s.get("friction_nm_s", 0.0)
        bw, zeta = s.get("bandwidth_hz", 20.0), s.get("damping", math.sqrt(0.5))
        tsp = s.get("ts_s", 10 * ts)
        ff = s.get("filter_hz", 5 * bw)
        wn = 2 * math.pi * bw
        kps, kis = (2 * zeta * wn * J - Bf) / kt, wn * wn * J / kt
        kp_pu, ki_pu = kps * w_mb / B["I_b"], kis * w_mb / B["I_b"]
        pm_kp, pm_ki = round(kp_pu * 4096), round(ki_pu * tsp * 65536)
        alpha = 1 - math.exp(-2 * math.pi * ff * tsp)
        mech = control.c2d(control.tf([kt], [J, Bf]), tsp, "zoh")

        def sloop(kp_, ki_):
            return (pi(kp_, ki_, tsp) * mech * control.tf([1.0], [1.0, 0.0], tsp) *
                    control.tf([alpha, 0.0], [1.0, alpha - 1.0], tsp))
        speed_loop = sloop(kps, kis)
        sp = {"bases": {"w_mb": w_mb, "torque_nm": B["P_b"] / w_mb, "kt_nm_per_a": kt,
                        "inertia_constant_s": J * w_mb ** 2 / (2 * B["P_b"])},
              "kp": kps, "ki": kis, "kp_pu": kp_pu, "ki_pu": ki_pu, "pm_kp": pm_kp,
              "pm_ki": pm_ki, **measure(speed_loop, tsp)}
        sp["firmware"] = measure(sloop(pm_kp / 4096 * B["I_b"] / w_mb,
                                       pm_ki / 65536 / tsp * B["I_b"] / w_mb), tsp)
        out["speed"] = sp
    # Bode samples
    cur = out["current"]
    f = grid(ts, [cur[x]["crossover_hz"] for x in ("d", "q")] +
             [cur["design"][x]["crossover_hz"] for x in ("d", "q")])
    bode = {"current": {"open": {}, "closed": {}}}
    for axis, L in (("d", motor["ld_h"]), ("q", motor["lq_h"])):
        g = rep["current_pi"][axis]
        dd = cur["design"][axis]
        for name, (kp, ki) in ((axis, (g["kp"], g["ki"])), (f"{axis}_design", (dd["kp"], dd["ki"]))):
            loop = current_loop(R, L, ts, kp, ki, delay)
            bode["current"]["open"][name] = bode_samples(loop, ts, f)
            bode["current"]["closed"][name] = bode_samples(control.feedback(loop, 1), ts, f)
    bode["current"]["f_hz"] = f[::BODE_EVERY] + [f[-1]]
    fp = grid(ts, [out["pll"]["correct"]["crossover_hz"]])
    bode["pll"] = {"f_hz": fp[::BODE_EVERY] + [fp[-1]], "open": {}}
    for name, gain in (("correct", 1.0), ("naive", g_naive)):
        loop = pi(p["kp"], p["ki"], ts) * control.tf([gain * ts], [1.0, -1.0], ts)
        bode["pll"]["open"][name] = bode_samples(loop, ts, fp)
    if speed_loop is not None:
        fs = grid(tsp, [out["speed"]["crossover_hz"]])
        bode["speed"] = {"f_hz": fs[::BODE_EVERY] + [fs[-1]],
                         "open": bode_samples(speed_loop, tsp, fs),
                         "closed": bode_samples(control.feedback(speed_loop, 1), tsp, fs)}
    out["bode"] = bode
    return out


EXTRA = {
    # 12 V drone motor: 14 pole pairs, 40 mΩ, 12 µH, 24 kHz
    "drone_12v": {"motor": {"rated_voltage_v": 8.5, "rated_current_a": 20, "rated_freq_hz": 600,
                            "rs_ohm": 0.04, "ld_h": 1.2e-5, "lq_h": 1.2e-5, "bemf_v": 7.0,
                            "pole_pairs": 7},
                  "drive": {"udc_v": 12, "ts_s": 1 / 24000},
                  "current_loop": {"bandwidth_hz": 2000}},
    # 18 000 rpm spindle, 2 pole pairs, 16 kHz
    "spindle_600hz": {"motor": {"rated_voltage_v": 220, "rated_current_a": 12, "rated_freq_hz": 600,
                                "rs_ohm": 0.35, "ld_h": 0.0011, "lq_h": 0.0011, "bemf_v": 190,
                                "pole_pairs": 2},
                      "drive": {"udc_v": 310, "ts_s": 6.25e-05},
                      "current_loop": {"bandwidth_hz": 1500}},
    # 60 kW traction IPM, 8 kHz
    "traction_60kw": {"motor": {"rated_voltage_v": 250, "rated_current_a": 180, "rated_freq_hz": 200,
                                "rs_ohm": 0.012, "ld_h": 0.00012, "lq_h": 0.0003, "bemf_v": 160,
                                "pole_pairs": 4},
                      "drive": {"udc_v": 400, "ts_s": 0.000125},
                      "current_loop": {"bandwidth_hz": 800}},
}

SPEED = [{"inertia_kg_m2": 1e-5}, {"inertia_kg_m2": 0.02, "friction_nm_s": 0.004, "bandwidth_hz": 15},
         {"inertia_kg_m2": 3e-4, "bandwidth_hz": 40, "damping": 1.0, "filter_hz": 300,
          "ts_s": 0.0005}]


def cases():
    out = {}
    base = [(n[3:], inp) for n, inp in REPORT_CASES] + list(EXTRA.items())
    delays = ("computation_pwm", "computation", "none")
    for k, (name, inp) in enumerate(base):
        inp = copy.deepcopy(inp)
        a = {"delay": delays[k % 3], "bode": True}
        if k % 4 == 1:
            a["design"] = "bandwidth"
            a["target_bandwidth_hz"] = 200.0 + 50 * k
        elif k % 4 == 2:
            a["target_phase_margin_deg"] = 45.0
        if k % 5 == 0:
            a["speed"] = SPEED[(k // 5) % len(SPEED)]
            if "ts_s" in a["speed"]:
                a["speed"] = dict(a["speed"], ts_s=inp["drive"]["ts_s"] * 4)
        inp["analysis"] = a
        out[f"{k + 1:02d}_{name}"] = inp
    return out


def main(argv: list[str]) -> int:
    files = {f"{name}.json": {"input": inp, "expected": {"loop": expected_loop(inp)}}
             for name, inp in cases().items()}
    return sync(files, golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
