// The worker script, run as a SharedWorker (one Python runtime for every tab and iframe of the
// origin) or, where there is none (Chrome for Android), as a dedicated Worker of one page.
// Thin glue between ports, Pyodide and worker-logic.ts.
import { loadPyodide, version } from 'pyodide';
import { SNAPSHOT } from 'virtual:pulab-build';
import { SnapshotUnpacker, restoreSparsely } from './snapshot-pack';
import { createRuntimeHost, describeError, fastOrFull, type BootProgress, type FsInit, type PyodideLike } from './worker-logic';
import type { MainToWorker, WorkerToMain } from './protocol';

/**
 * Free a buffer's memory now. A worker idle after its boot may not collect garbage for minutes:
 * the snapshot (31 MB) and its download chunks (31 MB more) stayed in every browser's memory
 * (PSS 56 MB lower after a forced collection). ArrayBuffer.prototype.transfer(0) detaches the
 * buffer and releases its backing store at once; without it (older browsers) the GC does it later.
 */
function release(buf: ArrayBufferLike): void {
  const b = buf as ArrayBuffer & { transfer?: (length: number) => ArrayBuffer; detached?: boolean };
  if (typeof b.transfer === 'function' && !b.detached) b.transfer(0);
}

/**
 * The snapshot's download, unpacked into a heap-sized buffer as it arrives (web/src/snapshot-pack.ts):
 * `heap` at once (Pyodide sizes its memory from it and compiles its wasm meanwhile), `started`
 * once the server has answered (a refused snapshot rejects here, before Pyodide starts), `done`
 * when the last byte is in place.
 */
function fetchSnapshot(url: string, snap: { size: number; bytes: number }, progress: BootProgress): { heap: Uint8Array; unpacker: SnapshotUnpacker; started: Promise<void>; done: Promise<void> } {
  const unpacker = new SnapshotUnpacker(new Uint8Array(snap.size));
  const response = fetch(url).then((res) => {
    if (!res.ok || !res.body) throw new Error(`${url}: HTTP ${res.status}`);
    return res.body;
  });
  const done = response.then(async (body) => {
    const reader = body.getReader();
    let at = 0;
    for (;;) {
      const { done: end, value } = await reader.read();
      if (end) break;
      unpacker.push(value);
      at += value.length;
      release(value.buffer);
      progress('runtime', 0.05 + 0.6 * Math.min(1, at / snap.bytes));
    }
    unpacker.finish();
    progress('snapshot', 0.7);
  });
  done.catch(() => undefined);
  return { heap: unpacker.heap, unpacker, started: response.then(() => undefined), done };
}

async function load(indexURL: string, progress: BootProgress, fsInit?: FsInit) {
  const full = async (): Promise<PyodideLike> => loadPyodide({ indexURL, packages: [], fsInit });
  const snap = SNAPSHOT;
  const fast = snap && snap.pyodideVersion === version
    ? async () => {
        // Pyodide takes the snapshot's buffer once the server has answered, and only its size
        // matters until it restores the heap: the wasm streams in and compiles, and the stdlib
        // downloads, while the snapshot does. Its `fsInit` hook runs after the wasm is
        // instantiated and before the heap is restored; it waits for the last byte (and forever
        // if the download fails: then `done` rejects below and the normal boot takes over).
        const { heap, unpacker, started, done } = fetchSnapshot(`${indexURL}${snap.file}`, snap, progress);
        let undo: (() => void) | null = null;
        const [py] = await Promise.all([
          loadPyodide({
            indexURL,
            packages: [],
            _loadSnapshot: started.then(() => heap),
            fsInit: async (fs) => {
              // Unwritten sources are written (or their failure named) by the host after the boot;
              // the heap is never restored from a partial snapshot.
              await fsInit?.(fs).catch(() => undefined);
              await done.catch(() => new Promise<never>(() => undefined));
              undo = restoreSparsely(heap, unpacker.runs);
            },
          }).finally(() => undo?.()),
          done,
        ]);
        // Pyodide keeps its config, and with it the 30 MB snapshot, for the runtime's lifetime; the
        // snapshot is in the runtime's memory now, so its bytes go.
        const internals: unknown = '_api' in py ? py._api : undefined;
        const config: unknown = typeof internals === 'object' && internals !== null && 'config' in internals ? internals.config : undefined;
        if (typeof config === 'object' && config !== null) Reflect.deleteProperty(config, '_loadSnapshot');
        release(heap.buffer);
        return py;
      }
    : null;
  return fastOrFull(fast, full);
}

// 200 warm-up runs after the first report: measured against 0, 40 and 100 side by side (first 8
// keystrokes, 5 fresh pages each), the Python time of the first keystrokes fell from p90 20 ms to
// 7.8 ms (100: 17 ms; 40: no change); they cost 0.7–0.9 s of this worker's idle time, once (traced).
// The pulab sources (0.9 MB of text) load beside the runtime, not as part of this script: this
// script's compilation comes before every download of the boot.
const sources = import('./pysources').then((m) => m.PULAB_FILES);
sources.catch(() => undefined);
const host = createRuntimeHost(load, sources, { warmRuns: 200 });

type Port = { postMessage(m: WorkerToMain): void; onmessage: ((ev: MessageEvent<MainToWorker>) => void) | null };
function serve(port: Port): void {
  const onMessage = host.connect((m) => port.postMessage(m));
  port.onmessage = (ev) => onMessage(ev.data);
}

// Alive while this lock is held: the browser releases it when the worker dies (crash, killed),
// which a page can see even while Python is busy (rpc.ts, PulabClient's liveness check).
void (navigator as Navigator & { locks?: LockManager }).locks?.request(`pulab-alive-${self.name}`, () => new Promise<never>(() => undefined));

// A SharedWorker's scope has `onconnect` (one port per page); a dedicated Worker's scope is the port.
if ('onconnect' in self) self.onconnect = (ev: MessageEvent) => ev.ports.forEach(serve);
else serve(self);
// Pyodide fetches some files on the side; when one fails, the boot fails with its own message
// (above) and the side promise's rejection must not surface as an uncaught error on the page.
self.addEventListener('unhandledrejection', (ev) => {
  ev.preventDefault();
  console.warn('pulab worker:', describeError(ev.reason));
});
