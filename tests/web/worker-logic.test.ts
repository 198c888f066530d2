// The worker logic on real Pyodide: boot messages, calls, coalescing, errors.
import { describe, it, expect, beforeAll } from 'vitest';
import { bootPulab, type NodePulab } from './pulab-node';

const SEED = {
  motor: { rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5, ld_h: 0.0006, lq_h: 0.0006, bemf_v: 12, pole_pairs: 4 },
  drive: { udc_v: 24, ts_s: 0.0001 },
};

let p: NodePulab;
beforeAll(async () => {
  p = await bootPulab();
});

describe('worker logic on Pyodide', () => {
  it('reports boot progress, then ready', () => {
    const types = p.messages.map((m) => (m.type === 'progress' ? `progress:${m.stage}` : m.type));
    expect(types.slice(0, 5)).toEqual(['progress:runtime', 'progress:files', 'progress:import', 'progress:ready', 'ready']);
  });
  it('seed motor → vendor.Rpm.value = 15022 (seed 1.4-1)', async () => {
    const { result } = await p.call('report', JSON.stringify(SEED));
    expect(result.ok).toBe(true);
    const r = (result as unknown as { report: { vendor: { Rpm: { value: number } } } }).report;
    expect(r.vendor.Rpm.value).toBe(15022);
  });
  it('bad input → ok:false naming the field', async () => {
    const bad = { ...SEED, motor: { ...SEED.motor, rs_ohm: -1 } };
    const { result } = await p.call('report', JSON.stringify(bad));
    expect(result).toMatchObject({ ok: false, field: 'motor.rs_ohm' });
  });
  it('calls on one channel are coalesced to the newest', async () => {
    const a = p.call('report', JSON.stringify(SEED), 'r');
    const b = p.call('report', JSON.stringify(SEED), 'r');
    await expect(a).rejects.toThrow('superseded');
    expect((await b).result.ok).toBe(true);
  });
  it('qcalc: 0.5 in Q0.15 → raw 16384, 0x4000', async () => {
    const { result } = await p.call('qcalc', JSON.stringify({ value: 0.5, format: 'Q0.15' }));
    expect(result).toMatchObject({ ok: true, result: { raw: 16384, hex: '0x4000' } });
  });
  it('export header contains PULAB_RPM 15022', async () => {
    const { result } = await p.call('export.header', JSON.stringify({ input: SEED }));
    expect(result.ok).toBe(true);
    expect(result.ok && 'text' in result ? result.text : '').toMatch(/PULAB_RPM\s+15022/);
  });
});
