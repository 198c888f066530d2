// Golden simulation trajectories (tests/golden/sim/*.json, independent numpy oracle) through
// pulab.api.run_json in Pyodide/Node, with each file's own comparison rules (as tests/py/test_sim.py).
import { describe, it, expect, beforeAll } from 'vitest';
import { existsSync, readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { dump, parseJsonExact, type JVal } from './json-exact';

const DIR = fileURLToPath(new URL('../golden/sim/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

interface Rules {
  rel: number;
  abs: Record<string, number>;
  skip: string[];
  wrapped: string[];
}
/** fnmatchcase: '*' any run of characters (dots included), '?' one character. */
const glob = (p: string): RegExp => new RegExp(`^${p.replace(/[.+^${}()|[\]\\]/g, '\\$&').replace(/\*/g, '.*').replace(/\?/g, '.')}$`);
const match = (path: string, pats: string[]): boolean => pats.some((p) => glob(p).test(path));
const num = (x: JVal): number => (typeof x === 'bigint' ? Number(x) : (x as number));
/** math.remainder(x, 2π): the representative in [−π, π]. */
const rem2pi = (x: number): number => x - 2 * Math.PI * Math.round(x / (2 * Math.PI));

export function compareSim(got: JVal, exp: JVal, path: string, r: Rules, bad: string[]): void {
  if (match(path, r.skip)) return;
  if (exp !== null && typeof exp === 'object' && !Array.isArray(exp)) {
    const g = got as Record<string, JVal>;
    const ek = Object.keys(exp).sort();
    const gk = g && typeof g === 'object' ? Object.keys(g).sort() : [];
    if (JSON.stringify(ek) !== JSON.stringify(gk)) return void bad.push(`${path}: keys ${gk} vs ${ek}`);
    for (const k of ek) compareSim(g[k], (exp as Record<string, JVal>)[k], path ? `${path}.${k}` : k, r, bad);
  } else if (Array.isArray(exp)) {
    const g = got as JVal[];
    if (!Array.isArray(g) || g.length !== exp.length) return void bad.push(`${path}: length ${g?.length} != ${exp.length}`);
    const scale = Math.max(0, ...exp.map((x) => Math.abs(num(x)))) || 1;
    const wrapped = match(path, r.wrapped);
    let d = 0;
    exp.forEach((e, i) => {
      const diff = num(g[i]) - num(e);
      d = Math.max(d, Math.abs(wrapped ? rem2pi(diff) : diff));
    });
    if (!(d <= r.rel * scale)) bad.push(`${path}: max |Δ| ${d} > ${r.rel}·${scale}`);
  } else if (typeof exp === 'number' && (typeof got === 'number' || typeof got === 'bigint')) {
    const floor = Math.max(0, ...Object.entries(r.abs).filter(([p]) => glob(p).test(path)).map(([, v]) => v));
    const g = num(got);
    if (!(Math.abs(g - exp) <= r.rel * Math.max(Math.abs(g), Math.abs(exp)) + floor)) bad.push(`${path}: ${g} != ${exp}`);
  } else if (got !== exp) bad.push(`${path}: ${String(got)} != ${String(exp)}`);
}

let p: NodePulab;
beforeAll(async () => {
  p = await bootPulab();
});

describe.skipIf(files.length === 0)('golden simulation trajectories through Pyodide', () => {
  for (const f of files) {
    it(f, () => {
      const c = parseJsonExact(readFileSync(join(DIR, f), 'utf8')) as Record<string, JVal>;
      const rules = JSON.parse(dump(c.compare)) as Rules;
      const out = parseJsonExact(p.raw('report', dump(c.input))) as Record<string, JVal>;
      expect(out.ok, dump(out).slice(0, 300)).toBe(true);
      const bad: string[] = [];
      compareSim((out.report as Record<string, JVal>).sim, c.expected, '', rules, bad);
      expect(bad.slice(0, 20)).toEqual([]);
      const naive = ((c.expected as Record<string, Record<string, Record<string, Record<string, JVal>>>>).pll.metrics.naive.locked);
      expect(naive).toBe(false);
    });
  }
});
