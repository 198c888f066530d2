import { describe, it, expect, beforeAll } from 'vitest';
import { bootPulab, type NodePulab } from './pulab-node';
import { PRESETS, SEED_INPUT, decodeHash, decodeUnits, encodeHash, getPath, initialInput, reportInput, setPath, simInput, type Input } from '../../web/src/state';
import { effectiveInput } from '../../web/src/fields';

describe('URL state: #in= + encodeURIComponent(JSON)', () => {
  const seed = reportInput(SEED_INPUT);
  const cases: [string, string, Input | null][] = [
    ['round trip of the seed input', encodeHash(seed), seed],
    ['hash without #', encodeHash(seed).slice(1), seed],
    ['other params before in=', `#lang=zh&in=${encodeURIComponent('{"motor":{"rs_ohm":2}}')}`, { motor: { rs_ohm: 2 } }],
    ['broken JSON → null', '#in=%7Bmotor', null],
    ['not an object → null', `#in=${encodeURIComponent('[1,2]')}`, null],
    ['a section that is not an object → null', `#in=${encodeURIComponent('{"motor":3}')}`, null],
    ['no state → null', '#panel-vendor', null],
  ];
  for (const [name, hash, want] of cases) it(`${name}: ${hash.slice(0, 40)} → ${want ? 'state' : 'null'}`, () => expect(decodeHash(hash)).toEqual(want));

  it('encodeHash is exactly #in= + encodeURIComponent(JSON.stringify(input))', () => {
    expect(encodeHash({ motor: { rs_ohm: 1.5 } })).toBe(`#in=${encodeURIComponent('{"motor":{"rs_ohm":1.5}}')}`);
  });
});

describe('initialInput: URL, then localStorage, then the seed', () => {
  const link = encodeHash({ motor: { rs_ohm: 7 } });
  const cases: [string, string, string | null, string, unknown][] = [
    ['URL wins', link, '{"motor":{"rs_ohm":3}}', 'url', 7],
    ['storage when no URL', '', '{"motor":{"rs_ohm":3}}', 'storage', 3],
    ['seed when storage is corrupt', '', '{oops', 'default', 1.5],
    ['seed when nothing', '', null, 'default', 1.5],
  ];
  for (const [name, hash, stored, source, rs] of cases)
    it(`${name} → ${source}, motor.rs_ohm = ${rs}`, () => {
      const r = initialInput(hash, stored);
      expect(r.source).toBe(source);
      expect(getPath(r.input, 'motor.rs_ohm')).toBe(rs);
      expect(r.input.sim).toBeDefined();
    });
});

describe('paths', () => {
  it('getPath reads nested values and array indices', () => {
    expect(getPath({ vendor: { Rpm: { trace: [{ value: 13235 }] } } }, 'vendor.Rpm.trace.0.value')).toBe(13235);
    expect(getPath({ a: 1 }, 'a.b.c')).toBeUndefined();
  });
  it('setPath creates sections and deletes on null', () => {
    const o: Record<string, unknown> = {};
    setPath(o, 'raw.LD', 60);
    expect(o).toEqual({ raw: { LD: 60 } });
    setPath(o, 'raw.LD', null);
    expect(o).toEqual({ raw: {} });
  });
});

describe('what is sent', () => {
  const cases: [string, Input, Input][] = [
    ['report input drops sim and empty sections', { motor: { rs_ohm: 1 }, raw: {}, sim: { current: {} } }, { motor: { rs_ohm: 1 } }],
  ];
  for (const [name, inp, want] of cases) it(name, () => expect(reportInput(inp)).toEqual(want));
  it('sim input keeps sim', () => expect(simInput({ motor: { rs_ohm: 1 }, sim: { current: { axis: 'q' } } })).toEqual({ motor: { rs_ohm: 1 }, sim: { current: { axis: 'q' } } }));
  const eff: [string, Input, Input][] = [
    ['bandwidth method: kp, ki, pm_* and damping are not sent',
      { current_loop: { method: 'bandwidth', bandwidth_hz: 500, damping: 0.7, kp: 1, ki: 2, pm_kp: 3 } },
      { current_loop: { method: 'bandwidth', bandwidth_hz: 500 } }],
    ['manual method: bandwidth is not sent',
      { current_loop: { method: 'manual', bandwidth_hz: 500, kp: 1, ki: 2 } },
      { current_loop: { method: 'manual', kp: 1, ki: 2 } }],
    ['rms base: custom U_b, I_b are not sent',
      { conventions: { base: 'rms', base_voltage_v: 10, base_current_a: 1 } },
      { conventions: { base: 'rms' } }],
    ['custom base: they are',
      { conventions: { base: 'custom', base_voltage_v: 10, base_current_a: 1 } },
      { conventions: { base: 'custom', base_voltage_v: 10, base_current_a: 1 } }],
  ];
  for (const [name, inp, want] of eff) it(`effectiveInput, ${name}`, () => expect(effectiveInput(inp)).toEqual(want));
});

describe('presets: current-loop bandwidth suited to Ts (no phase-margin finding from pulab.analyses.review\'s delay-aware loop model)', () => {
  let p: NodePulab;
  beforeAll(async () => {
    p = await bootPulab();
  });
  for (const preset of PRESETS)
    it(`${preset.id}: bandwidth ${String(preset.input.current_loop.bandwidth_hz)} Hz at Ts ${String(preset.input.drive.ts_s)} s → no phase_margin finding`, async () => {
      const { result } = await p.call('report', JSON.stringify(reportInput(preset.input)));
      expect(result.ok).toBe(true);
      const findings = (result as unknown as { report: { review: { findings: { code: string }[] } } }).report.review.findings;
      expect(findings.filter((f) => f.code === 'phase_margin')).toEqual([]);
    });
});

describe('share links keep display units and shortest decimals', () => {
  const inp: Input = { motor: { ld_h: 0.0042 }, drive: { ts_s: 0.0000625 } };
  it('encodeHash → decodeHash round trip, 0.0042 printed as 0.0042', () => {
    const hash = encodeHash(inp, { 'motor.ld_h': 'mH', 'drive.ts_s': 'kHz' });
    expect(decodeURIComponent(hash)).toContain('"ld_h":0.0042}');
    expect(decodeHash(hash)).toEqual(inp);
    expect(decodeUnits(hash)).toEqual({ 'motor.ld_h': 'mH', 'drive.ts_s': 'kHz' });
  });
  it('no units → no u= part; a bad u= is ignored', () => {
    expect(encodeHash(inp)).not.toContain('&u=');
    expect(decodeUnits(encodeHash(inp))).toBeNull();
    expect(decodeUnits('#in=%7B%7D&u=%5B1%5D')).toBeNull();
  });
});
