// The golden files' comparison rule, shared by the suites whose oracle states it in each file
// ("compare": a relative tolerance, absolute floors by path, paths skipped, angles compared
// modulo 2π): floats within it, everything else (keys, lengths, integers, strings, null) exact.
export type J = null | boolean | number | string | J[] | { [k: string]: J };
export interface Rules {
  rel: number;
  abs: Record<string, number>;
  skip: string[];
  wrapped: string[];
}

/** fnmatch-style pattern (only `*`, which also matches dots) as a RegExp. */
const glob = (p: string): RegExp =>
  new RegExp(`^${p.split('*').map((s) => s.replace(/[.+?^${}()|[\]\\]/g, '\\$&')).join('.*')}$`);
const matches = (path: string, patterns: string[]): boolean => patterns.some((p) => glob(p).test(path));
/** Python's math.remainder(x, 2π): the angle difference folded into [−π, π]. */
const wrapAngle = (x: number): number => x - 2 * Math.PI * Math.round(x / (2 * Math.PI));

export function compare(got: J, exp: J, path: string, rules: Rules, bad: string[]): void {
  if (matches(path, rules.skip)) return;
  if (Array.isArray(exp)) {
    if (!Array.isArray(got) || got.length !== exp.length) {
      bad.push(`${path}: length ${Array.isArray(got) ? got.length : typeof got} != ${exp.length}`);
      return;
    }
    const e = exp as number[];
    const g = got as number[];
    const scale = Math.max(0, ...e.map(Math.abs)) || 1;
    const wrapped = matches(path, rules.wrapped);
    const d = Math.max(...e.map((x, k) => Math.abs(wrapped ? wrapAngle(g[k] - x) : g[k] - x)));
    if (!(d <= rules.rel * scale)) bad.push(`${path}: max |Δ| ${d} > ${rules.rel}·${scale}`);
  } else if (exp !== null && typeof exp === 'object') {
    if (got === null || typeof got !== 'object' || Array.isArray(got)) {
      bad.push(`${path}: not an object`);
      return;
    }
    const gk = Object.keys(got).sort().join(',');
    const ek = Object.keys(exp).sort().join(',');
    if (gk !== ek) {
      bad.push(`${path}: keys ${gk} != ${ek}`);
      return;
    }
    for (const k of Object.keys(exp)) compare(got[k], exp[k], path ? `${path}.${k}` : k, rules, bad);
  } else if (typeof exp === 'number' && typeof got === 'number') {
    const floor = Math.max(0, ...Object.entries(rules.abs).filter(([p]) => glob(p).test(path)).map(([, v]) => v));
    if (!(Math.abs(got - exp) <= rules.rel * Math.max(Math.abs(got), Math.abs(exp)) + floor)) {
      bad.push(`${path}: ${got} != ${exp}`);
    }
  } else if (got !== exp) {
    bad.push(`${path}: ${JSON.stringify(got)} != ${JSON.stringify(exp)}`);
  }
}
