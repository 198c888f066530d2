// Hostile saved and linked states: each table row is input → what is kept, what is named.
import { describe, it, expect } from 'vitest';
import { checkInput, checkInputText, checkUnits, shownValue } from '../../web/src/state-check';
import { SEED_INPUT, encodeHash, getPath, initialInput, reportInput } from '../../web/src/state';
import { ALL_FIELDS } from '../../web/src/fields';

const link = (json: string): string => `#in=${encodeURIComponent(json)}`;

/** Linked states: [name, hash, source, named paths, a kept path and its value]. */
export const HOSTILE_LINKS: [string, string, string, string[], [string, unknown] | null][] = [
  ['object with toString where a choice belongs', link('{"motor":{"rs_ohm":2},"current_loop":{"method":{"toString":1}}}'), 'url', ['current_loop.method'], ['motor.rs_ohm', 2]],
  ['object in sim.current.axis', link('{"sim":{"current":{"axis":{"toString":1},"delay":true}}}'), 'url', ['sim.current.axis'], ['sim.current.delay', true]],
  ['string where a number belongs', link('{"motor":{"rs_ohm":"1.5","ld_h":0.001}}'), 'url', ['motor.rs_ohm'], ['motor.ld_h', 0.001]],
  ['fraction in an integer field', link('{"motor":{"pole_pairs":1.5}}'), 'url', ['motor.pole_pairs'], null],
  ['list in a number field', link('{"drive":{"ts_s":[1e-4]},"raw":{"LD":60}}'), 'url', ['drive.ts_s'], ['raw.LD', 60]],
  ['unknown choice', link('{"conventions":{"base":"RMS","angle_base":"2pi"}}'), 'url', ['conventions.base'], ['conventions.angle_base', '2pi']],
  ['string where a boolean belongs', link('{"sim":{"current":{"delay":"yes"}}}'), 'url', ['sim.current.delay'], null],
  ['a section that is a number', link('{"motor":3,"drive":{"udc_v":48}}'), 'url', ['motor'], ['drive.udc_v', 48]],
  ['a sim subsection that is a list', link('{"sim":{"pll":[1]}}'), 'url', ['sim.pll'], null],
  ['unknown section and field', link('{"bogus":1,"motor":{"colour":"red","rs_ohm":3}}'), 'url', ['bogus', 'motor.colour'], ['motor.rs_ohm', 3]],
  ['key with U+2028 and an empty key', link('{"a\u2028b":1,"":2}'), 'url', ['["a\\u2028b"]', '[""]'], null],
  ['__proto__ key', link('{"__proto__":{"polluted":1}}'), 'url', ['__proto__'], null],
  ['number overflowing to Infinity', link('{"motor":{"rs_ohm":1e999}}'), 'url', ['motor.rs_ohm'], null],
  ['not JSON', '#in=%7Bmotor', 'default', ['#in'], ['motor.rs_ohm', 1.5]],
  ['malformed %-escape', '#in=%E0%A4%A', 'default', ['#in'], ['motor.rs_ohm', 1.5]],
  ['a list', link('[1,2]'), 'default', ['#in'], ['motor.rs_ohm', 1.5]],
  ['null', link('null'), 'default', ['#in'], ['motor.rs_ohm', 1.5]],
  ['nested 100 000 deep', link('['.repeat(100000) + ']'.repeat(100000)), 'default', ['#in'], ['motor.rs_ohm', 1.5]],
];

describe('hostile links: the usable fields are kept, every dropped one is named', () => {
  for (const [name, hash, source, named, kept] of HOSTILE_LINKS)
    it(`${name} → ${source}, names ${named.join(', ')}`, () => {
      const r = initialInput(hash, null);
      expect(r.source).toBe(source);
      expect(r.problems.map((p) => p.path)).toEqual(named);
      expect(r.problems.every((p) => p.origin === 'url')).toBe(true);
      expect(r.linkBroken).toBe(true);
      if (kept) expect(getPath(r.input, kept[0])).toEqual(kept[1]);
      expect(checkInput(r.input).problems).toEqual([]); // what is kept fits the form
      expect(Object.getPrototypeOf({} as object)).not.toHaveProperty('polluted');
    });
});

