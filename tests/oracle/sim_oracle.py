"""Independent oracle for the report's "sim" section; writes tests/golden/sim/*.json.

    .venv/bin/python tests/oracle/sim_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/sim_oracle.py --check  # exit 1 if any file is stale

Never imports pulab.  Bases, per-unit values, gains and vendor integers come from the
report oracle next to this file (tests/oracle/oracle.py, itself independent of pulab); the
time-domain part is written here from the contract and the seed:

- plant (seed 1.2-3): ZOH transition from an eigendecomposition in numpy,
  Φ = V·e^{ΛT}·V⁻¹, Γ = V·diag(expm1(λT)/λ)·V⁻¹·B — a different algorithm from pulab's
  Taylor/scaling-and-squaring exponential — cross-checked against 400-sub-step RK4 of the
  matrix ODE (|Δ| < 1e-11 relative, asserted);
- vendor PI (seed 2.2) in np.int32 arithmetic (wraps by itself);
- int16 PLL angles as np.int16, products as np.int64.

Each file is {"input": report input incl. "sim", "expected": the "sim" section,
"compare": how to compare} — see tests/golden/README.md, section "Simulation trajectories".
"""

from __future__ import annotations

import copy
import json
import math
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from golden_files import golden_dir, sync  # noqa: E402
from oracle import oracle_report, parse  # noqa: E402

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "sim"
# The plant's ZOH comes from numpy's eigendecomposition, whose last digits depend on the BLAS
# kernel the CPU selects; traces are compared with pulab at the tolerances in "compare".
REL, ABS = 1e-9, 1e-12
MAX_POINTS = 400
TWO_PI = 2.0 * math.pi


def rha(x: float) -> int:
    """Round half away from zero."""
    return int(math.copysign(math.floor(abs(x) + 0.5), x))


# ----------------------------------------------------------------------------------------
# Plant: exact ZOH by eigendecomposition, checked against fine RK4

def plant_zoh(rs, ld, lq, psi, w, ts):
    A = np.array([[-rs / ld, w * lq / ld], [-w * ld / lq, -rs / lq]])
    B = np.diag([1.0 / ld, 1.0 / lq])
    lam, V = np.linalg.eig(A)
    Vi = np.linalg.inv(V)
    z = lam * ts
    phi = (V @ np.diag(np.exp(z)) @ Vi).real
    # ∫₀^T e^{λτ}dτ = T·expm1(λT)/(λT), without cancellation for small λT
    f = np.where(np.abs(z) > 0, np.expm1(z) / np.where(z == 0, 1, z), 1.0) * ts
    gam = (V @ np.diag(f) @ Vi @ B).real
    _check_rk4(A, B, ts, phi, gam)
    return phi, gam, w * psi


def _check_rk4(A, B, ts, phi, gam, sub=400):
    """d/dt [Φ(t) Γ(t)] = A·[Φ Γ] + [0 B], from [I 0]; RK4 with `sub` steps over T."""
    X = np.hstack([np.eye(2), np.zeros((2, 2))])
    F = np.hstack([np.zeros((2, 2)), B])
    h = ts / sub

    def f(X):
        return A @ X + F

    for _ in range(sub):
        k1 = f(X)
        k2 = f(X + 0.5 * h * k1)
        k3 = f(X + 0.5 * h * k2)
        k4 = f(X + h * k3)
        X = X + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
    ref = np.hstack([phi, gam])
    err = np.max(np.abs(X - ref)) / np.max(np.abs(ref))
    assert err < 1e-11, f"eig ZOH and RK4 disagree: {err:g}"


# ----------------------------------------------------------------------------------------
# Current loop

def clamp(x, lo, hi):
    return lo if x < lo else hi if x > hi else x


def _wrap32(v):
    return (v + 2 ** 31) % 2 ** 32 - 2 ** 31


def vendor_pi(integ, err, kp, ki, maxu, maxout):
    """seed 2.2: all long (int32), numpy wraps; __IQsat clamps. Returns (integral, output,
    whether one of its long operations overflowed, judged on exact Python integers)."""
    with np.errstate(over="ignore"):
        e = np.int32(err)
        s = np.int32(integ) + ((e * np.int32(ki)) >> np.int32(4))
        # minu = -maxu is a long negation: -(-2^31) wraps to -2^31
        s = clamp(int(s), -maxu, maxu) if maxu >= 0 else _iqsat(int(s), maxu, _wrap32(-maxu))
        d = (np.int32(s) + e * np.int32(kp)) >> np.int32(12)
        o = clamp(int(d), -maxout, maxout)
    p_i, p_p = err * ki, err * kp
    exact = (-maxu, -maxout, p_i, integ + (_wrap32(p_i) >> 4), p_p, s + _wrap32(p_p))
    return s, o, any(_wrap32(v) != v for v in exact)


