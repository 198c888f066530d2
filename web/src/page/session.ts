// The compute session: the input in the form, the reports computed from it, and the scheduling
// of report and simulation calls to the Python workers. Knows nothing of the DOM except the
// timing attributes on <html> (reportMs, renderMs, updateMs: the benchmark reads them).
import { effectiveInput } from '../fields';
import { errText } from '../i18n';
import { Superseded, type PulabClient } from '../rpc';
import type { ApiErr } from '../protocol';
import type { Report } from '../report-types';
import { STORAGE_KEY, encodeHash, reportInput, simInput, type Input } from '../state';
import { store } from './storage';

/** What the page does when the session's state changes. */
export interface SessionEvents {
  /** A new report for the input in the form (render every panel). */
  report(): void;
  /** A new simulation result or simulation error (render the plots). */
  sim(): void;
  /** Field errors or staleness changed. */
  errors(): void;
  /** A call started or finished (status line). */
  busy(): void;
}

/** Simulations wait for a pause in typing: they are heavier and only feed the plots. */
const SIM_PAUSE_MS = 400;

export class ComputeSession {
  input: Input;
  /** Display unit chosen per field path (the form's; kept in links and localStorage). */
  units: Record<string, string> = {};
  report: Report | null = null;
  simReport: Report | null = null;
  simError: string | null = null;
  /** The field a failed simulation named (shown at that field until the next simulation). */
  simFieldError: ApiErr | null = null;
  /** Errors found in the page before Python sees the input (not a number, …), by field path. */
  localErrors = new Map<string, string>();
  /** The error Python returned for the input in the form. */
  remoteError: ApiErr | null = null;
  /** Time in Python of the last report, ms. */
  lastMs = 0;
  client: PulabClient | null = null;
  /** Simulations run in a second worker (started after the first report), so a running
   * simulation never delays the numbers. */
  simClient: PulabClient | null = null;
  simWorkerFactory: (() => PulabClient) | null = null;
  /** Time of the last input event (for the input → numbers latency in dataset.updateMs). */
  private inputAt = 0;
  private timer: ReturnType<typeof setTimeout> | undefined;
  private simTimer: ReturnType<typeof setTimeout> | undefined;

  constructor(input: Input, private embed: boolean, private events: SessionEvents) {
    this.input = input;
  }

  get ready(): boolean {
    return this.client?.ready === true;
  }

  /** The form was edited (starts the input → numbers clock). */
  touched(): void {
    this.inputAt = performance.now();
  }

  /** Replace the whole input (preset, link): earlier errors no longer apply. */
  replaceInput(input: Input): void {
    this.input = input;
    this.localErrors.clear();
    this.remoteError = null;
    this.schedule(0);
  }

  setLocalError(path: string, message: string | null): void {
    if (message === null) this.localErrors.delete(path);
    else this.localErrors.set(path, message);
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

  get stale(): boolean {
    return this.localErrors.size > 0 || this.remoteError !== null;
  }

  /** The report input the shown numbers were computed from. */
  private reportFor = '';

  /** The numbers on the page are from another input than the form's (a computation is due). */
  get outdated(): boolean {
    return this.report !== null && this.reportFor !== JSON.stringify(reportInput(effectiveInput(this.input)));
  }

  schedule(delay = 10): void {
    clearTimeout(this.timer);
    this.timer = setTimeout(() => void this.compute(), delay);
  }

  private async compute(): Promise<void> {
    if (this.localErrors.size) return this.events.errors();
    const eff = effectiveInput(this.input);
    this.persist(eff);
    if (!this.client?.ready) return;
    const root = document.documentElement;
    root.dataset.busy = '1';
    try {
      const t0 = performance.now();
      const asked = reportInput(eff);
      const { result, ms } = await this.client.call('report', asked, 'report');
      this.lastMs = ms;
      if (result.ok) {
        this.report = result.report as unknown as Report;
        this.reportFor = JSON.stringify(asked);
        this.remoteError = null;
        const t1 = performance.now();
        this.events.report();
        this.events.errors();
        const t2 = performance.now();
        root.dataset.reportMs = (t1 - t0).toFixed(1);
        root.dataset.renderMs = (t2 - t1).toFixed(1);
        if (this.inputAt) root.dataset.updateMs = (t2 - this.inputAt).toFixed(1);
        clearTimeout(this.simTimer);
        this.simTimer = setTimeout(() => void this.computeSim(eff), SIM_PAUSE_MS);
      } else {
        this.remoteError = result;
        this.events.errors();
      }
    } catch (e) {
      if (!(e instanceof Superseded)) throw e;
    } finally {
      delete root.dataset.busy;
      this.events.busy();
    }
  }

  /** The worker for simulations and CSV exports (started on first use). */
  simWorker(): PulabClient | null {
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
        this.simFieldError = null;
      } else {
        this.simError = `${result.field}: ${errText(result)}`;
        this.simFieldError = result.field.startsWith('sim') ? result : null;
        if (this.simFieldError) this.events.errors();
      }
      this.events.sim();
    } catch (e) {
      if (!(e instanceof Superseded)) throw e;
    }
  }

  /** The input goes into the URL (#in=) and localStorage; embeds leave both to their host page. */
  private persist(eff: Input): void {
    if (this.embed) return;
    const hash = encodeHash(eff, this.units);
    if (location.hash !== hash) history.replaceState(null, '', hash);
    store(STORAGE_KEY, JSON.stringify(eff));
  }
}
