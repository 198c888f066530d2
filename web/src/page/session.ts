// The compute session: the input in the form, the reports computed from it, and the scheduling
// of report and simulation calls to the Python workers. It knows nothing of the DOM: what it
// publishes (<html data-*>, the address bar, stored input and reports) goes through the
// SessionEnv it is given (page/env.ts for the page; plain objects in tests/web/session.test.ts).
import { effectiveInput } from '../fields';
import { errText, t } from '../i18n';
import { Superseded, type PulabClient } from '../rpc';
import type { ApiErr } from '../protocol';
import type { Report } from '../generated/report-types';
import { decodeUnits, encodeHash, initialInput, reportKey, withSim, simInput, type Input } from '../state';
import type { NumbersSource } from './numbers';

/** What the session needs from the page around it. */
export interface SessionEnv {
  /** <html data-*>: the timings (reportMs, workerMs, renderMs, updateMs) and counters
   * (busy, simPosted, simDone, simSuperseded) that the benchmark and tests read. */
  attrs: Record<string, string | undefined>;
  /** Publish where the numbers on screen come from (<html data-numbers>). */
  showSource(source: NumbersSource): void;
  /** Record the first time of a boot step (<html data-t-…>). */
  mark(step: string): void;
  /** A report known without Python (prerendered or cached) for a report key, and keeping one. */
  known(key: string): { report: Report; source: 'build' | 'cached' } | null;
  keep(key: string, report: Report): void;
  /** The address bar's fragment, and replacing it without a history entry. */
  hash(): string;
  replaceHash(hash: string): void;
  /** Keep the input for the next visit. */
  storeInput(json: string): void;
  /** Call `retry` when the network comes back. */
  onOnline(retry: () => void): void;
}

/** What the page does when the session's state changes. */
export interface SessionEvents {
  /** A new report for the input in the form (render every panel); `same`: equal to the one shown
   * (the same input: pulab is deterministic), only what depends on Python being ready changes. */
  report(same?: boolean): void;
  /** A new simulation result or simulation error (render the plots). */
  sim(): void;
  /** Field errors or staleness changed. */
  errors(): void;
  /** A call started or finished (status line). */
  busy(): void;
}

/** A report takes milliseconds: a ready runtime silent this long is lost and gets replaced. */
const REPORT_LOST_MS = 15_000;
/** The worst allowed simulation takes ≈ 10 s in CPython; Pyodide is a few times slower. */
const SIM_LOST_MS = 120_000;

/** Simulations wait for a pause in typing: they are heavier and only feed the plots. */
const SIM_PAUSE_MS = 400;

export class ComputeSession {
  input: Input;
  /** Display unit chosen per field path (the form's; kept in links and localStorage). */
  units: Record<string, string> = {};
  report: Report | null = null;
  simReport: Report | null = null;
  simError: string | null = null;
  /** The simulation worker failed (not the input): a retry may help. */
  simWorkerFailed = false;
  /** The field a failed simulation named (shown at that field until the next simulation). */
  simFieldError: ApiErr | null = null;
  /** An input error found by a panel's own request (field weakening's section), by panel. */
  panelFieldErrors = new Map<string, ApiErr>();
  /** Errors found in the page before Python sees the input (not a number, …), by field path. */
  localErrors = new Map<string, string>();
  /** The error Python returned for the input in the form. */
  remoteError: ApiErr | null = null;
  /** Notes at fields whose linked or stored value could not be used (web/src/state-notice.ts). */
  stateNotes = new Map<string, string>();
  /** The opened link was broken: it stays in the address bar until the user changes an input. */
  keepLink = false;
  /** Where `report` comes from, and the input it is for (its reportKey). */
  source: NumbersSource = 'none';
  private reportFor: string | null = null;
  /** Time in Python of the last report, ms. */
  lastMs = 0;
  client: PulabClient | null = null;
  /** Simulations run in a second worker (started after the first report), so a running
   * simulation never delays the numbers. */
  simClient: PulabClient | null = null;
  simWorkerFactory: ((generation: number) => PulabClient) | null = null;
  /** Bumped when the simulation runtime died: the next one gets a new name (runtime.ts). */
  private simGeneration = 0;
  /** Time of the last input event (for the input → numbers latency in dataset.updateMs). */
  private inputAt = 0;
  private timer: ReturnType<typeof setTimeout> | undefined;
  /** The report key of the call in flight on the report channel, if any. */
  private asking: string | null = null;
  /** The last hash this page wrote into the address bar. */
  private wroteHash: string | null = null;
  private simTimer: ReturnType<typeof setTimeout> | undefined;

  constructor(input: Input, private embed: boolean, private events: SessionEvents, private env: SessionEnv) {
    this.input = input;
    this.paintKnown(reportKey(input));
    // A simulation that failed for want of a network is tried again when it returns.
    env.onOnline(() => {
      if (this.simWorkerFailed) this.retrySim();
    });
  }

  /** Run the simulation again, in a new worker if the old one died. */
  retrySim(): void {
    if (this.simClient?.fatalMessage) {
      this.simClient = null;
      this.simGeneration++;
    }
    this.simWorkerFailed = false;
    this.simError = null;
    this.events.sim();
    void this.computeSim(effectiveInput(this.input));
  }

