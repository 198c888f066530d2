"""Small dense matrices as lists of lists, and the matrix exponential.

Only what the zero-order-hold discretization of the plant needs (seed 1.2-3
discretized exactly instead of with the seed's Euler step 1.2-4), in plain
floats so that it runs in a bare Pyodide without numpy.

Examples
--------
>>> e = expm([[0.0, 1.0], [0.0, 0.0]])          # nilpotent: exp = I + M
>>> [[round(x, 15) for x in row] for row in e]
[[1.0, 1.0], [0.0, 1.0]]
"""

from __future__ import annotations

import math

__all__ = ["identity", "matmul", "expm"]


def identity(n: int) -> list:
    """The n×n identity matrix."""
    return [[1.0 if i == j else 0.0 for j in range(n)] for i in range(n)]


def matmul(a: list, b: list) -> list:
    """Matrix product a·b of lists of lists."""
    bt = list(zip(*b))
    return [[math.fsum(x * y for x, y in zip(row, col)) for col in bt] for row in a]


def expm(m: list, terms: int = 24) -> list:
    """Matrix exponential exp(M) by scaling and squaring with a Taylor series.

    M is scaled by 2^-s so that its ∞-norm is at most 1/2, where a Taylor
    series of ``terms`` terms is exact to far below one ulp ((1/2)^25/25! ≈
    2e-33), then squared s times.  For the 4×4 augmented plant matrices used
    here (s ≤ a few) this is accurate to a few ulp, which is what lets the SI
    and per-unit simulations agree to ~1e-14.

    Parameters
    ----------
    m : list of n lists of n floats
    terms : int ≥ 1, number of Taylor terms after scaling

    Returns
    -------
    list of lists
        exp(M).
    """
    n = len(m)
    norm = max(sum(abs(x) for x in row) for row in m)
    s = 0
    if norm > 0.5:
        s = int(math.ceil(math.log2(norm / 0.5)))
    scale = 2.0 ** -s
    x = [[v * scale for v in row] for row in m]
    result = identity(n)
    term = identity(n)
    for k in range(1, terms + 1):
        # term_k = term_{k-1}·X/k; stop early once it no longer changes the sum.
        term = [[v / k for v in row] for row in matmul(term, x)]
        result = [[a + b for a, b in zip(ra, rb)] for ra, rb in zip(result, term)]
        if max(abs(v) for row in term for v in row) < 1e-300:
            break
    for _ in range(s):
        result = matmul(result, result)
    return result