def _iqsat(x, hi, lo):
    return hi if x > hi else lo if x < lo else x


def current_loop(R, cfg, inp):
    B, PU, V, C = R["base"], R["pu"], R["vendor"], R["current_pi"]
    P = parse(inp)
    ts, Ub, Ib, wb = P["ts_s"], B["U_b"], B["I_b"], B["w_b"]
    axis = cfg.get("axis") or "d"
    L = P["ld_h"] if axis == "d" else P["lq_h"]
    dur = cfg.get("duration_s")
    if dur is None:
        dur = max(200 * ts, 30.0 / (C[axis]["kp"] / L))
    n = max(1, int(round(dur / ts)))
    step = cfg.get("step_a")
    if step is None:
        step = 0.5 * Ib
    delay = bool(cfg.get("delay") or False)
    w = TWO_PI * (cfg.get("speed_hz") or 0.0)
    rd, rq = (step, 0.0) if axis == "d" else (0.0, step)
    mo, mu = V["pm_maxout_vol"]["value"], V["maxu"]["value"]

    def run_float(phi, gam, bemf, kp, kits, umax, imax, ref, integ0):
        x = np.zeros(2)
        integ = np.array([0.0, clamp(integ0, -imax, imax)])
        prev = np.array([0.0, clamp(integ[1], -umax, umax)])
        I, U, S = [], [], []
        for _ in range(n + 1):
            I.append(x.copy())
            e = ref - x
            integ = np.clip(integ + kits * e, -imax, imax)
            o = integ + kp * e
            S.append(bool(np.any(np.abs(o) >= umax)))
            o = np.clip(o, -umax, umax)
            a = prev if delay else o
            prev = o
            U.append(a.copy())
            x = phi @ x + gam @ (a - np.array([0.0, bemf]))
        return np.array(I), np.array(U), S

    phi, gam, bemf = plant_zoh(P["rs_ohm"], P["ld_h"], P["lq_h"], PU["psi_r_wb"], w, ts)
    kp = np.array([C["d"]["kp"], C["q"]["kp"]])
    kits = np.array([C["d"]["ki"], C["q"]["ki"]]) * ts
    umax, imax = mo / 4096.0 * Ub, mu / 2.0 ** 24 * Ub
    out = {"si": run_float(phi, gam, bemf, kp, kits, umax, imax, np.array([rd, rq]), bemf)}

    # per unit: the same loop in per-unit quantities and per-unit time (seed 1.2-1/1.2-2)
    phip, gamp, bemfp = plant_zoh(PU["Rs"], PU["Ld"], PU["Lq"], PU["psi_r"], w / wb,
                                  ts * wb)
    kpp = np.array([C["d"]["kp_pu"], C["q"]["kp_pu"]])
    kitsp = np.array([C["d"]["ki_pu"], C["q"]["ki_pu"]]) * ts
    Ip, Up, Sp = run_float(phip, gamp, bemfp, kpp, kitsp, mo / 4096.0, mu / 2.0 ** 24,
                           np.array([rd, rq]) / Ib, bemfp)
    out["pu"] = (Ip * Ib, Up * Ub, Sp)

    # fixed: Q12 feedback, vendor integer PI, Q12·U_b = phase voltage
    refq = [rha(rd / Ib * 4096.0), rha(rq / Ib * 4096.0)]
    gains = [(C[a]["pm_kp"], C[a]["pm_ki"]) for a in "dq"]
    x = np.zeros(2)
    integ = [0, _iqsat(rha(bemf / Ub * 2.0 ** 24), mu, _wrap32(-mu))]
    prev = np.array([0.0, clamp(integ[1] >> 12, -mo, mo) * Ub / 4096.0])
    I, U, S = [], [], []
    wraps = 0
    for _ in range(n + 1):
        I.append(x.copy())
        o = [0, 0]
        for j in range(2):
            fb = int(np.clip(rha(x[j] / Ib * 4096.0), -32768, 32767))
            integ[j], o[j], w = vendor_pi(integ[j], refq[j] - fb, gains[j][0], gains[j][1],
                                          mu, mo)
            wraps += w
        S.append(abs(o[0]) == mo or abs(o[1]) == mo)
        ov = np.array(o, dtype=float) * Ub / 4096.0
        a = prev if delay else ov
        prev = ov
        U.append(a.copy())
        x = phi @ x + gam @ (a - np.array([0.0, bemf]))
    out["fixed"] = (np.array(I), np.array(U), S)

    t = np.arange(n + 1) * ts
    idx = decim(n + 1)
    j = 0 if axis == "d" else 1
    variants, metrics = {}, {}
    for name, (I, U, S) in out.items():
        variants[name] = {"id": I[idx, 0].tolist(), "iq": I[idx, 1].tolist(),
                          "ud": U[idx, 0].tolist(), "uq": U[idx, 1].tolist()}
        metrics[name] = step_metrics(t, I[:, j], step, S, ts)
    diff = float(np.max(np.abs(out["fixed"][0] - out["si"][0])))
    metrics["fixed_vs_si_max_abs_a"] = diff
    metrics["fixed_vs_si_max_lsb"] = diff / (Ib / 4096.0)
    metrics["fixed_wraps"] = wraps
    first = wcts = dev = None
    if P["method"] == "bandwidth":
        wc = TWO_PI * P["cl_bandwidth_hz"]
        first, wcts = 2.2 / wc, wc * ts
        if metrics["si"]["rise_time_s"] is not None:
            dev = 100.0 * (metrics["si"]["rise_time_s"] - first) / first
    metrics.update({"first_order_rise_time_s": first, "wc_ts": wcts,
                    "rise_time_deviation_pct": dev})
    return {"t": t[idx].tolist(), "variants": variants, "metrics": metrics}


