// Audit: paste or drop a vendor's generated headers and read back what each #define means, the
// design they encode and what is wrong with them. Every number comes from pulab (the audit kind).
import { h, keepFocus, num, sameItems, table } from '../dom';
import { errText, getLang, t } from '../i18n';
import type { Panel, PanelContext } from './panel';
import type { Audit, AuditDynamics, AuditRequest } from '../generated/api-types';
import type { Reply } from '../protocol';
import { encodeHash } from '../state';

const PROFILES = ['', 'st', 'ti', 'nxp', 'microchip', 'inovance'];

interface AuditState {
  /** Files chosen or dropped, in order; the text box is one more file when not empty. */
  files: { name: string; text: string }[];
  pasted: string;
  profile: string;
  define: string;
}

export const astate: AuditState = { files: [], pasted: '', profile: '', define: '' };

let last: Reply['audit'] | null = null;
let seq = 0;
let timer: ReturnType<typeof setTimeout> | undefined;
let waiting = false;

/** The audit request for the current state, or null when there is nothing to audit. */
export function auditRequest(s: AuditState): AuditRequest | null {
  const files = [...s.files, ...(s.pasted.trim() ? [{ name: 'pasted.h', text: s.pasted }] : [])];
  if (!files.length) return null;
  const req: AuditRequest = { files };
  if (s.profile) req.profile = s.profile;
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
    const req = auditRequest(astate);
    const id = ++seq;
    if (!req) {
      last = null;
      auditPanel.render(el, ctx);
      return;
    }
    if (!ctx.client) {
      waiting = true; // asked before Python is ready: render() asks again once it is
      return;
    }
    waiting = false;
    void ctx.client.call('audit', req, 'audit').then(({ result }) => {
      if (id !== seq) return;
      last = result;
      auditPanel.render(el, ctx);
    }, () => undefined);
  }, delay);
}

async function addFiles(list: FileList | null, el: HTMLElement, ctx: PanelContext): Promise<void> {
  for (const f of Array.from(list ?? [])) astate.files.push({ name: f.name, text: await f.text() });
  compute(el, ctx, 0);
}

function macrosTable(d: Audit): HTMLElement {
  const rows = Object.entries(d.macros).map(([name, m]) => [
    h('code', {}, name),
    num(`audit.macros.${name}.value`, m.value, { sig: 10, kind: Number.isInteger(m.value) ? 'int' : 'float' }),
    m.si === null ? '' : num(`audit.macros.${name}.si`, m.si, { sig: 6, unit: m.unit ?? '' }),
    m.meaning,
    h('code', { class: 'formula' }, m.formula),
    h('span', { class: 'src' }, m.source),
  ]);
  return h('div', { class: 'scroll' }, table([t('au_macro'), t('au_value'), t('au_si'), t('au_meaning'), t('au_formula'), t('au_source')], rows, 'dtable'));
}

function loopTable(d: Audit): HTMLElement | null {
  const loops = d.design.current_loop;
  const rows = (['d', 'q'] as const).flatMap((a) => {
    const c = loops[a];
    if (!c) return [];
    const k = `audit.design.current_loop.${a}`;
    return [[a, num(`${k}.kp_v_per_a`, c.kp_v_per_a, { unit: 'V/A' }), num(`${k}.ki_v_per_a_s`, c.ki_v_per_a_s, { unit: 'V/(A·s)' }),
      num(`${k}.bandwidth_hz`, c.bandwidth_hz, { unit: 'Hz' }), num(`${k}.zero_rad_s`, c.zero_rad_s, { unit: 'rad/s' }),
      num(`${k}.plant_pole_rad_s`, c.plant_pole_rad_s, { unit: 'rad/s' }), c.cancels_plant ? t('au_yes') : t('au_no'),
      typeof c.phase_margin_deg === 'number' ? num(`${k}.phase_margin_deg`, c.phase_margin_deg, { unit: '°', sig: 3 }) : (c.stable === false ? t('au_unstable') : '')]];
  });
  if (!rows.length) return null;
  return h('div', { class: 'scroll' }, table([t('au_axis'), 'kp', 'ki', t('au_bw'), t('au_zero'), t('au_pole'), t('au_cancels'), t('au_pm')], rows, 'dtable'));
}

