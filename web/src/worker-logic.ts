// Worker logic, independent of the browser: it gets a `post` function and a Pyodide loader,
// so vitest runs exactly this code on real Pyodide in Node.
import { API_FUNCTIONS, type ApiKind, type ApiResult, type MainToWorker, type WorkerToMain } from './protocol';

/** The part of the Pyodide API the worker uses. */
export interface PyodideLike {
  version: string;
  FS: { mkdirTree(path: string): void; writeFile(path: string, data: string): void };
  runPython(code: string): unknown;
  pyimport(name: string): unknown;
}

export type PyodideLoader = (indexURL: string) => Promise<PyodideLike>;

export const PY_ROOT = '/home/pyodide/pulab_src';

/**
 * Write the bundled py/pulab sources into Pyodide's file system under `root` and put `root` on
 * sys.path. Keys are glob paths such as '../../py/pulab/api.py'; everything from 'pulab/' on is kept.
 * Returns the number of files written.
 */
export function writePulab(py: PyodideLike, files: Record<string, string>, root = PY_ROOT): number {
  let n = 0;
  for (const [key, text] of Object.entries(files)) {
    const i = key.lastIndexOf('/pulab/');
    if (i < 0) continue;
    const rel = key.slice(i + 1);
    const path = `${root}/${rel}`;
    py.FS.mkdirTree(path.slice(0, path.lastIndexOf('/')));
    py.FS.writeFile(path, text);
    n++;
  }
  if (n === 0) throw new Error('no pulab sources were bundled (py/pulab/**/*.py)');
  py.runPython(`import sys\nif ${JSON.stringify(root)} not in sys.path: sys.path.insert(0, ${JSON.stringify(root)})`);
  return n;
}

/** Boot Pyodide with `load`, with a timeout (loadPyodide can hang instead of rejecting). */
export async function withTimeout<T>(p: Promise<T>, ms: number, what: string): Promise<T> {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const t = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what} did not finish within ${Math.round(ms / 1000)} s`)), ms);
  });
  try {
    return await Promise.race([p, t]);
  } finally {
    clearTimeout(timer);
  }
}

type PyApi = Record<string, (text: string) => string>;
type Call = Extract<MainToWorker, { type: 'call' }>;

/**
 * One readable line for anything thrown or rejected: an Error's message, an HTTP failure's status
 * and URL, an event's type — never "[object Object]" (a missing runtime file must be named).
 */
export function describeError(e: unknown): string {
  if (e instanceof Error) return e.message || e.name;
  if (typeof e === 'string') return e;
  if (e && typeof e === 'object') {
    const o = e as { message?: unknown; status?: unknown; url?: unknown; type?: unknown; constructor?: { name?: string } };
    if (typeof o.message === 'string' && o.message) return o.message;
    if (typeof o.status === 'number') return `HTTP ${o.status}${typeof o.url === 'string' ? ` for ${o.url}` : ''}`;
    if (typeof o.type === 'string') return `${o.type} event${typeof o.url === 'string' ? ` for ${o.url}` : ''}`;
    try {
      const json = JSON.stringify(e);
      if (json && json !== '{}') return json.slice(0, 200);
    } catch {
      /* cyclic */
    }
    return o.constructor?.name ?? 'unknown error';
  }
  return String(e);
}

export interface WorkerLogic {
  onMessage(msg: MainToWorker): void;
  /** Resolves when booted (for tests); rejects on a boot failure. */
  ready: Promise<void>;
}

const now = (): number => (typeof performance !== 'undefined' ? performance.now() : Date.now());

export function createWorkerLogic(
  post: (msg: WorkerToMain) => void,
  load: PyodideLoader,
  files: Record<string, string>,
): WorkerLogic {
  let api: PyApi | null = null;
  let resolveReady!: () => void;
  let rejectReady!: (e: unknown) => void;
  const ready = new Promise<void>((res, rej) => {
    resolveReady = res;
    rejectReady = rej;
  });
  ready.catch(() => undefined);
  const queue: Call[] = [];
  let scheduled = false;

  async function boot(indexURL: string, timeoutMs: number): Promise<void> {
    const t0 = now();
    try {
      post({ type: 'progress', stage: 'runtime', fraction: 0.05, ms: 0 });
      const py = await withTimeout(load(indexURL), timeoutMs, 'Loading the Python runtime (Pyodide)');
      post({ type: 'progress', stage: 'files', fraction: 0.8, ms: now() - t0 });
      writePulab(py, files);
      post({ type: 'progress', stage: 'import', fraction: 0.9, ms: now() - t0 });
      const mod = py.pyimport('pulab.api') as Record<string, unknown>;
      const fns: PyApi = {};
      for (const name of Object.values(API_FUNCTIONS)) {
        const f = mod[name];
        if (typeof f === 'function') fns[name] = f as (text: string) => string;
      }
      if (!fns.run_json) throw new Error('pulab.api.run_json is missing');
      api = fns;
      post({ type: 'progress', stage: 'ready', fraction: 1, ms: now() - t0 });
      post({ type: 'ready', bootMs: now() - t0, pyodideVersion: py.version });
      resolveReady();
      schedule();
    } catch (e) {
      const message = describeError(e);
      post({ type: 'fatal', message });
      rejectReady(e);
    }
  }

  function run(kind: ApiKind, payload: string): ApiResult {
    const fname = API_FUNCTIONS[kind];
    const f = api?.[fname];
    if (!f) return { ok: false, field: '', message: `pulab.api.${fname} is not available in this build` };
    try {
      return JSON.parse(f(payload)) as ApiResult;
    } catch (e) {
      const text = e instanceof Error ? e.message : String(e);
      const last = text.trim().split('\n').pop() ?? text;
      return { ok: false, field: '', message: `internal error in pulab.api.${fname}: ${last}` };
    }
  }

  function drain(): void {
    scheduled = false;
    if (!api) return;
    // Coalesce: for each channel only the newest queued call is computed.
    const newest = new Map<string, number>();
    queue.forEach((c, i) => {
      if (c.channel) newest.set(c.channel, i);
    });
    const batch = queue.splice(0, queue.length);
    batch.forEach((c, i) => {
      if (c.channel && newest.get(c.channel) !== i) {
        post({ type: 'superseded', id: c.id });
        return;
      }
      const t0 = now();
      const result = run(c.kind, c.payload);
      post({ type: 'result', id: c.id, kind: c.kind, result, ms: now() - t0 });
    });
  }

  function schedule(): void {
    if (scheduled || !api) return;
    scheduled = true;
    // A macrotask, so messages already posted to us are queued (and coalesced) first.
    setTimeout(drain, 0);
  }

  return {
    ready,
    onMessage(msg: MainToWorker): void {
      if (msg.type === 'init') {
        void boot(msg.indexURL, msg.timeoutMs ?? 60_000);
      } else if (msg.type === 'call') {
        queue.push(msg);
        schedule();
      }
    },
  };
}
