// Every golden firmware-table case (tests/golden/fw_tables/*.json, made by the numpy oracle
// tests/oracle/fw_tables_oracle.py that evaluates every input digit at once) through pulab in
// Pyodide/Node: integers exactly, error bounds and speeds to the file's relative tolerance, and TI's
// proven float32 bound at or above the oracle's largest sampled error.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/fw_tables/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

interface Gold {
  input: unknown;
  expected: Record<string, Record<string, unknown>>;
  compare: { rel: number };
}
type Table = Record<string, unknown> & { steady?: Record<string, unknown>; error_bound: number };

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden firmware MTPA/field-weakening tables through Pyodide', () => {
  it('finds tests/golden/fw_tables/*.json (three interior motors)', () => expect(files.length).toBeGreaterThanOrEqual(3));
  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as Gold;
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { fw: { tables: Record<string, Table> } }; message?: string };
      expect(out.ok, out.message).toBe(true);
      const tables = out.report!.fw.tables;
      for (const [name, want] of Object.entries(gold.expected)) {
        const got = tables[name];
        expect(got, name).toBeDefined();
        for (const [key, value] of Object.entries(want)) {
          const have = key in got ? got[key] : got.steady?.[key];
          const pairs: [unknown, unknown][] = Array.isArray(value) ? value.map((v, i) => [(have as unknown[])[i], v]) : [[have, value]];
          if (Array.isArray(value)) expect((have as unknown[]).length, `${name}.${key}`).toBe(value.length);
          for (const [h, v] of pairs) {
            // a JSON float written with a fraction (the oracle's floats) to the tolerance, integers exactly
            if (typeof v === 'number' && !Number.isInteger(v)) {
              expect(Math.abs((h as number) - v), `${name}.${key}`).toBeLessThanOrEqual(gold.compare.rel * Math.max(Math.abs(h as number), Math.abs(v)) + 1e-12);
            } else {
              expect(h, `${name}.${key}`).toEqual(v);
            }
          }
        }
      }
      expect(tables.ti_mtpa.error_sampled as number).toBeLessThanOrEqual(tables.ti_mtpa.error_bound);
    });
  }
});
