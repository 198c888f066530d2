// The induction motor's simulation golden cases (tests/golden/acim-sim/*.json, made by the
// independent oracle tests/oracle/acim_sim_oracle.py: flux-linkage model, float PI and the seed's
// PI in np.int32) through pulab in Pyodide/Node: the current step and the flux build-up, each
// with the oracle's keys only, under the file's compare rules; the per-unit run against the
// oracle's SI one.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { compare, type J, type Rules } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/acim-sim/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => /^\d.*\.json$/.test(f)).sort() : [];

type Obj = { [k: string]: J };
type Section = { variants: { [v: string]: Obj }; metrics: { [v: string]: Obj } } & Obj;

/** pulab's section reduced to the oracle's keys (a key pulab lacks stays undefined and fails). */
function project(got: Section, exp: Section): Obj {
  const out: Obj = {};
  for (const k of Object.keys(exp)) if (k !== 'variants' && k !== 'metrics') out[k] = got[k];
  const pick = (g: { [v: string]: Obj }, e: { [v: string]: Obj }): Obj =>
    Object.fromEntries(Object.keys(e).map((v) => [v, Object.fromEntries(Object.keys(e[v]).map((kk) => [kk, g[v][kk]]))]));
  out.variants = pick(got.variants, exp.variants);
  out.metrics = pick(got.metrics, exp.metrics);
  return out;
}

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden induction-motor simulations through Pyodide', () => {
  it('finds tests/golden/acim-sim/*.json', () => expect(files.length).toBeGreaterThanOrEqual(3));

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: J; expected: { [s: string]: Section }; compare: Rules };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { sim: { [s: string]: Section } }; message?: string };
      expect(out.ok, out.message).toBe(true);
      const bad: string[] = [];
      for (const sec of ['current', 'flux']) {
        const exp = gold.expected[sec];
        const got = out.report!.sim[sec];
        compare(project(got, exp), exp as J, sec, gold.compare, bad);
        const pu = Object.fromEntries(Object.keys(exp.variants.si).map((k) => [k, got.variants.pu[k]]));
        compare(pu, exp.variants.si as J, `${sec}.variants.pu`, gold.compare, bad);
      }
      expect(bad).toEqual([]);
    }, 60_000);
  }
});
