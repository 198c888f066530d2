// The input form: one element per field of the CLI input, `name` = its JSON path.
import type { UnitId } from './units';
import type { Input } from './state';
import type { Key } from './i18n';

export interface FieldSpec {
  path: string;
  kind: 'number' | 'int' | 'select' | 'bool';
  /** Unit shown when there is no choice. */
  unit?: string;
  /** Display-unit choices (first = default). */
  units?: UnitId[];
  options?: string[];
  /** Report path whose value is the placeholder when the field is empty (derived/default). */
  placeholderFrom?: string;
  /** Optional: empty means "absent" (default or derived). */
  optional?: boolean;
  enabled?: (inp: Input) => boolean;
}

export interface SectionSpec {
  id: string;
  title: Key;
  hint?: Key;
  fields: FieldSpec[];
  collapsed?: boolean;
}

const conv = (inp: Input, k: string): unknown => inp.conventions?.[k];
const loop = (inp: Input): string => String(inp.current_loop?.method ?? 'bandwidth');
const design = (inp: Input): string => String(inp.analysis?.design ?? 'phase_margin');

export const RAW_NAMES = ['Voltage', 'Current', 'FullFreq01', 'FreqRated01', 'RsPm', 'LD', 'LQ', 'BemfVolt', 'uDCFilter'];
const RAW_UNIT: Record<string, string> = {
  Voltage: '1 V', Current: '0.01 A', FullFreq01: '0.01 Hz', FreqRated01: '0.01 Hz', RsPm: 'mΩ', LD: 'LSB', LQ: 'LSB', BemfVolt: '0.1 V', uDCFilter: '0.1 V',
};

