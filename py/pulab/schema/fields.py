"""The input schema: every field of the report input, once, as data.

Each :class:`Field` names its JSON path, its kind, the unit of its JSON value,
its range, its default and its label and help in English and Chinese.
Everything else is derived from this table: the checks (:mod:`.validate`), the
page's form and its field checks (``web/src/generated/schema.json``, written by
the build from :func:`schema_json`), the contract's input tables (``tests/py/test_schema.py``
compares them) and the fuzzer's field list (``tests/py/adversarial.py``).

Adding an input field is one entry here, in the section it belongs to.  A
section's fields are checked in table order, so a field named by another's
``only_with`` comes first.  Rules that tie several fields together (the
datasheet's "give one of them") stay in the code that converts them.

Kinds: ``number`` (finite JSON number, booleans refused), ``integer``
(integral JSON number), ``choice`` (one of ``choices``), ``flag`` (true/false),
``name_or_number`` (one of ``choices``, or a number in the range), ``pair``
(``[low, high]``: two numbers in the range, low ≤ high), ``table`` (at least
2 rows of numbers, one per ``columns`` entry ``(name, unit, sign)``; the first
column strictly increases, as a lookup table's), ``text`` (a string of at most
``hi`` characters) and ``object`` (a JSON object, checked by the code that reads it).
``sign`` is checked before the range: ``'>0'``, ``'>=0'`` or ``'!=0'``;
``lo_open``/``hi_open`` leave the range's end out.
``default`` is a value, :data:`REQUIRED`, or ``None`` (absent; ``derived``
says what the report uses instead).  ``only_with = (path, value)``: the field
is used only while that field has that value (else giving it is an error and
the page disables it).

Examples
--------
>>> FIELD["drive.ts_s"].unit, FIELD["drive.ts_s"].hi
('s', 1.0)
>>> [f.path for f in section_fields("pll")]
['pll.bandwidth_hz', 'pll.damping']
>>> FIELD["current_loop.kp"].only_with
('current_loop.method', 'manual')
"""

from __future__ import annotations

import json
import math
from typing import NamedTuple

from . import vendors

__all__ = ["Field", "Section", "REQUIRED", "FIELDS", "FIELD", "SECTIONS", "RAW_FIELDS",
           "section_fields", "schema_json", "markdown"]


class _Required:
    def __repr__(self) -> str:
        return "REQUIRED"


#: Default of a field that must be given.
REQUIRED = _Required()


class Field(NamedTuple):
    """One input field (see the module docstring for the meaning of each part)."""

    path: str
    kind: str
    unit: str = ""
    sign: str = ""
    lo: float | None = None
    hi: float | None = None
    hi_open: bool = False
    default: object = None
    derived: str = ""
    choices: tuple = ()
    only_with: tuple = ()
    label: tuple = ("", "")
    help: tuple = ("", "")
    lo_open: bool = False
    columns: tuple = ()

    @property
    def section(self) -> str:
        return self.path.rsplit(".", 1)[0]

    @property
    def key(self) -> str:
        return self.path.rsplit(".", 1)[1]


class Section(NamedTuple):
    """A JSON object of the input: its path and its title (en, zh)."""

    path: str
    title: tuple


F = Field
DAMPING = math.sqrt(0.5)
INT32_MAX = (1 << 31) - 1

def _adc(section: str, what: tuple) -> tuple:
    """The two fields of an ADC of the board: its resolution and its reference."""
    return (F(f'{section}.adc_bits', 'integer', 'bit', lo=1, hi=32, default=12,
              label=(f'{what[0]} ADC resolution', f'{what[1]} ADC 位数')),
            F(f'{section}.adc_ref_v', 'number', 'V', sign='>0', lo=1e-6, hi=1e3, default=3.3,
              label=(f'{what[0]} ADC reference', f'{what[1]} ADC 参考电压')))


#: The Inovance firmware's raw Uint16 parameters (seed 1.4), in the order of its code.
RAW_FIELDS = ("Voltage", "Current", "FullFreq01", "FreqRated01", "RsPm", "LD", "LQ",
              "BemfVolt", "uDCFilter")
#: Firmware unit of each raw parameter (LD/LQ: conventions.inductance_unit).
RAW_UNITS = {"Voltage": "1 V", "Current": "0.01 A", "FullFreq01": "0.01 Hz",
             "FreqRated01": "0.01 Hz", "RsPm": "1 mΩ", "LD": "0.01 mH or 1 µH",
             "LQ": "0.01 mH or 1 µH", "BemfVolt": "0.1 V", "uDCFilter": "0.1 V"}
RAW_LABELS = {
    "Voltage": ("Voltage — rated line V", "Voltage — 额定线电压 V"),
    "Current": ("Current — rated A·100", "Current — 额定电流·100"),
    "FullFreq01": ("FullFreq01 — f_b·100", "FullFreq01 — f_b·100"),
    "FreqRated01": ("FreqRated01 — f_n·100", "FreqRated01 — f_n·100"),
    "RsPm": ("RsPm — Rs in mΩ", "RsPm — 电阻 mΩ"),
    "LD": ("LD — 0.01 mH (or µH)", "LD — 0.01 mH（或 µH）"),
    "LQ": ("LQ — 0.01 mH (or µH)", "LQ — 0.01 mH（或 µH）"),
    "BemfVolt": ("BemfVolt — E_LL·10", "BemfVolt — 反电势·10"),
    "uDCFilter": ("uDCFilter — Udc·10", "uDCFilter — 母线电压·10"),
}

