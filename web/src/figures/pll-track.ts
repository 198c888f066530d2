// PLL tracking: estimated speed and angle error of the correctly scaled loops vs the naive one.
import { t, type Key } from '../i18n';
import type { SimPll } from '../generated/report-types';
import { COLORS, plot, type Trace } from './figure';

export function renderPllTrack(el: HTMLElement, sim: SimPll): void {
  const traces: Trace[] = [];
  const ms = sim.t.map((x) => x * 1e3);
  let lo = Infinity;
  let hi = -Infinity;
  for (const v of ['naive', 'si', 'pu', 'q15']) {
    const s = sim.variants[v];
    if (!s) continue;
    // Display units only: rad/s → Hz, rad → degrees, error wrapped to ±180°.
    const hz = s.omega_hat.map((w) => w / (2 * Math.PI));
    if (v !== 'naive') for (const x of hz) if (Number.isFinite(x)) (lo = Math.min(lo, x)), (hi = Math.max(hi, x));
    traces.push({ x: ms, y: hz, name: t(`variant_${v}` as Key), color: COLORS[v], dash: v === 'pu' ? 'dash' : 'solid', width: v === 'pu' ? 2.4 : v === 'naive' ? 1 : 1.6, opacity: v === 'naive' ? 0.45 : 1 });
    const err = s.theta.map((th, i) => {
      const d = ((((th - s.theta_hat[i]) * 180) / Math.PI) % 360 + 540) % 360 - 180;
      return d;
    });
    traces.push({ x: ms, y: err, name: `${t('error')} ${v}`, color: COLORS[v], yaxis: 'y2', width: v === 'naive' ? 0.8 : 1.3, dash: v === 'pu' ? 'dash' : 'solid', opacity: v === 'naive' ? 0.4 : 1 });
  }
  const pad = Math.max(5, (hi - lo) * 0.4);
  plot(el, traces, {
    xTitle: `${t('time')} [ms]`, yTitle: 'ω̂/2π [Hz]', y2Title: 'θ − θ̂ [°]',
    yRange: Number.isFinite(lo) ? [lo - pad, hi + pad] : undefined,
  });
}
