// Every golden observer case (tests/golden/observer/*.json, made by the independent oracle
// tests/oracle/observer_oracle.py with python-control and numpy) through pulab in Pyodide/Node:
// each expected path of the report's "observer" section within the file's tolerance
// (|Δ| ≤ max(rel·|expected|, abs), as tests/py/test_observer.py), nulls exact.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import type { J } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/observer/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

interface Case { input: J; expected: Record<string, J>; tolerance: { rel: number; abs: number } }

const at = (d: J, path: string): J =>
  path.split('.').reduce<J>((x, k) => (x as Record<string, J>)[k], d);

function close(got: J, exp: J, path: string, tol: Case['tolerance'], bad: string[]): void {
  if (exp === null) {
    if (got !== null) bad.push(`${path}: ${JSON.stringify(got)} != null`);
  } else if (Array.isArray(exp)) {
    if (!Array.isArray(got) || got.length !== exp.length) bad.push(`${path}: length differs`);
    else exp.forEach((e, k) => close(got[k], e, `${path}[${k}]`, tol, bad));
  } else if (typeof exp === 'number') {
    const ok = typeof got === 'number' && Math.abs(got - exp) <= Math.max(tol.rel * Math.abs(exp), tol.abs);
    if (!ok) bad.push(`${path}: ${JSON.stringify(got)} != ${exp}`);
  } else if (got !== exp) bad.push(`${path}: ${JSON.stringify(got)} != ${JSON.stringify(exp)}`);
}

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden observer designs through Pyodide', () => {
  it('finds tests/golden/observer/*.json', () => expect(files.length).toBeGreaterThanOrEqual(3));

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as Case;
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { observer: J }; message?: string };
      expect(out.ok, out.message).toBe(true);
      const bad: string[] = [];
      for (const [path, want] of Object.entries(gold.expected)) close(at(out.report!.observer, path), want, path, gold.tolerance, bad);
      expect(bad).toEqual([]);
    });
  }
});
