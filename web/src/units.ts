// Display units of input fields and their exact conversion to the SI value of the input JSON.
// Powers of ten shift the decimal exponent (4.2 mH → "4.2e-3" → 0.0042), so the SI value is the
// shortest decimal the user meant, never 4.2/1000 = 0.004200000000000001.

export type UnitId = 'H' | 'mH' | 'µH' | 'Ω' | 'mΩ' | 'kΩ' | 's' | 'ms' | 'µs' | 'ns' | 'kHz' | 'V/krpm' | 'V/rpm';

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
  'Ω': { div: 1 },
  'mΩ': { div: 1e3 },
  'kΩ': { div: 1e-3 },
  s: { div: 1 },
  ms: { div: 1e3 },
  'µs': { div: 1e6 },
  ns: { div: 1e9 },
  kHz: { recip: 1e3 },
  // A back-EMF constant as some datasheets print it: volts per single rpm (EMRAX "Vrms/1RPM").
  'V/krpm': { div: 1 },
  'V/rpm': { div: 1e-3 },
};

/** `x`·10^-k through the decimal text of x (exact for every decimal the user can type). */
function shift(x: number, k: number): number {
  if (k === 0 || !Number.isFinite(x) || x === 0) return x;
  const [m, e] = x.toExponential().split('e');
  return Number(`${m}e${Number(e) - k}`);
}

export function toSI(display: number, unit: UnitId): number {
  const u = UNITS[unit];
  if (u.recip !== undefined) return display === 0 ? Infinity : shift(1 / display, Math.round(Math.log10(u.recip)));
  return shift(display, Math.round(Math.log10(u.div ?? 1)));
}

export function fromSI(si: number, unit: UnitId): number {
  const u = UNITS[unit];
  const v = u.recip !== undefined ? 1 / (si * u.recip) : si * (u.div ?? 1);
  return Number(v.toPrecision(12));
}
