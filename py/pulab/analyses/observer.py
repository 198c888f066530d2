"""Sensorless design: the back-EMF observer, the tracking observer, the speed filter, the budget.

Back-EMF observer (the d-q form of NXP's ``AMCLIB_PMSMBemfObsrvDQ``, vendor-neutral): a model
of the winding, discretized by backward Euler at the control period T_s, predicts the current;
a PI on the current error (î − i) is the back-EMF estimate::

    î_k = a·î_{k−1} + b·(u_k − ê_{k−1}),   a = L/(L + T_s·R),   b = T_s/(L + T_s·R)
    ê_k = kp·(î_k − i_k) + Σ ki·T_s·(î − i)

Its error loop is L(z) = C(z)·G(z) with G(z) = b/(z − a) and the firmware PI
C(z) = ((kp + ki·T_s)·z − kp)/(z − 1) (:mod:`pulab.analyses.loop.pi`); gains by pole placement
of the continuous loop L·s² + (R + kp)·s + ki at ω0, ζ: ``kp = 2ζω0·L − R``, ``ki = L·ω0²``
(MCAT's rule, inner_PoSpeBemfDQ.js).  The tracking observer is the angle PLL of
:mod:`pulab.analyses.loop.pll` with ``kp = 2ζω0``, ``ki = ω0²``.  The estimated speed is filtered
by a first-order IIR, bilinear at T_s: ``b0 = b1 = ωcT/(2 + ωcT)``, ``a1 = (ωcT − 2)/(2 + ωcT)``.
Poles and margins are exact from the polynomials (:func:`pulab.analyses.loop.discrete.margins`).

Lowest speed.  The observer reads e = u − R·i − L·di/dt; at a speed n (rpm) it sees the
back-EMF E = ψ·ω (phase peak, ω = n·p·π/30) against what corrupts it::

    err(ω) = ΔR·I + U_dt + (LSB + noise)·|R + jωL_q|

ΔR = R·r_error/100 (the winding hot against the R the observer holds), I the start-up current,
U_dt the dead-time error (:mod:`pulab.model.observer`), LSB and noise in A.  SNR = E/err; the
lowest sensorless speed is where SNR reaches ``snr_min`` (E − snr·err is concave in ω and
negative at 0: one crossing, found by bisection; null when none below 10·N_max).

Examples
--------
>>> d = design(0.55, 0.000403, 1e-4, 300.0, 1.0, 20.0, 1.0, 400.0)
>>> round(d["bemf"]["kp_v_per_a"], 5), d["bemf"]["stable"], d["tracking"]["stable"]
(0.96927, True, True)
>>> round(d["speed_filter"]["b0"], 6)
0.111635
"""

from __future__ import annotations

import cmath
import math

from .loop import pll as _pll
from .loop.discrete import margins
from .loop.pi import pi
from .loop.polynomial import multiply

__all__ = ["design", "budget", "analyze", "lowest_speed"]

_BUDGET_POINTS = 60


def _poles_s(w0: float, zeta: float) -> list:
    """Roots of s² + 2ζω0·s + ω0², [re, im] pairs, rad/s."""
    r = cmath.sqrt(complex(zeta * zeta - 1.0)) * w0
    return [[(-zeta * w0 + s * r).real, (-zeta * w0 + s * r).imag] for s in (1.0, -1.0)]


def _loop_record(num: list, den: list, ts: float, w0: float, zeta: float) -> dict:
    m = margins(num, den, ts)
    return {**m, "continuous_poles": _poles_s(w0, zeta),
            "discrete_poles_of_continuous": [[cmath.exp(complex(*p) * ts).real,
                                              cmath.exp(complex(*p) * ts).imag]
                                             for p in _poles_s(w0, zeta)]}


def bemf_loop(rs: float, l_h: float, ts: float, kp: float, ki: float) -> tuple:
    """(N, D) of the back-EMF observer's error loop C(z)·b/(z − a)."""
    a, b = l_h / (l_h + ts * rs), ts / (l_h + ts * rs)
    nc, dc = pi(kp, ki, ts)
    return [b * c for c in nc], multiply(dc, [1.0, -a])


