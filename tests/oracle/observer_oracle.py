"""Independent oracle for the report's "observer" section; writes tests/golden/observer/*.json.

    .venv/bin/python tests/oracle/observer_oracle.py          # (re)write the files
    .venv/bin/python tests/oracle/observer_oracle.py --check  # exit 1 if any file is stale

Never imports pulab. Written from the contract (docs/contract.md, "Output: observer"):

- back-EMF observer: the error loop C(z)·b/(z − a), a = L/(L + T·R), b = T/(L + T·R), PI
  C(z) = kp + ki·T·z/(z − 1), kp = 2ζω0·L_d − R, ki = L_d·ω0²; its closed-loop poles are also the
  eigenvalues of the 2×2 error-state matrix (numpy), which must agree with python-control's;
- tracking observer: C(z)·T/(z − 1) with kp = 2ζω_t, ki = ω_t² (python-control margins, poles);
- speed filter: bilinear first-order low-pass;
- lowest speed: ψ·ω = s·(ΔR·I + U_dt + (LSB + noise)·√(R² + ω²L_q²)) solved as a quadratic in ω
  (pulab bisects), the larger root where ψ·ω ≥ s·(ΔR·I + U_dt).
"""

from __future__ import annotations

import copy
import math
import sys
from pathlib import Path

import control
import numpy as np

from golden_files import golden_dir, sync

GOLDEN = Path(__file__).resolve().parents[1] / "golden" / "observer"
REL, ABS = 1e-7, 1e-9

SEED = {"motor": {"rated_voltage_v": 17, "rated_current_a": 1.5, "rated_freq_hz": 220,
                  "rs_ohm": 1.5, "ld_h": 0.0006, "lq_h": 0.0006, "bemf_v": 12, "pole_pairs": 4},
        "drive": {"udc_v": 24, "ts_s": 0.0001}}
LINIX = {"motor": {"rated_voltage_v": 15.0, "rated_current_a": 2.0, "rated_freq_hz": 133.33,
                   "rs_ohm": 0.55, "ld_h": 0.000403, "lq_h": 0.000512, "bemf_v": 9.0,
                   "pole_pairs": 2},
         "drive": {"udc_v": 24, "ts_s": 0.0001, "base_freq_hz": 2 * 4400 / 60}}
SERVO = {"motor": {"rated_voltage_v": 220, "rated_current_a": 2.8, "rated_freq_hz": 200,
                   "rs_ohm": 2.3, "ld_h": 0.0046, "lq_h": 0.0052, "bemf_v": 104.0,
                   "pole_pairs": 4},
         "drive": {"udc_v": 310, "ts_s": 0.0000625}}

CASES = {
    "01_seed_defaults.json": (SEED, {}, None),
    "02_linix_mcat.json": (LINIX, {"bemf_f0_hz": 300, "tracking_f0_hz": 20, "speed_filter_hz": 400,
                                   "startup_current_a": 0.6, "merging_speed_rpm": 500,
                                   "min_speed_rpm": 400, "r_error_pct": 20.0,
                                   "current_lsb_a": 0.004, "noise_a": 0.002}, None),
    "03_servo_deadtime.json": (SERVO, {"bemf_f0_hz": 600, "bemf_damping": 0.8,
                                       "tracking_f0_hz": 50, "tracking_damping": 0.707,
                                       "snr_min": 2.0},
                               {"pwm": {"freq_hz": 16000, "deadtime_s": 1e-6}}),
    "04_underdamped_fast.json": (SEED, {"bemf_f0_hz": 1200, "bemf_damping": 0.4,
                                        "tracking_f0_hz": 200, "tracking_damping": 0.5,
                                        "speed_filter_hz": 100, "r_error_pct": 0.0}, None),
}


def _poles(sys_cl) -> list:
    p = sorted(control.poles(sys_cl), key=lambda z: (z.real, z.imag))
    return [[float(z.real), float(z.imag)] for z in p]


