// Worker logic, independent of the browser: one Python runtime serving any number of clients
// (the tabs and iframes connected to a SharedWorker, or the one page of a dedicated Worker). It
// gets a `post` function per client and a Pyodide loader, so vitest runs exactly this code on
// real Pyodide in Node.
import { PRIORITY_CHANNEL, STEPPED_KINDS, type ApiKind, type ApiResult, type BootFrom, type BootStage, type MainToWorker, type WorkerToMain } from './protocol';

/** The part of the Pyodide API the worker uses. */
export interface PyodideLike {
  version: string;
  FS: PyFS;
  runPython(code: string): unknown;
  pyimport(name: string): unknown;
}
/** The part of Pyodide's (Emscripten's) file system the worker uses. */
export interface PyFS {
  mkdirTree(path: string): void;
  writeFile(path: string, data: string | Uint8Array): void;
}

/** Progress of a boot (a download, a step); every call also tells the boot watchdog it is alive. */
export type BootProgress = (stage: BootStage, fraction: number) => void;
/**
 * Writes the pulab sources into a file system before Python starts; a loader that can, passes it
 * to Pyodide as its `fsInit` hook (then the files are written while the runtime's downloads are
 * still under way, not after). A loader that does not call it leaves the writing to the host.
 */
export type FsInit = (fs: PyFS) => Promise<void>;
/** A loader returns the runtime, or the runtime and where it came from (a snapshot or a full boot). */
export type PyodideLoader = (indexURL: string, progress: BootProgress, fsInit?: FsInit) => Promise<PyodideLike | { py: PyodideLike; from: BootFrom; note?: string }>;

export const PY_ROOT = '/home/pyodide/pulab_src';

/**
 * Write the bundled py/pulab sources into `fs` under `root`. Keys are glob paths such as
 * '../../py/pulab/api.py'; everything from 'pulab/' on is kept. Returns the number of files
 * written. The text is encoded here (Emscripten's own encoding of a string, char by char in
 * JavaScript, took 2–3 times as long).
 */
export function writePulabFiles(fs: PyFS, files: Record<string, string>, root = PY_ROOT): number {
  const utf8 = new TextEncoder();
  const made = new Set<string>();
  let n = 0;
  for (const [key, text] of Object.entries(files)) {
    const i = key.lastIndexOf('/pulab/');
    if (i < 0) continue;
    const rel = key.slice(i + 1);
    const path = `${root}/${rel}`;
    const dir = path.slice(0, path.lastIndexOf('/'));
    if (!made.has(dir)) {
      fs.mkdirTree(dir);
      made.add(dir);
    }
    fs.writeFile(path, utf8.encode(text));
    n++;
  }
  if (n === 0) throw new Error('no pulab sources were bundled (py/pulab/**/*.py)');
  return n;
}

/** Put `root` on sys.path (once). */
export function addPulabPath(py: PyodideLike, root = PY_ROOT): void {
  py.runPython(`import sys\nif ${JSON.stringify(root)} not in sys.path: sys.path.insert(0, ${JSON.stringify(root)})`);
}

/**
 * Write the bundled py/pulab sources into Pyodide's file system under `root` and put `root` on
 * sys.path. Returns the number of files written.
 */
export function writePulab(py: PyodideLike, files: Record<string, string>, root = PY_ROOT): number {
  const n = writePulabFiles(py.FS, files, root);
  addPulabPath(py, root);
  return n;
}

/** Boot Pyodide with `load`, with a timeout (loadPyodide can hang instead of rejecting). */
export async function withTimeout<T>(p: Promise<T>, ms: number, what: string): Promise<T> {
  const w = idleTimeout(ms, what);
  try {
    return await Promise.race([p, w.expired]);
  } finally {
    w.stop();
  }
}

/**
 * A timeout that `kick()` restarts: a slow download that keeps making progress is not a failure,
 * only `ms` without any progress is.
 */
export function idleTimeout(ms: number, what: string): { expired: Promise<never>; kick(): void; stop(): void } {
  let timer: ReturnType<typeof setTimeout> | undefined;
  let reject!: (e: Error) => void;
  const expired = new Promise<never>((_, rej) => {
    reject = rej;
  });
  expired.catch(() => undefined);
  const arm = (): void => {
    clearTimeout(timer);
    timer = setTimeout(() => reject(new Error(`${what} made no progress for ${Math.round(ms / 1000)} s`)), ms);
  };
  arm();
  return { expired, kick: arm, stop: () => clearTimeout(timer) };
}

