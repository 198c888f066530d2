// The induction motor (motor.kind = acim): its circuit, slip and flux in SI and per unit, the
// current-model observer, the current PI on σ·L_s, R_σ and each vendor's C floats. Every number
// is pulab's (report `acim`, `current_pi`, `profiles`); this file formats only.
import { h, num, patch, table } from '../dom';
import { getLang, t, type Key } from '../i18n';
import type { AcimProfile, SimCurrent, SimEvent, SimProfileRun } from '../generated/report-types';
import { renderAcimFlux, renderAcimStep } from '../figures/acim-sim';
import { keptFigure, simPlaceholder } from '../figures/figure';
import { metricsTable, type MetricColumn, type MetricRow } from './metrics';
import type { Panel } from './panel';

const UNITS: Record<string, string> = {
  rs_ohm: 'Ω', rr_ohm: 'Ω', lls_h: 'H', llr_h: 'H', lm_h: 'H', lms_h: 'H', ls_h: 'H', lr_h: 'H', sigma: '',
  sigma_ls_h: 'H', r_sigma_ohm: 'Ω', tau_sigma_s: 's', tau_r_s: 's', tau_s_s: 's', sync_speed_rpm: 'rpm',
  rated_slip: '', slip_freq_hz: 'Hz', magnetizing_current_a: 'A', id_ref_a: 'A', torque_current_a: 'A',
  rotor_flux_wb: 'Wb', torque_per_amp_nm: 'N·m/A', rated_torque_nm: 'N·m', slip_freq_model_hz: 'Hz',
  slip_gain_per_s: '1/s', flux_95_s: 's',
};
const OBSERVER = ['a', 'b_h', 'a_euler', 'b_euler_h'];
const STEP_ROWS: MetricRow[] = [
  { key: 'rise_time_s', label: 'riseTime', unit: 'ms', scale: 1e3 },
  { key: 'overshoot_pct', label: 'overshoot', unit: '%' },
  { key: 'settling_time_s', label: 'settling', unit: 'ms', scale: 1e3 },
  { key: 'steady_state_error_a', label: 'sse', unit: 'A' },
  { key: 'vs_si_max_abs_a', label: 'acimVsSi', unit: 'A' },
  { key: 'wraps', label: 'acimWraps' },
];
const EVENTS: SimEvent[] = ['feedback_saturate', 'wrap', 'saturate', 'integral_limit', 'output_limit'];
const FLUX_ROWS: MetricRow[] = [
  { key: 'flux_95_s', label: 'acimFlux95', unit: 's' },
  { key: 'psi_final_wb', label: 'acimPsiFinal', unit: 'Wb' },
  ...STEP_ROWS,
];

/** One simulated run (sim.current or sim.flux): its plot, metrics and TI's event counts. */
function simSection(name: 'current' | 'flux', sim: SimCurrent | undefined): (HTMLElement | null)[] {
  const p = `sim.${name}`;
  const ti = sim?.by_profile?.ti as SimProfileRun | undefined;
  const extra: MetricColumn[] = ti?.ran ? [{ label: t('acimFixedTi'), path: `${p}.by_profile.ti.metrics`, metrics: ti.metrics }] : [];
  const variants = sim?.variants.fixed ? ['si', 'pu', 'fixed'] : ['si', 'pu'];
  return [
    h('h4', {}, t(name === 'current' ? 'acimSimStep' : 'acimSimFlux')),
    h('div', { class: 'figure', 'data-keep': `acim-${name}` }),
    sim ? metricsTable(`${p}.metrics`, sim.metrics, variants, name === 'flux' ? FLUX_ROWS : STEP_ROWS, extra) : null,
    sim && name === 'flux' ? h('p', { class: 'note' }, `${t('acimModel95')}: `,
      num('sim.flux.flux_95_model_s', sim.flux_95_model_s as number, { unit: 's', sig: 5 })) : null,
    ti?.ran ? h('p', { class: `note acim-ti-events${ti.events.wrap || ti.events.saturate ? ' flag-wrap' : ''}` },
      t('sf_events', { name: 'TI' }), ' ',
      ...EVENTS.flatMap((e, i) => [i ? ', ' : '', `${t(`sf_ev_${e}` as Key)} `, num(`${p}.by_profile.ti.events.${e}`, ti.events[e], { kind: 'int' })])) : null,
  ];
}

