"""Input: what a request may contain and how it is read and checked.

:mod:`.fields` is the one table of input fields (path, kind, unit, range, default, en/zh
label); :mod:`.validate` checks every section against it; :mod:`.inputs` fills the report
input's defaults; :mod:`.jsontext` parses request text with size and nesting limits;
:mod:`.textnum` reads numbers typed as text; :mod:`.errors` is the one error (a code, the
field's JSON path, params) and :mod:`.catalog` its English and Chinese text, rendered on
demand (every error of pulab, the C tracer's and the command line's included, is a code).
"""
