// The worker protocol: every message in both directions is a member of a typed union
// (in the spirit of stlite's types.ts), and every request kind has its request and reply types.
// The worker only forwards JSON text to pulab.api.call_json.

import type { BatchChunk, BatchRequest, Audit, AuditRequest, CodeProof, CodeProveRequest, Proof, Proposal, ProveEntry, ProveRequest, QcalcRequest, QFormat, QResult, Trace, TraceExample, TraceRequest, Translation, TranslateRequest } from './generated/api-types';
import type { Chunk, Plan, Points, Summary } from './family/types';
import type { Report } from './generated/report-types';
import type { Input, Json } from './json';

export type { Json } from './json';

/** A sweep request (docs/contract.md, "Sweep"): the motor, one or two axes, the profile. */
export interface SweepRequest {
  input: Input;
  x: SweepAxis;
  y?: SweepAxis;
  profile?: string;
}
export interface SweepAxis { path: string; start: number; stop: number; n: number; scale: 'linear' | 'log' }

/**
 * What each request kind sends: `pulab.api.call_json(kind, text)` gets the JSON text of
 * `Request[kind]`. `kind` is the one dispatch key (docs/contract.md, "API").
 */
export interface Request {
  report: Input;
  qcalc: QcalcRequest;
  'export.header': { input: Input };
  'export.csv_current': { input: Input };
  'export.csv_pll': { input: Input };
  sweep: SweepRequest;
  'sweep.plan': SweepRequest;
  'sweep.chunk': SweepRequest & { start: number; count: number };
  'sweep.merge': SweepRequest & { summaries: Summary[] };
  batch: BatchRequest;
  trace: TraceRequest;
  'trace.examples': Record<string, never>;
  'trace.prove': CodeProveRequest;
  'vendors.header': { input: Input; profile: string };
  'vendors.translate': TranslateRequest;
  prove: ProveRequest;
  'prove.plan': ProveRequest;
  'prove.integer': ProveRequest & { name: string };
  'prove.summary': ProveRequest & { integers: Record<string, ProveEntry> };
  'prove.propose': ProveRequest;
  'course.spec': Record<string, never>;
  'course.check': { input: Input; id: string; answer: string };
  'course.answers': { input: Input };
  'course.trainees': { start: number | string; count: number | string };
  audit: AuditRequest;
}
export type ApiKind = keyof Request;

/** What each kind answers when it succeeds (besides `ok: true`). */
export interface ReplyBody {
  report: { report: Report };
  qcalc: { format: QFormat; result: QResult };
  'export.header': { text: string };
  'export.csv_current': { text: string };
  'export.csv_pll': { text: string };
  sweep: { sweep: Plan & { points: Points; summary: Summary } };
  'sweep.plan': { plan: Plan };
  'sweep.chunk': { chunk: Chunk };
  'sweep.merge': { summary: Summary };
  batch: BatchChunk;
  trace: Trace;
  'trace.examples': { examples: TraceExample[]; targets: string[] };
  'trace.prove': { proof: CodeProof };
  'vendors.header': { text: string };
  'vendors.translate': { translation: Translation };
  prove: { proof: Proof };
  'prove.plan': { plan: { names: string[]; raw_box: Record<string, [number, number]> } };
  'prove.integer': { integer: ProveEntry };
  'prove.summary': { proof: Proof };
  'prove.propose': { proposal: Proposal };
  'course.spec': { exercises: ExerciseSpec[] };
  'course.check': { result: { id: string; state: 'correct' | 'wrong'; expected: Json; tolerance: Tolerance } };
  'course.answers': { answers: Record<string, { chapter: string; expected: Json; unit: string; tolerance: Tolerance }> };
  'course.trainees': { trainees: { n: number; input: Input }[] };
  audit: { audit: Audit };
}

/** An exercise's stated tolerance (pulab.analyses.exercises): data and its text in both languages. */
export interface Tolerance { kind: 'exact' | 'abs' | 'rel' | 'range'; value?: number; en: string; zh: string }
export interface ExerciseSpec { id: string; chapter: string; kind: string; unit: string; choices: string[]; tolerance: Tolerance }

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
  | { type: 'init'; indexURL: string; timeoutMs?: number }
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