#: Sections and fields in order: a Section entry, then its fields.
TABLE = (
    Section('motor', ('the motor (SI, per phase of the equivalent star)', '电机（SI，等效星形每相）')),
    F('motor.kind', 'choice', '', choices=('pmsm', 'acim'), default='pmsm',
      label=('Motor kind (pmsm: permanent magnet, acim: induction)', '电机类型（pmsm：永磁同步，acim：异步感应）')),
    F('motor.rated_voltage_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      derived='from datasheet.dc_bus_v when not given',
      label=('Rated voltage (line RMS)', '额定电压（线电压有效值）')),
    F('motor.rated_current_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      label=('Rated current (RMS)', '额定电流（有效值）')),
    F('motor.rated_freq_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      derived='from datasheet.speed_rpm when not given',
      label=('Rated frequency', '额定频率')),
    F('motor.rs_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      derived='from datasheet.rs_line_ohm or rs_phase_ohm when not given',
      label=('Stator resistance Rs (phase)', '定子电阻 Rs（相）')),
    F('motor.ld_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('motor.kind', 'pmsm'),
      derived='from datasheet L or Ld (line or phase) when not given',
      label=('d-axis inductance Ld', 'd 轴电感 Ld')),
    F('motor.lq_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('motor.kind', 'pmsm'),
      derived='from datasheet L or Lq (line or phase) when not given',
      label=('q-axis inductance Lq', 'q 轴电感 Lq')),
    F('motor.bemf_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('motor.kind', 'pmsm'),
      derived='from datasheet Ke, Kv, kT or ψ when not given',
      label=('Back-EMF at rated freq. (line RMS)', '额定频率反电势（线电压有效值）')),
    F('motor.pole_pairs', 'integer', '', lo=1, hi=1000, default=REQUIRED,
      label=('Pole pairs', '极对数')),
    # The induction motor's T-equivalent circuit, per phase, referred to the stator.
    F('motor.rated_speed_rpm', 'number', 'rpm', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('motor.kind', 'acim'),
      label=('Rated (full-load) speed, sets the slip', '额定（满载）转速，决定转差')),
    F('motor.rr_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('motor.kind', 'acim'),
      label=('Rotor resistance R_r (referred to the stator)', '转子电阻 R_r（折算到定子）')),
    F('motor.lm_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, only_with=('motor.kind', 'acim'),
      derived='1.5·datasheet.lms_h when not given (one of them is required)',
      label=('Magnetizing inductance L_m (T-equivalent)', '励磁电感 L_m（T 型等效电路）')),
    F('motor.lls_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, only_with=('motor.kind', 'acim'),
      derived='motor.ls_h − L_m when not given (one of them is required)',
      label=('Stator leakage inductance L_ls', '定子漏感 L_ls')),
    F('motor.llr_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, only_with=('motor.kind', 'acim'),
      derived='motor.lr_h − L_m when not given (one of them is required)',
      label=('Rotor leakage inductance L_lr (referred to the stator)', '转子漏感 L_lr（折算到定子）')),
    F('motor.ls_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, only_with=('motor.kind', 'acim'),
      derived='L_ls + L_m (give this or motor.lls_h)',
      label=('Stator self-inductance L_s = L_ls + L_m (instead of L_ls)', '定子自感 L_s = L_ls + L_m（代替 L_ls）')),
    F('motor.lr_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9, only_with=('motor.kind', 'acim'),
      derived='L_lr + L_m (give this or motor.llr_h)',
      label=('Rotor self-inductance L_r = L_lr + L_m (instead of L_lr)', '转子自感 L_r = L_lr + L_m（代替 L_lr）')),
    F('motor.magnetizing_current_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9,
      only_with=('motor.kind', 'acim'),
      derived='the no-load current U_ph/(2π·f_n·L_s) (R_s neglected)',
      label=('Magnetizing (no-load) current I_m (RMS)', '励磁（空载）电流 I_m（有效值）')),
    Section('drive', ('the drive', '驱动器')),
    F('drive.base_freq_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9,
      derived='motor.rated_freq_hz',
      label=('Base frequency f_b (drive max.)', '频率基值 f_b（最大频率）')),
    F('drive.udc_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      label=('DC bus voltage Udc', '母线电压 Udc')),
    F('drive.ts_s', 'number', 's', sign='>0', lo=1e-9, hi=1.0, default=REQUIRED,
      label=('Control period Ts', '控制周期 Ts')),
    Section('conventions', ('per-unit conventions', '标幺约定')),
    F('conventions.base', 'choice', '', choices=('rms', 'peak', 'custom'), default='rms',
      label=('Voltage/current bases', '电压/电流基值')),
    F('conventions.base_voltage_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('conventions.base', 'custom'),
      label=('Custom voltage base U_b', '自定义电压基值 U_b')),
    F('conventions.base_current_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('conventions.base', 'custom'),
      label=('Custom current base I_b', '自定义电流基值 I_b')),
    F('conventions.angle_base', 'choice', '', choices=('pi', '2pi'), default='pi',
      label=('Angle base θ_b', '角度基值 θ_b')),
    F('conventions.inductance_unit', 'choice', '', choices=('10uH', 'uH'), default='10uH',
      label=('Unit of raw LD/LQ', '原始 LD/LQ 单位')),
    F('conventions.firmware', 'choice', '', choices=vendors.NAMES, default='inovance',
      label=('Firmware you ship', '所用固件')),
    Section('current_loop', ('the current-loop PI', '电流环 PI')),
    F('current_loop.method', 'choice', '', choices=('bandwidth', 'damping', 'manual', 'integers'),
      default='bandwidth',
      label=('Method', '设计方法')),
    F('current_loop.bandwidth_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=500.0,
      label=('Bandwidth', '带宽')),
    F('current_loop.damping', 'number', '', sign='>0', lo=1e-3, hi=100.0, default=DAMPING,
      label=('Damping ζ', '阻尼比 ζ')),
    F('current_loop.kp', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('current_loop.method', 'manual'),
      label=('kp (phase)', 'kp（相值）')),
    F('current_loop.ki', 'number', 'Ω/s', sign='>0', lo=1e-9, hi=1e9, default=REQUIRED,
      only_with=('current_loop.method', 'manual'),
      label=('ki (phase)', 'ki（相值）')),
    F('current_loop.pm_kp', 'integer', 'Q12', lo=1, hi=INT32_MAX, default=REQUIRED,
      only_with=('current_loop.method', 'integers'),
      label=('pm_kp (firmware)', 'pm_kp（固件）')),
    F('current_loop.pm_ki', 'integer', 'Q16', lo=1, hi=INT32_MAX, default=REQUIRED,
      only_with=('current_loop.method', 'integers'),
      label=('pm_ki (firmware)', 'pm_ki（固件）')),
    Section('pll', ('the PLL', '锁相环')),
    F('pll.bandwidth_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=50.0,
      label=('Bandwidth', '带宽')),
    F('pll.damping', 'number', '', sign='>0', lo=1e-3, hi=100.0, default=DAMPING,
      label=('Damping ζ', '阻尼比 ζ')),
    Section('raw',
            ("the Inovance firmware's raw Uint16 parameters (each overrides the value from SI)",
             '汇川固件的原始 Uint16 参数（各自覆盖由 SI 换算的值）')),
    *(F(f"raw.{n}", "integer", RAW_UNITS[n], lo=0, hi=0xFFFF, derived="from SI (below)",
        label=RAW_LABELS[n])
      for n in RAW_FIELDS),
    Section('datasheet',
            ('values as a datasheet prints them; each fills a motor field left empty',
             '按数据手册填写的值；各自填入留空的电机字段')),
    F('datasheet.speed_rpm', 'number', 'rpm', sign='>0', lo=1e-9, hi=1e9,
      label=('Rated speed', '额定转速')),
    F('datasheet.ke_v_per_krpm', 'number', 'V/krpm', sign='>0', lo=1e-9, hi=1e9,
      label=('Back-EMF constant Ke', '反电势常数 Ke')),
    F('datasheet.ke_v_s_per_rad', 'number', 'V·s/rad', sign='>0', lo=1e-9, hi=1e9,
      label=('Ke in V·s/rad', 'Ke，单位 V·s/rad')),
    F('datasheet.ke_measure', 'choice', '', choices=('rms', 'peak'), derived='required with a Ke',
      label=('Ke measured as', 'Ke 的测量方式')),
    F('datasheet.ke_between', 'choice', '', choices=('line', 'phase'), default='line',
      label=('Ke measured between', 'Ke 的测量端')),
    F('datasheet.kv_rpm_per_v', 'number', 'rpm/V', sign='>0', lo=1e-9, hi=1e9,
      label=('Speed constant Kv', '速度常数 Kv')),
    F('datasheet.kv_measure', 'choice', '', choices=('rms', 'peak'), default='peak',
      label=('Kv per volt', 'Kv 的电压单位')),
    F('datasheet.kt_nm_per_a', 'number', 'N·m/A', sign='>0', lo=1e-9, hi=1e9,
      label=('Torque constant kT (sinusoidal)', '转矩常数 kT（正弦波）')),
    F('datasheet.kt_current', 'choice', '', choices=('rms', 'peak'), default='rms',
      label=('kT per ampere', 'kT 的电流单位')),
    F('datasheet.psi_wb', 'number', 'Wb', sign='>0', lo=1e-9, hi=1e9,
      label=('Magnet flux ψ (phase amplitude, Wb = V·s)', '永磁磁链 ψ（相幅值，Wb = V·s）')),
    F('datasheet.bemf_from', 'choice', '',
      choices=('ke_v_per_krpm', 'ke_v_s_per_rad', 'kv_rpm_per_v', 'kt_nm_per_a', 'psi_wb'),
      derived='the first given of Ke, Kv, kT, ψ',
      label=('Back-EMF the firmware uses', '固件采用的反电势来源')),
    F('datasheet.rs_line_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e9,
      label=('Resistance, terminal to terminal', '线间电阻（两端子之间）')),
    F('datasheet.rs_phase_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e9,
      label=('Resistance per phase', '每相电阻')),
    F('datasheet.l_line_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Inductance, terminal to terminal', '线间电感（两端子之间）')),
    F('datasheet.l_phase_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Inductance per phase', '每相电感')),
    F('datasheet.ld_line_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Ld, terminal to terminal', '线间 Ld（两端子之间）')),
    F('datasheet.ld_phase_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Ld per phase', '每相 Ld')),
    F('datasheet.lq_line_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Lq, terminal to terminal', '线间 Lq（两端子之间）')),
    F('datasheet.lq_phase_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      label=('Lq per phase', '每相 Lq')),
    F('datasheet.winding', 'choice', '', choices=('star', 'delta'), default='star',
      label=('Winding', '绕组接法')),
    F('datasheet.dc_bus_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9,
      label=('DC bus voltage (DC-bus motor)', '直流母线电压（直流供电电机）')),
    F('datasheet.lms_h', 'number', 'H', sign='>0', lo=1e-9, hi=1e9,
      derived='absent; refused unless motor.kind = acim',
      label=('Induction motor: L_ms = 2/3·L_m (per-phase magnetizing, steady-state model)',
             '异步电机：L_ms = 2/3·L_m（每相励磁电感，稳态模型）')),
    Section('board', ("the board's sensing and PWM (absent: none; every field optional)",
                      '板级采样与 PWM（不填则无；各字段均可选）')),
    Section('board.current', ('phase-current sensing', '相电流采样')),
    F('board.current.shunt_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e6,
      label=('Shunt resistor', '采样电阻')),
    F('board.current.gain', 'number', 'V/V', sign='>0', lo=1e-6, hi=1e6,
      label=('Amplifier gain', '放大器增益')),
    F('board.current.sensitivity_v_per_a', 'number', 'V/A', sign='>0', lo=1e-9, hi=1e6,
      label=('Sensor sensitivity (instead of shunt × gain)', '传感器灵敏度（代替电阻 × 增益）')),
    *_adc('board.current', ('Current', '电流')),
    F('board.current.bipolar', 'flag', '', default=True,
      label=('Bipolar (offset at mid-rail)', '双极性（偏置在中点）')),
    F('board.current.max_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9,
      derived='from the chain (shunt, gain or sensitivity, ADC reference)',
      label=('Largest measurable current ± (instead of the chain)', '最大可测电流 ±（代替采样链）')),
    Section('board.bus', ('DC-bus sensing', '母线电压采样')),
    F('board.bus.r_top_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e12,
      label=('Divider, top resistor', '分压上电阻')),
    F('board.bus.r_bottom_ohm', 'number', 'Ω', sign='>0', lo=1e-9, hi=1e12,
      label=('Divider, bottom resistor', '分压下电阻')),
    F('board.bus.ratio', 'number', '', sign='>0', lo=1e-9, hi=1.0,
      label=('Divider ratio (V at the ADC / V on the bus)', '分压比（ADC 端电压 / 母线电压）')),
    *_adc('board.bus', ('Bus', '母线')),
    F('board.bus.max_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9,
      derived='ADC reference / divider ratio',
      label=('Bus full scale (instead of the divider)', '母线满量程（代替分压）')),
    Section('board.pwm', ('the PWM timer', 'PWM 定时器')),
    F('board.pwm.clock_hz', 'number', 'Hz', sign='>0', lo=1.0, hi=1e12,
      label=('Timer clock', '定时器时钟')),
    F('board.pwm.freq_hz', 'number', 'Hz', sign='>0', lo=1e-3, hi=1e9,
      label=('PWM frequency', 'PWM 频率')),
    F('board.pwm.mode', 'choice', '', choices=('updown', 'up'), default='updown',
      label=('Counting (up-down = center-aligned)', '计数方式（增减 = 中心对齐）')),
    F('board.pwm.deadtime_s', 'number', 's', sign='>=0', hi=1.0,
      label=('Dead time', '死区时间')),
    F('board.pwm.periods_per_control', 'integer', '', lo=1, hi=1000, default=1,
      label=('PWM periods per control period', '每控制周期的 PWM 周期数')),
    Section('sim', ('the simulations (absent: none)', '仿真（不填则不仿真）')),
    Section('sim.current', ('the current-loop step simulation', '电流环阶跃仿真')),
    F('sim.current.axis', 'choice', '', choices=('d', 'q'), default='d', label=('Axis', '轴')),
    F('sim.current.step_a', 'number', 'A', sign='!=0', derived='0.5·I_b',
      label=('Reference step', '给定阶跃')),
    F('sim.current.duration_s', 'number', 's', sign='>0', derived='30/ω_c, at least 200 periods',
      label=('Duration', '时长')),
    F('sim.current.speed_hz', 'number', 'Hz', default=0.0, label=('Electrical speed', '电角频率')),
    F('sim.current.delay', 'flag', '', default=False,
      label=('One-sample computation delay', '一拍计算延时')),
    Section('sim.current.code', ("your C routine as the current controller, run beside pulab's own "
                                 "(absent: pulab's only)", '以你的 C 例程作电流控制器，与 pulab 自己的并列'
                                 '运行（不填则只有 pulab 的）')),
    F('sim.current.code.text', 'text', '', hi=200_000, default=REQUIRED,
      label=('C code of one axis\'s controller', '单轴控制器的 C 代码')),
    F('sim.current.code.target', 'choice', '', choices=('c28x', 'avr', 'msp430', 'arm'),
      default='c28x', label=('Target', '目标')),
    F('sim.current.code.entry', 'text', '', hi=200,
      derived='the statements outside functions are the period\'s code',
      label=('Entry function, called every period', '入口函数，每周期调用')),
    F('sim.current.code.scale', 'choice', '', choices=('inovance', 'ti', 'nxp', 'st', 'microchip'),
      default='inovance', label=('Integer units of current and voltage: this firmware\'s',
                                 '电流与电压的整数单位：取该固件的')),
    F('sim.current.code.reference', 'text', '', hi=200, label=('Input: current reference', '输入：电流给定')),
    F('sim.current.code.feedback', 'text', '', hi=200, label=('Input: measured current', '输入：电流反馈')),
    F('sim.current.code.error', 'text', '', hi=200,
      label=('Input: reference − feedback', '输入：给定 − 反馈')),
    F('sim.current.code.output', 'text', '', hi=200, default=REQUIRED,
      label=('Output: voltage command (variable, field or return)', '输出：电压指令（变量、字段或 return）')),
    F('sim.current.code.set', 'object', '', derived='none',
      label=('Values given before the first call: name → integer, report path or {"d", "q"}',
             '首次调用前给定的值：名字 → 整数、报告路径或 {"d", "q"}')),
    F('sim.current.code.integral', 'text', '', hi=200, derived='no preload (starts at 0)',
      label=('Integrator to preload with the back-EMF', '用反电势预置的积分器')),
    F('sim.current.code.integral_shift', 'integer', '', lo=0, hi=31, default=0,
      label=('Integrator = output units · 2^shift', '积分器 = 输出单位 · 2^shift')),
    Section('sim.pll', ('the PLL simulation', '锁相环仿真')),
    F('sim.pll.speed_hz', 'number', 'Hz', derived='motor.rated_freq_hz',
      label=('Electrical speed', '电角频率')),
    F('sim.pll.angle_step_deg', 'number', '°', lo=-180.0, hi=180.0, default=30.0,
      label=('Angle step', '角度阶跃')),
    F('sim.pll.ramp_hz_per_s', 'number', 'Hz/s', default=0.0, label=('Speed ramp', '速度斜坡')),
    F('sim.pll.duration_s', 'number', 's', sign='>0', derived='60/(ζω_n), at least 2000 periods',
      label=('Duration', '时长')),
    Section('sim.flux', ('an induction motor\'s flux build-up (magnetizing) simulation',
                         '异步电机建磁（励磁）仿真')),
    F('sim.flux.duration_s', 'number', 's', sign='>0',
      derived='5·τ_r, 200 to 50 000 periods (cut: complete false)',
      label=('Duration', '时长')),
    F('sim.flux.startup_s', 'number', 's', sign='>0', derived='none',
      label=('Torque commanded after (start-up magnetizing time)', '转矩给定时刻（起动励磁时间）')),
    Section('profiles', ("vendor profiles: each vendor's options are its module's OPTIONS "
                         "(pulab.profiles)", '厂商配置：各厂商的选项见其模块的 OPTIONS（pulab.profiles）')),
    Section('observer', ('sensorless: back-EMF observer, tracking observer and start-up (absent: '
                         'not analysed; `{}`: every default)',
                         '无感：反电势观测器、跟踪观测器与起动（不填则不分析；`{}` 取全部默认值）')),
    F('observer.bemf_f0_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=250.0,
      label=('Back-EMF observer natural frequency', '反电势观测器自然频率')),
    F('observer.bemf_damping', 'number', '', sign='>0', lo=1e-3, hi=100.0, default=1.0,
      label=('Back-EMF observer damping ζ', '反电势观测器阻尼比 ζ')),
    F('observer.tracking_f0_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=15.0,
      label=('Tracking observer (angle PLL) natural frequency', '跟踪观测器（角度锁相环）自然频率')),
    F('observer.tracking_damping', 'number', '', sign='>0', lo=1e-3, hi=100.0, default=1.0,
      label=('Tracking observer damping ζ', '跟踪观测器阻尼比 ζ')),
    F('observer.speed_filter_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=400.0,
      label=('Estimated-speed filter corner', '估算速度滤波器截止频率')),
    F('observer.startup_ramp_rpm_per_s', 'number', 'rpm/s', sign='>0', lo=1e-9, hi=1e9,
      derived='the maximum speed (60·drive.base_freq_hz/p) per second',
      label=('Open-loop start-up ramp', '开环起动斜坡')),
    F('observer.startup_current_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9,
      derived='√2·motor.rated_current_a',
      label=('Open-loop start-up current (phase peak)', '开环起动电流（相峰值）')),
    F('observer.merging_speed_rpm', 'number', 'rpm', sign='>0', lo=1e-9, hi=1e9,
      derived='ceil(0.1 × the maximum speed) (MCAT basic mode)',
      label=('Merging speed (open loop → observer)', '切换转速（开环 → 观测器）')),
    F('observer.merging_coeff_pct', 'number', '%', sign='>0', lo=1e-9, hi=1e6, default=100.0,
      label=('Merging coefficient', '切换系数')),
    F('observer.min_speed_rpm', 'number', 'rpm', sign='>0', lo=1e-9, hi=1e9,
      derived='observer.merging_speed_rpm',
      label=('Lowest closed-loop speed', '最低闭环转速')),
    F('observer.e_block_v', 'number', 'V', sign='>0', lo=1e-9, hi=1e9,
      derived='half the back-EMF (phase peak) at observer.min_speed_rpm',
      label=('Back-EMF blocking threshold (phase peak)', '反电势堵转阈值（相峰值）')),
    F('observer.snr_min', 'number', '', sign='>0', lo=1e-6, hi=1e6, default=1.0,
      label=('Required back-EMF to error ratio', '所需反电势与误差之比')),
    F('observer.r_error_pct', 'number', '%', sign='>=0', hi=1000.0,
      derived='α·(T_high − T_ref) of analysis.robust (its defaults: 53 %)',
      label=('Resistance error the observer sees', '观测器所见电阻误差')),
    F('observer.current_lsb_a', 'number', 'A', sign='>=0', hi=1e9,
      derived="board.current's A per count, else 2·√2·I_rated/4096 (12 bits)",
      label=('Current LSB', '电流 LSB')),
    F('observer.noise_a', 'number', 'A', sign='>=0', hi=1e9, default=0.0,
      label=('Current noise (the ADC, stated by you)', '电流噪声（ADC，自填）')),
    Section('analysis', ('loop analysis', '环路分析')),
    F('analysis.delay', 'choice', '', choices=('computation_pwm', 'computation', 'none'),
      default='computation_pwm',
      label=('Delay model', '延时模型')),
    F('analysis.design', 'choice', '', choices=('phase_margin', 'bandwidth'),
      default='phase_margin',
      label=('Design the current PI for', '电流 PI 设计目标')),
    F('analysis.target_phase_margin_deg', 'number', '°', sign='>0', hi=90.0, hi_open=True,
      default=60.0,
      label=('Target phase margin', '目标相位裕度')),
    F('analysis.target_bandwidth_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9,
      derived='current_loop.bandwidth_hz',
      label=('Target closed-loop bandwidth', '目标闭环带宽')),
    F('analysis.bode', 'flag', '', default=False,
      label=('Add the Bode data (loop.bode)', '加入伯德图数据（loop.bode）')),
    Section('analysis.speed', ('the speed loop (absent: not analysed)', '速度环（不填则不分析）')),
    F('analysis.speed.inertia_kg_m2', 'number', 'kg·m²', sign='>0', lo=1e-9, hi=1e9,
      default=REQUIRED,
      label=('Inertia J (motor + load)', '转动惯量 J（电机 + 负载）')),
    F('analysis.speed.friction_nm_s', 'number', 'N·m·s/rad', sign='>=0', hi=1e9, default=0.0,
      label=('Viscous friction B', '粘滞摩擦系数 B')),
    F('analysis.speed.bandwidth_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9, default=20.0,
      label=('Speed-loop natural frequency', '速度环自然频率')),
    F('analysis.speed.damping', 'number', '', sign='>0', lo=1e-3, hi=100.0, default=DAMPING,
      label=('Speed-loop damping ζ', '速度环阻尼比 ζ')),
    F('analysis.speed.filter_hz', 'number', 'Hz', sign='>0', lo=1e-9, hi=1e9,
      derived='5·analysis.speed.bandwidth_hz',
      label=('Speed-filter corner', '速度滤波器截止频率')),
    F('analysis.speed.ts_s', 'number', 's', sign='>0', lo=1e-9, hi=1.0, derived='10·drive.ts_s',
      label=('Speed-loop period', '速度环周期')),
    F('analysis.speed.current_limit_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9, derived='2·I_b',
      label=('i_q limit', 'i_q 限幅')),
    F('analysis.speed.response', 'flag', '', default=False,
      label=('Add the step and load-step responses (loop.speed.response)',
             '加入阶跃与负载阶跃响应（loop.speed.response）')),
    F('analysis.speed.step_pu', 'number', 'pu', sign='!=0', lo=-1.0, hi=1.0, default=0.1,
      label=('Speed step (pu of ω_b)', '速度阶跃（ω_b 的标幺值）')),
    F('analysis.speed.load_pu', 'number', 'pu', default=0.5,
      label=('Load step (pu of T_b)', '负载阶跃（T_b 的标幺值）')),
    Section('analysis.fw', ('above base speed: MTPA, field weakening and the voltage limit '
                            '(absent: not analysed; `{}`: every default)',
                            '基速以上：MTPA、弱磁与电压极限（不填则不分析；`{}` 取全部默认值）')),
    F('analysis.fw.current_limit_a', 'number', 'A', sign='>0', lo=1e-9, hi=1e9,
      derived='√2·motor.rated_current_a',
      label=('Current limit (phase peak)', '电流极限（相峰值）')),
    F('analysis.fw.modulation', 'name_or_number', '', lo=1e-3, hi=1.0,
      choices=('svpwm', 'spwm'), default='svpwm',
      label=('Voltage limit: svpwm U_dc/√3, spwm U_dc/2, or × U_dc (phase peak)',
             '电压极限：svpwm 为 U_dc/√3，spwm 为 U_dc/2，或 U_dc 的倍数（相峰值）')),
    F('analysis.fw.points', 'integer', '', lo=2, hi=2000, default=100,
      label=('Points of the curves', '曲线点数')),
    F('analysis.fw.table_points', 'integer', '', lo=2, hi=1024, default=8,
      label=('Breakpoints of the stored tables', '存储表的断点数')),
    F('analysis.fw.table_q', 'integer', '', lo=4, hi=15, default=15,
      label=('Q format of the generic tables (LSB = current limit/2^q)',
             '通用表的 Q 格式（LSB = 电流极限/2^q）')),
    F('analysis.fw.interpolation', 'choice', '', choices=('linear', 'step'), default='linear',
      label=('Interpolation of the generic tables', '通用表的插值方式')),
    F('analysis.fw.speed_max_rpm', 'number', 'rpm', sign='>0', lo=1e-9, hi=1e9,
      derived='1.2 × the maximum speed, or 3 × the base speed when unbounded',
      label=('Highest speed drawn', '绘制的最高转速')),
    Section('analysis.robust', ('robustness: the current loop tuned cold, run hot (absent: not '
                                'analysed; `{}`: every default)',
                                '鲁棒性：冷态整定、热态运行的电流环（不填则不分析；`{}` 取全部默认值）')),
    F('analysis.robust.temperature_c', 'pair', '°C', lo=-273.15, lo_open=True, hi=400.0,
      default=(20.0, 155.0),
      label=('[low, high] winding (and magnet) temperature', '绕组（及磁钢）温度 [低, 高]')),
    F('analysis.robust.reference_c', 'number', '°C', lo=-273.15, hi=400.0, default=20.0,
      label=('Temperature at which motor.rs_ohm and motor.bemf_v hold',
             'motor.rs_ohm 与 motor.bemf_v 对应的温度')),
    F('analysis.robust.copper_alpha_per_k', 'number', '/K', lo=0.0, hi=0.1, default=0.00393,
      label=('α of the winding: R(T) = R·(1 + α·(T − T_ref))', '绕组温度系数 α：R(T) = R·(1 + α·(T − T_ref))')),
    F('analysis.robust.magnet', 'name_or_number', '%/K', lo=-1.0, hi=1.0,
      choices=('ndfeb', 'smco', 'ferrite'), default='ndfeb',
      label=('Magnet: ndfeb (−0.12 %/K), smco (−0.035 %/K), ferrite (−0.20 %/K) or β: '
             'ψ(T) = ψ·(1 + β·(T − T_ref))',
             '磁钢：ndfeb（−0.12 %/K）、smco（−0.035 %/K）、ferrite（−0.20 %/K）或 β：'
             'ψ(T) = ψ·(1 + β·(T − T_ref))')),
    F('analysis.robust.peak_current_a', 'number', 'A', sign='>0', derived='2·motor.rated_current_a',
      label=('Peak current I_peak', '峰值电流 I_peak')),
    F('analysis.robust.inductance_drop_pct', 'number', '%', lo=0.0, hi=95.0, default=30.0,
      label=('L_d, L_q fall linearly to (1 − drop)·L at I_peak', 'L_d、L_q 在 I_peak 处线性降至 (1 − drop)·L')),
    F('analysis.robust.inductance_table', 'table', '',
      columns=(('current_a', 'A', '>=0'), ('ld_h', 'H', '>0'), ('lq_h', 'H', '>0')),
      derived='the linear drop',
      label=('L_d(i), L_q(i) points: linear between, flat beyond the ends (replaces the drop)',
             'L_d(i)、L_q(i) 数据点：点间线性插值，两端之外保持不变（取代线性下降）')),
    F('analysis.robust.udc_tolerance_pct', 'number', '%', lo=0.0, hi=90.0, default=10.0,
      label=('Bus voltage U_dc·(1 ± tol)', '母线电压 U_dc·(1 ± tol)')),
    F('analysis.robust.bus_compensated', 'flag', '', default=True,
      label=('The PWM divides by the measured U_dc (false: loop gain × U_dc/U_dc,nom)',
             'PWM 除以实测 U_dc（false：环路增益 × U_dc/U_dc,nom）')),
    F('analysis.robust.tolerance_rs_pct', 'number', '%', lo=0.0, hi=90.0, default=5.0,
      label=('Manufacturing tolerance of R_s (± %, uniform, Monte Carlo)', 'R_s 制造公差（± %，均匀分布，蒙特卡洛）')),
    F('analysis.robust.tolerance_l_pct', 'number', '%', lo=0.0, hi=90.0, default=10.0,
      label=('Manufacturing tolerance of L (± %, uniform, Monte Carlo)', 'L 制造公差（± %，均匀分布，蒙特卡洛）')),
    F('analysis.robust.tolerance_psi_pct', 'number', '%', lo=0.0, hi=90.0, default=3.0,
      label=('Manufacturing tolerance of ψ (± %, uniform, Monte Carlo)', 'ψ 制造公差（± %，均匀分布，蒙特卡洛）')),
    F('analysis.robust.samples', 'integer', '', lo=0, hi=1_000_000, default=0,
      label=('Monte Carlo samples (0 = none)', '蒙特卡洛样本数（0 = 不做）')),
    F('analysis.robust.seed', 'integer', '', lo=0, hi=2 ** 63 - 1, default=0,
      label=('Seed of random.Random', 'random.Random 的种子')),
    F('analysis.robust.min_phase_margin_deg', 'number', '°', lo=0.0, hi=90.0, default=45.0,
      label=('Phase-margin threshold', '相位裕度阈值')),
    F('analysis.robust.min_gain_margin_db', 'number', 'dB', lo=0.0, hi=60.0, default=6.0,
      label=('Gain-margin threshold', '增益裕度阈值')),
    F('analysis.robust.grid', 'integer', '', lo=2, hi=41, default=7,
      label=('Points per axis of the temperature × current map', '温度 × 电流图每轴点数')),
)

