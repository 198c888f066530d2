// Vendor profiles: the panel's pure helpers, and the profiles' golden vectors
// (tests/golden/profiles, from the independent numpy oracle) through Pyodide as the worker runs them.
import { describe, it, expect, beforeAll } from 'vitest';
import { readdirSync, readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { join } from 'node:path';
import { bootPulab, type NodePulab } from './pulab-node';
import { profilesSection } from '../../web/src/panels/vendors';
import { gainFields, VENDORS, type Vendor } from '../../web/src/vendors';

describe('gainFields: vendor and axis → the names of its two current-loop integers', () => {
  const cases: [Vendor, 'd' | 'q', [string, string]][] = [
    ['inovance', 'd', ['pm_kp', 'pm_ki']],
    ['ti', 'q', ['Kp_Iq', 'Ki_Iq']],
    ['ti', 'd', ['Kp_Id', 'Ki_Id']],
    ['nxp', 'q', ['M1_Q_KP_GAIN', 'M1_Q_KI_GAIN']],
    ['st', 'd', ['PID_FLUX_KP_DEFAULT', 'PID_FLUX_KI_DEFAULT']],
    ['st', 'q', ['PID_TORQUE_KP_DEFAULT', 'PID_TORQUE_KI_DEFAULT']],
    ['microchip', 'd', ['KIP', 'KII']],
  ];
  for (const [v, a, want] of cases) it(`${v} ${a} → ${want.join(', ')}`, () => expect(gainFields(v, a)).toEqual(want));
});

describe('profilesSection: field texts → the "profiles" input section or the field at fault', () => {
  const cases: [Record<string, string>, unknown][] = [
    [{}, { ok: true, section: {} }],
    [{ 'profiles.ti.full_scale_current_a': '10' }, { ok: true, section: { ti: { full_scale_current_a: 10 } } }],
    [{ 'profiles.ti.global_q': '20', 'profiles.st.rshunt_ohm': '3e-3' }, { ok: true, section: { ti: { global_q: 20 }, st: { rshunt_ohm: 0.003 } } }],
    [{ 'profiles.nxp.i_max_a': 'abc' }, { ok: false, field: 'profiles.nxp.i_max_a', error: 'number' }],
    [{ 'profiles.ti.global_q': '2.5' }, { ok: false, field: 'profiles.ti.global_q', error: 'integer' }],
  ];
  for (const [hw, want] of cases) it(`${JSON.stringify(hw)} → ${JSON.stringify(want)}`, () => expect(profilesSection(hw)).toEqual(want));
});

const DIR = fileURLToPath(new URL('../golden/profiles/', import.meta.url));
const files = readdirSync(DIR).filter((f) => f.endsWith('.json')).sort();
type Rec = { value: number; ideal: number; si: number; shift?: number };
let pulab: NodePulab;
beforeAll(async () => {
  pulab = await bootPulab();
});

describe('profiles golden vectors through pulab.api.call_json("report", …) in Pyodide', () => {
  it('finds the oracle files', () => expect(files.length).toBeGreaterThanOrEqual(5));
  for (const f of files) {
    it(f, () => {
      const gold = JSON.parse(readFileSync(join(DIR, f), 'utf8')) as { input: Record<string, unknown>; expected: Record<Vendor, Record<string, Rec>> };
      const out = JSON.parse(pulab.raw('report', JSON.stringify({ ...gold.input, profiles: gold.input.profiles ?? {} })));
      expect(out.ok).toBe(true);
      const bad: string[] = [];
      for (const v of VENDORS) {
        for (const [k, e] of Object.entries(gold.expected[v])) {
          const c = out.report.profiles[v].constants[k];
          if (!c || c.value !== e.value) bad.push(`${v}.${k}: ${c?.value} != ${e.value}`);
          else for (const key of ['ideal', 'si'] as const) {
            if (Math.abs(c[key] - e[key]) > 1e-9 * Math.abs(e[key])) bad.push(`${v}.${k}.${key}: ${c[key]} != ${e[key]}`);
          }
        }
      }
      expect(bad).toEqual([]);
    });
  }
});

describe('the vendors.* kinds of pulab.api.call_json in Pyodide', () => {
  const seed = { motor: { rated_voltage_v: 17, rated_current_a: 1.5, rated_freq_hz: 220, rs_ohm: 1.5, ld_h: 6e-4, lq_h: 6e-4, bemf_v: 12, pole_pairs: 4 }, drive: { udc_v: 24, ts_s: 1e-4 } };
  for (const [v, word] of [['ti', 'USER_MTR1_KP_IQ_IQ'], ['nxp', 'M1_Q_KP_GAIN'], ['st', 'PID_TORQUE_KP_DEFAULT'], ['microchip', 'KIP_SCALE'], ['inovance', 'PULAB_RPM']]) {
    it(`header ${v} → #define ${word}`, () => {
      const out = JSON.parse(pulab.raw('vendors.header', JSON.stringify({ input: seed, profile: v })));
      expect(out.ok).toBe(true);
      expect(out.text).toContain(`#define ${word}`);
    });
  }
  it('translate inovance 1180/4720 (q) → back at 1180/4720', () => {
    const out = JSON.parse(pulab.raw('vendors.translate', JSON.stringify({ input: seed, from: 'inovance', axis: 'q', values: { pm_kp: 1180, pm_ki: 4720 } })));
    expect(out.ok).toBe(true);
    expect(out.translation.round_trip.values).toEqual({ pm_kp: 1180, pm_ki: 4720 });
  });
  it('translate with a fractional integer → error at translate.values.KIP, Chinese too', () => {
    const out = JSON.parse(pulab.raw('vendors.translate', JSON.stringify({ input: seed, from: 'microchip', axis: 'q', values: { KIP: 1.5, KII: 3 } })));
    expect(out.ok).toBe(false);
    expect(out.field).toBe('translate.values.KIP');
    expect(out.message_zh).toMatch(/[\u4e00-\u9fff]/);
  });
});
