// The worker protocol: every message in both directions is a member of a typed union
// (in the spirit of stlite's types.ts), and every request kind has its request and reply types.
// The worker only forwards JSON text to pulab.api.call_json.

import type { ReplyBody, Request } from './generated/api-types';
import type { Json } from './json';

export type { Json } from './json';
/** What each request kind sends and answers (pulab.schema.api_shapes, generated). */
export type { ReplyBody, Request } from './generated/api-types';
export type ApiKind = keyof Request;

/** An error as data (docs/contract.md, Errors): `code` and `params` from pulab's catalog, the text in
 * both languages made from them. Worker-side failures (no reply from Python) have no code. The
 * tracer's errors say where in the code (`line`, `column`) and, once the code compiled, its `inputs`. */
export type ApiErr = {
  ok: false; field: string; message: string; message_zh?: string;
  code?: string; params?: Record<string, Json>;
  line?: number; column?: number; inputs?: string[];
  /** The tracer's: the functions the code defines, whenever it parsed (to pick the entry). */
  functions?: string[];
  /** The tracer's: the statement macros the code defines (entries too). */
  macros?: string[];
};
/** A kind's reply when it succeeds. */
export type Ok<K extends ApiKind> = { ok: true } & ReplyBody[K];
/** The reply to each kind: its body, or an error (`reply.ok` tells them apart). */
export type Reply = { [K in ApiKind]: Ok<K> | ApiErr };
/** Any reply, as the worker forwards it. */
export type ApiResult = Reply[ApiKind];

/** The kinds computed in slices (`pulab.api.call_json_steps`, a generator yielding between
 * slices): a newer call on the same channel cancels a running one between two slices
 * (`superseded`). */
export const STEPPED_KINDS: readonly ApiKind[] = ['report', 'prove', 'prove.integer', 'trace.prove'];

/**
 * The channel of the page's own numbers: a queued call on it is computed before every other
 * queued call (the code panel's traces, the vendors' report, another frame's sweep), so a panel
 * asking Python for something never delays the numbers.
 */
export const PRIORITY_CHANNEL = 'report';

/** Main thread → worker. */
export type MainToWorker =
  /**
   * `warm: false`: the page has no form to type in (an embed), so its first report does not start
   * the runtime's warm-up runs (web/src/worker-logic.ts); a page that has one does.
   */
  | { type: 'init'; indexURL: string; timeoutMs?: number; warm?: boolean }
  | {
      type: 'call';
      id: number;
      kind: ApiKind;
      /** JSON text handed to the Python function unchanged. */
      payload: string;
      /**
       * Calls sharing a channel are coalesced: only the newest queued one is computed, and a
       * running call of a STEPPED_KINDS kind is cancelled when a newer one arrives.
       */
      channel?: string;
    };

export type BootStage = 'runtime' | 'snapshot' | 'files' | 'import' | 'ready';
/** Where a runtime came from: the build's memory snapshot, or a full boot of Pyodide. */
export type BootFrom = 'snapshot' | 'full';

/** Worker → main thread. */
export type WorkerToMain =
  | { type: 'progress'; stage: BootStage; fraction: number; ms: number }
  | { type: 'ready'; bootMs: number; pyodideVersion: string; from?: BootFrom; note?: string }
  | { type: 'fatal'; message: string }
  | { type: 'result'; id: number; kind: ApiKind; result: ApiResult; ms: number }
  | { type: 'superseded'; id: number };

export function isWorkerToMain(x: unknown): x is WorkerToMain {
  if (typeof x !== 'object' || x === null) return false;
  const t = (x as { type?: unknown }).type;
  return t === 'progress' || t === 'ready' || t === 'fatal' || t === 'result' || t === 'superseded';
}
