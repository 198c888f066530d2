// embed.js — the one script tag a docs page adds to show pu-lab panels:
//   <script type="module" src="https://host/tools/pu-lab/embed.js"></script>
//   <pu-lab-panel panel="vendor" lang="zh" input='{"motor": {...}}'></pu-lab-panel>
// Each element holds an iframe of the site's `?embed=` page, found relative to this script's own
// URL (any sub-path, any origin). An iframe, not rendering into the host page: the host's CSS and
// CSP stay out of the panel, and every frame of the site's origin shares the runtime its
// SharedWorker already is (many panels, one or two runtimes). The frame reports its height and
// its numbers by postMessage (messages.ts); the element sizes itself and re-raises the report as a
// `pu-lab-report` DOM event. Contract: docs/contract.md, "Embedding".
import type { FrameMessage, SizeMessage, ReportMessage, Theme } from './messages';

/** A message from a frame this element understands, or null. */
function frameMessage(data: unknown): FrameMessage | null {
  const m = data as Partial<FrameMessage> | null;
  if (!m || typeof m !== 'object' || m.source !== 'pu-lab') return null;
  if (m.type === 'size') return typeof m.height === 'number' && Number.isFinite(m.height) && m.height >= 0 ? (m as SizeMessage) : null;
  if (m.type === 'report') return typeof m.panel === 'string' && typeof m.numbers === 'string' ? (m as ReportMessage) : null;
  return null;
}

const SITE = new URL(/* @vite-ignore */ './', import.meta.url);
const PANEL_ATTRS = ['panel', 'lang', 'input', 'theme'] as const;
const dark = window.matchMedia('(prefers-color-scheme: dark)');

/** The `?embed=` page for these attributes. */
export function frameUrl(panel: string, lang: string | null, input: string | null, theme: Theme): string {
  const u = new URL(SITE);
  u.searchParams.set('embed', panel);
  if (lang === 'zh' || lang === 'en') u.searchParams.set('lang', lang);
  u.searchParams.set('theme', theme);
  if (input && input.trim()) u.hash = 'in=' + encodeURIComponent(input.trim());
  return u.href;
}

export class PuLabPanel extends HTMLElement {
  static observedAttributes = [...PANEL_ATTRS];
  private frame: HTMLIFrameElement | null = null;
  private src = '';
  /** What the host page put inside the element (the numbers prerendered at docs build time):
   * shown until the frame shows numbers, so the page reads correctly before and without scripts. */
  private prerendered: Element[] = [];
  /** The frame stays collapsed behind prerendered numbers until it sends its first report. */
  private waitReport = false;
  private height = 0;

  private get theme(): Theme {
    const t = this.getAttribute('theme');
    return t === 'light' || t === 'dark' ? t : dark.matches ? 'dark' : 'light';
  }

  connectedCallback(): void {
    if (!this.frame) {
      const f = document.createElement('iframe');
      f.title = 'pu-lab';
      f.setAttribute('scrolling', 'no');
      f.style.cssText = 'display:block;width:100%;border:0;height:0;overflow:hidden';
      this.style.display ||= 'block';
      this.prerendered = [...this.children];
      this.waitReport = this.prerendered.some((el) => el.matches('[data-key]') || el.querySelector('[data-key]') !== null);
      this.frame = f;
    }
    this.append(this.frame);
    window.addEventListener('message', this.onMessage);
    dark.addEventListener('change', this.onScheme);
    this.load();
  }

  disconnectedCallback(): void {
    window.removeEventListener('message', this.onMessage);
    dark.removeEventListener('change', this.onScheme);
  }

  attributeChangedCallback(name: string): void {
    if (!this.frame) return;
    if (name === 'theme') this.onScheme();
    else this.load();
  }

  private load(): void {
    const src = frameUrl(this.getAttribute('panel') ?? 'bases', this.getAttribute('lang'), this.getAttribute('input'), this.theme);
    // A theme change alone is sent as a message; reloading would restart the panel.
    const sameButTheme = src.replace(/theme=\w+/, '') === this.src.replace(/theme=\w+/, '');
    if (this.frame && !sameButTheme) this.frame.src = src;
    this.src = src;
  }

  private reveal(): void {
    if (!this.frame) return;
    this.frame.style.height = `${this.height}px`;
    if (this.height > 0) for (const el of this.prerendered) el.setAttribute('hidden', '');
  }

  private onScheme = (): void => {
    this.frame?.contentWindow?.postMessage({ source: 'pu-lab', type: 'theme', theme: this.theme }, SITE.origin);
  };

  private onMessage = (ev: MessageEvent): void => {
    if (!this.frame || ev.source !== this.frame.contentWindow || ev.origin !== SITE.origin) return;
    const m = frameMessage(ev.data);
    if (m?.type === 'size') {
      this.height = m.height;
      if (!this.waitReport) this.reveal();
    } else if (m?.type === 'report') {
      this.waitReport = false;
      this.reveal();
      this.dataset.numbers = m.numbers;
      this.dispatchEvent(new CustomEvent('pu-lab-report', { bubbles: true, detail: { panel: m.panel, numbers: m.numbers, report: m.report } }));
    }
  };
}

if (!customElements.get('pu-lab-panel')) {
  customElements.define('pu-lab-panel', PuLabPanel);
}
