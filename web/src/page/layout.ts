// The page's skeleton (full page or one embedded panel), the panels rendered into it, the
// warnings list, and the stale marking of numbers that no longer match the form.
import { h } from '../dom';
import { errText, getLang, t, type Key } from '../i18n';
import type { Panel, PanelContext, PanelId } from '../panels/panel';
import { PANELS } from '../panels/registry';
import { docTarget, docsAvailable } from '../panels/docs';
import type { ComputeSession } from './session';

export class Layout {
  private panelEls = new Map<PanelId, HTMLElement>();

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
        h('main', { class: 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), ...sections),
        h('div', { class: 'toast' }),
      );
      return;
    }
    // Bases and per-unit values side by side on wide screens.
    const body = has('bases') && has('pu') && panels[0].id === 'bases' && panels[1].id === 'pu'
      ? [h('div', { class: 'pair' }, sections[0], sections[1]), ...sections.slice(2)]
      : sections;
    this.root.replaceChildren(
      chrome,
      h('div', { class: 'layout' },
        h('aside', { class: 'inputs' }),
        h('div', { class: 'content' },
          h('nav', { class: 'tabs' }, panels.map((p) => h('a', { href: `#panel-${p.id}`, 'data-nav': p.id }, t(`nav_${p.id}` as Key)))),
          h('main', { class: 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), h('div', { class: 'warnings' }), ...body))),
      h('div', { class: 'toast' }),
    );
  }

  /** Render every panel (or only those in `only`) and, on a full render, the warnings. */
  renderPanels(ctx: PanelContext, only?: PanelId[]): void {
    for (const p of PANELS) {
      if (only && !only.includes(p.id)) continue;
      const el = this.panelEls.get(p.id);
      if (el) p.render(el, ctx);
    }
    const w = this.root.querySelector('.warnings');
    if (w && (!only || only.length === 0)) {
      const list = (getLang() === 'zh' ? ctx.report?.warnings_zh : ctx.report?.warnings) ?? [];
      w.replaceChildren(...(list.length ? [h('strong', {}, `${t('warnings')}: `), h('ul', {}, list.map((x) => h('li', {}, x)))] : []));
    }
  }

  /**
   * Mark the panels stale while the form holds an input they were not computed from, with the
   * reason in the banner; an error naming no field of the form (a section, the whole input) is
   * shown above the panels.
   */
  showStale(session: ComputeSession, hasField: (field: string) => boolean): void {
    const { localErrors, remoteError: re } = session;
    const stale = session.stale;
    this.root.querySelector('.panels')?.classList.toggle('stale', stale);
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
