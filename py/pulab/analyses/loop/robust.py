"""Tuned cold, runs hot: the current loop's margins when the plant drifts and the gains do not.

The firmware keeps the integers it was given for the nameplate motor (``current_pi.*.
from_integers``: the SI gains the stored integers really are); the motor drifts inside a box:

- winding temperature T ∈ [T_lo, T_hi]: R(T) = R_ref·(1 + α·(T − T_ref)) (copper
  α = 0.00393 /K; R_ref = ``motor.rs_ohm`` at T_ref = 20 °C), and the magnets at the same
  temperature: ψ(T) = ψ_ref·(1 + β·(T − T_ref)) (β of NdFeB −0.12 %/K, SmCo −0.035 %/K,
  ferrite −0.20 %/K, or a number);
- current i ∈ [0, I_peak] (I_peak = 2·``motor.rated_current_a`` unless given): L_d(i),
  L_q(i) fall linearly to (1 − drop)·L at I_peak (drop 30 %), or follow a table of
  (current, L_d, L_q) points, linear between points, held flat beyond the ends;
- bus voltage U_dc·(1 ± 10 %).  With bus-voltage compensation (the default; the PWM
  divides by the measured U_dc) the bus does not change the loop gain; without it the loop
  gain is scaled by U_dc/U_dc,nom.

Each case is the per-axis loop of :mod:`pulab.analyses.loop.current` — the same ZOH plant,
the same delay model, the same firmware PI — measured by
:func:`pulab.analyses.loop.discrete.loop_margins` (python-control's definitions).

How the worst case is searched, and what is guaranteed
------------------------------------------------------
Margins are not monotone in the parameters (the PI zero cancels the nominal plant pole; a
hot motor moves the pole one way, saturation the other, and the gain and phase margins can
trade places), so the corners alone are not enough.  The search:

1. every corner of the box (2 temperatures × 2 currents × 2 bus voltages) and the nominal
   point (T_ref, 0 A, nominal bus);
2. a grid of ``grid`` × ``grid`` points over temperature × current (plus every current of an
   inductance table inside the range), at both bus ends when the bus changes the gain — this
   is also the margin map;
3. from the grid point with the smallest phase margin, a compass search (each coordinate
   ± step, step halved when no neighbour is worse, down to 1/64 of the range).

Guaranteed: every reported number is the exact margin of a plant inside the box, and the
worst case reported is no better than any corner or grid point.  Not guaranteed: that no
point between grid points is worse (the margins are continuous in R and L, so the map shows
how much they change over one cell).  The worst phase margin and the worst gain margin are
searched separately.

Safe bandwidth band: the bandwidths f for which the design by bandwidth
(:func:`pulab.analyses.loop.current.design`, on the nominal plant with the delay) keeps
phase margin ≥ ``min_phase_margin_deg`` and gain margin ≥ ``min_gain_margin_db`` (a missing
gain margin — no phase crossover — counts as infinite) and a stable loop, on both axes, at
every corner.  Scanned on 24 log-spaced bandwidths from f_N/1000 to 0.9·f_N (f_N = 1/(2·T_s)),
the widest safe run kept, its edges bisected to 0.1 %.  An edge at the end of the scan is the
end of the scan, not a limit found.

Examples
--------
>>> cfg = settings({})
>>> cfg["temperature_c"], cfg["copper_alpha_per_k"], cfg["magnet_pct_per_k"]
([20.0, 155.0], 0.00393, -0.12)
>>> round(resistance(1.5, 155.0, cfg), 6)
2.295825
"""

from __future__ import annotations

import math
import random

from ...fixedpoint.qformat import round_half_away
from ...schema.validate import read
from ..sim import decimate_indices
from ..sim.current import default_duration, run_fixed, run_float, voltage_limits
from ..sim.metrics import step_metrics
from ..sim.plant import zoh
from . import current as _current
from .discrete import loop_margins

__all__ = ["config", "settings", "MAGNETS", "resistance", "flux", "inductance", "analyze",
           "monte_carlo", "worst_step", "warnings", "study_row"]

