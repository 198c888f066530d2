"""Independent oracle for an induction motor's "sim" (current step and flux build-up).

    .venv/bin/python tests/oracle/acim_sim_oracle.py          # (re)write tests/golden/acim-sim/
    .venv/bin/python tests/oracle/acim_sim_oracle.py --check  # exit 1 if a file is stale

Never imports pulab.  The motor's numbers (σL_s, τ_r, I_m, the PI gains and Inovance
integers) come from tests/oracle/acim_oracle.py; the time domain is written here:

- plant: the induction motor in **flux linkages** (Krause's form; pulab integrates stator
  current and rotor flux), x = (ψ_sd, ψ_sq, ψ_rd, ψ_rq) in a frame at ω_e::

      dψ_s/dt = u − R_s·i_s − jω_e·ψ_s,   dψ_r/dt = −R_r·i_r − j(ω_e − ω_r)·ψ_r,
      [i_s; i_r] = [[L_s, L_m], [L_m, L_r]]⁻¹·[ψ_s; ψ_r]

  discretized for a held voltage with scipy.linalg.expm (Padé; pulab: Taylor scaling and
  squaring), asserted against scipy's solve_ivp (DOP853, rtol 1e-12) over 20 periods;
- controller: indirect rotor-flux orientation, slip i_q*/(τ_r·i_d*) of the references; a float
  PI (integral first, clamp, then the output, clamp) and the seed's integer PI in np.int32
  (Q12 error, Q24 integral, pm_kp Q12, pm_ki Q16; pm_maxout_vol and maxu from the raw
  Voltage and uDCFilter as seed 2.2-1/2 computes them);
- start: the magnetized steady state (current step) or zero (flux build-up); the integrals
  hold the voltages of the steady state before the step: u = R_s·i_s + jω_r·ψ_s.

Each file: {"input", "expected": {"current": {...}, "flux": {...}}, "compare"}; each section
has "t", "variants" ({"si", "fixed"} → id, iq, ud, uq, psi_d, psi_q) and "metrics".
"""

from __future__ import annotations

import copy
import math
import pathlib
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.linalg import expm

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from acim_oracle import KRAUSE_3HP, NXP_KV58, ST_MEZ, expected  # noqa: E402
from golden_files import golden_dir, sync  # noqa: E402
from sim_oracle import decim, rha, step_metrics  # noqa: E402

GOLDEN = pathlib.Path(__file__).resolve().parents[1] / "golden" / "acim-sim"
REL, ABS = 1e-9, 1e-12
KEYS = ("id", "iq", "ud", "uq", "psi_d", "psi_q")


def plant(m: dict, w_e: float, w_r: float, ts: float):
    """(Φ, Γ, C): x_k+1 = Φ·x_k + Γ·u_k over the flux linkages, i_s = C·x."""
    ls, lr, lm, rs, rr = m["ls"], m["lr"], m["lm"], m["rs"], m["rr"]
    minv = np.linalg.inv(np.array([[ls, lm], [lm, lr]]))
    # x = (ψ_sd, ψ_sq, ψ_rd, ψ_rq); currents per axis from the 2×2 inverse
    cur = np.zeros((4, 4))          # (i_sd, i_sq, i_rd, i_rq) = cur·x
    for ax in (0, 1):
        cur[ax, ax], cur[ax, 2 + ax] = minv[0, 0], minv[0, 1]
        cur[2 + ax, ax], cur[2 + ax, 2 + ax] = minv[1, 0], minv[1, 1]
    rot = np.array([[0.0, -1.0], [1.0, 0.0]])     # j·(d, q) = (−q, d)
    a = np.zeros((4, 4))
    a[0:2, :] = -rs * cur[0:2, :]
    a[0:2, 0:2] -= w_e * rot
    a[2:4, :] = -rr * cur[2:4, :]
    a[2:4, 2:4] -= (w_e - w_r) * rot
    b = np.zeros((4, 2))
    b[0, 0] = b[1, 1] = 1.0
    aug = np.zeros((6, 6))
    aug[:4, :4], aug[:4, 4:] = a * ts, b * ts
    e = expm(aug)
    phi, gam = e[:4, :4], e[:4, 4:]
    rng = np.random.default_rng(7)
    x = rng.normal(size=4) * 0.01
    for _ in range(20):             # the discretization against an ODE solver
        u = rng.normal(size=2)
        sol = solve_ivp(lambda _t, y: a @ y + b @ u, (0.0, ts), x, method="DOP853",
                        rtol=1e-12, atol=1e-15)
        want = sol.y[:, -1]
        x = phi @ x + gam @ u
        assert np.max(np.abs(x - want)) <= 1e-10 * max(1.0, np.max(np.abs(want))), (x, want)
    return phi, gam, cur[0:2, :]


