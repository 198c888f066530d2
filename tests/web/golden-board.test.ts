// Every golden board case (tests/golden/board/*.json, made by the independent oracle
// tests/oracle/board_oracle.py) through pulab in Pyodide/Node: the report's "board" section, floats
// to 1e-12 relative, integers, strings and nulls exact.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/board/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

type J = null | boolean | number | string | J[] | { [k: string]: J };

function compare(got: J, exp: J, path: string, bad: string[]): void {
  if (exp !== null && typeof exp === 'object' && !Array.isArray(exp)) {
    if (got === null || typeof got !== 'object' || Array.isArray(got)) {
      bad.push(`${path}: not an object`);
      return;
    }
    const gk = Object.keys(got).sort().join(',');
    const ek = Object.keys(exp).sort().join(',');
    if (gk !== ek) bad.push(`${path}: keys ${gk} != ${ek}`);
    else for (const k of Object.keys(exp)) compare(got[k], exp[k], path ? `${path}.${k}` : k, bad);
  } else if (typeof exp === 'number' && typeof got === 'number' && !Number.isInteger(exp)) {
    if (!(Math.abs(got - exp) <= 1e-12 * Math.max(Math.abs(got), Math.abs(exp)))) bad.push(`${path}: ${got} != ${exp}`);
  } else if (got !== exp) {
    bad.push(`${path}: ${JSON.stringify(got)} != ${JSON.stringify(exp)}`);
  }
}

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden board chains through Pyodide', () => {
  it('finds tests/golden/board/*.json', () => expect(files.length).toBeGreaterThanOrEqual(4));

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: J; expected: J };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { board: J }; message?: string };
      expect(out.ok, out.message).toBe(true);
      const bad: string[] = [];
      compare(out.report!.board, gold.expected, '', bad);
      expect(bad).toEqual([]);
    });
  }
});
