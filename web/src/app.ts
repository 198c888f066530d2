// The page: header, input form, panels; state in URL + localStorage; all numbers from the worker.
import 'katex/dist/katex.min.css';
import './style.css';
import { h } from './dom';
import { fmtInput, fmtNum, parseNumber } from './format';
import { ALL_FIELDS, SECTIONS, effectiveInput, type FieldSpec } from './fields';
import { defaultLang, errText, getLang, setLang, t, type Key, type Lang } from './i18n';
import { PulabClient, Superseded } from './rpc';
import type { ApiErr } from './protocol';
import type { Report } from './report-types';
import {
  PRESETS, STORAGE_KEY, clone, encodeHash, getPath, initialInput, reportInput, setPath, simInput, type Input,
} from './state';
import { fromSI, toSI, type UnitId } from './units';
import type { Panel, PanelContext, PanelId } from './panels/panel';
import { basesPanel } from './panels/bases';
import { puPanel } from './panels/pu';
import { vendorPanel } from './panels/vendor';
import { constantsPanel } from './panels/constants';
import { currentPanel } from './panels/current';
import { pllPanel } from './panels/pll';
import { qcalcPanel } from './panels/qcalc';
import { conventionsPanel } from './panels/conventions';
import { docTarget, docsAvailable, docsPanel, openChapter, setPanelRegistry } from './panels/docs';

export const PANELS: Panel[] = [basesPanel, puPanel, vendorPanel, constantsPanel, currentPanel, pllPanel, qcalcPanel, conventionsPanel, docsPanel];
setPanelRegistry(PANELS);

const LANG_KEY = 'pulab.lang';
const UNITS_KEY = 'pulab.units.v1';

function store(k: string, v: string): void {
  try {
    localStorage.setItem(k, v);
  } catch {
    /* private mode */
  }
}
function load(k: string): string | null {
  try {
    return localStorage.getItem(k);
  } catch {
    return null;
  }
}

export class App {
  input: Input;
  report: Report | null = null;
  simReport: Report | null = null;
  simError: string | null = null;
  localErrors = new Map<string, string>();
  remoteError: ApiErr | null = null;
  units: Record<string, UnitId> = {};
  client: PulabClient | null = null;
  /** A second worker for simulations (started after the first report), so a running
   * simulation never delays the numbers. */
  simClient: PulabClient | null = null;
  simWorkerFactory: (() => PulabClient) | null = null;
  embed: PanelId | null;
  lastMs = 0;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private simTimer: ReturnType<typeof setTimeout> | undefined;
  private panelEls = new Map<PanelId, HTMLElement>();
  private root: HTMLElement;
  bootState: { stage: Key; fraction: number; failed?: string } = { stage: 'boot_runtime', fraction: 0 };

  constructor(root: HTMLElement) {
    this.root = root;
    const params = new URLSearchParams(location.search);
    const e = params.get('embed');
    this.embed = PANELS.some((p) => p.id === e) ? (e as PanelId) : null;
    const chapter = params.get('chapter');
    if (chapter) openChapter(chapter, params.get('anchor') ?? '');
    const langParam = params.get('lang');
    setLang(langParam === 'zh' || langParam === 'en' ? langParam : defaultLang(navigator.languages, load(LANG_KEY)));
    this.input = initialInput(location.hash, this.embed ? null : load(STORAGE_KEY)).input;
    try {
      this.units = JSON.parse(load(UNITS_KEY) ?? '{}') as Record<string, UnitId>;
    } catch {
      this.units = {};
    }
    window.addEventListener('hashchange', () => {
      const next = initialInput(location.hash, null);
      if (next.source === 'url' && JSON.stringify(effectiveInput(next.input)) !== JSON.stringify(effectiveInput(this.input))) {
        this.input = next.input;
        this.localErrors.clear();
        this.renderForm();
        this.schedule(0);
      }
    });
  }

