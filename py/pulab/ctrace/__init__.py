"""A C-subset interpreter with each target's exact integer semantics.

Paste firmware scaling code, pick a target, give the inputs: :func:`trace`
returns every intermediate value with its C type after the usual arithmetic
conversions, its hex, and the flags the firmware silently suffers (signed
overflow shown as the two's-complement wrap, unsigned wrap, value-changing
conversion, truncating division or shift, shift count out of range,
saturation).  Standard library only; the code is parsed, never ``eval``-ed.

Modules: :mod:`~pulab.ctrace.lexer` (tokens), :mod:`~pulab.ctrace.preprocess`
(macros, ``#if``, standard headers, IQmath conversions), :mod:`~pulab.ctrace.parser`
(the subset, typedefs, ``// @q`` annotations), :mod:`~pulab.ctrace.types`
(targets, type names, conversions), :mod:`~pulab.ctrace.check` (static types),
:mod:`~pulab.ctrace.evaluate` (values and flags, on :mod:`pulab.fixedpoint.cint`),
:mod:`~pulab.ctrace.compile` (the same run as Python closures, for code run many times),
:mod:`~pulab.ctrace.tracing` (the entry point), :mod:`~pulab.ctrace.sequence` (the entry
called N times with the firmware's memory kept), :mod:`~pulab.cli.trace`
(``python -m pulab trace``), :mod:`~pulab.ctrace.examples` (the seed's blocks).

Examples
--------
>>> r = trace("Uint16 Voltage; long x = Voltage * 10;", "c28x", {"Voltage": 6554})
>>> r["vars"]["x"]["value"]
4
"""

from .errors import TraceError
from .tracing import DEFAULT_GLOBAL_Q, compile_code, run_checked, trace, trace_checked
from .types import TARGETS

__all__ = ["trace", "trace_checked", "compile_code", "run_checked", "TraceError", "TARGETS",
           "DEFAULT_GLOBAL_Q"]