SECTIONS = {e.path: e for e in TABLE if isinstance(e, Section)}
FIELDS = tuple(e for e in TABLE if isinstance(e, Field))
FIELD = {f.path: f for f in FIELDS}


_BY_SECTION: dict = {}
for _f in FIELDS:
    _BY_SECTION.setdefault(_f.section, []).append(_f)
del _f


def section_fields(path: str) -> list:
    """The fields directly inside the section at ``path``, in table order (a new list: the
    table is read on every report, so it is grouped once)."""
    return list(_BY_SECTION.get(path, ()))


def _plain(f: Field) -> dict:
    d = f._asdict()
    d["default"] = "required" if f.default is REQUIRED else \
        list(f.default) if isinstance(f.default, tuple) else f.default
    d["choices"], d["only_with"] = list(f.choices), list(f.only_with)
    d["columns"] = [list(c) for c in f.columns]
    d["label"], d["help"] = list(f.label), list(f.help)
    return d


def schema_json() -> str:
    """The schema as JSON text (``web/src/generated/schema.json``, what the page is built from)."""
    sections = [{"path": s.path, "title": list(s.title)} for s in SECTIONS.values()]
    # the vendors panel's options (registered by the vendors): their labels, units and kinds
    options = [{"path": f.path, "label": list(f.label), "unit": f.unit, "kind": f.kind}
               for f in vendors.option_fields()]
    return json.dumps({"sections": sections, "fields": [_plain(f) for f in FIELDS],
                       "options": options, "vendors": vendors.page()},
                      ensure_ascii=False, indent=1) + "\n"


