// Robustness figures (report "loop.robust"): the margin map over temperature × current, the safe
// band on the bandwidth axis, the Monte Carlo histograms. Plotly's basic bundle has no heatmap
// trace, so the map is a scatter of square markers coloured by the margin.
import { t } from '../i18n';
import type { Histogram, RobustReport } from '../generated/report-types';
import { COLORS, plot, plotRaw } from './figure';

/** Phase margin (worse of d and q) at each grid point, coloured; the threshold marks the scale. */
export function renderRobustMap(el: HTMLElement, r: RobustReport): void {
  const x: number[] = [];
  const y: number[] = [];
  const c: (number | null)[] = [];
  r.map.current_a.forEach((i, row) => r.map.temperature_c.forEach((temp, col) => {
    const d = r.map.d.phase_margin_deg[row]?.[col] ?? null;
    const q = r.map.q.phase_margin_deg[row]?.[col] ?? null;
    x.push(temp);
    y.push(i);
    c.push(d === null ? q : q === null ? d : Math.min(d, q));
  }));
  const thr = r.config.min_phase_margin_deg;
  const lo = Math.min(thr - 15, ...c.filter((v): v is number => v !== null));
  const hi = Math.max(thr + 15, ...c.filter((v): v is number => v !== null));
  const size = Math.max(10, Math.min(34, 260 / Math.max(r.map.temperature_c.length, r.map.current_a.length)));
  plotRaw(el, [{
    type: 'scatter', mode: 'markers', x, y, name: t('pm'), text: c.map((v) => (v === null ? t('noValue') : `${v.toFixed(1)}°`)),
    hovertemplate: '%{x} °C, %{y:.3g} A: %{text}<extra></extra>',
    marker: { symbol: 'square', size, color: c, cmin: lo, cmax: hi, cmid: thr,
      colorscale: [[0, '#cf222e'], [0.5, '#f6e05e'], [1, '#2da44e']], showscale: true,
      colorbar: { title: { text: `${t('pm')} [°]` }, thickness: 12 } },
  }], {
    showlegend: false,
    xaxis: { title: { text: `${t('robustTemperature')} [°C]` }, gridcolor: '#eaeef2' },
    yaxis: { title: { text: `${t('robustCurrent')} [A]` }, gridcolor: '#eaeef2' },
  }, 320);
}

/** The scanned bandwidth axis, the safe band over it and the bandwidth of the firmware's gains. */
export function renderRobustBand(el: HTMLElement, r: RobustReport): void {
  const [s0, s1] = r.safe_bandwidth_scan_hz;
  const data: object[] = [{ type: 'scatter', mode: 'lines', x: [s0, s1], y: [0, 0], name: t('robustScan'), line: { color: '#d0d7de', width: 14 } }];
  if (r.safe_bandwidth_hz) {
    data.push({ type: 'scatter', mode: 'lines', x: r.safe_bandwidth_hz, y: [0, 0], name: t('robustSafe'), line: { color: COLORS.pu, width: 14 } });
  }
  const bw = r.designed_bandwidth_hz.q ?? r.designed_bandwidth_hz.d;
  if (bw !== null) {
    data.push({ type: 'scatter', mode: 'markers', x: [bw], y: [0], name: t('robustDesigned'),
      marker: { symbol: 'triangle-down', size: 16, color: r.safe ? COLORS.si : COLORS.naive } });
  }
  plotRaw(el, data, {
    legend: { orientation: 'h', y: 1.3, x: 0 },
    xaxis: { title: { text: `${t('bwCl')} [Hz]` }, type: 'log', gridcolor: '#eaeef2' },
    yaxis: { visible: false, range: [-1, 1] },
    margin: { l: 24, r: 16, t: 30, b: 44 },
  }, 170);
}

function bars(hist: Histogram): { x: number[]; y: number[]; width: number[] } {
  return { x: hist.counts.map((_, k) => 0.5 * (hist.edges[k]! + hist.edges[k + 1]!)), y: hist.counts,
    width: hist.counts.map((_, k) => hist.edges[k + 1]! - hist.edges[k]!) };
}

/** Phase-margin histograms of the tolerance samples, d and q, with the threshold. */
export function renderRobustHistogram(el: HTMLElement, r: RobustReport): void {
  const mc = r.monte_carlo!;
  const thr = r.config.min_phase_margin_deg;
  const peak = Math.max(1, ...mc.phase_margin_deg.d.counts, ...mc.phase_margin_deg.q.counts);
  plotRaw(el, [
    { type: 'bar', ...bars(mc.phase_margin_deg.d), name: 'd', marker: { color: COLORS.si }, opacity: 0.6 },
    { type: 'bar', ...bars(mc.phase_margin_deg.q), name: 'q', marker: { color: COLORS.fixed }, opacity: 0.6 },
    { type: 'scatter', mode: 'lines', x: [thr, thr], y: [0, peak], name: `${thr}°`, line: { color: COLORS.naive, dash: 'dash' } },
  ], {
    barmode: 'overlay',
    legend: { orientation: 'h', y: 1.1, x: 0 },
    xaxis: { title: { text: `${t('pm')} [°]` }, gridcolor: '#eaeef2' },
    yaxis: { title: { text: t('robustCount') }, gridcolor: '#eaeef2' },
  }, 300);
}

/** The step at the worst case: float and fixed point, their difference below. */
export function renderRobustStep(el: HTMLElement, r: RobustReport): void {
  const s = r.step!;
  const ms = s.t.map((x) => x * 1e3);
  const fixed = s.fixed;  // null: the Inovance firmware cannot hold this drive
  plot(el, [
    { x: ms, y: s.float, name: t('variant_float'), color: COLORS.si },
    ...(fixed ? [{ x: ms, y: fixed, name: t('variant_fixed'), color: COLORS.fixed, dash: 'dash' as const }] : []),
    { x: [0, ms[ms.length - 1] ?? 0], y: [s.ref_a, s.ref_a], name: 'ref', color: COLORS.ref, dash: 'dot', width: 1 },
    ...(fixed ? [{ x: ms, y: fixed.map((v, k) => v - s.float[k]!), name: 'Δ', color: COLORS.fixed, yaxis: 'y2' as const, width: 1.2 }] : []),
  ], { xTitle: `${t('time')} [ms]`, yTitle: `i_${s.axis} [A]`, y2Title: 'fixed − float [A]', lower: 0.25 });
}
