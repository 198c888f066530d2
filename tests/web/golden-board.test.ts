// Every golden board case (tests/golden/board/*.json, made by the independent oracle
// tests/oracle/board_oracle.py) through pulab in Pyodide/Node: the report's "board" section, floats
// to 1e-12 relative, integers, strings and nulls exact.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { compare, type J, type Rules } from './golden-compare';

const DIR = fileURLToPath(new URL('../golden/board/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

const EXACT: Rules = { rel: 1e-12, abs: {}, skip: [], wrapped: [] };

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
      compare(out.report!.board, gold.expected, '', EXACT, bad);
      expect(bad).toEqual([]);
    });
  }
});
