"""The texts of input errors, English and Chinese, by code (one catalog).

An error is data (:class:`pulab.schema.errors.InputError`: code, field, params);
this table gives its words.  A parameter that is itself an error
(``{"code": …, "params": …}``) is rendered in the same language, so a derived
value's error reads as one sentence in either language.

A number parameter formatted ``{x:~H}`` is written with an SI prefix and unit
(:func:`pulab.schema.sitext.si_text`: ``10.6 µH``); the unit may be another parameter
(``{si:~{si_unit}}``).

A parameter ``{"label": path}`` is that input's form label in the language of the text (a
vendor profile's option too: :func:`pulab.schema.vendors.option_field`), ``{"vendor": name}`` a
firmware profile's name (``inovance`` is Inovance, 汇川; :func:`pulab.schema.vendors.display`),
and a list of those its words joined.

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

from . import vendors
from .fields import FIELD
from .sitext import si_text

__all__ = ["MESSAGES", "render"]

#: code → (English, Chinese); ``str.format`` fields name the error's params.
MESSAGES = {
    # the C tracer (pulab.ctrace): the position in the code, then the reason
    "trace_at": ("{line}:{column}: {reason}", "{line}:{column}：{reason}"),
    "trace_unset_input": ("{name} is read before it has a value (unset inputs: {unset}; give "
                          "each a value, or use zero-unset)",
                          "{name} 在赋值之前被读取（未设置的输入：{unset}；请逐个给值，或使用 "
                          "zero-unset）"),
    "trace_unset_pointer": ("{name} is a pointer read before it has a value: give it the "
                            "address of an object of the code (set {name}=&OBJECT)",
                            "{name} 是在赋值之前被读取的指针：请给它代码中某个对象的地址"
                            "（设置 {name}=&对象）"),
    "trace_pointer_syntax": ("{name} is a pointer: its value is &OBJECT (a global, an entry "
                             "parameter's object, a field or element of one), got {got}",
                             "{name} 是指针：其值应为 &对象（全局变量、入口参数所指对象，或其字段、"
                             "元素），当前为 {got}"),
    "trace_pointer_no_object": ("{name} cannot point to {got}: no such object among the globals "
                                "and the entry's parameters (nor a pointer: pointers to pointers "
                                "are not supported)",
                                "{name} 不能指向 {got}：全局变量和入口参数中没有这个对象（也不能是指针："
                                "不支持指向指针的指针）"),
    "trace_pointer_type": ("{name} points to {want}, but {got} is {type}",
                           "{name} 指向 {want}，但 {got} 的类型是 {type}"),
    "trace_return_local": ("{name}() returns the address of {got}, which ends with the call "
                           "(a local)",
                           "{name}() 返回了 {got} 的地址，该对象随调用结束而失效（局部变量）"),
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
    "trace_entry_name": ("must be a function name or MACRO(TYPE, …), got {got}",
                         "必须是函数名或 MACRO(TYPE, …)，当前为 {got}"),
    "trace_cast_not_pointer": ("{cast}: a pointer cast needs a pointer, not {got}",
                               "{cast}：指针转换需要指针，而不是 {got}"),
    "trace_cast_reinterprets": ("{cast} would read {src} as {dst} (a different memory layout; "
                                "only casts between the same layout, field by field, are "
                                "supported)",
                                "{cast} 会把 {src} 当作 {dst} 读取（内存布局不同；只支持逐字段布局"
                                "相同的转换）"),
    "trace_opaque_entry": ("{name} is a handle to an object of unknown type: the entry casts "
                           "it to {types} (it needs to cast it to one struct type, as "
                           "(PI_Obj *){name})",
                           "{name} 是指向未知类型对象的句柄：入口函数把它转换为 {types}（需要转换为"
                           "一种结构体类型，如 (PI_Obj *){name}）"),
    "trace_field_unsupported": ("field {name} of struct {struct}: {reason}",
                                "结构体 {struct} 的字段 {name}：{reason}"),
    "trace_define_list": ("must be a list of NAME[=VALUE] texts", "必须是 NAME[=VALUE] 文本的列表"),
    "trace_define_text": ("must be text NAME[=VALUE], got {got}",
                          "必须是文本 NAME[=VALUE]，当前为 {got}"),
    "trace_no_variable": ("no variable {name} is declared in the code", "代码中没有声明变量 {name}"),
    "trace_has_initializer": ("{name} has an initializer in the code", "{name} 在代码中已有初始值"),
    "trace_value_range": ("must be {lo}..{hi} for {type}, got {got}",
                          "对 {type} 必须在 {lo}..{hi} 之间，当前为 {got}"),
    "trace_expected": ("expected '{token}'{where}, got {got}", "此处应为 '{token}'{where}，实际为 {got}"),
    "trace_expected_name": ("expected a variable name after the type, got {got}",
                            "此处应为类型之后的变量名，实际为 {got}"),
    "trace_expected_bare": ("expected '{token}', got {got}", "此处应为 '{token}'，实际为 {got}"),
    "trace_where_after": (" after '{word}'", "（在 '{word}' 之后）"),
    "trace_where_struct_field": (" after a struct field", "（结构体字段之后）"),
    "trace_where_close_enum": (" to close the enum", "（闭合枚举）"),
    "trace_where_close_array_size": (" to close the array size", "（闭合数组大小）"),
    "trace_where_close_condition": (" to close the condition", "（闭合条件）"),
    "trace_where_statement_end": (" at the end of the statement", "（语句末尾）"),
    "trace_where_declaration_end": (" at the end of the declaration", "（声明末尾）"),
    "trace_where_do_while": (" after 'do … while (…)'", "（在 'do … while (…)' 之后）"),
    "trace_where_loop_first": (" after the loop's first clause", "（循环的第一个子句之后）"),
    "trace_where_loop_condition": (" after the loop's condition", "（循环条件之后）"),
    "trace_where_close_brace": (" to close '{{' at {at}", "（闭合 {at} 处的 '{{'）"),
    "trace_where_close_paren": (" to close '(' at {at}", "（闭合 {at} 处的 '('）"),
    "trace_where_conditional": (" in '?:'", "（在 '?:' 中）"),
    "trace_where_close_cast": (" to close the cast", "（闭合类型转换）"),
    "trace_where_close_index": (" to close the index", "（闭合下标）"),
    "trace_where_close_call": (" to close {name}(", "（闭合 {name}(）"),
    "trace_const": ("an integer constant is needed here", "此处需要整数常量"),
    "trace_const_array_size": ("an array size must be an integer constant", "数组大小必须是整数常量"),
    "trace_const_enum": ("an enumerator's value must be an integer constant", "枚举值必须是整数常量"),
    "trace_const_case": ("a case label must be an integer constant", "case 标签必须是整数常量"),
    # the checker's (static types), each at the construct's line:column
    "trace_no_type_on_target": ("{name} does not exist on {target}", "{target} 上没有 {name} 类型"),
    "trace_undeclared": ("{name} is not declared (declare it with its type, e.g. 'Uint16 "
                         "{name};')", "{name} 未声明（请带类型声明，例如 'Uint16 {name};'）"),
    "trace_pointer_pointer": ("pointers to pointers are not supported", "不支持指向指针的指针"),
    "trace_array_no_size": ("an array needs a size or an initializer", "数组需要大小或初始值"),
    "trace_struct_incomplete": ("struct {name} is declared but its fields are not pasted",
                                "结构体 {name} 已声明，但没有粘贴其字段"),
    "trace_field_incomplete": ("field {name} of struct {struct} has an incomplete type",
                               "结构体 {struct} 的字段 {name} 类型不完整"),
    "trace_declared_twice": ("{name} is already declared at {at}", "{name} 已在 {at} 处声明"),
    "trace_return_void_value": ("{name}() returns void: 'return' takes no value",
                                "{name}() 返回 void：'return' 不能带值"),
    "trace_return_no_value": ("{name}() must return a value", "{name}() 必须返回一个值"),
    "trace_return_type": ("{name}() returns {ret}, not {got}", "{name}() 返回 {ret}，而不是 {got}"),
    "trace_result_type": ("{name}() returns {ret}: only integer, struct, pointer and void "
                          "results are supported",
                          "{name}() 返回 {ret}：只支持整数、结构体、指针和 void 返回值"),
    "trace_case_twice": ("a case label repeats the one at {at}", "case 标签与 {at} 处的重复"),
    "trace_case_nested": ("a case label inside a nested statement is not supported (labels at "
                          "the top of the switch's block only)",
                          "不支持嵌套语句中的 case 标签（只支持 switch 块顶层的标签）"),
    "trace_init_array": ("{n} initializers for an array of {size}",
                         "{n} 个初始值，但数组只有 {size} 个元素"),
    "trace_init_struct": ("{n} initializers for struct {name} of {size} fields",
                          "{n} 个初始值，但结构体 {name} 只有 {size} 个字段"),
    "trace_init_braces": ("a braced list initializes an array or a struct",
                          "花括号列表只能初始化数组或结构体"),
    "trace_init_type": ("cannot initialize {dst} with {src}", "不能用 {src} 初始化 {dst}"),
    "trace_void_value": ("{name}() returns void: it has no value", "{name}() 返回 void：没有值"),
    "trace_not_scalar": ("{got} where an integer is needed (only integers are computed)",
                         "此处需要整数，实际为 {got}（只计算整数）"),
    "trace_constant_large": ("{text} is too large for every integer type of its kind ({types})",
                             "{text} 超出其所有可用整数类型的范围（{types}）"),
    "trace_arrow_needs_pointer": ("'->' needs a pointer to a struct, not {got}",
                                  "'->' 需要指向结构体的指针，而不是 {got}"),
    "trace_not_struct": ("{name} is not declared as a struct (declare {name} with its type)",
                         "{name} 没有声明为结构体（请带类型声明 {name}）"),
    "trace_dot_needs_struct": ("'.' needs a struct, not {got}", "'.' 需要结构体，而不是 {got}"),
    "trace_no_field": ("struct {name} has no field {field_name}",
                       "结构体 {name} 没有字段 {field_name}"),
    "trace_index_needs_array": ("'[]' needs an array or a pointer, not {got}",
                                "'[]' 需要数组或指针，而不是 {got}"),
    "trace_deref_needs_pointer": ("'*' needs a pointer, not {got}", "'*' 需要指针，而不是 {got}"),
    "trace_op_on": ("'{op}' on {got}", "不能对 {got} 使用 '{op}'"),
    "trace_op_unsupported": ("'{op}' on {got} is not supported", "不支持对 {got} 使用 '{op}'"),
    "trace_assign_type": ("cannot assign {src} to {dst}", "不能把 {src} 赋给 {dst}"),
    "trace_argument_type": ("argument {name} of {function}() is {want}, got {got}",
                            "{function}() 的参数 {name} 是 {want}，实际为 {got}"),
    "trace_note_undeclared": ("the annotation names {name}, which is not declared",
                              "注解中的 {name} 未声明"),
    # the preprocessor's
    "trace_in_directive": ("in {what}: {reason}", "在 {what} 中：{reason}"),
    "trace_directive_text": ("{what}: unexpected text", "{what}：有意外的内容"),
    "trace_define_name": ("#define needs a name", "#define 需要一个名字"),
    "trace_define_paren": ("#define {name}(: ')' missing after the parameters",
                           "#define {name}(：参数后缺少 ')'"),
    "trace_define_param": ("#define {name}(…): bad parameter {param}",
                           "#define {name}(…)：错误的参数 {param}"),
    "trace_define_param_twice": ("#define {name}(…): a parameter is named twice",
                                 "#define {name}(…)：参数重名"),
    "trace_define_paste_edge": ("#define {name}: '##' cannot begin or end a macro body",
                                "#define {name}：'##' 不能出现在宏体的开头或结尾"),
    "trace_define_option": ("-D {text}: NAME[=VALUE] needs a C name",
                            "-D {text}：NAME[=VALUE] 需要一个 C 名字"),
    "trace_global_q": ("GLOBAL_Q must be an integer 1..30", "GLOBAL_Q 必须是 1..30 的整数"),
    "trace_if_depth": ("#if nested deeper than {limit}", "#if 嵌套超过 {limit} 层"),
    "trace_without_if": ("#{word} without #if", "#{word} 没有对应的 #if"),
    "trace_after_else": ("#{word} after #else", "#{word} 出现在 #else 之后"),
    "trace_error_directive": ("#error{rest}", "#error（代码要求停止）{rest}"),
    "trace_unknown_directive": ("#{word} is not a preprocessor directive this tracer knows",
                                "#{word} 不是本工具认识的预处理指令"),
    "trace_include_syntax": ("#include needs <header> or \"header\"",
                             "#include 需要 <头文件> 或 \"头文件\""),
    "trace_directive_name": ("#{word} needs one name", "#{word} 需要一个名字"),
    "trace_defined_name": ("defined needs a macro name", "defined 需要一个宏名"),
    "trace_if_expression": ("#{word} needs an expression", "#{word} 需要一个表达式"),
    "trace_if_open": ("#if without #endif", "#if 没有对应的 #endif"),
    "trace_macro_depth": ("macro {name}: expansion nested deeper than {limit} macros",
                          "宏 {name}：展开嵌套超过 {limit} 层"),
    "trace_macro_tokens": ("macro {name}: more than {limit} tokens after expansion",
                           "宏 {name}：展开后超过 {limit} 个记号"),
    "trace_macro_paren": ("macro {name}(: ')' missing", "宏 {name}(：缺少 ')'"),
    "trace_macro_args": ("macro {name}() takes {n} arguments, got {got}",
                         "宏 {name}() 需要 {n} 个参数，实际为 {got} 个"),
    "trace_paste": ("'##' pasting {left} and {right} does not give one token",
                    "'##' 拼接 {left} 和 {right} 得不到一个记号"),
    "trace_iq_constant": ("{name}(…) needs a floating constant (a variable would need floating "
                          "point at run time)", "{name}(…) 需要浮点常量（变量需要运行时浮点运算）"),
    "trace_iq_range": ("{name}(…) = {value} does not fit a 32-bit long",
                       "{name}(…) = {value} 超出 32 位 long 的范围"),
    "trace_if": ("#if: {reason}", "#if：{reason}"),
    "trace_if_unexpected": ("unexpected {text}", "意外的 {text}"),
    "trace_if_missing": ("'{char}' missing", "缺少 '{char}'"),
    "trace_if_ends": ("expression ends early", "表达式不完整"),
    "trace_if_not_constant": ("{text} is not an integer constant", "{text} 不是整数常量"),
    # the run time's
    "trace_unset_global": ("{name} is read before it has a value (give it an input value or an "
                           "initializer)", "{name} 在赋值之前被读取（请给它输入值或初始值）"),
    "trace_division_zero": ("division by zero", "除以零"),
    "trace_remainder_zero": ("remainder by zero", "对零取余"),
    "trace_shift_by": ("shift by {n}", "移位位数为 {n}"),
    "trace_refused_use": ("{name} (at {at}) is outside the subset: {reason}",
                          "{name}（{at}）超出支持的子集：{reason}"),
    "trace_refused_call": ("{name} (called from {entry}) is outside the subset: {reason}",
                           "{name}（由 {entry} 调用）超出支持的子集：{reason}"),
    # the lexer's and parser's refusals, each naming the construct
    "trace_code_length": ("code is longer than {limit} characters", "代码超过 {limit} 个字符"),
    "trace_code_text": ("code must be text", "代码必须是文本"),
    "trace_character": ("unexpected character {char}", "意外的字符 {char}"),
    "trace_comment_open": ("comment not closed: */ missing", "注释未闭合：缺少 */"),
    "trace_end_of_code": ("end of code", "代码结尾"),
    "trace_annotation_syntax": ("annotation must read '// @q NAME Qn|auto [base=NUMBER [UNIT]]'",
                                "注解格式应为 '// @q NAME Qn|auto [base=NUMBER [UNIT]]'"),
    "trace_q_bits": ("Q{n}: at most 63 fraction bits", "Q{n}：小数位最多 63 位"),
    "trace_base_finite": ("base must be a finite number", "base 必须是有限数"),
    "trace_undeclared_macro": ("{name} is not declared: if it is a macro of a header not pasted "
                               "({headers}), paste the header or give it with -D {name}=VALUE",
                               "{name} 未声明：若它是未粘贴头文件（{headers}）中的宏，请粘贴该头文件，"
                               "或用 -D {name}=VALUE 给出"),
    "trace_undeclared_define": ("{name} is not declared: if it is a macro, give it with "
                                "-D {name}=VALUE (or declare it with its type, e.g. 'Uint16 "
                                "{name};')", "{name} 未声明：若它是宏，请用 -D {name}=VALUE 给出"
                                "（或带类型声明，例如 'Uint16 {name};'）"),
    "trace_calls_entry": ("a sequence of calls needs an entry function (--entry)",
                          "多次调用需要入口函数（--entry）"),
    "trace_table_rows": ("the input table has {rows} rows for {calls} calls",
                         "输入表有 {rows} 行，调用次数为 {calls}"),
    "trace_table_list": ("the input table must be a list of rows, got {got}",
                         "输入表必须是行的列表，当前为 {got}"),
    "trace_table_header": ("the CSV table needs a header row of input names",
                           "CSV 表需要一行输入名作为表头"),
    "trace_table_cells": ("line {row} has {n} cells for {names} columns",
                          "第 {row} 行有 {n} 个单元格，但只有 {names} 列"),
    "trace_table_json": ("line {row} is not a JSON object", "第 {row} 行不是 JSON 对象"),
    "trace_table_cell": ("the row of call {call}: {reason}", "第 {call} 次调用的行：{reason}"),
    "trace_table_read": ("cannot read {name}: {reason}", "无法读取 {name}：{reason}"),
    "trace_calls_prove": ("--calls cannot be combined with --prove", "--calls 不能与 --prove 同时使用"),
    "trace_table_kind": ("{name}: the table must be .csv or .jsonl", "{name}：输入表必须是 .csv 或 .jsonl"),
    "trace_sequence_steps": ("call {call} reaches {limit} statements executed over the sequence "
                             "(fewer calls?)", "第 {call} 次调用时整个序列执行的语句达到 {limit} 条"
                             "（减少调用次数？）"),
    "trace_in_call": ("in call {call}: {reason}", "第 {call} 次调用：{reason}"),
    "sim_code_in_call": ("in period {call} of the simulation: {reason}",
                         "仿真第 {call} 个周期：{reason}"),
    "sim_code_feedback": ("bind the measured current (feedback) or the error (error)",
                          "请绑定电流反馈（feedback）或误差（error）"),
    "sim_code_unread": ("{name} is not read by the code before it is written: binding it "
                        "would change nothing", "代码在写入 {name} 之前不读取它：绑定它不起作用"),
    "sim_code_return": ("the entry returns no integer: bind a variable or a field",
                        "入口函数不返回整数：请绑定变量或字段"),
    "sim_code_no_output": ("{name} has no value after call {call}", "第 {call} 次调用后 {name} 没有值"),
    "sim_code_fit": ("{value} (call {call}) does not fit {name} ({lo}..{hi})",
                     "{value}（第 {call} 次调用）超出 {name} 的范围（{lo}..{hi}）"),
    "sim_code_path": ("{got} names no integer of the report", "{got} 不是报告中的整数"),
    "sim_code_set_value": ("must be an integer, a report path, &OBJECT or {{\"d\": …, \"q\": …}}, "
                           "got {got}", "必须是整数、报告路径、&对象 或 {{\"d\": …, \"q\": …}}，"
                           "当前为 {got}"),
    "sim_code_scale": ("the {vendor} firmware cannot represent this drive ({problems}): no "
                       "integer units to run the code in", "{vendor} 固件无法表示该驱动（{problems}）："
                       "没有可运行代码的整数单位"),
    "sim_code_steps": ("the routine executed more than {limit} statements by period {call} "
                       "(a shorter duration?)", "例程在第 {call} 个周期时执行的语句超过 {limit} 条"
                       "（缩短时长？）"),
    "trace_undefine_name": ("-U takes a macro name, got {got}", "-U 需要宏名，当前为 {got}"),
    "trace_float_operator": ("{op} of a floating constant cannot be folded (only + - * /, "
                             "comparisons, && || and ?:)", "浮点常量不能用 {op} 折叠（只支持 + - * /、"
                             "比较、&& || 与 ?:）"),
    "trace_float_cast_range": ("{text} truncated toward zero is {value}, outside {type}: "
                               "undefined in C", "{text} 向零截断为 {value}，超出 {type} 的范围："
                               "C 中未定义"),
    "trace_float_constant": ("{text}: only integer constants are supported (no floating point; "
                             "a constant floating expression cast, initializing or assigned to an "
                             "integer is folded)",
                             "{text}：只支持整数常量（不支持浮点；转换、初始化或赋值给整数的浮点常量"
                             "表达式会被折叠）"),
    "trace_int_suffix": ("{text}: bad integer suffix {suffix}", "{text}：错误的整数后缀 {suffix}"),
    "trace_octal": ("{text}: bad octal constant", "{text}：错误的八进制常量"),
    "trace_nested": ("nested more than {limit} deep", "嵌套超过 {limit} 层"),
    "trace_height": ("expression more than {limit} operators deep",
                     "表达式的运算符嵌套超过 {limit} 层"),
    "trace_paren_open": ("'(' is never closed", "'(' 没有闭合"),
    "trace_brace_open": ("'{{' at {at} is never closed", "{at} 处的 '{{' 没有闭合"),
    "trace_expected_type": ("expected a type", "此处应为类型"),
    "trace_expected_value": ("expected a value, got {got}", "此处应为一个值，实际为 {got}"),
    "trace_not_c_type": ("not a C type: {words}", "不是 C 类型：{words}"),
    "trace_typedef_float": ("{name} is a floating-point type (typedef at {at}), not supported",
                            "{name} 是浮点类型（typedef 于 {at}），不支持"),
    "trace_typedef_pointer": ("{name} is a pointer type (typedef at {at}), not supported",
                              "{name} 是指针类型（typedef 于 {at}），不支持"),
    "trace_not_integer": ("'{word}' is not supported (integer types only)",
                          "不支持 '{word}'（只支持整数类型）"),
    "trace_not_supported": ("'{word}' is not supported", "不支持 '{word}'"),
    "trace_not_here": ("'{word}' is not supported here", "此处不支持 '{word}'"),
    "trace_cast_struct_void": ("a cast to a struct or void is not supported",
                               "不支持转换为结构体或 void"),
    "trace_struct_tag": ("expected a struct tag or '{{'", "此处应为结构体标签或 '{{'"),
    "trace_struct_redefined": ("struct {name} is already defined at {at}",
                               "结构体 {name} 已在 {at} 处定义"),
    "trace_bitfield": ("bit-fields are not supported", "不支持位域"),
    "trace_field_twice": ("field {name} is declared twice in struct {struct}",
                          "结构体 {struct} 中字段 {name} 声明了两次"),
    "trace_enumerator_name": ("expected an enumerator name", "此处应为枚举常量名"),
    "trace_function_pointer": ("function pointers are not supported", "不支持函数指针"),
    "trace_function_redefined": ("function {name} is already defined at {at}",
                                 "函数 {name} 已在 {at} 处定义"),
    "trace_nested_function": ("a function {name}(…) can only be declared at file scope (a "
                              "function definition is not supported inside a function)",
                              "函数 {name}(…) 只能在文件作用域声明（不支持在函数内定义函数）"),
    "trace_after_params": ("expected '{{' or ';' after {name}(…), got {got}",
                           "{name}(…) 之后应为 '{{' 或 ';'，实际为 {got}"),
    "trace_param_name": ("every parameter of {name}(…) needs a name",
                         "{name}(…) 的每个参数都需要名字"),
    "trace_void_object": ("{name} cannot have type void", "{name} 的类型不能是 void"),
    "trace_void_param": ("a parameter cannot have type void", "参数的类型不能是 void"),
    "trace_variadic": ("variadic functions are not supported", "不支持可变参数函数"),
    "trace_designated": ("designated initializers are not supported", "不支持指定初始化器"),
    "trace_typedef_name": ("expected a name after typedef {spelling}, got {got}",
                           "typedef {spelling} 之后应为名字，实际为 {got}"),
    "trace_typedef_function": ("typedef {name}: function and array typedefs are not supported",
                               "typedef {name}：不支持函数和数组类型的 typedef"),
    "trace_switch_brace": ("expected '{{' after 'switch (…)'", "'switch (…)' 之后应为 '{{'"),
    "trace_outside_switch": ("'{word}' outside a switch", "'{word}' 不在 switch 内"),
    "trace_outside_loop": ("'{word}' outside a loop", "'{word}' 不在循环内"),
    "trace_return_outside": ("'return' outside a function", "'return' 不在函数内"),
    "trace_else_without_if": ("'else' without 'if'", "'else' 没有对应的 'if'"),
    "trace_do_while": ("expected 'while' after the body of 'do'", "'do' 的循环体之后应为 'while'"),
    "trace_comma": ("the comma operator is not supported", "不支持逗号运算符"),
    "trace_lvalue_left": ("'{op}' needs a variable on its left", "'{op}' 的左边必须是变量"),
    "trace_needs_variable": ("'{op}' needs a variable", "'{op}' 需要一个变量"),
    "trace_field_name": ("expected a field name after '{op}'", "'{op}' 之后应为字段名"),
    "trace_builtin_arity": ("{name}() takes {n} arguments, got {got}",
                            "{name}() 需要 {n} 个参数，实际为 {got} 个"),
    "trace_iqmpy_q": ("__IQmpy(a, b, q): q must be an integer constant 0..62",
                      "__IQmpy(a, b, q)：q 必须是 0..62 的整数常量"),
    "trace_gen_kind": ("the generator is {got}; give KIND:PARAM=VALUE,… with KIND one of {kinds}",
                       "生成器为 {got}；应写成 KIND:参数=值,…，KIND 为 {kinds} 之一"),
    "trace_gen_param": ("{kind} has no parameter {got} (it takes {allowed})",
                        "{kind} 没有参数 {got}（可用：{allowed}）"),
    "trace_gen_missing": ("{kind} needs {param}=…", "{kind} 需要 {param}=…"),
    "trace_gen_number": ("{param}: {got} is not a finite number",
                         "{param}：{got} 不是有限数"),
    "trace_gen_whole": ("{param} must be a whole number ≥ 0, got {got}",
                        "{param} 必须是 ≥ 0 的整数，实际为 {got}"),
    "trace_gen_period": ("period must be > 0 calls, got {got}",
                         "period 必须大于 0 次调用，实际为 {got}"),
    "trace_gen_order": ("min {lo} is above max {hi}", "min {lo} 大于 max {hi}"),
    "trace_gen_name": ("{name} is not an integer input of the code (inputs: {inputs})",
                       "{name} 不是代码的整数输入（输入：{inputs}）"),
    "trace_gen_table": ("{name} is generated and also a column of the table (row of call {call})",
                        "{name} 既由生成器给出，又是表格的一列（第 {call} 次调用的行）"),
    "trace_gen_syntax": ("--gen takes NAME=KIND:PARAM=VALUE,…, got {got}",
                         "--gen 的格式为 NAME=KIND:参数=值,…，实际为 {got}"),
    "trace_iq_float": ("{name}() returns a float: the tracer follows integers only (use "
                       "_IQint/_IQfrac, or trace the integer you pass to it)",
                       "{name}() 返回浮点数：追踪器只跟踪整数（可改用 _IQint/_IQfrac，"
                       "或追踪传给它的整数）"),
    "trace_macro_arity": ("macro {name}({params}) has {n} parameters, {given} types given",
                          "宏 {name}({params}) 有 {n} 个参数，给出了 {given} 个类型"),
    "trace_macro_param_taken": ("macro {name}: its parameter {param} is already a name of the "
                                "code (run it through a function you write around it)",
                                "宏 {name}：参数 {param} 已是代码中的名字（请写一个函数调用它）"),
    "trace_macro_untyped": ("macro {name}: parameter {param} is not used as {param}.FIELD; "
                            "name its type: {example}",
                            "宏 {name}：参数 {param} 没有以 {param}.FIELD 形式使用；请给出其类型："
                            "{example}"),
    "trace_macro_no_type": ("macro {name}: no struct of the code has every field of {fields} "
                            "(structs: {known}); name the type: {example}",
                            "宏 {name}：代码中没有结构体包含 {fields} 的全部字段（结构体：{known}）；"
                            "请给出类型：{example}"),
    "trace_macro_many_types": ("macro {name}: several structs have every field of {fields} "
                               "({known}); name one: {example}",
                               "宏 {name}：多个结构体包含 {fields} 的全部字段（{known}）；"
                               "请指定其一：{example}"),
    "required": ("is required", "必填"),
    "required_choice": ("is required (one of {choices})", "必填（以下之一：{choices}）"),
    "not_json_object": ("must be a JSON object", "必须是 JSON 对象"),
    "not_object": ("must be an object, got {got}", "必须是对象，当前为 {got}"),
    "mcat_not_found": ("no MCAT JSON object found in the pasted text (paste MCAT's JSON, or the whole m1_pmsm_appconfig.h with the JSON in its first comment)",
                       "粘贴的文本中没有找到 MCAT 的 JSON 对象（请粘贴 MCAT 的 JSON，或首个注释中带有该 JSON 的整个 m1_pmsm_appconfig.h）"),
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
    "object_required": ("must be an object", "必须是对象"),
    "at_least": ("must be ≥ {lo}, got {got}", "必须大于等于 {lo}，当前为 {got}"),
    # the command line's own options (pulab robust)
    "cli_input_or_catalogue": ("an input JSON file is required (or --catalogue)",
                               "需要输入 JSON 文件（或 --catalogue）"),
    "cli_needs_dask": ("needs Dask: pip install 'pulab[dask]'", "需要 Dask：pip install 'pulab[dask]'"),
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
    "prove_auto_range": ("give {name} (// @q auto) a range in real units, NAME=LO:HI",
                         "请为 {name}（// @q auto）给出实数单位的范围 NAME=LO:HI"),
    "prove_not_input": ("not an input of the code (inputs: {inputs})",
                        "不是代码的输入（输入：{inputs}）"),
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
    "plant_static": ("{value:g} s with L/R = {tau:.3g} s: the current settles within a period "
                     "(R·Ts/L = {x:.4g} > {limit:g}), so the plant's pole e^(−R·Ts/L) is below "
                     "rounding and no PI zero can cancel it; a shorter Ts, or check R and L",
                     "{value:g} s 而 L/R = {tau:.3g} s：电流在一个周期内即已稳定（R·Ts/L = "
                     "{x:.4g} > {limit:g}），对象极点 e^(−R·Ts/L) 低于舍入误差，PI 零点无法对消；"
                     "请缩短 Ts，或检查 R 与 L"),
    "fw_no_voltage": ("leaves a voltage limit of {value:g} V", "电压极限为 {value:g} V，无可用电压"),
    "nxp_u_max_zero": ("gives U_max = U_DCB_MAX/UmaxCoeff = {value:g} V, which MCAT's rounding to "
                       "0.1 V makes 0 V (every scale would divide by it)",
                       "使 U_max = U_DCB_MAX/UmaxCoeff = {value:g} V，MCAT 取整到 0.1 V 后为 0 V"
                       "（所有比例都要除以它）"),
    "board_either": ("give this or {other}, not both (one replaces the other)",
                     "此项与 {other} 只能填一个（二者互相替代）"),
    "board_needs": ("is needed with {other}", "填写 {other} 时必须同时填写此项"),
    "board_pwm_ticks": ("the timer clock {clock:g} Hz gives {ticks:.3g} ticks per period: fewer "
                        "than a period register can hold", "定时器时钟 {clock:g} Hz 每周期只有 "
                        "{ticks:.3g} 个计数：周期寄存器无法表示"),
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
    "finding.constant_wrap": ("{name} = {value}: the firmware arithmetic wrapped (exact value "
                              "{ideal:.6g}), so the firmware uses a wrong number. {why}",
                              "{name} = {value}：固件运算发生回绕（精确值 {ideal:.6g}），固件用的是错误的数。{why}"),
    "finding.constant_error": ("{name} = {value} is {pct:+.3g} % off the exact value {ideal:.6g}. "
                               "{why}",
                               "{name} = {value} 与精确值 {ideal:.6g} 相差 {pct:+.3g} %。{why}"),
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
    "finding.raw_zero": ("{name} = 0: {path} = {si:~{si_unit}} is below the firmware resolution, so the "
                         "firmware sees 0. {fix}",
                         "{name} = 0：{path} = {si:~{si_unit}} 低于固件分辨率，固件看到的是 0。{fix}"),
    "finding.raw_rounding": ("{name} = {value}: rounding {path} = {si:~{si_unit}} to the firmware unit "
                             "changes it by {pct:+.2f} %. {fix}",
                             "{name} = {value}：把 {path} = {si:~{si_unit}} 取整到固件单位，改变了 {pct:+.2f} %。"
                             "{fix}"),
    "fix.parameter_unit": ("A property of the vendor's parameter table (one count is {unit}), not "
                           "of your inputs: it costs this much accuracy in every value the firmware "
                           "derives from it; only another choice under “{label}” changes it.",
                           "这是厂商参数表的性质（一个计数为 {unit}），不是输入的问题：固件由它导出的每个值"
                           "都损失这么多精度；只有改选“{label}”才能改变。"),
    "fix.parameter_unit_unshipped": ("A property of {vendor}'s parameter table (one count is "
                                     "{unit}): it matters only if you ship {vendor}'s firmware "
                                     "(“{label}” is {shipped}).",
                                     "这是{vendor}参数表的性质（一个计数为 {unit}）：只有交付{vendor}"
                                     "固件时才有影响（“{label}”当前为 {shipped}）。"),
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
    "finding.pi_zero": ("pm_ki ({axis} axis) rounds to 0: the integral action is lost (ki·Ts is "
                        "below one Q16 LSB of the per-unit gain); a longer {label} or a higher "
                        "current-loop bandwidth makes it count",
                        "pm_ki（{axis} 轴）取整为 0：积分作用丢失（ki·Ts 小于标幺增益的一个 Q16 LSB）；"
                        "加长{label}或提高电流环带宽可使其不为 0"),
    "finding.pi_rounding": ("pm_{k} ({axis} axis) = {value}: coarse, rounding changes {k} by "
                            "{pct:+.1f} % (the vendor's Q12/Q16 gain format; a higher {label} gives "
                            "larger, finer integers)",
                            "pm_{k}（{axis} 轴）= {value}：分辨率粗，取整使 {k} 改变 {pct:+.1f} %"
                            "（厂商的 Q12/Q16 增益格式；提高{label}可得到更大、更细的整数）"),
    "finding.phase_margin": ("current loop, {axis} axis: phase margin {pm:.3g}° with the {delay} delay "
                             "(below {limit:g}°: overshoot and ringing); {fix}",
                             "电流环 {axis} 轴：计入 {delay} 延时后相位裕度为 {pm:.3g}°（低于 {limit:g}°："
                             "超调与振荡）；{fix}"),
    "finding.phase_margin_unstable": ("current loop, {axis} axis: unstable with the {delay} delay; {fix}",
                                      "电流环 {axis} 轴：计入 {delay} 延时后不稳定；{fix}"),
    "finding.phase_margin_fix": ("for the {target:g}° design of the Loop design panel set {label} to "
                                 "{ok_hz:~Hz} (kp = {kp:~Ω}, ki = {ki:~Ω/s})",
                                 "按“环路设计”面板的 {target:g}° 设计，请把{label}设为 {ok_hz:~Hz}"
                                 "（kp = {kp:~Ω}，ki = {ki:~Ω/s}）"),
    "finding.phase_margin_lower": ("lower {label}", "请降低{label}"),
    "finding.base_below_rated": ("FullFreq01 = {full} < FreqRated01 = {rated}: base frequency "
                                 "below rated frequency, FreqPer > 1.0 in Q15; raise "
                                 "{label} to the rated frequency or more",
                                 "FullFreq01 = {full} < FreqRated01 = {rated}：基值频率低于额定频率，"
                                 "Q15 的 FreqPer > 1.0；请把{label}提高到不低于额定频率"),
    "finding.voltage_rated": ("at rated current and rated frequency the motor needs {need:~V} (line "
                              "RMS), above the voltage limit {limit:~V}; raise {label}",
                              "额定电流、额定频率下电机需要 {need:~V}（线电压有效值），超过电压限幅 "
                              "{limit:~V}；请提高{label}"),
    "finding.voltage_rated_firmware": ("at rated current and rated frequency the motor needs {need:~V} "
                                       "(line RMS): within U_dc/√2 = {udc_limit:~V}, but above the "
                                       "firmware's limit {limit:~V} (U_dc/√2 in whole volts, a "
                                       "property of the vendor's code); the rated point needs a little "
                                       "field weakening, or a higher {label}",
                                       "额定电流、额定频率下电机需要 {need:~V}（线电压有效值）：未超过 "
                                       "U_dc/√2 = {udc_limit:~V}，但超过固件限幅 {limit:~V}（U_dc/√2 "
                                       "取整伏，厂商代码的性质）；额定点需要少量弱磁，或提高{label}"),
    "finding.voltage_bemf": ("back-EMF at f_b = {f_b:~Hz} is {bemf:~V} (line RMS), above the "
                             "voltage limit {limit:~V}: field weakening needed above {from_hz:~Hz}"
                             "; lower {label} or raise the DC bus voltage Udc",
                             "f_b = {f_b:~Hz} 时反电势为 {bemf:~V}（线电压有效值），超过电压限幅 "
                             "{limit:~V}：{from_hz:~Hz} 以上需要弱磁；请降低{label}或提高直流母线电压 Udc"),
    "finding.voltage_fb": ("at rated current and f_b = {f_b:~Hz} the motor needs {need:~V} (line "
                           "RMS), above the voltage limit {limit:~V}: full current up to f_b needs "
                           "field weakening (or a lower {label}, or a higher DC bus voltage Udc)",
                           "额定电流、f_b = {f_b:~Hz} 时电机需要 {need:~V}（线电压有效值），超过电压限幅 "
                           "{limit:~V}：满电流运行到 f_b 需要弱磁（或降低{label}、提高直流母线电压 Udc）"),
    "finding.pll_unlocked": ("{key}: not locked (|θ − θ̂| ≥ 2° in the last 20 % of the run); change "
                             "{label}", "{key}：未锁定（仿真最后 20 % 内 |θ − θ̂| ≥ 2°）；请修改{label}"),
    "finding.pll_steady": ("{key}.steady_angle_error_deg = {value:.3g}°: angle error after lock; change "
                           "{label}", "{key}.steady_angle_error_deg = {value:.3g}°：锁定后的角度误差；"
                           "请修改{label}"),
    "finding.pi_wrap": ("{key}.wrap = {count}: the {profile} firmware's integer current PI "
                        "overflowed and wrapped {count} times in the simulated step, so it would "
                        "output a wrong voltage; lower {label}, or give that firmware's current "
                        "and voltage full scales more headroom (Firmware view)",
                        "{key}.wrap = {count}：{profile} 固件的整数电流 PI 在仿真阶跃中溢出回绕 "
                        "{count} 次，会输出错误的电压；请降低{label}，或为该固件的电流、电压满量程"
                        "留出更多余量（“固件”视图）"),
    "finding.pi_wrap_fixed": ("{key} = {count}: the Inovance firmware's current PI (long "
                              "arithmetic) overflowed and wrapped in {count} updates of the "
                              "simulated step, so it would output a wrong voltage; change {label} "
                              "until the voltage limits maxu and pm_maxout_vol hold",
                              "{key} = {count}：汇川固件的电流 PI（long 运算）在仿真阶跃中有 "
                              "{count} 次更新溢出回绕，会输出错误的电压；请修改{label}，使电压限幅 "
                              "maxu 与 pm_maxout_vol 不溢出"),
    "finding.fw_rated_beyond_base": ("the rated speed {rated:.5g} rpm is above the base speed {base:.5g} rpm "
                                     "of this bus and current limit: rated torque there needs field "
                                     "weakening; a higher {label} or a lower rated point",
                                     "额定转速 {rated:.5g} rpm 高于该母线电压和电流极限下的基速 {base:.5g} "
                                     "rpm：额定点需要弱磁才能输出额定转矩；请提高{label}或降低额定点"),
    "finding.fw_beyond_max": ("the range drawn ends at {want:.5g} rpm, above the maximum speed {top:.5g} "
                              "rpm: no current within the limit gives positive torque there; lower {label}",
                              "绘制范围到 {want:.5g} rpm，高于最高转速 {top:.5g} rpm：那里没有电流能在极限内"
                              "产生正转矩；请降低{label}"),
    "finding.fw_table_coarse": ("table {table} ({n} points) misses the exact curve by up to {err:.3g} A "
                                "({pct:.2g} % of the current limit); more {label}",
                                "表 {table}（{n} 点）与精确曲线相差最多 {err:.3g} A（电流极限的 {pct:.2g} %）；"
                                "请增加{label}"),
    "finding.observer_below_budget": ("{label} {want:.5g} rpm is below {low:.5g} rpm, the lowest speed "
                                      "where the back-EMF is {snr:g}× what corrupts it (R error, dead "
                                      "time, current LSB, noise): the observer is blind there; raise it",
                                      "{label} {want:.5g} rpm 低于 {low:.5g} rpm——反电势达到其误差（电阻误差、"
                                      "死区、电流 LSB、噪声）{snr:g} 倍的最低转速：观测器在此处看不清；请提高它"),
    "finding.observer_no_speed": ("the back-EMF never reaches {snr:g}× its errors up to 10× the maximum "
                                  "speed: no sensorless speed; lower {label} or the errors",
                                  "直到最高转速的 10 倍，反电势都达不到其误差的 {snr:g} 倍：无可用的无感转速；"
                                  "请降低{label}或误差"),
    "finding.observer_unstable": ("the observer loop set by {label} is unstable at this control period "
                                  "(pole radius {radius:.4g}): lower it",
                                  "由{label}决定的观测器环路在此控制周期下不稳定（极点半径 {radius:.4g}）：请降低它"),
    "finding.observer_merge_below_min": ("the merging speed {merge:.5g} rpm is below the lowest closed-loop "
                                         "speed {low:.5g} rpm (MCAT raises it); change {label}",
                                         "切换转速 {merge:.5g} rpm 低于最低闭环转速 {low:.5g} rpm（MCAT 会将其提高）；"
                                         "请修改{label}"),
    "finding.board_adc_clip": ("the rated peak current {peak:.4g} A is {pct:.0f} % of the ±{max_a:.4g} A "
                               "the current ADC measures: it clips; change {label}",
                               "额定峰值电流 {peak:.4g} A 达到电流 ADC 可测范围 ±{max_a:.4g} A 的 "
                               "{pct:.0f} %：会削顶；请修改{label}"),
    "finding.board_adc_low": ("the rated peak current {peak:.4g} A uses {pct:.1f} % of the ±{max_a:.4g} A "
                              "the current ADC measures: resolution is lost; {label} {fit} puts it "
                              "at {fit_pct:.0f} %",
                              "额定峰值电流 {peak:.4g} A 只用到电流 ADC 可测范围 ±{max_a:.4g} A 的 "
                              "{pct:.1f} %：分辨率被浪费；{label} {fit} 可使其达到 {fit_pct:.0f} %"),
    "finding.board_deadtime": ("the dead time costs {err:.3g} V of average voltage, {pct:.0f} % of the "
                               "{need:.3g} V (phase peak) the motor needs at rated current and 10 % "
                               "of rated speed: a shorter {label} or dead-time compensation",
                               "死区造成 {err:.3g} V 的平均电压误差，是额定电流、10 % 额定转速时所需 "
                               "{need:.3g} V（相峰值）的 {pct:.0f} %：请缩短{label}或加死区补偿"),
    "finding.board_duty_bits": ("the PWM period leaves {bits:.1f} bits of duty resolution ({steps:.0f} "
                                "steps); a lower {label} or a faster timer clock",
                                "PWM 周期只有 {bits:.1f} 位占空比分辨率（{steps:.0f} 级）；请降低{label}或"
                                "提高定时器时钟"),
    "finding.board_ts": ("the PWM gives a control period of {period:.6g} s, the drive says Ts = {ts:.6g} s; "
                         "change {label} or Ts",
                         "PWM 给出的控制周期为 {period:.6g} s，而驱动器 Ts = {ts:.6g} s；请修改{label}或 Ts"),
    "finding.pi_saturate": ("{key}.saturate = {count}: the {profile} firmware's integer current "
                            "PI clipped an intermediate value {count} times in the simulated step "
                            "(saturating arithmetic, not its output limit); lower {label}, or give "
                            "that firmware's full scales more headroom (Firmware view)",
                            "{key}.saturate = {count}：{profile} 固件的整数电流 PI 在仿真阶跃中 "
                            "{count} 次截断中间值（饱和运算，而非输出限幅）；请降低{label}，或为该"
                            "固件的满量程留出更多余量（“固件”视图）"),
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
                              "{current_a:~A}, U_dc {udc_v:~V} (below {threshold}; the firmware "
                              "gains are tuned for the nominal motor); {fix}",
                              "loop.robust.{name}：{axis} 轴{what} {shown}，工况 {temp_c:g} °C、"
                              "{current_a:~A}、U_dc {udc_v:~V}（低于 {threshold}；固件增益按标称"
                              "电机整定）；{fix}"),
    "finding.unrepresentable": ("the {profile_name} firmware cannot hold this motor ({fields}): "
                                "{results} are not computed. {advice}",
                                "{profile_name}固件无法表示这台电机（{fields}）：{results} 无法计算。{advice}"),
    "finding.unrepresentable_constants": ("the {profile_name} firmware cannot hold this motor: "
                                          "{results} do not fit their words and keep the largest "
                                          "integer instead. {advice}",
                                          "{profile_name}固件无法表示这台电机：{results} 超出其字长，只能存下"
                                          "最大整数。{advice}"),
    "limit.uint16": ("{name} is a Uint16 in {unit}: it holds at most {max:~{si_unit}}, and "
                     "{source_label} = {si:~{si_unit}} needs {value}; a 16-bit parameter would "
                     "keep {stored} ({stored_si:~{si_unit}}). Not computed: {results}",
                     "{name} 是以 {unit} 为单位的 Uint16，最大只能表示 {max:~{si_unit}}；{source_label} = "
                     "{si:~{si_unit}} 需要 {value}，16 位参数只会存下 {stored}（{stored_si:~{si_unit}}）。"
                     "无法计算：{results}"),
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
                              "fewer fractional bits (Q{q_new}), or change what scales it ({option_labels}) "
                              "so that it is {factor:.3g}× smaller.",
                              "它需要 {format} 所能表示范围的 {factor:.3g} 倍：请少用 {bits} 位小数"
                              "（Q{q_new}）存储，或修改它的缩放（{option_labels}），使其缩小 {factor:.3g} 倍。"),
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
    "warning.profile_overflow": ("{profile_name} {name}: {ideal:.6g} does not fit {format}; stored "
                                 "{value}",
                                 "{profile_name} {name}：{ideal:.6g} 超出 {format} 的范围；实际存储 {value}"),
    "warning.profile_zero": ("{profile_name} {name}: rounds to 0 in {format} (ideal {ideal:.6g})",
                             "{profile_name} {name}：在 {format} 中取整为 0（理想值 {ideal:.6g}）"),
    # the induction motor (motor.kind = acim)
    "acim_self_le_lm": ("must be larger than L_m = {lm:g} H (L = L_leak + L_m), got {value:g}",
                        "必须大于 L_m = {lm:g} H（L = 漏感 + L_m），当前为 {value:g}"),
    "acim_speed_not_below_sync": ("must be below the synchronous speed 60·f_n/p = {sync:g} rpm "
                                  "(the rated slip would be ≤ 0), got {value:g}",
                                  "必须低于同步转速 60·f_n/p = {sync:g} rpm（否则额定转差 ≤ 0），"
                                  "当前为 {value:g}"),
    "acim_flux_ref": ("gives the d reference I_m + ({value:g} A) ≤ 0 with I_m = {im:.4g} A: the "
                      "rotor flux would be reversed or gone; the slip ω_sl* = i_q*/(τ_r·i_d*) "
                      "is undefined",
                      "使 d 轴给定 I_m + ({value:g} A) ≤ 0（I_m = {im:.4g} A）：转子磁链反向或消失，"
                      "转差 ω_sl* = i_q*/(τ_r·i_d*) 无定义"),
    "acim_not_applicable": ("does not apply to an induction motor (motor.kind = acim) yet",
                            "暂不适用于异步电机（motor.kind = acim）"),
    "finding.acim_im_ge_rated": ("the magnetizing current I_m = {value:.4g} A is not below the rated "
                                 "current {rated:.4g} A: no current is left for torque. Check I_m "
                                 "(RMS, no-load) and L_m",
                                 "励磁电流 I_m = {value:.4g} A 不低于额定电流 {rated:.4g} A：没有电流"
                                 "留给转矩。请核对 I_m（有效值，空载）与 L_m"),
    "finding.acim_im_estimated": ("I_m = {value:.4g} A is the no-load estimate U_ph/(ω·L_s) with R_s "
                                  "neglected: give the measured no-load current "
                                  "(motor.magnetizing_current_a)",
                                  "I_m = {value:.4g} A 为忽略 R_s 的空载估算 U_ph/(ω·L_s)：请填写实测"
                                  "空载电流（motor.magnetizing_current_a）"),
    "finding.acim_flux_build": ("the rotor flux needs {t95:.3g} s (3·τ_r, τ_r = {tau:.3g} s) to reach "
                                "95 % after i_d steps to I_m: magnetize for at least that long before "
                                "asking for torque, or the torque per ampere is low and the slip "
                                "estimate wrong while it builds",
                                "i_d 阶跃到 I_m 后转子磁链需 {t95:.3g} s（3·τ_r，τ_r = {tau:.3g} s）才"
                                "达到 95 %：给转矩前至少预励磁这么久，否则建立期间每安培转矩偏低、"
                                "转差估计错误"),
    "finding.acim_rr_drift": ("the slip estimate ω_sl = i_q/(τ_r·i_d) scales with R_r: from "
                              "{t_lo:g} °C to {t_hi:g} °C R_r rises {pct:.3g} % (α = {alpha:g}/K), "
                              "so the field orientation drifts and torque per ampere falls. Adapt "
                              "R_r (temperature model, MRAS) or tune τ_r hot",
                              "转差估计 ω_sl = i_q/(τ_r·i_d) 与 R_r 成正比：从 {t_lo:g} °C 到 "
                              "{t_hi:g} °C R_r 升高 {pct:.3g} %（α = {alpha:g}/K），磁场定向漂移、"
                              "每安培转矩下降。请自适应 R_r（温度模型、MRAS）或按热态整定 τ_r"),
    "finding.acim_torque_before_flux": (
        "torque is commanded {t:.3g} s after magnetizing starts, but the rotor flux needs {t95:.3g} s "
        "to reach 95 %: only {pct:.3g} % is built then, so the torque per ampere is that share and "
        "the slip estimate i_q/(τ_r·i_d) is wrong while it builds. Magnetize for at least {t95:.3g} s "
        "(about 3·τ_r), or boost i_d at start, or hold the torque reference until the flux model "
        "reaches 95 %",
        "磁化开始后 {t:.3g} s 即给转矩，但转子磁链需 {t95:.3g} s 才达到 95 %：此时只建立了 "
        "{pct:.3g} %，每安培转矩仅为该比例，建立期间转差估计 i_q/(τ_r·i_d) 也错误。请至少预励磁 "
        "{t95:.3g} s（约 3·τ_r），或起动时加大 i_d，或在磁链模型达到 95 % 前保持转矩给定为零"),
    "finding.acim_rr_hot": (
        "with the rotor {rise_k:g} K hotter R_r rises {rr_pct:.3g} %, and a slip estimate with the "
        "cold τ_r sets {slip_pct:.3g} % too little slip: at rated current the rotor flux leads the "
        "controller's d axis by {angle_deg:.3g}°, the rotor flux by {flux_pct:+.3g} % and the torque per ampere by "
        "{torque_pct:+.3g} % (linear magnetics; saturation limits the flux rise, the torque then "
        "falls short). Track R_r (temperature model, MRAS) or tune τ_r for the hot motor",
        "转子温升 {rise_k:g} K 时 R_r 升高 {rr_pct:.3g} %，用冷态 τ_r 的转差估计少给 {slip_pct:.3g} % "
        "的转差：额定电流下转子磁链超前控制器 d 轴 {angle_deg:.3g}°，转子磁链偏差 {flux_pct:+.3g} %，每安培转矩"
        "偏差 {torque_pct:+.3g} %（线性磁路；饱和会限制磁链上升，转矩随之不足）。请跟踪 R_r"
        "（温度模型、MRAS）或按热态整定 τ_r"),
    "finding.acim_im_ratio": (
        "I_m is {pct:.3g} % of the rated current (usual {lo:g}–{hi:g} %): outside that range check "
        "I_m (RMS no-load current, not its peak) and L_m (per phase, not the 2/3·L_m convention)",
        "I_m 为额定电流的 {pct:.3g} %（常见 {lo:g}–{hi:g} %）：超出该范围时请核对 I_m（空载电流有效值，"
        "而非峰值）与 L_m（每相值，而非 2/3·L_m 约定）"),
    "finding.acim_im_vs_noload": (
        "the given I_m = {value:.4g} A is {pct:+.3g} % from the no-load current U_ph/(ω·L_s) = "
        "{noload:.4g} A of the circuit: I_m and L_m (or L_ls) disagree; at rated voltage the flux "
        "reference L_m·I_m then over- or under-fluxes the motor. Check both against the no-load test",
        "给定 I_m = {value:.4g} A 与等效电路的空载电流 U_ph/(ω·L_s) = {noload:.4g} A 相差 {pct:+.3g} %："
        "I_m 与 L_m（或 L_ls）不一致；额定电压下磁链给定 L_m·I_m 会使电机过励或欠励。请用空载试验"
        "核对两者"),
    "finding.acim_slip_mismatch": ("the circuit gives a rated slip frequency {model:.4g} Hz = "
                                   "I_q/(2π·τ_r·I_m) but the nameplate speed gives {plate:.4g} Hz "
                                   "({pct:+.3g} %): R_r, L_r or I_m do not match the nameplate",
                                   "等效电路给出的额定转差频率 {model:.4g} Hz = I_q/(2π·τ_r·I_m)，"
                                   "铭牌转速给出 {plate:.4g} Hz（{pct:+.3g} %）：R_r、L_r 或 I_m "
                                   "与铭牌不符"),
    "finding.acim_flux_stall": ("TI's IQ24 current model stops {pct:.3g} % ({lsb} LSB) below the "
                                "flux reference: _IQmpy(Kr = {kr}, error) floors to 0 once the error "
                                "is below 2^24/Kr. Round the product (add 2^23 before the shift), "
                                "keep more fraction bits in IMDs, or run the model at a longer period",
                                "TI 的 IQ24 电流模型停在磁链给定以下 {pct:.3g} %（{lsb} LSB）：误差小于 "
                                "2^24/Kr 后 _IQmpy(Kr = {kr}, 误差) 向下取整为 0。请对乘积做舍入（移位前加 "
                                "2^23）、为 IMDs 保留更多小数位，或以更长的周期运行该模型"),
    "set_syntax": ("--set needs NAME=VALUE, got {got}", "--set 需要 NAME=VALUE，当前为 {got}"),
    "json_invalid": ("not valid JSON: {detail}", "不是合法的 JSON：{detail}"),
    "json_not_text": ("not valid JSON: the input is not text", "不是合法的 JSON：输入不是文本"),
    "json_too_deep": ("nested deeper than {depth} levels", "嵌套超过 {depth} 层"),
    "json_too_long": ("longer than {limit} characters", "超过 {limit} 个字符"),
    # reading a vendor header back (pulab.analyses.audit)
    "audit_empty": ("{name} is empty: paste a generated header", "{name} 为空：请粘贴生成的头文件"),
    "audit_not_text": ("{name} is not C text ({why})", "{name} 不是 C 文本（{why}）"),
    "audit_why_nul": ("a NUL byte", "含 NUL 字节"),
    "audit_why_type": ("not a string", "不是字符串"),
    "audit_why_pair": ("not a (name, text) pair", "不是（名称，文本）对"),
    "audit_no_files": ("give at least one header file", "至少给出一个头文件"),
    "audit_no_vendor": ("no #define of a known vendor header (ST, TI, NXP, Microchip, "
                        "Inovance) in {names}", "{names} 中没有已知厂商头文件的 #define（ST、TI、NXP、"
                        "Microchip、汇川）"),
    "audit_define": ("{file}:{line}: #define {name} does not evaluate: {why}",
                     "{file}:{line}：#define {name} 无法求值：{why}"),
    "audit_values": ("the {vendor} header's numbers make no design ({why} in its formulas): "
                     "a scale or a divisor is zero or negative",
                     "{vendor} 头文件的数值构不成设计（其公式中出现 {why}）：某个比例或除数为零或负"),
    "audit_preprocess": ("{file}:{line}: {why}", "{file}:{line}：预处理：{why}"),
    "audit.comment_value": ("{macro} = {value} but its comment says {comment}: no reading of "
                            "it ({readings}) gives that; nearest {nearest}",
                            "{macro} = {value}，但其注释写的是 {comment}：任何读法（{readings}）"
                            "都得不到它；最接近的是 {nearest}"),
    "audit.comment_stale": ("{macro} = {value} stands for {got}, but its comment says {said}: "
                            "the integer or its scale changed after the file was generated",
                            "{macro} = {value} 代表 {got}，但其注释写的是 {said}：整数或其比例在"
                            "文件生成后被改过"),
    "audit.inconsistent": ("{what}: {a} from {a_from} but {b} from {b_from} ({diff} % apart)",
                           "{what}：由 {a_from} 得 {a}，由 {b_from} 得 {b}（相差 {diff} %）"),
    "audit.json": ("{macro} = {value}, but the tool's own inputs (the JSON in the header's "
                   "comment) give {expected} ({diff} LSB apart)",
                   "{macro} = {value}，但工具自己的输入（头文件注释中的 JSON）给出 {expected}"
                   "（相差 {diff} LSB）"),
    "audit.json_float": ("{macro} = {value}, but the tool's own inputs (the JSON in the header's "
                         "comment) give {expected} ({diff} % apart)",
                         "{macro} = {value}，但工具自己的输入（头文件注释中的 JSON）给出 {expected}"
                         "（相差 {diff} %）"),
    "audit.overflow": ("{macro}: the compiler's value {value} is not the {ideal} its formula "
                       "means: it does not fit {ctype}",
                       "{macro}：编译器得到的 {value} 不是公式所指的 {ideal}：超出 {ctype} 范围"),
    "audit.overflow_range": ("{macro}: fits for this motor, but not for every motor within ± "
                             "{spread} % ({kind} at {statement}; e.g. {at})",
                             "{macro}：对本电机不溢出，但在 ±{spread} % 范围内的电机中并非都不溢出"
                             "（{kind}，位于 {statement}；例如 {at}）"),
    "audit.rounding": ("{macro} = {value} stands for {ideal}: rounding costs {err} %",
                       "{macro} = {value} 代表 {ideal}：取整误差 {err} %"),
    "audit.if_undefined": ("#if compares names no given file defines ({names}): each is 0, so "
                           "the first such branch is taken whatever was meant",
                           "#if 比较了所给文件中都未定义的名字（{names}）：它们都为 0，因此总是取"
                           "第一个这样的分支"),
    "audit.if_undefined_unused": ("#if compares names no given file defines ({names}): the "
                                  "files' own choice is not affected, but a branch compared with "
                                  "them cannot be chosen by that name",
                                  "#if 比较了所给文件中都未定义的名字（{names}）：不影响文件当前的选择，"
                                  "但与它们比较的分支无法按该名字选中"),
    "audit.loop_margin": ("{axis} current loop with one sample of computation and the PWM's "
                          "half period (Ts = {ts} s): {stable}, phase margin {pm}°, gain margin "
                          "{gm} dB, crossover {fc} Hz (the report wants 30° or more)",
                          "{axis} 轴电流环（计入一个采样周期的计算延迟与 PWM 半周期，Ts = {ts} s）："
                          "{stable}，相位裕度 {pm}°，增益裕度 {gm} dB，穿越频率 {fc} Hz"
                          "（报告要求相位裕度不低于 30°）"),
    "audit.loop_stable": ("stable", "稳定"),
    "audit.loop_unstable": ("unstable", "不稳定"),
}


class _Number:
    """A number parameter whose format spec ``~UNIT`` asks for :func:`si_text`."""

    def __init__(self, v):
        self.v = v

    def __format__(self, spec: str) -> str:
        if not spec.startswith("~"):
            return format(self.v, spec)
        return si_text(self.v, spec[1:])


def _is_word(v) -> bool:
    return isinstance(v, dict) and (set(v) == {"label"} or set(v) == {"vendor"})


def _word(v, lang: str):
    """A parameter as its text's word: a form label or a profile's name (a list of them joined);
    else ``v`` itself."""
    if isinstance(v, list) and v and all(_is_word(x) for x in v):
        return (", " if lang == "en" else "、").join(str(_word(x, lang)) for x in v)
    if isinstance(v, dict) and set(v) == {"label"}:
        return _label(v["label"], lang)
    if isinstance(v, dict) and set(v) == {"vendor"} and v["vendor"] in vendors.NAMES:
        return vendors.display(v["vendor"], lang)
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        return _Number(v)
    return v


def _label(path: str, lang: str) -> str:
    f = FIELD.get(path)
    if f is None or not f.label[0]:
        f = vendors.option_field(path)
    return f.label[0 if lang == "en" else 1] if f is not None else path


def render(code: str, params: dict, lang: str) -> str:
    """The text of error ``code`` with ``params`` in ``lang`` (``'en'`` or ``'zh'``)."""
    en, zh = MESSAGES[code]
    # A field's form label or a profile's name in this language.
    params = {k: _word(v, lang) for k, v in params.items()}
    # A nested error sees the outer params it does not set itself (e.g. a finding's label).
    plain = {k: v for k, v in params.items() if not (isinstance(v, dict) and "code" in v)}
    values = {k: render(v["code"], {**plain, **v["params"]}, lang)
              if isinstance(v, dict) and "code" in v else v for k, v in params.items()}
    return (en if lang == "en" else zh).format(**values)
