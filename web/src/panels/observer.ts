// Sensorless: the back-EMF and tracking observers' gains, discrete poles and margins, the speed
// filter, the lowest speed the back-EMF budget allows, and NXP's, ST's, Microchip's and TI's
// sensorless constants (TI's eSMO fields are float32: shown as reals) —
// the report's "observer" section and profiles for the page's motor and the form's observer
// options (`{}` when none are typed), asked of pulab by this panel.
import { h, num, patch, table } from '../dom';
import { errText, t } from '../i18n';
import { effectiveInput } from '../fields';
import { reportInput, type Input } from '../state';
import type { Json } from '../protocol';
import { keptFigure } from '../figures/figure';
import { renderObserverBudget, renderObserverPoles } from '../figures/observer';
import type { ObserverLoop, ProfileReport, Report } from '../generated/report-types';
import type { Panel } from './panel';
import { OwnRequest } from './own-request';

/** The vendors whose sensorless integers the panel shows. */
const VENDORS = ['nxp', 'st', 'microchip', 'ti'];

type Obj = { [k: string]: Json };
const obj = (v: unknown): Obj => (v && typeof v === 'object' && !Array.isArray(v) ? (v as Obj) : {});

/** What the reader pasted into the MCAT box: MCAT's JSON or a whole m1_pmsm_appconfig.h, sent as
 * it is (pulab finds the JSON in it, or names the field: pulab.model.mcat.from_text). */
const mcatPaste = { text: '' };

/** The input pulab computes the panel's numbers from: the report input, the observer section
 * (`{}` = defaults) and the vendors' profiles with the form's options. With pasted MCAT inputs
 * the motor and drive are MCAT's (pulab.model.mcat fills them), not the page's: the view then
 * shows the motor of the pasted header. */
export function observerInput(inp: Input): Input {
  const eff = effectiveInput(inp);
  const prof = obj(eff.profiles);
  const profiles: Obj = { ...prof, ...Object.fromEntries(VENDORS.map((v) => [v, obj(prof[v])])) };
  if (!mcatPaste.text.trim()) return { ...reportInput(eff), observer: obj(inp.observer), profiles };
  profiles.nxp = { ...obj(profiles.nxp), mcat: mcatPaste.text };
  return { observer: obj(inp.observer), profiles };
}

interface Shown { report: Report }
const views = new WeakMap<HTMLElement, OwnRequest<Shown>>();

/** A number that may not exist (a margin without a crossover): "—", still keyed. */
function maybe(path: string, value: number | null, unit: string): Node {
  return value === null ? h('span', { 'data-key': path, 'data-value': 'null' }, '—') : num(path, value, { unit });
}

function loopRows(key: string, l: ObserverLoop): (string | Node)[][] {
  const at = `observer.design.${key}`;
  return [
    [t('obsPm'), maybe(`${at}.phase_margin_deg`, l.phase_margin_deg, '°')],
    [t('obsGm'), maybe(`${at}.gain_margin_db`, l.gain_margin_db, 'dB')],
    [t('obsCrossover'), maybe(`${at}.crossover_hz`, l.crossover_hz, 'Hz')],
    [t('obsRadius'), num(`${at}.spectral_radius`, l.spectral_radius)],
  ];
}

function vendorTable(name: string, p: ProfileReport | undefined): Node | null {
  const names = p?.observer_constants ?? [];
  if (!p || !names.length) return null;
  return h('div', {},
    h('h4', {}, name.toUpperCase()),
    table([t('name'), t('value'), t('obsIdeal'), t('obsErrorPct'), t('obsFlags')], names.map((k) => {
      const c = p.constants[k];
      return [h('code', {}, k),
        num(`profiles.${name}.constants.${k}.value`, c.value, c.real ? {} : { kind: 'int' }),
        num(`profiles.${name}.constants.${k}.ideal`, c.ideal),
        num(`profiles.${name}.constants.${k}.error_pct`, c.error_pct, { unit: '%' }),
        c.flags.join(', ') || '—'];
    }), `obs-${name}`));
}