def motor_of(inp: dict) -> tuple[dict, dict]:
    """The oracle's acim numbers and bases for one input."""
    e = expected({k: v for k, v in inp.items() if k != "sim"})
    a = e["acim"]
    m = inp["motor"]
    peak = inp.get("conventions", {}).get("base", "rms") == "peak"
    u_ll, i_n = m["rated_voltage_v"], m["rated_current_a"]
    u_b, i_b = (u_ll * math.sqrt(2.0 / 3.0), math.sqrt(2.0) * i_n) if peak else (u_ll / math.sqrt(3.0), i_n)
    mot = {"ls": a["ls_h"], "lr": a["lr_h"], "lm": a["lm_h"], "rs": a["rs_ohm"], "rr": a["rr_ohm"],
           "tau_r": a["tau_r_s"], "i_m": a["id_ref_a"], "sigma_ls": a["sigma_ls_h"]}
    # seed 2.2-1/2: pm_maxout_vol = ((uDCFilter·2316) >> 15 << 12) / Voltage, maxu = it << 12
    voltage, udc10 = rha(u_ll), rha(inp["drive"]["udc_v"] * 10.0)
    maxout = (((udc10 * 2316) >> 15) << 12) // voltage
    ctl = {"pi": e["current_pi"], "u_b": u_b, "i_b": i_b, "maxout": maxout,
           "maxu": int(np.int32(np.int64(maxout) << 12))}
    return mot, ctl


def run(mot: dict, ctl: dict, ts: float, n: int, ref: tuple, w_e: float, w_r: float,
        i0: float, delay: bool) -> dict:
    """The float and the integer PI on the plant for n periods (n + 1 samples)."""
    phi, gam, c = plant(mot, w_e, w_r, ts)
    x0 = np.array([mot["ls"] * i0, 0.0, mot["lm"] * i0, 0.0])     # i_s = (i0, 0), i_r = 0
    # the steady state before the step (ω_e = ω_r): u = R_s·i_s + jω_r·ψ_s
    hold = (mot["rs"] * i0, w_r * mot["ls"] * i0)
    u_b, i_b, pi = ctl["u_b"], ctl["i_b"], ctl["pi"]
    umax, imax = ctl["maxout"] / 4096.0 * u_b, ctl["maxu"] / 2 ** 24 * u_b
    out = {}
    # float
    x = x0.copy()
    integ = [max(-imax, min(imax, h)) for h in hold]
    prev = [max(-umax, min(umax, v)) for v in integ]
    rec = {k: [] for k in KEYS}
    sat = []
    for _ in range(n + 1):
        i = c @ x
        rec["id"].append(i[0]), rec["iq"].append(i[1])
        rec["psi_d"].append(x[2]), rec["psi_q"].append(x[3])
        o = []
        for ax in (0, 1):
            g = pi["dq"[ax]]
            e = ref[ax] - i[ax]
            integ[ax] = max(-imax, min(imax, integ[ax] + g["ki"] * ts * e))
            o.append(max(-umax, min(umax, integ[ax] + g["kp"] * e)))
        sat.append(any(abs(v) >= umax for v in o))
        u, prev = (prev, o) if delay else (o, o)
        rec["ud"].append(u[0]), rec["uq"].append(u[1])
        x = phi @ x + gam @ np.array(u)
    out["si"] = (rec, sat)
    # the seed's integer PI, np.int32 arithmetic (wraps like the C2000's long)
    i32 = np.int32
    maxout, maxu = i32(ctl["maxout"]), i32(ctl["maxu"])
    minu, minout = -maxu, -maxout

    def iqsat(v, hi, lo):
        return hi if v > hi else lo if v < lo else v

    refs = [rha(r / i_b * 4096.0) for r in ref]
    starts = [rha(h / u_b * 2 ** 24) for h in hold]
    integ = [i32(iqsat(i32(s), maxu, minu)) if s else i32(0) for s in starts]
    prev = [max(-ctl["maxout"], min(ctl["maxout"], int(v) >> 12)) * u_b / 4096.0 for v in integ]
    x = x0.copy()
    rec = {k: [] for k in KEYS}
    sat = []
    with np.errstate(over="ignore"):
        for _ in range(n + 1):
            i = c @ x
            rec["id"].append(i[0]), rec["iq"].append(i[1])
            rec["psi_d"].append(x[2]), rec["psi_q"].append(x[3])
            o = []
            for ax in (0, 1):
                g = pi["dq"[ax]]
                fb = max(-32768, min(32767, rha(i[ax] / i_b * 4096.0)))
                e = i32(refs[ax] - fb)
                s = i32(integ[ax] + i32(i32(e * i32(g["pm_ki"])) >> 4))
                integ[ax] = i32(iqsat(s, maxu, minu))
                d = i32(i32(integ[ax] + i32(e * i32(g["pm_kp"]))) >> 12)
                o.append(int(iqsat(d, maxout, minout)))
            sat.append(any(abs(v) == ctl["maxout"] for v in o))
            v = [q * u_b / 4096.0 for q in o]
            u, prev = (prev, v) if delay else (v, v)
            rec["ud"].append(u[0]), rec["uq"].append(u[1])
            x = phi @ x + gam @ np.array(u)
    out["fixed"] = (rec, sat)
    return out


