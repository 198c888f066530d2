// The worker protocol: every message in both directions is a member of a typed union
// (in the spirit of stlite's types.ts). The worker only forwards JSON text to pulab.api.

/** JSON value. */
export type Json = null | boolean | number | string | Json[] | { [k: string]: Json };

/** The Python entry points the worker calls: `pulab.api.<fn>(text: str) -> str`. */
export const API_FUNCTIONS = {
  report: 'run_json',
  qcalc: 'qcalc_json',
  export: 'export_json',
  vendors: 'vendors_json',
  sweep: 'sweep_json', batch: 'batch_json',
  trace: 'trace_json',
  traceExamples: 'trace_examples_json',
  course: 'course_json',
} as const;
export type ApiKind = keyof typeof API_FUNCTIONS;

/**
 * Entry points that compute in slices: `pulab.api.<fn>(text)` returns a Python generator that
 * yields between slices and returns the same JSON text as the API_FUNCTIONS entry. A call of
 * such a kind on a channel runs slice by slice, and a newer call on its channel cancels it
 * (`superseded`) between two slices.
 */
export const STEPPED_FUNCTIONS = { report: 'run_json_steps' } as const satisfies Partial<Record<ApiKind, string>>;
export type SteppedKind = keyof typeof STEPPED_FUNCTIONS;

/**
 * The channel of the page's own numbers: a queued call on it is computed before every other
 * queued call (the code panel's traces, the vendors' report, another frame's sweep), so a panel
 * asking Python for something never delays the numbers.
 */
export const PRIORITY_CHANNEL = 'report';

/** Main thread → worker. */
export type MainToWorker =
  | { type: 'init'; indexURL: string; timeoutMs?: number }
  | {
      type: 'call';
      id: number;
      kind: ApiKind;
      /** JSON text handed to the Python function unchanged. */
      payload: string;
      /**
       * Calls sharing a channel are coalesced: only the newest queued one is computed, and a
       * running call of a STEPPED_FUNCTIONS kind is cancelled when a newer one arrives.
       */
      channel?: string;
    };

export type BootStage = 'runtime' | 'snapshot' | 'files' | 'import' | 'ready';
/** Where a runtime came from: the build's memory snapshot, or a full boot of Pyodide. */
export type BootFrom = 'snapshot' | 'full';

/** What pulab.api returns (parsed). */
export type ApiOk = { ok: true; [k: string]: Json };
/** An error as data (docs/contract.md, Errors): `code` and `params` from pulab's catalog, the text in
 * both languages made from them. Worker-side failures (no reply from Python) have no code. */
export type ApiErr = {
  ok: false; field: string; message: string; message_zh?: string;
  code?: string; params?: Record<string, Json>;
};
export type ApiResult = ApiOk | ApiErr;

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
