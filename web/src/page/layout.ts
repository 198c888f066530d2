// The page's skeleton (full page or one embedded panel): the answer strip, the views (tabs) and
// the panels rendered into them, and the stale marking of numbers that no longer match the form.
import { h, keepFocus, patch, releaseFormulas } from '../dom';
import { errText, t, type Key } from '../i18n';
import type { Panel, PanelContext, PanelId } from '../panels/panel';
import { PANELS } from '../panels/registry';
import { docTarget, docsAvailable } from '../panels/docs';
import { allFindings, markFindings } from '../panels/review';
import { viewsFor, type View } from '../panels/views';
import { renderAnswer } from './answer';
import type { Vendor } from '../vendors';
import { closeInputs, openInputs, wireDrawer } from './drawer';
import type { ComputeSession } from './session';

/** Numbers later than this after an edit are faded as outdated (ms). */
const OUTDATED_MS = 300;
/** The sticky header and tabs cover this much of the view's top (style.css, scroll-margin-top). */
const ANCHOR_BELOW_PX = 84;
/** Renders of the pure panels while idle after the first live numbers (Layout.warmRenders). */
const WARM_RENDERS = 20;

/** Run `f` when the page is idle (at the latest after `timeout` ms). */
const idle = (f: () => void, timeout = 1000): void => {
  if (typeof requestIdleCallback === 'function') requestIdleCallback(f, { timeout });
  else setTimeout(f, Math.min(timeout, 500));
};

/** The panels that show an induction motor's report (motor.kind = acim); the others compute a
 * permanent-magnet motor and say so instead of reading sections its report does not have. */
const ACIM_PANELS = new Set<PanelId>(['acim', 'review', 'bases', 'pll', 'qcalc', 'conventions', 'docs', 'board']);