/**
 * Boot from `fast` (the memory snapshot); if it is refused in any way, boot normally with `full`
 * and say why in `note`.
 */
export async function fastOrFull(
  fast: (() => Promise<PyodideLike>) | null,
  full: () => Promise<PyodideLike>,
): Promise<{ py: PyodideLike; from: BootFrom; note?: string }> {
  if (fast) {
    try {
      return { py: await fast(), from: 'snapshot' };
    } catch (e) {
      return { py: await full(), from: 'full', note: `snapshot refused: ${e instanceof Error ? e.message : String(e)}` };
    }
  }
  return { py: await full(), from: 'full' };
}

/** A Python generator as Pyodide hands it to JavaScript (a PyProxy). */
interface PyGenerator {
  next(): { done?: boolean; value?: unknown };
  return(value?: unknown): unknown;
  destroy(): void;
}
/** The two entry points of pulab.api every request goes through: `kind` is the one dispatch key. */
interface PyApi {
  call_json(kind: string, text: string): string;
  call_json_steps(kind: string, text: string): PyGenerator;
}
type Queued = { call: Call; post: Post; client: number };
type Call = Extract<MainToWorker, { type: 'call' }>;
type Post = (msg: WorkerToMain) => void;

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

/** Files every boot needs; Pyodide may wait forever on a missing wasm instead of failing. */
export const ESSENTIAL_FILES = ['pyodide.asm.mjs', 'pyodide.asm.wasm'];

/**
 * Rejects as soon as an essential runtime file answers with an HTTP error (a HEAD request each),
 * naming it; otherwise never settles. A network error proves nothing (offline with the files
 * cached) and is ignored.
 */
export function missingRuntimeFile(indexURL: string, fetchFn: typeof fetch = fetch): Promise<never> {
  return new Promise<never>((_, reject) => {
    for (const f of ESSENTIAL_FILES) {
      const url = `${indexURL}${f}`;
      fetchFn(url, { method: 'HEAD' }).then((r) => {
        if (r.status >= 400) reject(new Error(`HTTP ${r.status} for ${url}`));
      }, () => undefined);
    }
  });
}

export interface WorkerLogic {
  onMessage(msg: MainToWorker): void;
  /** Resolves when booted (for tests); rejects on a boot failure. */
  ready: Promise<void>;
}

export interface RuntimeHost {
  /** A new client (a page or an iframe): `post` reaches it; returns the handler of its messages. */
  connect(post: Post): (msg: MainToWorker) => void;
  /** Resolves when booted (for tests); rejects on a boot failure. */
  ready: Promise<void>;
}

/**
 * A macrotask later: calls the pages posted meanwhile are queued first. Not setTimeout(0): timers
 * nested five deep are clamped to 4 ms (HTML), and a stepped call yields once per slice — in
 * Chromium's worker 20 such yields took 70 ms by setTimeout against 0.3 ms by a MessageChannel
 * (whose messages queue with the pages' own, in order). Node (the tests) has setImmediate, which
 * leaves its timers their turn (a MessageChannel there starves them).
 */
export const nextTask: () => Promise<void> = (() => {
  const immediate = (globalThis as { setImmediate?: (f: () => void) => unknown }).setImmediate;
  if (typeof immediate === 'function') return () => new Promise<void>((res) => void immediate(res));
  if (typeof MessageChannel !== 'function') return () => new Promise<void>((res) => setTimeout(res, 0));
  const ch = new MessageChannel();
  const waiting: (() => void)[] = [];
  ch.port1.onmessage = () => waiting.shift()?.();
  return () => new Promise<void>((res) => {
    waiting.push(res);
    ch.port2.postMessage(null);
  });
})();

/** Boot progress is sent to the pages in steps of this fraction at least (and at each new stage). */
const PROGRESS_STEP = 0.01;

const now = (): number => (typeof performance !== 'undefined' ? performance.now() : Date.now());

/**
 * `warmRuns`: after the first report of a page with a form (an embed's does not count: on a docs
 * page of twelve panels the runs took a core from the other panels' start, all live 1.78 → 2.14 s,
 * side by side), compute it this many times more while the runtime is idle
 * (results dropped, one per macrotask, never ahead of a queued call). The engine optimizes the
 * Python interpreter's wasm code only once it has run for a while: the first keystrokes after a
 * boot took 10–25 ms in Python instead of 2–5 ms (with the engine told to optimize everything at
 * once, `--no-wasm-dynamic-tiering`, they took 2 ms from the first).
 */