#: Reversible temperature coefficient of the remanence (≈ of ψ), % per K.
MAGNETS = {"ndfeb": -0.12, "smco": -0.035, "ferrite": -0.20}

_AXES = ("d", "q")
_KEYS = ("phase_margin_deg", "gain_margin_db", "crossover_hz", "bandwidth_hz", "stable")


def config(checked: dict) -> dict:
    """The analysis's settings from the checked ``analysis.robust`` section
    (:func:`pulab.schema.validate.read`): the magnet's name becomes its coefficient
    ``magnet_pct_per_k``; everything else as checked (docs/contract.md, "Robustness").
    """
    magnet = checked["magnet"]
    return {("magnet_pct_per_k" if k == "magnet" else k):
            (MAGNETS.get(magnet, magnet) if k == "magnet" else v) for k, v in checked.items()}


def settings(value) -> dict:
    """:func:`config` of the ``analysis.robust`` input ``value``, checked by the schema."""
    return config(read("analysis.robust", value))


# ---- the plant in the box ---------------------------------------------------------------

def resistance(r_ref: float, t_c: float, cfg: dict) -> float:
    """R_s(T) = R_ref·(1 + α·(T − T_ref)), Ω."""
    return r_ref * (1.0 + cfg["copper_alpha_per_k"] * (t_c - cfg["reference_c"]))


def flux(psi_ref: float, t_c: float, cfg: dict) -> float:
    """ψ(T) = ψ_ref·(1 + β·(T − T_ref)), Wb (β in %/K)."""
    return psi_ref * (1.0 + 0.01 * cfg["magnet_pct_per_k"] * (t_c - cfg["reference_c"]))


def inductance(ld: float, lq: float, i_a: float, peak: float, cfg: dict) -> tuple:
    """(L_d, L_q) at current i_a, H: the table, or the linear drop to I_peak."""
    table = cfg["inductance_table"]
    if table is None:
        f = 1.0 - 0.01 * cfg["inductance_drop_pct"] * min(i_a / peak, 1.0)
        return ld * f, lq * f
    if i_a <= table[0][0]:
        return table[0][1], table[0][2]
    for (i0, d0, q0), (i1, d1, q1) in zip(table, table[1:]):
        if i_a <= i1:
            w = (i_a - i0) / (i1 - i0)
            return d0 + w * (d1 - d0), q0 + w * (q1 - q0)
    return table[-1][1], table[-1][2]


class _Drive:
    """The nominal motor, its firmware gains and the drift model, for evaluating cases."""

    def __init__(self, report: dict, cfg: dict, delay: str):
        m, d = report["input"]["motor"], report["input"]["drive"]
        self.cfg, self.delay, self.ts = cfg, delay, d["ts_s"]
        self.rs, self.ld, self.lq = m["rs_ohm"], m["ld_h"], m["lq_h"]
        # RMS phase flux linkage ψ = E_LL/(√3·ω_n), as the review's headroom (whatever the
        # base convention: the headroom below is in RMS quantities)
        self.psi = m["bemf_v"] / (math.sqrt(3.0) * 2.0 * math.pi * m["rated_freq_hz"])
        self.udc, self.f_rated = d["udc_v"], m["rated_freq_hz"]
        self.peak = cfg["peak_current_a"] or 2.0 * m["rated_current_a"]
        self.gains = {a: (report["current_pi"][a]["from_integers"]["kp"],
                          report["current_pi"][a]["from_integers"]["ki"]) for a in _AXES}
        self.memo: dict = {}

    def measure(self, rs: float, l_h: float, kp: float, ki: float) -> dict:
        key = (rs, l_h, kp, ki)
        hit = self.memo.get(key)
        if hit is None:
            m = loop_margins(*_current.loop(kp, ki, rs, l_h, self.ts, self.delay), self.ts)
            hit = self.memo[key] = {k: m[k] for k in _KEYS}
        return hit

    def plant(self, t_c: float, i_a: float, udc: float, factors=(1.0, 1.0, 1.0)) -> dict:
        ld, lq = inductance(self.ld, self.lq, i_a, self.peak, self.cfg)
        return {"rs_ohm": resistance(self.rs, t_c, self.cfg) * factors[0],
                "ld_h": ld * factors[1], "lq_h": lq * factors[1],
                "psi_wb": flux(self.psi, t_c, self.cfg) * factors[2], "udc_v": udc}

    def axes(self, p: dict, gains: dict | None = None) -> dict:
        gains = gains or self.gains
        k = 1.0 if self.cfg["bus_compensated"] else p["udc_v"] / self.udc
        return {a: self.measure(p["rs_ohm"], p[f"l{a}_h"], k * gains[a][0], k * gains[a][1])
                for a in _AXES}

    def case(self, kind: str, t_c: float, i_a: float, udc: float) -> dict:
        p = self.plant(t_c, i_a, udc)
        return {"kind": kind, "temperature_c": t_c, "current_a": i_a, **p,
                **_headroom(p, i_a, self.f_rated), **self.axes(p)}


