"""The box search every proof runs: best first over boxes of inputs, within a budget.

A proof decides a claim for every point of a box of inputs by evaluating boxes over
intervals (a sound enclosure of every point's values and failures), running single points
concretely where a box may fail, and halving a box that neither decides.  What a box
evaluates to, which points are run and how a failure is reproduced differ between the
proofs — the family proof over a motor's firmware integers (:mod:`pulab.analyses.prove`)
and the code proof over traced C (:mod:`pulab.ctrace.prove`) — and are the ``visit``
callback of :func:`search`; the order (largest share first), the budget, the slices a
caller can cancel between and what is left when the budget runs out are this module's.

Examples
--------
Find an integer x in 0…100 with x·x > 5000, halving a box that may hold one (the first
single point reached, not the smallest):

>>> hits = []
>>> def visit(key, box, data):
...     lo, hi = box["x"]
...     if hi * hi <= 5000:
...         return 1, ()             # proven over the whole box
...     if lo == hi:
...         hits.append(lo)
...         return 1, None           # a counterexample: stop
...     return 1, [(-volume(h), h, None) for h in halve(box, "x")]
>>> steps = search({"x": (0, 100)}, -101, visit, budget=100)
>>> while True:                      # (a caller's slices: pulab.analyses.slices.finish)
...     try:
...         next(steps)
...     except StopIteration as end:
...         work, left = end.value
...         break
>>> hits, work
([82], 37)
"""

from __future__ import annotations

import heapq
import time

__all__ = ["search", "halve", "hull", "headroom_bits", "volume"]


def search(root: dict, key, visit, budget: int, data=None, every: int | None = None,
           seconds: float | None = None):
    """Visit boxes best first (smallest ``key``; ties in the order they were made).

    Parameters
    ----------
    root : dict
        The whole box (what a box is — raw integers, SI ranges — is the caller's).
    key : float or int
        Its priority: the negated share of the whole box, so the largest box comes first.
    visit : callable
        ``visit(key, box, data) → (work, children)``: the work it did (budget units) and the
        boxes it cut the box into, each ``(key, box, data)``; ``data`` travels with a box
        (a forced choice, the run of the box it was cut from).  Children None stop the
        search (the work is counted).
    budget : int
        Work allowed; a box is visited while the work done is below it.
    data : optional
        The root's ``data``.
    every, seconds : optional
        Yield between slices: before the next box once ``every`` units of work are done
        (multiples of it), or once ``seconds`` of wall time have passed since the last yield.

    Returns
    -------
    tuple
        A generator (yielding None between slices; closing it cancels) that returns
        ``(work, left)``: the work done and the heap entries ``(key, order, box, data)`` of
        the boxes never visited (the budget ran out, or ``visit`` stopped the search).
    """
    heap = [(key, 0, root, data)]
    order, work = 1, 0
    last = time.perf_counter() if seconds is not None else 0.0
    while heap and work < budget:
        if every is not None and work and work % every == 0:
            yield
        elif seconds is not None and time.perf_counter() - last > seconds:
            yield
            last = time.perf_counter()
        k, _, box, data = heapq.heappop(heap)
        cost, children = visit(k, box, data)
        work += cost
        if children is None:
            break
        for child in children:
            heapq.heappush(heap, (child[0], order, child[1], child[2]))
            order += 1
    return work, heap


def halve(box: dict, name: str) -> tuple:
    """The two halves of an integer box along input ``name`` (the lower one holds the middle).

    >>> halve({"a": (0, 9), "b": (1, 1)}, "a")
    ({'a': (0, 4), 'b': (1, 1)}, {'a': (5, 9), 'b': (1, 1)})
    """
    lo, hi = box[name]
    mid = lo + (hi - lo) // 2
    return {**box, name: (lo, mid)}, {**box, name: (mid + 1, hi)}


def volume(box: dict, names=None) -> int:
    """The number of integer points of a box (over ``names``, all inputs by default).

    >>> volume({"a": (0, 9), "b": (1, 2)}), volume({"a": (0, 9), "b": (1, 2)}, ["b"])
    (20, 2)
    """
    v = 1
    for lo, hi in (box.values() if names is None else (box[k] for k in names)):
        v *= hi - lo + 1
    return v


def hull(a, b):
    """The smallest interval holding both (either may be None).

    >>> hull(None, (1, 2)), hull((1, 2), (0, 1))
    ((1, 2), (0, 2))
    """
    return b if a is None else a if b is None else (min(a[0], b[0]), max(a[1], b[1]))


def headroom_bits(rng, word) -> int:
    """How many more fractional bits the word holds for every value of a proven range: the
    largest k with (hi + 1)·2^k − 1 ≤ max and lo·2^k ≥ min.

    >>> headroom_bits((3338, 53414), (0, 65535)), headroom_bits((692, 2808), (0, 65535))
    (0, 4)
    """
    lo, hi = rng
    k = 0
    while k < 62 and (hi + 1) << (k + 1) <= word[1] + 1 and lo << (k + 1) >= word[0]:
        k += 1
    return k
