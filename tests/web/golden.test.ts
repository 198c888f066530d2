// Every golden vector (tests/golden/*.json, made by the independent oracle) through
// pulab.api.call_json("report", …) in Pyodide/Node, booted the way the web worker boots it.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync, existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { compareGolden, dump, parseJsonExact, type JVal } from './json-exact';

const GOLDEN = fileURLToPath(new URL('../golden/', import.meta.url));
const files = existsSync(GOLDEN)
  ? readdirSync(GOLDEN).filter((f) => f.endsWith('.json') && f !== 'errors.json').sort()
  : [];

type Obj = { [k: string]: JVal };
const asObj = (v: JVal): Obj => v as Obj;
let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('golden vectors through pulab.api.call_json("report", …) in Pyodide', () => {
  it('finds golden files in tests/golden', () => {
    expect(files.length, 'no tests/golden/*.json found').toBeGreaterThan(0);
  });

  for (const f of files) {
    it(f, () => {
      const gold = asObj(parseJsonExact(readFileSync(join(GOLDEN, f), 'utf8')));
      expect(gold.input, `${f} has no "input"`).toBeDefined();
      expect(gold.expected, `${f} has no "expected"`).toBeDefined();
      const out = asObj(parseJsonExact(pulab.raw('report', dump(gold.input))));
      expect(out.ok, `${f}: ${dump(out)}`.slice(0, 400)).toBe(true);
      const mism = compareGolden(gold.expected, out.report, '', { skip: ['warnings'] });
      expect(mism.slice(0, 20), `${f}: ${mism.length} mismatches`).toEqual([]);
    });
  }
});

const errorsPath = join(GOLDEN, 'errors.json');
describe.skipIf(!existsSync(errorsPath))('error cases (tests/golden/errors.json)', () => {
  const raw = existsSync(errorsPath) ? parseJsonExact(readFileSync(errorsPath, 'utf8')) : [];
  const cases = (Array.isArray(raw) ? raw : (asObj(raw).cases as JVal[]) ?? []) as Obj[];
  it('has cases', () => expect(cases.length).toBeGreaterThan(0));
  cases.forEach((c, k) => {
    const field = (c.field ?? asObj(c.expected ?? {}).field) as string;
    it(`${String(c.name ?? k)} → ok:false at ${field}`, () => {
      const out = JSON.parse(pulab.raw('report', dump(c.input))) as { ok: boolean; field?: string; message?: string };
      expect(out.ok).toBe(false);
      expect(out.field).toBe(field);
      expect(typeof out.message).toBe('string');
    });
  });
});