  /** In-page links must not touch location.hash (it holds the state): handled here. */
  private onClick(ev: MouseEvent): void {
    const a = (ev.target as HTMLElement).closest<HTMLElement>('[data-why], [data-panel-link], [data-doc-link], nav.tabs a');
    if (!a) return;
    ev.preventDefault();
    const go = (id: string) => document.getElementById(id)?.scrollIntoView({ block: 'start' });
    if (a.dataset.why) {
      const target = docTarget(a.dataset.why);
      if (!target) return;
      openChapter(target.chapter, target.anchor);
      if (this.embed) {
        window.open(`./?embed=docs&chapter=${target.chapter}&anchor=${target.anchor}${location.hash}`, '_blank', 'noopener');
        return;
      }
      this.renderPanels(['docs']);
      go('panel-docs');
    } else if (a.dataset.panelLink) {
      if (this.embed) {
        window.open(`./${location.hash}`, '_blank', 'noopener');
        return;
      }
      go(a.dataset.panelLink === 'inputs' ? 'app' : `panel-${a.dataset.panelLink}`);
      if (a.dataset.panelLink === 'inputs') (this.root.querySelector('.inputs input') as HTMLElement | null)?.focus();
    } else if (a.dataset.docLink) {
      const el = this.root.querySelector(`[data-anchor="${CSS.escape(a.dataset.docLink)}"]`);
      if (el) el.scrollIntoView({ block: 'start' });
    } else if (a.dataset.nav) {
      go(`panel-${a.dataset.nav}`);
    }
  }

  /** Attach to a client that may already be booting (main.ts starts the worker first). */
  start(client: PulabClient): void {
    this.root.addEventListener('click', (ev) => this.onClick(ev));
    this.client = client;
    const onReady = (ms: number): void => {
      document.documentElement.dataset.bootMs = String(Math.round(ms));
      this.renderPanels();
      this.schedule(0);
    };
    client.events = {
      onProgress: (stage, fraction) => {
        this.bootState = { stage: `boot_${stage}` as Key, fraction };
        this.renderStatus();
      },
      onReady,
      onFatal: (message) => {
        this.bootState = { ...this.bootState, failed: message };
        this.renderStatus();
      },
    };
    this.bootState = { stage: `boot_${client.progress.stage}` as Key, fraction: client.progress.fraction, failed: client.fatalMessage ?? undefined };
    this.renderAll();
    if (client.ready) onReady(client.bootMs);
  }

  // ---- computing -------------------------------------------------------------------------

