"""The page's generated TypeScript types: each file's path and text, from the declared shapes.

``npm run build`` writes them (web/build/schema.ts), like the input schema's JSON;
tests/py/test_shapes.py fails when a checked-in file differs from :func:`typescript_files`.
"""

from .api_shapes import API
from .report_shapes import REPORT
from .shapes import typescript


def typescript_files() -> dict:
    """Repository path → text of each generated TypeScript file.

    Returns
    -------
    dict of str to str
        ``web/src/generated/report-types.ts`` (the report, :data:`.report_shapes.REPORT`) and
        ``web/src/generated/api-types.ts`` (requests and replies by kind, :data:`.api_shapes.API`).

    Examples
    --------
    >>> files = typescript_files()
    >>> sorted(files)
    ['web/src/generated/api-types.ts', 'web/src/generated/report-types.ts']
    >>> "export interface Report {" in files["web/src/generated/report-types.ts"]
    True
    """
    return {
        "web/src/generated/report-types.ts": typescript(
            REPORT, "The parts of the report (docs/contract.md) the page reads. Values are displayed, never computed."),
        "web/src/generated/api-types.ts": typescript(
            API, 'pulab.api\'s requests and replies (docs/contract.md, "API"): each kind\'s `Request` and\n'
                 "`ReplyBody` and the objects they name; protocol.ts builds the worker's messages on them."),
    }
