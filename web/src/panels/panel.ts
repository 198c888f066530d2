// The one small interface every panel and figure shares.
import type { Report } from '../generated/report-types';
import type { Input } from '../state';
import type { PulabClient } from '../rpc';
import type { ApiErr } from '../protocol';

/** A panel's id: its `?embed=` value, `#panel-<id>` anchor and `nav_<id>` i18n key (registry.ts lists them). */
export type PanelId = string;

export interface PanelContext {
  /** The last good report (null while Python boots). */
  report: Report | null;
  /** The report with the "sim" section, or null; `simError` when the simulation failed. */
  simReport: Report | null;
  simError: string | null;
  /** Present when the simulation failed for a reason a retry may cure (its worker died). */
  retrySim?: () => void;
  input: Input;
  client: PulabClient | null;
  /** A panel's own request failed on an input (`err`) or passed (null): the form shows it at the field. */
  fieldError?: (panel: PanelId, err: ApiErr | null) => void;
  /** Put a routine into the simulated current loop (the input's sim.current.code), or with null take it out. */
  setLoop?: (code: Record<string, unknown> | null) => void;
  embed: boolean;
}

export interface Panel {
  id: PanelId;
  /** i18n key of the title. */
  title: string;
  /** Calls Python itself (ctx.client): rendered again once Python is ready. */
  needsPython?: boolean;
  /** Shows simulation results: the simulation runtime starts only if a shown panel has this. */
  usesSim?: boolean;
  /** Its render reads only the context and writes only into `el` (no state of its own), so the
   * layout may also render it into a scratch element (Layout.settle's warm renders). */
  pure?: boolean;
  /** Render into `el` (called on every new report and on a language switch). A panel shows a
   * new report by `patch` (dom.ts): only the numbers that changed are laid out again. */
  render(el: HTMLElement, ctx: PanelContext): void;
}
