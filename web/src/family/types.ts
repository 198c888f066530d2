// The sweep and batch results the page reads (docs/contract.md, "Family sweep and batch").
export type Status = 'ok' | 'zero' | 'store' | 'wrap' | 'div0' | 'invalid';
export const STATUSES: Status[] = ['ok', 'zero', 'store', 'wrap', 'div0', 'invalid'];

export interface Axis {
  path: string;
  scale: 'linear' | 'log';
  values: number[];
  integer: boolean;
}
export interface Plan {
  profile: string;
  names: string[];
  total: number;
  x: Axis;
  y: Axis | null;
}
export interface Column {
  value: (number | null)[];
  error_pct: (number | null)[];
  status: Status[];
}
export interface Points {
  x: number[];
  y?: number[];
  error: (string | null)[];
  error_zh: (string | null)[];
  integers: Record<string, Column>;
  intermediates: Record<string, (number | null)[]>;
}
export interface Boundary {
  name: string;
  axis: 'x' | 'y';
  path: string;
  from: Status;
  to: Status;
  before: number;
  at: number;
  index: number;
  other: number | null;
  raw: Record<string, [number, number]>;
  intermediates: Record<string, [number | null, number | null]>;
  message?: string;
  message_zh?: string;
}
export interface Worst {
  name: string;
  index: number;
  x: number;
  y: number | null;
  status: Status;
  value: number | null;
  error_pct: number | null;
  message: string | null;
  message_zh: string | null;
  input: Record<string, unknown>;
}
export interface Summary {
  boundaries: Boundary[];
  worst: Worst[];
  per_integer: Record<string, { counts: Record<Status, number>; over_pct: Record<string, number>; max_abs_error_pct: number | null }>;
  regions?: Record<string, { status: Status; from: number; to: number }[]>;
  first?: Record<string, Status>;
}
export interface Chunk {
  start: number;
  count: number;
  total: number;
  points: Points;
  summary: Summary;
}

/** Append a chunk's point columns to the columns gathered so far (display only, no arithmetic). */
export function appendPoints(into: Points | null, add: Points): Points {
  if (!into) return add;
  const cat = <T>(a: T[] | undefined, b: T[] | undefined): T[] => (a ?? []).concat(b ?? []);
  const n = into.x.length;
  const integers: Record<string, Column> = {};
  for (const [k, c] of Object.entries(into.integers)) {
    const d = add.integers[k];
    integers[k] = { value: cat(c.value, d?.value), error_pct: cat(c.error_pct, d?.error_pct), status: cat(c.status, d?.status) };
  }
  const intermediates: Record<string, (number | null)[]> = {};
  for (const k of new Set([...Object.keys(into.intermediates), ...Object.keys(add.intermediates)])) {
    intermediates[k] = cat(into.intermediates[k] ?? Array<null>(n).fill(null), add.intermediates[k] ?? Array<null>(add.x.length).fill(null));
  }
  return {
    x: cat(into.x, add.x), y: into.y ? cat(into.y, add.y) : undefined,
    error: cat(into.error, add.error), error_zh: cat(into.error_zh, add.error_zh), integers, intermediates,
  };
}
