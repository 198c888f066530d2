"""Chinese text for the C tracer's messages (:mod:`pulab.ctrace`), by pattern.

Every other error and warning of pulab is data — a code and parameters — whose English and
Chinese text come from :mod:`pulab.schema.catalog`.  The tracer still raises its errors as
English text; this table turns each into Chinese until they carry catalog codes too.  A
message with no pattern here comes back unchanged (``tests/py/test_ctrace.py`` makes sure
every tracer message has one).

Examples
--------
>>> to_zh("3:14: division by zero")
'3:14：除以零'
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
    (r"code is longer than (\d+) characters", r"代码超过 \1 个字符"),
    (r"code must be text", "代码必须是文本"),
    (r"unexpected character (.*)", r"意外的字符 \1"),
    (r"comment not closed: \*/ missing", "注释未闭合：缺少 */"),
    (r"annotation must read (.*)", r"注解格式应为 \1"),
    (r"Q(\d+): at most 63 fraction bits", r"Q\1：小数位最多 63 位"),
    (r"base must be a finite number", "base 必须是有限数"),
    (r"#(\w*) is not supported \(only #define, #undef, #include, #pragma\)",
     r"不支持 #\1（只支持 #define、#undef、#include、#pragma）"),
    (r"#define needs a name", "#define 需要一个名字"),
    (r"function-like macro (.*) is not supported", r"不支持带参数的宏 \1"),
    (r"in #define (\w+): (.*)", lambda m: f"在 #define {m[1]} 中：{to_zh(m[2])}"),
    (r"#define (\w+): unexpected text in its body", r"#define \1：宏体中有意外的内容"),
    (r"GLOBAL_Q must be an integer 1\.\.30", "GLOBAL_Q 必须是 1..30 的整数"),
    (r"(.*): only integer constants are supported \(no floating point\)",
     r"\1：只支持整数常量（不支持浮点）"),
    (r"(.*): bad integer suffix (.*)", r"\1：错误的整数后缀 \2"),
    (r"(.*): bad octal constant", r"\1：错误的八进制常量"),
    (r"expected '(.*?)'(.*), got (.*)", lambda m: f"此处应为 '{m[1]}'{_where(m[2])}"
     f"，实际为 {_GOT.get(m[3], m[3])}"),
    (r"expected (a type|a value|a name|a variable name after the type), got (.*)",
     lambda m: f"此处应为{_EXPECTED[m[1]]}，实际为 {_GOT.get(m[2], m[2])}"),
    (r"nested more than (\d+) deep", r"嵌套超过 \1 层"),
    (r"expression more than (\d+) operators deep", r"表达式的运算符嵌套超过 \1 层"),
    (r"not a C type: (.*)", r"不是 C 类型：\1"),
    (r"'\{' at (\S+) is never closed", r"\1 处的 '{' 没有闭合"),
    (r"'else' without 'if'", "'else' 没有对应的 'if'"),
    (r"'(\w+)' is not supported \(declarations, assignments, if/else only\)",
     r"不支持 '\1'（只支持声明、赋值和 if/else）"),
    (r"the comma operator is not supported", "不支持逗号运算符"),
    (r"'(\S+)' needs a variable on its left", r"'\1' 的左边必须是变量"),
    (r"'(\S+)' needs a variable", r"'\1' 需要一个变量"),
    (r"'(\S+)' is not supported here", r"此处不支持 '\1'"),
    (r"unknown function (\S+) \(supported: (.*)\)", r"未知函数 \1（支持：\2）"),
    (r"(\S+) takes (\d+) arguments, got (\d+)", r"\1 需要 \2 个参数，实际为 \3 个"),
    (r"__IQmpy\(a, b, q\): q must be an integer constant 0\.\.62",
     "__IQmpy(a, b, q)：q 必须是 0..62 的整数常量"),
    (r"(.+) does not exist on (\w+)", r"\2 上没有 \1 类型"),
    (r"(\S+) is not declared \(declare it with its type, e\.g\. (.*)\)",
     r"\1 未声明（请带类型声明，例如 \2）"),
    (r"(\S+) is already declared at (\S+)", r"\1 已在 \2 处声明"),
    (r"(\S+) is too large for every integer type of its kind \((.*)\)",
     r"\1 超出其所有可用整数类型的范围（\2）"),
    (r"the annotation names (\S+), which is not declared", r"注解中的 \1 未声明"),
    (r"(\S+) is read before it has a value \(give it an input value or an initializer\)",
     r"\1 在赋值之前被读取（请给它输入值或初始值）"),
    (r"division by zero", "除以零"),
    (r"remainder by zero", "对零取余"),
    (r"no variable (\S+) is declared in the code", r"代码中没有声明变量 \1"),
    (r"(\S+) has an initializer in the code", r"\1 在代码中已有初始值"),
    (r"must be (\S+)\.\.(\S+) for (.+), got (.*)", r"对 \3 必须在 \1..\2 之间，当前为 \4"),
    (r"must be an integer 1\.\.30, got (.*)", r"必须是 1..30 的整数，当前为 \1"),
    (r"--set needs NAME=VALUE, got (.*)", r"--set 需要 NAME=VALUE，当前为 \1"),
]
_WHERE = {"": "", " after 'if'": "（在 'if' 之后）", " to close the condition": "（闭合条件）",
          " at the end of the declaration": "（声明末尾）",
          " at the end of the statement": "（语句末尾）", " in '?:'": "（在 '?:' 中）",
          " to close the cast": "（闭合类型转换）"}
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

    >>> has_chinese("division by zero"), has_chinese("no such pattern")
    (True, False)
    """
    zh = to_zh(message)
    return zh != message and any("\u4e00" <= ch <= "\u9fff" for ch in zh)
