// Decode: paste or drop a vendor's generated headers and read back what each #define means, the
// design they encode and what is wrong with them. Every number comes from pulab (the decode kind).
import { h, keepFocus, num, sameItems, table } from '../dom';
import { errText, getLang, t } from '../i18n';
import type { Panel, PanelContext } from './panel';
import type { Decoded, DecodeRequest } from '../api-types';
import type { Reply } from '../protocol';
import { encodeHash } from '../state';

const VENDORS = ['', 'st', 'ti', 'nxp', 'microchip', 'inovance'];

interface DecodeState {
  /** Files chosen or dropped, in order; the text box is one more file when not empty. */
  files: { name: string; text: string }[];
  pasted: string;
  vendor: string;
  define: string;
}

export const dstate: DecodeState = { files: [], pasted: '', vendor: '', define: '' };

let last: Reply['decode'] | null = null;
let seq = 0;
let timer: ReturnType<typeof setTimeout> | undefined;
let waiting = false;

/** The decode request for the current state, or null when there is nothing to decode. */
export function decodeRequest(s: DecodeState): DecodeRequest | null {
  const files = [...s.files, ...(s.pasted.trim() ? [{ name: 'pasted.h', text: s.pasted }] : [])];
  if (!files.length) return null;
  const req: DecodeRequest = { files };
  if (s.vendor) req.vendor = s.vendor;
  const define = s.define.split(/[\s,]+/).filter(Boolean);
  if (define.length) req.define = define;
  return req;
}

/** The context of the last render: a debounced request reads the client at the time it fires. */
let current: PanelContext | null = null;

function compute(el: HTMLElement, _ctx: PanelContext, delay = 250): void {
  clearTimeout(timer);
  timer = setTimeout(() => {
    const ctx = current ?? _ctx;
    const req = decodeRequest(dstate);
    const id = ++seq;
    if (!req) {
      last = null;
      decodePanel.render(el, ctx);
      return;
    }
    if (!ctx.client) {
      waiting = true; // asked before Python is ready: render() asks again once it is
      return;
    }
    waiting = false;
    void ctx.client.call('decode', req, 'decode').then(({ result }) => {
      if (id !== seq) return;
      last = result;
      decodePanel.render(el, ctx);
    }, () => undefined);
  }, delay);
}

async function addFiles(list: FileList | null, el: HTMLElement, ctx: PanelContext): Promise<void> {
  for (const f of Array.from(list ?? [])) dstate.files.push({ name: f.name, text: await f.text() });
  compute(el, ctx, 0);
}

function macrosTable(d: Decoded): HTMLElement {
  const rows = Object.entries(d.macros).map(([name, m]) => [
    h('code', {}, name),
    num(`decode.macros.${name}.value`, m.value, { sig: 10, kind: Number.isInteger(m.value) ? 'int' : 'float' }),
    m.si === null ? '' : num(`decode.macros.${name}.si`, m.si, { sig: 6, unit: m.unit ?? '' }),
    m.meaning,
    h('code', { class: 'formula' }, m.formula),
    h('span', { class: 'src' }, m.source),
  ]);
  return h('div', { class: 'scroll' }, table([t('dc_macro'), t('dc_value'), t('dc_si'), t('dc_meaning'), t('dc_formula'), t('dc_source')], rows, 'dtable'));
}

function loopTable(d: Decoded): HTMLElement | null {
  const loops = d.design.current_loop;
  if (!loops) return null;
  const rows = (['d', 'q'] as const).filter((a) => loops[a]).map((a) => {
    const c = loops[a];
    const k = `decode.design.current_loop.${a}`;
    return [a, num(`${k}.kp_v_per_a`, c.kp_v_per_a, { unit: 'V/A' }), num(`${k}.ki_v_per_a_s`, c.ki_v_per_a_s, { unit: 'V/(A·s)' }),
      num(`${k}.bandwidth_hz`, c.bandwidth_hz, { unit: 'Hz' }), num(`${k}.zero_rad_s`, c.zero_rad_s, { unit: 'rad/s' }),
      num(`${k}.plant_pole_rad_s`, c.plant_pole_rad_s, { unit: 'rad/s' }), c.cancels_plant ? t('dc_yes') : t('dc_no')];
  });
  return h('div', { class: 'scroll' }, table([t('dc_axis'), 'kp', 'ki', t('dc_bw'), t('dc_zero'), t('dc_pole'), t('dc_cancels')], rows, 'dtable'));
}

function motorTable(d: Decoded): HTMLElement {
  const rows: HTMLElement[][] = [];
  for (const [sec, vals] of Object.entries(d.design.input ?? {})) {
    if (!vals || typeof vals !== 'object') continue;
    for (const [k, v] of Object.entries(vals as Record<string, unknown>)) {
      if (typeof v === 'number') rows.push([h('code', {}, `${sec}.${k}`), num(`decode.design.input.${sec}.${k}`, v, { sig: 6 })]);
    }
  }
  return table([t('dc_input'), t('dc_value')], rows, 'dtable');
}

