// A new input cancels a running simulation. The worst allowed simulation (both runs at
// their period caps, pm_kp = pm_ki = 2^31 − 1: the e2e check's input) runs on a channel in the
// worker logic on real Pyodide; a newer call on that channel supersedes it between two slices.
// Latencies are printed (measured, not asserted tightly: the machine is shared).
import { describe, it, expect, beforeAll } from 'vitest';
import { bootPulab, type NodePulab } from './pulab-node';

const SEED = {
  motor: { rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5, ld_h: 0.0006, lq_h: 0.0006, bemf_v: 12, pole_pairs: 4 },
  drive: { udc_v: 24, ts_s: 0.0001 },
};
const WORST = {
  ...SEED,
  current_loop: { method: 'integers', pm_kp: 2 ** 31 - 1, pm_ki: 2 ** 31 - 1 },
  sim: { current: { duration_s: 200000 * 1e-4 }, pll: { duration_s: 500000 * 1e-4 } },
};
const SMALL = { ...SEED, sim: { current: {}, pll: {} } };

let p: NodePulab;
beforeAll(async () => {
  p = await bootPulab();
}, 120_000);

describe('cancelling a running simulation (worker logic on Pyodide)', () => {
  it('stepped call_json_steps → the same JSON text as call_json (seed with sim)', () => {
    const text = JSON.stringify(SMALL);
    const gen = (p.py.pyimport('pulab.api') as Record<string, (kind: string, t: string) => { next(): { done?: boolean; value?: unknown }; destroy(): void }>).call_json_steps('report', text);
    let r = gen.next();
    let slices = 1;
    while (!r.done) {
      r = gen.next();
      slices++;
    }
    gen.destroy();
    expect(slices).toBeGreaterThan(1);
    expect(r.value).toBe(p.raw('report', text));
  }, 120_000);

  it('worst simulation running, a new call on its channel → old superseded, new result; latency printed', async () => {
    const before = p.messages.length;
    const worst = p.call('report', JSON.stringify(WORST), 'sim');
    const outcome = worst.then(
      () => 'result',
      (e: Error) => e.message,
    );
    await new Promise((res) => setTimeout(res, 1500)); // the worst simulation is running now
    const t0 = performance.now();
    let tSuperseded = NaN;
    const watch = setInterval(() => {
      if (Number.isNaN(tSuperseded) && p.messages.slice(before).some((m) => m.type === 'superseded')) tSuperseded = performance.now() - t0;
    }, 1);
    const fresh = await p.call('report', JSON.stringify(SMALL), 'sim');
    const toResult = performance.now() - t0;
    clearInterval(watch);
    expect(await outcome).toBe('superseded');
    expect(fresh.result.ok).toBe(true);
    const sim = (fresh.result as unknown as { report: { sim: { current: { t: number[] } } } }).report.sim;
    expect(sim.current.t.length).toBeGreaterThan(0);
    console.log(
      `cancel: new call → old superseded (new computation starts) after ${tSuperseded.toFixed(0)} ms; ` +
        `→ new result after ${toResult.toFixed(0)} ms (of which computing it ${fresh.ms.toFixed(0)} ms)`,
    );
    expect(tSuperseded).toBeLessThan(toResult + 1);
  }, 300_000);

  it('the longest slice of the worst simulation in Pyodide, printed (the cancel latency bound)', () => {
    const gen = (p.py.pyimport('pulab.api') as Record<string, (kind: string, t: string) => { next(): { done?: boolean; value?: unknown }; destroy(): void }>).call_json_steps('report', JSON.stringify(WORST));
    const slices: number[] = [];
    let t = performance.now();
    const t0 = t;
    for (let r = gen.next(); ; r = gen.next()) {
      const n = performance.now();
      slices.push(n - t);
      t = n;
      if (r.done) break;
    }
    gen.destroy();
    slices.sort((a, b) => a - b);
    const median = slices[Math.floor(slices.length / 2)];
    console.log(`cancel: worst simulation ${((t - t0) / 1000).toFixed(1)} s in ${slices.length} slices; median ${median.toFixed(1)} ms, longest ${slices[slices.length - 1].toFixed(0)} ms, top 5 ${slices.slice(-5).map((x) => x.toFixed(0)).join(', ')} ms`);
    expect(slices.length).toBeGreaterThan(100);
  }, 300_000);
});
