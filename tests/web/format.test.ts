import { describe, it, expect } from 'vitest';
import { fmtHex, fmtInput, fmtNum, fmtPct, fmtToward, parseNumber } from '../../web/src/format';

describe('fmtNum: display with 6 significant digits', () => {
  const cases: [number | null, string][] = [
    [15022, '15022'],
    [0, '0'],
    [9.814954576223638, '9.81495'],
    [0.004733631930389124, '0.00473363'],
    [0.0000723, '7.23e-5'],
    [16748164.521926744, '1.67482e7'],
    [-0.010682750087148486, '-0.0106828'],
    [220.0, '220'],
    [null, '—'],
  ];
  for (const [x, want] of cases) it(`${x} → ${want}`, () => expect(fmtNum(x)).toBe(want));
});

describe('fmtHex: two\'s complement in the C type', () => {
  const cases: [number, string, string][] = [
    [15022, 'Uint16', '0x3AAE'],
    [32768, 'Uint16', '0x8000'],
    [15790080, 'long', '0x00F0F000'],
    [-1, 'long', '0xFFFFFFFF'],
    [-32768, 'int16', '0x8000'],
    [983087, 'Ulong', '0x000F002F'],
  ];
  for (const [v, ty, want] of cases) it(`${v} as ${ty} → ${want}`, () => expect(fmtHex(v, ty)).toBe(want));
});

describe('fmtPct', () => {
  const cases: [number, string][] = [
    [-0.010682750087148486, '-0.0107 %'],
    [0.6397576346157301, '+0.6398 %'],
    [0, '0 %'],
    [-4.05e-7, '-4.05e-7 %'],
  ];
  for (const [v, want] of cases) it(`${v} → ${want}`, () => expect(fmtPct(v)).toBe(want));
});

describe('parseNumber: what a user types', () => {
  const cases: [string, boolean, ReturnType<typeof parseNumber>][] = [
    ['17', false, { ok: true, value: 17 }],
    [' 1.5 ', false, { ok: true, value: 1.5 }],
    ['1,5', false, { ok: true, value: 1.5 }],
    ['1,500', false, { ok: false, error: 'number' }],
    ['0,0006', false, { ok: true, value: 0.0006 }],
    ['6e-4', false, { ok: true, value: 0.0006 }],
    ['.5', false, { ok: true, value: 0.5 }],
    ['-1', false, { ok: true, value: -1 }],
    ['', false, { ok: true, value: null }],
    ['abc', false, { ok: false, error: 'number' }],
    ['1.2.3', false, { ok: false, error: 'number' }],
    ['1e999', false, { ok: false, error: 'number' }],
    ['4', true, { ok: true, value: 4 }],
    ['4.5', true, { ok: false, error: 'integer' }],
    ['0x10', true, { ok: false, error: 'integer' }],
    // a Chinese input method: full-width digits, full-width and ideographic full stops, minus
    ['１７', false, { ok: true, value: 17 }],
    ['１７', true, { ok: true, value: 17 }],
    ['０．５', false, { ok: true, value: 0.5 }],
    ['０。５', false, { ok: true, value: 0.5 }],
    ['－１．５ｅ－３', false, { ok: true, value: -0.0015 }],
    ['1　5', false, { ok: true, value: 15 }],
  ];
  for (const [text, int, want] of cases) it(`${JSON.stringify(text)}${int ? ' (integer)' : ''} → ${JSON.stringify(want)}`, () => expect(parseNumber(text, int)).toEqual(want));
});

describe('fmtInput: numbers back into an input box', () => {
  const cases: [number | null, string][] = [
    [600.0000000000001, '600'],
    [0.1 + 0.2, '0.3'],
    [1.5, '1.5'],
    [null, ''],
  ];
  for (const [x, want] of cases) it(`${x} → ${JSON.stringify(want)}`, () => expect(fmtInput(x)).toBe(want));
});

describe('fmtToward: a sweep boundary as the decimal a user would type', () => {
  /** The adjacent double below/above x (bit arithmetic, positive x). */
  const adjacent = (x: number, d: 1 | -1): number => {
    const v = new DataView(new ArrayBuffer(8));
    v.setFloat64(0, x);
    v.setBigUint64(0, v.getBigUint64(0) + BigInt(d));
    return v.getFloat64(0);
  };
  it('rounds away from the neighbour across the boundary, to the shortest such decimal', () => {
    const at = 26.884999999999998;
    const before = adjacent(at, -1);
    expect(fmtToward(at, before)).toBe('26.885');
    expect(Number('26.885') >= at).toBe(true);
    // the other side rounds down, so typing it stays before the boundary
    const b = fmtToward(before, at);
    expect(Number(b) <= before && Number(b) > 26.88).toBe(true);
    expect(b.length).toBeLessThan(String(before).length);
  });
  it('decreasing sweeps round down; exact and short values print as they are', () => {
    expect(fmtToward(0.30000000000000004, adjacent(0.30000000000000004, 1))).toBe('0.3');
    expect(fmtToward(1.5, 2)).toBe('1.5');
    expect(fmtToward(220, 219)).toBe('220');
    expect(fmtToward(-3.0000000000000004, -3.000000000000001)).toBe('-3');
  });
});