def section(inp: dict, cfg: dict, flux: bool, delay: bool) -> dict:
    mot, ctl = motor_of(inp)
    ts = inp["drive"]["ts_s"]
    i_m = mot["i_m"]
    if flux:
        ref, w_r, i0, axis = (i_m, 0.0), 0.0, 0.0, "d"
        duration = cfg.get("duration_s", max(200 * ts, 5.0 * mot["tau_r"]))
    else:
        axis = cfg.get("axis", "d")
        step = cfg.get("step_a", 0.5 * ctl["i_b"])
        ref = (i_m + step, 0.0) if axis == "d" else (i_m, step)
        w_r, i0 = 2.0 * math.pi * cfg.get("speed_hz", 0.0), i_m
        duration = cfg.get("duration_s", max(200 * ts, 30.0 * mot["sigma_ls"] / ctl["pi"][axis]["kp"]))
    w_e = w_r + ref[1] / (mot["tau_r"] * ref[0])
    n = max(int(round(duration / ts)), 1)
    runs = run(mot, ctl, ts, n, ref, w_e, w_r, i0, delay)
    t = np.arange(n + 1) * ts
    idx = decim(n + 1)
    base = 0.0 if flux or axis == "q" else i_m
    r = ref[0] if axis == "d" else ref[1]
    psi_ref = mot["lm"] * ref[0]
    variants, metrics = {}, {}
    for name, (rec, sat) in runs.items():
        y = np.array(rec["id" if axis == "d" else "iq"]) - base
        mt = step_metrics(t, y, r - base, sat, ts)
        if flux:
            hit = np.nonzero(np.array(rec["psi_d"]) >= 0.95 * psi_ref)[0]
            mt["flux_95_s"] = float(t[hit[0]]) if len(hit) else None
        mt["psi_final_wb"] = float(rec["psi_d"][-1])
        metrics[name] = mt
        variants[name] = {k: [float(rec[k][i]) for i in idx] for k in KEYS}
    return {"t": t[idx].tolist(), "axis": axis, "ref_d_a": ref[0], "ref_q_a": ref[1],
            "omega_e_rad_s": w_e, "psi_ref_wb": psi_ref, "variants": variants, "metrics": metrics,
            "fixed": {"pm_maxout_vol": ctl["maxout"], "maxu": ctl["maxu"]}}


def oracle_sim(inp: dict) -> dict:
    sim = inp["sim"]
    delay = sim.get("current", {}).get("delay", False)
    return {"current": section(inp, sim.get("current", {}), False, delay),
            "flux": section(inp, sim.get("flux", {}), True, delay)}


def with_sim(base: dict, sim: dict) -> dict:
    d = copy.deepcopy(base)
    d.pop("analysis", None)
    d["sim"] = sim
    return d


CASES = [
    # The example motor (ST MEZ header): i_q step 0.75 A at 20 Hz rotor speed; the
    # flux build-up over its default 5·τ_r.
    ("01_st_mez_q_step", with_sim(ST_MEZ, {"current": {"axis": "q", "speed_hz": 20.0}})),
    # Krause's 3-hp machine, peak bases: i_d step +2 A at 30 Hz with the one-sample delay;
    # the build-up over 0.3 s.
    ("02_krause_d_step_delay",
     with_sim(KRAUSE_3HP, {"current": {"axis": "d", "step_a": 2.0, "speed_hz": 30.0,
                                       "delay": True, "duration_s": 0.02},
                           "flux": {"duration_s": 0.3}})),
    # NXP's HVP-KV58 demo motor (230 V, R_r 23 Ω: τ_r = 23 ms), its 150 Hz damping-designed
    # loop: i_q step 0.4 A at 45 Hz; the build-up over its default 5·τ_r.
    ("03_nxp_kv58_q_step",
     with_sim(NXP_KV58, {"current": {"axis": "q", "step_a": 0.4, "speed_hz": 45.0}})),
]


def compare_rules(inp: dict) -> dict:
    """Traces: max |a − b| ≤ rel·max|expected series|; scalars rel·max(|a|, |b|) + abs[path]."""
    return {"rel": 1e-9,
            "abs": {"*.metrics.*.steady_state_error_a": 1e-9, "*.metrics.*.overshoot_pct": 1e-7},
            "wrapped": [], "skip": []}


def build() -> dict:
    return {f"{name}.json": {"input": inp, "expected": oracle_sim(inp),
                             "compare": compare_rules(inp)} for name, inp in CASES}


def main(argv) -> int:
    return sync(build(), golden_dir(argv, GOLDEN), "--check" in argv, REL, ABS)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
