import { describe, it, expect } from 'vitest';
import { compareGolden, parseJsonExact } from './json-exact';

describe('parseJsonExact keeps ints and floats apart', () => {
  const cases: [string, unknown][] = [
    ['15022', 15022n],
    ['15022.0', 15022],
    ['-1e-3', -0.001],
    ['{"a":[1,2.5,"x",true,null]}', { a: [1n, 2.5, 'x', true, null] }],
  ];
  for (const [text, want] of cases) it(`${text} → ${String(want)}`, () => expect(parseJsonExact(text)).toEqual(want));
});

describe('compareGolden', () => {
  const cases: [string, string, string, number][] = [
    ['equal ints', '{"v":15022}', '{"v":15022}', 0],
    ['int vs different int', '{"v":15022}', '{"v":15023}', 1],
    ['int expected, float given', '{"v":15022}', '{"v":15022.0}', 1],
    ['float within 1e-12', '{"v":1.0}', '{"v":1.0000000000005}', 0],
    ['float beyond 1e-12', '{"v":1.0}', '{"v":1.00000000001}', 1],
    ['missing key', '{"v":1,"w":2}', '{"v":1}', 1],
    ['extra key in actual is fine', '{"v":1}', '{"v":1,"w":2}', 0],
    ['string', '{"s":"a"}', '{"s":"b"}', 1],
    ['array length', '{"a":[1,2]}', '{"a":[1]}', 1],
  ];
  for (const [name, e, a, n] of cases) it(`${name} → ${n} mismatch(es)`, () => expect(compareGolden(parseJsonExact(e), parseJsonExact(a))).toHaveLength(n));
});