def _g(x) -> str:
    return f"{x:g}" if isinstance(x, float) else str(x)


_SIGNS = {">0": "> 0", ">=0": "≥ 0", "!=0": "≠ 0"}


def _range(f: Field) -> str:
    if f.kind == "choice":
        return ", ".join(f"`{c}`" for c in f.choices)
    if f.kind == "flag":
        return "`true`, `false`"
    if f.kind == "table":
        cols = ", ".join(f"{n} ({u}, {_SIGNS[s]})" for n, u, s in f.columns)
        return f"list of ≥ 2 rows [{cols}], {f.columns[0][0]} increasing"
    if f.kind == "text":
        return f"text, ≤ {_g(f.hi)} characters"
    if f.kind == "object":
        return "object"
    if f.kind == "name_or_number":
        return ", ".join(f"`{c}`" for c in f.choices) + f" or a number, {f.unit}, {_g(f.lo)}..{_g(f.hi)}"
    if f.kind == "pair":
        lo = f"{_g(f.lo)} <" if f.lo_open else f"{_g(f.lo)} ≤"
        return f"[low, high], {f.unit}, {lo} low ≤ high ≤ {_g(f.hi)}"
    parts = [f.unit] if f.unit else []
    if f.kind == "integer":
        parts.append(f"integer {_g(f.lo)}..{_g(f.hi)}")
        return ", ".join(parts)
    parts.append(_SIGNS.get(f.sign, "finite"))
    if f.lo is not None or f.hi is not None:
        lo = _g(f.lo) if f.lo is not None else ""
        if lo and f.hi is None:
            parts.append(f"> {lo}" if f.lo_open else f"≥ {lo}")
        else:
            parts.append(f"{lo}..{_g(f.hi)}" + (" (excl.)" if f.hi_open else "") if lo else
                         f"< {_g(f.hi)}" if f.hi_open else f"≤ {_g(f.hi)}")
    return ", ".join(parts)


