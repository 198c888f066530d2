"""Real polynomials as coefficient lists (highest power first) and their roots.

Only what the discrete-time loop analysis needs, in plain floats so that it runs
in a bare Pyodide: products, sums, evaluation and all complex roots.

Roots by the Aberth–Ehrlich iteration (simultaneous Newton steps with the
repulsion of the other estimates, cubic convergence for simple roots), started
on a circle of the Fujiwara radius bound, then one guarded Newton step per root
on the original polynomial.  For the degrees here (≤ 16) this converges in a
few dozen sweeps; simple roots come out to a few ulp relative to the
polynomial's scale, multiple roots to about √ε (as with any method that does
not know the multiplicity).  Exact zero roots (trailing zero coefficients, e.g.
from a z⁻ᵏ delay) are split off first and returned as exactly 0.

Examples
--------
>>> sorted(round(r.real, 12) for r in roots([1.0, -6.0, 11.0, -6.0]))
[1.0, 2.0, 3.0]
>>> [round(abs(r), 12) for r in roots([1.0, 0.0, 1.0])]
[1.0, 1.0]
>>> multiply([1.0, -1.0], [1.0, 1.0])
[1.0, 0.0, -1.0]
"""

from __future__ import annotations

import cmath
import math

__all__ = ["multiply", "add", "scale", "reverse", "pad", "evaluate", "roots", "real_roots"]


