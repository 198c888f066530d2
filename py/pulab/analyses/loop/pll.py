"""The PLL loop in discrete time: margins of the scaled and the naive loop (seed 3).

The loop of :mod:`pulab.analyses.sim.pll` (phase detector, firmware PI, integrator with
gain g)::

    e_k = θ_k − θ̂_k,  ω̂_k = PI(e)_k,  θ̂_{k+1} = θ̂_k + g·T_s·ω̂_k
    L(z) = C(z)·g·T_s/(z − 1),  C(z) = ((kp + ki·T_s)·z − kp)/(z − 1)

Correctly scaled (seed 3.1-6, 3.2-5): SI gains with g = 1, or per-unit gains
kp·θ_b/ω_b with g = ω_b/θ_b — the same L.  Naive: SI gains with the per-unit
integrator g = ω_b/θ_b, a loop gain ω_b/θ_b (= 2·f_b for θ_b = π) times too
high.

Both loops are type 2; their only phase crossover is at z = −1 (Nyquist),
where L(−1) = −g·T_s·(2·kp + ki·T_s)/4, so the closed loop is stable exactly
while x = kp·T_s·g < 4/(2 + ki·T_s/kp) ≈ 2 (Jury's condition at z = −1).
``boundary_kp_ts_gain`` is that limit; ``kp_ts_gain`` is x of each loop.

Examples
--------
>>> r = analyze(444.288, 98696.0, 1e-4, 440.0)
>>> r["correct"]["stable"], r["naive"]["stable"], round(r["naive"]["kp_ts_gain"], 2)
(True, False, 19.55)
"""

from __future__ import annotations

from .discrete import margins
from .pi import pi
from .polynomial import multiply

__all__ = ["loop", "analyze"]


def loop(kp: float, ki: float, ts: float, gain: float) -> tuple:
    """(N, D) of L = C(z)·g·T_s/(z − 1)."""
    nc, dc = pi(kp, ki, ts)
    return [gain * ts * c for c in nc], multiply(dc, [1.0, -1.0])


def analyze(kp: float, ki: float, ts: float, naive_gain: float) -> dict:
    """Margins of the correctly scaled PLL and of the naive one.

    Parameters
    ----------
    kp : float > 0, rad/s per rad ; ki : float > 0, rad/s² per rad (SI, seed 3.1-1)
    ts : float > 0, seconds
    naive_gain : float > 0 — ω_b/θ_b, the factor the naive loop has too much

    Returns
    -------
    dict
        ``correct`` and ``naive`` (margins as :func:`pulab.analyses.loop.discrete.margins`
        plus ``kp_ts_gain``), ``boundary_kp_ts_gain``.
    """
    out = {}
    for name, g in (("correct", 1.0), ("naive", naive_gain)):
        num, den = loop(kp, ki, ts, g)
        out[name] = {**margins(num, den, ts), "kp_ts_gain": kp * ts * g}
    out["boundary_kp_ts_gain"] = 4.0 / (2.0 + ki * ts / kp)
    return out
