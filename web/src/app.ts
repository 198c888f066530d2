// The page, put together: reads the URL (embed, chapter, language, #in= state), and wires the
// compute session to the form, the layout of panels, the header and the status line.
import 'katex/dist/katex.min.css';
import './style.css';
import { h, holdFormulas } from './dom';
import { effectiveInput } from './fields';
import { defaultLang, getLang, setLang, t, type Lang } from './i18n';
import type { PulabClient } from './rpc';
import { STORAGE_KEY, initialInput, setPath, type Initial, type Input } from './state';
import { fieldNotes, stateBanner } from './state-notice';
import type { PanelContext, PanelId } from './panels/panel';
import { PANELS, panelById } from './panels/registry';
import { openChapter } from './panels/docs';
import { pageEnv } from './page/env';
import { ComputeSession } from './page/session';
import { InputForm } from './page/form';
import { Layout } from './page/layout';
import { closeInputs } from './page/drawer';
import { StatusLine } from './page/status';
import { langSwitch, renderHeader } from './page/header';
import { handleLinks } from './page/links';
import { LANG_KEY, load, store } from './page/storage';
import { registerOfflineLater } from './offline';
import { mark } from './page/marks';
import { applyTheme, linkToHost, themeParam } from './page/frame-link';
import { codeStateFromSearch } from './code-share';

/** Panels that call Python themselves: rendered again when it becomes ready. */
const PYTHON_PANELS = PANELS.filter((p) => p.needsPython).map((p) => p.id);

export class App {
  readonly embed: PanelId | null;
  readonly session: ComputeSession;
  private form: InputForm;
  private layout: Layout;
  private status: StatusLine;
  /** How the opening state was read: its problems are shown until dismissed or replaced. */
  private init: Initial;

  constructor(private root: HTMLElement) {
    mark('app');
    const params = new URLSearchParams(location.search);
    this.embed = panelById(params.get('embed'))?.id ?? null;
    const chapter = params.get('chapter');
    if (chapter) openChapter(chapter, params.get('anchor') ?? '');
    const theme = themeParam(params);
    if (theme) applyTheme(theme);
    const langParam = params.get('lang');
    setLang(langParam === 'zh' || langParam === 'en' ? langParam : defaultLang(navigator.languages, load(LANG_KEY)));
    this.init = initialInput(location.hash, this.embed ? null : load(STORAGE_KEY));
    this.session = new ComputeSession(this.init.input, this.embed !== null, {
      report: (same) => {
        if (same) this.renderPanels(PYTHON_PANELS);
        else this.renderPanels();
        if (this.session.source === 'live') this.layout.settle(this.ctx());
      },
      // code: its "In the current loop" box shows pulab's verdict on the binding
      sim: () => this.renderPanels(['current', 'pll', 'loop', 'docs', 'review', 'code', 'acim']),
      errors: () => this.showErrors(),
      busy: () => this.status.render(),
    }, pageEnv());
    this.form = new InputForm(root, this.session);
    this.layout = new Layout(root, this.embed);
    // A link with the code panel's state (?code=…) opens on that panel's view.
    if (codeStateFromSearch(location.search)) this.layout.openOn = 'code';
    this.layout.onPickProfile = (v) => {
      // Inovance is the default: left out, so the seed and the presets keep their links.
      const c = this.session.input.conventions ?? {};
      if (v === 'inovance') delete c.firmware;
      else c.firmware = v;
      if (Object.keys(c).length) this.session.input.conventions = c;
      else delete this.session.input.conventions;
      this.session.touched('conventions.firmware');
      this.form.render();
      this.session.schedule();
    };
    this.session.wantsSim = PANELS.some((p) => p.usesSim && (this.embed === null || p.id === this.embed));
    this.session.simGate = this.layout.simPanelNear;
    this.status = new StatusLine(root, this.session);
    this.useInitial(this.init);
    if (this.embed) linkToHost(this.embed, () => this.session.report);
    // The link navigated to, not location.hash: a report answered in the same moment may have
    // written its own input into the address bar before this event runs.
    window.addEventListener('hashchange', (e) => this.followLink(new URL(e.newURL).hash));
  }

