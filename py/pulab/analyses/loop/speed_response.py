"""Speed step and load step with the current loop inside: float next to fixed point.

Plant (q axis, i_d held at 0 so the d axis and its coupling drop out; seed 1.2-3
and the mechanics of :mod:`pulab.analyses.loop.speed`), state x = (i_q [A], ω_m [rad/s])::

    L_q·di_q/dt = u_q − R_s·i_q − p·ψ_r·ω_m
    J·dω_m/dt   = K_t·i_q − T_L − B·ω_m

discretized exactly for a hold over half a period (Van Loan, one
:func:`pulab.analyses.sim.linalg.expm`), so that the delay models of
:mod:`pulab.analyses.loop.current` are exact in time as well: ``none`` applies u_k over
[t_k, t_k+1); ``computation`` applies u_{k−1}; ``computation_pwm`` applies
u_{k−2} over the first and u_{k−1} over the second half.

Every current period the q current PI runs; every ``ratio`` periods the speed PI
runs on the filtered speed.  Variants:

``float``
    Both PIs in SI floats (firmware form, integral clamped at the limits the
    firmware uses: ±maxu/2^24·U_b and ±pm_maxout_vol/2^12·U_b for the current PI,
    ±current_limit for the speed PI).
``fixed``
    The firmware: speed quantized to Q15 of ω_b (round to nearest), the filter in
    Q15 (α in Q15, rounded shift), the speed PI in the module's Q formats
    (e Q15, pm_kp Q12, pm_ki Q16, integral Q24, output Q12 current reference,
    int64 products), the current read as Q12 and the vendor current PI
    (:func:`pulab.profiles.inovance.code.current_pi_step`).

The speed reference steps by ``step_pu``·ω_mb at t = 0; the load torque steps
by ``load_pu``·T_mb at the middle of the run.
"""

from __future__ import annotations

import math

from ..sim import decimate_indices
from ..sim.current import voltage_limits
from ..sim.linalg import expm
from ..sim.metrics import overshoot_pct, rise_time, settling_time
from ...fixedpoint.qformat import round_half_away
from ...profiles.inovance.code import current_pi_step

__all__ = ["run", "MAX_STEPS"]

#: At most this many current-loop periods per run.
MAX_STEPS = 100_000


def _half_step(rs, lq, psi_p, kt, inertia, friction, ts) -> tuple:
    """Φ, Γ (row-major) of the (i_q, ω_m) plant over ts/2; inputs (u_q, T_L)."""
    h = 0.5 * ts
    aug = [[-rs / lq * h, -psi_p / lq * h, h / lq, 0.0],
           [kt / inertia * h, -friction / inertia * h, 0.0, -h / inertia],
           [0.0, 0.0, 0.0, 0.0], [0.0, 0.0, 0.0, 0.0]]
    e = expm(aug)
    return (e[0][0], e[0][1], e[1][0], e[1][1]), (e[0][2], e[0][3], e[1][2], e[1][3])


def _clamp(x, limit):
    return limit if x > limit else -limit if x < -limit else x


def _simulate(fixed: bool, c: dict) -> dict:
    (p0, p1, p2, p3), (g0, g1, g2, g3) = c["phi"], c["gamma"]
    n, ratio, delay = c["n"], c["ratio"], c["delay"]
    i, w = 0.0, 0.0
    u_prev = u_prev2 = 0.0
    out_w, out_i, out_ref, sat = [], [], [], []
    # float state
    integ_s = 0.0
    y = 0.0
    integ_c = 0.0
    iq_ref = 0.0
    # fixed state
    integ_s24 = 0
    y15 = 0
    integ_c24 = 0
    ref12 = 0
    memo: dict = {}
    to_q15 = 32768.0 / c["w_mb"]
    to_q12 = 4096.0 / c["i_b"]
    lim12 = round_half_away(c["limit_a"] * to_q12)
    lim24 = lim12 << 12
    for k in range(n + 1):
        load = c["load_nm"] if k >= c["k_load"] else 0.0
        if k % ratio == 0:
            if fixed:
                x15 = round_half_away(w * to_q15)
                y15 += (c["alpha_q15"] * (x15 - y15) + 16384) >> 15
                e = c["ref_q15"] - y15
                integ_s24 = _clamp(integ_s24 + ((e * c["pm_ki_s"]) >> 7), lim24)
                ref12 = _clamp((integ_s24 >> 12) + ((e * c["pm_kp_s"]) >> 15), lim12)
                iq_ref = ref12 / to_q12
            else:
                y += c["alpha"] * (w - y)
                e = c["ref"] - y
                integ_s = _clamp(integ_s + c["ki_ts_s"] * e, c["limit_a"])
                iq_ref = _clamp(c["kp_s"] * e + integ_s, c["limit_a"])
        out_w.append(w)
        out_i.append(i)
        out_ref.append(iq_ref)
        if fixed:
            v = i * to_q12
            fb = int(v + 0.5) if v >= 0 else -int(0.5 - v)
            fb = 32767 if fb > 32767 else -32768 if fb < -32768 else fb
            key = (integ_c24, ref12 - fb)
            r = memo.get(key)
            if r is None:
                if len(memo) > 4096:
                    memo.clear()
                r = memo[key] = current_pi_step(integ_c24, ref12 - fb, c["pm_kp"], c["pm_ki"],
                                                c["maxu"], c["maxout"])
            integ_c24, u = r[0], r[1] * c["u_b"] / 4096.0
            sat.append(abs(r[1]) == c["maxout"] or abs(ref12) == lim12)
        else:
            integ_c = _clamp(integ_c + c["ki_ts"] * (iq_ref - i), c["imax"])
            u = _clamp(c["kp"] * (iq_ref - i) + integ_c, c["umax"])
            sat.append(abs(u) == c["umax"] or abs(iq_ref) == c["limit_a"])
        if delay == "none":
            first = second = u
        elif delay == "computation":
            first = second = u_prev
        else:
            first, second = u_prev2, u_prev
        u_prev2, u_prev = u_prev, u
        for v in (first, second):
            i, w = p0 * i + p1 * w + g0 * v + g1 * load, p2 * i + p3 * w + g2 * v + g3 * load
    return {"w": out_w, "i": out_i, "ref": out_ref, "sat": sat}


