// The chunk runner of the sweep and batch panels: ranges cover every item once, in order; sizes
// adapt to the time Python takes; cancel and errors stop the job.
import { describe, expect, it } from 'vitest';
import { nextChunkSize, runChunks, CHUNK_TARGET_MS } from '../../web/src/family/chunks';
import type { PulabClient } from '../../web/src/rpc';

function fakeClient(msPerItem: number, failAt = -1) {
  const calls: { start: number; count: number }[] = [];
  const client = {
    call: async (_kind: string, payload: { start: number; count: number }) => {
      calls.push(payload);
      if (payload.start === failAt) return { result: { ok: false, field: 'x', message: 'bad' }, ms: 1 };
      return { result: { ok: true, n: payload.count }, ms: payload.count * msPerItem };
    },
  } as unknown as PulabClient;
  return { client, calls };
}

describe('nextChunkSize', () => {
  it.each([
    [100, CHUNK_TARGET_MS, 100],
    [100, 2 * CHUNK_TARGET_MS, 50],
    [100, CHUNK_TARGET_MS / 4, 400],
    [100, 100_000, 5],
    [1000, 1, 1000],
  ])('size %i after %f ms → %i', (size, ms, want) => {
    expect(nextChunkSize(size, ms)).toBe(want);
  });
});

describe('runChunks', () => {
  it('covers 0 … total−1 once, in order, with sizes adapting to the time taken', async () => {
    const { client, calls } = fakeClient(2); // 2 ms per item → 20 items per chunk
    const seen: number[] = [];
    const x = { path: 'motor.rs_ohm', start: 1, stop: 2, n: 137, scale: 'linear' as const };
    const end = await runChunks(client, 'sweep.chunk', 137, 40, (start, count) => ({ input: {}, x, start, count }), (_r, done) => seen.push(done), { cancelled: false });
    expect(end).toBe('done');
    let next = 0;
    for (const c of calls) {
      expect(c.start).toBe(next);
      next += c.count;
    }
    expect(next).toBe(137);
    expect(calls[1].count).toBe(20);
    expect(seen[seen.length - 1]).toBe(137);
  });
  it('stops on cancel and on the first error', async () => {
    const job = { cancelled: false };
    const { client } = fakeClient(1);
    const end = await runChunks(client, 'batch', 500, 10, (start, count) => ({ csv: '', start, count }), () => { job.cancelled = true; }, job);
    expect(end).toBe('cancelled');
    const f = fakeClient(1, 0);
    const err = await runChunks(f.client, 'batch', 50, 10, (start, count) => ({ csv: '', start, count }), () => undefined, { cancelled: false });
    expect(err).toMatchObject({ ok: false, field: 'x' });
  });
});
