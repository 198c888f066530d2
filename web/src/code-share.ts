// The "Your code" panel's state without DOM: reading and writing it in the URL's query
// (?code=…&target=…&vs=…&entry=…&set.NAME=…, beside #in= which keeps the motor), the trace request,
// and the inputs prefilled from the report's integers.
import type { TraceLine } from './generated/api-types';

export interface CodeState {
  code: string;
  target: string;
  /** Second target to compare with, or '' for none. */
  vs: string;
  /** Input values the user typed (text, sent as is: pulab checks them). */
  set: Record<string, string>;
  /** The function of the code to run, or '' for the statements outside functions. */
  entry?: string;
}

export const DEFAULT_TARGET = 'c28x';
export const DEFAULT_VS = 'arm';

/** The panel's state from `location.search`; null when the URL carries no code. */
export function codeStateFromSearch(search: string): CodeState | null {
  const p = new URLSearchParams(search);
  const code = p.get('code');
  if (code === null) return null;
  const set: Record<string, string> = {};
  for (const [k, v] of p) if (k.startsWith('set.') && k.length > 4) set[k.slice(4)] = v;
  return { code, target: p.get('target') ?? DEFAULT_TARGET, vs: p.get('vs') ?? DEFAULT_VS, set, entry: p.get('entry') ?? '' };
}

/** The query string that reproduces `s` (with `embed=code` when asked). */
export function codeSearch(s: CodeState, embed = false): string {
  const p = new URLSearchParams();
  if (embed) p.set('embed', 'code');
  p.set('code', s.code);
  p.set('target', s.target);
  p.set('vs', s.vs);
  if (s.entry) p.set('entry', s.entry);
  for (const [k, v] of Object.entries(s.set)) if (v.trim() !== '') p.set(`set.${k}`, v);
  return `?${p.toString()}`;
}

/** Firmware variable names (seed 1.4, 2.2) → their integer in the report. */
export const FIRMWARE_NAMES: Record<string, string> = {
  'gMotorExtPer.Rpm': 'vendor.Rpm.value', 'gMotorExtPer.LD': 'vendor.LD.value', 'gMotorExtPer.LQ': 'vendor.LQ.value',
  'gMotorInfo.FreqPer': 'vendor.FreqPer.value', 'gMotorExtPer.FluxRotor': 'vendor.FluxRotor.value',
  pm_maxout_vol: 'vendor.pm_maxout_vol.value', maxu: 'vendor.maxu.value',
  pm_kp_d: 'current_pi.d.pm_kp', pm_ki_d: 'current_pi.d.pm_ki', pm_kp_q: 'current_pi.q.pm_kp', pm_ki_q: 'current_pi.q.pm_ki',
  pm_error_id: 'current_pi.step_example.error', pm_integral_d: 'current_pi.step_example.integral',
};

function at(report: unknown, path: string): number | undefined {
  let v: unknown = report;
  for (const k of path.split('.')) {
    if (v === null || typeof v !== 'object' || !Object.prototype.hasOwnProperty.call(v, k)) return undefined;
    v = (v as Record<string, unknown>)[k];
  }
  return typeof v === 'number' && Number.isInteger(v) ? v : undefined;
}

/**
 * The report's integer for each input, with its JSON path: a firmware name of FIRMWARE_NAMES,
 * else a raw input by the name's last part (gMotorInfo.Voltage, p->Voltage → raw.Voltage).
 */
export function prefill(inputs: string[], report: unknown): Record<string, { value: number; source: string }> {
  const out: Record<string, { value: number; source: string }> = {};
  for (const name of inputs) {
    const own = Object.prototype.hasOwnProperty.call(FIRMWARE_NAMES, name) ? FIRMWARE_NAMES[name] : undefined;
    const paths = [own, `vendor.raw.${name.split(/\.|->/).pop() ?? name}`].filter((p): p is string => p !== undefined);
    for (const source of paths) {
      const value = at(report, source);
      if (value !== undefined) {
        out[name] = { value, source };
        break;
      }
    }
  }
  return out;
}

/** The request of the trace kind of pulab.api.call_json: typed values win over the report's. */
export function traceRequest(s: CodeState, target: string, inputs: string[], report: unknown): { code: string; target: string; set: Record<string, string | number>; entry?: string } {
  const set: Record<string, string | number> = {};
  const fromReport = prefill(inputs, report);
  for (const name of inputs) {
    const typed = s.set[name];
    if (typed !== undefined && typed.trim() !== '') set[name] = typed.trim();
    else if (name in fromReport) set[name] = fromReport[name].value;
  }
  return s.entry ? { code: s.code, target, set, entry: s.entry } : { code: s.code, target, set };
}

/** The steps (paired as the steps table pairs them: same statement at the same place) whose value
 * or one of whose terms' values differs between two traces: a final state can agree while an
 * intermediate result does not. */
export function differingSteps(a: TraceLine[], b: TraceLine[] | undefined): TraceLine[] {
  if (!b) return [];
  return a.filter((x, i) => {
    const y = b[i];
    if (!y || y.code !== x.code || y.line !== x.line || y.column !== x.column) return false;
    return y.value !== x.value || x.terms.some((tm, j) => y.terms[j]?.expr === tm.expr && y.terms[j].value !== tm.value);
  });
}

/** Names of the variables whose final values differ between two traces' `vars`. */
export function differingVars(a: Record<string, { value: number | null }>, b: Record<string, { value: number | null }> | undefined): string[] {
  if (!b) return [];
  return Object.keys(a).filter((k) => k in b && a[k].value !== b[k].value);
}