def _headroom(p: dict, i_a: float, f_rated: float) -> dict:
    """Voltage need at rated frequency against U_dc/√2 (line RMS, the linear SVPWM limit).

    As the review's headroom (seed 1.2-3): i_d = 0, i_q = i (RMS),
    U_LL = √3·|(R·i + ω·ψ, −ω·L_q·i)|; field weakening is needed from the frequency where
    that reaches the limit (the positive root of a quadratic in ω)."""
    avail = p["udc_v"] / math.sqrt(2.0)
    w = 2.0 * math.pi * f_rated
    r, psi, lq = p["rs_ohm"], p["psi_wb"], p["lq_h"]
    need = math.sqrt(3.0) * math.hypot(r * i_a + w * psi, w * lq * i_a)
    v = avail / math.sqrt(3.0)
    a, b, c = psi * psi + (lq * i_a) ** 2, 2.0 * r * i_a * psi, (r * i_a) ** 2 - v * v
    disc = b * b - 4.0 * a * c
    f_fw = None if c >= 0 or disc < 0 else (-b + math.sqrt(disc)) / (2.0 * a) / (2.0 * math.pi)
    return {"voltage_need_v": need, "voltage_limit_v": avail,
            "voltage_headroom_pct": 100.0 * (1.0 - need / avail),
            "field_weakening_from_hz": f_fw}


# ---- ranking ----------------------------------------------------------------------------

def _pm_key(r: dict) -> float:
    """Smaller is worse: unstable first, a missing phase margin (|L| < 1 everywhere) last."""
    if not r["stable"]:
        return -math.inf
    return math.inf if r["phase_margin_deg"] is None else r["phase_margin_deg"]


def _gm_key(r: dict) -> float:
    if not r["stable"]:
        return -math.inf
    return math.inf if r["gain_margin_db"] is None else r["gain_margin_db"]


def _worst_axis(case: dict, key) -> tuple:
    return min(((key(case[a]), a) for a in _AXES), key=lambda x: x[0])


def _passes(r: dict, cfg: dict) -> bool:
    return r["stable"] and _pm_key(r) >= cfg["min_phase_margin_deg"] and \
        _gm_key(r) >= cfg["min_gain_margin_db"]


# ---- the search -------------------------------------------------------------------------

def _linspace(lo: float, hi: float, n: int) -> list:
    return [lo + (hi - lo) * k / (n - 1) for k in range(n)]


def _compass(drive: _Drive, start: tuple, key, box: list) -> tuple:
    """Compass search for the smallest key(worst axis) from start = (T, i, U), inside box."""
    def score(x):
        return _worst_axis(drive.axes(drive.plant(*x)), key)[0]
    x, best = list(start), score(start)
    steps = [0.25 * (hi - lo) for lo, hi in box]
    while any(s > (hi - lo) / 64.0 for s, (lo, hi) in zip(steps, box) if hi > lo):
        moved = False
        for j, (lo, hi) in enumerate(box):
            if hi <= lo:
                continue
            for sign in (-1.0, 1.0):
                y = list(x)
                y[j] = min(max(x[j] + sign * steps[j], lo), hi)
                v = score(tuple(y))
                if v < best:
                    x, best, moved = y, v, True
        if not moved:
            steps = [0.5 * s for s in steps]
    return tuple(x), best


