// The page's skeleton (full page or one embedded panel), the panels rendered into it, the
// warnings list, and the stale marking of numbers that no longer match the form.
import { h } from '../dom';
import { errText, t, type Key } from '../i18n';
import type { Panel, PanelContext, PanelId } from '../panels/panel';
import { PANELS } from '../panels/registry';
import { docTarget, docsAvailable } from '../panels/docs';
import { allFindings, findingItem, markFindings, reviewCounts } from '../panels/review';
import type { ComputeSession } from './session';

/** Numbers later than this after an edit are faded as outdated (ms). */
const OUTDATED_MS = 300;
/** Renders of the pure panels while idle after the first live numbers (Layout.warmRenders). */
const WARM_RENDERS = 20;

/** Run `f` when the page is idle (at the latest after `timeout` ms). */
const idle = (f: () => void, timeout = 1000): void => {
  if (typeof requestIdleCallback === 'function') requestIdleCallback(f, { timeout });
  else setTimeout(f, Math.min(timeout, 500));
};

/** The review's errors and warnings at the top of the page (notes only in its panel). */
function warnings(ctx: PanelContext): HTMLElement[] {
  const all = allFindings(ctx);
  const serious = all.filter((f) => f.severity !== 'note');
  return ctx.report && serious.length ? [
    h('strong', {}, `${t('p_review')}: `), h('a', { href: '#panel-review', class: 'counts' }, reviewCounts(all)),
    h('ul', { class: 'findings' }, serious.map(findingItem))] : [];
}

export class Layout {
  private panelEls = new Map<PanelId, HTMLElement>();
  private outdatedTimer: ReturnType<typeof setTimeout> | undefined;
  private settled: 'no' | 'pending' | 'yes' = 'no';

  private near: IntersectionObserver | null = null;
  private onNear: (() => void) | null = null;
  /** Resolves once a panel that draws simulations is near the viewport (see ComputeSession.simGate). */
  readonly simPanelNear: Promise<void>;

  constructor(private root: HTMLElement, private embed: PanelId | null) {
    this.simPanelNear = new Promise((resolve) => {
      this.onNear = resolve;
    });
  }

  private watchSimPanels(sections: HTMLElement[]): void {
    if (!this.onNear) return;
    if (typeof IntersectionObserver === 'undefined') return this.onNear();
    this.near?.disconnect();
    this.near = new IntersectionObserver((entries) => {
      if (!entries.some((e) => e.isIntersecting)) return;
      this.near?.disconnect();
      this.onNear?.();
      this.onNear = null;
    }, { rootMargin: '600px 0px' });
    for (const s of sections) this.near.observe(s);
  }

  /** The panels this page shows: all of them, or the embedded one. */
  private panels(): Panel[] {
    return (this.embed ? PANELS.filter((p) => p.id === this.embed) : PANELS).filter((p) => p.id !== 'docs' || docsAvailable());
  }

  /** Build the skeleton; `chrome` is the header (full page) or the embed bar. */
  build(chrome: HTMLElement): void {
    this.panelEls.clear();
    const panels = this.panels();
    const sections = panels.map((p) => {
      const body = h('div', { class: 'panel-body' });
      this.panelEls.set(p.id, body);
      return h('section', { class: `panel panel-${p.id}`, id: `panel-${p.id}`, 'data-panel': p.id },
        h('h2', {}, t(p.title as Key), p.id !== 'docs' && docTarget(p.id) ? h('a', { class: 'why', href: `#panel-docs`, 'data-why': p.id }, t('why')) : null), body);
    });
    const has = (id: PanelId) => panels.some((p) => p.id === id);
    this.watchSimPanels(sections.filter((_, i) => panels[i].usesSim));
    if (this.embed) {
      document.body.classList.add('embed');
      this.root.replaceChildren(
        chrome,
        h('div', { class: 'inputs', hidden: true }),
        h('main', { class: this.settled === 'yes' ? 'panels settled' : 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), ...sections),
        h('div', { class: 'toast' }),
      );
      return;
    }
    // Bases and per-unit values side by side on wide screens.
    const ib = panels.findIndex((p) => p.id === 'bases');
    const body = has('bases') && has('pu') && panels[ib + 1]?.id === 'pu'
      ? [...sections.slice(0, ib), h('div', { class: 'pair' }, sections[ib], sections[ib + 1]), ...sections.slice(ib + 2)]
      : sections;
    this.root.replaceChildren(
      chrome,
      h('div', { class: 'layout' },
        h('aside', { class: 'inputs' }),
        h('div', { class: 'content' },
          h('nav', { class: 'tabs' }, panels.map((p) => h('a', { href: `#panel-${p.id}`, 'data-nav': p.id }, t(`nav_${p.id}` as Key)))),
          h('main', { class: this.settled === 'yes' ? 'panels settled' : 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), h('div', { class: 'warnings' }), ...body))),
      h('div', { class: 'toast' }),
    );
  }

