// Main-thread client of the worker: typed calls returning promises, boot progress callbacks.
import { isWorkerToMain, type ApiKind, type ApiResult, type BootFrom, type BootStage, type MainToWorker, type Ok, type ApiErr, type Request } from './protocol';

/** A call's reply, as its kind promises, and the time spent in Python (ms). */
export interface CallResult<K extends ApiKind = ApiKind> {
  result: Ok<K> | ApiErr;
  ms: number;
}

export class Superseded extends Error {
  constructor() {
    super('superseded by a newer request');
  }
}

export interface RpcEvents {
  onProgress?(stage: BootStage, fraction: number): void;
  onReady?(bootMs: number, version: string): void;
  onFatal?(message: string): void;
  /** The boot failed and is tried again in `delayMs` (attempt `attempt` of `of`). */
  onRetry?(message: string, attempt: number, of: number, delayMs: number): void;
}

/** How often a pending call checks that its worker is still alive. */
const LIVENESS_MS = 1000;

/** Waits before each new boot attempt after a failed one (a network hiccup, a server restart). */
export const BOOT_RETRY_MS = [1000, 4000, 12000];

export interface WorkerLike {
  postMessage(m: MainToWorker): void;
  onmessage: ((ev: MessageEvent) => void) | null;
  onerror: ((ev: ErrorEvent) => void) | null;
}

export class PulabClient {
  private next = 1;
  private pending = new Map<number, { resolve(r: { result: ApiResult; ms: number }): void; reject(e: Error): void }>();
  private fatal: string | null = null;
  private watchdog: ReturnType<typeof setTimeout> | undefined;
  ready = false;
  bootMs = 0;
  version = '';
  /** Whether the runtime came from the build's memory snapshot or a full boot. */
  bootFrom: BootFrom = 'full';
  /** When each boot stage was first reported (performance.now()), for listeners that attach late. */
  stageAt: Partial<Record<BootStage, number>> = {};
  /** The last boot progress, for listeners that attach late. */
  progress: { stage: BootStage; fraction: number } = { stage: 'runtime', fraction: 0 };
  fatalMessage: string | null = null;

  /**
   * `aliveLock`: the Web Lock the worker holds for its lifetime (worker.ts). While a call is
   * pending, the lock is probed every LIVENESS_MS; if the page can take it, the worker is gone.
   */
  constructor(private worker: WorkerLike, public events: RpcEvents = {}, private aliveLock?: string) {
    worker.onmessage = (ev) => this.receive(ev.data);
    worker.onerror = (ev) => {
      ev.preventDefault?.(); // handled here: reported in the status line, not as an uncaught error
      this.fail(`the worker failed: ${ev.message || 'its script did not load'}`);
    };
  }

  /**
   * Start the boot. `timeoutMs` bounds the time without progress (the worker applies it to
   * Pyodide's start-up); a watchdog here, restarted by every progress message, bounds the worker itself.
   */
  init(indexURL: string, timeoutMs = 60_000, warm = true): void {
    this.boot = { type: 'init', indexURL, timeoutMs, warm };
    this.worker.postMessage(this.boot);
    this.idleMs = timeoutMs + 5000;
    this.armWatchdog();
  }

  private boot: MainToWorker | null = null;
  private attempts = 0;
  private retryTimer: ReturnType<typeof setTimeout> | undefined;

  /**
   * A failed boot (a file that did not load, no progress for too long) is tried again with
   * backoff before it counts as fatal; the runtime boots again when asked again. Calls wait.
   */
  private bootFailed(message: string): void {
    const delay = BOOT_RETRY_MS[this.attempts];
    if (delay === undefined || !this.boot || this.ready) return this.fail(message);
    this.attempts++;
    clearTimeout(this.watchdog);
    this.events.onRetry?.(message, this.attempts, BOOT_RETRY_MS.length, delay);
    this.retryTimer = setTimeout(() => {
      if (this.fatal || this.ready || !this.boot) return;
      this.worker.postMessage(this.boot);
      this.armWatchdog();
    }, delay);
  }

