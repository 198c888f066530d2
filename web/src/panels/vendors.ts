// Vendor profiles side by side (Inovance, TI, NXP, ST, Microchip), the translator between their
// current-loop integers, and a C header per vendor. Every number comes from pulab in the worker:
// the report with a "profiles" section, and the kinds vendors.translate and vendors.header.
import { flagChips, h, keepFocus, num, table } from '../dom';
import { effectiveInput } from '../fields';
import { parseNumber } from '../format';
import { errText, getLang, t, type Key } from '../i18n';
import { reportInput, type Input } from '../state';
import type { FirmwareStatus, ProfileReport } from '../generated/report-types';
import type { Translation } from '../generated/api-types';
import type { ApiErr } from '../protocol';
import { limitsBox } from './limits';
import type { Panel, PanelContext } from './panel';
import schema from '../generated/schema.json';
import { VENDORS, gainFields, headerFile, vendorName, type Vendor } from '../vendors';


/** Hardware inputs offered as fields; `name` = `profiles.VENDOR.KEY` (empty = pulab's default). */
export const HW_FIELDS: [Vendor, string][] = [
  ['ti', 'full_scale_voltage_v'], ['ti', 'full_scale_current_a'], ['ti', 'global_q'],
  ['nxp', 'udcb_max_v'], ['nxp', 'i_max_a'],
  ['st', 'rshunt_ohm'], ['st', 'amplification_gain'], ['st', 'adc_reference_v'], ['st', 'tf_kpdiv'], ['st', 'tf_kidiv'],
  ['microchip', 'voltage_base_v'], ['microchip', 'current_base_a'], ['microchip', 'velocity_base_hz'],
];
/** Each option's label (vendor first), unit and kind, as pulab names it in its messages (the
 * fields each vendor registers, pulab.schema.vendors, written to generated/schema.json by the build). */
const OPTION_LABEL = new Map(schema.options.map((o) => [o.path, o]));
function optionLabel(name: string): string {
  const o = OPTION_LABEL.get(name);
  if (!o) throw new Error(`web/src/panels/vendors.ts: ${name} is not a profile option`);
  const label = o.label[getLang() === 'zh' ? 1 : 0];
  return o.unit ? `${label}${getLang() === 'zh' ? '，' : ', '}${o.unit}` : label;
}

/** Where a profile's own current-loop integers sit in report.profiles.V.constants. */
function ownKey(v: Vendor, name: string, axis: 'd' | 'q'): string {
  return v === 'inovance' ? `${name}_${axis}` : name;
}

const BASE_ROWS = ['voltage_base', 'current_base', 'line_or_phase', 'rms_or_peak', 'clarke_k', 'inductance_base', 'pi_form', 'rounding'] as const;
const BASE_NUMS: [string, string][] = [['U_b', 'V'], ['I_b', 'A'], ['Z_b', 'Ω'], ['L_b', 'H']];


export interface VendorsState {
  hw: Record<string, string>;
  from: Vendor;
  axis: 'd' | 'q';
  kp: string;
  ki: string;
}
export const vstate: VendorsState = { hw: {}, from: 'inovance', axis: 'q', kp: '', ki: '' };

let profiles: Record<string, ProfileReport> | null = null;
let firmware: Record<string, FirmwareStatus> = {};
let profErr: ApiErr | null = null;
let translation: Translation | null = null;
let transErr: ApiErr | null = null;
let lastKey = '';
let lastTransKey = '';
let lastCtx: { el: HTMLElement; ctx: PanelContext } | null = null;

/** The "profiles" input section from the fields, or the field that does not parse. */
export function profilesSection(hw: Record<string, string>): { ok: true; section: Record<string, Record<string, number>> } | { ok: false; field: string; error: 'number' | 'integer' } {
  const section: Record<string, Record<string, number>> = {};
  for (const [v, k] of HW_FIELDS) {
    const name = `profiles.${v}.${k}`;
    const p = parseNumber(hw[name] ?? '', OPTION_LABEL.get(name)?.kind === 'integer');
    if (!p.ok) return { ok: false, field: name, error: p.error };
    if (p.value !== null) (section[v] ??= {})[k] = p.value;
  }
  return { ok: true, section };
}

