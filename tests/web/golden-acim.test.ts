// Every golden induction-motor case (tests/golden/acim/*.json, made by the independent numpy
// oracle tests/oracle/acim_oracle.py) through pulab in Pyodide/Node: the report's "acim" section
// (without its "inovance" text), "current_pi", the vendors' stored floats and the speed-loop bases,
// floats to 1e-12 relative, integers, strings and nulls exact; each bad input names its field.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { compare, type J, type Rules } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/acim/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => /^\d.*\.json$/.test(f)).sort() : [];
const EXACT: Rules = { rel: 1e-12, abs: {}, skip: [], wrapped: [] };

interface Constant { value: number }
interface Report {
  acim: { [k: string]: J };
  current_pi: J;
  profiles: { [vendor: string]: { constants: { [name: string]: Constant } } };
  loop?: { speed: { bases: J } };
  acim_flux?: { [k: string]: J };
}

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden induction motors through Pyodide', () => {
  it('finds tests/golden/acim/*.json', () => expect(files.length).toBeGreaterThanOrEqual(4));

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: J; expected: { [k: string]: J } };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: Report; message?: string };
      expect(out.ok, out.message).toBe(true);
      const r = out.report!;
      const acim = Object.fromEntries(Object.entries(r.acim).filter(([k]) => k !== 'inovance'));
      const vendors = gold.expected.vendor_values as { [v: string]: { [k: string]: number } };
      const got: { [k: string]: J } = {
        acim,
        current_pi: r.current_pi,
        vendor_values: Object.fromEntries(Object.keys(vendors).map((v) => [
          v, Object.fromEntries(Object.entries(r.profiles[v].constants).map(([k, c]) => [k, c.value])),
        ])),
      };
      if ('speed_bases' in gold.expected) got.speed_bases = r.loop!.speed.bases;
      if ('acim_flux' in gold.expected) got.acim_flux = Object.fromEntries(Object.entries(r.acim_flux!).filter(([k]) => k !== 'trace'));
      const bad: string[] = [];
      compare(got, gold.expected, '', EXACT, bad);
      expect(bad).toEqual([]);
    });
  }

  const errors = (JSON.parse(readFileSync(join(DIR, 'errors.json'), 'utf8')) as { cases: { input: J; field: string }[] }).cases;
  for (const [k, c] of errors.entries()) {
    it(`bad input ${k} names ${c.field}`, () => {
      const out = JSON.parse(pulab.raw('report', JSON.stringify(c.input))) as { ok: boolean; field?: string };
      expect(out.ok).toBe(false);
      expect(out.field).toBe(c.field);
    });
  }
});