  private idleMs = 65_000;
  private armWatchdog(): void {
    clearTimeout(this.watchdog);
    this.watchdog = setTimeout(() => {
      if (!this.ready) this.bootFailed(`Python made no progress for ${Math.round(this.idleMs / 1000)} s`);
    }, this.idleMs);
  }

  /**
   * Call pulab.api in the worker. `lostAfterMs`: a ready runtime that has not answered by then is
   * lost (crashed, killed or hung): the client fails with a message and `lost` set, so the page
   * can start a new runtime (a report takes milliseconds, so a short limit is safe for it).
   */
  call<K extends ApiKind>(kind: K, req: Request[K], channel?: string, lostAfterMs?: number): Promise<CallResult<K>> {
    if (this.fatal) return Promise.reject(new Error(this.fatal));
    const id = this.next++;
    return new Promise<CallResult<K>>((resolve, reject) => {
      // The worker answers a call with the reply of the call's own kind (pulab.api.call_json).
      this.pending.set(id, { resolve: (r) => resolve({ result: r.result as Ok<K> | ApiErr, ms: r.ms }), reject });
      this.worker.postMessage({ type: 'call', id, kind, payload: JSON.stringify(req), channel });
      if (lostAfterMs !== undefined && this.ready)
        setTimeout(() => {
          if (this.pending.has(id)) this.markLost(`Python did not answer for ${Math.round(lostAfterMs / 1000)} s`);
        }, lostAfterMs);
      if (this.ready) this.watchLiveness();
    });
  }

  /** The runtime was ready and then died or stopped answering (see `call`). */
  lost = false;
  private liveness: ReturnType<typeof setInterval> | undefined;

  private markLost(message: string): void {
    this.lost = true;
    this.fail(message);
  }

  /** Probe the worker's lock while calls are pending (a dead worker never answers them). */
  private watchLiveness(): void {
    const locks = typeof navigator === 'undefined' ? undefined : (navigator as Navigator & { locks?: LockManager }).locks;
    if (!this.aliveLock || !locks || this.liveness !== undefined) return;
    const name = this.aliveLock;
    this.liveness = setInterval(() => {
      if (!this.pending.size || this.fatal) {
        clearInterval(this.liveness);
        this.liveness = undefined;
        return;
      }
      void locks.request(name, { ifAvailable: true }, (lock) => lock !== null)
        .then((free) => {
          if (free && this.ready) this.markLost('the Python worker stopped');
        })
        .catch(() => undefined);
    }, LIVENESS_MS);
  }

  private fail(message: string): void {
    if (this.fatal) return;
    this.fatal = message;
    this.fatalMessage = message;
    clearTimeout(this.watchdog);
    clearTimeout(this.retryTimer);
    for (const p of this.pending.values()) p.reject(new Error(message));
    this.pending.clear();
    this.events.onFatal?.(message);
  }

  private receive(m: unknown): void {
    if (!isWorkerToMain(m)) return;
    switch (m.type) {
      case 'progress':
        // A failed boot's loader may still report progress in the background: the failure stands.
        if (this.fatal) break;
        this.progress = { stage: m.stage, fraction: m.fraction };
        this.stageAt[m.stage] ??= performance.now();
        if (!this.ready) this.armWatchdog();
        this.events.onProgress?.(m.stage, m.fraction);
        break;
      case 'ready':
        this.ready = true;
        this.bootMs = m.bootMs;
        this.version = m.pyodideVersion;
        this.bootFrom = m.from ?? 'full';
        clearTimeout(this.watchdog);
        this.events.onReady?.(m.bootMs, m.pyodideVersion);
        break;
      case 'fatal':
        if (this.ready) this.fail(m.message);
        else this.bootFailed(m.message);
        break;
      case 'result': {
        const p = this.pending.get(m.id);
        this.pending.delete(m.id);
        p?.resolve({ result: m.result, ms: m.ms });
        break;
      }
      case 'superseded': {
        const p = this.pending.get(m.id);
        this.pending.delete(m.id);
        p?.reject(new Superseded());
        break;
      }
    }
  }
}
