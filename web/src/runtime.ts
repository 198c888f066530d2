// Starting a Python runtime from the page: one SharedWorker per kind, shared by every tab and
// iframe of the origin (an embed connects to a runtime that is already up), or a dedicated Worker
// where SharedWorker does not exist (Chrome for Android) or is denied (a frame of another site in a
// browser that blocks third-party storage). <html data-runtime> says which.
import { PulabClient, type WorkerLike } from './rpc';
import type { MainToWorker } from './protocol';

/** Reports and the Q calculator; simulations and CSV exports (so a simulation never delays numbers). */
export type RuntimeKind = 'report' | 'sim';

/** Python's start-up may take this long without any progress before it counts as failed. */
const BOOT_IDLE_MS = 60_000;

function sharedWorker(name: string): WorkerLike {
  // The literal `new SharedWorker(new URL(…))` lets Vite bundle the worker script.
  const sw = new SharedWorker(new URL('./worker.ts', import.meta.url), { type: 'module', name });
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

function dedicatedWorker(name: string): WorkerLike {
  return new Worker(new URL('./worker.ts', import.meta.url), { type: 'module', name });
}

/**
 * A SharedWorker, or a dedicated Worker when the shared one fails before it has said anything: a
 * browser that blocks third-party storage (Chromium's default for a frame of another site, e.g. an
 * embed in a docs page) denies SharedWorker there. What was posted meanwhile is posted again.
 */
function sharedOrDedicated(name: string): WorkerLike {
  let target = sharedWorker(name);
  let answered = false;
  const sent: MainToWorker[] = [];
  const w: WorkerLike = {
    postMessage: (m) => {
      if (!answered) sent.push(m);
      target.postMessage(m);
    },
    onmessage: null,
    onerror: null,
  };
  const follow = (t: WorkerLike): void => {
    t.onmessage = (ev) => {
      answered = true;
      sent.length = 0;
      w.onmessage?.(ev);
    };
  };
  follow(target);
  target.onerror = (ev) => {
    if (answered) return w.onerror?.(ev);
    document.documentElement.dataset.runtime = 'dedicated';
    target = dedicatedWorker(name);
    follow(target);
    target.onerror = (e) => w.onerror?.(e);
    for (const m of sent) target.postMessage(m);
  };
  return w;
}

/**
 * A client of the `kind` runtime. `generation` > 0 after a lost runtime: a new name, so a hung
 * SharedWorker (which the page cannot terminate) is not joined again.
 */
export function startRuntime(kind: RuntimeKind, generation = 0): PulabClient {
  const shared = typeof SharedWorker === 'function';
  const name = generation ? `pulab-${kind}-${generation}` : `pulab-${kind}`;
  document.documentElement.dataset.runtime = shared ? 'shared' : 'dedicated';
  const client = new PulabClient(shared ? sharedOrDedicated(name) : dedicatedWorker(name), {}, `pulab-alive-${name}`);
  // An embed (?embed=…) has no form to type in: its reports do not warm the runtime up.
  client.init(new URL('pyodide/', document.baseURI).href, BOOT_IDLE_MS, !new URLSearchParams(location.search).has('embed'));
  return client;
}
