// Bode plots of the loop analysis (report "loop.bode"): magnitude above, phase below, log f.
import { t } from '../i18n';
import type { BodeCurve } from '../generated/report-types';
import { plot, type Trace } from './figure';

export interface BodeLine {
  curve: BodeCurve;
  name: string;
  color: string;
  dash?: Trace['dash'];
}

export function renderBode(el: HTMLElement, f: number[], lines: BodeLine[]): void {
  const traces: Trace[] = [];
  for (const l of lines) traces.push({ x: f, y: l.curve.magnitude_db, name: l.name, color: l.color, dash: l.dash });
  for (const l of lines) traces.push({ x: f, y: l.curve.phase_deg, name: l.name, color: l.color, dash: l.dash, yaxis: 'y2' });
  plot(el, traces, { xTitle: `${t('frequency')} [Hz]`, yTitle: `${t('magnitude')} [dB]`, y2Title: `${t('phase')} [°]`, xLog: true, lower: 0.4 });
}
