"""Chinese text for every message pulab produces (errors and warnings).

Messages are written once, in English, where they arise; this catalog turns
each into Chinese by pattern, the way a gettext catalog would, so the page
can show "every label, unit and message in both" without two code paths.
A message with no pattern here comes back unchanged — the tests make sure
every message the core can produce has one.

Examples
--------
>>> to_zh("must be > 0, got -1")
'必须大于 0，当前为 -1'
>>> to_zh("raw.LD = 5: rounding motor.ld_h = 4.5e-05 to the firmware unit changes it by +11.11 %")
'raw.LD = 5：把 motor.ld_h = 4.5e-05 取整到固件单位，改变了 +11.11 %'
"""

from __future__ import annotations

import re

__all__ = ["to_zh", "has_chinese", "CATALOG"]

_SRC = {"given": "直接给定"}

#: (English pattern, Chinese replacement); the first full match wins.
CATALOG = [
    # errors: input validation
    (r"is required", "必填"),
    (r"must be a JSON object", "必须是 JSON 对象"),
    (r"must be an object", "必须是对象"),
    (r"must be an object, got (.*)", r"必须是对象，当前为 \1"),
    (r"not valid JSON: (.*)", r"不是合法的 JSON：\1"),
    (r"nested deeper than (\d+) levels", r"嵌套超过 \1 层"),
    (r"unknown field \(expected one of: (.*)\)", r"未知字段（应为以下之一：\1）"),
    (r"unknown section \(expected one of: (.*)\)", r"未知分节（应为以下之一：\1）"),
    (r"must be a number, got (.*) \(ambiguous: a decimal comma or a thousands separator\?\)",
     r"必须是数字，当前为 \1（有歧义：是小数逗号还是千位分隔符？）"),
    (r"must be a number, got (.*)", r"必须是数字，当前为 \1"),
    (r"must be an integer \(decimal, 0x… hex or 0b… binary\), got (.*)",
     r"必须是整数（十进制、0x… 十六进制或 0b… 二进制），当前为 \1"),
    (r"must be finite", "必须是有限数"),
    (r"must be a finite number", "必须是有限数"),
    (r"must be > 0, got (.*)", r"必须大于 0，当前为 \1"),
    (r"must not be 0", "不能为 0"),
    (r"must be between (\S+) and (\S+), got (.*)", r"必须在 \1 与 \2 之间，当前为 \3"),
    (r"must be one of (.*), got (.*)", r"必须是以下之一：\1；当前为 \2"),
    (r"must be one of (.*)", r"必须是以下之一：\1"),
    (r"must be an integer, got (.*)", r"必须是整数，当前为 \1"),
    (r"must be an integer", "必须是整数"),
    (r"must be (\S+)\.\.(\S+), got (.*)", r"必须在 \1..\2 之间，当前为 \3"),
    (r"must be (\S+)\.\.(\S+) for (\S+)", r"对 \3 必须在 \1..\2 之间"),
    (r"must be true or false, got (.*)", r"必须是 true 或 false，当前为 \1"),
    (r"is only used with (\w+) = (\w+)", r"仅在 \1 = \2 时使用"),
    (r"not a Q format: (.*) \(use Qm\.n, UQm\.n, or Qn with word_bits\)",
     r"不是 Q 格式：\1（请用 Qm.n、UQm.n，或 Qn 并给出 word_bits）"),
    (r"(\S+) is outside (\S+) \[(\S+), (\S+)\]", r"\1 超出 \2 的范围 [\3, \4]"),
    (r"(\S+) does not fit (\d+) word bits", r"\1 放不进 \2 位字长"),
    # errors: the firmware path and the gains
    (r"(-?\d+) \((given|from \S+)\) is outside Uint16 0\.\.65535",
     lambda m: f"{m[1]}（{_SRC.get(m[2], '由 ' + m[2][5:] + ' 换算')}）超出 Uint16 范围 0..65535"),
    (r"the firmware divides by zero: (.*)", r"固件出现除以零：\1"),
    (r"too low for damping design: kp = 2ζω0·L − Rs = (\S+) Ω ≤ 0",
     r"对阻尼比设计而言过低：kp = 2ζω0·L − Rs = \1 Ω ≤ 0"),
    (r"(\S+) = (\S+) does not fit a 32-bit long", r"\1 = \2 超出 32 位 long 的范围"),
    (r"the input asks for no (\w+) simulation", r"输入中没有 \1 仿真"),
    # errors: the simulation
    (r"(\S+) s is (\S+) control periods; at most (\d+)", r"\1 s 等于 \2 个控制周期；最多 \3 个"),
    (r"(\S+) A is (\S+) pu; the Q12 current \(int16\) holds less than ±8 pu \(±(\S+) A\)",
     r"\1 A 即 \2 pu；Q12 电流（int16）只能表示 ±8 pu 以内（±\3 A）"),
    (r"\|(\S+)\| Hz is not below half the control frequency 1/\(2·Ts\) = (\S+) Hz",
     r"|\1| Hz 未低于控制频率的一半 1/(2·Ts) = \2 Hz"),
    (r"the input speed reaches (\S+) Hz, not below half the control frequency "
     r"1/\(2·Ts\) = (\S+) Hz", r"输入转速达到 \1 Hz，未低于控制频率的一半 1/(2·Ts) = \2 Hz"),
    (r"q15 PLL gain (\S+) = (\S+) does not fit int32 \(Q24 allows per-unit gains below 128\)",
     r"q15 锁相环增益 \1 = \2 超出 int32（Q24 只允许小于 128 的标幺增益）"),
    # warnings
    (r"LD/LQ taken in µH: .*", "原始 LD/LQ 按 µH 输入：汇川代码按 0.01 mH 编写，因此 "
     "gMotorExtPer.LD/LQ 是 Q13 标幺电感的 10 倍（式 1.4-6 的“×10”之谜）"),
    (r"custom bases: .*", "自定义基值：汇川整数（Rpm、LD 等）始终使用汇川 rms 基值 U_LL/√3 与 "
     "I_rms；PI 整数使用自定义基值"),
    (r"raw\.(\S+) = 0: (\S+) = (\S+) is below the firmware resolution",
     r"raw.\1 = 0：\2 = \3 低于固件分辨率"),
    (r"raw\.(\S+) = (\S+): rounding (\S+) = (\S+) to the firmware unit changes it by (\S+) %",
     r"raw.\1 = \2：把 \3 = \4 取整到固件单位，改变了 \5 %"),
    (r"current_pi\.(\w)\.pm_ki rounds to 0: .*",
     r"current_pi.\1.pm_ki 取整为 0：积分作用丢失（ki·Ts 小于标幺增益的一个 Q16 LSB）"),
    (r"current_pi\.(\w)\.(pm_k[pi]) = (\S+): coarse, rounding changes (k[pi]) by (\S+) %",
     r"current_pi.\1.\2 = \3：分辨率粗，取整使 \4 改变 \5 %"),
    # the design review (pulab.analyses.review)
    (r"vendor\.(\S+) = (\S+): the firmware arithmetic wrapped \(exact value (\S+)\); "
     r"change (\S+)", r"vendor.\1 = \2：固件运算发生回绕（精确值 \3）；请修改 \4"),
    (r"vendor\.(\S+) = (\S+) is (\S+) % off the exact value (\S+); change (\S+)",
     r"vendor.\1 = \2 与精确值 \4 相差 \3 %；请修改 \5"),
    (r"current-loop ω_c·Ts = (\S+) ≥ (\S+): the 1\.5·Ts loop delay leaves a phase margin "
     r"below 5°; lower the bandwidth to (\S+) Hz or less \((\S+)\)",
     r"电流环 ω_c·Ts = \1 ≥ \2：1.5·Ts 的环路延迟使相位裕度低于 5°；请把带宽降到 \3 Hz 以下（\4）"),
    (r"current-loop ω_c·Ts = (\S+) > (\S+): the continuous-time design is far from the "
     r"discrete loop's behaviour; lower the bandwidth to (\S+) Hz or less \((\S+)\)",
     r"电流环 ω_c·Ts = \1 > \2：连续域设计与离散环路的实际行为相差较大；请把带宽降到 \3 Hz 以下（\4）"),
    (r"raw\.FullFreq01 = (\S+) < raw\.FreqRated01 = (\S+): base frequency below rated "
     r"frequency, FreqPer > 1\.0 in Q15; raise drive\.base_freq_hz to motor\.rated_freq_hz "
     r"or more", r"raw.FullFreq01 = \1 < raw.FreqRated01 = \2：基值频率低于额定频率，Q15 的 "
     r"FreqPer > 1.0；请把 drive.base_freq_hz 提高到不低于 motor.rated_freq_hz"),
    (r"at rated current and rated frequency the motor needs (\S+) V \(line RMS\), above the "
     r"voltage limit (\S+) V; raise drive\.udc_v",
     r"额定电流、额定频率下电机需要 \1 V（线电压有效值），超过电压限幅 \2 V；请提高 drive.udc_v"),
    (r"back-EMF at f_b = (\S+) Hz is (\S+) V \(line RMS\), above the voltage limit (\S+) V: "
     r"field weakening needed above (\S+) Hz; raise drive\.udc_v or lower drive\.base_freq_hz",
     r"f_b = \1 Hz 时反电势为 \2 V（线电压有效值），超过电压限幅 \3 V：\4 Hz 以上需要弱磁；"
     r"请提高 drive.udc_v 或降低 drive.base_freq_hz"),
    (r"at rated current and f_b = (\S+) Hz the motor needs (\S+) V \(line RMS\), above the "
     r"voltage limit (\S+) V: full current up to f_b needs field weakening",
     r"额定电流、f_b = \1 Hz 时电机需要 \2 V（线电压有效值），超过电压限幅 \3 V："
     r"满电流运行到 f_b 需要弱磁"),
    (r"(\S+): not locked \(\|θ − θ̂\| ≥ 2° in the last 20 % of the run\); change "
     r"pll\.bandwidth_hz", r"\1：未锁定（仿真最后 20 % 内 |θ − θ̂| ≥ 2°）；请修改 pll.bandwidth_hz"),
    (r"(\S+)\.steady_angle_error_deg = (\S+)°: angle error after lock; change pll\.bandwidth_hz",
     r"\1.steady_angle_error_deg = \2°：锁定后的角度误差；请修改 pll.bandwidth_hz"),
    # errors: the datasheet section (pulab.model.datasheet)
    (r"and (\S+) both given; give one of them", r"与 \1 不能同时给出；请只给其中一个"),
    (r"and (\S+) both give the back-EMF; give one of them", r"与 \1 都给出反电势；请只给其中一个"),
    (r"gives (\S+) = (\S+), which (.*)", lambda m: f"得到 {m[1]} = {m[2]}，{to_zh(m[3])}"),
    (r"is required \(one of (.*)\)", r"必填（以下之一：\1）"),
    (r"is required to convert (\S+) \(or give (\S+)\)", r"换算 \1 时必填（或给出 \2）"),
    (r"is only used with (\S+) or (\S+)", r"仅与 \1 或 \2 一起使用"),
    (r"is only used with (\S+)", r"仅与 \1 一起使用"),
    # two hardening messages that had no Chinese yet (CLI input bytes, qcalc.format type)
    (r"not UTF-8 text \(byte (\d+)\)", r"不是 UTF-8 文本（第 \1 字节）"),
    (r"must be a string, got (.*)", r"必须是字符串，当前为 \1"),
    # vendor profiles, headers and the translator
    (r"must be a power of two, got (.*)", r"必须是 2 的幂，当前为 \1"),
    (r"profiles\.(\S+): (\S+) does not fit (.+); stored (\S+)",
     r"profiles.\1：\2 超出 \3 的范围；实际存储 \4"),
    (r"profiles\.ti: USER_checkForErrors would set (\S+) \((.+)\)",
     r"profiles.ti：USER_checkForErrors 会置位 \1（\2）"),
    (r"profiles\.(\S+): rounds to 0 in (.+) \(ideal (\S+)\)",
     r"profiles.\1：在 \2 中取整为 0（理想值 \3）"),
    # errors: the family sweep and the batch (issue 13)
    (r"not a numeric input path: (.*)", r"不是数值输入路径：\1"),
    (r"must be > 0 for a log scale, got (.*)", r"对数刻度要求大于 0，当前为 \1"),
    (r"must differ from (\S+) \((.*)\)", r"必须不同于 \1（\2）"),
    (r"unknown profile (.*)", r"未知的厂商配置：\1"),
    (r"the sweep has (\d+) points; at most (\d+)", r"扫描共有 \1 个点；最多 \2 个"),
    (r"must be a list of chunk summaries", "必须是分块摘要的列表"),
    (r"expected PATH=START:STOP\[:N\]\[:log\], got (.*)",
     r"格式应为 PATH=START:STOP[:N][:log]，当前为 \1"),
    (r"empty column name (.*)", r"列名为空：\1"),
    (r"a unit is only converted for an input path, not (.*)", r"只有输入路径列才换算单位，\1 不是"),
    (r"unknown unit \[(.*)\] for (\S+) \(allowed: none \(give the value in the unit its name "
     r"ends in\)\)", r"\2 的单位 [\1] 未知（此列不换算单位：请按列名结尾的单位给值）"),
    (r"unknown unit \[(.*)\] for (\S+) \(allowed: (.*)\)", r"\2 的单位 [\1] 未知（可用：\3）"),
    (r"must be text", "必须是文本"),
    (r"not readable as CSV: (.*)", r"无法按 CSV 读取：\1"),
    (r"no header row", "没有表头行"),
    (r"duplicate column (\S+) \(also column (\d+)\)", r"列 \1 重复（与第 \2 列相同）"),
    (r"(\d+) cells, the header has (\d+)", r"该行有 \1 个单元格，表头只有 \2 列"),
    (r"cannot read (.*): not UTF-8 \((.*)\)", r"无法读取 \1：不是 UTF-8 编码（\2）"),
    (r"cannot read (.*): (.*)", r"无法读取 \1：\2"),
    # the C tracer (pulab.ctrace): a position prefix, then the reason
    (r"(\d+:\d+): (.*)", lambda m: f"{m[1]}：{to_zh(m[2])}"),
    (r"code is longer than (\d+) characters", r"代码超过 \1 个字符"),
    (r"code must be text", "代码必须是文本"),
    (r"unexpected character (.*)", r"意外的字符 \1"),
    (r"comment not closed: \*/ missing", "注释未闭合：缺少 */"),
    (r"annotation must read (.*)", r"注解格式应为 \1"),
    (r"Q(\d+): at most 63 fraction bits", r"Q\1：小数位最多 63 位"),
    (r"base must be a finite number", "base 必须是有限数"),
    (r"#define needs a name", "#define 需要一个名字"),
    (r"function definition (\w+)\(…\) is not supported \(trace its body's statements\)",
     r"不支持函数定义 \1(…)（请追踪其函数体中的语句）"),
    (r"typedef (\w+) is not supported \(only typedefs of integer types\)",
     r"不支持 typedef \1（只支持整数类型的 typedef）"),
    (r"expected a name after typedef (.*), got (.*)", r"typedef \1 之后应为名字，实际为 \2"),
    (r"(\w+) is a floating-point type \(typedef at (\S+)\), not supported",
     r"\1 是浮点类型（typedef 于 \2），不支持"),
    (r"(\w+) is a pointer type \(typedef at (\S+)\), not supported",
     r"\1 是指针类型（typedef 于 \2），不支持"),
    # the preprocessor (pulab.ctrace.preprocess)
    (r"must be a list of NAME\[=VALUE\] texts", "必须是 NAME[=VALUE] 文本的列表"),
    (r"must be text NAME\[=VALUE\], got (.*)", r"必须是文本 NAME[=VALUE]，当前为 \1"),
    (r"(\w+)\(…\) needs a floating constant \(a variable would need floating point at run "
     r"time\)", r"\1(…) 需要浮点常量（变量需要运行时浮点运算）"),
    (r"(\w+)\(…\) = (\S+) does not fit a 32-bit long", r"\1(…) = \2 超出 32 位 long 的范围"),
    (r"in (#\w+(?: \w+)?|[\w.]+\.h): (.*)", lambda m: f"在 {m[1]} 中：{to_zh(m[2])}"),
    (r"(#\w+(?: \w+)?|[\w.]+\.h): unexpected text", r"\1：有意外的内容"),
    (r"#define (\w+)\(: '\)' missing after the parameters", r"#define \1(：参数后缺少 ')'"),
    (r"#define (\w+)\(…\): bad parameter (.*)", r"#define \1(…)：错误的参数 \2"),
    (r"#define (\w+)\(…\): a parameter is named twice", r"#define \1(…)：参数重名"),
    (r"#define (\w+): '##' cannot begin or end a macro body",
     r"#define \1：'##' 不能出现在宏体的开头或结尾"),
    (r"-D (.*): NAME\[=VALUE\] needs a C name", r"-D \1：NAME[=VALUE] 需要一个 C 名字"),
    (r"#(\w+) without #if", r"#\1 没有对应的 #if"),
    (r"#(\w+) after #else", r"#\1 出现在 #else 之后"),
    (r"#if without #endif", "#if 没有对应的 #endif"),
    (r"#if nested deeper than (\d+)", r"#if 嵌套超过 \1 层"),
    (r"#error(.*)", r"#error（代码要求停止）\1"),
    (r"#(.*) is not a preprocessor directive this tracer knows", r"#\1 不是本工具认识的预处理指令"),
    (r"#include needs <header> or \"header\"", "#include 需要 <头文件> 或 \"头文件\""),
    (r"#(\w+) needs one name", r"#\1 需要一个名字"),
    (r"defined needs a macro name", "defined 需要一个宏名"),
    (r"#if needs an expression", "#if 需要一个表达式"),
    (r"#if: (.*)", lambda m: f"#if：{to_zh(m[1])}"),
    (r"expression ends early", "表达式不完整"),
    (r"unexpected (.*)", r"意外的 \1"),
    (r"'(.)' missing", r"缺少 '\1'"),
    (r"shift by (.*)", r"移位位数为 \1"),
    (r"(.*) is not an integer constant", r"\1 不是整数常量"),
    (r"macro (\w+): expansion nested deeper than (\d+) macros", r"宏 \1：展开嵌套超过 \2 层"),
    (r"macro (\w+): more than (\d+) tokens after expansion", r"宏 \1：展开后超过 \2 个记号"),
    (r"macro (\w+)\(: '\)' missing", r"宏 \1(：缺少 ')'"),
    (r"macro (\w+)\(\) takes (\d+) arguments, got (\d+)", r"宏 \1() 需要 \2 个参数，实际为 \3 个"),
    (r"'##' pasting (.*) and (.*) does not give one token", r"'##' 拼接 \1 和 \2 得不到一个记号"),
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
    # loop analysis (issue 11)
    (r"(\S+): the closed current loop is unstable with the (\w+) delay \(largest \|pole\| (\S+)\)",
     r"\1：计入 \2 延时后电流闭环不稳定（最大极点模 \3）"),
    (r"(\S+): phase margin (\S+)° with the (\w+) delay \(below 30°: .*\)",
     r"\1：计入 \3 延时后相位裕度只有 \2°（低于 30°：超调与振荡明显）"),
    (r"loop\.speed: the closed speed loop is unstable \(largest \|pole\| (\S+)\)",
     r"loop.speed：速度闭环不稳定（最大极点模 \1）"),
    (r"loop\.speed: the current loop's bandwidth is only (\S+)× the speed crossover; .*",
     r"loop.speed：电流环带宽只有速度环穿越频率的 \1 倍；速度环裕度（把内环当作一个周期的延时）偏乐观"),
    (r"too low for the friction: kp = \(2ζωn·J − B\)/Kt = (\S+) ≤ 0",
     r"相对摩擦过低：kp = (2ζωn·J − B)/Kt = \1 ≤ 0"),
    (r"speed (pm_k[pi]) = (\S+) does not fit a 32-bit long", r"速度环 \1 = \2 超出 32 位 long 的范围"),
    (r"must be 1\.\.1000 times drive\.ts_s = (\S+) s, got (\S+) times",
     r"必须是 drive.ts_s = \1 s 的 1..1000 整数倍，当前为 \2 倍"),
    (r"(\S+) A is not below 8·I_b = (\S+) A \(the Q12 current reference is an int16\)",
     r"\1 A 未低于 8·I_b = \2 A（Q12 电流给定是 int16）"),
    (r"(\S+) Hz is not below the Nyquist frequency 1/\(2·Ts\) = (\S+) Hz",
     r"\1 Hz 未低于奈奎斯特频率 1/(2·Ts) = \2 Hz"),
    (r"(\S+)° is not reached below the Nyquist frequency \(the loop keeps more phase margin\)",
     r"在奈奎斯特频率以下达不到 \1°（环路的相位裕度始终更大）"),
    (r"must be between (\S+) and (\S+) and not 0, got (.*)", r"必须在 \1 与 \2 之间且不为 0，当前为 \3"),
    (r"must be ≥ 0, got (.*)", r"必须大于等于 0，当前为 \1"),
    (r"must be true or false, got (.*)", r"必须是 true 或 false，当前为 \1"),
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

    >>> has_chinese("must be finite"), has_chinese("no such pattern")
    (True, False)
    """
    zh = to_zh(message)
    return zh != message and any("\u4e00" <= ch <= "\u9fff" for ch in zh)
