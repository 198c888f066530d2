"""pulab: per-unit and Q-format scaling of PMSM motor-control firmware.

Pure Python standard library, so it imports in a bare Pyodide.  The entry
point is :func:`report` (dict → dict, docs/contract.md); :mod:`pulab.api`
wraps it for JSON callers and ``python -m pulab report FILE`` for the shell.

Layout
------
The package is grouped by layer.  A module imports from its own layer and the
layers listed above it, never from a layer below; the import graph has no cycle.
``tests/py/test_imports.py`` declares the order (``LAYERS``, with the modules that sit
above their folder: the families that call :func:`report`) and checks every import,
deferred ones too::

    fixedpoint/   Q formats and C integer arithmetic; the      qformat, cint, counted,
                  proofs' box search                           interval, boxsearch
    schema/       what an input is and how it is read and      errors, jsontext, textnum,
                  checked; the error texts                     inputs, catalog, vendors (the
                                                               vendors the input knows)
    model/        the per-unit model of one motor and drive    bases, gains, datasheet, board
                                                               (sensing and PWM scales)
    profiles/     firmware scaling, one package per vendor     registry (the list), vendor
                                                               (the interface), inovance
                                                               (+ inovance/code: the seed's
                                                               C, run by ctrace), ti, st, nxp,
                                                               microchip, headers, translate
    ctrace/       the C tracer: a user's own fixed-point code  lexer, parser, check, evaluate…
    analyses/     what is computed from a model                loop/, sim/, review, sweep,
                                                               integers, batch, slices,
                                                               envelope (above base speed)
    (top level)   the ways in and out                          report (dict → dict), qcalc
                                                               (the Q calculator, dict →
                                                               dict), api (JSON text → JSON
                                                               text: call_json, one kind
                                                               per request),
                                                               export (C header, CSV),
                                                               html (notebook tables,
                                                               docs panels),
                                                               benchmark, __main__ (the
                                                               command line: parser, main,
                                                               report, header, translate)
    cli/          the other subcommands                        family (sweep, batch),
                                                               trace

Where a new module goes: a new number format or integer rule → ``fixedpoint``; a
new input check, parser limit or error text → ``schema``; a new per-unit quantity
→ ``model``; a vendor → ``profiles/NAME/`` (one line in ``profiles/registry.py``;
docs/design.md, "Adding a vendor"); a
new computation over a model (margins, responses, families) → ``analyses`` (a report
section: one entry in ``analyses/registry.py``; docs/design.md, "Adding an analysis"); a new
output format → ``export``; a new subcommand → ``cli/`` (registered in ``__main__``).
Tests mirror modules: ``tests/py/test_NAME.py``.

Adding an input field is one entry in :mod:`pulab.schema.fields` (path, kind, unit,
range, default, en/zh label): the validator (:mod:`pulab.schema.validate`), the page's
form (``web/src/generated/schema.json``, rewritten by ``npm run build``), the contract's
input tables (``tests/py/test_schema.py`` prints the text to paste) and the fuzzer follow
from it.  A new error or warning is one entry in :mod:`pulab.schema.catalog` (code → en,
zh text), raised as ``InputError(field, code=..., **params)``.
"""

from .schema.errors import InputError
from .report import format_text, report
from .html import Report

__all__ = ["report", "format_text", "Report", "InputError", "__version__"]
__version__ = "0.1.0"
