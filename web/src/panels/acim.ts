// The induction motor (motor.kind = acim): its circuit, slip and flux in SI and per unit, the
// current-model observer, the current PI on σ·L_s, R_σ and each vendor's C floats. Every number
// is pulab's (report `acim`, `current_pi`, `profiles`); this file formats only.
import { h, num, patch, table } from '../dom';
import { getLang, t, type Key } from '../i18n';
import type { AcimProfile } from '../generated/report-types';
import type { Panel } from './panel';

const UNITS: Record<string, string> = {
  rs_ohm: 'Ω', rr_ohm: 'Ω', lls_h: 'H', llr_h: 'H', lm_h: 'H', lms_h: 'H', ls_h: 'H', lr_h: 'H', sigma: '',
  sigma_ls_h: 'H', r_sigma_ohm: 'Ω', tau_sigma_s: 's', tau_r_s: 's', tau_s_s: 's', sync_speed_rpm: 'rpm',
  rated_slip: '', slip_freq_hz: 'Hz', magnetizing_current_a: 'A', id_ref_a: 'A', torque_current_a: 'A',
  rotor_flux_wb: 'Wb', torque_per_amp_nm: 'N·m/A', rated_torque_nm: 'N·m', slip_freq_model_hz: 'Hz',
  slip_gain_per_s: '1/s', flux_95_s: 's',
};
const OBSERVER = ['a', 'b_h', 'a_euler', 'b_euler_h'];

export const acimPanel: Panel = {
  id: 'acim',
  title: 'p_acim',
  pure: true,
  render(el, { report }) {
    const a = report?.acim;
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
    );
  },
};
