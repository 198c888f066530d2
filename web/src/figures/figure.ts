// Shared by the figures: Plotly loaded lazily as its own chunk, one common look.
import { h, patch } from '../dom';
import { getLang, t } from '../i18n';
import type { PanelContext } from '../panels/panel';

type PlotlyT = typeof import('plotly.js-basic-dist-min').default;
let plotly: Promise<PlotlyT> | null = null;

/** Plotly, loaded once; a failed load is forgotten so the next call tries again. */
export function loadPlotly(): Promise<PlotlyT> {
  plotly ??= import('plotly.js-basic-dist-min').then((m) => m.default, (e: unknown) => {
    plotly = null;
    throw e;
  });
  return plotly;
}

// Plots whose library failed to load: drawn again when the browser comes back online.
const failed = new Map<HTMLElement, () => void>();
if (typeof window !== 'undefined') window.addEventListener('online', () => {
  const jobs = [...failed.values()];
  failed.clear();
  for (const job of jobs) job();
});

export const COLORS: Record<string, string> = {
  si: '#1f6feb', pu: '#2da44e', fixed: '#d4670f', q15: '#8250df', naive: '#cf222e', ref: '#57606a', code: '#bf3989',
};

export interface Trace {
  x: number[];
  y: number[];
  name: string;
  color: string;
  dash?: 'solid' | 'dash' | 'dot';
  width?: number;
  yaxis?: 'y' | 'y2';
  opacity?: number;
}

// Plots are drawn only while (nearly) visible: Plotly costs tens of ms of main thread, which
// must not delay the numbers while the user types.
const pending = new WeakMap<HTMLElement, () => void>();
const visible = new WeakSet<HTMLElement>();
let io: IntersectionObserver | null = null;

function whenVisible(el: HTMLElement, job: () => void): void {
  if (typeof IntersectionObserver === 'undefined') return job();
  io ??= new IntersectionObserver((entries) => {
    for (const e of entries) {
      const target = e.target as HTMLElement;
      if (e.isIntersecting) {
        visible.add(target);
        const j = pending.get(target);
        pending.delete(target);
        j?.();
      } else visible.delete(target);
    }
  }, { rootMargin: '300px' });
  pending.set(el, job);
  io.observe(el);
  if (visible.has(el)) {
    pending.delete(el);
    job();
  }
}

export interface PlotLayout {
  xTitle: string;
  yTitle: string;
  y2Title: string;
  yRange?: [number, number];
  xRange?: [number, number];
  /** Logarithmic x axis (Bode plots). */
  xLog?: boolean;
  /** Share of the height for the lower subplot (default 0.26: an error trace; Bode: the phase). */
  lower?: number;
}

/** A figure with a main plot and a subplot below (y2). */
export function plot(el: HTMLElement, traces: Trace[], layout: PlotLayout): void {
  const lower = layout.lower ?? 0.26;
  plotRaw(el, traces.map((tr) => ({
    type: 'scatter', mode: 'lines', x: tr.x, y: tr.y, name: tr.name, yaxis: tr.yaxis ?? 'y',
    line: { color: tr.color, dash: tr.dash ?? 'solid', width: tr.width ?? 1.8 }, opacity: tr.opacity ?? 1, showlegend: tr.yaxis !== 'y2',
  })), {
    legend: { orientation: 'h', y: 1.08, x: 0 },
    grid: { rows: 2, columns: 1, roworder: 'top to bottom' },
    xaxis: { title: { text: layout.xTitle }, gridcolor: '#eaeef2', anchor: 'y2', range: layout.xRange, type: layout.xLog ? 'log' : 'linear' },
    yaxis: { title: { text: layout.yTitle }, domain: [lower + 0.1, 1], gridcolor: '#eaeef2', range: layout.yRange },
    yaxis2: { title: { text: layout.y2Title }, domain: [0, lower], gridcolor: '#eaeef2', zerolinecolor: '#aaa' },
  });
}

/** A figure from Plotly traces and layout as given (the common look added), drawn when visible. */
export function plotRaw(el: HTMLElement, data: object[], layout: Record<string, unknown>, height = 380): void {
  if (!el.querySelector('.plot-host')) el.replaceChildren(h('div', { class: 'plot-host' }, h('div', { class: 'plot-loading' }, t('plotLoading'))));
  const host = el.querySelector('.plot-host') as HTMLElement;
  // The stylesheet reserves 380 px per plot (no jump when it arrives); a shorter plot says so.
  if (height !== 380) host.style.minHeight = `${height}px`;
  whenVisible(host, () => draw(host, data, layout, height));
}

function draw(host: HTMLElement, data: object[], layout: Record<string, unknown>, height: number): void {
  failed.delete(host);
  loadPlotly().then((P) => {
    host.querySelector('.plot-loading, .plot-error')?.remove();
    return P.react(
      host,
      data as Parameters<PlotlyT['react']>[1],
      {
        height,
        margin: { l: 64, r: 16, t: 10, b: 44 },
        font: { family: 'system-ui, sans-serif', size: 12, color: '#24292f' },
        paper_bgcolor: 'rgba(0,0,0,0)', plot_bgcolor: '#fff',
        ...layout,
      },
      { displaylogo: false, responsive: true, modeBarButtonsToRemove: ['lasso2d', 'select2d'] },
    );
  }).catch(() => {
    // The chunk did not load (offline, blocked, a new deployment removed it): say so at the plot,
    // offer a retry, and retry by itself when the network returns. The numbers are unaffected.
    const again = (): void => {
      host.querySelector('.plot-error')?.replaceWith(h('div', { class: 'plot-loading' }, t('plotLoading')));
      draw(host, data, layout, height);
    };
    failed.set(host, again);
    host.querySelector('.plot-loading, .plot-error')?.remove();
    host.prepend(h('div', { class: 'plot-error', role: 'alert' }, t('plotFailed'), ' ',
      h('button', { type: 'button', class: 'plot-retry', onclick: again }, t('retry'))));
  });
}

/** What a plot shows while its simulation runs, or why it has none (with a retry when one helps). */
export function simPlaceholder(ctx: PanelContext): HTMLElement {
  if (!ctx.simError) return h('div', { class: 'plot-placeholder' }, t('simRunning'));
  return h('div', { class: 'sim-error', role: 'alert' }, t('simNotAvailable', { m: ctx.simError }),
    ctx.retrySim ? h('button', { type: 'button', class: 'sim-retry', onclick: ctx.retrySim }, t('retry')) : null);
}

/** What each kept figure element was last drawn with. */
const drawnWith = new WeakMap<HTMLElement, { data: unknown; lang: string }>();

/**
 * The figure slot `name` inside `el` (an element with `data-keep="name"`, which `patch` keeps
 * across renders): drawn by `draw` only when its data or the language changed since it was drawn,
 * so typing re-renders a panel's numbers without touching its plot; `empty()` shown while there
 * is no data.
 */
export function keptFigure(el: HTMLElement, name: string, data: unknown, draw: (fig: HTMLElement) => void, empty: () => Node | null = () => null): void {
  const fig = el.querySelector<HTMLElement>(`[data-keep="${name}"]`);
  if (!fig) return;
  const was = drawnWith.get(fig);
  const lang = getLang();
  if (data) {
    if (data !== was?.data || lang !== was?.lang) draw(fig);
  } else {
    const shown = empty();
    // A placeholder is patched over a placeholder; a plot (with the library's own listeners) is replaced.
    if (was && !was.data) patch(fig, shown);
    else fig.replaceChildren(...(shown ? [shown] : []));
  }
  drawnWith.set(fig, { data, lang });
}
