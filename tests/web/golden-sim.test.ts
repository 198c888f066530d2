// Every golden simulation trajectory (tests/golden/sim/*.json, made by the independent numpy
// oracle tests/oracle/sim_oracle.py) through pulab.api.call_json("report", …) in Pyodide/Node. The tolerance
// rules travel with each file ("compare"), the same rules tests/py/test_sim.py applies.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { compare, type J, type Rules } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/sim/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

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