/** The speed loop and the observers whose bandwidth and damping the gains give. */
function dynamicsTable(d: Audit): HTMLElement | null {
  const obs = (d.design.observer ?? {}) as Record<string, unknown>;
  const parts: [string, string, AuditDynamics | null | undefined][] = [
    [t('au_speed'), 'audit.design.speed_loop', d.design.speed_loop],
    [t('au_tracking'), 'audit.design.observer.tracking', obs.tracking as AuditDynamics | undefined],
    [t('au_bemf'), 'audit.design.observer.bemf', obs.bemf as AuditDynamics | undefined],
  ];
  const rows = parts.filter(([, , x]) => x && typeof x.natural_hz === 'number').map(([name, k, x]) => [
    name,
    typeof x!.bandwidth_hz === 'number' ? num(`${k}.bandwidth_hz`, x!.bandwidth_hz, { unit: 'Hz' }) : '',
    num(`${k}.natural_hz`, x!.natural_hz as number, { unit: 'Hz' }),
    num(`${k}.damping`, x!.damping as number, { sig: 3 }),
  ]);
  if (!rows.length) return null;
  return h('div', { class: 'scroll' }, table(['', t('au_bw'), t('au_natural'), t('au_damping')], rows, 'dtable'));
}

function motorTable(d: Audit): HTMLElement {
  const rows: HTMLElement[][] = [];
  for (const [sec, vals] of Object.entries(d.design.input ?? {})) {
    if (!vals || typeof vals !== 'object') continue;
    for (const [k, v] of Object.entries(vals as Record<string, unknown>)) {
      if (typeof v === 'number') rows.push([h('code', {}, `${sec}.${k}`), num(`audit.design.input.${sec}.${k}`, v, { sig: 6 })]);
    }
  }
  return table([t('au_input'), t('au_value')], rows, 'dtable');
}

function roundtripTable(d: Audit): HTMLElement | null {
  const gen = d.regenerated;
  if (!gen) return null;
  if (gen.error) return h('p', { class: 'err' }, getLang() === 'zh' && gen.error_zh ? gen.error_zh : gen.error);
  const rows = Object.entries(d.roundtrip).map(([name, m]) => {
    const k = `audit.roundtrip.${name}`;
    return [h('code', {}, name), num(`${k}.file`, m.file, { sig: 10 }), num(`${k}.pulab`, m.pulab, { sig: 10 }),
      m.delta_lsb !== undefined ? num(`${k}.delta_lsb`, m.delta_lsb, { kind: 'int', unit: 'LSB' }) : num(`${k}.delta_rel`, m.delta_rel, { sig: 3 })];
  });
  return h('div', { class: 'scroll' }, table([t('au_macro'), t('au_file'), 'pu-lab', t('au_delta')], rows, 'dtable'));
}

/** What the panel was last drawn with. */
let drawn: unknown[] = [];