  /** Publish <html data-numbers> (once the page has rendered what the session holds). */
  publish(): void {
    this.updateSource();
  }

  /** Numbers without Python: the build's seed report or a cached one, if one is for `key`. */
  private paintKnown(key: string): boolean {
    const known = this.env.known(key);
    if (!known) return false;
    this.report = known.report;
    this.reportFor = key;
    this.source = known.source;
    return true;
  }

  /** <html data-numbers>: the source while the numbers are of the input in the form, else stale. */
  private updateSource(): void {
    const current = !this.localErrors.size && this.reportFor === reportKey(this.input);
    const source = this.report === null ? 'none' : current ? this.source : 'stale';
    this.env.showSource(source);
    if (source !== 'none' && source !== 'stale') this.env.mark('numbers');
    if (source === 'live') this.env.mark('live');
  }

  get ready(): boolean {
    return this.client?.ready === true;
  }

  /** The form was edited at `path` (starts the input → numbers clock; the user's own state may
   * now replace a broken link, and the note on that field no longer applies). */
  touched(path: string): void {
    this.inputAt = performance.now();
    this.keepLink = false;
    if (this.stateNotes.delete(path)) this.events.errors();
  }

  /** Replace the whole input (preset, link): earlier errors no longer apply. */
  replaceInput(input: Input): void {
    // Without a "sim" section nothing is simulated and the plots keep the previous motor's.
    this.input = withSim(input);
    this.keepLink = false;
    this.stateNotes.clear();
    this.localErrors.clear();
    this.remoteError = null;
    this.schedule(0);
  }

  setLocalError(path: string, message: string | null): void {
    if (message === null) this.localErrors.delete(path);
    else this.localErrors.set(path, message);
    // A field that does not parse leaves the numbers of an earlier input on screen: stale.
    this.updateSource();
    this.events.errors();
  }

  /** A panel's own request failed on an input (or passed again): shown at that field. */
  setPanelFieldError(panel: string, err: ApiErr | null): void {
    const was = this.panelFieldErrors.get(panel) ?? null;
    if (was === err || (was && err && was.field === err.field && was.code === err.code && was.message === err.message)) return;
    if (err) this.panelFieldErrors.set(panel, err);
    else this.panelFieldErrors.delete(panel);
    this.events.errors();
  }

  /** Show the current errors again (after the form was rebuilt). */
  errorsChanged(): void {
    this.events.errors();
  }

  /** The input changed and Python's last verdict on it no longer holds. */
  clearRemoteError(): void {
    this.remoteError = null;
  }

  /** The panels are shown stale: an error, or (before Python is ready) numbers of another input. */
  get stale(): boolean {
    const behind = !this.ready && this.report !== null && this.reportFor !== reportKey(this.input);
    return this.localErrors.size > 0 || this.remoteError !== null || behind;
  }

  /** The numbers on the page are from another input than the form's (a computation is due). */
  get outdated(): boolean {
    return this.report !== null && this.reportFor !== reportKey(this.input);
  }

  /** Compute the input in the form: at once (a report takes milliseconds and a newer call
   * supersedes an older one, so keystrokes need no debounce), or after `delay` ms. */
  schedule(delay = 0): void {
    this.updateSource();
    clearTimeout(this.timer);
    if (delay <= 0) void this.compute();
    else this.timer = setTimeout(() => void this.compute(), delay);
  }

  private async compute(): Promise<void> {
    if (this.localErrors.size) return this.events.errors();
    const eff = effectiveInput(this.input);
    const key = reportKey(this.input);
    if (!this.client?.ready) {
      this.persist(eff);
      // Typing before Python is ready: painted at once if known, and asked for now: the worker
      // keeps the newest call and computes it the moment Python is ready (the page's own "ready"
      // message and its answer are not waited for).
      if (key !== this.reportFor && this.paintKnown(key)) this.events.report();
      this.updateSource();
      this.events.busy();
      this.events.errors();
      if (!this.client || this.client.fatalMessage) return;
    }
    // The same input already asked (before Python was ready): its answer is on its way.
    if (this.asking === key) return;
    const root = this.env.attrs;
    root.busy = '1';
    // The address bar and localStorage are written after the numbers are shown (history.replaceState
    // takes milliseconds); a call superseded by a newer input leaves them to that one.
    let superseded = false;
    try {
      const t0 = performance.now();
      this.asking = key;
      const { result, ms } = await this.client.call('report', JSON.parse(key), 'report', REPORT_LOST_MS);
      this.lastMs = ms;
      if (result.ok) {
        const same = this.reportFor === key && this.source !== 'live';
        this.report = result.report;
        this.remoteError = null;
        // Another input may have been typed while Python computed this one.
        this.reportFor = key;
        this.source = 'live';
        this.env.keep(key, this.report);
        const t1 = performance.now();
        this.events.report(same);
        this.events.errors();
        this.updateSource();
        const t2 = performance.now();
        root.reportMs = (t1 - t0).toFixed(1);
        root.workerMs = ms.toFixed(1);
        root.renderMs = (t2 - t1).toFixed(1);
        if (this.inputAt) root.updateMs = (t2 - this.inputAt).toFixed(1);
        clearTimeout(this.simTimer);
        this.simTimer = setTimeout(() => void this.computeSim(eff), SIM_PAUSE_MS);
      } else {
        this.remoteError = result;
        this.updateSource();
        this.events.errors();
      }
    } catch (e) {
      // Superseded: a newer input is on its way. Anything else is the worker failing, which the
      // status line reports (PulabClient onFatal); never an unhandled rejection.
      superseded = e instanceof Superseded;
      if (!superseded) console.warn('report call failed:', e);
    } finally {
      this.answered();
      if (this.asking === key) this.asking = null;
      if (!superseded) this.persist(eff);
      delete root.busy;
      this.events.busy();
    }
  }

