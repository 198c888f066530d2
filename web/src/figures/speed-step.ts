// Speed step and load step (report "loop.speed.response"): float and fixed point, i_q below.
import { t } from '../i18n';
import type { LoopReport } from '../generated/report-types';
import { COLORS, plot, type Trace } from './figure';

type Response = NonNullable<NonNullable<LoopReport['speed']>['response']>;

export function renderSpeedStep(el: HTMLElement, r: Response): void {
  const ms = r.t.map((x) => x * 1e3);
  const traces: Trace[] = [];
  for (const [v, color] of [['float', COLORS.si], ['fixed', COLORS.fixed]] as const) {
    const s = r.variants[v];
    if (!s) continue;
    const name = t(v === 'float' ? 'variant_float' : 'variant_fixed');
    traces.push({ x: ms, y: s.speed_rpm, name: `${name} n`, color, dash: v === 'fixed' ? 'dash' : 'solid' });
    traces.push({ x: ms, y: s.iq_a, name: `${name} i_q`, color, dash: v === 'fixed' ? 'dash' : 'solid', yaxis: 'y2', width: 1.2 });
  }
  traces.push({ x: [0, ms[ms.length - 1] ?? 0], y: [r.reference_rpm, r.reference_rpm], name: 'ref', color: COLORS.ref, dash: 'dot', width: 1 });
  plot(el, traces, { xTitle: `${t('time')} [ms]`, yTitle: 'n [r/min]', y2Title: 'i_q [A]', lower: 0.3 });
}
