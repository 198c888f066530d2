"""The texts of input errors, English and Chinese, by code (one catalog).

An error is data (:class:`pulab.schema.errors.InputError`: code, field, params);
this table gives its words.  A parameter that is itself an error
(``{"code": …, "params": …}``) is rendered in the same language, so a derived
value's error reads as one sentence in either language.

Adding an error: one entry here; ``tests/py/test_schema.py`` renders every code
in both languages.

Examples
--------
>>> render("out_of_range", {"lo": 1e-9, "hi": 1.0, "value": 2.0}, "zh")
'必须在 1e-09 与 1 之间，当前为 2'
>>> render("derived_invalid", {"target": "motor.rs_ohm", "value": 1e12,
...     "reason": {"code": "out_of_range", "params": {"lo": 1e-9, "hi": 1e9, "value": 1e12}}}, "en")
'gives motor.rs_ohm = 1e+12, which must be between 1e-09 and 1e+09, got 1e+12'
"""

from __future__ import annotations

__all__ = ["MESSAGES", "render"]

#: code → (English, Chinese); ``str.format`` fields name the error's params.
MESSAGES = {
    "required": ("is required", "必填"),
    "required_choice": ("is required (one of {choices})", "必填（以下之一：{choices}）"),
    "not_json_object": ("must be a JSON object", "必须是 JSON 对象"),
    "not_object": ("must be an object, got {got}", "必须是对象，当前为 {got}"),
    "unknown_field": ("unknown field (expected one of: {expected})",
                      "未知字段（应为以下之一：{expected}）"),
    "unknown_section": ("unknown section (expected one of: {expected})",
                        "未知分节（应为以下之一：{expected}）"),
    "not_number": ("must be a number, got {got}", "必须是数字，当前为 {got}"),
    "not_finite": ("must be finite", "必须是有限数"),
    "not_positive": ("must be > 0, got {value:g}", "必须大于 0，当前为 {value:g}"),
    "negative": ("must be ≥ 0, got {value:g}", "必须大于等于 0，当前为 {value:g}"),
    "zero": ("must not be 0", "不能为 0"),
    "out_of_range": ("must be between {lo:g} and {hi:g}, got {value:g}",
                     "必须在 {lo:g} 与 {hi:g} 之间，当前为 {value:g}"),
    "below": ("must be below {hi:g}, got {value:g}", "必须小于 {hi:g}，当前为 {value:g}"),
    "not_integer": ("must be an integer, got {got}", "必须是整数，当前为 {got}"),
    "integer_range": ("must be {lo}..{hi}, got {got}", "必须在 {lo}..{hi} 之间，当前为 {got}"),
    "not_choice": ("must be one of {choices}, got {got}", "必须是以下之一：{choices}；当前为 {got}"),
    "not_flag": ("must be true or false, got {got}", "必须是 true 或 false，当前为 {got}"),
    "only_with": ("is only used with {key} = {value}", "仅在 {key} = {value} 时使用"),
    "derived_invalid": ("gives {target} = {value:g}, which {reason}",
                        "得到 {target} = {value:g}，{reason}"),
    "chain_kp_zero": ("gives kp = 0 in profile {profile}, so the round trip through the "
                      "other profiles stops (a series Ki = ki·T/kp needs kp ≠ 0)",
                      "在厂商配置 {profile} 中 kp 取整为 0，无法继续在其他配置间往返换算"
                      "（串联式 Ki = ki·T/kp 要求 kp ≠ 0）"),
    "json_invalid": ("not valid JSON: {detail}", "不是合法的 JSON：{detail}"),
    "json_not_text": ("not valid JSON: the input is not text", "不是合法的 JSON：输入不是文本"),
    "json_too_deep": ("nested deeper than {depth} levels", "嵌套超过 {depth} 层"),
    "json_too_long": ("longer than {limit} characters", "超过 {limit} 个字符"),
}


def render(code: str, params: dict, lang: str) -> str:
    """The text of error ``code`` with ``params`` in ``lang`` (``'en'`` or ``'zh'``).

    Code ``text`` is free English text (``params["text"]``), translated by
    :func:`pulab.schema.messages.to_zh` for ``zh``.
    """
    if code == "text":
        if lang == "en":
            return params["text"]
        from .messages import to_zh
        return to_zh(params["text"])
    en, zh = MESSAGES[code]
    values = {k: render(v["code"], v["params"], lang) if isinstance(v, dict) and "code" in v
              else v for k, v in params.items()}
    return (en if lang == "en" else zh).format(**values)
