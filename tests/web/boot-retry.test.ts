// A failed boot is tried again with backoff before it is fatal (rpc.ts PulabClient).
import { describe, it, expect, vi, afterEach } from 'vitest';
import { BOOT_RETRY_MS, PulabClient, type WorkerLike } from '../../web/src/rpc';
import type { MainToWorker } from '../../web/src/protocol';

/** A worker whose n-th boot fails while n < failures, then reports ready. */
function fakeWorker(failures: number): WorkerLike & { inits: number } {
  const w = {
    inits: 0,
    onmessage: null as WorkerLike['onmessage'],
    onerror: null as WorkerLike['onerror'],
    postMessage(m: MainToWorker) {
      if (m.type !== 'init') return;
      const n = w.inits++;
      const reply = n < failures ? { type: 'fatal', message: `HTTP 503 for python_stdlib.zip (${n})` } : { type: 'ready', bootMs: 1, pyodideVersion: 'x' };
      queueMicrotask(() => w.onmessage?.({ data: reply } as MessageEvent));
    },
  };
  return w;
}

afterEach(() => vi.useRealTimers());

describe('boot retries', () => {
  const cases: [number, boolean, number][] = [
    [0, true, 0], [1, true, 1], [BOOT_RETRY_MS.length, true, BOOT_RETRY_MS.length], [BOOT_RETRY_MS.length + 1, false, BOOT_RETRY_MS.length],
  ];
  for (const [failures, ready, retries] of cases)
    it(`${failures} failed boots → ${ready ? 'ready' : 'fatal'} after ${retries} retries`, async () => {
      vi.useFakeTimers();
      const w = fakeWorker(failures);
      const seen: number[] = [];
      let fatal = '';
      const c = new PulabClient(w, { onRetry: (_m, _n, _of, delay) => seen.push(delay), onFatal: (m) => (fatal = m) });
      c.init('x/', 60_000);
      await vi.runAllTimersAsync();
      expect(c.ready).toBe(ready);
      expect(seen).toEqual(BOOT_RETRY_MS.slice(0, retries));
      expect(w.inits).toBe(1 + retries);
      expect(fatal === '').toBe(ready);
      if (!ready) expect(fatal).toMatch(/HTTP 503 for python_stdlib.zip/);
    });

  it('a call made during the retries is answered once Python is ready', async () => {
    vi.useFakeTimers();
    const w = fakeWorker(1);
    const post = w.postMessage.bind(w);
    w.postMessage = (m: MainToWorker) => {
      post(m);
      if (m.type === 'call') queueMicrotask(() => w.onmessage?.({ data: { type: 'result', id: m.id, kind: m.kind, result: { ok: true }, ms: 1 } } as MessageEvent));
    };
    const c = new PulabClient(w);
    c.init('x/');
    const call = c.call('report', {});
    await vi.runAllTimersAsync();
    await expect(call).resolves.toMatchObject({ result: { ok: true } });
  });
});

describe('a lost runtime: a ready worker that stops answering', () => {
  it('a call unanswered for lostAfterMs fails the client with lost = true', async () => {
    vi.useFakeTimers();
    const w = fakeWorker(0); // ready, then silent: calls are never answered
    let fatal = '';
    const c = new PulabClient(w, { onFatal: (m) => (fatal = m) });
    c.init('x/');
    await vi.runAllTimersAsync();
    expect(c.ready).toBe(true);
    const call = c.call('report', {}, 'report', 15_000);
    const settled = expect(call).rejects.toThrow(/did not answer for 15 s/);
    await vi.advanceTimersByTimeAsync(15_000);
    await settled;
    expect([c.lost, fatal]).toEqual([true, 'Python did not answer for 15 s']);
  });
  it('an answered call leaves the client alone', async () => {
    vi.useFakeTimers();
    const w = fakeWorker(0);
    const post = w.postMessage.bind(w);
    w.postMessage = (m: MainToWorker) => {
      post(m);
      if (m.type === 'call') queueMicrotask(() => w.onmessage?.({ data: { type: 'result', id: m.id, kind: m.kind, result: { ok: true }, ms: 1 } } as MessageEvent));
    };
    const c = new PulabClient(w);
    c.init('x/');
    await vi.runAllTimersAsync();
    await c.call('report', {}, 'report', 15_000);
    await vi.advanceTimersByTimeAsync(20_000);
    expect([c.lost, c.fatalMessage]).toEqual([false, null]);
  });
});