function renderPanel(p: Panel, el: HTMLElement, ctx: PanelContext): void {
  if (ctx.report?.acim && !ACIM_PANELS.has(p.id)) patch(el, h('p', { class: 'note acim-na' }, t('acimNotApplicable')));
  else p.render(el, ctx);
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
    this.waiting.clear();
    const panels = this.panels();
    const sections = panels.map((p) => {
      const body = h('div', { class: 'panel-body' });
      this.panelEls.set(p.id, body);
      return h('section', { class: `panel panel-${p.id}`, id: `panel-${p.id}`, 'data-panel': p.id },
        h('h2', {}, t(p.title as Key), p.id !== 'docs' && docTarget(p.id) ? h('a', { class: 'why', href: `#panel-docs`, 'data-why': p.id }, t('why')) : null,
          h('span', { class: 'scroll-cue', 'aria-hidden': 'true' }, `⇆ ${t('scrollsSideways')}`)), body);
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
    this.views = viewsFor(panels.map((p) => p.id));
    if (!this.views.some((v) => v.id === this.view)) this.view = this.openingView();
    for (const sec of sections) this.revealOnScroll(sec);
    // In the order the views list them (their sub-navigation's order), not the registry's.
    const ids = this.views.flatMap((v) => v.panels);
    const ordered = ids.map((id) => sections[panels.findIndex((p) => p.id === id)]);
    // Bases and per-unit values side by side on wide screens.
    const ib = ids.indexOf('bases');
    const body = has('bases') && has('pu') && ids[ib + 1] === 'pu'
      ? [...ordered.slice(0, ib), h('div', { class: 'pair' }, ordered[ib], ordered[ib + 1]), ...ordered.slice(ib + 2)]
      : ordered;
    this.root.replaceChildren(
      chrome,
      h('div', { class: 'layout' },
        h('aside', { class: 'inputs', id: 'inputs' }),
        h('div', { class: 'drawer-backdrop', onclick: closeInputs }),
        h('div', { class: 'content' },
          h('nav', { class: 'tabs', 'aria-label': t('viewsLabel') },
            h('button', { type: 'button', class: 'inputs-toggle', 'aria-controls': 'inputs', onclick: openInputs }, t('inputsOpen')),
            this.views.map((v) => h('a', { href: `#panel-${v.panels[0]}`, 'data-view': v.id }, t(`view_${v.id}` as Key)))),
          h('nav', { class: 'subtabs' }),
          h('main', { class: this.settled === 'yes' ? 'panels settled' : 'panels' }, h('div', { class: 'stale-banner', role: 'status' }), h('div', { class: 'global-error' }),
            h('section', { class: 'answer', 'aria-label': t('answerIntegers') }), ...body))),
      h('div', { class: 'toast' }),
    );
    wireDrawer();
    this.showView(this.view);
    if (!this.resizeWired) {
      this.resizeWired = true;
      window.addEventListener('resize', () => this.markScrollersSoon());
    }
  }

  private resizeWired = false;
  /** The panel whose view the page opens on (a link that carries that panel's state), else the first view. */
  openOn: PanelId | null = null;
  /** The views (tabs) of this page, and the one shown. */
  private views: View[] = [];
  private view = '';

  /** The view the page opens on: the one of `openOn`, else the first. */
  private openingView(): string {
    return (this.openOn && this.viewOf(this.openOn)) || (this.views[0]?.id ?? '');
  }

  /** Show the view the page opens on (a link opened in this tab). */
  showOpeningView(): void {
    this.showView(this.openingView());
  }

  /** Show the view `id`: its panels, its tab marked, the panel links of its sub-navigation. */
  showView(id: string): void {
    const view = this.views.find((v) => v.id === id);
    if (!view) return;
    this.view = id;
    for (const [pid, body] of this.panelEls) {
      const sec = body.closest<HTMLElement>('section.panel');
      if (sec) sec.hidden = !view.panels.includes(pid);
    }
    const due = view.panels.filter((p) => this.waiting.has(p));
    if (due.length && this.lastCtx) this.renderPanels(this.lastCtx, due);
    for (const a of this.root.querySelectorAll<HTMLElement>('nav.tabs a[data-view]')) {
      a.classList.toggle('on', a.dataset.view === id);
      if (a.dataset.view === id) a.setAttribute('aria-current', 'true');
      else a.removeAttribute('aria-current');
    }
    this.markScrollersSoon();
    this.root.querySelector('nav.subtabs')?.replaceChildren(...(view.panels.length > 1
      ? view.panels.map((p) => h('a', { href: `#panel-${p}`, 'data-nav': p }, t(`nav_${p}` as Key))) : []));
  }

  /** Typeset the formulas held since the page started (dom.ts `holdFormulas`) once the page is
   * idle, then look again at what scrolls sideways (a formula may be wider than its panel). */
  showFormulas(): void {
    idle(() => {
      releaseFormulas(this.root);
      this.markScrollersSoon();
    }, 1000);
  }

  private scrollCheck = false;
  /** Once the page is idle: mark what scrolls sideways (markScrollers). */
  private markScrollersSoon(): void {
    if (this.scrollCheck) return;
    this.scrollCheck = true;
    idle(() => {
      this.scrollCheck = false;
      this.markScrollers();
    }, 300);
  }

  /**
   * Wide content that scrolls sideways inside a shown panel says so: the scroller gets
   * `x-scroll` (edge shadows, style.css) and its panel a "⇆ scrolls sideways" cue in its title.
   */
  private markScrollers(): void {
    for (const sec of this.root.querySelectorAll<HTMLElement>('section.panel:not([hidden])')) {
      let any = false;
      for (const el of sec.querySelectorAll<HTMLElement>('.panel-body, .scroll, .code-out, .code-trace, .formulas')) {
        const wide = el.scrollWidth > el.clientWidth + 1 && getComputedStyle(el).overflowX === 'auto';
        if (el.classList.contains('x-scroll') !== wide) el.classList.toggle('x-scroll', wide);
        any ||= wide;
      }
      if (sec.classList.contains('x-scroll') !== any) sec.classList.toggle('x-scroll', any);
    }
  }

  /** The view that shows panel `id`. */
  viewOf(id: PanelId): string | undefined {
    return this.views.find((v) => v.panels.includes(id))?.id;
  }

  /**
   * A panel asked to scroll into view (a link, the nav, a finding, a test or a host script) first
   * shows its view: every panel stays reachable by its `#panel-<id>` element.
   */
  private revealOnScroll(sec: HTMLElement): void {
    const show = (): void => {
      const v = this.viewOf(sec.dataset.panel ?? '');
      if (v && v !== this.view) this.showView(v);
    };
    sec.scrollIntoView = (arg?: boolean | ScrollIntoViewOptions): void => {
      show();
      HTMLElement.prototype.scrollIntoView.call(sec, arg);
    };
  }

  /** Render every panel (or only those in `only`), the review's findings at the top (on a full
   * render or with the review), and the marks at the values they concern. */
  private lastCtx: PanelContext | null = null;
  /** The answer strip's firmware picker (the page sets it into the input). */
  onPickProfile: (v: Vendor) => void = () => undefined;

  /** The answer strip (page/answer.ts), with the last context; again when a profile's report arrives. */
  private renderAnswer = (): void => {
    const el = this.root.querySelector<HTMLElement>('section.answer');
    if (el && this.lastCtx) renderAnswer(el, this.lastCtx, this.renderAnswer, (v) => this.onPickProfile(v));
  };

  /** Panels of a hidden view not rendered yet. Before the first numbers they have nothing current to
   * show: the shown view is built first and these when the page is idle (or with the first report,
   * or when their view is shown, whichever comes first), so the first paint does not wait for them. */
  private waiting = new Set<PanelId>();

  renderPanels(ctx: PanelContext, only?: PanelId[], hiddenToo = false): void {
    this.keepTopPanel(() => this.renderPanelsNow(ctx, only, hiddenToo));
  }

  /**
   * Run `change` and keep the panel at the top of the view where it was. The browser anchors the
   * view to the first thing in it — often the last lines of the panel above, under the sticky
   * tabs — so when that panel grew (the loop panel once the simulations answer: 128 → 4685 px),
   * the panel being read was pushed off screen (the field-weakening panel: 4.5k px down, its plot
   * then never drawn).
   */
  private keepTopPanel(change: () => void): void {
    // At the top of the page nothing is above the view to grow; and no layout is forced there,
    // where a keystroke's render runs.
    if (window.scrollY <= 0) return change();
    const top = [...this.root.querySelectorAll<HTMLElement>('main.panels section.panel:not([hidden])')]
      .find((sec) => sec.getBoundingClientRect().bottom > ANCHOR_BELOW_PX);
    const before = top?.getBoundingClientRect().top;
    change();
    if (!top || before === undefined || !top.isConnected) return;
    const moved = top.getBoundingClientRect().top - before;
    if (moved !== 0) window.scrollBy(0, moved);
  }

  private renderPanelsNow(ctx: PanelContext, only?: PanelId[], hiddenToo = false): void {
    const took: [string, number][] = [];
    for (const p of PANELS) {
      if (only && !only.includes(p.id) && !(ctx.report && this.waiting.has(p.id))) continue;
      const el = this.panelEls.get(p.id);
      if (!el) continue;
      if (!ctx.report && !hiddenToo && el.closest<HTMLElement>('section.panel')?.hidden) {
        if (!this.waiting.size) idle(() => {
          if (this.waiting.size && this.lastCtx) this.renderPanels(this.lastCtx, [...this.waiting], true);
        }, 3000);
        this.waiting.add(p.id);
        continue;
      }
      this.waiting.delete(p.id);
      const t0 = performance.now();
      keepFocus(el, () => renderPanel(p, el, ctx));
      took.push([p.id, performance.now() - t0]);
    }
    // <html data-render-slowest>: the three slowest panels of the last render (the bench prints them).
    document.documentElement.dataset.renderSlowest = took.sort((a, b) => b[1] - a[1]).slice(0, 3).map(([id, ms]) => `${id} ${ms.toFixed(1)}`).join(', ');
    this.lastCtx = ctx;
    this.renderAnswer();
    this.markScrollersSoon();
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
      // The panels off screen take their real heights now (600 px each until then).
      this.keepTopPanel(() => this.root.querySelector('main.panels')?.classList.add('settled'));
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
      renderPanel(p, body, ctx);
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
    const f = localErrors.size ? [...localErrors.keys()][0] : re?.field ?? '';
    const msg = localErrors.size ? localErrors.get(f) : re && errText(re);
    const why = stale ? `${t('staleField')}${f ? `${f}: ` : ''}${msg ?? ''}` : '';
    const banner = this.root.querySelector('.stale-banner');
    if (banner && stale) banner.textContent = why;
    const note = this.root.querySelector('.inputs .stale-note');
    if (note && note.textContent !== why) note.textContent = why;
  }
}
