// embed.js — the one script tag a docs page adds to show pu-lab panels, in either form:
//   <script src="https://host/tools/pu-lab/embed.js"></script>                (classic: no CORS)
//   <script type="module" src="https://host/tools/pu-lab/embed.js"></script>  (needs CORS)
//   <pu-lab-panel panel="vendor" lang="zh" input='{"motor": {...}}'></pu-lab-panel>
// Built as one classic script (an IIFE: no import/export, no import.meta), so the same file runs
// in both forms. Each element holds an iframe of the site's `?embed=` page, found relative to this
// script's own URL (any sub-path, any origin; see scriptSrc). An iframe, not rendering into the
// host page: the host's CSS and CSP stay out of the panel, and every frame of the site's origin
// shares the runtime its SharedWorker already is (many panels, one or two runtimes). The host page
// never fetches anything else from the site: the frame loads the rest, same-origin. The frame
// reports its height and its numbers by postMessage (messages.ts); the element sizes itself and
// re-raises the report as a `pu-lab-report` DOM event. Contract: docs/contract.md, "Embedding".
import type { FrameMessage, SizeMessage, ReportMessage, Theme } from './messages';

/** A message from a frame this element understands, or null. */
function frameMessage(data: unknown): FrameMessage | null {
  const m = data as Partial<FrameMessage> | null;
  if (!m || typeof m !== 'object' || m.source !== 'pu-lab') return null;
  if (m.type === 'size') return typeof m.height === 'number' && Number.isFinite(m.height) && m.height >= 0 ? (m as SizeMessage) : null;
  if (m.type === 'report') return typeof m.panel === 'string' && typeof m.numbers === 'string' ? (m as ReportMessage) : null;
  return null;
}

/**
 * This script's URL. A classic script is `document.currentScript` while it first runs (null
 * afterwards, and always null in a module script); a module script — deferred, run in document
 * order — is the first `<script type="module" src>` of the document whose path ends in
 * `/embed.js`. Loading embed.js by `import()` leaves neither: null.
 */
function scriptSrc(): string | null {
  const cur = document.currentScript;
  if (cur instanceof HTMLScriptElement && cur.src) return cur.src;
  const tag = Array.from(document.querySelectorAll<HTMLScriptElement>('script[src]'))
    .find((s) => s.type.trim().toLowerCase() === 'module' && /\/embed\.js([?#]|$)/.test(s.src));
  return tag ? tag.src : null;
}

const SRC = scriptSrc();
const SITE = new URL('./', SRC ?? document.baseURI);
const PANEL_ATTRS = ['panel', 'lang', 'input', 'theme'] as const;
const dark = window.matchMedia('(prefers-color-scheme: dark)');

/** The `?embed=` page for these attributes. */
function frameUrl(panel: string, lang: string | null, input: string | null, theme: Theme): string {
  const u = new URL(SITE);
  u.searchParams.set('embed', panel);
  if (lang === 'zh' || lang === 'en') u.searchParams.set('lang', lang);
  u.searchParams.set('theme', theme);
  if (input && input.trim()) u.hash = 'in=' + encodeURIComponent(input.trim());
  return u.href;
}

class PuLabPanel extends HTMLElement {
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

function define(): void {
  if (customElements.get('pu-lab-panel')) return;
  if (SRC === null) throw new Error('pu-lab: load embed.js with a <script src> tag (classic or type="module"), not import()');
  customElements.define('pu-lab-panel', PuLabPanel);
}

// A classic tag in the page's head runs before the elements below it are parsed; defined then,
// an element would be connected before its children (the prerendered numbers) exist. Defining
// once the document is parsed — when a module tag runs anyway — gives both forms the same start.
if (document.readyState === 'loading') document.addEventListener('DOMContentLoaded', define, { once: true });
else define();
