"""Margins, crossover, bandwidth, poles and Bode data of a discrete SISO loop.

A loop is L(z) = N(z)/D(z) with real coefficients (highest power first),
deg N ≤ deg D = m, sampled at T_s.  Every figure is computed exactly, from
polynomials, not by scanning a grid (z = e^{jθ}, θ = ω·T_s ∈ (0, π]; on the
unit circle 1/z = z̄):

- gain crossover, |L| = 1 ⇔ P(z) = z^m·[N(z)N(1/z) − D(z)D(1/z)] = 0;
- phase crossover, Im L = 0 ⇔ Q(z) = z^m·[N(z)D(1/z) − N(1/z)D(z)] = 0,
  kept where Re L < 0 (θ = π, z = −1, is checked directly);
- closed loop T = L/(1 + L): poles are the roots of D + N; the −3 dB
  bandwidth is the lowest θ with |T|² = |T(1)|²/2, i.e. a root of
  2·N(z)N(1/z) − |T(1)|²·(D+N)(z)(D+N)(1/z) times z^m.

Roots on the unit circle (||z| − 1| < 1e-7) are then polished by Newton's
method on the real function of θ they solve, so the frequencies are exact to
rounding.  Margins as python-control's ``stability_margins`` defines them:

- phase margin PM = (arg L(e^{jθ_c}) mod 360°) − 180°, in [−180°, 180°), at
  the gain crossover with the smallest |PM| when there are several;
- gain margin GM = −20·log10|L(e^{jθ_180})| dB at the phase crossover whose
  |GM| is smallest.

A margin that does not exist (no gain crossover below Nyquist, no phase
crossover; no −3 dB point below Nyquist) is ``None`` (JSON null).  A negative
margin means the closed loop is unstable (``stable`` says so from the poles).

Examples
--------
>>> m = margins([0.5], [1.0, -1.0], 1e-3)       # 0.5/(z − 1): integrator loop
>>> round(m["phase_margin_deg"], 6), round(m["gain_margin_db"], 6)
(75.522488, 12.0412)
>>> m["stable"], m["poles"]
(True, [[0.5, 0.0]])
"""

from __future__ import annotations

import cmath
import math

from .polynomial import add, evaluate, multiply, pad, reverse, roots, scale

__all__ = ["margins", "response", "bode", "log_frequencies", "closed_loop"]

_ON_CIRCLE = 1e-7


def response(num: list, den: list, theta: float) -> complex:
    """L(e^{jθ}) for θ = ω·T_s in radians."""
    z = cmath.exp(1j * theta)
    return evaluate(num, z) / evaluate(den, z)


def closed_loop(num: list, den: list) -> tuple:
    """(N, D + N): the unity-feedback closed loop T = L/(1 + L)."""
    n = max(len(num), len(den))
    return pad(num, n), add(den, num)


def _circle_angles(poly: list) -> list:
    """Angles θ ∈ (0, π] of the roots of ``poly`` on the unit circle."""
    out = []
    for r in roots(poly):
        if abs(abs(r) - 1.0) < _ON_CIRCLE:
            t = abs(cmath.phase(r))
            if t > 1e-12:
                out.append(t)
    return out


def _polish(f, theta: float) -> float:
    """Newton (numeric slope) on a smooth real f(θ), kept inside (0, π]."""
    for _ in range(6):
        h = 1e-7 * max(theta, 1e-6)
        fx = f(theta)
        slope = (f(theta + h) - f(theta - h)) / (2.0 * h)
        if slope == 0 or fx == 0:
            break
        new = theta - fx / slope
        if not 0.0 < new <= math.pi or abs(new - theta) > 1e-3 * theta:
            break
        if abs(new - theta) <= 4e-16 * theta:
            theta = new
            break
        theta = new
    return theta


def _unique(values: list) -> list:
    out = []
    for v in sorted(values):
        if not out or v - out[-1] > 1e-9 * max(v, 1e-12):
            out.append(v)
    return out


