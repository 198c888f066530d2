import { h, num, patch, table } from '../dom';
import { t, type Key } from '../i18n';
import type { Panel } from './panel';

const GROUPS: { title: Key; path: string; options: [string, Key][]; affects: string[] }[] = [
  { title: 'conv_base_title', path: 'conventions.base', options: [['rms', 'conv_base_rms'], ['peak', 'conv_base_peak'], ['custom', 'conv_base_custom']], affects: ['base.U_b', 'base.I_b', 'base.P_b', 'pu.psi_r', 'current_pi.d.pm_kp', 'current_pi.d.pm_ki'] },
  { title: 'conv_angle_title', path: 'conventions.angle_base', options: [['pi', 'conv_angle_pi'], ['2pi', 'conv_angle_2pi']], affects: ['base.theta_b', 'pll.kp_pu', 'pll.ki_pu', 'pll.integrator_gain'] },
  { title: 'conv_l_title', path: 'conventions.inductance_unit', options: [['10uH', 'conv_l_10uH'], ['uH', 'conv_l_uH']], affects: ['vendor.raw.LD', 'vendor.LD.value', 'vendor.LQ.value'] },
];

function get(obj: unknown, path: string): unknown {
  return path.split('.').reduce<unknown>((o, k) => (o && typeof o === 'object' ? (o as Record<string, unknown>)[k] : undefined), obj);
}

export const conventionsPanel: Panel = {
  id: 'conventions',
  title: 'p_conventions',
  pure: true,
  render(el, { report, input }) {
    patch(el,
      ...GROUPS.map((g) => {
        const cur = String(get(report?.input ?? input, g.path) ?? g.options[0][0]);
        return h('div', { class: 'conv' },
          h('h3', {}, t(g.title), ' ', h('code', { class: 'path' }, g.path)),
          h('ul', {}, g.options.map(([v, k]) => h('li', { class: v === cur ? 'current' : '' }, h('code', {}, v), v === cur ? h('span', { class: 'badge' }, t('current')) : null, ' ', t(k)))),
          table([t('affects'), t('value')], g.affects.map((p) => [h('code', {}, p), num(p, get(report, p), { sig: 8 })]), 'affects'));
      }),
    );
  },
};
