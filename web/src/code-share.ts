// The "Your code" panel's state without DOM: reading and writing it in the URL's query
// (?code=…&target=…&vs=…&set.NAME=…, beside #in= which keeps the motor), the trace request,
// and the inputs prefilled from the report's raw integers.

export interface CodeState {
  code: string;
  target: string;
  /** Second target to compare with, or '' for none. */
  vs: string;
  /** Input values the user typed (text, sent as is: pulab checks them). */
  set: Record<string, string>;
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
  return { code, target: p.get('target') ?? DEFAULT_TARGET, vs: p.get('vs') ?? DEFAULT_VS, set };
}

/** The query string that reproduces `s` (with `embed=code` when asked). */
export function codeSearch(s: CodeState, embed = false): string {
  const p = new URLSearchParams();
  if (embed) p.set('embed', 'code');
  p.set('code', s.code);
  p.set('target', s.target);
  p.set('vs', s.vs);
  for (const [k, v] of Object.entries(s.set)) if (v.trim() !== '') p.set(`set.${k}`, v);
  return `?${p.toString()}`;
}

/** The report's raw integer for each input whose last name part matches (gMotorInfo.Voltage → Voltage). */
export function prefill(inputs: string[], raw: Record<string, number> | undefined): Record<string, number> {
  const out: Record<string, number> = {};
  if (!raw) return out;
  for (const name of inputs) {
    const last = name.split(/\.|->/).pop() ?? name;
    if (Object.prototype.hasOwnProperty.call(raw, last) && typeof raw[last] === 'number') out[name] = raw[last];
  }
  return out;
}

/** The request for pulab.api.trace_json: typed values win over the report's. */
export function traceRequest(s: CodeState, target: string, inputs: string[], raw: Record<string, number> | undefined): { code: string; target: string; set: Record<string, string | number> } {
  const set: Record<string, string | number> = {};
  const fromReport = prefill(inputs, raw);
  for (const name of inputs) {
    const typed = s.set[name];
    if (typed !== undefined && typed.trim() !== '') set[name] = typed.trim();
    else if (name in fromReport) set[name] = fromReport[name];
  }
  return { code: s.code, target, set };
}

/** Names of the variables whose final values differ between two traces' `vars`. */
export function differingVars(a: Record<string, { value: number | null }>, b: Record<string, { value: number | null }> | undefined): string[] {
  if (!b) return [];
  return Object.keys(a).filter((k) => k in b && a[k].value !== b[k].value);
}