export const acimPanel: Panel = {
  id: 'acim',
  title: 'p_acim',
  usesSim: true,
  render(el, ctx) {
    const { report } = ctx;
    const a = report?.acim;
    // the last simulation is an induction motor's when it has the flux build-up
    const sim = a && ctx.simReport?.sim?.flux ? ctx.simReport.sim : undefined;
    if (!a) {
      patch(el, h('p', { class: 'note' }, t('acimPmsm')));
      return;
    }
    const profiles = (report?.profiles ?? {}) as unknown as Record<string, AcimProfile>;
    const pi = report!.current_pi;
    patch(el,
      h('p', { class: 'note' }, t(a.magnetizing_from === 'given' ? 'acimImGiven' : 'acimImEstimated')),
      h('h3', {}, t('acimCircuit')),
      table([t('quantity'), t('value'), t('unit'), 'pu'],
        Object.keys(UNITS).map((k) => [t(`acim_${k}` as Key), num(`acim.${k}`, a[k], { sig: 7 }), UNITS[k],
          k in a.pu ? num(`acim.pu.${k}`, a.pu[k], { sig: 7 }) : '']), 'acim'),
      h('h3', {}, t('acimObserver')),
      table([t('quantity'), t('value')], [
        ...OBSERVER.map((k) => [t(`acim_${k}` as Key), num(`acim.observer.${k}`, a.observer[k], { sig: 9 })]),
        ['b / L_b', num('acim.pu.observer_b', a.pu.observer_b, { sig: 9 })],
      ]),
      h('h3', {}, t('acimLoop')),
      table(['', 'kp [Ω]', 'ki [Ω/s]', 'pm_kp (Q12)', 'pm_ki (Q16)'], (['d', 'q'] as const).map((x) => [x,
        num(`current_pi.${x}.kp`, pi[x].kp, { sig: 7 }), num(`current_pi.${x}.ki`, pi[x].ki, { sig: 7 }),
        num(`current_pi.${x}.pm_kp`, pi[x].pm_kp, { kind: 'int' }), num(`current_pi.${x}.pm_ki`, pi[x].pm_ki, { kind: 'int' })])),
      h('p', { class: 'note' }, t('acimInovance')),
      h('h3', {}, t('acimVendors')),
      ...Object.entries(profiles).map(([v, p]) => p.available && p.constants
        ? h('div', { class: 'acim-vendor', 'data-vendor': v },
          h('h4', {}, v),
          table([t('quantity'), t('value'), '', '=', 'err %'], Object.entries(p.constants).map(([k, c]) => [h('code', {}, k),
            num(`profiles.${v}.constants.${k}.value`, c.value, { sig: 9 }), c.format, c.expression,
            num(`profiles.${v}.constants.${k}.error_pct`, c.error_pct, { sig: 3 })])),
          h('p', { class: 'note' }, (getLang() === 'zh' ? p.not_covered_zh : p.not_covered) ?? ''))
        : h('p', { class: 'note', 'data-vendor': v }, h('strong', {}, v), `: ${t('acimNoProfile')}`)),
      h('h3', {}, t('acimSim')),
      ...simSection('current', sim?.current),
      ...simSection('flux', sim?.flux),
    );
    keptFigure(el, 'acim-current', sim?.current, (fig) => renderAcimStep(fig, sim!.current!), () => simPlaceholder(ctx));
    keptFigure(el, 'acim-flux', sim?.flux, (fig) => renderAcimFlux(fig, sim!.flux!), () => simPlaceholder(ctx));
  },
};