  schedule(delay = 10): void {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => void this.compute(), delay);
  }

  private async compute(): Promise<void> {
    if (this.localErrors.size) return this.markStale();
    const eff = effectiveInput(this.input);
    this.persist(eff);
    if (!this.client?.ready) return;
    document.documentElement.dataset.busy = '1';
    try {
      const t0 = performance.now();
      const { result, ms } = await this.client.call('report', reportInput(eff), 'report');
      this.lastMs = ms;
      if (result.ok) {
        this.report = result.report as unknown as Report;
        this.remoteError = null;
        const t1 = performance.now();
        this.renderPanels();
        this.showFieldErrors();
        const t2 = performance.now();
        document.documentElement.dataset.reportMs = (t1 - t0).toFixed(1);
        document.documentElement.dataset.renderMs = (t2 - t1).toFixed(1);
        if (this.inputAt) document.documentElement.dataset.updateMs = (t2 - this.inputAt).toFixed(1);
        clearTimeout(this.simTimer);
        // Simulations wait for a pause in typing (they are heavier and only feed the plots).
        this.simTimer = setTimeout(() => void this.computeSim(eff), 400);
      } else {
        this.remoteError = result;
        this.showFieldErrors();
        this.markStale();
      }
    } catch (e) {
      if (!(e instanceof Superseded)) throw e;
    } finally {
      delete document.documentElement.dataset.busy;
      this.renderStatus();
    }
  }

  private simWorker(): PulabClient | null {
    if (!this.simClient && this.simWorkerFactory) this.simClient = this.simWorkerFactory();
    return this.simClient ?? this.client;
  }

  private async computeSim(eff: Input): Promise<void> {
    const sc = this.simWorker();
    if (!sc || !eff.sim) return;
    try {
      const { result } = await sc.call('report', simInput(eff), 'sim');
      if (result.ok) {
        this.simReport = result.report as unknown as Report;
        this.simError = this.simReport.sim ? null : 'no "sim" section in the report';
      } else {
        this.simError = `${result.field}: ${errText(result)}`;
        if (result.field.startsWith('sim')) this.showFieldErrors(result);
      }
      this.renderPanels(['current', 'pll', 'docs']);
    } catch (e) {
      if (!(e instanceof Superseded)) throw e;
    }
  }

  private persist(eff: Input): void {
    if (this.embed) return;
    const hash = encodeHash(eff);
    if (location.hash !== hash) history.replaceState(null, '', hash);
    store(STORAGE_KEY, JSON.stringify(eff));
  }

  private markStale(): void {
    this.root.querySelector('.panels')?.classList.add('stale');
    const banner = this.root.querySelector('.stale-banner');
    if (banner) {
      const f = this.localErrors.size ? [...this.localErrors.keys()][0] : this.remoteError?.field ?? '';
      const msg = this.localErrors.size ? this.localErrors.get(f) : this.remoteError && errText(this.remoteError);
      banner.textContent = `${t('staleField')}${f ? `${f}: ` : ''}${msg ?? ''}`;
    }
  }

  private showFieldErrors(simErr?: ApiErr): void {
    const stale = this.localErrors.size > 0 || this.remoteError !== null;
    this.root.querySelector('.panels')?.classList.toggle('stale', stale);
    for (const el of this.root.querySelectorAll<HTMLElement>('.inputs [data-err-for]')) {
      const f = el.dataset.errFor ?? '';
      let msg = this.localErrors.get(f) ?? '';
      if (!msg && this.remoteError?.field === f) msg = errText(this.remoteError);
      if (!msg && simErr?.field === f) msg = errText(simErr);
      el.textContent = msg;
      el.closest('.field')?.classList.toggle('invalid', msg !== '');
    }
    // An error naming a field with no element of its own (a section, the whole input) goes to
    // the nearest section or the banner.
    const re = this.remoteError;
    const global = this.root.querySelector('.global-error') as HTMLElement | null;
    if (global) {
      const hasField = re && this.root.querySelector(`.inputs [data-err-for="${CSS.escape(re.field)}"]`);
      global.textContent = re && !hasField ? `${re.field}: ${errText(re)}` : '';
    }
    if (stale) this.markStale();
  }

  // ---- form ------------------------------------------------------------------------------

  private unitOf(f: FieldSpec): UnitId | undefined {
    if (!f.units) return undefined;
    const u = this.units[f.path];
    return u && f.units.includes(u) ? u : f.units[0];
  }

  private fieldEl(f: FieldSpec): HTMLElement {
    const v = getPath(this.input, f.path);
    const enabled = f.enabled ? f.enabled(this.input) : true;
    const label = h('span', { class: 'lbl' }, t(`f.${f.path}` as Key));
    let control: HTMLElement;
    if (f.kind === 'select') {
      control = h('select', { name: f.path, disabled: !enabled, onchange: (ev: Event) => this.onSelect(f, (ev.target as HTMLSelectElement).value) },
        (f.options ?? []).map((o) => h('option', { value: o, selected: String(v ?? f.options?.[0]) === o }, t(`o.${o}` as Key))));
    } else if (f.kind === 'bool') {
      control = h('input', { type: 'checkbox', name: f.path, checked: v === true, onchange: (ev: Event) => this.onBool(f, (ev.target as HTMLInputElement).checked) });
    } else {
      const unit = this.unitOf(f);
      const shown = typeof v === 'number' ? (unit ? fromSI(v, unit) : v) : null;
      control = h('input', {
        name: f.path, type: 'text', inputmode: 'decimal', autocomplete: 'off', spellcheck: 'false',
        value: fmtInput(shown), disabled: !enabled, 'data-unit': unit ?? f.unit ?? '',
        oninput: (ev: Event) => this.onNumber(f, (ev.target as HTMLInputElement).value),
      });
    }
    const unitEl = f.units
      ? h('select', { class: 'unit', 'data-unit-for': f.path, 'aria-label': t('unit'), disabled: !enabled, onchange: (ev: Event) => this.onUnit(f, (ev.target as HTMLSelectElement).value as UnitId) },
          f.units.map((u) => h('option', { value: u, selected: this.unitOf(f) === u }, u === 'kHz' ? 'kHz (f_s)' : u)))
      : f.unit ? h('span', { class: 'unit' }, f.unit) : null;
    return h('label', { class: `field kind-${f.kind}${enabled ? '' : ' disabled'}` },
      label, h('span', { class: 'ctl' }, control, unitEl), h('span', { class: 'err', 'data-err-for': f.path }));
  }

  renderForm(): void {
    const host = this.root.querySelector('.inputs');
    if (!host) return;
    const open = new Set([...host.querySelectorAll<HTMLDetailsElement>('details[open]')].map((d) => d.dataset.section));
    const first = !host.childElementCount;
    host.replaceChildren(
      h('div', { class: 'inputs-head' }, h('h2', {}, t('inputs')),
        h('label', { class: 'preset' }, h('span', {}, t('preset')),
          h('select', { name: 'preset', onchange: (ev: Event) => this.onPreset((ev.target as HTMLSelectElement).value) },
            h('option', { value: '' }, t('presetCustom')),
            PRESETS.map((p) => h('option', { value: p.id, selected: this.matchesPreset(p.input) }, p.label[getLang()]))))),
      ...SECTIONS.map((s) => h('details', { class: 'section', 'data-section': s.id, open: first ? !s.collapsed : open.has(s.id) },
        h('summary', {}, t(s.title), h('span', { class: 'err', 'data-err-for': s.id })),
        s.hint ? h('p', { class: 'hint' }, t(s.hint)) : null,
        h('div', { class: 'fields' }, s.fields.map((f) => this.fieldEl(f))))),
    );
    this.updatePlaceholders();
    this.showFieldErrors();
  }

  private matchesPreset(p: Input): boolean {
    return JSON.stringify(effectiveInput(p)) === JSON.stringify(effectiveInput(this.input));
  }

  private updatePlaceholders(): void {
    for (const f of ALL_FIELDS) {
      const el = this.root.querySelector<HTMLInputElement>(`.inputs input[name="${f.path}"]`);
      if (!el || f.kind === 'bool') continue;
      let ph = '';
      if (f.placeholderFrom && this.report) {
        const v = getPath(this.report, f.placeholderFrom);
        if (typeof v === 'number') {
          const u = this.unitOf(f);
          ph = `= ${fmtNum(u ? fromSI(v, u) : v, 8)}`;
          el.title = `${t('derived')}: ${fmtNum(u ? fromSI(v, u) : v, 12)}`;
        }
      } else if (f.optional && this.report) {
        const v = getPath(this.report.input, f.path);
        if (typeof v === 'number') ph = `= ${fmtNum(v, 8)}`;
      }
      el.placeholder = ph;
    }
  }

  /** Time of the last input event (for the input → numbers latency in dataset.updateMs). */
  private inputAt = 0;

  private onNumber(f: FieldSpec, text: string): void {
    this.inputAt = performance.now();
    const r = parseNumber(text, f.kind === 'int');
    if (!r.ok) {
      this.localErrors.set(f.path, t(r.error === 'integer' ? 'errInteger' : 'errNumber'));
      this.showFieldErrors();
      return;
    }
    const unit = this.unitOf(f);
    const si = r.value === null ? null : unit ? toSI(r.value, unit) : r.value;
    if (si !== null && !Number.isFinite(si)) {
      // f_s = 0 kHz has no period: JSON would turn Infinity into null ("is required").
      this.localErrors.set(f.path, t('errPositive'));
      this.showFieldErrors();
      return;
    }
    this.localErrors.delete(f.path);
    setPath(this.input as Record<string, unknown>, f.path, si);
    this.remoteError = null;
    this.showFieldErrors();
    this.syncPresetSelect();
    this.schedule();
  }

  private onSelect(f: FieldSpec, value: string): void {
    setPath(this.input as Record<string, unknown>, f.path, value);
    if (f.path === 'current_loop.method' && value === 'manual' && this.report) {
      // Start manual tuning from the current design.
      const cl = this.input.current_loop ?? (this.input.current_loop = {});
      cl.kp ??= this.report.current_pi.d.kp;
      cl.ki ??= this.report.current_pi.d.ki;
    }
    if (f.path === 'current_loop.method' && value === 'integers' && this.report) {
      const cl = this.input.current_loop ?? (this.input.current_loop = {});
      cl.pm_kp ??= this.report.current_pi.d.pm_kp;
      cl.pm_ki ??= this.report.current_pi.d.pm_ki;
    }
    if (f.path === 'conventions.base' && value === 'custom' && this.report) {
      const c = this.input.conventions ?? (this.input.conventions = {});
      c.base_voltage_v ??= this.report.base.U_b;
      c.base_current_a ??= this.report.base.I_b;
    }
    this.remoteError = null;
    this.renderForm();
    this.schedule();
  }

  private onBool(f: FieldSpec, v: boolean): void {
    setPath(this.input as Record<string, unknown>, f.path, v);
    this.schedule();
  }

  private onUnit(f: FieldSpec, u: UnitId): void {
    this.units[f.path] = u;
    store(UNITS_KEY, JSON.stringify(this.units));
    this.renderForm();
  }

  private onPreset(id: string): void {
    const p = PRESETS.find((x) => x.id === id);
    if (!p) return;
    this.input = clone(p.input);
    this.localErrors.clear();
    this.remoteError = null;
    this.renderForm();
    this.schedule(0);
  }

  private syncPresetSelect(): void {
    const sel = this.root.querySelector<HTMLSelectElement>('select[name="preset"]');
    if (sel) sel.value = PRESETS.find((p) => this.matchesPreset(p.input))?.id ?? '';
  }

  // ---- header, panels, exports ----------------------------------------------------------

  private ctx(): PanelContext {
    return { report: this.report, simReport: this.simReport, simError: this.simError, input: this.input, client: this.client?.ready ? this.client : null, embed: this.embed !== null };
  }

  renderPanels(only?: PanelId[]): void {
    const ctx = this.ctx();
    for (const p of PANELS) {
      if (only && !only.includes(p.id)) continue;
      const el = this.panelEls.get(p.id);
      if (el) p.render(el, ctx);
    }
    const w = this.root.querySelector('.warnings');
    if (w && (!only || only.length === 0)) {
      const list = (getLang() === 'zh' ? this.report?.warnings_zh : this.report?.warnings) ?? [];
      w.replaceChildren(...(list.length ? [h('strong', {}, `${t('warnings')}: `), h('ul', {}, list.map((x) => h('li', {}, x)))] : []));
    }
    if (!only) this.updatePlaceholders();
  }

  renderStatus(): void {
    const el = this.root.querySelector('.status');
    if (!el) return;
    const b = this.bootState;
    document.documentElement.dataset.ready = this.client?.ready ? '1' : '0';
    if (b.failed) {
      el.replaceChildren(h('span', { class: 'status-fatal', role: 'alert' }, `${t('bootFailed')}: ${b.failed}. ${t('fatalHelp')}`));
    } else if (!this.client?.ready) {
      el.replaceChildren(h('span', {}, t(b.stage)), h('progress', { max: 1, value: b.fraction }));
    } else {
      el.replaceChildren(h('span', { class: 'ok' }, `● ${t('boot_ready')}`), h('span', { class: 'lat' }, this.lastMs ? ` · ${t('latency', { ms: this.lastMs.toFixed(1) })}` : ''));
    }
  }

  private switchLang(l: Lang): void {
    setLang(l);
    store(LANG_KEY, l);
    this.renderAll();
  }

  private download(name: string, text: string, type: string): void {
    const url = URL.createObjectURL(new Blob([text], { type }));
    const a = h('a', { href: url, download: name }) as HTMLAnchorElement;
    document.body.append(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 5000);
  }

  private async exportPy(kind: 'header' | 'csv_current' | 'csv_pll'): Promise<void> {
    if (!this.client?.ready) return;
    const eff = effectiveInput(this.input);
    const c = kind === 'header' ? this.client : this.simWorker() ?? this.client;
    const { result } = await c.call('export', { input: kind === 'header' ? reportInput(eff) : simInput(eff), kind });
    if (result.ok) {
      const name = kind === 'header' ? 'pulab_params.h' : `pulab_${kind.slice(4)}.csv`;
      this.download(name, String(result.text), kind === 'header' ? 'text/x-c' : 'text/csv');
    } else this.toast(`${result.field}: ${errText(result)}`);
  }

  private toast(msg: string, extra?: HTMLElement): void {
    const el = this.root.querySelector('.toast');
    if (!el) return;
    el.replaceChildren(h('span', {}, msg), extra ?? '');
    el.classList.add('show');
    setTimeout(() => el.classList.remove('show'), extra ? 12000 : 2500);
  }

  private async copyLink(): Promise<void> {
    const url = location.href.split('#')[0] + encodeHash(effectiveInput(this.input));
    try {
      await navigator.clipboard.writeText(url);
      this.toast(t('linkCopied'));
    } catch {
      const box = h('input', { class: 'linkbox', value: url, readonly: true }) as HTMLInputElement;
      this.toast(t('linkCopyFailed'), box);
      box.select();
    }
    document.documentElement.dataset.shareLink = url;
  }

  renderAll(): void {
    document.documentElement.lang = getLang() === 'zh' ? 'zh-CN' : 'en';
    document.title = `pu-lab — ${t('subtitle')}`;
    this.panelEls.clear();
    const panels = (this.embed ? PANELS.filter((p) => p.id === this.embed) : PANELS).filter((p) => p.id !== 'docs' || docsAvailable());
    const pair = (a: PanelId, b: PanelId) => !this.embed && panels.some((p) => p.id === a) && panels.some((p) => p.id === b);
    const sections = panels.map((p) => {
      const body = h('div', { class: 'panel-body' });
      this.panelEls.set(p.id, body);
      return h('section', { class: `panel panel-${p.id}`, id: `panel-${p.id}`, 'data-panel': p.id },
        h('h2', {}, t(p.title as Key), p.id !== 'docs' && docTarget(p.id) ? h('a', { class: 'why', href: `#panel-docs`, 'data-why': p.id }, t('why')) : null), body);
    });
    const lang = h('div', { class: 'lang', role: 'group' },
      (['zh', 'en'] as Lang[]).map((l) => h('button', { type: 'button', 'data-lang': l, class: getLang() === l ? 'on' : '', onclick: () => this.switchLang(l) }, l === 'zh' ? '中文' : 'English')));
    if (this.embed) {
      document.body.classList.add('embed');
      this.root.replaceChildren(
        h('div', { class: 'embed-bar' }, h('span', { class: 'status' }), lang,
          h('a', { href: `./${location.hash}`, target: '_blank', rel: 'noopener' }, t('embedOpen'))),
        h('div', { class: 'inputs', hidden: true }),
        h('main', { class: 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), ...sections),
        h('div', { class: 'toast' }),
      );
    } else {
      this.root.replaceChildren(
        h('header', { class: 'top' },
          h('div', { class: 'brand' }, h('strong', {}, 'pu-lab'), h('span', { class: 'sub' }, t('subtitle'))),
          h('div', { class: 'status' }),
          h('div', { class: 'actions' },
            h('button', { type: 'button', class: 'copy-link', onclick: () => void this.copyLink() }, t('copyLink')),
            h('details', { class: 'export' }, h('summary', {}, t('export')),
              h('div', { class: 'menu' },
                h('button', { type: 'button', 'data-export': 'json', onclick: () => this.report && this.download('pulab_report.json', JSON.stringify(this.report, null, 2), 'application/json') }, t('exportJson')),
                h('button', { type: 'button', 'data-export': 'header', onclick: () => void this.exportPy('header') }, t('exportHeader')),
                h('button', { type: 'button', 'data-export': 'csv_current', onclick: () => void this.exportPy('csv_current') }, t('exportCsvCurrent')),
                h('button', { type: 'button', 'data-export': 'csv_pll', onclick: () => void this.exportPy('csv_pll') }, t('exportCsvPll')))),
            lang)),
        h('div', { class: 'layout' },
          h('aside', { class: 'inputs' }),
          h('div', { class: 'content' },
            h('nav', { class: 'tabs' }, panels.map((p) => h('a', { href: `#panel-${p.id}`, 'data-nav': p.id }, t(`nav_${p.id}` as Key)))),
            h('main', { class: 'panels' }, h('div', { class: 'stale-banner' }), h('div', { class: 'global-error' }), h('div', { class: 'warnings' }),
              ...(pair('bases', 'pu') ? [h('div', { class: 'pair' }, sections[0], sections[1]), ...sections.slice(2)] : sections)))),
        h('div', { class: 'toast' }),
      );
      this.renderForm();
    }
    this.renderPanels();
    this.renderStatus();
    this.showFieldErrors();
  }
}
