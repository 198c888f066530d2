// Starting a Python runtime from the page: one SharedWorker per kind, shared by every tab and
// iframe of the origin (an embed connects to a runtime that is already up), or a dedicated Worker
// where SharedWorker does not exist (Chrome for Android). <html data-runtime> says which.
import { PulabClient, type WorkerLike } from './rpc';
import type { MainToWorker } from './protocol';

/** Reports and the Q calculator; simulations and CSV exports (so a simulation never delays numbers). */
export type RuntimeKind = 'report' | 'sim';

/** Python's start-up may take this long without any progress before it counts as failed. */
const BOOT_IDLE_MS = 60_000;

function sharedWorker(kind: RuntimeKind): WorkerLike {
  // The literal `new SharedWorker(new URL(…))` lets Vite bundle the worker script.
  const sw = new SharedWorker(new URL('./worker.ts', import.meta.url), { type: 'module', name: `pulab-${kind}` });
  const port = sw.port;
  return {
    postMessage: (m: MainToWorker) => port.postMessage(m),
    get onmessage() {
      return port.onmessage;
    },
    set onmessage(f) {
      port.onmessage = f;
    },
    get onerror() {
      return sw.onerror as WorkerLike['onerror'];
    },
    set onerror(f) {
      sw.onerror = f as (ev: Event) => void;
    },
  };
}

function dedicatedWorker(kind: RuntimeKind): WorkerLike {
  return new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name: `pulab-${kind}` }) as unknown as WorkerLike;
}

export function startRuntime(kind: RuntimeKind): PulabClient {
  const shared = typeof SharedWorker === 'function';
  document.documentElement.dataset.runtime = shared ? 'shared' : 'dedicated';
  const client = new PulabClient(shared ? sharedWorker(kind) : dedicatedWorker(kind));
  client.init(new URL('pyodide/', document.baseURI).href, BOOT_IDLE_MS);
  return client;
}
