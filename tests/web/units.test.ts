import { describe, it, expect } from 'vitest';
import { fromSI, toSI, type UnitId } from '../../web/src/units';

describe('toSI: display unit → the SI value of the input JSON (exact for the usual values)', () => {
  const cases: [number, UnitId, number][] = [
    [600, 'µH', 0.0006],
    [0.6, 'mH', 0.0006],
    [8.5, 'mH', 0.0085],
    [100, 'µs', 0.0001],
    [62.5, 'µs', 0.0000625],
    [10, 'kHz', 0.0001],
    [16, 'kHz', 0.0000625],
    [5, 'ms', 0.005],
    [0.0006, 'H', 0.0006],
    // shortest round-trip decimals (4.2/1000 = 0.004200000000000001)
    [4.2, 'mH', 0.0042],
    [4.2, 'ms', 0.0042],
    [1.1, 'µH', 0.0000011],
    [1e-7, 'mH', 1e-10],
    [12.5, 'kHz', 0.00008],
    // EMRAX prints Ke as "0,0176 Vrms/1RPM": the input is V/krpm
    [0.0176, 'V/rpm', 17.6],
    [0.0304, 'V/rpm', 30.4],
    [57, 'V/krpm', 57],
    // large motors' datasheets print the winding resistance in mΩ (EMRAX 228: 1.1 mΩ per phase)
    [1.1, 'mΩ', 0.0011],
    [4.2, 'mΩ', 0.0042],
    [0.35, 'mΩ', 0.00035],
    [12.5, 'mΩ', 0.0125],
    [0.0011, 'Ω', 0.0011],
    // the board: shunts in mΩ, dividers in kΩ, dead times in ns
    [7, 'mΩ', 0.007],
    [4.99, 'kΩ', 4990],
    [82, 'kΩ', 82000],
    [800, 'ns', 8e-7],
    [1.5, 'ns', 1.5e-9],
  ];
  for (const [v, u, want] of cases) it(`${v} ${u} → ${want}`, () => expect(toSI(v, u)).toBe(want));
});

describe('fromSI: SI → display unit (12 significant digits)', () => {
  const cases: [number, UnitId, number][] = [
    [0.0006, 'µH', 600],
    [0.0006, 'mH', 0.6],
    [0.0001, 'µs', 100],
    [0.0001, 'kHz', 10],
    [0.0000625, 'kHz', 16],
    [0.2, 'ms', 200],
    [17.6, 'V/rpm', 0.0176],
    [0.0011, 'mΩ', 1.1],
    [0.0042, 'mΩ', 4.2],
    [0.0011, 'Ω', 0.0011],
  ];
  for (const [v, u, want] of cases) it(`${v} → ${want} ${u}`, () => expect(fromSI(v, u)).toBe(want));
});
