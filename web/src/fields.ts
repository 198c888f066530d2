// The input form: one element per field of the CLI input, `name` = its JSON path. The fields, their
// kinds, units, choices, labels and when they apply come from pulab's input schema
// (generated/schema.json, written by the build from py/pulab/schema/fields.py); this file adds only
// what the page alone knows (display units, placeholders, section layout).
import schema from './generated/schema.json';
import type { UnitId } from './units';
import type { Input } from './json';
import type { Key } from './i18n';

export interface FieldSpec {
  path: string;
  /** 'text' and 'object' only outside the form (sim.current.code: set by the Code view). */
  kind: 'number' | 'int' | 'select' | 'bool' | 'text' | 'object';
  /** English and Chinese label. */
  label: [string, string];
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

/** One field of pulab's input schema (py/pulab/schema/fields.py, written here by the build). */
interface SchemaField {
  path: string;
  kind: string;
  unit: string;
  default: unknown;
  derived: string;
  choices: string[];
  only_with: string[];
  /** English, Chinese. */
  label: string[];
}

const FIELDS: SchemaField[] = schema.fields;
const KIND: Record<string, FieldSpec['kind']> = { number: 'number', integer: 'int', choice: 'select', flag: 'bool', text: 'text', object: 'object' };

const value = (inp: Input, path: string): unknown => {
  const [s, ...rest] = path.split('.');
  let v: unknown = inp[s];
  for (const k of rest) v = v && typeof v === 'object' ? (v as Record<string, unknown>)[k] : undefined;
  return v;
};
const loop = (inp: Input): string => String(inp.current_loop?.method ?? 'bandwidth');
const design = (inp: Input): string => String(inp.analysis?.design ?? 'phase_margin');

/** What only the page knows about a field: display units, the report value shown when empty, and
 * when it is greyed out beyond the schema's own `only_with`. */
/** Every inductance field offers the same units in the same order: the form shows one unit for all. */
const L_UNITS: UnitId[] = ['µH', 'mH', 'H'];
/** Resistances likewise; Ω first, as links handed out before mΩ existed meant Ω. */
const R_UNITS: UnitId[] = ['Ω', 'mΩ'];
const PAGE: Record<string, Partial<FieldSpec>> = {
  'motor.rated_voltage_v': { placeholderFrom: 'input.motor.rated_voltage_v' },
  'motor.rated_freq_hz': { placeholderFrom: 'input.motor.rated_freq_hz' },
  'motor.rs_ohm': { units: R_UNITS, placeholderFrom: 'input.motor.rs_ohm' },
  'motor.ld_h': { units: L_UNITS, placeholderFrom: 'input.motor.ld_h' },
  'motor.lq_h': { units: L_UNITS, placeholderFrom: 'input.motor.lq_h' },
  'motor.bemf_v': { placeholderFrom: 'input.motor.bemf_v' },
  'motor.rr_ohm': { units: R_UNITS },
  'motor.lm_h': { units: L_UNITS },
  'motor.lls_h': { units: L_UNITS },
  'motor.llr_h': { units: L_UNITS },
  'motor.ls_h': { units: L_UNITS },
  'motor.lr_h': { units: L_UNITS },
  // checked against motor.kind in code (the schema's only_with stays within a section)
  'datasheet.lms_h': { units: L_UNITS, enabled: (i) => String(i.motor?.kind ?? 'pmsm') === 'acim' },
  'datasheet.ke_v_per_krpm': { units: ['V/krpm', 'V/rpm'] },
  'datasheet.rs_line_ohm': { units: R_UNITS },
  'datasheet.rs_phase_ohm': { units: R_UNITS },
  'datasheet.l_line_h': { units: L_UNITS },
  'datasheet.ld_line_h': { units: L_UNITS },
  'datasheet.lq_line_h': { units: L_UNITS },
  'datasheet.l_phase_h': { units: L_UNITS },
  'datasheet.ld_phase_h': { units: L_UNITS },
  'datasheet.lq_phase_h': { units: L_UNITS },
  'drive.base_freq_hz': { placeholderFrom: 'base.f_b' },
  // from the datasheet's DC bus when not typed: the bus every voltage limit is graded against
  'drive.udc_v': { placeholderFrom: 'input.drive.udc_v' },
  'drive.ts_s': { units: ['µs', 'kHz', 's'] },
  'current_loop.bandwidth_hz': { enabled: (i) => loop(i) === 'bandwidth' || loop(i) === 'damping' },
  'current_loop.damping': { enabled: (i) => loop(i) === 'damping' },
  'current_loop.kp': { placeholderFrom: 'current_pi.d.kp' },
  'current_loop.ki': { placeholderFrom: 'current_pi.d.ki' },
  'current_loop.pm_kp': { placeholderFrom: 'current_pi.d.pm_kp' },
  'current_loop.pm_ki': { placeholderFrom: 'current_pi.d.pm_ki' },
  'sim.current.duration_s': { units: ['ms', 's'] },
  'sim.pll.duration_s': { units: ['ms', 's'] },
  // an induction motor's flux build-up (pulab refuses sim.flux for a PMSM)
  'sim.flux.duration_s': { units: ['ms', 's'], enabled: (i) => value(i, 'motor.kind') === 'acim' },
  'sim.flux.startup_s': { units: ['ms', 's'], enabled: (i) => value(i, 'motor.kind') === 'acim' },
  'analysis.target_phase_margin_deg': { enabled: (i) => design(i) === 'phase_margin' },
  'analysis.target_bandwidth_hz': { enabled: (i) => design(i) === 'bandwidth', placeholderFrom: 'current_pi.bandwidth_hz' },
  'analysis.speed.ts_s': { units: ['µs', 'kHz', 's'] },
  'board.current.shunt_ohm': { units: ['mΩ', 'Ω'] },
  'board.bus.r_top_ohm': { units: ['kΩ', 'Ω'] },
  'board.bus.r_bottom_ohm': { units: ['kΩ', 'Ω'] },
  'board.pwm.deadtime_s': { units: ['ns', 'µs', 's'] },
};
/** The fields that share a display unit with `f` (inductances, resistances: one choice for the
 * motor and the datasheet). */
export function unitSiblings(f: FieldSpec): FieldSpec[] {
  return f.units === L_UNITS || f.units === R_UNITS ? ALL_FIELDS.filter((g) => g.units === f.units) : [f];
}
/** Set by panels, or only in the JSON (the modulation: a choice or a number), not typed into the form. */
const NOT_IN_FORM = new Set(['analysis.bode', 'analysis.speed.response', 'analysis.fw.modulation']);
// A field renamed or removed in the schema must not leave page settings behind (fails the build).
for (const p of [...Object.keys(PAGE), ...NOT_IN_FORM]) {
  if (!FIELDS.some((f) => f.path === p)) throw new Error(`web/src/fields.ts: ${p} is not in the input schema`);
}

function spec(f: SchemaField, emptyChoice: boolean): FieldSpec {
  const page = PAGE[f.path] ?? {};
  const kind = KIND[f.kind];
  if (!kind) throw new Error(`schema field ${f.path}: unknown kind ${f.kind}`);
  const out: FieldSpec = { path: f.path, kind, label: [f.label[0], f.label[1]] };
  if (f.unit && !page.units) out.unit = f.unit;
  if (f.kind === 'choice') {
    const rest = f.choices.filter((c) => c !== f.default);
    out.options = emptyChoice ? ['', ...f.choices] : f.default === null ? f.choices : [String(f.default), ...rest];
  }
  if (f.default !== 'required' || f.derived || f.only_with.length > 0) out.optional = true;
  if (f.only_with.length > 0) {
    const [on, want] = f.only_with;
    out.enabled = (inp) => String(value(inp, on) ?? FIELDS.find((x) => x.path === on)?.default) === want;
  }
  if (f.path.startsWith('raw.')) out.placeholderFrom = `vendor.${f.path}`;
  return { ...out, ...page };
}

/** The form's sections, in the page's order: each shows its schema section's fields. */
const LAYOUT: Omit<SectionSpec, 'fields'>[] = [
  { id: 'motor', title: 'sec_motor' },
  { id: 'datasheet', title: 'sec_datasheet', hint: 'datasheetHint', collapsed: true },
  { id: 'drive', title: 'sec_drive' },
  { id: 'conventions', title: 'sec_conventions' },
  { id: 'current_loop', title: 'sec_current_loop' },
  { id: 'pll', title: 'sec_pll' },
  { id: 'raw', title: 'sec_raw', hint: 'rawHint', collapsed: true },
  { id: 'board.current', title: 'sec_board_current', hint: 'boardHint', collapsed: true },
  { id: 'board.bus', title: 'sec_board_bus', collapsed: true },
  { id: 'board.pwm', title: 'sec_board_pwm', collapsed: true },
  { id: 'sim.current', title: 'sec_sim_current', collapsed: true },
  { id: 'sim.pll', title: 'sec_sim_pll', collapsed: true },
  { id: 'sim.flux', title: 'sec_sim_flux', collapsed: true },
  { id: 'analysis', title: 'sec_analysis', collapsed: true },
  { id: 'analysis.speed', title: 'sec_speed', collapsed: true },
  { id: 'analysis.fw', title: 'sec_fw', collapsed: true },
  { id: 'observer', title: 'sec_observer', collapsed: true },
];

export const SECTIONS: SectionSpec[] = LAYOUT.map((s) => ({
  ...s,
  // A datasheet value is given or not: its choices start with "not given".
  fields: FIELDS.filter((f) => f.path.slice(0, f.path.lastIndexOf('.')) === s.id && !NOT_IN_FORM.has(f.path))
    .map((f) => spec(f, s.id === 'datasheet')),
}));

/** A field's label in the page's language. */
export function fieldLabel(f: FieldSpec, lang: 'en' | 'zh'): string {
  return f.label[lang === 'zh' ? 1 : 0];
}

export const ALL_FIELDS: FieldSpec[] = SECTIONS.flatMap((s) => s.fields);

/** Your routine in the current loop (sim.current.code): filled by the Code view's "Use in the loop",
 * kept in links and storage, not in the form. */
export const LOOP_PATH = 'sim.current.code';
export const LOOP_FIELDS: FieldSpec[] = FIELDS.filter((f) => f.path.startsWith(`${LOOP_PATH}.`)).map((f) => spec(f, false));

/** The SI unit of an input path as pulab reads it ('' for a count or a raw integer). */
export function siUnit(path: string): string {
  return FIELDS.find((f) => f.path === path)?.unit ?? '';
}

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