def run(report: dict, s: dict, sp: dict, mech: dict, delay: str) -> dict:
    """The ``loop.speed.response`` section.

    Parameters
    ----------
    report : dict — the report (input, base, pu, vendor, current_pi)
    s : dict — resolved ``analysis.speed`` ; sp : dict — the speed section so far
    mech : dict — :func:`pulab.analyses.loop.speed.mechanical_bases`
    delay : one of :data:`pulab.analyses.loop.current.DELAYS`

    Returns
    -------
    dict
        ``t`` (s), ``t_load_s``, ``reference_rpm``, ``load_nm``, ``variants``:
        ``float``/``fixed`` → ``speed_rpm``, ``iq_a``, ``iq_ref_a`` (≤ 400 points),
        ``metrics``: ``float``/``fixed`` → ``rise_time_s``, ``overshoot_pct``,
        ``settling_time_s`` (of the step, before the load), ``load_dip_rpm``,
        ``saturation_time_s``; ``fixed_vs_float_max_rpm``.  No ``fixed`` (and a null
        difference) when the Inovance firmware cannot hold this drive
        (:func:`pulab.analyses.sim.current.voltage_limits`).
    """
    inp, b, gq = report["input"], report["base"], report["current_pi"]["q"]
    m, ts = inp["motor"], inp["drive"]["ts_s"]
    zeta_wn = s["damping"] * 2.0 * math.pi * s["bandwidth_hz"]
    t_load = max(10.0 / zeta_wn, 20.0 * s["ts_s"])
    n = min(int(round(2.0 * t_load / ts)), MAX_STEPS)
    k_load = min(int(round(t_load / ts)), n // 2)
    phi, gamma = _half_step(m["rs_ohm"], m["lq_h"], m["pole_pairs"] * report["pu"]["psi_r_wb"],
                            mech["kt_nm_per_a"], s["inertia_kg_m2"], s["friction_nm_s"], ts)
    umax_pu, imax_pu, ints = voltage_limits(report)
    maxout, maxu = ints if ints is not None else (None, None)
    alpha = 1.0 - math.exp(-2.0 * math.pi * s["filter_hz"] * s["ts_s"])
    ref = s["step_pu"] * mech["w_mb"]
    c = {"phi": phi, "gamma": gamma, "n": n, "ratio": s["ratio"], "delay": delay,
         "w_mb": mech["w_mb"], "i_b": b["I_b"], "u_b": b["U_b"], "limit_a": s["current_limit_a"],
         "load_nm": s["load_pu"] * mech["torque_nm"], "k_load": k_load,
         "alpha": alpha, "alpha_q15": round_half_away(alpha * 32768.0),
         "ref": ref, "ref_q15": round_half_away(s["step_pu"] * 32768.0),
         "kp_s": sp["kp"], "ki_ts_s": sp["ki"] * s["ts_s"],
         "pm_kp_s": sp["pm_kp"], "pm_ki_s": sp["pm_ki"],
         "kp": gq["kp"], "ki_ts": gq["ki"] * ts,
         "umax": umax_pu * b["U_b"], "imax": imax_pu * b["U_b"],
         "pm_kp": gq["pm_kp"], "pm_ki": gq["pm_ki"], "maxu": maxu, "maxout": maxout}
    runs = {"float": _simulate(False, c)}
    if ints is not None:  # the firmware's fixed point, when it can hold this drive
        runs["fixed"] = _simulate(True, c)
    t = [k * ts for k in range(n + 1)]
    idx = decimate_indices(n + 1)
    rpm = 30.0 / math.pi
    variants, metrics = {}, {}
    for name, r in runs.items():
        variants[name] = {"speed_rpm": [r["w"][k] * rpm for k in idx],
                          "iq_a": [r["i"][k] for k in idx],
                          "iq_ref_a": [r["ref"][k] for k in idx]}
        head_t, head_w = t[:k_load], r["w"][:k_load]
        before = r["w"][k_load]
        metrics[name] = {"rise_time_s": rise_time(head_t, head_w, ref),
                         "overshoot_pct": overshoot_pct(head_w, ref),
                         "settling_time_s": settling_time(head_t, head_w, ref),
                         "load_dip_rpm": (before - min(r["w"][k_load:])) * rpm
                         if c["load_nm"] >= 0 else (max(r["w"][k_load:]) - before) * rpm,
                         "saturation_time_s": sum(r["sat"]) * ts}
    diff = None if "fixed" not in runs else \
        max(abs(a - b_) for a, b_ in zip(runs["fixed"]["w"], runs["float"]["w"])) * rpm
    return {"t": [t[k] for k in idx], "t_load_s": k_load * ts, "reference_rpm": ref * rpm,
            "load_nm": c["load_nm"], "variants": variants, "metrics": metrics,
            "fixed_vs_float_max_rpm": diff}