/** Whether the reader typed a hardware value for vendor `v` (the simulation uses its defaults). */
export function hardwareTyped(v: string): boolean {
  return HW_FIELDS.some(([w, k]) => w === v && (vstate.hw[`profiles.${w}.${k}`] ?? '').trim() !== '');
}

function baseInput(ctx: PanelContext, section: Record<string, unknown>): Input {
  return { ...reportInput(effectiveInput(ctx.input)), profiles: section as Input[string] };
}

// Computed only while (nearly) visible: five profiles cost ~0.5 ms of Python per report, which
// must not queue behind every keystroke while the reader looks at another panel.
let visibleNow = typeof IntersectionObserver === 'undefined';
let io: IntersectionObserver | null = null;
let watched: HTMLElement | null = null;
function watch(el: HTMLElement): void {
  if (el === watched || typeof IntersectionObserver === 'undefined') return;
  io ??= new IntersectionObserver((entries) => {
    for (const e of entries) if (e.target === watched) visibleNow = e.isIntersecting;
    if (visibleNow && lastCtx) {
      refresh(lastCtx.ctx);
      rerender();
    }
  }, { rootMargin: '400px' });
  if (watched) io.unobserve(watched); // the layout rebuilt the panel: follow the new element
  watched = el;
  io.observe(el);
}

/** Told when new profiles arrive: the page's answer strip, which shows the chosen profile's integers. */
let onProfiles: (() => void) | null = null;

function rerender(): void {
  if (lastCtx) vendorsPanel.render(lastCtx.el, lastCtx.ctx);
}

/**
 * The firmware the reader ships (`v`, not Inovance) as this panel shows it. The page's own report
 * holds that profile with its default hardware (one Python call per keystroke); only with hardware
 * inputs typed here for `v` are the panel's own profiles asked for, even while it is off screen,
 * and `changed` is called when they arrive. Null until known.
 */
export function shippedProfileReport(ctx: PanelContext, v: Vendor, changed: () => void): { profile: ProfileReport; status: FirmwareStatus | undefined } | null {
  const typed = HW_FIELDS.some(([x, k]) => x === v && (vstate.hw[`profiles.${x}.${k}`] ?? '').trim() !== '');
  if (!typed) {
    const profile = ctx.report?.profiles?.[v];
    return profile ? { profile, status: ctx.report?.firmware[v] } : null;
  }
  onProfiles = changed;
  refresh(ctx);
  const profile = profiles?.[v];
  return profile ? { profile, status: firmware[v] } : null;
}

function refresh(ctx: PanelContext): void {
  const s = profilesSection(vstate.hw);
  if (!s.ok) {
    profErr = { ok: false, field: s.field, message: t(s.error === 'integer' ? 'errInteger' : 'errNumber') };
    lastKey = '';
    return;
  }
  const inp = baseInput(ctx, s.section);
  const key = JSON.stringify(inp);
  if (key === lastKey || !ctx.client) return;
  lastKey = key;
  void ctx.client.call('report', inp, 'vendors').then(({ result }) => {
    if (JSON.stringify(inp) !== lastKey) return;
    if (result.ok) {
      profiles = result.report.profiles ?? null;
      firmware = result.report.firmware;
      profErr = null;
      if (vstate.kp === '' && vstate.ki === '') seedTranslator();
    } else profErr = result;
    translate(ctx);
    rerender();
    onProfiles?.();
  }, () => undefined);
}

/** Start the translator from the source profile's own integers for the current motor. */
function seedTranslator(): void {
  const c = profiles?.[vstate.from]?.constants;
  if (!c) return;
  const [kp, ki] = gainFields(vstate.from, vstate.axis);
  vstate.kp = String(c[ownKey(vstate.from, kp, vstate.axis)]?.value ?? '');
  vstate.ki = String(c[ownKey(vstate.from, ki, vstate.axis)]?.value ?? '');
}

