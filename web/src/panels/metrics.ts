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

/** A column of its own: a label and where its metrics sit in the report (`path` = their JSON path). */
export interface MetricColumn {
  label: string;
  path: string;
  metrics: Record<string, unknown>;
}

export function metricsTable(prefix: string, metrics: Record<string, unknown>, variants: string[], rows: MetricRow[], extra: MetricColumn[] = []): HTMLElement {
  const cols: MetricColumn[] = [
    ...variants.map((v) => ({ label: t(`variant_${v}` as Key), path: `${prefix}.${v}`, metrics: (metrics[v] ?? {}) as Record<string, unknown> })),
    ...extra,
  ];
  return table(
    [t('metrics'), ...cols.map((c) => c.label)],
    rows.map((r) => [
      `${t(r.label)}${r.unit ? ` [${r.unit}]` : ''}`,
      ...cols.map(({ path, metrics: m }) => {
        const x = m[r.key];
        if (r.bool) return h('span', { class: x ? 'ok' : 'bad-text', 'data-key': `${path}.${r.key}`, 'data-value': JSON.stringify(x ?? null) }, x === undefined ? '—' : x ? `✔ ${t('yes')}` : `✘ ${t('no')}`);
        if (typeof x !== 'number') return h('span', { class: 'num', 'data-key': `${path}.${r.key}`, 'data-value': 'null' }, '—');
        const shown = x * (r.scale ?? 1);
        return num(`${path}.${r.key}`, x, { text: Number(shown.toPrecision(4)).toString() });
      }),
    ]),
    'metrics',
  );
}