def margins(num: list, den: list, ts: float) -> dict:
    """Stability margins, crossovers, bandwidth and poles of L(z) = num/den in unity feedback.

    Parameters
    ----------
    num, den : list of float, highest power of z first; deg num ≤ deg den
    ts : float > 0, seconds — sample time (frequencies come out in Hz)

    Returns
    -------
    dict
        ``phase_margin_deg`` (deg or None), ``gain_margin_db`` (dB or None),
        ``crossover_hz`` (gain crossover of the PM, Hz or None),
        ``phase_crossover_hz`` (of the GM, Hz or None), ``bandwidth_hz``
        (closed-loop −3 dB, Hz; None when none below Nyquist or the closed
        loop is unstable), ``poles`` ([re, im] pairs, sorted),
        ``spectral_radius`` (max |pole|), ``stable`` (all |pole| < 1).
    """
    m = len(den) - 1
    n_p = pad(num, m + 1)
    to_hz = 1.0 / (2.0 * math.pi * ts)

    # gain crossovers: |L| = 1
    p = add(multiply(n_p, reverse(n_p)), scale(multiply(den, reverse(den)), -1.0))
    mag = lambda t: math.log(abs(response(num, den, t)))  # noqa: E731 - local root function
    crossings = _unique([_polish(mag, t) for t in _circle_angles(p)])
    pm, wc = None, None
    for t in crossings:
        value = (math.degrees(cmath.phase(response(num, den, t))) % 360.0) - 180.0
        if pm is None or abs(value) < abs(pm):
            pm, wc = value, t

    # phase crossovers: Im L = 0 with Re L < 0
    q = add(multiply(n_p, reverse(den)), scale(multiply(reverse(n_p), den), -1.0))
    imag = lambda t: response(num, den, t).imag  # noqa: E731
    candidates = [_polish(imag, t) for t in _circle_angles(q) if t < math.pi - 1e-9]
    candidates.append(math.pi)
    gm, w180 = None, None
    for t in _unique(candidates):
        value = response(num, den, t)
        if value.real < 0 and abs(value.imag) <= 1e-9 * abs(value):
            db = -20.0 * math.log10(abs(value))
            if gm is None or abs(db) < abs(gm):
                gm, w180 = db, t

    # closed loop
    cn, cd = closed_loop(num, den)
    poles = sorted(roots(cd), key=lambda r: (r.real, r.imag))
    radius = max((abs(r) for r in poles), default=0.0)
    dc = abs(evaluate(cd, 1.0))
    bandwidth = None
    if radius < 1.0 and dc > 0 and evaluate(cn, 1.0) != 0:
        t0 = abs(evaluate(cn, 1.0) / evaluate(cd, 1.0))
        b = add(scale(multiply(cn, reverse(cn)), 2.0), scale(multiply(cd, reverse(cd)), -t0 * t0))
        drop = lambda t: math.log(abs(response(cn, cd, t)) / t0) + 0.5 * math.log(2.0)  # noqa: E731
        found = [_polish(drop, t) for t in _circle_angles(b)]
        if found:
            bandwidth = min(found) * to_hz
    return {"phase_margin_deg": pm,
            "gain_margin_db": gm,
            "crossover_hz": None if wc is None else wc * to_hz,
            "phase_crossover_hz": None if w180 is None else w180 * to_hz,
            "bandwidth_hz": bandwidth,
            "poles": [[r.real, r.imag] for r in poles],
            "spectral_radius": radius,
            "stable": radius < 1.0}


def log_frequencies(f_low: float, f_high: float, count: int) -> list:
    """``count`` log-spaced frequencies from f_low to f_high inclusive (Hz).

    >>> [round(f, 9) for f in log_frequencies(1.0, 100.0, 3)]
    [1.0, 10.0, 100.0]
    """
    ratio = math.log(f_high / f_low)
    return [f_low * math.exp(ratio * k / (count - 1)) for k in range(count)]


def bode(num: list, den: list, ts: float, frequencies: list) -> dict:
    """Magnitude (dB) and unwrapped phase (deg) of L(e^{jωT_s}) at the given Hz.

    The phase starts in (−180°, 180°] at the first frequency and is unwrapped
    from there, so it is continuous along the plot.
    """
    mags, phases = [], []
    w = 2.0 * math.pi * ts
    prev = None
    for f in frequencies:
        v = response(num, den, w * f)
        mags.append(20.0 * math.log10(abs(v)))
        ph = math.degrees(cmath.phase(v))
        if prev is not None:
            ph -= 360.0 * round((ph - prev) / 360.0)
        phases.append(ph)
        prev = ph
    return {"magnitude_db": mags, "phase_deg": phases}