export const auditPanel: Panel = {
  id: 'audit',
  needsPython: true,
  title: 'p_audit',
  render(el, ctx) {
    current = ctx;
    if (waiting && ctx.client) compute(el, ctx, 0);
    const shows = [getLang(), last, astate.files.length, ctx.client];
    if (el.firstChild && sameItems(shows, drawn)) return;
    drawn = shows;
    const ok = last?.ok ? last.audit : null;
    const err = last && !last.ok ? errText(last) : '';
    const drop = (ev: Event) => {
      ev.preventDefault();
      void addFiles((ev as DragEvent).dataTransfer?.files ?? null, el, ctx);
    };
    keepFocus(el, () => el.replaceChildren(
      h('div', { class: 'audit' },
        h('p', { class: 'hint' }, t('au_hint')),
        h('label', { class: 'field paste' }, h('span', { class: 'lbl' }, t('au_paste')),
          h('textarea', { name: 'audit.text', rows: '8', spellcheck: 'false', ondragover: (ev: Event) => ev.preventDefault(), ondrop: drop,
            oninput: (ev: Event) => { astate.pasted = (ev.target as HTMLTextAreaElement).value; compute(el, ctx); } }, astate.pasted),
          h('span', { class: 'err', 'data-err-for': 'audit.text' }, err)),
        h('div', { class: 'qform' },
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('au_files')),
            h('input', { type: 'file', name: 'audit.files', multiple: true, accept: '.h,.c,.txt', onchange: (ev: Event) => void addFiles((ev.target as HTMLInputElement).files, el, ctx) })),
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('au_profile')),
            h('select', { name: 'audit.profile', onchange: (ev: Event) => { astate.profile = (ev.target as HTMLSelectElement).value; compute(el, ctx, 0); } },
              PROFILES.map((v) => h('option', { value: v, selected: astate.profile === v }, v || t('au_auto'))))),
          h('label', { class: 'field' }, h('span', { class: 'lbl' }, t('au_define')),
            h('input', { name: 'audit.define', value: astate.define, placeholder: 'BSXL8323RS_REVA', spellcheck: 'false',
              oninput: (ev: Event) => { astate.define = (ev.target as HTMLInputElement).value; compute(el, ctx); } })),
          h('button', { type: 'button', 'data-audit-clear': '', onclick: () => { astate.files = []; astate.pasted = ''; compute(el, ctx, 0); } }, t('au_clear'))),
        astate.files.length ? h('p', { class: 'hint', 'data-audit-files': '' }, `${t('au_files')}: ${astate.files.map((f) => f.name).join(', ')}`) : null,
        ok ? h('div', { class: 'qout', 'data-audit-profile': ok.profile },
          h('p', {}, t('au_found', { profile: ok.profile, target: ok.target, n: Object.keys(ok.macros).length })),
          h('h3', {}, t('au_findings')),
          ok.findings.length
            ? h('ul', { class: 'findings' }, ok.findings.map((f) => h('li', { class: `sev-${f.severity}`, 'data-finding': f.code },
              h('b', {}, `${f.severity} · ${f.code}`), ' ', getLang() === 'zh' ? f.message_zh : f.message, f.advice ? h('span', { class: 'hint' }, ` — ${f.advice}`) : null)))
            : h('p', {}, t('au_none')),
          h('h3', {}, t('au_loop')), loopTable(ok) ?? h('p', {}, t('au_noloop')), dynamicsTable(ok),
          ok.design.range_proof?.verdict
            ? h('p', { 'data-audit-proof': ok.design.range_proof.verdict }, t('au_proof', { verdict: t(`au_v_${ok.design.range_proof.verdict}`) }))
            : null,
          h('h3', {}, t('au_design')), motorTable(ok),
          ok.design.missing.length
            ? h('p', { class: 'hint' }, `${t('au_missing')}: ${ok.design.missing.join(', ')}`)
            : h('p', {}, h('a', { href: encodeHash(ok.design.input), class: 'open-motor', 'data-open-audit': '' }, t('au_open'))),
          ok.regenerated ? h('h3', {}, t('au_roundtrip')) : null, roundtripTable(ok),
          h('h3', {}, t('au_macros')), macrosTable(ok),
          Object.keys(ok.unknown).length ? h('p', { class: 'hint' }, `${t('au_unknown')}: ${[...new Set(Object.values(ok.unknown).flat())].join(', ')}`) : null,
          ok.unresolved.length ? h('p', { class: 'hint' }, `${t('au_unresolved')}: ${ok.unresolved.join(', ')}`) : null)
          : null),
    ));
  },
};
