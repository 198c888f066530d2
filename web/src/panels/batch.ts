// The Batch panel: a CSV of motors → every motor's firmware integers, errors and
// findings, computed by pulab.analyses.batch in the worker chunk by chunk (progress, cancel). The CSV
// downloaded is the text Python wrote, the same as `pulab batch motors.csv`.
import { h, num } from '../dom';
import { errText, getLang, t, type Key } from '../i18n';
import type { ApiErr } from '../protocol';
import { runChunks, type ChunkJob } from '../family/chunks';
import type { Panel, PanelContext } from './panel';

/** Rows in the first worker call; later calls adapt (family/chunks.ts). */
const CHUNK = 40;
/** Rows drawn in the table; the CSV has them all. */
const SHOWN = 200;
/** Columns drawn in the table (all are in the CSV). */
const TABLE_COLUMNS = ['vendor.Rpm.value', 'vendor.LD.value', 'vendor.LD.error_pct', 'vendor.LD.flags', 'vendor.FluxRotor.value',
  'vendor.pm_maxout_vol.error_pct', 'current_pi.d.pm_kp', 'current_pi.d.pm_ki', 'review.counts.error', 'review.counts.warning', 'review.counts.note'];

const st = {
  file: '' as string,
  text: '' as string,
  job: null as ChunkJob | null,
  done: 0,
  total: 0,
  columns: [] as string[],
  rows: [] as string[][],
  csv: [] as string[],
  error: null as ApiErr | null,
  /** The finished run's line, translated at render time. */
  note: null as null | { key: Key; vars: Record<string, string | number> },
};

async function run(el: HTMLElement, ctx: PanelContext): Promise<void> {
  if (!ctx.client || !st.text) return;
  const client = ctx.client;
  const job: ChunkJob = { cancelled: false };
  Object.assign(st, { job, done: 0, total: 0, columns: [], rows: [], csv: [], error: null, note: null });
  batchPanel.render(el, ctx);
  const first = await client.call('batch', { csv: st.text, start: 0, count: 0 });
  if (!first.result.ok) {
    Object.assign(st, { job: null, error: first.result });
    return batchPanel.render(el, ctx);
  }
  st.total = first.result.total;
  st.columns = first.result.columns;
  const t0 = performance.now();
  const end = await runChunks(client, 'batch', st.total, CHUNK, (start, count) => ({ csv: st.text, start, count }), (r, done) => {
    st.rows.push(...r.rows);
    st.csv.push(r.csv);
    st.done = done;
    const bar = el.querySelector<HTMLProgressElement>('progress.batch-progress');
    if (bar) {
      bar.max = st.total;
      bar.value = done;
    }
  }, job);
  if (end !== 'done' && end !== 'cancelled') st.error = end;
  if (st.total === 0) st.csv = [first.result.csv];
  const bad = st.rows.filter((r) => r[st.columns.indexOf('error')]).length;
  st.note = end === 'cancelled' ? { key: 'swCancelled', vars: { done: st.done, total: st.total } }
    : { key: 'btDone', vars: { n: st.total, bad, s: ((performance.now() - t0) / 1000).toFixed(2) } };
  st.job = null;
  document.documentElement.dataset.batchDone = String(st.done);
  batchPanel.render(el, ctx);
}

function download(): void {
  const blob = new Blob([st.csv.join('')], { type: 'text/csv;charset=utf-8' });
  const a = h('a', { href: URL.createObjectURL(blob), download: (st.file.replace(/\.csv$/i, '') || 'motors') + '-pulab.csv' });
  document.body.append(a);
  a.click();
  a.remove();
}

function resultTable(): HTMLElement {
  const col = (name: string) => st.columns.indexOf(name);
  const labels = st.columns.slice(1, col('error'));
  const head = ['row', ...labels, 'error', 'firmware', ...TABLE_COLUMNS];
  const errCol = col(getLang() === 'zh' ? 'error_zh' : 'error');
  return h('div', { class: 'scroll' }, h('table', { class: 'grid batch-table' },
    h('thead', {}, h('tr', {}, head.map((c) => h('th', {}, c)))),
    h('tbody', {}, st.rows.slice(0, SHOWN).map((r, i) => h('tr', { class: r[col('error')] ? 'bad' : r[col('firmware')] ? 'limit' : '', 'data-row': r[0] },
      h('td', { class: 'r' }, r[0]),
      labels.map((l) => h('td', {}, r[col(l)])),
      h('td', { class: 'batch-error' }, r[errCol]),
      h('td', { class: 'batch-firmware' }, r[col('firmware')]),
      TABLE_COLUMNS.map((c) => {
        const v = r[col(c)];
        return h('td', { class: 'r' }, v === '' || c.endsWith('.flags') ? v : num(`batch.rows.${i}.${c}`, Number(v), { text: v }));
      }))))));
}

export const batchPanel: Panel = {
  id: 'batch',
  title: 'p_batch',
  needsPython: true,
  render(el, ctx) {
    const key = [getLang(), !!ctx.client, !!st.job, JSON.stringify(st.note), st.file, st.error?.message ?? ''].join('|');
    if (el.querySelector('.batch') && el.dataset.rendered === key) return;
    const running = st.job !== null;
    const pick = (ev: Event) => {
      const f = (ev.target as HTMLInputElement).files?.[0];
      if (!f) return;
      void f.text().then((text) => {
        Object.assign(st, { file: f.name, text, rows: [], csv: [], columns: [], note: null, error: null, done: 0, total: 0 });
        void run(el, ctx);
      });
    };
    el.replaceChildren(h('div', { class: 'batch' },
      h('p', { class: 'hint' }, t('btIntro')),
      h('div', { class: 'sweep-run' },
        h('label', { class: 'field inline' }, h('span', { class: 'lbl' }, t('btFile')),
          h('input', { type: 'file', name: 'batch.csv', accept: '.csv,text/csv', disabled: running || !ctx.client, onchange: pick })),
        h('button', { type: 'button', class: 'cancel-batch', disabled: !running, onclick: () => { if (st.job) st.job.cancelled = true; } }, t('swCancel')),
        h('progress', { class: 'batch-progress', max: Math.max(1, st.total), value: st.done }),
        h('button', { type: 'button', class: 'download-batch', disabled: running || st.csv.length === 0, onclick: download }, t('btDownload')),
        h('span', { class: 'hint batch-note' }, st.file ? `${st.file}: ${st.note ? t(st.note.key, st.note.vars) : ''}` : '')),
      st.error ? h('p', { class: 'err', 'data-err-for': st.error.field }, `${st.error.field}: ${errText(st.error)}`) : null,
      st.rows.length ? resultTable() : null,
      st.rows.length > SHOWN ? h('p', { class: 'hint' }, t('btMoreRows', { shown: SHOWN, n: st.rows.length })) : null));
    el.dataset.rendered = key;
  },
};