def _safe_band(drive: _Drive, corners: list, cfg: dict) -> list | None:
    lo_f, hi_f = 0.5e-3 / drive.ts, 0.45 / drive.ts       # f_N/1000 … 0.9·f_N
    plants = [drive.plant(c["temperature_c"], c["current_a"], c["udc_v"]) for c in corners]
    nominal = drive.plant(cfg["reference_c"], 0.0, drive.udc)

    def safe(f: float) -> bool:
        gains = {a: _current.design(nominal["rs_ohm"], nominal[f"l{a}_h"], drive.ts, drive.delay,
                                    "bandwidth", f) for a in _AXES}
        return all(_passes(r, cfg) for p in plants for r in drive.axes(p, gains).values())

    scan = [lo_f * (hi_f / lo_f) ** (k / 23.0) for k in range(24)]
    ok = [safe(f) for f in scan]
    runs, start = [], None
    for k, good in enumerate(ok + [False]):
        if good and start is None:
            start = k
        elif not good and start is not None:
            runs.append((start, k - 1))
            start = None
    if not runs:
        return None
    a, b = max(runs, key=lambda r: r[1] - r[0])

    def edge(inside: float, outside: float) -> float:
        while abs(outside - inside) > 1e-3 * inside:
            mid = math.sqrt(inside * outside)
            if safe(mid):
                inside = mid
            else:
                outside = mid
        return inside
    lo = scan[a] if a == 0 else edge(scan[a], scan[a - 1])
    hi = scan[b] if b == len(scan) - 1 else edge(scan[b], scan[b + 1])
    return [lo, hi]