describe('a broken link falls back to the stored state, which is checked too', () => {
  const cases: [string, string | null, string, string[], unknown][] = [
    ['stored "null"', 'null', 'default', ['#in', 'localStorage'], 1.5],
    ['stored string', '"x"', 'default', ['#in', 'localStorage'], 1.5],
    ['stored valueOf object in a number', '{"motor":{"rs_ohm":{"valueOf":1},"ld_h":0.002}}', 'storage', ['#in', 'motor.rs_ohm'], undefined],
    ['stored good state', '{"motor":{"rs_ohm":4}}', 'storage', ['#in'], 4],
  ];
  for (const [name, stored, source, named, rs] of cases)
    it(`${name} → ${source}, names ${named.join(', ')}, motor.rs_ohm = ${String(rs)}`, () => {
      const r = initialInput('#in=%7B', stored);
      expect(r.source).toBe(source);
      expect(r.problems.map((p) => p.path)).toEqual(named);
      expect(r.linkBroken).toBe(true);
      expect(getPath(r.input, 'motor.rs_ohm')).toBe(rs);
    });
});

describe('a good link or none: nothing named, the link is not broken', () => {
  it('seed link', () => {
    const r = initialInput(encodeHash(reportInput(SEED_INPUT)), 'null');
    expect([r.source, r.problems, r.linkBroken]).toEqual(['url', [], false]);
  });
  it('no link, good storage', () => expect(initialInput('', '{"motor":{"rs_ohm":3}}').linkBroken).toBe(false));
  it('the seed input itself fits every field', () => expect(checkInput(SEED_INPUT).problems).toEqual([]));
});

describe('stored display units: only a field\'s own unit choices survive', () => {
  const cases: [string | null, Record<string, string>][] = [
    ['null', {}], ['[]', {}], ['"µH"', {}], ['{oops', {}], [null, {}],
    ['{"motor.ld_h":"furlong"}', {}],
    ['{"motor.ld_h":{"toString":1}}', {}],
    ['{"motor.ld_h":"mH","motor.rs_ohm":"mH","sim.pll.duration_s":"s"}', { 'motor.ld_h': 'mH', 'sim.pll.duration_s': 's' }],
    ['{"__proto__":{"motor.ld_h":"mH"}}', {}],
  ];
  for (const [text, want] of cases) it(`${String(text)} → ${JSON.stringify(want)}`, () => expect(checkUnits(text)).toEqual(want));
});

describe('shownValue: one short printable line, never calling the value', () => {
  const cases: [unknown, string][] = [
    [{ toString: 1 }, 'an object'], [[1], 'a list'], ['a\nb', '"a\\nb"'], ['a\u2028b', '"a\\u2028b"'],
    ['x'.repeat(100), `"${'x'.repeat(38)}…`], [1e999, 'Infinity'], [null, 'null'],
  ];
  for (const [v, want] of cases) it(`${String(JSON.stringify(v)).slice(0, 20)} → ${want}`, () => expect(shownValue(v)).toBe(want));
});

describe('property: 5 000 seeded random states never throw and keep only fitting values', () => {
  let seed = 14;
  const rnd = (): number => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const pick = <T>(xs: T[]): T => xs[Math.floor(rnd() * xs.length)];
  const atoms: unknown[] = [null, true, false, 0, -0, 1.5, -1, 1e308, 2 ** 53, '', 'd', 'rms', 'mH', '\u2028', { toString: 1 }, { valueOf: [] }, [], [1]];
  const keys = [...new Set(ALL_FIELDS.flatMap((f) => f.path.split('.'))), '__proto__', 'constructor', '', 'x'];
  const value = (depth: number): unknown => {
    if (depth > 3 || rnd() < 0.5) return pick(atoms);
    const o: Record<string, unknown> = {};
    for (let i = 0; i < 4; i++) o[pick(keys)] = value(depth + 1);
    return rnd() < 0.1 ? [o] : o;
  };
  it('holds', () => {
    let n = 0;
    for (; n < 5000; n++) {
      const text = JSON.stringify(value(0)) ?? 'null';
      const r = checkInputText(text, '#in');
      expect(checkInput(r.input).problems).toEqual([]);
      for (const p of r.problems) expect(p.path + p.got).not.toMatch(/[\n\r\u2028\u2029\0]/);
    }
    expect(n).toBe(5000);
  });
});
