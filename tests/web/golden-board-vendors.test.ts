// Every golden board-vendor case (tests/golden/board-vendors/*.json, made by the independent
// oracle tests/oracle/board_vendors_oracle.py) through pulab in Pyodide/Node: the macros each
// vendor's header holds for the board, exactly (integers, and the float a compiler stores).
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';

const DIR = fileURLToPath(new URL('../golden/board-vendors/', import.meta.url));
const files = existsSync(DIR) ? readdirSync(DIR).filter((f) => f.endsWith('.json')).sort() : [];

type Profile = { board?: string[]; constants: Record<string, { value: number }> };

let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden board-vendor constants through Pyodide', () => {
  it('finds tests/golden/board-vendors/*.json', () => expect(files.length).toBeGreaterThanOrEqual(4));

  for (const f of files) {
    it(`${f} matches the oracle`, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: unknown; expected: Record<string, Record<string, number>> };
      const out = JSON.parse(pulab.raw('report', JSON.stringify(gold.input))) as { ok: boolean; report?: { profiles: Record<string, Profile> }; message?: string };
      expect(out.ok, out.message).toBe(true);
      for (const [vendor, want] of Object.entries(gold.expected)) {
        const p = out.report!.profiles[vendor];
        expect([...(p.board ?? [])].sort(), vendor).toEqual(Object.keys(want).sort());
        const got = Object.fromEntries(Object.keys(want).map((k) => [k, p.constants[k].value]));
        expect(got, vendor).toEqual(want);
      }
    });
  }
});
