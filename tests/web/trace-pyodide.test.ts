// pulab.ctrace in Pyodide (the worker's runtime): the example and the seed's flux lines,
// c28x vs arm, with the values worked out by hand (C99 6.3.1.8 with each target's int width).
import { describe, it, expect } from 'vitest';
import { bootPulab } from './pulab-node';

const FLUX = `Uint16 BemfVolt, Voltage;
Ulong m_Ulong;
m_Ulong = ((Long)BemfVolt <<12) / (Voltage *10); //Q12
long out = _IQmpy(-3, 5);
`;

describe('the trace kind in Pyodide', () => {
  const cases: [string, number, number][] = [
    // 6554*10 = 65540 wraps to 4 in 16-bit unsigned int: 120<<12 / 4 = 122880; on arm / 65540 = 7
    ['c28x', 122880, -1],
    ['arm', 7, -1],
  ];
  for (const [target, ulong, out] of cases) {
    it(`flux line on ${target}: m_Ulong = ${ulong}, _IQmpy(-3, 5) = ${out} (floor)`, async () => {
      const pulab = await bootPulab();
      const r = JSON.parse(pulab.raw('trace', JSON.stringify({ code: FLUX, target, set: { BemfVolt: 120, Voltage: 6554 } })));
      expect(r.ok).toBe(true);
      expect(r.vars.m_Ulong.value).toBe(ulong);
      expect(r.vars.out.value).toBe(out);
    }, 60_000);
  }
  it('bad code: line and column, Chinese message', async () => {
    const pulab = await bootPulab();
    const r = JSON.parse(pulab.raw('trace', JSON.stringify({ code: 'long a = 1;\nlong b = a / 0;' })));
    expect([r.ok, r.field, r.line, r.column]).toEqual([false, 'code', 2, 14]);
    expect(r.message_zh).toContain('除以零');
  }, 60_000);
});
