import { flagChips, h, num, patch, table } from '../dom';
import { ALL_FIELDS } from '../fields';
import { t } from '../i18n';
import { VENDOR_NAMES, type TraceStep, type VendorResult } from '../generated/report-types';
import { limitsBox } from './limits';
import type { Panel } from './panel';

/** Each raw firmware parameter's unit, from the input schema (`raw.*`). */
const RAW_UNITS: Record<string, string> = Object.fromEntries(
  ALL_FIELDS.filter((f) => f.path.startsWith('raw.')).map((f) => [f.path.slice(4), f.unit ?? '']));

const VAR: Record<string, string> = {
  Rpm: 'gMotorExtPer.Rpm', LD: 'gMotorExtPer.LD', LQ: 'gMotorExtPer.LQ', FreqPer: 'gMotorInfo.FreqPer',
  FluxRotor: 'gMotorExtPer.FluxRotor', pm_maxout_vol: 'pm_maxout_vol', maxu: 'maxu',
};

/** Highlight C: keywords/types, numbers, comments. Text only, no HTML from the report. */
export function cCode(code: string): HTMLElement {
  const el = h('code', { class: 'c' });
  const re = /(\/\/.*$)|\b(Ulong|Uint16|Long|long|unsigned|int)\b|\b(\d+L?)\b|(<<|>>)/g;
  let last = 0;
  for (const m of code.matchAll(re)) {
    el.append(code.slice(last, m.index));
    const cls = m[1] ? 'cm' : m[2] ? 'kw' : m[3] ? 'nu' : 'op';
    el.append(h('span', { class: cls }, m[0]));
    last = (m.index ?? 0) + m[0].length;
  }
  el.append(code.slice(last));
  return el;
}

/** A result the firmware cannot compute for this motor (its reason is in the limits box). */
function notHeldRow(name: string): HTMLElement {
  return h('tr', { class: 'na' }, h('td', {}, h('code', {}, VAR[name])), h('td', { colspan: 8 }, t('fw_not_computed')));
}

function resultRow(name: string, v: VendorResult | undefined, missing: boolean): HTMLElement {
  if (missing) return notHeldRow(name);
  const p = `vendor.${name}`;
  const bad = v?.flags.some((f) => f === 'wrap' || f === 'store');
  return h(
    'tr',
    { class: bad ? 'bad' : '' },
    h('td', {}, h('code', {}, VAR[name])),
    h('td', { class: 'r' }, num(`${p}.value`, v?.value, { kind: 'int', alias: p })),
    h('td', { class: 'r' }, v ? num(`${p}.value`, v.value, { kind: 'hex', type: v.type }) : '…'),
    h('td', { class: 'r' }, num(`${p}.q`, v?.q, { kind: 'int' })),
    h('td', { class: 'r' }, num(`${p}.ideal`, v?.ideal, { sig: 8 })),
    h('td', { class: 'r' }, num(`${p}.error_pct`, v?.error_pct, { kind: 'pct' })),
    h('td', { class: 'r' }, num(`${p}.si`, v?.si, { sig: 6 }), h('span', { class: 'u' }, ` ${v?.unit ?? ''}`)),
    h('td', {}, v?.type ?? ''),
    h('td', {}, flagChips(v?.flags)),
  );
}

/** The C statements of a trace with the integer after each one (data-key = `${prefix}.${i}.value`). */
export function traceTable(prefix: string, steps: TraceStep[]): HTMLElement {
  return h(
    'table',
    { class: 'trace' },
    h('tbody', {}, steps.map((s, i) =>
      h(
        'tr',
        { class: s.flags.some((f) => f === 'wrap' || f === 'store') ? 'bad' : s.flags.length ? 'warn' : '' },
        h('td', { class: 'code' }, cCode(s.code)),
        h('td', { class: 'arrow' }, '→'),
        h('td', { class: 'var' }, h('code', {}, s.var), h('span', { class: 'ty' }, ` (${s.type})`)),
        h('td', { class: 'r' }, num(`${prefix}.${i}.value`, s.value, { kind: 'int' })),
        h('td', { class: 'r' }, num(`${prefix}.${i}.value`, s.value, { kind: 'hex', type: s.type })),
        h('td', { class: 'meaning' }, s.meaning),
        h('td', {}, flagChips(s.flags)),
      ),
    )),
  );
}

function traceBlock(name: string, v: VendorResult | undefined): HTMLElement {
  const p = `vendor.${name}`;
  const steps = v?.trace ?? [];
  return h(
    'div',
    { class: 'trace-block' },
    h('div', { class: 'trace-title' }, h('code', {}, VAR[name]), ' = ', num(`${p}.value`, v?.value, { kind: 'int', mirror: true }), h('span', { class: 'q' }, v ? ` Q${v.q}` : ''), ' ', flagChips(v?.flags)),
    traceTable(`${p}.trace`, steps),
  );
}

export const vendorPanel: Panel = {
  id: 'vendor',
  title: 'p_vendor',
  pure: true,
  render(el, { report }) {
    const vd = report?.vendor;
    const raw = vd?.raw ?? {};
    const status = report?.firmware?.inovance;
    const missing = new Set(status?.problems.flatMap((p) => p.results) ?? []);
    patch(el,
      limitsBox('inovance', status),
      h('div', { class: 'raw-used' }, h('span', { class: 'lbl' }, `${t('raw')}: `),
        Object.keys(RAW_UNITS).map((k) => h('span', { class: 'rawchip', title: RAW_UNITS[k] }, h('code', {}, k), ' = ',
          report && !(k in raw) ? h('span', { class: 'num na' }, t('fw_not_held')) : num(`vendor.raw.${k}`, raw[k], { kind: 'int' })))),
      table(
        [t('name'), t('value'), t('hex'), t('q'), t('ideal'), t('errorPct'), t('si'), t('type'), t('flags')],
        VENDOR_NAMES.map((n) => resultRow(n, vd?.[n] as VendorResult | undefined, missing.has(n))),
        'vendor',
      ),
      h('h3', {}, t('p_trace')),
      h('div', { class: 'traces' }, VENDOR_NAMES.filter((n) => !missing.has(n)).map((n) => traceBlock(n, vd?.[n] as VendorResult | undefined))),
    );
  },
};