export const observerPanel: Panel = {
  id: 'observer',
  title: 'p_observer',
  needsPython: true,
  render(el, ctx) {
    let v = views.get(el);
    if (!v) views.set(el, (v = new OwnRequest(el, 'observer', observerInput, (r) => (r.observer ? { report: r } : null), observerPanel.render)));
    v.ask(ctx);
    const r = v.data?.report;
    const o = r?.observer;
    const s = o?.settings;
    const b = o?.budget;
    patch(el,
      h('p', { class: 'note' }, t('obsIntro')),
      // A refused MCAT paste is said at its box below.
      v.error && !v.failed?.field.startsWith('profiles.nxp.mcat') ? h('p', { class: 'sim-error', role: 'alert' }, v.error) : null,
      o && s && b ? h('div', {},
        table([t('quantity'), t('value')], [
          [t('obsLowest'), b.min_speed_rpm === null
            ? h('span', { 'data-key': 'observer.budget.min_speed_rpm', 'data-value': 'null' }, t('obsNever'))
            : num('observer.budget.min_speed_rpm', b.min_speed_rpm, { unit: 'rpm' })],
          [t('obsMinSpeed'), num('observer.settings.min_speed_rpm', s.min_speed_rpm, { unit: 'rpm' })],
          [t('obsMerge'), num('observer.settings.merging_speed_rpm', s.merging_speed_rpm, { unit: 'rpm' })],
          [t('obsRErr'), num('observer.budget.terms_v.resistance', b.terms_v.resistance, { unit: 'V' })],
          [t('obsDead'), num('observer.budget.terms_v.deadtime', b.terms_v.deadtime, { unit: 'V' })],
          [t('obsLsb'), num('observer.settings.current_lsb_a', s.current_lsb_a, { unit: 'A' })],
        ], 'obs-budget'),
        h('h3', {}, t('obsDesign')),
        table([t('quantity'), t('obsBemfLoop'), t('obsTrackLoop')], [
          [t('obsKp'), num('observer.design.bemf.kp_v_per_a', o.design.bemf.kp_v_per_a, { unit: 'V/A' }), num('observer.design.tracking.kp_per_s', o.design.tracking.kp_per_s, { unit: '1/s' })],
          [t('obsKi'), num('observer.design.bemf.ki_v_per_as', o.design.bemf.ki_v_per_as, { unit: 'V/(A·s)' }), num('observer.design.tracking.ki_per_s2', o.design.tracking.ki_per_s2, { unit: '1/s²' })],
          ...loopRows('bemf', o.design.bemf).map((row, k) => [...row, loopRows('tracking', o.design.tracking)[k][1]]),
        ], 'obs-design'),
        h('p', {}, t('obsFilter'), ' b0 = b1 = ', num('observer.design.speed_filter.b0', o.design.speed_filter.b0),
          ', a1 = ', num('observer.design.speed_filter.a1', o.design.speed_filter.a1)),
      ) : h('div', { class: 'plot-placeholder' }, v.pending ? t('obsComputing') : t('fwWaiting')),
      h('h3', {}, t('obsPoles')),
      h('div', { class: 'figure', 'data-keep': 'obs-poles' }),
      h('h3', {}, t('obsBudget')),
      h('div', { class: 'figure', 'data-keep': 'obs-budget' }),
      h('h3', {}, t('obsIntegers')),
      h('label', { class: 'field paste' }, h('span', { class: 'lbl' }, t('obsMcat')),
        h('textarea', { name: 'profiles.nxp.mcat', rows: '3', spellcheck: 'false',
          oninput: (ev: Event) => {
            mcatPaste.text = (ev.target as HTMLTextAreaElement).value;
            v!.ask(ctx);
            observerPanel.render(el, ctx);
          } }, mcatPaste.text),
        h('span', { class: 'err', 'data-err-for': 'profiles.nxp.mcat' },
          mcatPaste.text.trim() && v.failed?.field.startsWith('profiles.nxp.mcat') ? errText(v.failed) : '')),
      ...VENDORS.map((name) => vendorTable(name, r?.profiles?.[name])),
      r?.profiles?.st?.observer_constants?.length ? h('p', { class: 'note', 'data-st-rule': r.profiles.st.inputs?.observer_design ? 'design' : 'workbench' },
        t(r.profiles.st.inputs?.observer_design ? 'obsStDesign' : 'obsStRule')) : null,
    );
    keptFigure(el, 'obs-poles', o, (fig) => renderObserverPoles(fig, o!));
    keptFigure(el, 'obs-budget', o, (fig) => renderObserverBudget(fig, o!));
  },
};
