// Current-loop step response: SI, per-unit and the fixed point of the firmware the reader ships,
// the user's routine when it is in the loop, with that fixed − SI error below.
import { t, type Key } from '../i18n';
import type { SimCurrent, SimProfileRun } from '../generated/report-types';
import { vendorName } from '../vendors';
import { COLORS, plot, type Trace } from './figure';

/** The fixed-point run of `firmware`: Inovance's `variants.fixed`, another's `by_profile` run;
 * undefined when that firmware has none for this motor. */
export function fixedRun(sim: SimCurrent, firmware: string): { id: number[]; iq: number[] } | undefined {
  if (firmware === 'inovance') return sim.variants.fixed;
  const run = sim.by_profile?.[firmware] as SimProfileRun | undefined;
  return run?.ran ? run.variant : undefined;
}

export function renderCurrentStep(el: HTMLElement, sim: SimCurrent, axis: 'd' | 'q', ts?: number, firmware = 'inovance'): void {
  const key = axis === 'q' ? 'iq' : 'id';
  const traces: Trace[] = [];
  const ms = sim.t.map((x) => x * 1e3);
  const name = vendorName(firmware);
  const fx = fixedRun(sim, firmware)?.[key];
  for (const v of ['si', 'pu']) {
    const s = sim.variants[v];
    if (!s?.[key]) continue;
    traces.push({ x: ms, y: s[key], name: `${t(`variant_${v}` as Key)} i_${axis}`, color: COLORS[v], dash: v === 'pu' ? 'dash' : 'solid', width: v === 'pu' ? 2.4 : 1.6 });
  }
  if (fx) traces.push({ x: ms, y: fx, name: `${t('sf_fixed', { name })} i_${axis}`, color: COLORS.fixed, width: 1.6 });
  // The user's routine in the loop (sim.current.code), dotted so an equal fixed-point trace shows under it.
  const own = sim.code?.variant[key];
  if (own) traces.push({ x: ms, y: own, name: `${t('cl_code')} i_${axis}`, color: COLORS.code, dash: 'dot', width: 2.2 });
  const ref = (sim as Record<string, unknown>)[`${key}_ref`] ?? (sim as Record<string, unknown>).ref;
  if (Array.isArray(ref)) traces.push({ x: ms, y: ref as number[], name: 'ref', color: COLORS.ref, dash: 'dot', width: 1 });
  const si = sim.variants.si?.[key];
  if (si && fx) {
    // Difference of two series for display only (fixed − SI), in mA.
    traces.push({ x: ms, y: fx.map((v, i) => (v - si[i]) * 1e3), name: `${t('error')} ${t('sf_minus_si', { name })}`, color: COLORS.fixed, yaxis: 'y2', width: 1.2 });
  }
  // Initial view: the transient (≈ 5 settling times, at least 20 periods); zoom out to see all.
  const settle = (sim.metrics.si as Record<string, unknown> | undefined)?.settling_time_s;
  const tEnd = sim.t[sim.t.length - 1] ?? 0;
  const span = typeof settle === 'number' && settle > 0 ? Math.min(tEnd, Math.max(5 * settle, 20 * (ts ?? 0))) : tEnd;
  plot(el, traces, { xTitle: `${t('time')} [ms]`, yTitle: `i_${axis} [A]`, y2Title: 'Δ [mA]', xRange: span < tEnd ? [0, span * 1e3] : undefined });
}
