// Saved and linked state checked field by field against the form's fields (= the contract's input
// fields, docs/contract.md), before anything renders it. A link or a stored entry is data from
// anywhere: a wrong type, an object where a string belongs ({"toString": 1}), an unknown key or a
// non-JSON text must never reach the form. What cannot be used is dropped and named; the rest is
// kept. Range checks stay with pulab (it names the field); here only the JSON shape is checked.
import { ALL_FIELDS, LOOP_FIELDS, type FieldSpec } from './fields';
import type { Input, Json } from './json';
import type { UnitId } from './units';

/** One thing in a state that could not be used. `path` is its JSON path ("#in" for the text). */
export interface StateProblem {
  path: string;
  /** 'json': not JSON text; 'shape': not an object; 'type': wrong type for the field; 'unknown': no such field. */
  reason: 'json' | 'shape' | 'type' | 'unknown';
  /** The offending value, short and printable (for the message). */
  got: string;
}

export interface Checked {
  input: Input;
  problems: StateProblem[];
}

const own = (o: object, k: string): boolean => Object.prototype.hasOwnProperty.call(o, k);
const isObject = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);

const UNPRINTABLE = /[\p{C}\p{Zl}\p{Zp}]/u;

/** A value as quoted in a message: one short printable line, never throwing (no toString call). */
export function shownValue(v: unknown): string {
  if (Array.isArray(v)) return 'a list';
  if (isObject(v)) return 'an object';
  let s: string;
  try {
    s = typeof v === 'string' ? JSON.stringify(v) : String(v);
  } catch {
    s = typeof v;
  }
  // JSON.stringify leaves U+2028/9 and other separators unescaped; they must not break the line.
  s = s.replace(new RegExp(UNPRINTABLE.source, 'gu'), (c) => `\\u${c.charCodeAt(0).toString(16).padStart(4, '0')}`);
  return s.length > 40 ? `${s.slice(0, 39)}…` : s;
}

function fits(f: FieldSpec, v: unknown): boolean {
  switch (f.kind) {
    case 'number': return typeof v === 'number' && Number.isFinite(v);
    case 'int': return typeof v === 'number' && Number.isSafeInteger(v);
    case 'select': return typeof v === 'string' && (f.options ?? []).includes(v);
    case 'bool': return typeof v === 'boolean';
    case 'text': return typeof v === 'string';
    case 'object': return isObject(v);
  }
}

const FIELD_BY_PATH = new Map([...ALL_FIELDS, ...LOOP_FIELDS].map((f) => [f.path, f]));
/** Objects that hold fields: "motor", …, "sim", "sim.current", "sim.pll". */
const CONTAINERS = new Set([...ALL_FIELDS, ...LOOP_FIELDS].flatMap((f) => {
  const parts = f.path.split('.');
  return parts.slice(0, -1).map((_, i) => parts.slice(0, i + 1).join('.'));
}));

/** Copy the usable fields of `v` (at `path`) into `out`, naming everything dropped. */
function walk(v: Record<string, unknown>, path: string, out: Record<string, Json>, problems: StateProblem[]): void {
  for (const key of Object.keys(v)) {
    const child = path ? `${path}.${key}` : key;
    const x = v[key];
    if (x === null || x === undefined) continue; // absent = null (contract)
    const field = FIELD_BY_PATH.get(child);
    if (field) {
      if (fits(field, x)) out[key] = x as Json;
      else problems.push({ path: child, reason: 'type', got: shownValue(x) });
    } else if (CONTAINERS.has(child)) {
      if (!isObject(x)) {
        problems.push({ path: child, reason: 'shape', got: shownValue(x) });
        continue;
      }
      const sub: Record<string, Json> = {};
      walk(x, child, sub, problems);
      out[key] = sub;
    } else {
      const plain = key !== '' && !key.includes('.') && !UNPRINTABLE.test(key);
      problems.push({ path: plain ? child : `${path}[${shownValue(key)}]`, reason: 'unknown', got: shownValue(x) });
    }
  }
}

/** The usable part of any value as a page input, and what was dropped. */
export function checkInput(v: unknown): Checked {
  if (!isObject(v)) return { input: {}, problems: [{ path: 'input', reason: 'shape', got: shownValue(v) }] };
  const out: Record<string, Json> = {};
  const problems: StateProblem[] = [];
  walk(v, '', out, problems);
  return { input: out as Input, problems };
}

/** Parse JSON text as a page input: non-JSON text is one 'json' problem at `where`. */
export function checkInputText(text: string, where: string): Checked {
  let v: unknown;
  try {
    v = JSON.parse(text);
  } catch {
    return { input: {}, problems: [{ path: where, reason: 'json', got: shownValue(text) }] };
  }
  const r = checkInput(v);
  if (r.problems.length === 1 && r.problems[0].path === 'input') r.problems[0].path = where;
  return r;
}

/** The stored display units: only known fields and their own unit choices survive. */
export function checkUnits(text: string | null): Record<string, UnitId> {
  let v: unknown;
  try {
    v = JSON.parse(text ?? '{}');
  } catch {
    return {};
  }
  const out: Record<string, UnitId> = {};
  if (!isObject(v)) return out;
  for (const f of ALL_FIELDS) {
    const u = own(v, f.path) ? v[f.path] : undefined;
    if (typeof u === 'string' && (f.units as string[] | undefined)?.includes(u)) out[f.path] = u as UnitId;
  }
  return out;
}
