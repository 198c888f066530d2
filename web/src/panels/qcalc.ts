// Standalone Q-format calculator: every result comes from pulab (pulab.qcalc, the qcalc kind) in the worker.
import { flagChips, h, keepFocus, num, sameItems, table } from '../dom';
import { parseNumber } from '../format';
import { errText, getLang, t } from '../i18n';
import type { Panel, PanelContext } from './panel';
import type { QcalcRequest } from '../generated/api-types';
import type { Reply } from '../protocol';

export interface QcalcState {
  mode: 'encode' | 'decode';
  format: string;
  word_bits: string;
  value: string;
  raw: string;
  rounding: string;
  overflow: string;
}

export const qstate: QcalcState = { mode: 'encode', format: 'Q3.12', word_bits: '', value: '0.229242018648822', raw: '939', rounding: 'nearest', overflow: 'saturate' };

/** The last reply shown; `null`: nothing asked yet; `{ ok: true }` alone: asked, no reply yet. */
let last: Reply['qcalc'] | { ok: true; format?: undefined; result?: undefined } | null = null;
let seq = 0;

/** The qcalc request (JSON of pulab.api.qcalc) for the current state, or a local parse error. */
export function qcalcRequest(s: QcalcState): { ok: true; req: QcalcRequest } | { ok: false; field: string; error: 'number' | 'integer' } {
  const req: QcalcRequest = { format: s.format.trim(), rounding: s.rounding, overflow: s.overflow };
  const wb = parseNumber(s.word_bits, true);
  if (!wb.ok) return { ok: false, field: 'qcalc.word_bits', error: wb.error };
  if (wb.value !== null) req.word_bits = wb.value;
  if (s.mode === 'decode') {
    // Sent as typed: pulab reads decimal, 0x… hex, 0b… binary and full-width digits.
    const r = parseNumber(s.raw, true);
    if (r.ok && r.value === null) return { ok: false, field: 'qcalc.raw', error: 'integer' };
    req.raw = r.ok && r.value !== null ? r.value : s.raw.trim();
  } else {
    const v = parseNumber(s.value);
    if (!v.ok || v.value === null) return { ok: false, field: 'qcalc.value', error: 'number' };
    req.value = v.value;
  }
  return { ok: true, req };
}

function field(label: string, control: HTMLElement, name: string, err?: string): HTMLElement {
  return h('label', { class: 'field' }, h('span', { class: 'lbl' }, label), control, h('span', { class: 'err', 'data-err-for': name }, err ?? ''));
}

function compute(el: HTMLElement, ctx: PanelContext): void {
  const r = qcalcRequest(qstate);
  const id = ++seq;
  if (!r.ok) {
    last = { ok: false, field: r.field, message: t(r.error === 'integer' ? 'errInteger' : 'errNumber') };
    qcalcPanel.render(el, ctx);
    return;
  }
  if (!ctx.client) return;
  void ctx.client.call('qcalc', r.req, 'qcalc').then(({ result }) => {
    if (id !== seq) return;
    last = result;
    qcalcPanel.render(el, ctx);
  }, () => undefined);
}

/** What the panel was last drawn with (language, result, form state, runtime). */
let drawn: unknown[] = [];

export const qcalcPanel: Panel = {
  id: 'qcalc',
  needsPython: true,
  title: 'p_qcalc',
  render(el, ctx) {
    if (ctx.client && last === null) {
      last = { ok: true };
      compute(el, ctx);
    }
    // Nothing here depends on the report: a new one (every keystroke in the form) changes nothing.
    const shows = [getLang(), last, JSON.stringify(qstate), ctx.client];
    if (el.firstChild && sameItems(shows, drawn)) return;
    drawn = shows;
    const on = (k: keyof QcalcState) => (ev: Event) => {
      const v = (ev.target as HTMLInputElement).value;
      if (k === 'mode') qstate.mode = v === 'decode' ? 'decode' : 'encode';
      else qstate[k] = v;
      compute(el, ctx);
    };
    const sel = (k: keyof QcalcState, opts: [string, string][]) =>
      h('select', { name: `qcalc.${k}`, onchange: on(k) }, opts.map(([v, l]) => h('option', { value: v, selected: qstate[k] === v }, l)));
    const inp = (k: keyof QcalcState, ph = '') => h('input', { name: `qcalc.${k}`, value: qstate[k], placeholder: ph, inputmode: 'decimal', spellcheck: 'false', oninput: on(k) });
    const errFor = (name: string) => (last && !last.ok && last.field === name ? errText(last) : undefined);
    const f = last?.ok ? last.format : undefined;
    const res = last?.ok ? last.result : undefined;
    const otherErr = last && !last.ok && !['qcalc.value', 'qcalc.raw', 'qcalc.format', 'qcalc.word_bits'].includes(last.field ?? '') ? errText(last) : null;
    keepFocus(el, () => el.replaceChildren(
      h('div', { class: 'qcalc' },
        h('div', { class: 'qform' },
          field(t('qMode'), sel('mode', [['encode', t('qEncode')], ['decode', t('qDecode')]]), 'qcalc.mode'),
          field(t('qFormat'), inp('format', 'Q3.12'), 'qcalc.format', errFor('qcalc.format')),
          field(t('qWordBits'), inp('word_bits', '16'), 'qcalc.word_bits', errFor('qcalc.word_bits')),
          qstate.mode === 'encode'
            ? field(t('qValue'), inp('value'), 'qcalc.value', errFor('qcalc.value'))
            : field(t('qRaw'), inp('raw'), 'qcalc.raw', errFor('qcalc.raw')),
          field(t('qRounding'), sel('rounding', [['nearest', t('qr_nearest')], ['convergent', t('qr_convergent')], ['floor', t('qr_floor')], ['zero', t('qr_zero')]]), 'qcalc.rounding'),
          field(t('qOverflow'), sel('overflow', [['saturate', t('qo_saturate')], ['wrap', t('qo_wrap')], ['error', t('qo_error')]]), 'qcalc.overflow'),
          h('p', { class: 'hint' }, t('qFormatHint'))),
        h('div', { class: 'qout' + (last && !last.ok ? ' stale' : '') },
          otherErr ? h('p', { class: 'err' }, otherErr) : null,
          table([t('quantity'), t('value')], [
            [t('qFormat'), h('code', {}, f?.name ?? '…'), ],
            [t('qRange'), h('span', {}, num('qcalc.format.min', f?.min, { sig: 10 }), ' … ', num('qcalc.format.max', f?.max, { sig: 10 }))],
            [t('qResolution'), num('qcalc.format.resolution', f?.resolution, { sig: 10 })],
            [t('qRaw'), h('span', {}, num('qcalc.result.raw', res?.raw, { kind: 'int' }), '  ', h('code', { class: 'int' }, res?.hex ?? ''))],
            [t('qResult'), num('qcalc.result.value', res?.value, { sig: 12 })],
            [t('qError'), num('qcalc.result.error', res?.error, { sig: 6 })],
            [t('flags'), flagChips(res?.flags)],
          ], 'qtable'))),
    ));
  },
};