function translate(ctx: PanelContext): void {
  const s = profilesSection(vstate.hw);
  if (!s.ok || !ctx.client) return;
  const [kpName, kiName] = gainFields(vstate.from, vstate.axis);
  const values: Record<string, number> = {};
  for (const [name, text] of [[kpName, vstate.kp], [kiName, vstate.ki]] as const) {
    const p = parseNumber(text, true);
    if (!p.ok) {
      transErr = { ok: false, field: `translate.values.${name}`, message: t('errInteger') };
      lastTransKey = '';
      return;
    }
    if (p.value !== null) values[name] = p.value;
  }
  const req = { input: baseInput(ctx, s.section), from: vstate.from, axis: vstate.axis, values };
  const key = JSON.stringify(req);
  if (key === lastTransKey) return;
  lastTransKey = key;
  void ctx.client.call('vendors.translate', req, 'vendors-translate').then(({ result }) => {
    if (key !== lastTransKey) return;
    if (result.ok) {
      translation = result.translation;
      transErr = null;
    } else transErr = result;
    rerender();
  }, () => undefined);
}

async function downloadHeader(ctx: PanelContext, v: Vendor, el: HTMLElement): Promise<void> {
  const s = profilesSection(vstate.hw);
  if (!s.ok || !ctx.client) return;
  const { result } = await ctx.client.call('vendors.header', { input: baseInput(ctx, s.section), profile: v });
  if (!result.ok) {
    const msg = el.querySelector(`[data-err-for="header.${v}"]`);
    if (msg) msg.textContent = `${result.field}: ${errText(result)}`;
    return;
  }
  const url = URL.createObjectURL(new Blob([result.text], { type: 'text/x-c' }));
  const a = h('a', { href: url, download: headerFile(v) }) as HTMLAnchorElement;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 5000);
}

function field(label: string, control: HTMLElement, name: string, err?: string): HTMLElement {
  return h('label', { class: 'field' }, h('span', { class: 'lbl' }, label), control, h('span', { class: 'err', 'data-err-for': name }, err ?? ''));
}

const errFor = (e: ApiErr | null, name: string) => (e && e.field === name ? errText(e) : undefined);

function hwForm(ctx: PanelContext): HTMLElement {
  return h('div', { class: 'qform vendors-hw' },
    HW_FIELDS.map(([v, k]) => {
      const name = `profiles.${v}.${k}`;
      const dflt = profiles?.[v]?.inputs?.[k];
      return field(optionLabel(name),
        h('input', { name, value: vstate.hw[name] ?? '', placeholder: typeof dflt === 'number' ? String(Number(dflt.toPrecision(6))) : '', inputmode: 'decimal', spellcheck: 'false',
          oninput: (ev: Event) => { vstate.hw[name] = (ev.target as HTMLInputElement).value; refresh(ctx); rerender(); } }),
        name, errFor(profErr, name));
    }),
    h('p', { class: 'hint' }, t('vd_hw_hint')));
}

function basesTable(): HTMLElement {
  const rows: HTMLElement[] = [];
  for (const k of BASE_ROWS) {
    const words = (v: Vendor) => {
      const b = profiles?.[v]?.bases;
      const zhWords = b?.zh;
      const zh = getLang() === 'zh' && typeof zhWords === 'object' && zhWords !== null ? zhWords[k] : undefined;
      return zh ?? String(b?.[k] ?? '…');
    };
    rows.push(h('tr', {}, h('td', {}, t(`vb_${k}` as Key)), VENDORS.map((v) => h('td', {}, words(v)))));
  }
  for (const [k, unit] of BASE_NUMS) {
    rows.push(h('tr', {}, h('td', {}, h('code', {}, k)), VENDORS.map((v) => {
      const x = profiles?.[v]?.bases?.[k];
      return h('td', { class: 'r' }, x === null ? '—' : num(`profiles.${v}.bases.${k}`, x, { sig: 6, unit }));
    })));
  }
  return table([t('quantity'), ...VENDORS.map((v) => vendorName(v))], rows, 'vendors-bases');
}