def decim(n):
    # The first half of the point budget at full rate (the transient), the rest evenly strided.
    if n <= MAX_POINTS:
        return np.arange(n)
    head = MAX_POINTS // 2
    stride = math.ceil((n - 1 - head) / (MAX_POINTS - head - 1))
    idx = list(range(head)) + list(range(head - 1 + stride, n, stride))
    if idx[-1] != n - 1:
        idx.append(n - 1)
    return np.array(idx)


def first_crossing(t, y, level, s):
    hit = np.nonzero(s * (y - level) >= 0)[0]
    if len(hit) == 0:
        return None
    k = int(hit[0])
    if k == 0:
        return float(t[0])
    return float(t[k - 1] + (t[k] - t[k - 1]) * (level - y[k - 1]) / (y[k] - y[k - 1]))


def step_metrics(t, y, ref, sat, ts):
    s = 1.0 if ref > 0 else -1.0
    a, b = first_crossing(t, y, 0.1 * ref, s), first_crossing(t, y, 0.9 * ref, s)
    rise = None if a is None or b is None else b - a
    over = max(0.0, 100.0 * (float(np.max(s * y)) - abs(ref)) / abs(ref))
    tol = 0.02 * abs(ref)
    out = np.nonzero(np.abs(y - ref) > tol)[0]
    if len(out) == 0:
        settle = float(t[0])
    elif out[-1] == len(y) - 1:
        settle = None
    else:
        k = int(out[-1])
        y0, y1 = y[k] - ref, y[k + 1] - ref
        edge = tol if y0 > 0 else -tol
        settle = float(t[k] + (t[k + 1] - t[k]) * (edge - y0) / (y1 - y0))
    m = max(1, int(len(y) * 0.1))
    return {"rise_time_s": rise, "overshoot_pct": over, "settling_time_s": settle,
            "steady_state_error_a": float(ref - np.mean(y[-m:])),
            "saturation_time_s": sum(sat) * ts}


# ----------------------------------------------------------------------------------------
# PLL (seed 3): wrapped-difference detector, PI (integral first), integrator

def wrap(x):
    return math.remainder(x, TWO_PI)