def multiply(a: list, b: list) -> list:
    """Product of two polynomials."""
    out = [0.0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def pad(a: list, length: int) -> list:
    """``a`` with leading zeros up to ``length`` coefficients (same polynomial)."""
    return [0.0] * (length - len(a)) + list(a)


def add(a: list, b: list) -> list:
    """Sum of two polynomials (aligned at the constant term)."""
    n = max(len(a), len(b))
    return [x + y for x, y in zip(pad(a, n), pad(b, n))]


def scale(a: list, k: float) -> list:
    """k·a."""
    return [k * x for x in a]


def reverse(a: list) -> list:
    """zⁿ·a(1/z) for a polynomial of n+1 coefficients."""
    return list(reversed(a))


def evaluate(a: list, z):
    """a(z) by Horner's rule (z real or complex)."""
    acc = 0.0
    for c in a:
        acc = acc * z + c
    return acc


def _value_and_slope(a: list, z: complex) -> tuple:
    p = 0j
    dp = 0j
    for c in a:
        dp = dp * z + p
        p = p * z + c
    return p, dp


def roots(coefficients: list, max_sweeps: int = 200) -> list:
    """All complex roots of a real polynomial.

    Parameters
    ----------
    coefficients : list of float, highest power first; leading zeros are ignored
    max_sweeps : int ≥ 1, Aberth iterations at most

    Returns
    -------
    list of complex
        deg roots (multiple roots repeated); real roots have imaginary part
        exactly 0 when the iteration put them within 1e-14 of the real axis.
    """
    c = [float(x) for x in coefficients]
    while c and c[0] == 0.0:
        c.pop(0)
    zeros = 0
    while len(c) > 1 and c[-1] == 0.0:
        c.pop()
        zeros += 1
    n = len(c) - 1
    found = [0j] * zeros
    if n <= 0:
        return found
    monic = [x / c[0] for x in c]
    if n == 1:
        return found + [complex(-monic[1], 0.0)]
    if n == 2:
        return found + _quadratic(monic[1], monic[2])
    # Fujiwara bound: every root has |z| ≤ 2·max |a_k|^(1/k) (a_n/2 for the last).
    radius = max(abs(monic[k]) ** (1.0 / k) if k < n else (abs(monic[n]) / 2.0) ** (1.0 / n)
                 for k in range(1, n + 1))
    radius = radius if radius > 0 else 1.0
    z = [radius * cmath.exp(1j * (2.0 * math.pi * k / n + 0.4)) for k in range(n)]
    done = [False] * n
    remaining = n
    pairs = list(zip(monic, [abs(c) for c in monic]))
    for _ in range(max_sweeps):
        for i in range(n):
            if done[i]:
                continue
            zi = z[i]
            # p, p' and the rounding-error bound Σ|a_k|·|z|^k in one Horner pass
            p = dp = 0j
            bound = 0.0
            r = abs(zi)
            for c, m in pairs:
                dp = dp * zi + p
                p = p * zi + c
                bound = bound * r + m
            if abs(p) <= 8e-16 * bound:                # backward error at rounding level
                done[i] = True
                remaining -= 1
                continue
            repel = 0j
            for j in range(n):
                if j != i and z[j] != zi:
                    repel += 1.0 / (zi - z[j])
            ratio = p / dp if dp != 0 else p
            step = ratio / (1.0 - ratio * repel)
            z[i] = zi - step
            if abs(step) <= 1e-15 * abs(z[i]):
                done[i] = True
                remaining -= 1
        if remaining == 0:
            break
    out = []
    for r in z:
        p, dp = _value_and_slope(monic, r)
        if dp != 0:
            better = r - p / dp
            if abs(evaluate(monic, better)) < abs(p):
                r = better
        if abs(r.imag) <= 1e-14 * max(abs(r), 1e-300):
            r = complex(r.real, 0.0)
        out.append(r)
    return found + _conjugate_pairs(out)


def _quadratic(b: float, c: float) -> list:
    """Roots of z² + b·z + c without cancellation (the larger root first, then c/it)."""
    disc = b * b - 4.0 * c
    if disc >= 0:
        big = -0.5 * (b + math.copysign(math.sqrt(disc), b))
        return [complex(big, 0.0), complex(c / big if big != 0 else 0.0, 0.0)]
    re, im = -0.5 * b, 0.5 * math.sqrt(-disc)
    return [complex(re, im), complex(re, -im)]


def _conjugate_pairs(rs: list) -> list:
    """Make complex roots of a real polynomial exact conjugate pairs (mean of each pair)."""
    upper = [r for r in rs if r.imag > 0]
    lower = [r for r in rs if r.imag < 0]
    out = [r for r in rs if r.imag == 0]
    for r in upper:
        if not lower:
            out.append(r)
            continue
        k = min(range(len(lower)), key=lambda i: abs(lower[i] - r.conjugate()))
        mate = lower.pop(k)
        re, im = 0.5 * (r.real + mate.real), 0.5 * (r.imag - mate.imag)
        out += [complex(re, im), complex(re, -im)]
    return out + lower


def _derivative(c: list) -> list:
    n = len(c) - 1
    return [x * (n - k) for k, x in enumerate(c[:-1])]


def _bracketed(c: list, d: list, a: float, b: float, fa: float) -> float:
    """The root of c in [a, b] (sign change), Newton kept inside the bracket, else bisection."""
    x = 0.5 * (a + b)
    for _ in range(100):
        fx = evaluate(c, x)
        if fx == 0.0:
            return x
        if (fx < 0) == (fa < 0):
            a, fa = x, fx
        else:
            b = x
        slope = evaluate(d, x)
        new = x - fx / slope if slope != 0 else a - 1.0
        if not a < new < b:
            new = 0.5 * (a + b)
        # Newton converges quadratically: a step this small leaves only rounding behind.
        if abs(new - x) <= 1e-15 * max(abs(new), 1.0) or b - a <= 4e-16 * max(abs(a), abs(b)):
            return new
        x = new
    return x


def real_roots(coefficients: list, low: float, high: float) -> list:
    """The real roots of a real polynomial in [low, high], sorted, in real arithmetic only.

    The roots of the derivative (found the same way, down to the quadratic formula)
    split the interval into pieces on which the polynomial is monotone; each piece whose
    ends differ in sign holds exactly one root, found by bracketed Newton.  A root of
    even multiplicity (the polynomial touches zero without crossing) is not reported:
    for a loop, a curve that only touches |L| = 1 does not cross over.

    Parameters
    ----------
    coefficients : list of float, highest power first
    low, high : float, low < high — the interval (ends included)

    Examples
    --------
    >>> [round(r, 12) for r in real_roots([1.0, 0.0, -2.0, 0.0], -1.0, 2.0)]   # z³ − 2z
    [0.0, 1.414213562373]
    """
    c = [float(x) for x in coefficients]
    while c and c[0] == 0.0:
        c.pop(0)
    n = len(c) - 1
    if n <= 0:
        return []
    if n == 1:
        r = -c[1] / c[0]
        return [r] if low <= r <= high else []
    if n == 2:
        disc = c[1] * c[1] - 4.0 * c[0] * c[2]
        if disc <= 0:
            return []
        return sorted(r.real for r in _quadratic(c[1] / c[0], c[2] / c[0]) if low <= r.real <= high)
    d = _derivative(c)
    ends = [low] + real_roots(d, low, high) + [high]
    out = []
    f_prev = evaluate(c, low)
    if f_prev == 0.0:
        out.append(low)
    for a, b in zip(ends, ends[1:]):
        f_b = evaluate(c, b)
        if f_b == 0.0:
            out.append(b)
        elif f_prev != 0.0 and (f_prev < 0) != (f_b < 0):
            out.append(_bracketed(c, d, a, b, f_prev))
        f_prev = f_b
    return sorted(set(out))