  /**
   * A link opened in this tab that differs only in its hash (the browser does not reload): the
   * page becomes what opening it afresh gives — its inputs and display units, their numbers, the
   * opening view from the top, the inputs drawer closed. The page's own writes to the address bar
   * (history.replaceState) fire no hashchange; a hash without state (#panel-…) changes nothing.
   */
  private followLink(hash: string): void {
    const next = initialInput(hash, null);
    if (next.source !== 'url') return;
    // The units first: before Python is ready the session writes the address bar at once.
    this.form.useUnits(hash);
    if (JSON.stringify(effectiveInput(next.input)) !== JSON.stringify(effectiveInput(this.session.input))) this.session.replaceInput(next.input);
    this.init = next;
    this.useInitial(next);
    this.form.render();
    this.showErrors();
    this.showStateBanner();
    this.layout.showOpeningView();
    closeInputs();
    window.scrollTo({ top: 0 });
  }

  /** Problems of the opened state: notes at their fields, and the link kept while it is broken. */
  private useInitial(init: Initial): void {
    this.session.keepLink = init.linkBroken;
    this.session.stateNotes = fieldNotes(init);
  }

  private showStateBanner(): void {
    this.root.querySelector('.state-banner')?.remove();
    const banner = stateBanner(this.init, () => {
      this.init = { ...this.init, problems: [] };
      this.root.querySelector('.state-banner')?.remove();
    });
    if (banner) this.root.querySelector('main.panels')?.prepend(banner);
  }

  /** Attach to a client that may already be booting (main.ts starts the worker first). */
  start(client: PulabClient, restart?: (generation: number) => PulabClient): void {
    // The numbers first: the panels' formulas are typeset once the first answer is on screen.
    holdFormulas();
    this.session.afterFirstAnswer(() => this.layout.showFormulas());
    handleLinks(this.root, this.embed, () => this.renderPanels(['docs']), (id) => this.layout.showView(id));
    this.attach(client, restart, 0);
    this.renderAll();
    // The numbers are asked for now, not when Python says it is ready (the worker keeps the call).
    if (!client.ready) this.session.schedule(0);
    // No warm-up render of the seed's panels while Python boots (a share link has no numbers to
    // show before it): on 2 cores it delayed the boot more than it saved on the first live render
    // (docs/performance.md, "Cold start sequencing").
  }

  /** Follow `client`; when a ready runtime is lost (PulabClient.lost), start the next generation. */
  private attach(client: PulabClient, restart: ((generation: number) => PulabClient) | undefined, generation: number): void {
    this.session.client = client;
    const onReady = (ms: number): void => {
      document.documentElement.dataset.bootMs = String(Math.round(ms));
      // The offline cache (a download of the whole site, 45 MB) a while after Python's first
      // answer, not beside the first report's rendering or the other panels' boots.
      this.session.afterFirstAnswer(() => registerOfflineLater());
      document.documentElement.dataset.pythonBoot = client.bootFrom;
      // The numbers first: the report is posted before the panels that call Python post theirs.
      this.session.schedule(0);
      this.renderPanels(PYTHON_PANELS);
    };
    const onLost = restart
      ? (message: string) => {
        document.documentElement.dataset.runtimeRestarts = String(generation + 1);
        this.attach(restart(generation + 1), restart, generation + 1);
        this.status.lost(message);
      }
      : undefined;
    this.status.follow(client, onReady, onLost);
    if (client.ready) onReady(client.bootMs);
  }

  private ctx(): PanelContext {
    const s = this.session;
    return { report: s.report, simReport: s.simReport, simError: s.simError, retrySim: s.simWorkerFailed ? () => s.retrySim() : undefined, input: s.input, client: s.ready ? s.client : null, embed: this.embed !== null, fieldError: (p, e) => s.setPanelFieldError(p, e),
      setLoop: (code) => {
        const next = JSON.parse(JSON.stringify(s.input)) as Record<string, unknown>;
        setPath(next, 'sim.current.code', code);
        s.replaceInput(next as Input);
      } };
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
    this.session.publish();
    this.status.render();
    this.showErrors();
    this.showStateBanner();
  }
}
