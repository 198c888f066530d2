// Sweep figures: 1-D error curves with the chosen integer's status regions and
// boundaries; 2-D status map. Every number drawn comes from pulab.analyses.sweep; nothing is computed here.
import { h } from '../dom';
import { t, type Key } from '../i18n';
import type { Boundary, Plan, Points, Status, Summary } from '../family/types';
import { loadPlotly } from './figure';

export const STATUS_COLORS: Record<Status, string> = {
  ok: '#2da44e', zero: '#8250df', store: '#d4670f', wrap: '#cf222e', div0: '#6e1e1e', invalid: '#8c959f',
};
const LINE_COLORS = ['#1f6feb', '#d4670f', '#2da44e', '#8250df', '#cf222e', '#57606a', '#bf8700', '#1b7c83', '#a40e26', '#6639ba', '#0a3069'];

const short = (name: string): string => name.replace(/^vendor\./, '').replace(/^current_pi\./, 'PI ').replace(/^profiles\.[^.]+\.constants\./, '');

function host(el: HTMLElement, cls: string): HTMLElement {
  let div = el.querySelector<HTMLElement>(`.${cls}`);
  if (!div) {
    div = h('div', { class: `plot-host ${cls}` }, h('div', { class: 'plot-loading' }, t('plotLoading')));
    el.append(div);
  }
  return div;
}

const base = {
  margin: { l: 64, r: 16, t: 10, b: 44 },
  font: { family: 'system-ui, sans-serif', size: 12, color: '#24292f' },
  paper_bgcolor: 'rgba(0,0,0,0)', plot_bgcolor: '#fff',
  legend: { orientation: 'h', y: 1.12, x: 0 },
};

/** |error| of every integer along x (log), m_BaseL below, `show`'s regions shaded and boundaries marked. */
export function renderSweep1d(el: HTMLElement, plan: Plan, pts: Points, sum: Summary, show: string): void {
  const div = host(el, 'sweep-1d');
  const traces: unknown[] = plan.names.map((name, i) => ({
    type: 'scatter', mode: 'lines', name: short(name), x: pts.x,
    y: pts.integers[name].error_pct.map((e) => (e === null || e === 0 ? null : Math.abs(e))),
    line: { color: LINE_COLORS[i % LINE_COLORS.length], width: name === show ? 2.6 : 1.2 },
    opacity: name === show ? 1 : 0.55, visible: name.startsWith('vendor.') || name === show ? true : 'legendonly',
  }));
  const inter = Object.entries(pts.intermediates);
  for (const [k, ys] of inter) {
    traces.push({ type: 'scatter', mode: 'lines', name: k, x: pts.x, y: ys, yaxis: 'y2', line: { color: '#57606a', width: 1.4, shape: 'hv' } });
  }
  const shapes: unknown[] = [];
  const notes: unknown[] = [];
  for (const r of sum.regions?.[show] ?? []) {
    if (r.status === 'ok') continue;
    shapes.push({ type: 'rect', xref: 'x', yref: 'paper', x0: r.from, x1: r.to, y0: 0, y1: 1, fillcolor: STATUS_COLORS[r.status], opacity: 0.16, line: { width: 0 }, layer: 'below' });
  }
  for (const b of sum.boundaries.filter((b) => b.name === show)) {
    shapes.push({ type: 'line', xref: 'x', yref: 'paper', x0: b.at, x1: b.at, y0: 0, y1: 1, line: { color: STATUS_COLORS[b.to], width: 1.2, dash: 'dash' } });
    notes.push({ x: plan.x.scale === 'log' ? Math.log10(b.at) : b.at, y: 1, xref: 'x', yref: 'paper', yanchor: 'bottom', showarrow: false, text: `${t(`st_${b.to}` as Key)} ${String(b.at)}`, font: { size: 11, color: STATUS_COLORS[b.to] } });
  }
  const two = inter.length > 0;
  const layout = {
    ...base, height: 420, shapes, annotations: notes,
    grid: two ? { rows: 2, columns: 1, roworder: 'top to bottom' } : undefined,
    xaxis: { title: { text: plan.x.path }, type: plan.x.scale === 'log' ? 'log' : 'linear', gridcolor: '#eaeef2', anchor: two ? 'y2' : 'y' },
    yaxis: { title: { text: `|${t('error')}| [%]` }, type: 'log', domain: two ? [0.34, 1] : [0, 1], gridcolor: '#eaeef2', exponentformat: 'power' },
    yaxis2: two ? { title: { text: inter.map(([k]) => k).join(', ') }, domain: [0, 0.24], gridcolor: '#eaeef2', rangemode: 'tozero' } : undefined,
  };
  void loadPlotly().then((P) => {
    div.querySelector('.plot-loading')?.remove();
    void P.react(div, traces, layout, { displaylogo: false, responsive: true, modeBarButtonsToRemove: ['lasso2d', 'select2d'] });
  });
}

/** Status of `show` at every grid point (squares), its boundaries as dots. */
export function renderSweep2d(el: HTMLElement, plan: Plan, pts: Points, sum: Summary, show: string): void {
  const div = host(el, 'sweep-2d');
  const col = pts.integers[show];
  const ys = pts.y ?? [];
  const nx = plan.x.values.length;
  const ny = plan.y?.values.length ?? 1;
  const size = Math.max(3, Math.min(18, Math.floor(560 / Math.max(nx, ny))));
  const traces: unknown[] = [];
  for (const s of ['ok', 'zero', 'store', 'wrap', 'div0', 'invalid'] as Status[]) {
    const idx = col.status.flatMap((st, i) => (st === s ? [i] : []));
    if (!idx.length) continue;
    traces.push({
      type: 'scatter', mode: 'markers', name: t(`st_${s}` as Key), x: idx.map((i) => pts.x[i]), y: idx.map((i) => ys[i]),
      text: idx.map((i) => (col.error_pct[i] === null ? s : `${col.error_pct[i]} %`)), hoverinfo: 'x+y+text',
      marker: { symbol: 'square', size, color: STATUS_COLORS[s], line: { width: 0 } },
    });
  }
  const bs = sum.boundaries.filter((b: Boundary) => b.name === show);
  if (bs.length) {
    traces.push({
      type: 'scatter', mode: 'markers', name: t('swBoundaries'),
      x: bs.map((b) => (b.axis === 'x' ? b.at : b.other)), y: bs.map((b) => (b.axis === 'y' ? b.at : b.other)),
      marker: { symbol: 'circle', size: 5, color: '#000' },
    });
  }
  const layout = {
    ...base, height: 460,
    xaxis: { title: { text: plan.x.path }, type: plan.x.scale === 'log' ? 'log' : 'linear', gridcolor: '#eaeef2' },
    yaxis: { title: { text: plan.y?.path ?? '' }, type: plan.y?.scale === 'log' ? 'log' : 'linear', gridcolor: '#eaeef2' },
  };
  void loadPlotly().then((P) => {
    div.querySelector('.plot-loading')?.remove();
    void P.react(div, traces, layout, { displaylogo: false, responsive: true, modeBarButtonsToRemove: ['lasso2d', 'select2d'] });
  });
}
