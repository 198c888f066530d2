// The bodies of pulab.api's requests and replies that are not a report (docs/contract.md, "API"):
// the Q calculator, the C tracer and the vendor translator. protocol.ts pairs them by kind.
import type { Input } from './json';

/** `qcalc`: a value to encode or a raw reading to decode (pulab.qcalc.qcalc). */
export interface QcalcRequest {
  format: string;
  word_bits?: number;
  rounding?: string;
  overflow?: string;
  value?: number | string;
  raw?: number | string;
}
export interface QFormat { name: string; word_bits: number; frac_bits: number; signed: boolean; min: number; max: number; resolution: number }
export interface QResult { raw: number; hex: string; value: number; error: number; flags: string[] }

/** `trace`: C code, its target and the values of its inputs. */
export interface TraceRequest {
  code: string;
  target?: string;
  set?: Record<string, string | number>;
  global_q?: number;
  define?: string[];
  /** The function of the code to run, or a statement macro as `NAME` / `NAME(TYPE, …)` (absent: the statements outside functions). */
  entry?: string;
  zero_unset?: boolean;
  /** A sequence: call the entry this many times (the reply is a {@link TraceSequence}). */
  calls?: number | string;
  /** Generated per-call inputs: input name → `KIND:PARAM=VALUE,…` (pulab.ctrace.generate). */
  gen?: Record<string, string>;
}
/** The reply of `trace` with `calls`/`gen`: each call's result, the first wrap/overflow/clamp,
 * and the values the generators gave. */
export interface TraceSequence {
  target: string; entry: string; inputs: string[];
  calls: { return: TraceVar | null; vars: Record<string, TraceVar>; flags: string[] }[];
  first_event: { call: number; line: number; kind: string; name: string } | null;
  generated?: Record<string, { spec: string; type: string; values: number[]; clamped: number; first_clamped: number | null }>;
}
/** A term; a call of a function of the code carries `call` and the statements it ran. */
export interface TraceTerm { expr: string; line: number; column: number; type: string; value: number | null; hex: string | null; flags: string[]; var?: string; rounding?: 'floor' | 'toward_zero'; lost?: number; call?: string; steps?: TraceLine[] }
export interface TraceLine { line: number; column: number; code: string; var: string | null; type: string; value: number | null; hex: string | null; flags: string[]; terms: TraceTerm[]; spelling?: string; input?: boolean; branch?: string; points_to?: string }
/** A variable after the run; a pointer (`c_type` "pointer", `bits` null) names its object in `points_to`. */
export interface TraceVar { type: string; c_type: string; bits: number | null; signed: boolean; value: number | null; hex: string | null; input: boolean; q?: number; real?: number; si?: number; unit?: string; q_auto?: boolean; points_to?: string | null }
export interface Trace {
  target: string; global_q: number; inputs: string[]; vars: Record<string, TraceVar>; steps: TraceLine[];
  entry: string | null; functions: string[];
  /** The function-like macros that assign (each can be the entry: `NAME` or `NAME(TYPE, …)`). */
  macros: string[];
  rounding: Record<string, { floor: number; toward_zero: number; max_lost: number }>;
}
export interface TraceExample { id: string; title: string; title_zh: string; code: string }

/** `trace.prove`: the tracer's request plus integer ranges of inputs (docs/contract.md, "Code proof"). */
export interface CodeProveRequest extends TraceRequest { range: Record<string, [number | string, number | string]>; budget?: number }
/** A failure a statement is proven free of (or shown to have). */
export type CodeFailure = 'signed_overflow' | 'unsigned_wrap' | 'conversion' | 'shift_count' | 'division_by_zero' | 'index' | 'error';
export interface CodeStatement {
  line: number; column: number; code: string; var: string | null;
  type: string | null; word: [number, number] | null; range: [number, number] | null;
  /** The exact value the statement's store converts (before C's modulo rule). */
  computed: [number, number] | null;
  verdict: 'proven' | 'violated' | 'unknown'; kinds: CodeFailure[]; kind: CodeFailure | null;
  proven_fraction: number; headroom_bits: number | null;
  /** Every input's value at a point where the statement fails (violated only). */
  counterexample?: Record<string, number>;
}
export interface CodeProof {
  verdict: 'proven' | 'violated' | 'unknown'; target: string; global_q: number; entry: string | null;
  inputs: string[]; box: Record<string, [number, number]>; set: Record<string, number>;
  budget: number; work: number; boxes: number; decided_fraction: number; proven_fraction: number;
  statements: CodeStatement[]; counterexample?: Record<string, number>;
  /** With `// @q NAME auto` inputs: the Q proposed for each, and the real ranges given. */
  proposals?: Record<string, QProposal | LocalProposal>; real?: Record<string, [number, number]>;
}
/** `// @q NAME auto` on a local: what its stores compute over the box and the shift that fits them. */
export interface LocalProposal {
  local: true; type: string; bits: number; signed: boolean; computed: [number, number];
  shift: number; max_error_lsb: number;
}
export interface QProposal {
  local?: undefined; q: number | null; type: string; bits: number; signed: boolean; range_real: [number, number];
  raw_range: [number, number] | null; max_error: number | null; max_error_pct: number | null;
  tried: Record<string, 'proven' | 'violated' | 'unknown'>;
}