function constantsBlock(ctx: PanelContext, v: Vendor, el: HTMLElement): HTMLElement {
  const consts = profiles?.[v]?.constants ?? {};
  const rows = Object.entries(consts).map(([k, c]) => {
    const p = `profiles.${v}.constants.${k}`;
    const bad = c.flags.some((f) => f === 'out_of_range' || f === 'saturate');
    return h('tr', { class: bad ? 'bad' : '' },
      h('td', {}, h('code', {}, k)),
      h('td', { class: 'r' }, num(`${p}.value`, c.value, c.real ? { sig: 10 } : { kind: 'int' })),
      h('td', {}, c.format),
      h('td', { class: 'r' }, num(`${p}.ideal`, c.ideal, { sig: 8 })),
      h('td', { class: 'r' }, num(`${p}.error_pct`, c.error_pct, { kind: 'pct' })),
      h('td', { class: 'r' }, num(`${p}.si`, c.si, { sig: 6, unit: c.unit })),
      h('td', {}, flagChips(c.flags)),
      h('td', { class: 'src' }, h('span', { title: c.expression }, c.source)));
  });
  return h('details', { class: 'vendor-profile', open: v !== 'inovance', 'data-profile': v },
    h('summary', {}, vendorName(v), ' ',
      h('button', { type: 'button', 'data-header': v, onclick: (ev: Event) => { ev.preventDefault(); void downloadHeader(ctx, v, el); } }, t('vd_header')),
      h('span', { class: 'err', 'data-err-for': `header.${v}` })),
    limitsBox(v, firmware[v]),
    table([t('vd_const'), t('value'), t('vd_format'), t('vd_ideal'), t('vd_error'), t('vd_si'), t('flags'), t('vd_source')], rows, 'vendors-constants'),
    piExample(v),
    profiles?.[v]?.files ? h('p', { class: 'hint' }, t('vd_rounding_read'), ' ', profiles[v].files?.rounding ?? '', '. ',
      profiles[v].files?.worked_numbers.length ? [t('vd_worked'), ' ', profiles[v].files?.worked_numbers.join('; ')] : t('vd_no_worked')) : null);
}

/** TI: the USER_checkForErrors codes the firmware would set; ST: the PI example below. */
function piExample(v: Vendor): HTMLElement | null {
  const checks = profiles?.[v]?.checks;
  if (checks) {
    return checks.length === 0 ? h('p', { class: 'hint' }, t('vd_checks_ok'))
      : h('ul', { class: 'err vendors-checks' }, checks.map(([code, why]) => h('li', {}, h('code', {}, code), ` (${why})`)));
  }
  const ex = profiles?.[v]?.pi_example;
  if (!ex) return null;
  return h('p', { class: 'hint' }, t('vd_pi_example'), ' ', ex.map((x, i) => {
    const p = `profiles.${v}.pi_example.${i}`;
    return h('span', { class: 'rt' + (x.shift !== x.misra ? ' bad' : '') }, 'e = ', num(`${p}.error`, x.error, { kind: 'int' }), ': >> ', num(`${p}.shift`, x.shift, { kind: 'int' }), ', / ', num(`${p}.misra`, x.misra, { kind: 'int' }));
  }));
}