def analyze(report: dict, cfg: dict, delay: str, band: bool = True) -> dict:
    """The report's ``loop.robust`` section (docs/contract.md, "Robustness").

    Parameters
    ----------
    report : dict
        Output of :func:`pulab.report` so far (``input``, ``pu``, ``current_pi``).
    cfg : dict
        The ``analysis.robust`` input as :func:`settings` returns it.
    delay : one of :data:`pulab.analyses.loop.current.DELAYS`
    band : bool — compute the safe bandwidth band (the study mode leaves it out)

    Returns
    -------
    dict
        ``config`` (the validated input, I_peak resolved), ``cases``, ``worst``,
        ``worst_gain``, ``map``, ``safe_bandwidth_hz``, ``safe_bandwidth_scan_hz``,
        ``designed_bandwidth_hz``, ``safe``, ``headroom`` and, when ``samples`` > 0, ``monte_carlo``.
    """
    drive = _Drive(report, cfg, delay)
    cfg = {**cfg, "peak_current_a": drive.peak}
    (t_lo, t_hi), u = cfg["temperature_c"], drive.udc
    u_lo, u_hi = u * (1 - 0.01 * cfg["udc_tolerance_pct"]), u * (1 + 0.01 * cfg["udc_tolerance_pct"])
    cases = [drive.case("nominal", cfg["reference_c"], 0.0, u)]
    cases += [drive.case("corner", t, i, v) for t in (t_lo, t_hi) for i in (0.0, drive.peak)
              for v in (u_lo, u_hi)]
    corners = cases[1:]

    temps = _linspace(t_lo, t_hi, cfg["grid"])
    currents = _linspace(0.0, drive.peak, cfg["grid"])
    if cfg["inductance_table"]:
        currents = sorted(set(currents) | {p[0] for p in cfg["inductance_table"]
                                           if 0.0 < p[0] < drive.peak})
    buses = [u] if cfg["bus_compensated"] else [u_lo, u_hi]
    grid = {a: {"phase_margin_deg": [], "gain_margin_db": []} for a in _AXES}
    worst_start = {}
    for i_a in currents:
        rows = {a: ([], []) for a in _AXES}
        for t in temps:
            results = [(v, drive.axes(drive.plant(t, i_a, v))) for v in buses]
            for a in _AXES:
                pm = min(results, key=lambda x: _pm_key(x[1][a]))[1][a]
                gm = min(results, key=lambda x: _gm_key(x[1][a]))[1][a]
                rows[a][0].append(pm["phase_margin_deg"])
                rows[a][1].append(gm["gain_margin_db"])
            for name, key in (("pm", _pm_key), ("gm", _gm_key)):
                for v, axes in results:
                    score = _worst_axis(axes, key)[0]
                    if name not in worst_start or score < worst_start[name][0]:
                        worst_start[name] = (score, (t, i_a, v))
        for a in _AXES:
            grid[a]["phase_margin_deg"].append(rows[a][0])
            grid[a]["gain_margin_db"].append(rows[a][1])

    box = [(t_lo, t_hi), (0.0, drive.peak), (buses[0], buses[-1])]
    worst = {}
    for name, key in (("pm", _pm_key), ("gm", _gm_key)):
        best_case = min(range(len(cases)), key=lambda k: _worst_axis(cases[k], key)[0])
        x, score = _compass(drive, worst_start[name][1], key, box)
        if score < _worst_axis(cases[best_case], key)[0]:
            cases.append(drive.case("search", *x))
            best_case = len(cases) - 1
        axis = _worst_axis(cases[best_case], key)[1]
        worst[name] = {**cases[best_case], "case": best_case, "axis": axis}

    hot = [c for c in corners if c["temperature_c"] == t_hi]
    cold = [c for c in corners if c["temperature_c"] == t_lo]
    out = {"config": cfg, "cases": cases, "worst": worst["pm"], "worst_gain": worst["gm"],
           "map": {"temperature_c": temps, "current_a": currents, **grid},
           "headroom": {"cold_pct": min(c["voltage_headroom_pct"] for c in cold),
                        "hot_pct": min(c["voltage_headroom_pct"] for c in hot)},
           "designed_bandwidth_hz": {a: cases[0][a]["bandwidth_hz"] for a in _AXES},
           "safe": all(_passes(c[a], cfg) for c in cases for a in _AXES),
           "safe_bandwidth_hz": _safe_band(drive, corners, cfg) if band else None,
           "safe_bandwidth_scan_hz": [0.5e-3 / drive.ts, 0.45 / drive.ts]}
    if band:
        out["step"] = worst_step(report, worst["pm"], delay)
    if cfg["samples"] > 0:
        out["monte_carlo"] = monte_carlo(drive, worst["pm"], cfg["samples"], cfg["seed"])
    return out


def worst_step(report: dict, case: dict, delay: str) -> dict:
    """Current step on the worst case's weaker axis: float PI beside the firmware's fixed point.

    The time simulation of :mod:`pulab.analyses.sim.current` (vendor PI on integers, its
    voltage limits and anti-windup clamp as the firmware holds them for the nominal motor) on
    the drifted plant at standstill, a step of 0.5·I_b.  Its delay model is the simulation's:
    one sample of computation delay unless ``analysis.delay`` is ``none`` (the PWM's half
    period is in the margins, not in this time response).  Run length as the simulation's
    default for the nominal motor (30/ω_c, at least 200 periods); at most 400 points kept.
    """
    inp, b, pi = report["input"], report["base"], report["current_pi"]
    ts = inp["drive"]["ts_s"]
    u_b, i_b = b["U_b"], b["I_b"]
    axis = case["axis"]
    n = int(math.ceil(default_duration(report, axis) / ts))
    step = 0.5 * i_b
    ref_d, ref_q = (step, 0.0) if axis == "d" else (0.0, step)
    umax_pu, imax_pu, ints = voltage_limits(report)
    z = zoh(case["rs_ohm"], case["ld_h"], case["lq_h"], case["psi_wb"], 0.0, ts)
    with_delay = delay != "none"
    gd, gq = pi["d"]["from_integers"], pi["q"]["from_integers"]
    fl = run_float(z, gd["kp"], gd["ki"] * ts, gq["kp"], gq["ki"] * ts, umax_pu * u_b,
                   imax_pu * u_b, ref_d, ref_q, 0.0, n, with_delay)
    t = [k * ts for k in range(n + 1)]
    key = "id" if axis == "d" else "iq"
    keep = decimate_indices(n + 1)
    out = {"case": case["case"], "axis": axis, "ref_a": step, "t": [t[k] for k in keep],
           "float": [fl[key][k] for k in keep], "fixed": None,
           "metrics": {"float": step_metrics(t, list(fl[key]), step, list(fl["sat"]), ts),
                       "fixed": None}, "fixed_vs_float_max_a": None}
    if ints is None:  # the Inovance firmware cannot hold this drive: no fixed-point run
        return out
    maxout, maxu = ints
    fx = run_fixed(z, i_b, u_b, pi["d"]["pm_kp"], pi["d"]["pm_ki"], pi["q"]["pm_kp"],
                   pi["q"]["pm_ki"], maxu, maxout, round_half_away(ref_d / i_b * 4096.0),
                   round_half_away(ref_q / i_b * 4096.0), 0, n, with_delay)
    out["fixed"] = [fx[key][k] for k in keep]
    out["metrics"]["fixed"] = step_metrics(t, list(fx[key]), step, list(fx["sat"]), ts)
    out["fixed_vs_float_max_a"] = max(abs(a - c) for a, c in zip(fl[key], fx[key]))
    return out


