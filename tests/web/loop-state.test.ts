// The loop analysis rides on the simulation request only: the plain report stays fast.
import { describe, it, expect } from 'vitest';
import { SEED_INPUT, initialInput, reportInput, simInput, type Input } from '../../web/src/state';
import { effectiveInput } from '../../web/src/fields';

describe('analysis: reportInput drops it, simInput asks for Bode data, the robustness view and the speed response', () => {
  const cases: [string, Input, unknown][] = [
    ['no analysis → none added', { motor: { rs_ohm: 1 }, sim: {} }, undefined],
    ['delay only → bode', { analysis: { delay: 'none' } }, { delay: 'none', bode: true, robust: { samples: 200 } }],
    ['speed → response', { analysis: { speed: { inertia_kg_m2: 0.001 } } }, { bode: true, robust: { samples: 200 }, speed: { inertia_kg_m2: 0.001, response: true } }],
  ];
  for (const [name, inp, want] of cases) {
    it(name, () => {
      expect(reportInput(inp).analysis).toBeUndefined();
      expect(simInput(inp).analysis).toEqual(want);
    });
  }
  it('the seed input carries the realistic delay and a 60° target', () => {
    expect(SEED_INPUT.analysis).toMatchObject({ delay: 'computation_pwm', target_phase_margin_deg: 60 });
  });
  it('a shared link without analysis gets the defaults (so the loop panel has numbers)', () => {
    const hash = `#in=${encodeURIComponent(JSON.stringify({ motor: { rs_ohm: 2 } }))}`;
    expect(initialInput(hash, null).input.analysis).toEqual(SEED_INPUT.analysis);
  });
  it('the target bandwidth is not sent while designing for a phase margin', () => {
    const eff = effectiveInput({ analysis: { design: 'phase_margin', target_bandwidth_hz: 300, target_phase_margin_deg: 50 } });
    expect(eff.analysis).toEqual({ design: 'phase_margin', target_phase_margin_deg: 50 });
  });
});
