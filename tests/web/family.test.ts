// The sweep panel's page-side helpers: which inputs can be swept, and gathering chunk columns.
import { describe, expect, it } from 'vitest';
import { appendPoints, type Points } from '../../web/src/family/types';
import { sweepPaths } from '../../web/src/panels/sweep';

const pts = (x: number[], ld: (number | null)[], base?: (number | null)[]): Points => ({
  x, error: x.map(() => null), error_zh: x.map(() => null),
  integers: { 'vendor.LD': { value: ld, error_pct: ld.map((v) => (v === null ? null : 0.5)), status: ld.map((v) => (v === null ? 'div0' : 'ok')) } },
  intermediates: base ? { m_BaseL: base } : {},
});

describe('sweepPaths', () => {
  it.each([
    [{ current_loop: { method: 'bandwidth' } }, 'current_loop.bandwidth_hz', true],
    [{ current_loop: { method: 'bandwidth' } }, 'current_loop.pm_kp', false],
    [{ current_loop: { method: 'integers' } }, 'current_loop.pm_kp', true],
    [{}, 'raw.LD', true],
    [{}, 'motor.rated_voltage_v', true],
    [{}, 'conventions.base', false],
    [{}, 'sim.current.step_a', false],
  ])('%j: %s sweepable = %s', (input, path, want) => {
    expect(sweepPaths(input as never).includes(path)).toBe(want);
  });
});

describe('appendPoints', () => {
  it.each([
    ['first chunk is taken as is', null, pts([1, 2], [10, 11], [5, 4]), [1, 2], [10, 11], [5, 4]],
    ['columns concatenate in order', pts([1], [10], [5]), pts([2, 3], [null, 12], [0, 3]), [1, 2, 3], [10, null, 12], [5, 0, 3]],
    ['an intermediate missing in one chunk is null there', pts([1], [10]), pts([2], [11], [4]), [1, 2], [10, 11], [null, 4]],
  ])('%s', (_name, a, b, x, ld, base) => {
    const out = appendPoints(a as Points | null, b as Points);
    expect(out.x).toEqual(x);
    expect(out.integers['vendor.LD'].value).toEqual(ld);
    expect(out.integers['vendor.LD'].status.length).toBe(x.length);
    expect(out.intermediates.m_BaseL).toEqual(base);
  });
});
