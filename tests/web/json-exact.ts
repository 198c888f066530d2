// A small JSON parser that keeps Python's int/float distinction: integer literals become
// bigint, everything else a number. The golden comparison needs it ("integers exactly").
export type JVal = null | boolean | bigint | number | string | JVal[] | { [k: string]: JVal };

export function parseJsonExact(text: string): JVal {
  let i = 0;
  const ws = (): void => {
    while (i < text.length && ' \t\n\r'.includes(text[i])) i++;
  };
  const fail = (what: string): never => {
    throw new SyntaxError(`${what} at offset ${i}`);
  };
  const value = (): JVal => {
    ws();
    const c = text[i];
    if (c === '{') {
      i++;
      const o: { [k: string]: JVal } = {};
      ws();
      if (text[i] === '}') return i++, o;
      for (;;) {
        ws();
        const k = value();
        if (typeof k !== 'string') fail('object key expected');
        ws();
        if (text[i++] !== ':') fail('":" expected');
        o[k as string] = value();
        ws();
        if (text[i] === ',') i++;
        else if (text[i] === '}') return i++, o;
        else fail('"," or "}" expected');
      }
    }
    if (c === '[') {
      i++;
      const a: JVal[] = [];
      ws();
      if (text[i] === ']') return i++, a;
      for (;;) {
        a.push(value());
        ws();
        if (text[i] === ',') i++;
        else if (text[i] === ']') return i++, a;
        else fail('"," or "]" expected');
      }
    }
    if (c === '"') {
      const m = /^"(?:[^"\\]|\\.)*"/.exec(text.slice(i, i + 1_000_000));
      if (!m) fail('bad string');
      i += m![0].length;
      return JSON.parse(m![0]) as string;
    }
    const lit = /^(true|false|null|-?\d+(\.\d+)?([eE][+-]?\d+)?|NaN|-?Infinity)/.exec(text.slice(i, i + 400));
    if (!lit) return fail('value expected');
    i += lit[0].length;
    const s = lit[0];
    if (s === 'true') return true;
    if (s === 'false') return false;
    if (s === 'null') return null;
    if (s === 'NaN' || s.endsWith('Infinity')) return fail(`non-finite number ${s}`);
    if (/^-?\d+$/.test(s)) return BigInt(s);
    return Number(s);
  };
  const v = value();
  ws();
  if (i !== text.length) fail('trailing text');
  return v;
}

export interface Mismatch {
  path: string;
  expected: string;
  actual: string;
}

const show = (v: JVal | undefined): string =>
  v === undefined ? 'missing' : typeof v === 'bigint' ? `${v} (int)` : typeof v === 'number' ? `${v} (float)` : JSON.stringify(v, (_, x) => (typeof x === 'bigint' ? Number(x) : x)).slice(0, 120);

/**
 * Compare `actual` against `expected` recursively: every expected key must exist; ints exactly
 * (and must be ints); floats to `rel` relative (absolute floor `abs` near zero); strings and bools
 * exactly; arrays element-wise with equal length. Keys listed in `skip` (at any depth) are ignored.
 */
export function compareGolden(
  expected: JVal,
  actual: JVal | undefined,
  path = '',
  opts: { rel?: number; abs?: number; skip?: string[] } = {},
  out: Mismatch[] = [],
): Mismatch[] {
  const rel = opts.rel ?? 1e-12;
  const abs = opts.abs ?? 1e-15;
  const bad = (): void => {
    out.push({ path: path || '(root)', expected: show(expected), actual: show(actual) });
  };
  if (typeof expected === 'bigint') {
    if (typeof actual !== 'bigint' || actual !== expected) bad();
  } else if (typeof expected === 'number') {
    const a = typeof actual === 'bigint' ? Number(actual) : actual;
    if (typeof a !== 'number' || !(Math.abs(a - expected) <= Math.max(rel * Math.abs(expected), abs))) bad();
  } else if (Array.isArray(expected)) {
    if (!Array.isArray(actual) || actual.length !== expected.length) return bad(), out;
    expected.forEach((e, k) => compareGolden(e, actual[k], `${path}[${k}]`, opts, out));
  } else if (expected !== null && typeof expected === 'object') {
    if (actual === null || typeof actual !== 'object' || Array.isArray(actual) || typeof actual === 'bigint') return bad(), out;
    for (const [k, e] of Object.entries(expected)) {
      if (opts.skip?.includes(k)) continue;
      compareGolden(e, (actual as Record<string, JVal>)[k], path ? `${path}.${k}` : k, opts, out);
    }
  } else if (expected !== actual) bad();
  return out;
}

/** JSON text of a parsed value (bigints back to integer literals). */
export const dump = (v: JVal): string =>
  JSON.stringify(v, (_, x) => (typeof x === 'bigint' ? `@@int:${x}@@` : x)).replace(/"@@int:(-?\d+)@@"/g, '$1');
