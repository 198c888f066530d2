// Issue 14: what the status line says when Python cannot start.
import { describe, it, expect } from 'vitest';
import { describeError } from '../../web/src/worker-logic';

describe('describeError: a boot failure names what failed, never [object Object]', () => {
  const cases: [string, unknown, string][] = [
    ['Error', new Error('boom'), 'boom'],
    ['HTTP response-like', { status: 404, url: 'https://x/pyodide/python_stdlib.zip' }, 'HTTP 404 for https://x/pyodide/python_stdlib.zip'],
    ['event-like', { type: 'error' }, 'error event'],
    ['object with message', { message: 'no network' }, 'no network'],
    ['plain object', { a: 1 }, '{"a":1}'],
    ['string', 'text', 'text'],
    ['undefined', undefined, 'undefined'],
  ];
  for (const [name, e, want] of cases) it(`${name} → ${want}`, () => expect(describeError(e)).toBe(want));
});
