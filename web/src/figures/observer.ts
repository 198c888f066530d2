// Sensorless (report "observer"): the discrete poles of the back-EMF and tracking observers in
// the unit circle, beside the images e^{sT} of their continuous design poles, and the back-EMF
// budget over speed with the lowest sensorless speed. Every point is pulab's
// (pulab.analyses.observer); the page only draws.
import { t } from '../i18n';
import type { ObserverReport } from '../generated/report-types';
import { COLORS, plotRaw } from './figure';

export function renderObserverPoles(el: HTMLElement, o: ObserverReport): void {
  const n = 181;
  const angle = Array.from({ length: n }, (_, k) => (2 * Math.PI * k) / (n - 1));
  const marks = (pts: [number, number][], name: string, color: string, symbol: string): object =>
    ({ type: 'scatter', mode: 'markers', x: pts.map((p) => p[0]), y: pts.map((p) => p[1]), name, marker: { color, symbol, size: 10, line: { width: 1.5, color } } });
  const d = o.design;
  plotRaw(el, [
    { type: 'scatter', mode: 'lines', x: angle.map(Math.cos), y: angle.map(Math.sin), name: t('obsUnitCircle'), line: { color: '#8c959f', width: 1, dash: 'dot' }, hoverinfo: 'skip' },
    marks(d.bemf.poles, t('obsBemfPoles'), COLORS.si, 'x'),
    marks(d.bemf.discrete_poles_of_continuous, t('obsBemfDesign'), COLORS.si, 'circle-open'),
    marks(d.tracking.poles, t('obsTrackPoles'), COLORS.fixed, 'x'),
    marks(d.tracking.discrete_poles_of_continuous, t('obsTrackDesign'), COLORS.fixed, 'circle-open'),
  ], {
    legend: { orientation: 'h', y: -0.15, x: 0 },
    xaxis: { title: { text: 'Re z' }, range: [-1.1, 1.1], gridcolor: '#eaeef2', zerolinecolor: '#aaa' },
    yaxis: { title: { text: 'Im z' }, range: [-1.1, 1.1], gridcolor: '#eaeef2', zerolinecolor: '#aaa', scaleanchor: 'x' },
  }, 420);
}

export function renderObserverBudget(el: HTMLElement, o: ObserverReport): void {
  const b = o.budget;
  // where the back-EMF crosses the required multiple of its errors is the lowest speed
  const shapes: object[] = b.min_speed_rpm === null ? [] : [{ type: 'line', yref: 'paper', y0: 0, y1: 1, x0: b.min_speed_rpm, x1: b.min_speed_rpm, line: { color: COLORS.naive, dash: 'dot', width: 1 } }];
  plotRaw(el, [
    { type: 'scatter', mode: 'lines', x: b.speeds_rpm, y: b.bemf_v, name: t('obsBemf'), line: { color: COLORS.si, width: 2.2 } },
    { type: 'scatter', mode: 'lines', x: b.speeds_rpm, y: b.error_v.map((e) => e * b.snr_min), name: t('obsRequired', { snr: b.snr_min }), line: { color: COLORS.fixed, width: 2, dash: 'dash' } },
  ], {
    legend: { orientation: 'h', y: 1.12, x: 0 },
    xaxis: { title: { text: `${t('fwSpeed')} [rpm]` }, gridcolor: '#eaeef2' },
    yaxis: { title: { text: `${t('obsVolts')} [V]` }, gridcolor: '#eaeef2', rangemode: 'tozero' },
    margin: { l: 64, r: 20, t: 10, b: 44 },
    shapes,
  }, 340);
}
