// Every golden loop analysis (tests/golden/loop/*.json, made by the python-control oracle
// tests/oracle/loop_oracle.py) through pulab.api.call_json("report", …) in Pyodide/Node, with the rules of
// tests/py/test_loop.py: numbers to 1e-6 relative (+1e-9), poles matched as complex numbers,
// Bode samples compared as complex L(e^{jωTs}) (so a 360° unwrap difference does not count).
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/loop/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];
const REL = 1e-6;

type J = null | boolean | number | string | J[] | { [k: string]: J };
interface BodeCurve {
  magnitude_db: number[];
  phase_deg: number[];
}
interface BodeSamples extends BodeCurve {
  index: number[];
}

const close = (a: number, e: number): boolean => Math.abs(a - e) <= REL * Math.max(Math.abs(a), Math.abs(e)) + 1e-9;

/** L as (re, im) from dB and degrees. */
const complex = (db: number, deg: number): [number, number] => {
  const m = 10 ** (db / 20);
  const r = (deg * Math.PI) / 180;
  return [m * Math.cos(r), m * Math.sin(r)];
};

function polesMatch(got: number[][], exp: number[][]): boolean {
  const left = got.slice();
  if (left.length !== exp.length) return false;
  for (const [re, im] of exp) {
    let best = 0;
    let dist = Infinity;
    left.forEach(([r, i], k) => {
      const d = Math.hypot(r - re, i - im);
      if (d < dist) [best, dist] = [k, d];
    });
    if (dist > REL * Math.max(Math.hypot(re, im), 1)) return false;
    left.splice(best, 1);
  }
  return true;
}

function compare(got: J, exp: J, path: string, bad: string[]): void {
  if (exp !== null && typeof exp === 'object' && !Array.isArray(exp)) {
    if (got === null || typeof got !== 'object' || Array.isArray(got)) {
      bad.push(`${path}: not an object`);
      return;
    }
    if ('index' in exp) {
      const e = exp as unknown as BodeSamples;
      const g = got as unknown as BodeCurve;
      e.index.forEach((i, k) => {
        const [ar, ai] = complex(g.magnitude_db[i], g.phase_deg[i]);
        const [er, ei] = complex(e.magnitude_db[k], e.phase_deg[k]);
        if (Math.hypot(ar - er, ai - ei) > REL * Math.hypot(er, ei)) bad.push(`${path}[${i}]`);
      });
      return;
    }
    for (const [k, v] of Object.entries(exp)) {
      const p = `${path}.${k}`;
      if (!(k in got)) bad.push(`${p}: missing`);
      else if (k === 'poles') {
        if (!polesMatch(got[k] as number[][], v as number[][])) bad.push(`${p}: poles differ`);
      } else if (k === 'f_hz') {
        const g = got[k] as number[];
        const idx = [...Array.from({ length: 40 }, (_, n) => n * 10), g.length - 1];
        if (g.length !== 400 || !idx.every((i, n) => close(g[i], (v as number[])[n]))) bad.push(`${p}: differs`);
      } else compare(got[k], v, p, bad);
    }
  } else if (typeof exp === 'number') {
    if (typeof got !== 'number' || !close(got, exp)) bad.push(`${path}: ${JSON.stringify(got)} != ${exp}`);
  } else if (got !== exp) {
    bad.push(`${path}: ${JSON.stringify(got)} != ${JSON.stringify(exp)}`);
  }
}

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden loop analysis (python-control oracle) through Pyodide', () => {
  it('finds at least 20 motors/drives in tests/golden/loop', () => expect(files.length).toBeGreaterThanOrEqual(20));

  for (const f of files) {
    it(`${f} matches python-control`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: J; expected: { loop: J } };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as {
        ok: boolean;
        report?: { loop: J };
        message?: string;
      };
      expect(out.ok, out.message).toBe(true);
      const bad: string[] = [];
      compare(out.report!.loop, gold.expected.loop, 'loop', bad);
      expect(bad.slice(0, 20)).toEqual([]);
    });
  }
});
