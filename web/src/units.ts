// Display units of input fields and their exact conversion to the SI value of the input JSON.
// Division by powers of ten (not multiplication by 1e-6) keeps 600 µH → 0.0006 exactly.

export type UnitId = 'H' | 'mH' | 'µH' | 's' | 'ms' | 'µs' | 'kHz';

interface UnitDef {
  /** SI = display / div ... */
  div?: number;
  /** ... or SI = 1 / (display · recip) (a frequency shown for a period). */
  recip?: number;
}

export const UNITS: Record<UnitId, UnitDef> = {
  H: { div: 1 },
  mH: { div: 1e3 },
  'µH': { div: 1e6 },
  s: { div: 1 },
  ms: { div: 1e3 },
  'µs': { div: 1e6 },
  kHz: { recip: 1e3 },
};

export function toSI(display: number, unit: UnitId): number {
  const u = UNITS[unit];
  return u.recip !== undefined ? 1 / (display * u.recip) : display / (u.div ?? 1);
}

export function fromSI(si: number, unit: UnitId): number {
  const u = UNITS[unit];
  const v = u.recip !== undefined ? 1 / (si * u.recip) : si * (u.div ?? 1);
  return Number(v.toPrecision(12));
}
