// Validation messages: what the page shows at a field, local (TS parse) or from Python.
import { describe, it, expect, beforeAll } from 'vitest';
import { parseNumber } from '../../web/src/format';
import { t, setLang } from '../../web/src/i18n';
import { qcalcRequest, qstate } from '../../web/src/panels/qcalc';
import { bootPulab, type NodePulab } from './pulab-node';
import { reportInput, SEED_INPUT } from '../../web/src/state';

describe('local parse errors → message key', () => {
  const cases: [string, boolean, string, string][] = [
    ['abc', false, 'en', 'Enter a number (e.g. 1.5 or 6e-4).'],
    ['abc', false, 'zh', '请输入数字（例如 1.5 或 6e-4）。'],
    ['2.5', true, 'en', 'Enter a whole number.'],
    ['2.5', true, 'zh', '请输入整数。'],
  ];
  for (const [text, int, lang, msg] of cases)
    it(`${text}${int ? ' (integer)' : ''} [${lang}] → ${msg}`, () => {
      const r = parseNumber(text, int);
      expect(r.ok).toBe(false);
      setLang(lang as 'en' | 'zh');
      expect(t(!r.ok && r.error === 'integer' ? 'errInteger' : 'errNumber')).toBe(msg);
      setLang('en');
    });
});

describe('qcalc request from the form state', () => {
  const cases: [Partial<typeof qstate>, unknown][] = [
    [{ mode: 'encode', format: 'Q0.15', value: '0.5', word_bits: '' }, { ok: true, req: { format: 'Q0.15', rounding: 'nearest', overflow: 'saturate', value: 0.5 } }],
    [{ mode: 'decode', format: 'Q15', raw: '-16384', word_bits: '16' }, { ok: true, req: { format: 'Q15', rounding: 'nearest', overflow: 'saturate', word_bits: 16, raw: -16384 } }],
    [{ mode: 'encode', format: 'Q0.15', value: 'x' }, { ok: false, field: 'qcalc.value', error: 'number' }],
    // Not a decimal integer: sent as typed, pulab reads hex/binary or names qcalc.raw.
    [{ mode: 'decode', format: 'Q0.15', raw: '1.5' }, { ok: true, req: { format: 'Q0.15', rounding: 'nearest', overflow: 'saturate', raw: '1.5' } }],
    [{ mode: 'decode', format: 'Q15', raw: ' 0x8000 ' }, { ok: true, req: { format: 'Q15', rounding: 'nearest', overflow: 'saturate', raw: '0x8000' } }],
    [{ mode: 'decode', format: 'Q15', raw: '４００００' }, { ok: true, req: { format: 'Q15', rounding: 'nearest', overflow: 'saturate', raw: 40000 } }],
    [{ mode: 'decode', format: 'Q15', raw: ' ' }, { ok: false, field: 'qcalc.raw', error: 'integer' }],
  ];
  for (const [s, want] of cases) it(`${JSON.stringify(s)} → ${JSON.stringify(want)}`, () => expect(qcalcRequest({ ...qstate, word_bits: '', ...s })).toEqual(want));
});

describe('Python validation messages reach the field that caused them', () => {
  let p: NodePulab;
  beforeAll(async () => {
    p = await bootPulab();
  });
  const base = reportInput(SEED_INPUT) as Record<string, Record<string, unknown>>;
  const cases: [string, string, unknown, string][] = [
    ['motor', 'rs_ohm', -1, 'motor.rs_ohm'],
    ['motor', 'pole_pairs', 2.5, 'motor.pole_pairs'],
    ['drive', 'ts_s', 0, 'drive.ts_s'],
    ['raw', 'Voltage', 70000, 'raw.Voltage'],
    ['conventions', 'base', 'line', 'conventions.base'],
  ];
  for (const [sec, key, v, field] of cases)
    it(`${sec}.${key} = ${JSON.stringify(v)} → ok:false at ${field}`, async () => {
      const inp = { ...base, [sec]: { ...(base[sec] ?? {}), [key]: v } };
      const { result } = await p.call('report', JSON.stringify(inp));
      expect(result.ok).toBe(false);
      expect(result).toMatchObject({ field });
      expect(String((result as { message: string }).message).length).toBeGreaterThan(3);
    });
});
