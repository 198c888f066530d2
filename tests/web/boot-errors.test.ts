// What the status line says when Python cannot start.
import { describe, it, expect } from 'vitest';
import { describeError, missingRuntimeFile } from '../../web/src/worker-logic';

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

describe('missingRuntimeFile: a definitive HTTP error on an essential file fails the boot at once', () => {
  const fakeFetch = (status: Record<string, number | 'offline'>) => ((url: string) => {
    const s = status[String(url).split('/').pop() ?? ''] ?? 200;
    return s === 'offline' ? Promise.reject(new TypeError('Failed to fetch')) : Promise.resolve({ status: s } as Response);
  }) as unknown as typeof fetch;
  const settle = (p: Promise<never>) => Promise.race([p.then(() => 'resolved', (e: Error) => e.message), new Promise((r) => setTimeout(() => r('pending'), 50))]);
  const cases: [string, Record<string, number | 'offline'>, string][] = [
    ['all there', {}, 'pending'],
    ['wasm 404', { 'pyodide.asm.wasm': 404 }, 'HTTP 404 for x/pyodide.asm.wasm'],
    ['mjs 500', { 'pyodide.asm.mjs': 500 }, 'HTTP 500 for x/pyodide.asm.mjs'],
    ['offline (cached files may still load)', { 'pyodide.asm.wasm': 'offline', 'pyodide.asm.mjs': 'offline' }, 'pending'],
    ['a non-essential file missing', { 'python_stdlib.zip': 404 }, 'pending'],
  ];
  for (const [name, status, want] of cases) it(`${name} → ${want}`, async () => expect(await settle(missingRuntimeFile('x/', fakeFetch(status)))).toBe(want));
});
