import { h, num, patch, table, tex } from '../dom';
import { t } from '../i18n';
import type { Panel } from './panel';

const UNITS: Record<string, string> = { U_b: 'V', I_b: 'A', f_b: 'Hz', w_b: 'rad/s', Z_b: 'Ω', L_b: 'H', psi_b: 'Wb', T_b: 's', P_b: 'W', theta_b: 'rad' };
const SYM: Record<string, string> = { U_b: 'U_b', I_b: 'I_b', f_b: 'f_b', w_b: '\\omega_b', Z_b: 'Z_b', L_b: 'L_b', psi_b: '\\psi_b', T_b: 'T_b', P_b: 'P_b', theta_b: '\\theta_b' };

function formulas(base: string, angle: string): Record<string, string> {
  const given = `\\text{${t('texGiven')}}`;
  const ub = base === 'peak' ? '\\sqrt{2/3}\\,U_{LL}' : base === 'custom' ? given : 'U_{LL}/\\sqrt{3}';
  const ib = base === 'peak' ? '\\sqrt{2}\\,I_{rms}' : base === 'custom' ? given : 'I_{rms}';
  const pb = base === 'rms' ? '3\\,U_b I_b' : '\\tfrac{3}{2}\\,U_b I_b';
  return {
    U_b: ub, I_b: ib, f_b: `f_{max}\\ (\\text{${t('texDrive')}})`, w_b: '2\\pi f_b', Z_b: 'U_b / I_b', L_b: 'Z_b / \\omega_b',
    psi_b: 'U_b / \\omega_b', T_b: '1/\\omega_b', P_b: pb, theta_b: angle === '2pi' ? '2\\pi' : '\\pi',
  };
}

export const basesPanel: Panel = {
  id: 'bases',
  title: 'p_bases',
  pure: true,
  render(el, { report, input }) {
    const conv = (report?.input.conventions ?? input.conventions ?? {}) as Record<string, string>;
    const f = formulas(conv.base ?? 'rms', conv.angle_base ?? 'pi');
    patch(el,
      h('p', { class: 'note' }, tex('\\{U_b, I_b, f_b\\} \\Rightarrow Z_b = \\frac{U_b}{I_b},\\ \\omega_b = 2\\pi f_b,\\ L_b = \\frac{Z_b}{\\omega_b},\\ \\psi_b = \\frac{U_b}{\\omega_b}'), ' ', h('span', { class: 'cite' }, t('seedCite', { n: '1.1-1' }))),
      table(
        [t('quantity'), t('formula'), t('value'), t('unit')],
        Object.keys(UNITS).map((k) => [tex(SYM[k]), tex(`${SYM[k]} = ${f[k]}`), num(`base.${k}`, report?.base[k]), UNITS[k]]),
        'bases',
      ),
    );
  },
};
