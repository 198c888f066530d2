// Explainer chapters (docs/zh, docs/en, docs/index.json) rendered with the current
// report: {{path}} values, {{panel:NAME}} and {{plot:NAME}} embeds, links back to the panels.
import { h, morph, num, patch, scrollToEl, table } from '../dom';
import { SECTIONS, fieldLabel } from '../fields';
import { fmtNum } from '../format';
import { fromSI } from '../units';
import { getLang, t } from '../i18n';
import { renderMarkdown } from '../docs/render';
import { getPath } from '../state';
import { choiceText } from '../vendors';
import { renderCurrentStep } from '../figures/current-step';
import { renderPllTrack } from '../figures/pll-track';
import { keptFigure, simPlaceholder } from '../figures/figure';
import type { Panel, PanelContext } from './panel';
import { applyProgress, wireExercises } from '../course/exercises';
import '../course/course.css';

const CHAPTERS = import.meta.glob('../../../docs/{zh,en}/*.md', { query: '?raw', import: 'default', eager: true }) as Record<string, string>;
const INDEX = Object.values(import.meta.glob('../../../docs/index.json', { import: 'default', eager: true }))[0] as DocsIndex | undefined;

export interface DocsIndex {
  chapters: { id: string; file: string; title: { zh: string; en: string } }[];
  panels: Record<string, string>;
}

export function docsAvailable(): boolean {
  return !!INDEX && INDEX.chapters.length > 0 && Object.keys(CHAPTERS).length > 0;
}

/** "01-per-unit#bases" for a panel, or null. */
export function docTarget(panel: string): { chapter: string; anchor: string } | null {
  const v = INDEX?.panels[panel];
  if (!v) return null;
  const [chapter, anchor = ''] = v.split('#');
  return { chapter, anchor };
}

let registry: Panel[] = [];
/** The panels that {{panel:NAME}} can embed (set by the app; avoids an import cycle). */
export function setPanelRegistry(p: Panel[]): void {
  registry = p;
}

const state = { chapter: INDEX?.chapters[0]?.id ?? '', anchor: '' };

export function openChapter(chapter: string, anchor = ''): void {
  if (INDEX?.chapters.some((c) => c.id === chapter)) state.chapter = chapter;
  state.anchor = anchor;
}

function chapterText(id: string): string | null {
  const file = INDEX?.chapters.find((c) => c.id === id)?.file;
  if (!file) return null;
  const key = Object.keys(CHAPTERS).find((k) => k.endsWith(`/docs/${getLang()}/${file}`))
    ?? Object.keys(CHAPTERS).find((k) => k.endsWith(`/docs/en/${file}`));
  return key ? CHAPTERS[key] : null;
}

const timers = new WeakMap<HTMLElement, ReturnType<typeof setTimeout>>();
const pending = new WeakMap<HTMLElement, () => void>();
const visible = new WeakSet<HTMLElement>();
const observed = new WeakSet<HTMLElement>();
let io: IntersectionObserver | null = null;

function flush(el: HTMLElement): void {
  clearTimeout(timers.get(el));
  timers.set(el, setTimeout(() => {
    const job = pending.get(el);
    pending.delete(el);
    job?.();
  }, 30));
}

function observe(el: HTMLElement): void {
  if (observed.has(el) || typeof IntersectionObserver === 'undefined') return;
  io ??= new IntersectionObserver((entries) => {
    for (const e of entries) {
      const target = e.target as HTMLElement;
      if (e.isIntersecting) {
        visible.add(target);
        if (pending.has(target)) flush(target);
      } else visible.delete(target);
    }
  }, { rootMargin: '400px' });
  io.observe(el);
  observed.add(el);
}

/** The reader's inputs as Python normalized them (defaults filled in), for {{panel:inputs}}. */
function inputsSummary(ctx: PanelContext): HTMLElement {
  const inp = ctx.report?.input;
  const rows = SECTIONS.filter((s) => ['motor', 'drive', 'conventions'].includes(s.id)).flatMap((s) =>
    s.fields.flatMap((f) => {
      const [sec, key] = f.path.split('.');
      const v = inp?.[sec]?.[key];
      if (v === null || v === undefined) return [];
      // data-value stays SI; the text uses the form's default display unit (600 µH, 100 µs).
      const u = f.units?.[0];
      const shown = typeof v !== 'number' ? choiceText(f.path, String(v))
        : num(`input.${f.path}`, v, u ? { unit: u, text: fmtNum(fromSI(v, u), 6) } : { unit: f.unit });
      return [[fieldLabel(f, getLang()), shown]];
    }));
  return table([t('quantity'), t('value')], rows, 'doc-inputs');
}

