"""Chinese text for the C tracer's messages (:mod:`pulab.ctrace`), by pattern.

Every other error and warning of pulab is data — a code and parameters — whose English and
Chinese text come from :mod:`pulab.schema.catalog`, the tracer's lexer, parser and checker
errors included, and its preprocessor's and run time's.  The parser's "expected …" messages,
its constant-expression checks and a few input checks still raise English text; this table turns
each into Chinese until they carry catalog codes too.  A
message with no pattern here comes back unchanged (``tests/py/test_ctrace.py`` makes sure
every tracer message has one).

Examples
--------
>>> to_zh("3:14: expected ';', got end of code")
"3:14：此处应为 ';'，实际为 代码结尾"
"""

from __future__ import annotations

import re

__all__ = ["to_zh", "has_chinese", "CATALOG"]

#: (English pattern, Chinese replacement); the first full match wins.
CATALOG = [
    # the tracer's own input checks (target, --set values, GLOBAL_Q)
    (r"must be one of (.*), got (.*)", r"必须是以下之一：\1；当前为 \2"),
    (r"must be an integer, got (.*)", r"必须是整数，当前为 \1"),
    (r"must be an integer 1\.\.30, got (.*)", r"必须是 1..30 的整数，当前为 \1"),
    # the C tracer (pulab.ctrace): a position prefix, then the reason
    (r"(\d+:\d+): (.*)", lambda m: f"{m[1]}：{to_zh(m[2])}"),
    # the parser's constants and the tokens it expected (pulab.ctrace.parser)
    (r"an array size must be an integer constant", "数组大小必须是整数常量"),
    (r"an enumerator's value must be an integer constant", "枚举值必须是整数常量"),
    (r"a case label must be an integer constant", "case 标签必须是整数常量"),
    # the tracer's define list (pulab.ctrace.tracing, pulab.api)
    (r"must be a list of NAME\[=VALUE\] texts", "必须是 NAME[=VALUE] 文本的列表"),
    (r"must be text NAME\[=VALUE\], got (.*)", r"必须是文本 NAME[=VALUE]，当前为 \1"),
    (r"expected '(.*?)'(.*), got (.*)", lambda m: f"此处应为 '{m[1]}'{_where(m[2])}"
     f"，实际为 {_GOT.get(m[3], m[3])}"),
    (r"expected (a type|a value|a name|a variable name after the type), got (.*)",
     lambda m: f"此处应为{_EXPECTED[m[1]]}，实际为 {_GOT.get(m[2], m[2])}"),
    (r"no variable (\S+) is declared in the code", r"代码中没有声明变量 \1"),
    (r"(\S+) has an initializer in the code", r"\1 在代码中已有初始值"),
    (r"must be (\S+)\.\.(\S+) for (.+), got (.*)", r"对 \3 必须在 \1..\2 之间，当前为 \4"),
    (r"must be an integer 1\.\.30, got (.*)", r"必须是 1..30 的整数，当前为 \1"),
    (r"--set needs NAME=VALUE, got (.*)", r"--set 需要 NAME=VALUE，当前为 \1"),
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
_WHERE = {"": "", " after 'if'": "（在 'if' 之后）", " to close the condition": "（闭合条件）",
          " at the end of the declaration": "（声明末尾）",
          " at the end of the statement": "（语句末尾）", " in '?:'": "（在 '?:' 中）",
          " to close the cast": "（闭合类型转换）", " after a struct field": "（结构体字段之后）",
          " to close the enum": "（闭合枚举）", " to close the array size": "（闭合数组大小）",
          " to close the index": "（闭合下标）", " after 'while'": "（在 'while' 之后）",
          " after 'for'": "（在 'for' 之后）", " after 'break'": "（在 'break' 之后）",
          " after 'continue'": "（在 'continue' 之后）",
          " after 'do … while (…)'": "（在 'do … while (…)' 之后）",
          " after the loop's first clause": "（循环的第一个子句之后）",
          " after the loop's condition": "（循环条件之后）", " after 'switch'": "（在 'switch' 之后）",
          " after 'case'": "（在 'case' 之后）", " after 'default'": "（在 'default' 之后）"}
_GOT = {"end of code": "代码结尾"}


def _where(text: str) -> str:
    if text in _WHERE:
        return _WHERE[text]
    m = re.fullmatch(r" to close '\(' at (\S+)", text) or re.fullmatch(r" to close (\S+)", text)
    return f"（闭合 {m[1]} 处的 '('）" if m and ":" in m[1] else f"（闭合 {m[1]}）" if m else text
_EXPECTED = {"a type": "类型", "a value": "一个值", "a name": "一个名字",
             "a variable name after the type": "类型之后的变量名"}
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

    >>> has_chinese("a case label must be an integer constant"), has_chinese("no such pattern")
    (True, False)
    """
    zh = to_zh(message)
    return zh != message and any("\u4e00" <= ch <= "\u9fff" for ch in zh)
