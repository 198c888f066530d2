// Long Python jobs (a sweep, a batch) as a sequence of small worker calls: between two calls the
// worker serves the page's reports, the page draws its progress bar, and Cancel stops the job.
import type { PulabClient } from '../rpc';
import type { ApiErr, Ok, Request } from '../protocol';

export interface ChunkJob {
  cancelled: boolean;
}

/** Time in Python one call should take: a report typed meanwhile waits at most about this long. */
export const CHUNK_TARGET_MS = 40;

/** The next chunk's size from the last one's: aim at CHUNK_TARGET_MS, within [min, max]. */
export function nextChunkSize(size: number, ms: number, min = 5, max = 1000): number {
  return Math.max(min, Math.min(max, Math.round(size * CHUNK_TARGET_MS / Math.max(ms, 1))));
}

/**
 * Call `kind` with `payload(start, count)` for consecutive ranges covering 0 … total−1, in order,
 * starting with `size` items and adapting it to the time Python takes (a loaded machine gets
 * smaller chunks). `onChunk` gets each result; returns 'done', 'cancelled' or the first error.
 */
export async function runChunks<K extends 'sweep.chunk' | 'batch'>(
  client: PulabClient,
  kind: K,
  total: number,
  size: number,
  payload: (start: number, count: number) => Request[K],
  onChunk: (result: Ok<K>, done: number) => void,
  job: ChunkJob,
): Promise<'done' | 'cancelled' | ApiErr> {
  for (let start = 0; start < total;) {
    if (job.cancelled) return 'cancelled';
    const count = Math.min(size, total - start);
    const { result, ms } = await client.call(kind, payload(start, count));
    if (!result.ok) return result;
    if (job.cancelled) return 'cancelled';
    start += count;
    onChunk(result, start);
    size = nextChunkSize(count, ms);
  }
  return 'done';
}
