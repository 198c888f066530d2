// Microchip's and TI's sensorless constants (tests/golden/observer-vendors/*.json, made by
// tests/oracle/observer_vendors_oracle.py: motorBench's printed pll_params.h integers, TI's
// esmo.c in numpy float32) through pulab in Pyodide/Node: each expected path of the report,
// integers exactly, floats within the file's relative tolerance (as tests/py/test_observer_vendors.py).
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import type { J } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/observer-vendors/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

interface Case { input: J; expected: Record<string, number>; tolerance: { rel: number; abs: number } }

const at = (d: J, path: string): J =>
  path.split('.').reduce<J>((x, k) => (x as Record<string, J>)[k], d);

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden Microchip and TI observer constants through Pyodide', () => {
  it('finds both vendors\' files', () => {
    expect(files.some((f) => f.startsWith('mchp_'))).toBe(true);
    expect(files.some((f) => f.startsWith('ti_'))).toBe(true);
  });

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as Case;
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: J; message?: string };
      expect(out.ok, out.message).toBe(true);
      const bad: string[] = [];
      for (const [path, want] of Object.entries(gold.expected)) {
        const got = at(out.report!, path);
        const ok = typeof got === 'number' && Math.abs(got - want) <= Math.max(gold.tolerance.rel * Math.abs(want), gold.tolerance.abs);
        if (!ok) bad.push(`${path}: ${JSON.stringify(got)} != ${want}`);
      }
      expect(bad).toEqual([]);
    });
  }
});
