import { h, num, patch, table, tex } from '../dom';
import { t } from '../i18n';
import type { Panel } from './panel';

const ROWS: [string, string, string][] = [
  ['Rs', 'R_s^* = R_s / Z_b', 'pu'],
  ['Ld', 'L_d^* = L_d / L_b', 'pu'],
  ['Lq', 'L_q^* = L_q / L_b', 'pu'],
  ['psi_r', '\\psi_r^* = \\psi_r / \\psi_b', 'pu'],
  ['Ts', 'T_s^* = T_s\\,\\omega_b', 'pu'],
  ['psi_r_wb', '', 'Wb'],
];

/** ψ_r from the back-EMF in the chosen convention (seed 1.3-2, 1.4-22): peak dq is √2 larger. */
const PSI_R = (conv: 'rms' | 'peak'): string => conv === 'rms'
  ? `\\psi_r = \\dfrac{E_{LL}}{\\sqrt{3}\\cdot 2\\pi f_n}\\ (\\text{${t('texRms')}})`
  : `\\psi_r = \\dfrac{\\sqrt{2}\\,E_{LL}}{\\sqrt{3}\\cdot 2\\pi f_n}\\ (\\text{${t('texPeakCustom')}})`;

export const puPanel: Panel = {
  id: 'pu',
  title: 'p_pu',
  pure: true,
  render(el, { report }) {
    patch(el,
      h('p', { class: 'note' }, tex('u_d^* = R_s^* i_d^* + L_d^* \\frac{di_d^*}{dt^*} - \\omega_e^* L_q^* i_q^*'), ' ', h('span', { class: 'cite' }, t('seedCite', { n: '1.2-2' }))),
      table(
        [t('quantity'), t('formula'), t('value'), t('unit')],
        ROWS.map(([k, f, u]) => [h('code', {}, k),
          tex(k === 'psi_r_wb' ? PSI_R(report?.input.conventions?.base === 'rms' || !report ? 'rms' : 'peak') : f),
          num(`pu.${k}`, report?.pu[k], { sig: 8 }), u]),
      ),
    );
  },
};
