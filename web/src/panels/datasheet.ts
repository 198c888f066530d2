// Datasheet entry: each conversion pulab made (formula and result) and what the pole pairs give.
import { h, num, patch, table } from '../dom';
import { getLang, t, type Key } from '../i18n';
import type { Panel } from './panel';

const MECH = ['rated_speed_rpm', 'base_speed_rpm', 'w_mech_b', 'torque_base_nm', 'psi_pk_wb', 'ke_v_s_per_rad', 'kt_nm_per_a', 'rated_torque_nm', 'rated_torque_pu'] as const;
const MECH_UNIT: Record<string, string> = {
  rated_speed_rpm: 'rpm', base_speed_rpm: 'rpm', w_mech_b: 'rad/s', torque_base_nm: 'N·m', psi_pk_wb: 'Wb',
  ke_v_s_per_rad: 'V·s/rad', kt_nm_per_a: 'N·m/A', rated_torque_nm: 'N·m', rated_torque_pu: 'pu',
};

export const datasheetPanel: Panel = {
  id: 'datasheet',
  title: 'p_datasheet',
  pure: true,
  render(el, { report }) {
    const conv = report?.datasheet?.conversions ?? [];
    const mech = report?.mechanical;
    patch(el,
      conv.length
        ? table([t('dsField'), t('quantity'), t('dsFormula'), t('value'), t('unit')], conv.map((c, i) => [
          h('code', {}, c.field),
          getLang() === 'zh' ? c.label_zh : c.label,
          h('code', { class: 'formula' }, c.formula),
          num(`datasheet.conversions.${i}.value`, c.value, { sig: 8 }),
          c.unit]), 'conversions')
        : h('p', { class: 'note' }, t('dsNone')),
      h('h3', {}, t('mechTitle')),
      table([t('quantity'), t('value'), t('unit')], MECH.map((k) => [
        t(`mech_${k}` as Key), num(`mechanical.${k}`, mech?.[k], { sig: 6 }), MECH_UNIT[k]]), 'mechanical'),
    );
  },
};