# ---- Monte Carlo ------------------------------------------------------------------------

def _step_overshoot(num: list, den: list, steps: int = 200) -> float | None:
    """Overshoot (%) of the unit step response of L/(1 + L), by its difference equation."""
    n = max(len(num), len(den))
    b = [0.0] * (n - len(num)) + list(num)
    a = [x + y for x, y in zip([0.0] * (n - len(den)) + list(den), b)]
    final = sum(b) / sum(a) if sum(a) != 0 else 0.0
    if a[0] == 0 or final == 0:
        return None
    # y_k = (Σ_{j≤k} b_j − Σ_{j≥1} a_j·y_{k−j}) / a_0, the input a unit step
    feed = [sum(b[:k + 1]) for k in range(n)]
    back = [x / a[0] for x in a[1:]]
    hist = [0.0] * (n - 1)                 # y_{k−1}, y_{k−2}, …
    peak = 0.0
    for k in range(steps):
        y = feed[min(k, n - 1)] / a[0]
        for c, h in zip(back, hist):
            y -= c * h
        hist = [y] + hist[:-1]
        if y > peak:
            peak = y
    return max(0.0, 100.0 * (peak / final - 1.0)) if math.isfinite(peak) else None


def _histogram(values: list, bins: int = 20) -> dict:
    finite = [v for v in values if v is not None and math.isfinite(v)]
    if not finite:
        return {"edges": [], "counts": [], "missing": len(values)}
    lo, hi = min(finite), max(finite)
    width = (hi - lo) / bins or 1.0
    counts = [0] * bins
    for v in finite:
        counts[min(int((v - lo) / width), bins - 1)] += 1
    return {"edges": [lo + width * k for k in range(bins + 1)], "counts": counts,
            "missing": len(values) - len(finite)}


