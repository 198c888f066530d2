// An induction motor's simulation (report sim.current and sim.flux, motor.kind = acim): the
// current step and the flux build-up, SI float beside the seed's Q12/Q16 PI and TI's IQ PI.
// Every series is pulab's; this file only chooses what is drawn.
import { t } from '../i18n';
import type { SimCurrent, SimProfileRun } from '../generated/report-types';
import { COLORS, plot, type Trace } from './figure';

const TI = '#8250df';

/** The runs drawn: SI, Inovance's fixed point (when the firmware can hold the limits) and TI's. */
function runs(sim: SimCurrent): [string, Record<string, number[]>, string, 'solid' | 'dash'][] {
  const out: [string, Record<string, number[]>, string, 'solid' | 'dash'][] = [[t('variant_si'), sim.variants.si, COLORS.si, 'solid']];
  if (sim.variants.fixed) out.push([t('acimFixedInovance'), sim.variants.fixed, COLORS.fixed, 'solid']);
  const ti = sim.by_profile?.ti as SimProfileRun | undefined;
  if (ti?.ran) out.push([t('acimFixedTi'), ti.variant as unknown as Record<string, number[]>, TI, 'dash']);
  return out;
}

/** The current step: the stepped axis' current (and the other's) against time. */
export function renderAcimStep(el: HTMLElement, sim: SimCurrent): void {
  const ms = sim.t.map((x) => x * 1e3);
  const axis = sim.axis === 'q' ? 'q' : 'd';
  const other = axis === 'q' ? 'd' : 'q';
  const traces: Trace[] = [];
  for (const [name, v, color, dash] of runs(sim)) traces.push({ x: ms, y: v[`i${axis}`], name: `${name} i_${axis}`, color, dash, width: 1.6 });
  // the other axis (held at its reference, the coupling shows in it): SI only
  traces.push({ x: ms, y: sim.variants.si[`i${other}`], name: `${t('variant_si')} i_${other}`, color: COLORS.si, dash: 'dot', width: 1, opacity: 0.6 });
  const si = sim.variants.si[`i${axis}`];
  for (const [name, v, color] of runs(sim).slice(1)) {
    // difference of two series for display only (fixed − SI), in mA
    traces.push({ x: ms, y: v[`i${axis}`].map((x, i) => (x - si[i]) * 1e3), name: `${name} − SI`, color, yaxis: 'y2', width: 1.2 });
  }
  // initial view: the transient (5 settling times); zoom out to see all
  const settle = (sim.metrics.si as Record<string, unknown> | undefined)?.settling_time_s;
  const tEnd = sim.t[sim.t.length - 1] ?? 0;
  const span = typeof settle === 'number' && settle > 0 ? Math.min(tEnd, 5 * settle) : tEnd;
  plot(el, traces, { xTitle: `${t('time')} [ms]`, yTitle: 'i [A]', y2Title: 'Δ [mA]', xRange: span < tEnd ? [0, span * 1e3] : undefined });
}

/** The flux build-up: ψ_rd of each run, with the SI i_d on the lower axis. */
export function renderAcimFlux(el: HTMLElement, sim: SimCurrent): void {
  const s = sim.t;
  const traces: Trace[] = runs(sim).map(([name, v, color, dash]) => ({ x: s, y: v.psi_d, name: `${name} ψ_rd`, color, dash, width: 1.6 }));
  traces.push({ x: s, y: sim.variants.si.id, name: `${t('variant_si')} i_d [A]`, color: COLORS.ref, yaxis: 'y2', width: 1.2 });
  plot(el, traces, { xTitle: `${t('time')} [s]`, yTitle: t('acimFluxAxis'), y2Title: 'i_d [A]' });
}