function translator(ctx: PanelContext): HTMLElement {
  const [kpName, kiName] = gainFields(vstate.from, vstate.axis);
  const tr = translation;
  const onSel = (k: 'from' | 'axis') => (ev: Event) => {
    const v = (ev.target as HTMLSelectElement).value;
    if (k === 'from') vstate.from = VENDORS.find((x) => x === v) ?? vstate.from;
    else vstate.axis = v === 'd' ? 'd' : 'q';
    vstate.kp = '';
    vstate.ki = '';
    seedTranslator();
    translate(ctx);
    rerender();
  };
  const onInt = (k: 'kp' | 'ki') => (ev: Event) => {
    vstate[k] = (ev.target as HTMLInputElement).value;
    translate(ctx);
  };
  const profRows = VENDORS.map((v) => {
    const s = tr?.profiles?.[v];
    const p = `translation.profiles.${v}`;
    return h('tr', {}, h('td', {}, vendorName(v)),
      h('td', {}, s ? Object.entries(s.values).map(([k, x]) => h('div', {}, h('code', {}, k), ' = ', num(`${p}.values.${k}`, x, { kind: 'int' }))) : '…'),
      h('td', { class: 'r' }, num(`${p}.si.kp`, s?.si.kp, { sig: 7, unit: 'V/A' })),
      h('td', { class: 'r' }, num(`${p}.si.ki`, s?.si.ki, { sig: 7, unit: 'V/(A·s)' })),
      h('td', { class: 'r' }, num(`${p}.loss_pct.kp`, s?.loss_pct.kp, { kind: 'pct' }), ' / ', num(`${p}.loss_pct.ki`, s?.loss_pct.ki, { kind: 'pct' })));
  });
  const chainRows = (tr?.chain ?? []).map((s, i) => {
    const p = `translation.chain.${i}`;
    return h('tr', {}, h('td', {}, `${i + 1}. `, vendorName(s.profile ?? 'inovance')),
      h('td', {}, Object.entries(s.values).map(([k, x]) => h('div', {}, h('code', {}, k), ' = ', num(`${p}.values.${k}`, x, { kind: 'int' })))),
      h('td', { class: 'r' }, num(`${p}.drift_pct.kp`, s.drift_pct?.kp, { kind: 'pct' }), ' / ', num(`${p}.drift_pct.ki`, s.drift_pct?.ki, { kind: 'pct' })));
  });
  return h('div', { class: 'vendors-translate' },
    h('div', { class: 'qform' },
      field(t('vd_from'), h('select', { name: 'translate.from', onchange: onSel('from') }, VENDORS.map((v) => h('option', { value: v, selected: v === vstate.from }, vendorName(v)))), 'translate.from', errFor(transErr, 'translate.from')),
      field(t('vd_axis'), h('select', { name: 'translate.axis', onchange: onSel('axis') }, (['d', 'q'] as const).map((a) => h('option', { value: a, selected: a === vstate.axis }, a))), 'translate.axis'),
      field(kpName, h('input', { name: `translate.values.${kpName}`, value: vstate.kp, inputmode: 'numeric', spellcheck: 'false', oninput: onInt('kp') }), `translate.values.${kpName}`, errFor(transErr, `translate.values.${kpName}`)),
      field(kiName, h('input', { name: `translate.values.${kiName}`, value: vstate.ki, inputmode: 'numeric', spellcheck: 'false', oninput: onInt('ki') }), `translate.values.${kiName}`, errFor(transErr, `translate.values.${kiName}`)),
      h('p', { class: 'hint' }, t('vd_translate_hint'))),
    transErr && !transErr.field.startsWith('translate.') ? h('p', { class: 'err' }, `${transErr.field}: ${errText(transErr)}`) : null,
    h('div', { class: transErr ? 'stale' : '' },
      h('p', {}, t('vd_si_gains'), ' ', num('translation.si.kp', tr?.si.kp, { sig: 8, unit: 'V/A' }), ', ', num('translation.si.ki', tr?.si.ki, { sig: 8, unit: 'V/(A·s)' })),
      table([t('vd_profile'), t('value'), 'kp', 'ki', t('vd_loss')], profRows, 'vendors-translation'),
      h('h4', {}, t('vd_chain')),
      table([t('vd_step'), t('value'), t('vd_drift')], chainRows, 'vendors-chain'),
      h('p', {}, t('vd_roundtrip'), ' ', Object.entries(tr?.round_trip.delta ?? {}).map(([k, d]) => h('span', { class: 'rt' }, h('code', {}, k), ' Δ = ', num(`translation.round_trip.delta.${k}`, d, { kind: 'int' }), ' ')))));
}

export const vendorsPanel: Panel = {
  id: 'vendors',
  title: 'p_vendors',
  needsPython: true,
  render(el, ctx) {
    lastCtx = { el, ctx };
    watch(el);
    // Off screen its numbers (profiles) are not recomputed (see `watch`), so a new report changes
    // nothing worth rebuilding 1.7 ms of DOM on every keystroke for: it is rebuilt when it nears.
    // (A language switch builds the page anew: `el` is then empty.)
    if (!visibleNow && el.querySelector('.vendors')) return;
    if (visibleNow) refresh(ctx);
    const other = profErr && !profErr.field.startsWith('profiles.') ? h('p', { class: 'err' }, `${profErr.field}: ${errText(profErr)}`) : null;
    keepFocus(el, () => el.replaceChildren(h('div', { class: 'vendors' },
      h('h3', {}, t('vd_hw')), hwForm(ctx), other,
      h('div', { class: profErr ? 'stale' : '' },
        h('h3', {}, t('vd_bases')), basesTable(),
        h('h3', {}, t('vd_constants')), VENDORS.map((v) => constantsBlock(ctx, v, el))),
      h('h3', {}, t('vd_translator')), translator(ctx))));
  },
};
