// Your code in the loop in Pyodide (the worker's runtime): the seed's PI block pasted as C equals
// pulab's own Inovance integers over the whole run, and what one period of it costs there.
import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import { describe, it, expect } from 'vitest';
import { bootPulab } from './pulab-node';

const ROOT = join(__dirname, '../..');
const PI = readFileSync(join(ROOT, 'py/pulab/ctrace/examples.py'), 'utf8').match(/_PI = """\\\n([\s\S]*?)"""/)![1];
const SEED = { motor: { rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5, ld_h: 6e-4, lq_h: 6e-4, bemf_v: 12, pole_pairs: 4 },
  drive: { udc_v: 24, ts_s: 1e-4 } };
const CODE = { text: PI, error: 'pm_error_id', output: 'pm_ud', integral: 'pm_integral_d', integral_shift: 12,
  set: { pm_kp_d: { d: 'current_pi.d.pm_kp', q: 'current_pi.q.pm_kp' }, pm_ki_d: { d: 'current_pi.d.pm_ki', q: 'current_pi.q.pm_ki' },
    maxu: 'vendor.maxu', pm_maxout_vol: 'vendor.pm_maxout_vol' } };

describe('sim.current.code in Pyodide', () => {
  it('the seed PI as C equals pulab\'s fixed point at 50 Hz with the delay; the cost per period', async () => {
    const pulab = await bootPulab();
    const current = { axis: 'q', step_a: 6, speed_hz: 50, delay: true, duration_s: 0.2 };
    const run = (sim: object) => {
      const t0 = performance.now();
      const r = JSON.parse(pulab.raw('report', JSON.stringify({ ...SEED, sim })));
      return [r, performance.now() - t0] as const;
    };
    run({ current }); // warm: the first report imports and compiles what the others reuse
    const [own, ms0] = run({ current });
    const [r, ms1] = run({ current: { ...current, code: CODE } });
    expect(own.ok && r.ok).toBe(true);
    const c = r.report.sim.current;
    expect(c.code.metrics.vs_fixed_max_abs_a).toBe(0);
    expect(c.code.variant.iq).toEqual(c.variants.fixed.iq);
    expect(c.code.flags).toContain('saturate');
    console.log(`sim.current.code in Pyodide: 2000 periods, ${((ms1 - ms0) / 2000).toFixed(3)} ms per period (two calls) over the report without code (${ms0.toFixed(0)} ms)`);
  }, 120_000);
});
