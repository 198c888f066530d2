// Formatting of numbers for display and parsing of typed numbers. No formulas here.

/** `x` with `sig` significant digits, trailing zeros dropped; exponent form outside [1e-4, 1e7). */
export function fmtNum(x: number | null | undefined, sig = 6): string {
  if (x === null || x === undefined || typeof x !== 'number') return '—';
  if (!Number.isFinite(x)) return String(x);
  if (x === 0) return '0';
  const a = Math.abs(x);
  if (Number.isInteger(x) && a < 1e15) return String(x);
  if (a >= 1e7 || a < 1e-4) {
    const [m, e] = x.toExponential(sig - 1).split('e');
    return `${stripZeros(m)}e${Number(e)}`;
  }
  return stripZeros(x.toPrecision(sig));
}

/**
 * The shortest decimal a user would type for `x`, a value found next to `other` (a sweep
 * boundary and its neighbour across it): rounded away from `other`, so the typed value lands on
 * x's side, and within `rel` of x. 26.884999999999998 (after 26.884999999999994) → "26.885".
 */
export function fmtToward(x: number, other: number, rel = 1e-9): string {
  if (!Number.isFinite(x) || x === other) return String(x);
  const up = x > other;
  const e = Math.floor(Math.log10(Math.abs(x)));
  for (let p = 1; p <= 17; p++) {
    const step = 10 ** (e - p + 1);
    const c = Number(((up ? Math.ceil(x / step) : Math.floor(x / step)) * step).toPrecision(p));
    if ((up ? c >= x : c <= x) && Math.abs(c - x) <= rel * Math.abs(x)) return String(c);
  }
  return String(x);
}

function stripZeros(s: string): string {
  return s.includes('.') ? s.replace(/\.?0+$/, '') : s;
}

/** Percentage with sign, e.g. "+0.6398 %". */
export function fmtPct(x: number | null | undefined, digits = 4): string {
  if (x === null || x === undefined || !Number.isFinite(x)) return '—';
  if (x === 0) return '0 %';
  const s = Math.abs(x) < 1e-4 ? x.toExponential(2) : x.toFixed(digits);
  return `${x > 0 ? '+' : ''}${s} %`;
}

/** Two's-complement hex of an integer in a C type: Uint16 → 4 digits, long/Ulong → 8 digits. */
export function fmtHex(value: number, type: string): string {
  const bits = /16/.test(type) ? 16 : /64/.test(type) ? 64 : 32;
  const mod = 1n << BigInt(bits);
  const v = ((BigInt(Math.trunc(value)) % mod) + mod) % mod;
  return `0x${v.toString(16).toUpperCase().padStart(bits / 4, '0')}`;
}

export type ParseResult = { ok: true; value: number | null } | { ok: false; error: 'number' | 'integer' };

/**
 * What a Chinese input method types, folded to ASCII: full-width digits and signs (NFKC), the
 * ideographic full stop 。 and the Unicode minus −; white space removed.
 */
export function asciiNumber(text: string): string {
  return text.normalize('NFKC').replace(/[。｡]/g, '.').replace(/−/g, '-').replace(/\s+/g, '');
}

/**
 * Parse what a user typed into a number field. Empty → null (the field is absent: default or
 * derived). Accepts a decimal comma, surrounding spaces, exponent notation, full-width digits and
 * IME decimal points; `integer` demands an integer literal.
 */
export function parseNumber(text: string, integer = false): ParseResult {
  const s = asciiNumber(text);
  if (s === '') return { ok: true, value: null };
  // A decimal comma (1,5) is accepted; 1,500 could be a thousands separator (1500) — refuse it.
  if (/^[+-]?\d+,\d{3}$/.test(s)) return { ok: false, error: integer ? 'integer' : 'number' };
  const norm = /^[+-]?\d+,\d+$/.test(s) ? s.replace(',', '.') : s;
  if (integer) {
    if (!/^[+-]?\d+$/.test(norm)) return { ok: false, error: 'integer' };
    return { ok: true, value: Number(norm) };
  }
  if (!/^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/.test(norm)) return { ok: false, error: 'number' };
  const v = Number(norm);
  return Number.isFinite(v) ? { ok: true, value: v } : { ok: false, error: 'number' };
}

/** A number as it should appear in an input box: at most 12 significant digits. */
export function fmtInput(x: number | null | undefined): string {
  if (x === null || x === undefined || !Number.isFinite(x)) return '';
  return String(Number(x.toPrecision(12)));
}
