// pulab.analyses.decode in Pyodide (the worker's runtime): the real ST MCSDK set of
// tests/data/headers/st folds as in CPython — C1 = (int32_t)(16384·0.35/(0.0006·20000)) = 477,
// CURRENT_CONV_FACTOR = (uint16_t)(65536·0.003·9.14/3.3) = 544 — and the time it takes is printed
// (target ≤ 1 s in Pyodide for a whole set).
import { readFileSync } from 'node:fs';
import { describe, it, expect } from 'vitest';
import { bootPulab } from './pulab-node';

const DIR = new URL('../data/headers/st/', import.meta.url);
const FILES = ['pmsm_motor_parameters.h', 'drive_parameters.h', 'power_stage_parameters.h', 'parameters_conversion.h',
  'parameters_conversion_g4xx.h'].map((name) => ({ name, text: readFileSync(new URL(name, DIR), 'utf8') }));

describe('the decode kind in Pyodide', () => {
  it('the ST set: vendor, folded integers, the round trip at 0 LSB; timed', async () => {
    const pulab = await bootPulab();
    const req = JSON.stringify({ files: FILES });
    pulab.raw('decode', req); // warm: imports
    const times: number[] = [];
    let r: { ok: boolean; decode: { vendor: string; macros: Record<string, { value: number }>; roundtrip: { macros: Record<string, { delta_lsb?: number }> } } } | null = null;
    for (let i = 0; i < 5; i++) {
      const t0 = performance.now();
      r = JSON.parse(pulab.raw('decode', req));
      times.push(performance.now() - t0);
    }
    times.sort((a, b) => a - b);
    console.log(`decode of the 5-file ST set in Pyodide: ${times[2].toFixed(1)} ms median, ${times[0].toFixed(1)} ms min`);
    expect(r?.ok).toBe(true);
    expect(r?.decode.vendor).toBe('st');
    expect(r?.decode.macros.C1.value).toBe(477);
    expect(r?.decode.macros.CURRENT_CONV_FACTOR.value).toBe(544);
    expect(r?.decode.roundtrip.macros.PID_TORQUE_KP_DEFAULT.delta_lsb).toBe(0);
  }, 120_000);
});
