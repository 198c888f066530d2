"""The texts of input errors, English and Chinese, by code (one catalog).

An error is data (:class:`pulab.schema.errors.InputError`: code, field, params);
this table gives its words.  A parameter that is itself an error
(``{"code": …, "params": …}``) is rendered in the same language, so a derived
value's error reads as one sentence in either language.

A parameter ``{"label": path}`` is that input's form label in the language of the text, and
``{"vendor": name}`` a firmware profile's name (``inovance`` is Inovance, 汇川).

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
    # the C tracer (pulab.ctrace): the position in the code, then the reason
    "trace_at": ("{line}:{column}: {reason}", "{line}:{column}：{reason}"),
    "trace_unset_input": ("{name} is read before it has a value (unset inputs: {unset}; give "
                          "each a value, or use zero-unset)",
                          "{name} 在赋值之前被读取（未设置的输入：{unset}；请逐个给值，或使用 "
                          "zero-unset）"),
    "trace_unset_local": ("{name} is read before it has a value (it has no initializer)",
                          "{name} 在赋值之前被读取（它没有初始值）"),
    "trace_steps": ("more than {limit} statements executed (a loop that does not end?)",
                    "执行了超过 {limit} 条语句（循环不结束？）"),
    "trace_no_return": ("{name}() ends without 'return'", "{name}() 没有 'return' 就结束了"),
    "trace_index": ("index {index} is outside {array}[0..{last}]",
                    "下标 {index} 超出 {array}[0..{last}]"),
    "trace_one_object": ("{name} is one object, not an element of an array: only index 0 "
                         "exists", "{name} 是单个对象，不是数组元素：只有下标 0"),
    "trace_null_pointer": ("a pointer without a value", "指针没有值"),
    "trace_recursion": ("{name}() calls itself (recursion is not supported)",
                        "{name}() 调用了自身（不支持递归）"),
    "trace_call_depth": ("calls nested more than {limit} deep", "函数调用嵌套超过 {limit} 层"),
    "trace_analysis": ("the calls reach more than {limit} expressions: too large to trace",
                       "调用涉及超过 {limit} 个表达式：太大，无法追踪"),
    "trace_array_size": ("array of {n} elements: at most {limit} integers per object",
                         "{n} 个元素的数组：每个对象最多 {limit} 个整数"),
    "trace_struct_size": ("struct {name}: at most {limit} integers per object",
                          "结构体 {name}：每个对象最多 {limit} 个整数"),
    "trace_unknown_function": ("unknown function {name}() (functions of the code: {known}; "
                               "IQmath: _IQmpy, _IQNmpy, __IQmpy, _IQsat, __IQsat, _IQabs)",
                               "未知函数 {name}()（代码中的函数：{known}；IQmath：_IQmpy、"
                               "_IQNmpy、__IQmpy、_IQsat、__IQsat、_IQabs）"),
    "trace_unknown_type": ("unknown type {name} (is the header that defines it pasted?)",
                           "未知类型 {name}（定义它的头文件粘贴了吗？）"),
    "trace_no_entry": ("no function {name} in the code (functions: {known})",
                       "代码中没有函数 {name}（函数：{known}）"),
    "trace_choose_entry": ("choose the function to run (functions: {known})",
                           "请选择要运行的函数（函数：{known}）"),
    "trace_entry_name": ("must be a function name, got {got}", "必须是函数名，当前为 {got}"),
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
    "too_large": ("must be at most {hi:g}, got {value:g}", "必须不大于 {hi:g}，当前为 {value:g}"),
    "too_small": ("must be at least {lo:g}, got {value:g}", "必须不小于 {lo:g}，当前为 {value:g}"),
    "not_integer": ("must be an integer, got {got}", "必须是整数，当前为 {got}"),
    "integer_range": ("must be {lo}..{hi}, got {got}", "必须在 {lo}..{hi} 之间，当前为 {got}"),
    "not_choice": ("must be one of {choices}, got {got}", "必须是以下之一：{choices}；当前为 {got}"),
    "not_flag": ("must be true or false, got {got}", "必须是 true 或 false，当前为 {got}"),
    "not_name_or_number": ("must be one of {choices} or a number, got {got}",
                           "必须是以下之一：{choices}，或一个数字；当前为 {got}"),
    "not_pair": ("must be [low, high], got {got}", "必须是 [低, 高]，当前为 {got}"),
    "pair_order": ("must have low ≤ high, got [{lo:g}, {hi:g}]",
                   "必须满足 低 ≤ 高，当前为 [{lo:g}, {hi:g}]"),
    "not_table": ("must be a list of at least 2 rows [{columns}], got {got}",
                  "必须是至少 2 行 [{columns}] 的列表，当前为 {got}"),
    "not_row": ("must be a row [{columns}], got {got}", "必须是一行 [{columns}]，当前为 {got}"),
    "not_increasing": ("{column} must increase from row to row, got {value:g} after {before:g}",
                       "{column} 必须逐行递增，当前 {value:g} 在 {before:g} 之后"),
    "only_with": ("is only used with {key} = {value}", "仅在 {key} = {value} 时使用"),
    "derived_invalid": ("gives {target} = {value:g}, which {reason}",
                        "得到 {target} = {value:g}，{reason}"),
    "chain_kp_zero": ("gives kp = 0 in profile {profile}, so the round trip through the "
                      "other profiles stops (a series Ki = ki·T/kp needs kp ≠ 0)",
                      "在厂商配置 {profile} 中 kp 取整为 0，无法继续在其他配置间往返换算"
                      "（串联式 Ki = ki·T/kp 要求 kp ≠ 0）"),
    "not_string": ("must be a string, got {got}", "必须是字符串，当前为 {got}"),
    "number_ambiguous": ("must be a number, got {got} (ambiguous: a decimal comma or a thousands "
                         "separator?)", "必须是数字，当前为 {got}（有歧义：是小数逗号还是千位分隔符？）"),
    "not_register": ("must be an integer (decimal, 0x… hex or 0b… binary), got {got}",
                     "必须是整数（十进制、0x… 十六进制或 0b… 二进制），当前为 {got}"),
    "power_of_two": ("must be a power of two, got {got}", "必须是 2 的幂，当前为 {got}"),
    "q_too_wide": ("{name} does not fit {bits} word bits", "{name} 放不进 {bits} 位字长"),
    "not_q_format": ("not a Q format: {got} (use Qm.n, UQm.n, or Qn with word_bits)",
                     "不是 Q 格式：{got}（请用 Qm.n、UQm.n，或 Qn 并给出 word_bits）"),
    "q_outside": ("{value} is outside {fmt} [{lo}, {hi}]", "{value} 超出 {fmt} 的范围 [{lo}, {hi}]"),
    "raw_range_for": ("must be {lo}..{hi} for {fmt}", "对 {fmt} 必须在 {lo}..{hi} 之间"),
    "no_simulation": ("the input asks for no {kind} simulation", "输入中没有 {kind} 仿真"),
    "summaries_list": ("must be a list of chunk summaries", "必须是分块摘要的列表"),
    "both_given": ("{this_label} ({this}) and {other_label} ({other}) both set the motor's "
                   "{target}: give only one of them.",
                   "{this_label}（{this}）和{other_label}（{other}）都会设定电机的{target}：请只填其中一个。"),
    "required_or": ("is required (or give {alternatives})",
                    "必填（或给出 {alternatives}）"),
    "used_with": ("is only used with {other}", "仅与 {other} 一起使用"),
    "used_with_either": ("is only used with {a} or {b}", "仅与 {a} 或 {b} 一起使用"),
    "required_to_convert": ("is required to convert {source} (or give {other})",
                            "换算 {source} 时必填（或给出 {other}）"),
    "damping_kp_low": ("too low for damping design: kp = 2ζω0·L − Rs = {kp:.4g} Ω ≤ 0",
                       "对阻尼比设计而言过低：kp = 2ζω0·L − Rs = {kp:.4g} Ω ≤ 0"),
    "long_overflow": ("{what} = {value} does not fit a 32-bit long", "{what} = {value} 超出 32 位 long 的范围"),
    "raw_outside_given": ("{value} (given) is outside Uint16 0..65535",
                          "{value}（直接给定）超出 Uint16 范围 0..65535"),
    "raw_outside_from": ("{value} (from {source}) is outside Uint16 0..65535",
                         "{value}（由 {source} 换算）超出 Uint16 范围 0..65535"),
    "firmware_div0": ("the firmware divides by zero: {why}", "固件出现除以零：{why}"),
    "cannot_read": ("cannot read {path}: {why}", "无法读取 {path}：{why}"),
    "not_utf8": ("not UTF-8 text (byte {byte})", "不是 UTF-8 文本（第 {byte} 字节）"),
    "axis_syntax": ("expected PATH=START:STOP[:N][:log], got {got}",
                    "格式应为 PATH=START:STOP[:N][:log]，当前为 {got}"),
    "not_numeric_path": ("not a numeric input path: {got}", "不是数值输入路径：{got}"),
    "log_not_positive": ("must be > 0 for a log scale, got {value:g}", "对数刻度要求大于 0，当前为 {value:g}"),
    "same_as": ("must differ from {other} ({value})", "必须不同于 {other}（{value}）"),
    "unknown_profile": ("unknown profile {got}", "未知的厂商配置：{got}"),
    "prove_profile": ("a proof covers the profiles {choices}, got {got}",
                      "证明目前只支持这些配置：{choices}；当前为 {got}"),
    "prove_no_ranges": ("give at least one input range (PATH=LO:HI)",
                        "至少给出一个输入范围（PATH=LO:HI）"),
    "prove_pair": ("must be [lo, hi] (integers for a raw or integer input), got {got}",
                   "必须是 [lo, hi]（raw 或整数输入须为整数），当前为 {got}"),
    "prove_propose_ti": ("a Q proposal is made for --profile ti (its GLOBAL_Q)",
                         "Q 格式建议只用于 --profile ti（其 GLOBAL_Q）"),
    "prove_range_syntax": ("expected PATH=LO:HI, got {got}", "格式应为 PATH=LO:HI，当前为 {got}"),
    "prove_order": ("lo must be ≤ hi, got {lo:g} > {hi:g}", "lo 必须 ≤ hi，当前 {lo:g} > {hi:g}"),
    "unknown_exercise": ("unknown exercise {got}", "未知的练习：{got}"),
    "too_many_points": ("the sweep has {total} points; at most {limit}", "扫描共有 {total} 个点；最多 {limit} 个"),
    "empty_column": ("empty column name {got}", "列名为空：{got}"),
    "unit_not_path": ("a unit is only converted for an input path, not {got}",
                      "只有输入路径列才换算单位，{got} 不是"),
    "unit_none": ("unknown unit [{unit}] for {name} (allowed: none (give the value in the unit its "
                  "name ends in))", "{name} 的单位 [{unit}] 未知（此列不换算单位：请按列名结尾的单位给值）"),
    "unit_unknown": ("unknown unit [{unit}] for {name} (allowed: {allowed})",
                     "{name} 的单位 [{unit}] 未知（可用：{allowed}）"),
    "csv_unreadable": ("not readable as CSV: {detail}", "无法按 CSV 读取：{detail}"),
    "no_header": ("no header row", "没有表头行"),
    "duplicate_column": ("duplicate column {name} (also column {other})",
                         "列 {name} 重复（与第 {other} 列相同）"),
    "ragged_row": ("{cells} cells, the header has {columns}", "该行有 {cells} 个单元格，表头只有 {columns} 列"),
    "speed_ts_multiple": ("must be 1..1000 times drive.ts_s = {ts:g} s, got {ratio:.6g} times",
                          "必须是 drive.ts_s = {ts:g} s 的 1..1000 整数倍，当前为 {ratio:.6g} 倍"),
    "speed_limit_q12": ("{value:g} A is not below 8·I_b = {limit:g} A (the Q12 current reference is an "
                        "int16)", "{value:g} A 未低于 8·I_b = {limit:g} A（Q12 电流给定是 int16）"),
    "above_nyquist": ("{value:g} Hz is not below the Nyquist frequency 1/(2·Ts) = {nyquist:g} Hz",
                      "{value:g} Hz 未低于奈奎斯特频率 1/(2·Ts) = {nyquist:g} Hz"),
    "pm_unreachable": ("{value:g}° is not reached below the Nyquist frequency (the loop keeps more "
                       "phase margin)", "在奈奎斯特频率以下达不到 {value:g}°（环路的相位裕度始终更大）"),
    "speed_kp_low": ("too low for the friction: kp = (2ζωn·J − B)/Kt = {kp:.4g} ≤ 0",
                     "相对摩擦过低：kp = (2ζωn·J − B)/Kt = {kp:.4g} ≤ 0"),
    "step_q12": ("{value:g} A is {pu:.3g} pu; the Q12 current (int16) holds less than ±8 pu "
                 "(±{limit:.4g} A)", "{value:g} A 即 {pu:.3g} pu；Q12 电流（int16）只能表示 ±8 pu 以内（±{limit:.4g} A）"),
    "speed_nyquist": ("|{value:g}| Hz is not below half the control frequency 1/(2·Ts) = {nyquist:g} Hz",
                      "|{value:g}| Hz 未低于控制频率的一半 1/(2·Ts) = {nyquist:g} Hz"),
    "too_many_periods": ("{value:g} s is {count} control periods; at most {limit}",
                         "{value:g} s 等于 {count} 个控制周期；最多 {limit} 个"),
    "pll_q24_overflow": ("q15 PLL gain {name} = {value} does not fit int32 (Q24 allows per-unit gains "
                         "below 128)", "q15 锁相环增益 {name} = {value} 超出 int32（Q24 只允许小于 128 的标幺增益）"),
    "input_speed_nyquist": ("the input speed reaches {value:g} Hz, not below half the control frequency "
                            "1/(2·Ts) = {nyquist:g} Hz",
                            "输入转速达到 {value:g} Hz，未低于控制频率的一半 1/(2·Ts) = {nyquist:g} Hz"),
    # findings of the design review (pulab.analyses.review), by finding code
    "finding.constant_wrap": ("vendor.{name} = {value}: the firmware arithmetic wrapped (exact value "
                              "{ideal:.6g}), so the firmware uses a wrong number. {why}",
                              "vendor.{name} = {value}：固件运算发生回绕（精确值 {ideal:.6g}），固件用的是错误的数。{why}"),
    "finding.constant_error": ("vendor.{name} = {value} is {pct:+.3g} % off the exact value {ideal:.6g}. "
                               "{why}",
                               "vendor.{name} = {value} 与精确值 {ideal:.6g} 相差 {pct:+.3g} %。{why}"),
    "cost.rpm": ("A property of the vendor's code (its integer divisions truncate): the firmware's R_s is "
                 "{pct:+.3g} % off, which shifts the resistive drop its model expects; no input changes it.",
                 "这是厂商代码的性质（整数除法截断）：固件中的 R_s 偏差 {pct:+.3g} %，改变其模型中的电阻压降；"
                 "任何输入都无法改变它。"),
    "cost.inductance": ("A property of the vendor's code: m_BaseL counts L_b in coarse integer steps "
                        "(≈ 2·10⁴·L_b), so L per unit is {pct:+.3g} % off; a lower base frequency "
                        "(Base frequency f_b, not below the rated frequency) makes the count finer.",
                        "这是厂商代码的性质：m_BaseL 以粗整数步长计数 L_b（约 2·10⁴·L_b），因此标幺电感偏差 "
                        "{pct:+.3g} %；降低基值频率（基值频率 f_b，不低于额定频率）可使计数更细。"),
    "cost.freq": ("It comes from the ratio of the rated and base frequency in the vendor's integer code; "
                  "the Base frequency f_b is the design choice that moves it.",
                  "它来自厂商整数代码中额定频率与基值频率之比；能改变它的设计选择是基值频率 f_b。"),
    "cost.voltage": ("A property of the vendor's code: data1 keeps U_dc/√2 in whole volts, so the "
                     "firmware's voltage limit is {pct:+.3g} % off U_dc/√2 (it matters on low-voltage "
                     "buses; the voltage headroom below uses the firmware's limit).",
                     "这是厂商代码的性质：data1 以整伏保存 U_dc/√2，因此固件的电压限幅与 U_dc/√2 相差 "
                     "{pct:+.3g} %（低压母线上才明显；下面的电压裕量按固件限幅计算）。"),
    "finding.raw_zero": ("raw.{name} = 0: {path} = {si:g} is below the firmware resolution, so the "
                         "firmware sees 0. {fix}",
                         "raw.{name} = 0：{path} = {si:g} 低于固件分辨率，固件看到的是 0。{fix}"),
    "finding.raw_rounding": ("raw.{name} = {value}: rounding {path} = {si:g} to the firmware unit "
                             "changes it by {pct:+.2f} %. {fix}",
                             "raw.{name} = {value}：把 {path} = {si:g} 取整到固件单位，改变了 {pct:+.2f} %。"
                             "{fix}"),
    "fix.parameter_unit": ("A property of the vendor's parameter table (one count is {unit}), not "
                           "of your inputs: it costs this much accuracy in every value the firmware "
                           "derives from it; only another choice under “{label}” changes it.",
                           "这是厂商参数表的性质（一个计数为 {unit}），不是输入的问题：固件由它导出的每个值"
                           "都损失这么多精度；只有改选“{label}”才能改变。"),
    "fix.inductance_unit": ("Set “{label}” to µH: the counts become 10× finer (the firmware must read "
                            "LD/LQ in µH too).",
                            "把“{label}”设为 µH：计数细 10 倍（固件也须按 µH 读取 LD/LQ）。"),
    "finding.bemf_spread": ("the datasheet's back-EMF constants disagree by {spread:.3g} % at "
                            "{rpm:.5g} rpm ({listed}); the firmware uses {used}. {why}",
                            "数据手册的各反电势常数在 {rpm:.5g} rpm 时相差 {spread:.3g} %（{listed}）；"
                            "固件采用 {used}。{why}"),
    "bemf_spread.note": ("Within what datasheets usually differ by (kT is often printed hot or at "
                         "rated current, Ke cold): in “{label}”, choose the one your "
                         "firmware's observer and feed-forward should use.",
                         "在数据手册常见的差异之内（kT 常按热态或额定电流给出，Ke 按冷态）：请在“{label}”"
                         "中选择固件观测器与前馈应使用的那个。"),
    "bemf_spread.warning": ("More than temperature usually explains: check at which temperature "
                            "and current each was measured, and in “{label}” choose the one the "
                            "firmware should use.",
                            "超出温度通常能解释的范围：请核对各常数的测量温度与电流，并在“{label}”中选择固件"
                            "应使用的那个。"),
    "bemf_spread.error": ("More than temperature or saturation explain: a convention is probably "
                          "mixed up (RMS and peak differ by 41 %, line and phase by 73 %); check "
                          "Ke measured as / between, Kv per volt and kT per ampere.",
                          "超出温度或饱和所能解释的范围：多半混淆了约定（有效值与峰值差 41 %，线与相差 "
                          "73 %）；请核对 Ke 的测量方式/测量端、Kv 的电压单位与 kT 的电流单位。"),
    "finding.pi_zero": ("current_pi.{axis}.pm_ki rounds to 0: the integral action is lost (ki·Ts is "
                        "below one Q16 LSB of the per-unit gain); a longer {label} or a higher "
                        "current-loop bandwidth makes it count",
                        "current_pi.{axis}.pm_ki 取整为 0：积分作用丢失（ki·Ts 小于标幺增益的一个 Q16 LSB）；"
                        "加长{label}或提高电流环带宽可使其不为 0"),
    "finding.pi_rounding": ("current_pi.{axis}.pm_{k} = {value}: coarse, rounding changes {k} by "
                            "{pct:+.1f} % (the vendor's Q12/Q16 gain format; a higher {label} gives "
                            "larger, finer integers)",
                            "current_pi.{axis}.pm_{k} = {value}：分辨率粗，取整使 {k} 改变 {pct:+.1f} %"
                            "（厂商的 Q12/Q16 增益格式；提高{label}可得到更大、更细的整数）"),
    "finding.phase_margin": ("current loop, {axis} axis: phase margin {pm:.3g}° with the {delay} delay "
                             "(below {limit:g}°: overshoot and ringing); {fix}",
                             "电流环 {axis} 轴：计入 {delay} 延时后相位裕度为 {pm:.3g}°（低于 {limit:g}°："
                             "超调与振荡）；{fix}"),
    "finding.phase_margin_unstable": ("current loop, {axis} axis: unstable with the {delay} delay; {fix}",
                                      "电流环 {axis} 轴：计入 {delay} 延时后不稳定；{fix}"),
    "finding.phase_margin_fix": ("for the {target:g}° design of the Loop design panel set {label} to "
                                 "{ok_hz:.4g} Hz (kp = {kp:.4g} Ω, ki = {ki:.4g} Ω/s)",
                                 "按“环路设计”面板的 {target:g}° 设计，请把{label}设为 {ok_hz:.4g} Hz"
                                 "（kp = {kp:.4g} Ω，ki = {ki:.4g} Ω/s）"),
    "finding.phase_margin_lower": ("lower {label}", "请降低{label}"),
    "finding.base_below_rated": ("raw.FullFreq01 = {full} < raw.FreqRated01 = {rated}: base frequency "
                                 "below rated frequency, FreqPer > 1.0 in Q15; raise "
                                 "{label} to the rated frequency or more",
                                 "raw.FullFreq01 = {full} < raw.FreqRated01 = {rated}：基值频率低于额定频率，"
                                 "Q15 的 FreqPer > 1.0；请把{label}提高到不低于额定频率"),
    "finding.voltage_rated": ("at rated current and rated frequency the motor needs {need:.4g} V (line "
                              "RMS), above the voltage limit {limit:.4g} V; raise {label}",
                              "额定电流、额定频率下电机需要 {need:.4g} V（线电压有效值），超过电压限幅 "
                              "{limit:.4g} V；请提高{label}"),
    "finding.voltage_rated_firmware": ("at rated current and rated frequency the motor needs {need:.4g} V "
                                       "(line RMS): within U_dc/√2 = {udc_limit:.4g} V, but above the "
                                       "firmware's limit {limit:.4g} V (U_dc/√2 in whole volts, a "
                                       "property of the vendor's code); the rated point needs a little "
                                       "field weakening, or a higher {label}",
                                       "额定电流、额定频率下电机需要 {need:.4g} V（线电压有效值）：未超过 "
                                       "U_dc/√2 = {udc_limit:.4g} V，但超过固件限幅 {limit:.4g} V（U_dc/√2 "
                                       "取整伏，厂商代码的性质）；额定点需要少量弱磁，或提高{label}"),
    "finding.voltage_bemf": ("back-EMF at f_b = {f_b:g} Hz is {bemf:.4g} V (line RMS), above the "
                             "voltage limit {limit:.4g} V: field weakening needed above {from_hz:.4g} "
                             "Hz; lower {label} or raise the DC bus voltage Udc",
                             "f_b = {f_b:g} Hz 时反电势为 {bemf:.4g} V（线电压有效值），超过电压限幅 "
                             "{limit:.4g} V：{from_hz:.4g} Hz 以上需要弱磁；请降低{label}或提高直流母线电压 Udc"),
    "finding.voltage_fb": ("at rated current and f_b = {f_b:g} Hz the motor needs {need:.4g} V (line "
                           "RMS), above the voltage limit {limit:.4g} V: full current up to f_b needs "
                           "field weakening (or a lower {label}, or a higher DC bus voltage Udc)",
                           "额定电流、f_b = {f_b:g} Hz 时电机需要 {need:.4g} V（线电压有效值），超过电压限幅 "
                           "{limit:.4g} V：满电流运行到 f_b 需要弱磁（或降低{label}、提高直流母线电压 Udc）"),
    "finding.pll_unlocked": ("{key}: not locked (|θ − θ̂| ≥ 2° in the last 20 % of the run); change "
                             "{label}", "{key}：未锁定（仿真最后 20 % 内 |θ − θ̂| ≥ 2°）；请修改{label}"),
    "finding.pll_steady": ("{key}.steady_angle_error_deg = {value:.3g}°: angle error after lock; change "
                           "{label}", "{key}.steady_angle_error_deg = {value:.3g}°：锁定后的角度误差；"
                           "请修改{label}"),
    "finding.unit_uH": ("LD/LQ taken in µH: the vendor code was written for 0.01 mH, so "
                        "gMotorExtPer.LD/LQ are 10× the Q13 per-unit inductance (source eq. 1.4-6, the "
                        "'×10' puzzle)", "原始 LD/LQ 按 µH 输入：汇川代码按 0.01 mH 编写，因此 "
                        "gMotorExtPer.LD/LQ 是 Q13 标幺电感的 10 倍（式 1.4-6 的“×10”之谜）"),
    "finding.custom_bases": ("custom bases: the vendor integers (Rpm, LD, …) always use the Inovance "
                             "rms bases U_LL/√3 and I_rms; the PI integers use the custom bases",
                             "自定义基值：汇川整数（Rpm、LD 等）始终使用汇川 rms 基值 U_LL/√3 与 I_rms；"
                             "PI 整数使用自定义基值"),
    # report warnings beyond the review's findings
    "warning.current_unstable": ("{path}: the closed current loop is unstable with the {delay} delay "
                                 "(largest |pole| {radius:.4g})",
                                 "{path}：计入 {delay} 延时后电流闭环不稳定（最大极点模 {radius:.4g}）"),
    "warning.current_low_pm": ("{path}: phase margin {pm:.1f}° with the {delay} delay (below 30°: "
                               "strong overshoot and ringing)",
                               "{path}：计入 {delay} 延时后相位裕度只有 {pm:.1f}°（低于 30°：超调与振荡明显）"),
    "warning.speed_unstable": ("loop.speed: the closed speed loop is unstable (largest |pole| "
                               "{radius:.4g})", "loop.speed：速度闭环不稳定（最大极点模 {radius:.4g}）"),
    "warning.speed_inner_slow": ("loop.speed: the current loop's bandwidth is only {ratio:.2g}× the "
                                 "speed crossover; the speed margins (inner loop as one period of "
                                 "delay) are optimistic",
                                 "loop.speed：电流环带宽只有速度环穿越频率的 {ratio:.2g} 倍；速度环裕度"
                                 "（把内环当作一个周期的延时）偏乐观"),
    "finding.robust_margin": ("loop.robust.{name}: {what} {shown} on the {axis} axis at {temp_c:g} °C, "
                              "{current_a:.4g} A, U_dc {udc_v:.4g} V (below {threshold}; the firmware "
                              "gains are tuned for the nominal motor); {fix}",
                              "loop.robust.{name}：{axis} 轴{what} {shown}，工况 {temp_c:g} °C、"
                              "{current_a:.4g} A、U_dc {udc_v:.4g} V（低于 {threshold}；固件增益按标称"
                              "电机整定）；{fix}"),
    "finding.unrepresentable": ("the {profile_name} firmware cannot hold this motor ({fields}): "
                                "{results} are not computed. {advice}",
                                "{profile_name}固件无法表示这台电机（{fields}）：{results} 无法计算。{advice}"),
    "finding.unrepresentable_constants": ("the {profile_name} firmware cannot hold this motor: "
                                          "{results} do not fit their words and keep the largest "
                                          "integer instead. {advice}",
                                          "{profile_name}固件无法表示这台电机：{results} 超出其字长，只能存下"
                                          "最大整数。{advice}"),
    "limit.uint16": ("{name} is a Uint16 in {unit}: it holds at most {max:g} {si_unit}, and "
                     "{source_label} = {si:g} {si_unit} needs {value}; a 16-bit parameter would "
                     "keep {stored} ({stored_si:g} {si_unit}). Not computed: {results}",
                     "{name} 是以 {unit} 为单位的 Uint16，最大只能表示 {max:g} {si_unit}；{source_label} = "
                     "{si:g} {si_unit} 需要 {value}，16 位参数只会存下 {stored}（{stored_si:g} "
                     "{si_unit}）。无法计算：{results}"),
    "limit.uint16_advice": ("This is a limit of the vendor's code, not of the motor or of your inputs: "
                            "ship a profile that holds it, or change the unit of {name} in the "
                            "firmware (a coarser one).",
                            "这是厂商代码的限制，不是电机或输入的问题：请选用能表示它的配置，"
                            "或在固件中把 {name} 改用更粗的单位。"),
    "limit.code": ("{reason}; not computed: {results}", "{reason}；无法计算：{results}"),
    "limit.code_advice": ("The vendor's C code cannot compute these integers for this motor (a value "
                          "truncates to 0 before it divides); this is a property of the code: ship a "
                          "profile that holds it, or change the firmware's units.",
                          "厂商 C 代码无法为这台电机计算这些整数（某个值在作除数前截断为 0）；"
                          "这是代码本身的性质：请选用能表示它的配置，或修改固件的单位。"),
    "limit.constant_advice": ("It needs {factor:.3g}× what {format} holds: store it with {bits} "
                              "fewer fractional bits (Q{q_new}), or change what scales it ({options}) "
                              "so that it is {factor:.3g}× smaller.",
                              "它需要 {format} 所能表示范围的 {factor:.3g} 倍：请少用 {bits} 位小数"
                              "（Q{q_new}）存储，或修改它的缩放（{options}），使其缩小 {factor:.3g} 倍。"),
    "profile_unrepresentable": ("the {profile} firmware cannot hold this motor: {reason}",
                                "{profile} 固件无法表示这台电机：{reason}"),
    "raw_missing": ("{name} does not fit its Uint16 parameter", "{name} 超出其 Uint16 参数范围"),
    "robust.phase_margin": ("phase margin", "相位裕度"),
    "robust.gain_margin": ("gain margin", "增益裕度"),
    "robust.unstable": ("unstable", "不稳定"),
    "robust.band": ("designed bandwidths {lo:.4g}–{hi:.4g} Hz keep it at every corner",
                    "设计带宽 {lo:.4g}–{hi:.4g} Hz 在所有角点都满足"),
    "robust.no_band": ("no designed bandwidth keeps it at every corner", "没有任何设计带宽能在所有角点满足"),
    "warning.ti_check": ("profiles.ti: USER_checkForErrors would set {code} ({why})",
                         "profiles.ti：USER_checkForErrors 会置位 {code}（{why}）"),
    "warning.profile_overflow": ("{path}: {ideal:.6g} does not fit {format}; stored {value}",
                                 "{path}：{ideal:.6g} 超出 {format} 的范围；实际存储 {value}"),
    "warning.profile_zero": ("{path}: rounds to 0 in {format} (ideal {ideal:.6g})",
                             "{path}：在 {format} 中取整为 0（理想值 {ideal:.6g}）"),
    "set_syntax": ("--set needs NAME=VALUE, got {got}", "--set 需要 NAME=VALUE，当前为 {got}"),
    "json_invalid": ("not valid JSON: {detail}", "不是合法的 JSON：{detail}"),
    "json_not_text": ("not valid JSON: the input is not text", "不是合法的 JSON：输入不是文本"),
    "json_too_deep": ("nested deeper than {depth} levels", "嵌套超过 {depth} 层"),
    "json_too_long": ("longer than {limit} characters", "超过 {limit} 个字符"),
}


#: A firmware profile's name in each language (``{"vendor": name}``).
VENDOR_NAMES = {"inovance": ("Inovance", "汇川"), "ti": ("TI", "TI"), "nxp": ("NXP", "NXP"),
                "st": ("ST", "ST"), "microchip": ("Microchip", "Microchip")}


def _word(v, lang: str):
    """A parameter as its text's word: a form label or a profile's name; else ``v`` itself."""
    if isinstance(v, dict) and set(v) == {"label"}:
        return _label(v["label"], lang)
    if isinstance(v, dict) and set(v) == {"vendor"} and v["vendor"] in VENDOR_NAMES:
        return VENDOR_NAMES[v["vendor"]][0 if lang == "en" else 1]
    return v


def _label(path: str, lang: str) -> str:
    from .fields import FIELD  # data only; imported late to keep this module first to load
    f = FIELD.get(path)
    return f.label[0 if lang == "en" else 1] if f is not None and f.label[0] else path


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
    # A field's form label or a profile's name in this language.
    params = {k: _word(v, lang) for k, v in params.items()}
    # A nested error sees the outer params it does not set itself (e.g. a finding's label).
    plain = {k: v for k, v in params.items() if not (isinstance(v, dict) and "code" in v)}
    values = {k: render(v["code"], {**plain, **v["params"]}, lang)
              if isinstance(v, dict) and "code" in v else v for k, v in params.items()}
    return (en if lang == "en" else zh).format(**values)