function roundtripTable(d: Decoded): HTMLElement | null {
  const rt = d.roundtrip;
  if (!rt) return null;
  if (rt.error) return h('p', { class: 'err' }, getLang() === 'zh' && rt.error_zh ? rt.error_zh : rt.error);
  const rows = Object.entries(rt.macros).map(([name, m]) => {
    const k = `decode.roundtrip.macros.${name}`;
    return [h('code', {}, name), num(`${k}.file`, m.file, { sig: 10 }), num(`${k}.pulab`, m.pulab, { sig: 10 }),
      m.delta_lsb !== undefined ? num(`${k}.delta_lsb`, m.delta_lsb, { kind: 'int', unit: 'LSB' }) : num(`${k}.delta_rel`, m.delta_rel, { sig: 3 })];
  });
  return h('div', { class: 'scroll' }, table([t('dc_macro'), t('dc_file'), 'pu-lab', t('dc_delta')], rows, 'dtable'));
}

/** What the panel was last drawn with. */
let drawn: unknown[] = [];

export const decodePanel: Panel = {
  id: 'decode',
  needsPython: true,
  title: 'p_decode',
  render(el, ctx) {
    current = ctx;
    if (waiting && ctx.client) compute(el, ctx, 0);
    const shows = [getLang(), last, dstate.files.length, ctx.client];
    if (el.firstChild && sameItems(shows, drawn)) return;
    drawn = shows;
    const ok = last?.ok ? last.decode : null;
    const err = last && !last.ok ? errText(last) : '';
    const drop = (ev: Event) => {
      ev.preventDefault();
      void addFiles((ev as DragEvent).dataTransfer?.files ?? null, el, ctx);
    };
    keepFocus(el, () => el.replaceChildren(
      h('div', { class: 'decode' },
        h('p', { class: 'hint' }, t('dc_hint')),
        h('label', { class: 'field paste' }, h('span', { class: 'lbl' }, t('dc_paste')),
          h('textarea', { name: 'decode.text', rows: '8', spellcheck: 'false', ondragover: (ev: Event) => ev.preventDefault(), ondrop: drop,
            oninput: (ev: Event) => { dstate.pasted = (ev.target as HTMLTextAreaElement).value; compute(el, ctx); } }, dstate.pasted),
          h('span', { class: 'err', 'data-err-for': 'decode.text' }, err)),
        h('div', { class: 'qform' },
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('dc_files')),
            h('input', { type: 'file', name: 'decode.files', multiple: true, accept: '.h,.c,.txt', onchange: (ev: Event) => void addFiles((ev.target as HTMLInputElement).files, el, ctx) })),
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('dc_vendor')),
            h('select', { name: 'decode.vendor', onchange: (ev: Event) => { dstate.vendor = (ev.target as HTMLSelectElement).value; compute(el, ctx, 0); } },
              VENDORS.map((v) => h('option', { value: v, selected: dstate.vendor === v }, v || t('dc_auto'))))),
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('dc_define')),
            h('input', { name: 'decode.define', value: dstate.define, placeholder: 'BSXL8323RS_REVA', spellcheck: 'false',
              oninput: (ev: Event) => { dstate.define = (ev.target as HTMLInputElement).value; compute(el, ctx); } })),
          h('button', { type: 'button', 'data-decode-clear': '', onclick: () => { dstate.files = []; dstate.pasted = ''; compute(el, ctx, 0); } }, t('dc_clear'))),
        dstate.files.length ? h('p', { class: 'hint', 'data-decode-files': '' }, `${t('dc_files')}: ${dstate.files.map((f) => f.name).join(', ')}`) : null,
        ok ? h('div', { class: 'qout', 'data-decode-vendor': ok.vendor },
          h('p', {}, t('dc_found', { vendor: ok.vendor, target: ok.target, n: Object.keys(ok.macros).length })),
          h('h3', {}, t('dc_findings')),
          ok.findings.length
            ? h('ul', { class: 'findings' }, ok.findings.map((f) => h('li', { class: `sev-${f.severity}`, 'data-finding': f.code },
              h('b', {}, `${f.severity} · ${f.code}`), ' ', getLang() === 'zh' ? f.message_zh : f.message, f.advice ? h('span', { class: 'hint' }, ` — ${f.advice}`) : null)))
            : h('p', {}, t('dc_none')),
          h('h3', {}, t('dc_loop')), loopTable(ok) ?? h('p', {}, t('dc_noloop')),
          h('h3', {}, t('dc_design')), motorTable(ok),
          ok.design.missing.length
            ? h('p', { class: 'hint' }, `${t('dc_missing')}: ${ok.design.missing.join(', ')}`)
            : h('p', {}, h('a', { href: encodeHash(ok.design.input), class: 'open-motor', 'data-open-decoded': '' }, t('dc_open'))),
          ok.roundtrip ? h('h3', {}, t('dc_roundtrip')) : null, roundtripTable(ok),
          h('h3', {}, t('dc_macros')), macrosTable(ok),
          Object.keys(ok.unknown).length ? h('p', { class: 'hint' }, `${t('dc_unknown')}: ${[...new Set(Object.values(ok.unknown).flat())].join(', ')}`) : null,
          ok.unresolved.length ? h('p', { class: 'hint' }, `${t('dc_unresolved')}: ${ok.unresolved.join(', ')}`) : null)
          : null),
    ));
  },
};
