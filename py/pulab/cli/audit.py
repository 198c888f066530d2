"""The ``audit`` subcommand: read generated vendor headers back into their design.

::

    pulab audit pmsm_motor_parameters.h drive_parameters.h power_stage_parameters.h \\
        parameters_conversion.h                       # ST MCSDK set, vendor detected
    pulab audit user_mtr1.h user_common.h --profile ti -D BSXL8323RS_REVA

prints :func:`pulab.analyses.audit.audit`'s result as JSON (docs/contract.md, "Audit").
Exit status 0 (findings are data); 2 with one line ``error: FIELD: MESSAGE`` on stderr: a
file that cannot be read, is empty, is no text or is larger than the limit, a preprocessor
error or a known ``#define`` that does not evaluate (``FILE:LINE``), no macro of a known
vendor, an unknown ``--profile``.
"""

from __future__ import annotations

import json
import os
import sys

from ..analyses.audit import MAX_CHARS, audit
from ..schema.errors import InputError

__all__ = ["add_audit_parser", "read_header"]


def add_audit_parser(sub) -> None:
    p = sub.add_parser("audit", help="read generated vendor headers back into their design")
    p.add_argument("files", nargs="+", help="header files ('-' = stdin)")
    p.add_argument("--profile", default=None, help="inovance, ti, nxp, st or microchip "
                   "(default: detected from the macro names)")
    p.add_argument("-D", dest="defines", action="append", default=[], metavar="NAME[=VALUE]",
                   help="a definition made before the files, as a compiler's -D")
    p.set_defaults(run=run)


def read_header(path: str, k: int) -> tuple:
    """(name, text) of file ``path`` (``-``: stdin): UTF-8, else Latin-1 (any byte is a
    character there; a NUL byte is refused by the decoder)."""
    field = f"files[{k}]"
    try:
        if path == "-":
            data = sys.stdin.buffer.read(MAX_CHARS + 1)
        else:
            if os.path.getsize(path) > MAX_CHARS:
                raise InputError(field, code="json_too_long", limit=MAX_CHARS)
            with open(path, "rb") as f:
                data = f.read(MAX_CHARS + 1)
    except OSError as e:
        raise InputError(field, code="audit_not_text", name=path,
                         why=e.strerror or type(e).__name__) from None
    if len(data) > MAX_CHARS:
        raise InputError(field, code="json_too_long", limit=MAX_CHARS)
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        text = data.decode("latin-1")
    return ("stdin" if path == "-" else path), text


def run(args) -> int:
    try:
        files = [read_header(p, k) for k, p in enumerate(args.files)]
        out = audit(files, args.profile, args.defines)
    except InputError as e:
        print(f"error: {e.field}: {e.message}", file=sys.stderr)
        return 2
    json.dump(out, sys.stdout, indent=1, ensure_ascii=False, allow_nan=False)
    sys.stdout.write("\n")
    return 0
