// Every golden field-weakening case (tests/golden/fw/*.json, made by the brute-force numpy oracle
// tests/oracle/fw_oracle.py) through pulab in Pyodide/Node, with the tolerances each file states:
// base speed and characteristic current to 1e-9, maximum speed to the oracle's grid (0.2 %),
// envelope torque at or above the grid's maximum and within 0.5 % of the largest torque.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/fw/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

interface Gold {
  input: unknown;
  expected: { base_speed_rpm: number; max_speed_rpm: number | null; characteristic_current_a: number; envelope_speed_rpm: number[]; envelope_torque_nm: number[] };
  compare: { rel: number; torque_rel: number; max_speed_rel: number };
}
interface Fw {
  base_speed_rpm: number;
  max_speed_rpm: number | null;
  characteristic_current_a: number;
  envelope: { speed_rpm: number; torque_nm: number }[];
}
const rel = (a: number, b: number): number => Math.abs(a - b) / Math.max(Math.abs(a), Math.abs(b));

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden field-weakening envelopes through Pyodide', () => {
  it('finds tests/golden/fw/*.json', () => expect(files.length).toBeGreaterThanOrEqual(3));
  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as Gold;
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { fw: Fw }; message?: string };
      expect(out.ok, out.message).toBe(true);
      const fw = out.report!.fw;
      const e = gold.expected;
      expect(rel(fw.base_speed_rpm, e.base_speed_rpm)).toBeLessThanOrEqual(gold.compare.rel);
      expect(rel(fw.characteristic_current_a, e.characteristic_current_a)).toBeLessThanOrEqual(1e-12);
      if (e.max_speed_rpm === null) expect(fw.max_speed_rpm).toBeNull();
      else expect(rel(fw.max_speed_rpm!, e.max_speed_rpm)).toBeLessThanOrEqual(gold.compare.max_speed_rel);
      const tMax = Math.max(...e.envelope_torque_nm);
      expect(fw.envelope.length).toBe(e.envelope_torque_nm.length);
      fw.envelope.forEach((p, k) => {
        expect(Math.abs(p.speed_rpm - e.envelope_speed_rpm[k])).toBeLessThanOrEqual(1e-9 * Math.max(1, e.envelope_speed_rpm[k]));
        expect(p.torque_nm).toBeGreaterThanOrEqual(e.envelope_torque_nm[k] - 1e-12);
        expect(p.torque_nm - e.envelope_torque_nm[k]).toBeLessThanOrEqual(gold.compare.torque_rel * tMax);
      });
    });
  }
});
