// The status line: Python's boot progress, a boot failure, or "ready" with the last latency.
import { h } from '../dom';
import { t, type Key } from '../i18n';
import type { PulabClient } from '../rpc';

export interface BootState {
  stage: Key;
  fraction: number;
  failed?: string;
}

export class StatusLine {
  boot: BootState = { stage: 'boot_runtime', fraction: 0 };
  private client: PulabClient | null = null;

  constructor(private root: HTMLElement, private lastMs: () => number) {}

  /** Follow a client that may already be booting; `onReady` runs once it is (or now, if it is). */
  follow(client: PulabClient, onReady: (bootMs: number) => void): void {
    this.client = client;
    client.events = {
      onProgress: (stage, fraction) => {
        this.boot = { stage: `boot_${stage}` as Key, fraction };
        this.render();
      },
      onReady,
      onFatal: (message) => {
        this.boot = { ...this.boot, failed: message };
        this.render();
      },
    };
    this.boot = { stage: `boot_${client.progress.stage}` as Key, fraction: client.progress.fraction, failed: client.fatalMessage ?? undefined };
  }

  render(): void {
    const el = this.root.querySelector('.status');
    if (!el) return;
    const b = this.boot;
    const ready = this.client?.ready === true;
    document.documentElement.dataset.ready = ready ? '1' : '0';
    if (b.failed) {
      el.replaceChildren(h('span', { class: 'status-fatal', role: 'alert' }, `${t('bootFailed')}: ${b.failed}. ${t('fatalHelp')}`));
    } else if (!ready) {
      el.replaceChildren(h('span', {}, t(b.stage)), h('progress', { max: 1, value: b.fraction }));
    } else {
      const ms = this.lastMs();
      el.replaceChildren(h('span', { class: 'ok' }, `● ${t('boot_ready')}`), h('span', { class: 'lat' }, ms ? ` · ${t('latency', { ms: ms.toFixed(1) })}` : ''));
    }
  }
}