export function createRuntimeHost(load: PyodideLoader, files: Record<string, string> | Promise<Record<string, string>>, opts: { warmRuns?: number } = {}): RuntimeHost {
  let api: PyApi | null = null;
  let resolveReady!: () => void;
  let rejectReady!: (e: unknown) => void;
  const ready = new Promise<void>((res, rej) => {
    resolveReady = res;
    rejectReady = rej;
  });
  ready.catch(() => undefined);
  const clients = new Set<Post>();
  /** What a client connecting late is told at once. */
  let state: 'idle' | 'booting' | 'ready' | 'failed' = 'idle';
  let lastProgress: WorkerToMain | null = null;
  let readyMsg: WorkerToMain | null = null;
  const queue: Queued[] = [];
  const clientIds = new Map<Post, number>();
  let scheduled = false;
  let draining = false;
  let warm: { payload: string; left: number } | null = null;
  /** Clients whose first report may start the warm-up (their `init` did not say `warm: false`). */
  const warmers = new Set<Post>();
  let warmTimer: ReturnType<typeof setTimeout> | undefined;

  const broadcast = (m: WorkerToMain): void => {
    for (const post of clients) post(m);
  };

  async function boot(indexURL: string, timeoutMs: number): Promise<void> {
    state = 'booting';
    const t0 = now();
    const watchdog = idleTimeout(timeoutMs, 'Loading the Python runtime (Pyodide)');
    let sent: { stage: BootStage; fraction: number } | null = null;
    const progress: BootProgress = (stage, fraction) => {
      watchdog.kick();
      lastProgress = { type: 'progress', stage, fraction, ms: now() - t0 };
      // The snapshot's download reports every network chunk (hundreds), and each message redraws
      // the status line of every connected page (12 panels: thousands of redraws while booting):
      // sent when the stage changes and per 1 % of the way.
      if (sent && sent.stage === stage && fraction - sent.fraction < PROGRESS_STEP) return;
      sent = { stage, fraction };
      broadcast(lastProgress);
    };
    try {
      progress('runtime', 0.05);
      const missing = typeof fetch === 'function' ? missingRuntimeFile(indexURL) : new Promise<never>(() => undefined);
      missing.catch(() => undefined);
      let written = false;
      const fsInit: FsInit = async (fs) => {
        writePulabFiles(fs, await files);
        written = true;
      };
      const loaded = await Promise.race([load(indexURL, progress, fsInit), watchdog.expired, missing]);
      watchdog.stop();
      const { py, from, note } = 'py' in loaded ? loaded : { py: loaded, from: undefined, note: undefined };
      progress('files', 0.8);
      if (!written) writePulabFiles(py.FS, await files);
      // A snapshot was taken with the sources' directory on sys.path; compiling even this one line
      // of Python cost 5–25 ms of a cold runtime.
      if (from !== 'snapshot') addPulabPath(py);
      progress('import', 0.9);
      const mod = py.pyimport('pulab.api') as Record<string, unknown>;
      // Everything imported so far lives as long as the runtime: out of the cyclic collector's
      // sight, a full collection during a report no longer walks the whole stdlib and pulab.
      // (Called, not run as source: no compilation.)
      const gc = py.pyimport('gc') as { freeze?: unknown } | undefined;
      if (typeof gc?.freeze === 'function') gc.freeze();
      else py.runPython('import gc; gc.freeze()');
      const { call_json, call_json_steps } = mod;
      if (typeof call_json !== 'function' || typeof call_json_steps !== 'function') throw new Error('pulab.api.call_json is missing');
      api = { call_json: call_json as PyApi['call_json'], call_json_steps: call_json_steps as PyApi['call_json_steps'] };
      progress('ready', 1);
      readyMsg = { type: 'ready', bootMs: now() - t0, pyodideVersion: py.version, ...(from ? { from } : {}), ...(note ? { note } : {}) };
      state = 'ready';
      broadcast(readyMsg);
      resolveReady();
      schedule();
    } catch (e) {
      watchdog.stop();
      const message = describeError(e);
      state = 'failed';
      broadcast({ type: 'fatal', message });
      rejectReady(e);
    }
  }

  /** Python's reply text, read as the reply its kind promises (docs/contract.md, "API"). */
  const reply = (text: unknown): ApiResult => JSON.parse(String(text)) as ApiResult;

  function run(kind: ApiKind, payload: string): ApiResult {
    if (!api) return { ok: false, field: '', message: 'pulab.api.call_json is not available in this build' };
    try {
      return reply(api.call_json(kind, payload));
    } catch (e) {
      return internalError(kind, e);
    }
  }

  function internalError(kind: string, e: unknown): ApiResult {
    const text = e instanceof Error ? e.message : String(e);
    const last = text.trim().split('\n').pop() ?? text;
    return { ok: false, field: '', message: `internal error in pulab.api.call_json(${JSON.stringify(kind)}): ${last}` };
  }

  const channelKey = (c: Queued): string | null => (c.call.channel ? `${c.client}:${c.call.channel}` : null);
  /** A newer call of the same client on the same channel is waiting. */
  const newerQueued = (c: Queued): boolean => {
    const key = channelKey(c);
    return key !== null && queue.some((q) => channelKey(q) === key);
  };

  /**
   * A call of a STEPPED_KINDS kind: one slice per macrotask, so calls posted meanwhile are
   * queued; null when a newer call on its channel cancelled it (the generator is closed).
   */
  async function runSteps(c: Queued, kind: ApiKind): Promise<ApiResult | null> {
    if (!api) return run(kind, c.call.payload);
    let gen: PyGenerator | null = null;
    try {
      gen = api.call_json_steps(kind, c.call.payload);
      for (;;) {
        const slice = gen.next();
        if (slice.done) return reply(slice.value);
        await nextTask();
        if (newerQueued(c)) {
          gen.return();
          return null;
        }
      }
    } catch (e) {
      return internalError(kind, e);
    } finally {
      gen?.destroy();
    }
  }

  const isStepped = (kind: ApiKind): boolean => STEPPED_KINDS.includes(kind);

  /** The oldest queued call on the priority channel, else the oldest queued call. */
  const takeNext = (): Queued | undefined => {
    const i = queue.findIndex((q) => q.call.channel === PRIORITY_CHANNEL);
    return queue.splice(Math.max(i, 0), 1)[0];
  };

  /** Compute the queued calls in order; calls posted during a stepped call join this loop. */
  async function drain(): Promise<void> {
    scheduled = false;
    if (!api || draining) return;
    draining = true;
    try {
      for (let c = takeNext(); c; c = takeNext()) {
        // Coalesce: for each client's channel only the newest queued call is computed.
        if (newerQueued(c)) {
          c.post({ type: 'superseded', id: c.call.id });
          continue;
        }
        const t0 = now();
        const { kind } = c.call;
        const result = c.call.channel && isStepped(kind) ? await runSteps(c, kind) : run(kind, c.call.payload);
        if (result === null) c.post({ type: 'superseded', id: c.call.id });
        else c.post({ type: 'result', id: c.call.id, kind, result, ms: now() - t0 });
        // The page's own report (not a simulation: same kind, another channel, seconds per run).
        if (warm === null && c.call.channel === PRIORITY_CHANNEL && result?.ok && warmers.has(c.post)) warm = { payload: c.call.payload, left: opts.warmRuns ?? 0 };
      }
    } finally {
      draining = false;
    }
    warmSoon();
  }

  /** One warm-up run per idle macrotask (see `warmRuns`); a queued call always goes first. */
  function warmSoon(): void {
    clearTimeout(warmTimer);
    if (!warm || warm.left <= 0) return;
    warmTimer = setTimeout(() => {
      if (!warm || draining || scheduled || queue.length > 0) return;
      warm.left--;
      run('report', warm.payload);
      warmSoon();
    }, 0);
  }

  function schedule(): void {
    if (scheduled || !api) return;
    scheduled = true;
    // A macrotask, so messages already posted to us are queued (and coalesced) first.
    setTimeout(() => void drain(), 0);
  }

  return {
    ready,
    connect(post) {
      clients.add(post);
      const client = clientIds.size + 1;
      clientIds.set(post, client);
      return (msg) => {
        if (msg.type === 'init') {
          if (msg.warm !== false) warmers.add(post);
          // A failed boot is tried again when a client asks again (a reload, a retry).
          if (state === 'idle' || state === 'failed') void boot(msg.indexURL, msg.timeoutMs ?? 60_000);
          else if (state === 'booting' && lastProgress) post(lastProgress);
          else if (state === 'ready' && readyMsg) post(readyMsg);
        } else if (msg.type === 'call') {
          queue.push({ call: msg, post, client });
          schedule();
        }
      };
    },
  };
}

/** One runtime, one client (a dedicated Worker; the vitest suites). */
export function createWorkerLogic(post: Post, load: PyodideLoader, files: Record<string, string>): WorkerLogic {
  const host = createRuntimeHost(load, files);
  return { ready: host.ready, onMessage: host.connect(post) };
}
