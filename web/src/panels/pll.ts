import { h, num, patch, table, tex } from '../dom';
import { t } from '../i18n';
import { renderPllTrack } from '../figures/pll-track';
import { keptFigure, simPlaceholder } from '../figures/figure';
import { metricsTable } from './metrics';
import type { Panel } from './panel';

export const pllPanel: Panel = {
  id: 'pll',
  usesSim: true,
  title: 'p_pll',
  render(el, ctx) {
    const { report, simReport } = ctx;
    const g = report?.pll ?? {};
    const sim = simReport?.sim?.pll;
    patch(el, ...[
      h('div', { class: 'formulas' },
        tex('k_p = 2\\zeta\\omega_n,\\ k_i = \\omega_n^2;\\qquad k_p^{pu} = k_p\\frac{\\theta_b}{\\omega_b},\\ k_i^{pu} = k_i\\frac{\\theta_b}{\\omega_b}\\ \\text{(3.1-6)};\\qquad \\frac{\\theta_{pu}}{\\omega_{pu}} = \\frac{\\omega_b}{\\theta_b}\\cdot\\frac{1}{s}\\ \\text{(3.2-5)}', true)),
      table(
        [t('quantity'), t('value'), t('unit')],
        [
          [tex('\\omega_n'), num('pll.wn', g.wn), 'rad/s'],
          [tex('k_p'), num('pll.kp', g.kp), '1/s'],
          [tex('k_i'), num('pll.ki', g.ki), '1/s²'],
          [tex('k_p^{pu}'), num('pll.kp_pu', g.kp_pu), 'pu'],
          [tex('k_i^{pu}'), num('pll.ki_pu', g.ki_pu), '1/s'],
          [tex(`${t('integratorGain')}\\ \\omega_b/\\theta_b`.replace(/^([^\\]+)/, '\\text{$1}')), num('pll.integrator_gain', g.integrator_gain), '1/s'],
        ],
        'pllgains',
      ),
      h('h3', {}, t('plotPll')),
      h('div', { class: 'figure', 'data-keep': 'pll-track' }),
      sim ? metricsTable('sim.pll.metrics', sim.metrics, ['si', 'pu', 'q15', 'naive'], [
        { key: 'locked', label: 'locked', bool: true },
        { key: 'lock_time_s', label: 'lockTime', unit: 'ms', scale: 1e3 },
        { key: 'speed_error_hz', label: 'speedErr', unit: 'Hz' },
        { key: 'steady_angle_error_deg', label: 'steadyAngleErr', unit: '°' },
        { key: 'max_angle_error_deg', label: 'maxAngleErr', unit: '°' },
      ]) : null,
    ]);
    keptFigure(el, 'pll-track', sim, (fig) => renderPllTrack(fig, sim!), () => simPlaceholder(ctx));
  },
};
