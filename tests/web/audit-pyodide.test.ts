// pulab.analyses.audit in Pyodide (the worker's runtime): the real ST MCSDK set of
// tests/data/headers/st folds as in CPython — C1 = (int32_t)(16384·0.35/(0.0006·20000)) = 477,
// CURRENT_CONV_FACTOR = (uint16_t)(65536·0.003·9.14/3.3) = 544 — and the time it takes is printed,
// for that set and for the ~600-macro set of pulab.benchmark.audit_timing (target ≤ 1 s in
// Pyodide for a whole set; printed, not asserted: the machine is shared).
import { readFileSync } from 'node:fs';
import { describe, it, expect } from 'vitest';
import { bootPulab } from './pulab-node';

const DIR = new URL('../data/headers/st/', import.meta.url);
const FILES = ['pmsm_motor_parameters.h', 'drive_parameters.h', 'power_stage_parameters.h', 'parameters_conversion.h',
  'parameters_conversion_g4xx.h'].map((name) => ({ name, text: readFileSync(new URL(name, DIR), 'utf8') }));

describe('the audit kind in Pyodide', () => {
  it('the ST set: profile, folded integers, the round trip at 0 LSB; timed', async () => {
    const pulab = await bootPulab();
    const req = JSON.stringify({ files: FILES });
    pulab.raw('audit', req); // warm: imports
    const times: number[] = [];
    let r: { ok: boolean; audit: { profile: string; macros: Record<string, { value: number }>; roundtrip: Record<string, { delta_lsb?: number }> } } | null = null;
    for (let i = 0; i < 5; i++) {
      const t0 = performance.now();
      r = JSON.parse(pulab.raw('audit', req));
      times.push(performance.now() - t0);
    }
    times.sort((a, b) => a - b);
    console.log(`audit of the 5-file ST set in Pyodide: ${times[2].toFixed(1)} ms median, ${times[0].toFixed(1)} ms min`);
    expect(r?.ok).toBe(true);
    expect(r?.audit.profile).toBe('st');
    expect(r?.audit.macros.C1.value).toBe(477);
    expect(r?.audit.macros.CURRENT_CONV_FACTOR.value).toBe(544);
    expect(r?.audit.roundtrip.PID_TORQUE_KP_DEFAULT.delta_lsb).toBe(0);
  }, 120_000);

  it('the ~600-macro ST set of the benchmark: measured and printed', async () => {
    const pulab = await bootPulab();
    const bench = pulab.py.pyimport('pulab.benchmark') as { audit_timing(n: number): unknown };
    const json = pulab.py.pyimport('json') as { dumps(x: unknown): string };
    const t0 = performance.now();
    const t = JSON.parse(json.dumps(bench.audit_timing(3))) as { macros: number; median_ms: number; min_ms: number; p95_ms: number };
    const wall = performance.now() - t0; // a warm-up and 3 runs, as the JS clock sees them
    console.log(`audit of a ${t.macros}-macro ST set in Pyodide: ${t.min_ms.toFixed(1)} / ${t.median_ms.toFixed(1)} / ${t.p95_ms.toFixed(1)} ms `
      + `(min / median / max of 3; ${(wall / 4).toFixed(1)} ms per call by the JS clock; target ≤ 1 s)`);
    expect(t.macros).toBe(600);
  }, 120_000);
});
