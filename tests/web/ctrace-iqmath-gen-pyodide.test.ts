// IQmath library calls and generated sequence inputs in Pyodide (the worker's runtime): the same
// JSON as CPython's CLI, number for number, and what 1,000 generated calls cost there.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { describe, it, expect } from 'vitest';
import { bootPulab } from './pulab-node';

const ROOT = join(__dirname, '../..');
const CODE = `long acc, y_div, y_sin, y_frac;
long f(long e)
{
  acc = _IQrsmpy(acc, _IQ(0.99)) + e;
  y_div = _IQdiv(acc, _IQ(3.0));
  y_sin = _IQsinPU(acc);
  y_frac = _IQfrac(acc);
  return _IQatan2PU(y_sin, _IQ(0.5));
}
`;
const GEN = { e: 'noise:amp=200000,dist=gauss,seed=3' };

describe('IQmath calls and generated inputs in Pyodide', () => {
  it('equal CPython over 1,000 calls; the flagged calls are flagged', async () => {
    const pulab = await bootPulab();
    const req = { code: CODE, target: 'c28x', entry: 'f', calls: 1000, set: { acc: 0 }, gen: GEN };
    const t0 = performance.now();
    const got = JSON.parse(pulab.raw('trace', JSON.stringify(req)));
    const ms = performance.now() - t0;
    const want = JSON.parse(execFileSync('python3', ['-m', 'pulab', 'trace', '-', '--entry', 'f', '--calls', '1000', '--set', 'acc=0',
      '--gen', `e=${GEN.e}`], { cwd: ROOT, env: { ...process.env, PYTHONPATH: join(ROOT, 'py') }, input: CODE, maxBuffer: 1 << 26 }).toString());
    expect(got.ok).toBe(true);
    expect(got.generated).toEqual(want.generated);
    expect(got.calls).toEqual(want.calls);
    expect(got.calls.every((c: { flags: string[] }) => c.flags.includes('not_bit_exact'))).toBe(true);
    console.log(`IQmath + generated sequence in Pyodide: 1000 calls in ${ms.toFixed(0)} ms`);
  }, 120_000);
});
