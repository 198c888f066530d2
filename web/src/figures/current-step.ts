// Current-loop step response: SI, per-unit and fixed point, with the fixed − SI error below.
import { t, type Key } from '../i18n';
import type { SimCurrent } from '../report-types';
import { COLORS, plot, type Trace } from './figure';

export function renderCurrentStep(el: HTMLElement, sim: SimCurrent, axis: 'd' | 'q', ts?: number): void {
  const key = axis === 'q' ? 'iq' : 'id';
  const traces: Trace[] = [];
  const ms = sim.t.map((x) => x * 1e3);
  for (const v of ['si', 'pu', 'fixed']) {
    const s = sim.variants[v];
    if (!s?.[key]) continue;
    traces.push({ x: ms, y: s[key], name: `${t(`variant_${v}` as Key)} i_${axis}`, color: COLORS[v], dash: v === 'pu' ? 'dash' : 'solid', width: v === 'pu' ? 2.4 : 1.6 });
  }
  const ref = (sim as Record<string, unknown>)[`${key}_ref`] ?? (sim as Record<string, unknown>).ref;
  if (Array.isArray(ref)) traces.push({ x: ms, y: ref as number[], name: 'ref', color: COLORS.ref, dash: 'dot', width: 1 });
  const si = sim.variants.si?.[key];
  const fx = sim.variants.fixed?.[key];
  if (si && fx) {
    // Difference of two series for display only (fixed − SI), in mA.
    traces.push({ x: ms, y: fx.map((v, i) => (v - si[i]) * 1e3), name: `${t('error')} fixed − SI`, color: COLORS.fixed, yaxis: 'y2', width: 1.2 });
  }
  // Initial view: the transient (≈ 5 settling times, at least 20 periods); zoom out to see all.
  const settle = (sim.metrics.si as Record<string, unknown> | undefined)?.settling_time_s;
  const tEnd = sim.t[sim.t.length - 1] ?? 0;
  const span = typeof settle === 'number' && settle > 0 ? Math.min(tEnd, Math.max(5 * settle, 20 * (ts ?? 0))) : tEnd;
  plot(el, traces, { xTitle: `${t('time')} [ms]`, yTitle: `i_${axis} [A]`, y2Title: 'Δ [mA]', xRange: span < tEnd ? [0, span * 1e3] : undefined });
}