def pll(R, cfg, inp):
    P = parse(inp)
    B, G = R["base"], R["pll"]
    ts, wb, thb, fb = P["ts_s"], B["w_b"], B["theta_b"], B["f_b"]
    dur = cfg.get("duration_s")
    if dur is None:
        dur = max(2000 * ts, 60.0 / (P["pll_damping"] * TWO_PI * P["pll_bandwidth_hz"]))
    n = max(1, int(round(dur / ts)))
    spd = cfg.get("speed_hz")
    if spd is None:
        spd = P["rated_freq_hz"]
    ramp = cfg.get("ramp_hz_per_s") or 0.0
    st = cfg.get("angle_step_deg")
    st = 30.0 if st is None else st
    t = np.arange(n + 1) * ts
    w0 = TWO_PI * spd
    theta = [wrap(math.radians(st) + w0 * (k * ts) + math.pi * ramp * (k * ts) ** 2)
             for k in range(n + 1)]
    omega = [w0 + TWO_PI * ramp * (k * ts) for k in range(n + 1)]

    def run(kp, ki, base, gain):
        th, integ, TH, W = 0.0, 0.0, [], []
        for x in theta:
            TH.append(th * base)
            e = math.remainder(x / base - th, TWO_PI / base)
            integ += ki * ts * e
            w = integ + kp * e
            W.append(w)
            th = math.remainder(th + gain * ts * w, TWO_PI / base)
        return TH, W

    v = {}
    v["si"] = run(G["kp"], G["ki"], 1.0, 1.0)
    th, w = run(G["kp_pu"], G["ki_pu"], thb, wb / thb)
    v["pu"] = (th, [x * wb for x in w])
    th, w = run(G["kp"], G["ki"], thb, wb / thb)          # naive: SI gains, pu loop
    v["naive"] = (th, [x * wb for x in w])

    # q15: int16 angle (32768 ↔ π), Q24 speed of ω_b, Q31 angle accumulator, int64 products
    kp = rha(G["kp"] * math.pi / wb * 2.0 ** 24)
    ki = rha(G["ki"] * math.pi / wb * ts * 2.0 ** 24)
    g = rha(2.0 * fb * ts * 2.0 ** 23)
    acc, integ, TH, W = np.int32(0), np.int64(0), [], []
    i32 = (np.int64(-2 ** 31), np.int64(2 ** 31 - 1))
    with np.errstate(over="ignore"):
        for x in theta:
            q = np.int16(np.int64(rha(x * 32768.0 / math.pi)).astype(np.int16))
            h = np.int16(acc >> np.int32(16))
            TH.append(int(h) * math.pi / 32768.0)
            e = np.int64(np.int16(q - h))
            integ = np.clip(integ + ((e * np.int64(ki)) >> np.int64(15)), *i32)
            w = np.clip(integ + ((e * np.int64(kp)) >> np.int64(15)), *i32)
            W.append(int(w) * wb / 2.0 ** 24)
            acc = (np.int64(acc) + ((w * np.int64(g)) >> np.int64(16))).astype(np.int32)
    v["q15"] = (TH, W)

    idx = decim(n + 1)
    variants, metrics = {}, {}
    for name in ("si", "pu", "q15", "naive"):
        th, w = v[name]
        variants[name] = {"theta": [theta[k] for k in idx], "theta_hat": [th[k] for k in idx],
                          "omega_hat": [w[k] for k in idx]}
        err = np.abs([wrap(a - b) for a, b in zip(theta, th)])
        start = min(n, int(math.floor((n + 1) * 0.8)))
        locked = bool(np.all(err[start:] < math.radians(2.0)))
        lt = None
        if locked:
            above = np.nonzero(err >= math.radians(2.0))[0]
            lt = float(t[above[-1] + 1]) if len(above) else float(t[0])
        se = float(np.mean(np.array(w[start:]) - np.array(omega[start:])) / TWO_PI)
        metrics[name] = {"locked": locked, "lock_time_s": lt, "speed_error_hz": se,
                         "max_angle_error_deg": math.degrees(float(np.max(err))),
                         "steady_angle_error_deg": math.degrees(float(np.max(err[start:])))}
    return {"t": t[idx].tolist(), "variants": variants, "metrics": metrics}


def oracle_sim(inp: dict) -> dict:
    base = {k: v for k, v in inp.items() if k != "sim"}
    R = oracle_report(base)
    sim = inp.get("sim") or {}
    return {"current": current_loop(R, sim.get("current") or {}, base),
            "pll": pll(R, sim.get("pll") or {}, base)}


# ----------------------------------------------------------------------------------------
# Cases

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12.0,
                  "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 0.0001}}
V690 = {"motor": {"rated_voltage_v": 690, "rated_current_a": 112, "rated_freq_hz": 50,
                  "rs_ohm": 0.021, "ld_h": 0.0021, "lq_h": 0.0034, "bemf_v": 610.0,
                  "pole_pairs": 3},
        "drive": {"base_freq_hz": 75, "udc_v": 1000, "ts_s": 0.00025}}
IND380 = {"motor": {"rated_voltage_v": 380, "rated_current_a": 14.5, "rated_freq_hz": 50,
                    "rs_ohm": 0.42, "ld_h": 0.0085, "lq_h": 0.0135, "bemf_v": 335.0,
                    "pole_pairs": 2},
          "drive": {"udc_v": 540, "ts_s": 0.000125}}