/** The panels and plots a chapter embeds, each patched in place (its kept slot: `data-keep`). */
function fillEmbeds(body: HTMLElement, ctx: PanelContext): void {
  for (const el of body.querySelectorAll<HTMLElement>('[data-embed-panel]')) {
    const name = el.dataset.embedPanel ?? '';
    const p = registry.find((x) => x.id === name && x.id !== 'docs');
    const link = h('a', { href: `#panel-${name}`, 'data-panel-link': name, class: 'doc-embed-link' }, `↗ ${p ? t(p.title as never) : t('inputs')}`);
    patch(el, link, p ? h('div', { class: 'panel-body', 'data-keep': 'panel' }) : inputsSummary(ctx));
    if (p) p.render(el.querySelector<HTMLElement>(':scope > .panel-body')!, ctx);
  }
  for (const el of body.querySelectorAll<HTMLElement>('[data-embed-plot]')) {
    const name = el.dataset.embedPlot;
    const link = h('a', { href: `#panel-${name}`, 'data-panel-link': name ?? '', class: 'doc-embed-link' }, `↗ ${t(name === 'pll' ? 'plotPll' : 'plotCurrent')}`);
    patch(el, link, h('div', { class: 'figure', 'data-keep': 'plot' }));
    const sim = ctx.simReport?.sim;
    const axis = String((ctx.input.sim?.current as Record<string, unknown> | undefined)?.axis ?? 'd') === 'q' ? 'q' : 'd';
    const shown = name === 'current' ? sim?.current : name === 'pll' ? sim?.pll : undefined;
    keptFigure(el, 'plot', shown, (fig) => name === 'current' ? renderCurrentStep(fig, sim!.current!, axis) : renderPllTrack(fig, sim!.pll!), () => simPlaceholder(ctx));
  }
}

export const docsPanel: Panel = {
  id: 'docs',
  usesSim: true,
  needsPython: true,
  title: 'p_docs',
  render(el, ctx) {
    if (!docsAvailable() || !INDEX) {
      el.replaceChildren(h('p', {}, t('docsMissing')));
      return;
    }
    const lang = getLang();
    const nav = h('nav', { class: 'doc-nav' }, INDEX.chapters.map((c) =>
      h('button', { type: 'button', class: c.id === state.chapter ? 'on' : '', 'data-chapter': c.id, onclick: () => { openChapter(c.id); docsPanel.render(el, ctx); } }, `${parseInt(c.id, 10)}. ${c.title[lang]}`)));
    // The chapter is kept across renders (its job below patches it): typing re-lays out only the
    // numbers that changed, not the whole chapter.
    patch(el, nav, h('article', { class: 'doc', 'data-keep': 'chapter' }, h('p', { class: 'note' }, '…')));
    const body = el.querySelector<HTMLElement>(':scope > article.doc')!;
    // Chapters are long: rendered only while visible, and after the numbers of the other panels.
    pending.set(el, () => {
      const fresh = h('article');
      fresh.innerHTML = renderMarkdown(chapterText(state.chapter) ?? '', { value: (p) => getPath(ctx.report, p) ?? getPath(ctx.simReport, p) });
      // The embedded panels and plots are kept too, then patched by fillEmbeds.
      for (const e of fresh.querySelectorAll('[data-embed-panel], [data-embed-plot]')) e.setAttribute('data-keep', `embed ${e.getAttribute('data-embed-panel') ?? ''} ${e.getAttribute('data-embed-plot') ?? ''}`);
      morph(body, fresh);
      body.dataset.chapter = state.chapter;
      fillEmbeds(body, ctx);
      const raw = ctx.report?.vendor?.raw as Record<string, number> | undefined;
      const env = { input: () => ctx.input, reportInput: () => ctx.report?.input ?? null, raw: () => raw ?? null, client: () => ctx.client };
      wireExercises(body, env);
      applyProgress(body, env);
      if (state.anchor) {
        scrollToEl(body.querySelector(`[data-anchor="${CSS.escape(state.anchor)}"]`));
        state.anchor = '';
      }
    });
    observe(el);
    if (visible.has(el) || state.anchor || ctx.embed) flush(el);
  },
};
