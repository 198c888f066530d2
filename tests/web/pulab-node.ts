// One Pyodide (from node_modules/pyodide) per test process, booted through the same worker
// logic and the same file-loading function as the browser worker.
import { loadPyodide } from 'pyodide';
import { fileURLToPath } from 'node:url';
import { createWorkerLogic, type PyodideLike } from '../../web/src/worker-logic';
import { PULAB_FILES } from '../../web/src/pysources';
import type { ApiKind, ApiResult, WorkerToMain } from '../../web/src/protocol';

export const INDEX_URL = fileURLToPath(new URL('../../node_modules/pyodide/', import.meta.url));

export interface NodePulab {
  call(kind: ApiKind, payload: string, channel?: string): Promise<{ result: ApiResult; text: string; ms: number }>;
  raw(kind: ApiKind, payload: string): string;
  messages: WorkerToMain[];
  bootMs: number;
  py: PyodideLike;
}

let shared: Promise<NodePulab> | null = null;

export function bootPulab(): Promise<NodePulab> {
  shared ??= (async () => {
    const messages: WorkerToMain[] = [];
    const waiters = new Map<number, (m: WorkerToMain) => void>();
    let py!: PyodideLike;
    const logic = createWorkerLogic(
      (m) => {
        messages.push(m);
        if (m.type === 'result' || m.type === 'superseded') waiters.get(m.id)?.(m);
      },
      async (indexURL) => (py = (await loadPyodide({ indexURL })) as unknown as PyodideLike),
      PULAB_FILES,
    );
    const t0 = performance.now();
    logic.onMessage({ type: 'init', indexURL: INDEX_URL, timeoutMs: 60_000 });
    await logic.ready;
    const bootMs = performance.now() - t0;
    const api = py.pyimport('pulab.api') as { call_json(kind: string, text: string): string };
    let next = 1;
    return {
      messages,
      bootMs,
      py,
      raw: (kind, payload) => api.call_json(kind, payload),
      call(kind, payload, channel) {
        const id = next++;
        return new Promise((resolve, reject) => {
          waiters.set(id, (m) => {
            waiters.delete(id);
            if (m.type === 'result') resolve({ result: m.result, text: JSON.stringify(m.result), ms: m.ms });
            else reject(new Error('superseded'));
          });
          logic.onMessage({ type: 'call', id, kind, payload, channel });
        });
      },
    };
  })();
  return shared;
}