def with_(base, **sections):
    d = copy.deepcopy(base)
    for k, v in sections.items():
        d.setdefault(k, {}).update(v)
    return d


CASES = [
    # Seed motor, every sim default: i_d step 0.5·I_b at standstill; PLL cold start at the
    # rated 220 Hz with a 30° step, 50 Hz bandwidth — correct scalings lock, naive does not.
    ("01_seed_defaults", with_(SEED, sim={})),
    # Seed motor, i_q step 1.2 A at 150 Hz electrical with the one-sample delay; PLL at
    # 100 Hz with a −120° step and a 500 Hz/s ramp, 2π angle base.
    ("02_seed_q_step_speed_delay",
     with_(SEED, conventions={"angle_base": "2pi"},
           sim={"current": {"axis": "q", "step_a": 1.2, "speed_hz": 150.0, "delay": True,
                            "duration_s": 0.01},
                "pll": {"speed_hz": 100.0, "angle_step_deg": -120.0, "ramp_hz_per_s": 500.0,
                        "duration_s": 0.15}})),
    # 690 V 112 A, Ld ≠ Lq, i_d step −56 A (field weakening direction) at 30 Hz, 150 Hz
    # bandwidth (ω_c·Ts = 0.24); PLL 20 Hz bandwidth.
    ("03_mv690_d_step",
     with_(V690, current_loop={"bandwidth_hz": 150}, pll={"bandwidth_hz": 20},
           sim={"current": {"axis": "d", "step_a": -56.0, "speed_hz": 30.0,
                            "duration_s": 0.06},
                "pll": {"speed_hz": 40.0, "angle_step_deg": 90.0, "duration_s": 0.4}})),
    # 380 V IPM at rated 50 Hz, i_q step 2× rated: the q voltage saturates (pm_maxout_vol),
    # the integral clamp (maxu) is the anti-windup; the fixed-vs-SI metrics show it.
    ("04_ind380_q_saturation",
     with_(IND380, sim={"current": {"axis": "q", "step_a": 29.0, "speed_hz": 50.0,
                                    "duration_s": 0.05},
                        "pll": {"angle_step_deg": 180.0, "duration_s": 0.2}})),
    # A 27 V motor on a 4890.3 V bus: maxu = pm_maxout_vol << 12 = 2^31 wraps to -2^31, so
    # minu = -maxu wraps too and the integral is pinned at -2^31: the PI's sums wrap.
    ("05_seed_maxu_wrapped",
     with_(SEED, motor={"rated_voltage_v": 27}, drive={"udc_v": 4890.3},
           sim={"current": {"duration_s": 0.005}, "pll": {"duration_s": 0.02}})),
]

def compare_rules(inp: dict) -> dict:
    """How tests and the vitest runner compare pulab's "sim" with "expected" (README).

    Scalars: |a − b| ≤ rel·max(|a|, |b|) + abs[path]; a list of floats (time series):
    max |a − b| ≤ rel·max|expected series| (angles: the difference wrapped into [−π, π]);
    bools, ints and nulls exactly.  Absolute floors only for the metrics that are a
    difference of nearly equal numbers (a steady-state error of 1e-16 A, a locked PLL's speed
    error of 1e-14 Hz, a locked PLL's angle error of 1e-11°).  ``skip``: compared to nothing (the naive PLL is unstable, rounding
    differences grow exponentially; only its ``locked`` = false is compared).
    """
    ib = oracle_report({k: v for k, v in inp.items() if k != "sim"})["base"]["I_b"]
    return {"rel": 1e-9,
            "abs": {"current.metrics.*.steady_state_error_a": 1e-9 * ib,
                    "current.metrics.*.overshoot_pct": 1e-7,
                    "pll.metrics.*.speed_error_hz": 1e-6,
                    "pll.metrics.*.steady_angle_error_deg": 1e-9},
            "wrapped": ["pll.variants.*.theta", "pll.variants.*.theta_hat"],
            "skip": ["pll.variants.naive", "pll.metrics.naive.lock_time_s",
                     "pll.metrics.naive.speed_error_hz", "pll.metrics.naive.max_angle_error_deg",
                     "pll.metrics.naive.steady_angle_error_deg"]}


def build() -> dict:
    out = {}
    for name, inp in CASES:
        out[f"{name}.json"] = {"input": inp, "expected": oracle_sim(inp),
                               "compare": compare_rules(inp)}
    return out


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