def _default(f: Field) -> str:
    if f.default is REQUIRED:
        text = "required" + (f"; {f.derived}" if f.derived else "")
    elif f.default is None:
        text = f.derived or "absent"
    elif isinstance(f.default, bool):
        text = "`true`" if f.default else "`false`"
    elif isinstance(f.default, str):
        text = f"`{f.default}`"
    elif isinstance(f.default, tuple):
        text = f"[{', '.join(_g(x) for x in f.default)}]"
    else:
        text = "1/√2" if f.default == DAMPING else _g(f.default)
    if f.only_with:
        text += f" (only with {f.only_with[0]} = `{f.only_with[1]}`)"
    return text


def markdown() -> str:
    """The input tables of docs/contract.md, one per section (``tests/py/test_schema.py``
    checks the contract against this text)."""
    out = []
    for sec in SECTIONS.values():
        fields = section_fields(sec.path)
        out.append(f"**`{sec.path}`** — {sec.title[0]}\n")
        if not fields:
            out.append("Its fields are in the sections below it." if sec.path == "sim" else
                       "Documented under Vendor profiles.")
            out.append("")
            continue
        out.append("| field | meaning | type, unit, range | default |\n|---|---|---|---|")
        for f in fields:
            out.append(f"| {f.path} | {f.label[0] or '—'} | {_range(f)} | {_default(f)} |")
        out.append("")
    return "\n".join(out)