def monte_carlo(drive: _Drive, at: dict, samples: int, seed: int, start: int = 0) -> dict:
    """Tolerances drawn around the worst-phase-margin case ``at``.

    Each sample draws, uniformly and in this order, factors 1 ± tol on R_s, on L (both axes
    together: one lamination stack) and on ψ from ``random.Random(seed)`` (standard
    library, the same on every Python ≥ 3.2), so a seed gives the same samples everywhere;
    ``start`` skips that many samples (a worker's slice of a study).  Per sample and axis:
    phase margin, closed-loop bandwidth and step overshoot (200 samples of the closed
    loop's difference equation) with the nominal firmware gains.
    """
    cfg = drive.cfg
    rng = random.Random(seed)
    tol = [0.01 * cfg["tolerance_rs_pct"], 0.01 * cfg["tolerance_l_pct"],
           0.01 * cfg["tolerance_psi_pct"]]
    for _ in range(3 * start):
        rng.random()
    pm = {a: [] for a in _AXES}
    bw = {a: [] for a in _AXES}
    os_ = {a: [] for a in _AXES}
    below = 0
    for _ in range(samples):
        f = tuple(1.0 + t * (2.0 * rng.random() - 1.0) for t in tol)
        p = drive.plant(at["temperature_c"], at["current_a"], at["udc_v"], f)
        k = 1.0 if cfg["bus_compensated"] else p["udc_v"] / drive.udc
        fail, seen = False, {}
        for a in _AXES:
            key = (k * drive.gains[a][0], k * drive.gains[a][1], p[f"l{a}_h"])
            if key not in seen:             # L_d = L_q: the q loop is the d loop
                num, den = _current.loop(key[0], key[1], p["rs_ohm"], key[2], drive.ts,
                                         drive.delay)
                r = loop_margins(num, den, drive.ts)
                seen[key] = (r, _step_overshoot(num, den) if r["stable"] else None)
            r, overshoot = seen[key]
            pm[a].append(r["phase_margin_deg"])
            bw[a].append(r["bandwidth_hz"])
            os_[a].append(overshoot)
            fail = fail or not _passes(r, cfg)
        below += fail
    return {"samples": samples, "seed": seed, "at_case": at["case"], "below": below,
            "fraction_below": below / samples if samples else 0.0,
            "phase_margin_deg": {a: _histogram(pm[a]) for a in _AXES},
            "bandwidth_hz": {a: _histogram(bw[a]) for a in _AXES},
            "overshoot_pct": {a: _histogram(os_[a]) for a in _AXES},
            "min_phase_margin_deg": {a: min((v for v in pm[a] if v is not None), default=None)
                                     for a in _AXES}}


def study_row(report: dict, cfg: dict, delay: str, samples: int, seed: int,
              start: int) -> dict:
    """One motor of a catalogue × tolerance study: the worst case and a slice of samples."""
    r = analyze(report, {**cfg, "samples": 0}, delay, band=False)
    drive = _Drive(report, r["config"], delay)
    mc = monte_carlo(drive, r["worst"], samples, seed, start)
    return {"worst_phase_margin_deg": r["worst"][r["worst"]["axis"]]["phase_margin_deg"],
            "worst_case": r["worst"]["case"], "below": mc["below"], "samples": samples,
            "min_phase_margin_deg": min((v for v in mc["min_phase_margin_deg"].values()
                                         if v is not None), default=None)}


def losses(rob: dict) -> list:
    """Where the nominal gains lose a margin in the box: ``(name, value, params)`` per margin.

    ``name`` is ``worst`` (phase) or ``worst_gain``; ``value`` the margin (None when that
    case is unstable); ``params`` those of catalog entry ``finding.robust_margin``.  The
    review turns each into a finding that points at the designed bandwidth.
    """
    cfg = rob["config"]
    out = []
    for name, key, thr, unit in (("worst", "phase_margin_deg", cfg["min_phase_margin_deg"], "°"),
                                 ("worst_gain", "gain_margin_db", cfg["min_gain_margin_db"], " dB")):
        c = rob[name]
        r = c[c["axis"]]
        v = r[key]
        if r["stable"] and (v is None or v >= thr):
            continue
        band = rob["safe_bandwidth_hz"]
        out.append((name, v if r["stable"] else None, {
            "name": name, "axis": c["axis"], "temp_c": c["temperature_c"],
            "current_a": c["current_a"], "udc_v": c["udc_v"], "threshold": f"{thr:g}{unit}",
            "what": {"code": f"robust.{key.rsplit('_', 1)[0]}", "params": {}},
            "shown": {"code": "robust.unstable", "params": {}} if not r["stable"] else
            f"{v:.1f}{unit}",
            "fix": {"code": "robust.no_band", "params": {}} if band is None else
            {"code": "robust.band", "params": {"lo": band[0], "hi": band[1]}}}))
    return out
