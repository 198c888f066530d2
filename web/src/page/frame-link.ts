// An embedded panel talking to the page around its iframe (protocol: embed/messages.ts): its
// height whenever it changes (so the host sizes the iframe to its content: no inner scrollbar, no
// guessed height), its report whenever the numbers shown change (so host text can quote them),
// and the host's light/dark scheme in return. The numbers are public; any host may listen.
import type { FrameMessage, ThemeMessage, Theme } from '../embed/messages';
import type { NumbersSource } from './numbers';

const isTheme = (v: unknown): v is Theme => v === 'light' || v === 'dark';

/** A message from the host this frame understands, or null. */
function hostMessage(data: unknown): ThemeMessage | null {
  const m = data as Partial<ThemeMessage> | null;
  return m && typeof m === 'object' && m.source === 'pu-lab' && m.type === 'theme' && isTheme(m.theme) ? (m as ThemeMessage) : null;
}

/** Show the page in `theme` (CSS: html[data-theme]). */
export function applyTheme(theme: Theme): void {
  document.documentElement.dataset.theme = theme;
}

/** The theme the URL asks for (`theme=light|dark`), if any. */
export function themeParam(params: URLSearchParams): Theme | null {
  const t = params.get('theme');
  return isTheme(t) ? t : null;
}

/** Start talking to the parent window (a no-op outside a frame). `report` reads the report shown. */
export function linkToHost(panel: string, report: () => unknown): void {
  if (window.parent === window) return;
  const post = (m: FrameMessage): void => window.parent.postMessage(m, '*');
  const root = document.documentElement;
  let height = -1;
  let measured = -Infinity;
  let timer: ReturnType<typeof setTimeout> | undefined;
  // The body's scroll height also counts what overflows the boxes (it is not clamped to the
  // viewport, as the root's is, so the frame can shrink again).
  const size = (): void => {
    clearTimeout(timer);
    timer = undefined;
    measured = performance.now();
    const h = Math.ceil(Math.max(root.getBoundingClientRect().height, document.body.scrollHeight));
    if (h !== height) post({ source: 'pu-lab', type: 'size', height: (height = h) });
  };
  // Each measurement outside a rendering step is a forced layout, and DOM changes come in bursts
  // (the boot's progress line, a report's render: with 12 panels on a page, measuring at every
  // change took half of the main thread until all were live): at most one per MEASURE_MS, the
  // last change always measured.
  const MEASURE_MS = 100;
  const soon = (): void => {
    if (timer !== undefined) return;
    const wait = measured + MEASURE_MS - performance.now();
    if (wait <= 0) size();
    else timer = setTimeout(size, wait);
  };
  const ro = new ResizeObserver(size);
  ro.observe(root);
  ro.observe(document.body);
  // An off-screen frame of another origin gets no rendering steps (Chromium throttles it), so no
  // ResizeObserver callbacks: changes to the DOM and loaded fonts measure again as well.
  new MutationObserver(soon).observe(document.body, { subtree: true, childList: true, characterData: true, attributes: true });
  document.fonts.addEventListener('loadingdone', size);
  size();
  let sent = '';
  const numbers = (): void => {
    size();
    const source = (root.dataset.numbers ?? 'none') as NumbersSource;
    const r = report();
    const key = source + JSON.stringify(r);
    if (key === sent || source === 'none' || source === 'stale') return;
    sent = key;
    post({ source: 'pu-lab', type: 'report', panel, numbers: source, report: r });
  };
  new MutationObserver(numbers).observe(root, { attributes: true, attributeFilter: ['data-numbers'] });
  numbers();
  window.addEventListener('message', (ev) => {
    if (ev.source !== window.parent) return;
    const m = hostMessage(ev.data);
    if (m) applyTheme(m.theme);
  });
}