/** `vendors.translate`: a vendor's two current-loop integers in every other vendor's scaling. */
export interface TranslateRequest { input: Input; from: string; axis: 'd' | 'q'; values: Record<string, number> }
export interface TranslationStep { values: Record<string, number>; si: { kp: number; ki: number }; loss_pct: { kp: number; ki: number }; profile?: string; drift_pct?: { kp: number; ki: number } }
export interface Translation {
  si: { kp: number; ki: number };
  profiles: Record<string, TranslationStep>;
  chain: TranslationStep[];
  round_trip: { values: Record<string, number>; delta: Record<string, number> };
}

/** `batch`: a CSV of motors, data rows `start` … `start + count − 1`. */
export interface BatchRequest { csv: string; start?: number; count?: number }
export interface BatchChunk { total: number; columns: string[]; rows: string[][]; csv: string }

/** `prove`: a family proof over ranges of inputs (docs/contract.md, "Family proof"). */
/** A range end that is not a number is sent as typed: pulab names it in its message. */
export interface ProveRequest { input: Input; ranges: Record<string, [number | string, number | string]>; profile?: string; budget?: number }
export type ProveVerdict = 'proven' | 'violated' | 'unknown';
export type ProveKind = 'wrap' | 'store' | 'div0' | 'zero' | 'outside' | 'saturate' | 'invalid';
export interface ProveEntry {
  verdict: ProveVerdict;
  range: [number, number] | null;
  type: string | null;
  word: [number, number] | null;
  proven_fraction: number;
  worst_error_pct: number | null;
  error_bound: boolean;
  headroom_bits: number | null;
  kind?: ProveKind;
  statement?: string;
  raw?: Record<string, number | null>;
  counterexample?: Input;
}
export interface Proof { verdict: ProveVerdict; profile: string; integers: Record<string, ProveEntry>; not_analysed: string[]; counterexample?: Input; first_violated?: string }
/** `prove.propose`: each constant's finest format in its vendor's form (pulab.analyses.propose). */
export interface ProposalEntry {
  format: string;
  frac_bits: number;
  range: [number, number] | null;
  worst_error_pct: number | null;
  real_range: [number, number];
  witnessed: [number, number] | null;
  holds: boolean;
  impossible?: boolean;
  current: string;
  shift?: number;
  q?: number;
  current_q?: number;
}
export interface Proposal {
  profile: string;
  form: string;
  constants?: Record<string, ProposalEntry | null>;
  divisors?: Record<string, number>;
  confirmed?: Record<string, ProveVerdict>;
  global_q?: number | null;
  tried?: Record<string, string>;
  worst_error_pct?: Record<string, number | null>;
  integers?: Record<string, { headroom_bits: number | null; worst_error_pct: number | null; error_bound: boolean }>;
}

/** `audit`: generated vendor headers read back (docs/contract.md, "Audit"). */
export interface AuditRequest { files: { name: string; text: string }[]; profile?: string; define?: string[] }
export interface AuditMacro {
  value: number; type: string; si: number | null; unit: string | null; meaning: string;
  formula: string; source: string; expansion: string;
}
export interface AuditFinding {
  severity: 'error' | 'warning' | 'note'; code: string; macros: string[];
  message: string; message_zh: string; advice: string;
}
export interface AuditLoop {
  kp_v_per_a: number; ki_v_per_a_s: number; bandwidth_hz: number; zero_rad_s: number | null;
  plant_pole_rad_s: number; cancels_plant: boolean;
  macros?: string[]; delay?: string; phase_margin_deg?: number | null; gain_margin_db?: number | null;
  crossover_hz?: number | null; stable?: boolean;
}
/** A PI around an integrator (a speed loop, a PLL) as the audit reads it from its gains. */
export interface AuditDynamics { bandwidth_hz?: number; natural_hz?: number; damping?: number; [key: string]: unknown }
export interface AuditRangeProof {
  verdict: 'proven' | 'violated' | 'unknown' | null; spread: number; error?: string; error_zh?: string;
  constants?: Record<string, { verdict: string; range?: number[]; word?: number[] }>;
}
export interface Audit {
  profile: string; target: string; files: string[]; unresolved: string[];
  macros: Record<string, AuditMacro>;
  other: Record<string, { value: number; source: string }>;
  unknown: Record<string, string[]>;
  design: {
    input: Input; assumed: string[]; missing: string[];
    current_loop: Partial<Record<'d' | 'q', AuditLoop>>;
    speed_loop: AuditDynamics | null; observer: Record<string, unknown> | null;
    range_proof?: AuditRangeProof | null;
    [key: string]: unknown;
  };
  findings: AuditFinding[];
  regenerated: { header: string | null; error?: string; error_zh?: string } | null;
  roundtrip: Record<string, { file: number; pulab: number; delta_lsb?: number; delta_rel?: number | null }>;
}
