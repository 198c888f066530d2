// The page, put together: reads the URL (embed, chapter, language, #in= state), and wires the
// compute session to the form, the layout of panels, the header and the status line.
import 'katex/dist/katex.min.css';
import './style.css';
import { h } from './dom';
import { effectiveInput } from './fields';
import { defaultLang, getLang, setLang, t, type Lang } from './i18n';
import type { PulabClient } from './rpc';
import { STORAGE_KEY, initialInput } from './state';
import type { PanelContext, PanelId } from './panels/panel';
import { panelById } from './panels/registry';
import { openChapter } from './panels/docs';
import { ComputeSession } from './page/session';
import { InputForm } from './page/form';
import { Layout } from './page/layout';
import { StatusLine } from './page/status';
import { langSwitch, renderHeader } from './page/header';
import { handleLinks } from './page/links';
import { LANG_KEY, load, store } from './page/storage';

export class App {
  readonly embed: PanelId | null;
  readonly session: ComputeSession;
  private form: InputForm;
  private layout: Layout;
  private status: StatusLine;

  constructor(private root: HTMLElement) {
    const params = new URLSearchParams(location.search);
    this.embed = panelById(params.get('embed'))?.id ?? null;
    const chapter = params.get('chapter');
    if (chapter) openChapter(chapter, params.get('anchor') ?? '');
    const langParam = params.get('lang');
    setLang(langParam === 'zh' || langParam === 'en' ? langParam : defaultLang(navigator.languages, load(LANG_KEY)));
    const input = initialInput(location.hash, this.embed ? null : load(STORAGE_KEY)).input;
    this.session = new ComputeSession(input, this.embed !== null, {
      report: () => this.renderPanels(),
      sim: () => this.renderPanels(['current', 'pll', 'docs', 'review']),
      errors: () => this.showErrors(),
      busy: () => this.status.render(),
    });
    this.form = new InputForm(root, this.session);
    this.layout = new Layout(root, this.embed);
    this.status = new StatusLine(root, () => this.session.lastMs);
    window.addEventListener('hashchange', () => {
      const next = initialInput(location.hash, null);
      if (next.source === 'url' && JSON.stringify(effectiveInput(next.input)) !== JSON.stringify(effectiveInput(this.session.input))) {
        this.session.replaceInput(next.input);
        this.form.render();
      }
    });
  }

  /** Attach to a client that may already be booting (main.ts starts the worker first). */
  start(client: PulabClient): void {
    handleLinks(this.root, this.embed, () => this.renderPanels(['docs']));
    this.session.client = client;
    const onReady = (ms: number): void => {
      document.documentElement.dataset.bootMs = String(Math.round(ms));
      this.renderPanels();
      this.session.schedule(0);
    };
    this.status.follow(client, onReady);
    this.renderAll();
    if (client.ready) onReady(client.bootMs);
  }

  private ctx(): PanelContext {
    const s = this.session;
    return { report: s.report, simReport: s.simReport, simError: s.simError, input: s.input, client: s.ready ? s.client : null, embed: this.embed !== null };
  }

  renderPanels(only?: PanelId[]): void {
    this.layout.renderPanels(this.ctx(), only);
    if (!only) this.form.updatePlaceholders();
  }

  private showErrors(): void {
    this.form.showErrors();
    this.layout.showStale(this.session, (f) => this.form.hasField(f));
  }

  private switchLang(l: Lang): void {
    setLang(l);
    store(LANG_KEY, l);
    this.renderAll();
  }

  renderAll(): void {
    document.documentElement.lang = getLang() === 'zh' ? 'zh-CN' : 'en';
    document.title = `pu-lab — ${t('subtitle')}`;
    const lang = langSwitch((l) => this.switchLang(l));
    this.layout.build(this.embed
      ? h('div', { class: 'embed-bar' }, h('span', { class: 'status' }), lang,
          h('a', { href: `./${location.hash}`, target: '_blank', rel: 'noopener' }, t('embedOpen')))
      : renderHeader(this.root, this.session, lang));
    if (!this.embed) this.form.render();
    this.renderPanels();
    this.status.render();
    this.showErrors();
  }
}
