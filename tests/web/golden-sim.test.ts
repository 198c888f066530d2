// Every golden simulation trajectory (tests/golden/sim/*.json, made by the independent numpy
// oracle tests/oracle/sim_oracle.py) through pulab.api.call_json("report", …) in Pyodide/Node. The tolerance
// rules travel with each file ("compare"), the same rules tests/py/test_sim.py applies.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/sim/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

type J = null | boolean | number | string | J[] | { [k: string]: J };
interface Rules {
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

function compare(got: J, exp: J, path: string, rules: Rules, bad: string[]): void {
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

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden simulation trajectories through Pyodide', () => {
  it('finds tests/golden/sim/*.json', () => expect(files.length).toBeGreaterThanOrEqual(4));

  for (const f of files) {
    it(`${f} matches the numpy oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as {
        input: J;
        expected: { [k: string]: J };
        compare: Rules;
      };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as {
        ok: boolean;
        report?: { sim: J };
        message?: string;
      };
      expect(out.ok, out.message).toBe(true);
      // The four vendors' integer PIs have their own C oracle (tests/py/test_vendor_pi.py).
      delete ((out.report!.sim as { [k: string]: J }).current as { [k: string]: J }).by_profile;
      const bad: string[] = [];
      compare(out.report!.sim, gold.expected, '', gold.compare, bad);
      expect(bad.slice(0, 20)).toEqual([]);
    });
  }
});
