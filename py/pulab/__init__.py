"""pulab: per-unit and Q-format scaling of PMSM motor-control firmware.

Pure Python standard library, so it imports in a bare Pyodide.  The entry
point is :func:`report` (dict → dict, docs/contract.md); :mod:`pulab.api`
wraps it for JSON callers and ``python -m pulab report FILE`` for the shell.
"""

from .errors import InputError
from .report import format_text, report

__all__ = ["report", "format_text", "InputError", "__version__"]
__version__ = "0.1.0"
