"""Margins, crossover, bandwidth, poles and Bode data of a discrete SISO loop.

A loop is L(z) = N(z)/D(z) with real coefficients (highest power first),
deg N ≤ deg D = m, sampled at T_s.  Every figure is computed exactly, from
polynomials, not by scanning a grid (z = e^{jθ}, θ = ω·T_s ∈ (0, π]; on the
unit circle 1/z = z̄):

- gain crossover, |L| = 1 ⇔ N(z)N(1/z) − D(z)D(1/z) = 0;
- phase crossover, Im L = 0 ⇔ Im N(z)D(1/z) = 0, kept where Re L < 0
  (θ = π, z = −1, is checked directly);
- closed loop T = L/(1 + L): poles are the roots of D + N; the −3 dB
  bandwidth is the lowest θ with 2·|N|² − |T(1)|²·|D + N|² = 0.

On the circle a(z)·b(1/z) = Σ c_k·e^{jkθ} (c_k the correlation of the
coefficients), so each condition is a cosine series Σ α_k·cos kθ or a sine
series sin θ·Σ β_k·U_{k−1}(cos θ): with c = cos θ and Chebyshev polynomials
it becomes a real polynomial of degree m (half the degree of the z-domain
form) whose real roots in [−1, 1] are the crossings (found in real arithmetic,
:func:`pulab.analyses.loop.polynomial.real_roots`).  Each is then polished by
Newton's method on the real function of θ it solves, so the frequencies are
exact to rounding.  Margins as python-control's ``stability_margins`` defines them:

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
from functools import lru_cache

from .polynomial import add, evaluate, pad, real_roots, roots

__all__ = ["margins", "loop_margins", "forget", "response", "bode", "curve", "values", "unit_circle", "log_frequencies",
           "closed_loop"]



def response(num: list, den: list, theta: float) -> complex:
    """L(e^{jθ}) for θ = ω·T_s in radians."""
    z = cmath.exp(1j * theta)
    return evaluate(num, z) / evaluate(den, z)


def closed_loop(num: list, den: list) -> tuple:
    """(N, D + N): the unity-feedback closed loop T = L/(1 + L)."""
    n = max(len(num), len(den))
    return pad(num, n), add(den, num)


def _correlation(a: list, b: list) -> list:
    """c_k, k = −m..m (index k + m), of a(z)·b(1/z) = Σ c_k·z^k; a, b of m+1 coefficients."""
    m = len(a) - 1
    lo, hi = a[::-1], b[::-1]                      # ascending powers
    return [math.fsum(lo[j + k] * hi[j] for j in range(max(0, -k), min(m, m - k) + 1))
            for k in range(-m, m + 1)]


@lru_cache(maxsize=32)
def _chebyshev(kind: int, count: int) -> tuple:
    """T_0..T_{count−1} (kind 1) or U_0..U_{count−1} (kind 2), ascending coefficient lists."""
    out = [[1.0], [0.0, float(kind)]]
    while len(out) < count:
        a, b = out[-1], out[-2]
        nxt = [0.0] + [2.0 * x for x in a]
        for i, x in enumerate(b):
            nxt[i] -= x
        out.append(nxt)
    return tuple(out[:count])


def _cosine_roots(alpha: list) -> list:
    """θ ∈ (0, π] where Σ_k alpha_k·cos(kθ) = 0 (via c = cos θ and T_k(c))."""
    poly = [0.0] * len(alpha)
    for a, t in zip(alpha, _chebyshev(1, len(alpha))):
        for i, x in enumerate(t):
            poly[i] += a * x
    return _angles(poly)


def _sine_roots(beta: list) -> list:
    """θ ∈ (0, π) where Σ_{k≥1} beta_k·sin(kθ) = sin θ·Σ beta_k·U_{k−1}(cos θ) = 0."""
    poly = [0.0] * max(len(beta) - 1, 1)
    for b, u in zip(beta[1:], _chebyshev(2, len(beta) - 1)):
        for i, x in enumerate(u):
            poly[i] += b * x
    return [t for t in _angles(poly) if t < math.pi]


def _angles(ascending: list) -> list:
    """acos of the real roots in [−1, 1] of a polynomial in c (ascending coefficients)."""
    return [math.acos(c) for c in real_roots(ascending[::-1], -1.0, 1.0) if c < 1.0]


def _cosine_series(pairs: list) -> list:
    """alpha_k of Σ w·a(z)a(1/z) on the unit circle, for (w, a) pairs of equal length."""
    m = len(pairs[0][1]) - 1
    alpha = [0.0] * (m + 1)
    for w, a in pairs:
        c = _correlation(a, a)
        alpha[0] += w * c[m]
        for k in range(1, m + 1):
            alpha[k] += w * (c[m + k] + c[m - k])
    return alpha


def _polish(f, theta: float) -> float:
    """Newton (forward-difference slope) on a smooth real f(θ), kept inside (0, π].

    The roots come from the cos θ polynomial already close (1e-10 or better), so one or
    two steps reach rounding level."""
    fx = f(theta)
    for _ in range(3):
        h = 1e-7 * max(theta, 1e-6)
        if fx == 0:
            break
        slope = (f(theta + h) - fx) / h
        if slope == 0:
            break
        new = theta - fx / slope
        if not 0.0 < new <= math.pi or abs(new - theta) > 1e-3 * theta:
            break
        done = abs(new - theta) <= 1e-12 * theta    # quadratic: the next step is below rounding
        theta = new
        if done:
            break
        fx = f(theta)
    return theta


def _unique(values: list) -> list:
    out = []
    for v in sorted(values):
        if not out or v - out[-1] > 1e-9 * max(v, 1e-12):
            out.append(v)
    return out


_MEMO: dict = {}


def forget() -> None:
    """Empty the memo of :func:`margins` (:func:`pulab.analyses.loop.analyze` does, once per report,
    so that it only joins identical loops within one report, never across reports)."""
    _MEMO.clear()


def margins(num: list, den: list, ts: float) -> dict:
    """:func:`loop_margins`, memoized: the d and q loops of a motor with L_d = L_q are one loop."""
    key = (tuple(num), tuple(den), ts)
    hit = _MEMO.get(key)
    if hit is None:
        hit = _MEMO[key] = loop_margins(num, den, ts)
    return {**hit, "poles": [list(p) for p in hit["poles"]]}


def loop_margins(num: list, den: list, ts: float) -> dict:
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

    # gain crossovers: |N|² − |D|² = 0
    mag = lambda t: math.log(abs(response(num, den, t)))  # noqa: E731 - local root function
    # A root where N vanishes too is a pole and a zero cancelling on the unit circle (a PI whose
    # integral gain rounded to 0 against its integrator), not a crossing: |L| is 0 there, not 1.
    crossings = _unique([_polish(mag, t)
                         for t in _cosine_roots(_cosine_series([(1.0, n_p), (-1.0, den)]))
                         if abs(response(num, den, t)) > 0.0])
    pm, wc = None, None
    for t in crossings:
        value = (math.degrees(cmath.phase(response(num, den, t))) % 360.0) - 180.0
        if pm is None or abs(value) < abs(pm):
            pm, wc = value, t

    # phase crossovers: Im N(z)·D(1/z) = 0 with Re L < 0
    c = _correlation(n_p, den)
    imag = lambda t: response(num, den, t).imag  # noqa: E731
    candidates = [_polish(imag, t) for t in _sine_roots([0.0] + [c[m + k] - c[m - k]
                                                                 for k in range(1, m + 1)])]
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
        drop = lambda t: math.log(abs(response(cn, cd, t)) / t0) + 0.5 * math.log(2.0)  # noqa: E731
        found = [_polish(drop, t) for t in
                 _cosine_roots(_cosine_series([(2.0, cn), (-t0 * t0, cd)]))]
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


def unit_circle(ts: float, frequencies: list) -> list:
    """z = e^{j·2π·f·T_s} for each frequency f (Hz)."""
    w = 2.0 * math.pi * ts
    return [cmath.exp(1j * w * f) for f in frequencies]


def values(num: list, den: list, points: list) -> list:
    """num(z)/den(z) at each z."""
    return [evaluate(num, z) / evaluate(den, z) for z in points]


def curve(samples: list) -> dict:
    """Magnitude (dB) and unwrapped phase (deg) of complex samples along a frequency axis.

    The phase starts in (−180°, 180°] at the first sample and is unwrapped from
    there, so it is continuous along the plot.
    """
    reals = [v.real for v in samples]
    imags = [v.imag for v in samples]
    mags = [10.0 * x for x in map(math.log10, [a * a + b * b for a, b in zip(reals, imags)])]
    raw = list(map(math.atan2, imags, reals))
    phases = []
    offset, prev = 0.0, raw[0] if raw else 0.0
    two_pi, to_deg = 2.0 * math.pi, 180.0 / math.pi
    for ph in raw:
        step = ph - prev
        if step > math.pi:
            offset -= two_pi
        elif step < -math.pi:
            offset += two_pi
        prev = ph
        phases.append((ph + offset) * to_deg)
    return {"magnitude_db": mags, "phase_deg": phases}


def bode(num: list, den: list, ts: float, frequencies: list) -> dict:
    """:func:`curve` of L(e^{jωT_s}) = num/den at the given frequencies (Hz)."""
    return curve(values(num, den, unit_circle(ts, frequencies)))
