// Metrics of a simulation as a table: one column per variant, one row per metric.
import { h, num, table } from '../dom';
import { t, type Key } from '../i18n';

export interface MetricRow {
  key: string;
  label: Key;
  unit?: string;
  /** Display scale (e.g. s → ms) applied to the text only; data-value keeps the report value. */
  scale?: number;
  bool?: boolean;
}

export function metricsTable(prefix: string, metrics: Record<string, unknown>, variants: string[], rows: MetricRow[]): HTMLElement {
  return table(
    [t('metrics'), ...variants.map((v) => t(`variant_${v}` as Key))],
    rows.map((r) => [
      `${t(r.label)}${r.unit ? ` [${r.unit}]` : ''}`,
      ...variants.map((v) => {
        const m = (metrics[v] ?? {}) as Record<string, unknown>;
        const x = m[r.key];
        if (r.bool) return h('span', { class: x ? 'ok' : 'bad-text', 'data-key': `${prefix}.${v}.${r.key}`, 'data-value': JSON.stringify(x ?? null) }, x === undefined ? '—' : x ? `✔ ${t('yes')}` : `✘ ${t('no')}`);
        if (typeof x !== 'number') return h('span', { class: 'num', 'data-key': `${prefix}.${v}.${r.key}`, 'data-value': 'null' }, '—');
        const shown = x * (r.scale ?? 1);
        return num(`${prefix}.${v}.${r.key}`, x, { text: Number(shown.toPrecision(4)).toString() });
      }),
    ]),
    'metrics',
  );
}
