"""Resumable computations: generators that yield between slices of work.

A long simulation runs as a generator that yields ``None`` every
:data:`SLICE_STEPS` controller periods and finally returns its result.  The
page's worker drives it slice by slice and returns to its event loop in between,
so a newer input can cancel it (close the generator); every other caller runs
it to the end with :func:`finish`, so there is one implementation, not two.
"""

from __future__ import annotations

__all__ = ["SLICE_STEPS", "finish"]

#: Controller periods per slice: a few tens of milliseconds of the slowest loop in Pyodide.
SLICE_STEPS = 4096


def finish(steps):
    """Run a slice generator to the end and return its result.

    Parameters
    ----------
    steps : generator yielding None, returning the result

    Returns
    -------
    object — the generator's return value

    Examples
    --------
    >>> def count(n):
    ...     for k in range(n):
    ...         yield
    ...     return n
    >>> finish(count(3))
    3
    """
    while True:
        try:
            next(steps)
        except StopIteration as done:
            return done.value
