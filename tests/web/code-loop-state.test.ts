// A link or stored state that carries a routine in the current loop (sim.current.code, set by the
// Code view's "Use in the loop"): kept as it is (pulab checks its contents), a wrong shape named.
import { describe, it, expect } from 'vitest';
import { getPath, initialInput } from '../../web/src/state';
import { LOOP_FIELDS } from '../../web/src/fields';

const link = (v: unknown): string => `#in=${encodeURIComponent(JSON.stringify(v))}`;
const CODE = { text: 'long e, u; u = e;', target: 'c28x', scale: 'st', error: 'e', output: 'u',
  set: { k: { d: 'current_pi.d.pm_kp', q: 'current_pi.q.pm_kp' } }, integral_shift: 12 };

describe('sim.current.code in links', () => {
  it('every schema field of the binding is known to the page', () => {
    expect(LOOP_FIELDS.map((f) => f.path.split('.').pop())).toEqual(
      ['text', 'target', 'entry', 'scale', 'reference', 'feedback', 'error', 'output', 'set', 'integral', 'integral_shift']);
  });
  it('a whole binding is kept, its set object as given', () => {
    const r = initialInput(link({ motor: { rs_ohm: 2 }, sim: { current: { axis: 'q', code: CODE } } }), null);
    expect(r.problems).toEqual([]);
    expect(getPath(r.input, 'sim.current.code')).toEqual(CODE);
  });
  it.each([
    ['text that is a number', { ...CODE, text: 5 }, 'sim.current.code.text'],
    ['set that is a list', { ...CODE, set: [1] }, 'sim.current.code.set'],
    ['an unknown scale', { ...CODE, scale: 'acme' }, 'sim.current.code.scale'],
    ['an unknown key', { ...CODE, outputs: 'u' }, 'sim.current.code.outputs'],
  ])('%s is dropped and named, the rest kept', (_, code, path) => {
    const r = initialInput(link({ sim: { current: { code } } }), null);
    expect(r.problems.map((p) => p.path)).toEqual([path]);
    expect(getPath(r.input, 'sim.current.code.output')).toBe('u');
  });
});
