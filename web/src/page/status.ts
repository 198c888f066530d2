// The status line: Python's boot progress, a boot failure, or "ready" with the last latency.
import { h } from '../dom';
import { t, type Key } from '../i18n';
import type { PulabClient } from '../rpc';
import { mark } from './marks';

export interface BootState {
  stage: Key;
  fraction: number;
  failed?: string;
  /** A failed boot about to be tried again. */
  retry?: { message: string; attempt: number; of: number; seconds: number };
  /** Python was lost after it was ready, and is starting again. */
  lostMessage?: string;
}

export class StatusLine {
  boot: BootState = { stage: 'boot_runtime', fraction: 0 };
  private client: PulabClient | null = null;

  constructor(private root: HTMLElement, private session: { lastMs: number }) {}

  /** Follow a client that may already be booting; `onReady` runs once it is (or now, if it is). */
  follow(client: PulabClient, onReady: (bootMs: number) => void, onLost?: (message: string) => void): void {
    this.client = client;
    for (const [stage, at] of Object.entries(client.stageAt)) mark(`boot-${stage}`, at);
    client.events = {
      onProgress: (stage, fraction) => {
        mark(`boot-${stage}`);
        this.boot = { stage: `boot_${stage}` as Key, fraction, lostMessage: this.boot.lostMessage };
        this.render();
      },
      onReady: (ms) => {
        mark('boot-ready');
        onReady(ms);
      },
      onFatal: (message) => {
        if (client.lost && onLost) return onLost(message);
        this.boot = { ...this.boot, failed: message, retry: undefined };
        this.render();
      },
      onRetry: (message, attempt, of, delayMs) => {
        this.boot = { ...this.boot, retry: { message, attempt, of, seconds: Math.round(delayMs / 1000) } };
        this.render();
      },
    };
    this.boot = { stage: `boot_${client.progress.stage}` as Key, fraction: client.progress.fraction, failed: client.fatalMessage ?? undefined };
  }

  /** A lost runtime was replaced: say so until the new one reports progress. */
  lost(message: string): void {
    this.boot = { stage: 'boot_runtime', fraction: 0, lostMessage: message };
    this.render();
  }

  render(): void {
    const el = this.root.querySelector('.status');
    if (!el) return;
    const b = this.boot;
    const ready = this.client?.ready === true;
    document.documentElement.dataset.ready = ready ? '1' : '0';
    if (b.failed) {
      el.replaceChildren(h('span', { class: 'status-fatal', role: 'alert' }, `${t('bootFailed')}: ${b.failed}. ${t('fatalHelp')}`),
        h('button', { type: 'button', class: 'status-reload', onclick: () => location.reload() }, t('reload')));
    } else if (!ready && b.lostMessage) {
      el.replaceChildren(h('span', { class: 'status-retry', role: 'status' }, t('runtimeLost', { m: b.lostMessage })), h('progress', { max: 1, value: b.fraction }));
    } else if (!ready && b.retry) {
      el.replaceChildren(h('span', { class: 'status-retry', role: 'status' }, t('bootRetry', { m: b.retry.message, s: b.retry.seconds, n: b.retry.attempt, of: b.retry.of })));
    } else if (!ready) {
      // Numbers already on screen say where they come from (<html data-numbers>).
      const shown = document.documentElement.dataset.numbers;
      const note = shown === 'build' ? t('numbers_build') : shown === 'cached' ? t('numbers_cached') : shown === 'stale' ? t('numbers_waiting') : t(b.stage);
      el.replaceChildren(h('span', { class: shown === 'none' ? '' : 'prelive' }, note), h('progress', { max: 1, value: b.fraction }));
    } else {
      const ms = this.session.lastMs;
      el.replaceChildren(h('span', { class: 'ok' }, `● ${t('boot_ready')}`), h('span', { class: 'lat' }, ms ? ` · ${t('latency', { ms: ms.toFixed(1) })}` : ''));
    }
  }
}
