import { describe, it, expect } from 'vitest';
import { codeSearch, codeStateFromSearch, differingVars, prefill, traceRequest, type CodeState } from '../../web/src/code-share';

describe('codeStateFromSearch: the "Your code" state from ?code=…', () => {
  const cases: [string, CodeState | null][] = [
    ['', null],
    ['?embed=vendor', null],
    ['?code=long%20a%20%3D%201%3B', { code: 'long a = 1;', target: 'c28x', vs: 'arm', set: {}, entry: '' }],
    ['?code=x&target=arm&vs=&set.gMotorInfo.Voltage=6554', { code: 'x', target: 'arm', vs: '', set: { 'gMotorInfo.Voltage': '6554' }, entry: '' }],
    ['?code=x&set.=1&set.a=0x10', { code: 'x', target: 'c28x', vs: 'arm', set: { a: '0x10' }, entry: '' }],
    ['?code=x&entry=pi_step&set.s.kp=3', { code: 'x', target: 'c28x', vs: 'arm', set: { 's.kp': '3' }, entry: 'pi_step' }],
  ];
  for (const [search, want] of cases) it(`${search || '(empty)'} → ${JSON.stringify(want)}`, () => expect(codeStateFromSearch(search)).toEqual(want));
});

describe('codeSearch round-trips through codeStateFromSearch', () => {
  const states: CodeState[] = [
    { code: 'Uint16 v;\nlong x = v * 10; // 100% & more?', target: 'c28x', vs: 'arm', set: { v: '6554' }, entry: '' },
    { code: '#define K (1<<4)\n', target: 'msp430', vs: '', set: {}, entry: '' },
    { code: 'int f(int *p) { return *p; }', target: 'arm', vs: '', set: { '*p': '-1' }, entry: 'f' },
  ];
  for (const s of states) it(`${JSON.stringify(s.code)} on ${s.target}`, () => expect(codeStateFromSearch(codeSearch(s))).toEqual(s));
  it('embed=code first, empty values dropped', () => {
    expect(codeSearch({ code: 'a', target: 'arm', vs: 'c28x', set: { a: '', b: '2' } }, true)).toBe('?embed=code&code=a&target=arm&vs=c28x&set.b=2');
  });
});

describe('prefill: firmware names, then raw inputs by the last name part', () => {
  const report = {
    vendor: { raw: { Voltage: 17, Current: 150, LD: 60 }, LD: { value: 1045 }, maxu: { value: 15790080 } },
    current_pi: { d: { pm_kp: 1180, pm_ki: 4720 }, step_example: { error: 410, integral: 0 } },
  };
  const cases: [string[], Record<string, [number, string]>][] = [
    [['gMotorInfo.Voltage', 'gMotorExtInfo.LD', 'm_x'], { 'gMotorInfo.Voltage': [17, 'vendor.raw.Voltage'], 'gMotorExtInfo.LD': [60, 'vendor.raw.LD'] }],
    [['gMotorExtPer.LD', 'maxu', 'pm_kp_d', 'pm_error_id'], { 'gMotorExtPer.LD': [1045, 'vendor.LD.value'], maxu: [15790080, 'vendor.maxu.value'], pm_kp_d: [1180, 'current_pi.d.pm_kp'], pm_error_id: [410, 'current_pi.step_example.error'] }],
    [['Current', 'p->Voltage'], { Current: [150, 'vendor.raw.Current'], 'p->Voltage': [17, 'vendor.raw.Voltage'] }],
    [['toString', 'constructor', 'pm_kp_q'], {}],
  ];
  for (const [names, want] of cases) {
    it(`${names.join(', ')} → ${JSON.stringify(want)}`, () => {
      const got = Object.fromEntries(Object.entries(prefill(names, report)).map(([k, v]) => [k, [v.value, v.source]]));
      expect(got).toEqual(want);
    });
  }
  it('no report → nothing', () => expect(prefill(['Voltage'], null)).toEqual({}));
});

describe('traceRequest: typed values win over the report', () => {
  const s: CodeState = { code: 'c', target: 'c28x', vs: 'arm', set: { 'g.Voltage': ' 6554 ', 'g.Current': '' } };
  it('typed, report, absent', () => {
    expect(traceRequest(s, 'arm', ['g.Voltage', 'g.Current', 'g.Other'], { vendor: { raw: { Voltage: 17, Current: 150 } } }))
      .toEqual({ code: 'c', target: 'arm', set: { 'g.Voltage': '6554', 'g.Current': 150 } });
  });
});

describe('differingVars', () => {
  const a = { x: { value: 4 }, y: { value: 1 }, z: { value: null } };
  it('x differs, y equal, z null on both', () => expect(differingVars(a, { x: { value: 65540 }, y: { value: 1 }, z: { value: null } })).toEqual(['x']));
  it('no comparison → none', () => expect(differingVars(a, undefined)).toEqual([]));
});
