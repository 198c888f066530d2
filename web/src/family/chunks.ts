// Long Python jobs (a sweep, a batch) as a sequence of small worker calls: between two calls the
// worker serves the page's reports, the page draws its progress bar, and Cancel stops the job.
import type { PulabClient } from '../rpc';
import type { ApiKind, ApiResult } from '../protocol';

export interface ChunkJob {
  cancelled: boolean;
}

/**
 * Call `kind` with `payload(start, count)` for start = 0, size, 2·size … < total, in order.
 * `onChunk` gets each result; returns 'done', 'cancelled' or the first error result.
 */
export async function runChunks(
  client: PulabClient,
  kind: ApiKind,
  total: number,
  size: number,
  payload: (start: number, count: number) => unknown,
  onChunk: (result: ApiResult & { ok: true }, done: number) => void,
  job: ChunkJob,
): Promise<'done' | 'cancelled' | (ApiResult & { ok: false })> {
  for (let start = 0; start < total; start += size) {
    if (job.cancelled) return 'cancelled';
    const count = Math.min(size, total - start);
    const { result } = await client.call(kind, payload(start, count));
    if (!result.ok) return result;
    if (job.cancelled) return 'cancelled';
    onChunk(result, start + count);
  }
  return 'done';
}