  /** Render every panel (or only those in `only`), the review's findings at the top (on a full
   * render or with the review), and the marks at the values they concern. */
  renderPanels(ctx: PanelContext, only?: PanelId[]): void {
    const took: [string, number][] = [];
    for (const p of PANELS) {
      if (only && !only.includes(p.id)) continue;
      const el = this.panelEls.get(p.id);
      if (!el) continue;
      const t0 = performance.now();
      p.render(el, ctx);
      took.push([p.id, performance.now() - t0]);
    }
    // <html data-render-slowest>: the three slowest panels of the last render (the bench prints them).
    document.documentElement.dataset.renderSlowest = took.sort((a, b) => b[1] - a[1]).slice(0, 3).map(([id, ms]) => `${id} ${ms.toFixed(1)}`).join(', ');
    const w = this.root.querySelector('.warnings');
    if (w && (!only || only.length === 0 || only.includes('review'))) w.replaceChildren(...warnings(ctx));
    markFindings(this.root, allFindings(ctx));
  }

  /** After the first live numbers: lay out the panels off screen too, once the page is idle
   * (style.css), then warm the renderers up (`warmRenders`); a page built again later (a language
   * switch) starts settled. */
  settle(ctx: PanelContext): void {
    if (this.settled !== 'no') return;
    this.settled = 'pending';
    const go = (): void => {
      this.settled = 'yes';
      this.root.querySelector('main.panels')?.classList.add('settled');
      // Not in an embed: nobody types there (its form is hidden), and six of them held ≈ 11 MB more.
      if (!this.embed) this.warmRenders(ctx, WARM_RENDERS);
    };
    idle(go, 2000);
  }

  /** Every pure panel rendered with `ctx` into `bodies` (new detached ones when not given). */
  private renderPure(ctx: PanelContext, bodies?: Map<PanelId, HTMLElement>): Map<PanelId, HTMLElement> {
    const out = bodies ?? new Map<PanelId, HTMLElement>();
    for (const p of this.panels()) {
      if (!p.pure) continue;
      const body = out.get(p.id) ?? h('div', { class: 'panel-body' });
      p.render(body, ctx);
      out.set(p.id, body);
    }
    return out;
  }

  /**
   * Render the pure panels `runs` more times into detached elements, one run per idle period (the
   * first builds, the others patch: the code paths of a keystroke). The first keystrokes' renders
   * ran up to twice as long as later ones: JavaScript not yet optimized by the engine.
   */
  private warmRenders(ctx: PanelContext, runs: number): void {
    let bodies: Map<PanelId, HTMLElement> | undefined;
    const step = (): void => {
      bodies = this.renderPure(ctx, bodies);
      if (--runs > 0) idle(step);
    };
    if (runs > 0) idle(step);
  }

  /**
   * Lay out the pure panels once with `ctx` (the build's seed report) in a hidden scratch box, and
   * remove it in the same task (nothing can see its numbers). A page opened without any known
   * numbers (a share link) has only placeholders to lay out while Python boots; its first live
   * render then paid ≈ 0.2–0.3 s of font lookups and text shaping on the main thread. Done here,
   * that work overlaps the boot.
   */
  warmUp(ctx: PanelContext): void {
    const host = this.root.querySelector('main.panels');
    if (!host) return;
    const box = h('div', { class: 'warmup', 'aria-hidden': 'true' }, h('div', { class: 'warnings' }, warnings(ctx)));
    for (const [id, body] of this.renderPure(ctx)) box.append(h('section', { class: `panel panel-${id}` }, body));
    host.append(box);
    void box.offsetHeight;
    box.remove();
  }

  /**
   * Mark the panels stale while the form holds an input they were not computed from, with the
   * reason in the banner; an error naming no field of the form (a section, the whole input) is
   * shown above the panels.
   */
  showStale(session: ComputeSession, hasField: (field: string) => boolean): void {
    const { localErrors, remoteError: re } = session;
    const stale = session.stale;
    const panels = this.root.querySelector('.panels');
    panels?.classList.toggle('stale', stale);
    // Between an edit and its numbers the panels show the previous input's: marked when the
    // numbers take longer than OUTDATED_MS. Not at once: the class fades every panel, which made
    // the browser repaint the whole page on each keystroke while the report was on its way.
    clearTimeout(this.outdatedTimer);
    if (!stale && session.outdated) this.outdatedTimer = setTimeout(() => panels?.classList.toggle('outdated', !session.stale && session.outdated), OUTDATED_MS);
    else panels?.classList.remove('outdated');
    const global = this.root.querySelector('.global-error');
    if (global) global.textContent = re && !hasField(re.field) ? `${re.field}: ${errText(re)}` : '';
    const banner = this.root.querySelector('.stale-banner');
    if (banner && stale) {
      const f = localErrors.size ? [...localErrors.keys()][0] : re?.field ?? '';
      const msg = localErrors.size ? localErrors.get(f) : re && errText(re);
      banner.textContent = `${t('staleField')}${f ? `${f}: ` : ''}${msg ?? ''}`;
    }
  }
}