  private firstAnswer: (() => void)[] | null = [];
  /** Run `f` once, when the first report call has been answered (soon if it has been), or
   * after `latestMs` if none is (an input the page itself refuses asks nothing). */
  afterFirstAnswer(f: () => void, latestMs = 3000): void {
    let done = false;
    const once = (): void => {
      if (!done) f();
      done = true;
    };
    setTimeout(once, latestMs);
    if (this.firstAnswer) this.firstAnswer.push(once);
    else setTimeout(once, 0);
  }
  private answered(): void {
    const waiting = this.firstAnswer;
    if (!waiting) return;
    this.firstAnswer = null;
    // After the answer's rendering (this task), in a task of its own.
    setTimeout(() => waiting.forEach((f) => f()), 0);
  }

  /** Whether simulations are computed (a shown panel draws them). */
  wantsSim = true;
  /** Resolves when a panel that draws simulations comes near the viewport: the simulation
   * runtime (a second Python) is not started for a page nobody scrolls to the plots of. */
  simGate: Promise<void> = Promise.resolve();
  private simLatest: Input | null = null;

  /** The worker for simulations and CSV exports (started on first use). */
  simWorker(): PulabClient | null {
    if (!this.simClient && this.simWorkerFactory) this.simClient = this.simWorkerFactory(this.simGeneration);
    return this.simClient ?? this.client;
  }

  private async computeSim(eff: Input): Promise<void> {
    if (!this.wantsSim || !eff.sim) return;
    // Only the newest input is simulated once the gate opens.
    const waiting = this.simLatest !== null;
    this.simLatest = eff;
    if (waiting) return;
    await this.simGate;
    eff = this.simLatest;
    this.simLatest = null;
    const sc = this.simWorker();
    if (!sc) return;
    // <html data-sim-posted/-done/-superseded>: counters of simulation requests, results and
    // requests cancelled by a newer one (the fault suite measures the cancellation latency).
    const root = this.env.attrs;
    try {
      root.simPosted = String(Number(root.simPosted ?? 0) + 1);
      const { result } = await sc.call('report', simInput(eff), 'sim', SIM_LOST_MS);
      root.simDone = String(Number(root.simDone ?? 0) + 1);
      if (result.ok) {
        this.simReport = result.report;
        this.simError = this.simReport.sim ? null : 'no "sim" section in the report';
        this.simFieldError = null;
        this.simWorkerFailed = false;
      } else {
        this.simError = `${result.field}: ${errText(result)}`;
        this.simFieldError = /^(sim|analysis)\b/.test(result.field) ? result : null;
        if (this.simFieldError) this.events.errors();
      }
      this.events.sim();
    } catch (e) {
      if (e instanceof Superseded) {
        root.simSuperseded = String(Number(root.simSuperseded ?? 0) + 1);
        return;
      }
      // The simulation worker could not start or died: say so at the plots, with a retry.
      this.simReport = null;
      this.simWorkerFailed = true;
      this.simError = t('simWorkerFailed', { m: e instanceof Error ? e.message : String(e) });
      this.events.sim();
    }
  }

  /**
   * The address bar already holds `eff` (and the units), spelled another way (a link written by
   * hand): left as it is. Rewriting it made the browser lay out the whole page at once, on the
   * first live numbers of a share link (≈ 0.2 s).
   */
  private linkSays(eff: Input): boolean {
    const hash = this.env.hash();
    const linked = initialInput(hash, null);
    return linked.source === 'url' && linked.problems.length === 0
      && JSON.stringify(effectiveInput(linked.input)) === JSON.stringify(eff)
      && JSON.stringify(decodeUnits(hash) ?? {}) === JSON.stringify(this.units);
  }

  /** The input goes into the URL (#in=) and localStorage; embeds leave both to their host page. */
  private persist(eff: Input): void {
    if (this.embed) return;
    const hash = encodeHash(eff, this.units);
    // Whether an opened link already says this input is asked only while it is in the address bar
    // (decoding and checking a link took 0.2–11 ms of every keystroke).
    const now = this.env.hash();
    if (now !== hash && !this.keepLink && (now === this.wroteHash || !this.linkSays(eff))) {
      this.env.replaceHash(hash);
      this.wroteHash = hash;
    }
    this.env.storeInput(JSON.stringify(eff));
  }
}