def design(rs: float, l_h: float, ts: float, bemf_f0_hz: float, bemf_damping: float,
           tracking_f0_hz: float, tracking_damping: float, speed_filter_hz: float) -> dict:
    """Gains, poles and margins of the two observers and the speed filter's coefficients.

    Parameters
    ----------
    rs : float, Ω ; l_h : float, H (the inductance the observer models, L_d for MCAT)
    ts : float, s — control period
    bemf_f0_hz, bemf_damping, tracking_f0_hz, tracking_damping : float — pole placement
    speed_filter_hz : float — the estimated speed's filter corner

    Returns
    -------
    dict
        ``bemf`` and ``tracking``: ``kp``/``ki`` in SI, the margins of
        :func:`pulab.analyses.loop.discrete.margins` (``poles`` = the discrete closed loop),
        ``continuous_poles`` and their images e^{sT}; ``speed_filter``: ``b0``, ``b1``,
        ``a1`` and its pole.
    """
    w0, wt = 2.0 * math.pi * bemf_f0_hz, 2.0 * math.pi * tracking_f0_hz
    kp, ki = 2.0 * bemf_damping * w0 * l_h - rs, l_h * w0 * w0
    bemf = {"kp_v_per_a": kp, "ki_v_per_as": ki,
            **_loop_record(*bemf_loop(rs, l_h, ts, kp, ki), ts, w0, bemf_damping)}
    tkp, tki = 2.0 * tracking_damping * wt, wt * wt
    tracking = {"kp_per_s": tkp, "ki_per_s2": tki,
                **_loop_record(*_pll.loop(tkp, tki, ts, 1.0), ts, wt, tracking_damping)}
    x = 2.0 * math.pi * speed_filter_hz * ts
    b0, a1 = x / (2.0 + x), (x - 2.0) / (2.0 + x)
    return {"bemf": bemf, "tracking": tracking,
            "speed_filter": {"b0": b0, "b1": b0, "a1": a1, "pole": -a1}}


def _error_v(s: dict, motor: dict, w: float) -> float:
    z = math.hypot(motor["rs_ohm"], w * motor["lq_h"])
    return (motor["rs_ohm"] * s["r_error_pct"] / 100.0 * s["startup_current_a"] + s["deadtime_v"]
            + (s["current_lsb_a"] + s["noise_a"]) * z)


def lowest_speed(s: dict, motor: dict) -> float | None:
    """The lowest speed (rpm) where ψ·ω ≥ snr_min·err(ω), or None below 10·N_max."""
    to_w = motor["pole_pairs"] * math.pi / 30.0
    f = lambda n: s["psi_peak"] * n * to_w - s["snr_min"] * _error_v(s, motor, n * to_w)  # noqa: E731
    lo, hi = 0.0, 10.0 * s["max_speed_rpm"]
    if f(hi) < 0.0:
        return None
    if f(lo) >= 0.0:
        return 0.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) >= 0.0:
            hi = mid
        else:
            lo = mid
        if hi - lo <= 1e-12 * hi:
            break
    return hi


def budget(s: dict, motor: dict) -> dict:
    """The back-EMF against its errors over 0..N_max (``speeds_rpm``, ``snr``, the terms)."""
    to_w = motor["pole_pairs"] * math.pi / 30.0
    speeds = [s["max_speed_rpm"] * k / (_BUDGET_POINTS - 1) for k in range(_BUDGET_POINTS)]
    snr, emf, err = [], [], []
    for n in speeds:
        e, x = s["psi_peak"] * n * to_w, _error_v(s, motor, n * to_w)
        emf.append(e)
        err.append(x)
        snr.append(e / x if x > 0.0 else None)
    return {"speeds_rpm": speeds, "snr": snr, "bemf_v": emf, "error_v": err,
            "terms_v": {"resistance": motor["rs_ohm"] * s["r_error_pct"] / 100.0
                        * s["startup_current_a"],
                        "deadtime": s["deadtime_v"],
                        "current_lsb_per_ohm": s["current_lsb_a"],
                        "noise_per_ohm": s["noise_a"]},
            "snr_min": s["snr_min"], "min_speed_rpm": lowest_speed(s, motor)}


def analyze(report: dict, s: dict) -> dict:
    """The report's ``observer`` section (docs/contract.md, "Output: observer").

    ``s``: the settings of :func:`pulab.model.observer.settings`.
    """
    mo, d = report["input"]["motor"], report["input"]["drive"]
    des = design(mo["rs_ohm"], mo["ld_h"], d["ts_s"], s["bemf_f0_hz"], s["bemf_damping"],
                 s["tracking_f0_hz"], s["tracking_damping"], s["speed_filter_hz"])
    return {"settings": s, "design": des, "budget": budget(s, mo)}