def _loop(num, den, ts) -> dict:
    L = control.tf(num, den, ts)
    gm, pm, _, _, wc, _ = control.stability_margins(L)  # wc: the gain crossover, rad/s
    finite = math.isfinite(pm) and math.isfinite(wc)  # no gain crossover: none (null)
    out = {"poles": _poles(control.feedback(L, 1)),
           "phase_margin_deg": float(pm) if finite else None,
           "crossover_hz": float(wc) / (2 * math.pi) if finite else None}
    # a type-2 loop's phase is −180° at ω → 0 too, where python-control reports a crossing of
    # huge gain; the contract's phase crossovers lie in (0, Nyquist]: those above 1 mrad/s
    gms, _, _, wpcs, _, _ = control.stability_margins(L, returnall=True)
    db = [20 * math.log10(float(g)) for g, w in zip(gms, wpcs) if w > 1e-3 and math.isfinite(g)]
    nyq = complex(L(-1.0 + 0j))  # z = −1 (Nyquist), where the contract checks directly
    if nyq.real < 0 and abs(nyq.imag) <= 1e-9 * abs(nyq):
        db.append(-20 * math.log10(abs(nyq)))
    out["gain_margin_db"] = min(db, key=abs) if db else None
    return out


def expected(inp: dict, o: dict, board) -> dict:
    m, d = inp["motor"], inp["drive"]
    ts, r, ld, lq, p = d["ts_s"], m["rs_ohm"], m["ld_h"], m["lq_h"], m["pole_pairs"]
    w0 = 2 * math.pi * o.get("bemf_f0_hz", 250.0)
    z0 = o.get("bemf_damping", 1.0)
    kp, ki = 2 * z0 * w0 * ld - r, ld * w0 ** 2
    a, b = ld / (ld + ts * r), ts / (ld + ts * r)
    bemf = _loop(np.polymul([b], [kp + ki * ts, -kp]), np.polymul([1, -a], [1, -1]), ts)
    # the same poles as eigenvalues of the error state [ĩ, integral]
    A = np.array([[a - b * kp, -b], [ki * ts * (a - b * kp), 1 - b * ki * ts]])
    eig = sorted(np.linalg.eigvals(A), key=lambda z: (z.real, z.imag))
    assert np.allclose([complex(*x) for x in bemf["poles"]], eig, atol=1e-12)
    wt = 2 * math.pi * o.get("tracking_f0_hz", 15.0)
    zt = o.get("tracking_damping", 1.0)
    tkp, tki = 2 * zt * wt, wt ** 2
    track = _loop(np.polymul([ts], [tkp + tki * ts, -tkp]), np.polymul([1, -1], [1, -1]), ts)
    x = 2 * math.pi * o.get("speed_filter_hz", 400.0) * ts
    # budget
    n_max = 60 * d.get("base_freq_hz", m["rated_freq_hz"]) / p
    psi = math.sqrt(2 / 3) * m["bemf_v"] / (2 * math.pi * m["rated_freq_hz"])
    i_start = o.get("startup_current_a", math.sqrt(2) * m["rated_current_a"])
    r_err = o.get("r_error_pct", 100 * 0.00393 * (155 - 20))
    lsb = o.get("current_lsb_a", 2 * math.sqrt(2) * m["rated_current_a"] / 4096)
    noise = o.get("noise_a", 0.0)
    u_dt = 0.0
    if board and "pwm" in board:
        u_dt = 4 / math.pi * d["udc_v"] * board["pwm"]["deadtime_s"] * board["pwm"]["freq_hz"]
    s = o.get("snr_min", 1.0)
    c0, c1 = r * r_err / 100 * i_start + u_dt, lsb + noise
    qa, qb, qc = psi ** 2 - (s * c1 * lq) ** 2, -2 * psi * s * c0, (s * c0) ** 2 - (s * c1 * r) ** 2
    roots = [float(w.real) for w in np.roots([qa, qb, qc]) if abs(w.imag) < 1e-9 and psi * w.real >= s * c0]
    w_min = max(roots) if roots else None
    low = None if w_min is None or w_min * 30 / (math.pi * p) > 10 * n_max else \
        w_min * 30 / (math.pi * p)
    out = {f"design.bemf.{k}": v for k, v in bemf.items()}
    out.update({f"design.tracking.{k}": v for k, v in track.items()})
    out.update({"design.bemf.kp_v_per_a": kp, "design.bemf.ki_v_per_as": ki,
                "design.speed_filter.b0": x / (2 + x), "design.speed_filter.a1": (x - 2) / (2 + x),
                "budget.min_speed_rpm": low})
    return out


def build() -> dict:
    files = {}
    for name, (base, o, board) in CASES.items():
        inp = copy.deepcopy(base)
        inp["observer"] = dict(o)
        if board:
            inp["board"] = board
        files[name] = {"input": inp, "expected": expected(inp, o, board),
                       "tolerance": {"rel": 1e-6, "abs": 1e-9}}
    return files


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
