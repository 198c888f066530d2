"""Chinese text, by pattern, for the few messages still raised as English text.

Every error and warning of pulab is data — a code and parameters — whose English and Chinese
text come from :mod:`pulab.schema.catalog`, the C tracer's (:mod:`pulab.ctrace`) included.  The
robustness inputs (``analysis.robust``, ``pulab robust``) still raise some errors as English
text; this table turns each into Chinese until they carry catalog codes too.  A message with no
pattern here comes back unchanged.

Examples
--------
>>> to_zh("must be [low, high] in °C")
'必须是 [下限, 上限]，单位 °C'
"""

from __future__ import annotations

import re

__all__ = ["to_zh", "has_chinese", "CATALOG"]

#: (English pattern, Chinese replacement); the first full match wins.
CATALOG = [
    # the robustness input (analysis.robust) and `pulab robust`
    (r"must be \[low, high\] in °C", "必须是 [下限, 上限]，单位 °C"),
    (r"must be between (\S+) and (\S+) with low ≤ high, got (.*)",
     r"必须在 \1 与 \2 之间且下限 ≤ 上限，当前为 \3"),
    (r"must be a list of at least 2 \[current_a, ld_h, lq_h\] points",
     "必须是至少 2 个 [current_a, ld_h, lq_h] 点的列表"),
    (r"must be \[current_a, ld_h, lq_h\]", "必须是 [current_a, ld_h, lq_h]"),
    (r"must have current ≥ 0 and inductances > 0", "电流必须 ≥ 0，电感必须 > 0"),
    (r"currents must increase from point to point", "各点电流必须递增"),
    (r"an input JSON file is required \(or --catalogue\)", "需要输入 JSON 文件（或 --catalogue）"),
    (r"needs Dask: pip install 'pulab\[dask\]'", "需要 Dask：pip install 'pulab[dask]'"),
    (r"must be between (\S+) and (\S+) and not 0, got (.*)", r"必须在 \1 与 \2 之间且不为 0，当前为 \3"),
    (r"must be ≥ 0, got (.*)", r"必须大于等于 0，当前为 \1"),
    (r"must be true or false, got (.*)", r"必须是 true 或 false，当前为 \1"),
]
_COMPILED = [(re.compile(p, re.S), r) for p, r in CATALOG]


def to_zh(message: str) -> str:
    """The Chinese text of a pulab message (unchanged when no pattern matches)."""
    for pattern, repl in _COMPILED:
        m = pattern.fullmatch(message)
        if m:
            return repl(m) if callable(repl) else m.expand(repl)
    return message


def has_chinese(message: str) -> bool:
    """True when the catalog turns ``message`` into text with Chinese characters.

    >>> has_chinese("must be [low, high] in °C"), has_chinese("no such pattern")
    (True, False)
    """
    zh = to_zh(message)
    return zh != message and any("\u4e00" <= ch <= "\u9fff" for ch in zh)