export const SECTIONS: SectionSpec[] = [
  {
    id: 'motor', title: 'sec_motor', fields: [
      // Empty = derived from the datasheet section (placeholder: the derived value).
      { path: 'motor.rated_voltage_v', kind: 'number', unit: 'V', optional: true, placeholderFrom: 'input.motor.rated_voltage_v' },
      { path: 'motor.rated_current_a', kind: 'number', unit: 'A' },
      { path: 'motor.rated_freq_hz', kind: 'number', unit: 'Hz', optional: true, placeholderFrom: 'input.motor.rated_freq_hz' },
      { path: 'motor.rs_ohm', kind: 'number', unit: 'Ω', optional: true, placeholderFrom: 'input.motor.rs_ohm' },
      { path: 'motor.ld_h', kind: 'number', units: ['µH', 'mH', 'H'], optional: true, placeholderFrom: 'input.motor.ld_h' },
      { path: 'motor.lq_h', kind: 'number', units: ['µH', 'mH', 'H'], optional: true, placeholderFrom: 'input.motor.lq_h' },
      { path: 'motor.bemf_v', kind: 'number', unit: 'V', optional: true, placeholderFrom: 'input.motor.bemf_v' },
      { path: 'motor.pole_pairs', kind: 'int' },
    ],
  },
  {
    // pulab.model.datasheet: what datasheets print; each value fills a motor field left empty.
    id: 'datasheet', title: 'sec_datasheet', hint: 'datasheetHint', collapsed: true, fields: [
      { path: 'datasheet.speed_rpm', kind: 'number', unit: 'rpm', optional: true },
      { path: 'datasheet.ke_v_per_krpm', kind: 'number', unit: 'V/krpm', optional: true },
      { path: 'datasheet.ke_v_s_per_rad', kind: 'number', unit: 'V·s/rad', optional: true },
      { path: 'datasheet.ke_measure', kind: 'select', options: ['', 'rms', 'peak'], optional: true },
      { path: 'datasheet.kt_nm_per_a', kind: 'number', unit: 'N·m/A', optional: true },
      { path: 'datasheet.kt_current', kind: 'select', options: ['', 'rms', 'peak'], optional: true },
      { path: 'datasheet.psi_wb', kind: 'number', unit: 'Wb', optional: true },
      { path: 'datasheet.rs_line_ohm', kind: 'number', unit: 'Ω', optional: true },
      { path: 'datasheet.l_line_h', kind: 'number', units: ['mH', 'µH', 'H'], optional: true },
      { path: 'datasheet.ld_line_h', kind: 'number', units: ['mH', 'µH', 'H'], optional: true },
      { path: 'datasheet.lq_line_h', kind: 'number', units: ['mH', 'µH', 'H'], optional: true },
      { path: 'datasheet.winding', kind: 'select', options: ['', 'star', 'delta'], optional: true },
      { path: 'datasheet.dc_bus_v', kind: 'number', unit: 'V', optional: true },
    ],
  },
  {
    id: 'drive', title: 'sec_drive', fields: [
      { path: 'drive.base_freq_hz', kind: 'number', unit: 'Hz', optional: true, placeholderFrom: 'base.f_b' },
      { path: 'drive.udc_v', kind: 'number', unit: 'V' },
      { path: 'drive.ts_s', kind: 'number', units: ['µs', 'kHz', 's'] },
    ],
  },
  {
    id: 'conventions', title: 'sec_conventions', fields: [
      { path: 'conventions.base', kind: 'select', options: ['rms', 'peak', 'custom'] },
      { path: 'conventions.base_voltage_v', kind: 'number', unit: 'V', optional: true, enabled: (i) => conv(i, 'base') === 'custom' },
      { path: 'conventions.base_current_a', kind: 'number', unit: 'A', optional: true, enabled: (i) => conv(i, 'base') === 'custom' },
      { path: 'conventions.angle_base', kind: 'select', options: ['pi', '2pi'] },
      { path: 'conventions.inductance_unit', kind: 'select', options: ['10uH', 'uH'] },
    ],
  },
  {
    id: 'current_loop', title: 'sec_current_loop', fields: [
      { path: 'current_loop.method', kind: 'select', options: ['bandwidth', 'damping', 'manual', 'integers'] },
      { path: 'current_loop.bandwidth_hz', kind: 'number', unit: 'Hz', optional: true, enabled: (i) => loop(i) === 'bandwidth' || loop(i) === 'damping' },
      { path: 'current_loop.damping', kind: 'number', optional: true, enabled: (i) => loop(i) === 'damping' },
      { path: 'current_loop.kp', kind: 'number', unit: 'Ω', optional: true, enabled: (i) => loop(i) === 'manual', placeholderFrom: 'current_pi.d.kp' },
      { path: 'current_loop.ki', kind: 'number', unit: 'Ω/s', optional: true, enabled: (i) => loop(i) === 'manual', placeholderFrom: 'current_pi.d.ki' },
      { path: 'current_loop.pm_kp', kind: 'int', unit: 'Q12', optional: true, enabled: (i) => loop(i) === 'integers', placeholderFrom: 'current_pi.d.pm_kp' },
      { path: 'current_loop.pm_ki', kind: 'int', unit: 'Q16', optional: true, enabled: (i) => loop(i) === 'integers', placeholderFrom: 'current_pi.d.pm_ki' },
    ],
  },
  {
    id: 'pll', title: 'sec_pll', fields: [
      { path: 'pll.bandwidth_hz', kind: 'number', unit: 'Hz', optional: true },
      { path: 'pll.damping', kind: 'number', optional: true },
    ],
  },
  {
    id: 'raw', title: 'sec_raw', hint: 'rawHint', collapsed: true,
    fields: RAW_NAMES.map((n) => ({ path: `raw.${n}`, kind: 'int' as const, unit: RAW_UNIT[n], optional: true, placeholderFrom: `vendor.raw.${n}` })),
  },
  {
    id: 'sim.current', title: 'sec_sim_current', collapsed: true, fields: [
      { path: 'sim.current.axis', kind: 'select', options: ['d', 'q'] },
      { path: 'sim.current.step_a', kind: 'number', unit: 'A', optional: true },
      { path: 'sim.current.duration_s', kind: 'number', units: ['ms', 's'], optional: true },
      { path: 'sim.current.speed_hz', kind: 'number', unit: 'Hz', optional: true },
      { path: 'sim.current.delay', kind: 'bool' },
    ],
  },
  {
    id: 'sim.pll', title: 'sec_sim_pll', collapsed: true, fields: [
      { path: 'sim.pll.speed_hz', kind: 'number', unit: 'Hz', optional: true },
      { path: 'sim.pll.angle_step_deg', kind: 'number', unit: '°', optional: true },
      { path: 'sim.pll.ramp_hz_per_s', kind: 'number', unit: 'Hz/s', optional: true },
      { path: 'sim.pll.duration_s', kind: 'number', units: ['ms', 's'], optional: true },
    ],
  },
  {
    id: 'analysis', title: 'sec_analysis', collapsed: true, fields: [
      { path: 'analysis.delay', kind: 'select', options: ['computation_pwm', 'computation', 'none'] },
      { path: 'analysis.design', kind: 'select', options: ['phase_margin', 'bandwidth'] },
      { path: 'analysis.target_phase_margin_deg', kind: 'number', unit: '°', optional: true, enabled: (i) => design(i) === 'phase_margin' },
      { path: 'analysis.target_bandwidth_hz', kind: 'number', unit: 'Hz', optional: true, enabled: (i) => design(i) === 'bandwidth', placeholderFrom: 'current_pi.bandwidth_hz' },
    ],
  },
  {
    id: 'analysis.speed', title: 'sec_speed', collapsed: true, fields: [
      { path: 'analysis.speed.inertia_kg_m2', kind: 'number', unit: 'kg·m²' },
      { path: 'analysis.speed.friction_nm_s', kind: 'number', unit: 'N·m·s/rad', optional: true },
      { path: 'analysis.speed.bandwidth_hz', kind: 'number', unit: 'Hz', optional: true },
      { path: 'analysis.speed.damping', kind: 'number', optional: true },
      { path: 'analysis.speed.filter_hz', kind: 'number', unit: 'Hz', optional: true },
      { path: 'analysis.speed.ts_s', kind: 'number', units: ['µs', 'kHz', 's'], optional: true },
      { path: 'analysis.speed.current_limit_a', kind: 'number', unit: 'A', optional: true },
      { path: 'analysis.speed.step_pu', kind: 'number', unit: 'pu', optional: true },
      { path: 'analysis.speed.load_pu', kind: 'number', unit: 'pu', optional: true },
    ],
  },
];

export const ALL_FIELDS: FieldSpec[] = SECTIONS.flatMap((s) => s.fields);

/** The input without the values of disabled fields (what is sent, shared and stored). */
export function effectiveInput(inp: Input): Input {
  const out = JSON.parse(JSON.stringify(inp)) as Input;
  for (const f of ALL_FIELDS) {
    if (f.enabled && !f.enabled(inp)) {
      const [s, ...rest] = f.path.split('.');
      if (rest.length === 1 && out[s]) delete out[s][rest[0]];
    }
  }
  for (const [k, v] of Object.entries(out)) if (k !== 'sim' && v && typeof v === 'object' && Object.keys(v).length === 0) delete out[k];
  return out;
}
