// Above base speed: base and maximum speed, the current plane and the torque–speed envelope, and
// the tables firmware stores — the report's "fw" section for the page's motor and the form's
// analysis.fw options, asked of pulab by this panel (it costs more than a report, so it has its
// own request and never delays the numbers of the others).
import { flagChips, h, num, patch, table } from '../dom';
import { has, t } from '../i18n';
import { effectiveInput } from '../fields';
import { reportInput, type Input } from '../state';
import { keptFigure } from '../figures/figure';
import { renderFwPlane, renderFwSpeed } from '../figures/fw';
import type { FwReport, FwTable } from '../generated/report-types';
import type { Panel } from './panel';
import { OwnRequest } from './own-request';

/** The input pulab computes the "fw" section from: the plain report input and analysis.fw. */
export function fwInput(inp: Input): Input {
  const eff = effectiveInput(inp);
  const fw = inp.analysis?.fw;
  return { ...reportInput(eff), analysis: { fw: fw && typeof fw === 'object' && !Array.isArray(fw) ? fw : {} } };
}

const views = new WeakMap<HTMLElement, OwnRequest<FwReport>>();

/** What a table holds, in the page's language (the report's `quantity` and `format` are English). */
function tableWhat(name: string, tb: FwTable): string {
  const key = `fwTable_${name}`;
  return has(key) ? t(key) : `${tb.quantity}, ${tb.format}`;
}

/** What a table of pulab.analyses.fwtables adds: its input digits, TI's float32 figures, a voltage
 * loop's constants (stored, ideal, error) and the speed its steady state holds. */
function tableDetails(name: string, tb: FwTable): HTMLElement | null {
  const k = (key: string): string => `fw.tables.${name}.${key}`;
  const parts: (Node | string)[] = [];
  if (tb.x_scale !== undefined) {
    parts.push(`${t('fwInput')}: `, num(k('x_scale'), tb.x_scale, { unit: `${tb.x_unit}/digit` }));
    if (tb.x_step_digits !== undefined) parts.push(' × ', num(k('x_step_digits'), tb.x_step_digits, { kind: 'int' }));
    if (tb.x_first_digit !== undefined) parts.push(', ', num(k('x_first_digit'), tb.x_first_digit, { kind: 'int' }), '…', num(k('x_last_digit'), tb.x_last_digit, { kind: 'int' }));
  }
  if (tb.fwonspeed !== undefined) parts.push(' FWONSPEED ', num(k('fwonspeed'), tb.fwonspeed, { kind: 'int' }), ', SPEED_INDEX_CONST ', num(k('speed_index_const'), tb.speed_index_const, { kind: 'int' }));
  if (tb.kconst !== undefined) {
    parts.push('kconst ', num(k('kconst'), tb.kconst), `; ${t('fwSampled')} `, num(k('error_sampled'), tb.error_sampled, { unit: 'A' }));
    if (tb.cla_error_at_limit_a !== undefined) parts.push(`; ${t('fwClaError')} `, tb.cla_error_at_limit_a === null ? h('span', { 'data-key': k('cla_error_at_limit_a'), 'data-value': 'null' }, 'NaN') : num(k('cla_error_at_limit_a'), tb.cla_error_at_limit_a, { unit: 'A' }));
  }
  if (tb.steady?.max_speed_rpm !== undefined) parts.push(`${t('fwHeldMax')} `, num(k('steady.max_speed_rpm'), tb.steady.max_speed_rpm, { unit: 'rpm' }));
  const consts = tb.constants ? table([t('fwConstant'), t('fwStored'), t('fwIdeal'), t('fwRelError')],
    Object.entries(tb.constants).map(([c, v]) => [h('code', {}, c), num(k(`constants.${c}.value`), v.value),
      v.ideal === null ? '—' : num(k(`constants.${c}.ideal`), v.ideal), v.error === null ? '—' : num(k(`constants.${c}.error`), v.error, { kind: 'pct' })]), 'fw-constants') : null;
  if (!parts.length && !consts) return null;
  return h('div', { class: 'fw-details' }, parts.length ? h('p', {}, ...parts) : null, consts);
}

export const fwPanel: Panel = {
  id: 'fw',
  title: 'p_fw',
  needsPython: true,
  render(el, ctx) {
    let v = views.get(el);
    if (!v) views.set(el, (v = new OwnRequest(el, 'fw', fwInput, (r) => r.fw ?? null, fwPanel.render)));
    v.ask(ctx);
    const fw = v.data;
    patch(el,
      h('p', { class: 'note' }, t('fwIntro')),
      v.error ? h('p', { class: 'sim-error', role: 'alert' }, v.error) : null,
      fw ? table([t('quantity'), t('value')], [
        [t('fwBase'), num('fw.base_speed_rpm', fw.base_speed_rpm, { unit: 'rpm' })],
        [t('fwMax'), fw.max_speed_rpm === null ? h('span', { 'data-key': 'fw.max_speed_rpm', 'data-value': 'null' }, t('fwUnbounded')) : num('fw.max_speed_rpm', fw.max_speed_rpm, { unit: 'rpm' })],
        [t('fwChar'), num('fw.characteristic_current_a', fw.characteristic_current_a, { unit: 'A' })],
        [t('fwCurrentLimit'), num('fw.current_limit_a', fw.current_limit_a, { unit: 'A' })],
        [t('fwVoltageLimit'), num('fw.voltage_limit_v', fw.voltage_limit_v, { unit: 'V' })],
        [t('fwPsi'), num('fw.psi_wb', fw.psi_wb, { unit: 'Wb' })],
      ], 'fw-summary') : h('div', { class: 'plot-placeholder' }, v.pending ? t('fwComputing') : t('fwWaiting')),
      h('h3', {}, t('fwPlane')),
      h('div', { class: 'figure', 'data-keep': 'fw-plane' }),
      h('h3', {}, t('fwSpeedCurves')),
      h('div', { class: 'figure', 'data-keep': 'fw-speed' }),
      h('h3', {}, t('fwTables')),
      fw ? h('p', { class: 'note' }, t('fwTablesNote')) : null,
      ...(fw ? Object.entries(fw.tables).map(([name, tb]) => h('div', { class: 'fw-table' },
        h('p', {}, h('code', {}, name), ` — ${tableWhat(name, tb)}`,
          tb.scale !== null ? [' (', num(`fw.tables.${name}.scale`, tb.scale, { unit: `${tb.unit}/LSB` }), ')'] : null,
          `, ${t('fwErrorBound')} `, num(`fw.tables.${name}.error_bound`, tb.error_bound, { unit: tb.unit }),
          tb.error_bound_shift !== undefined ? [' (>> 15: ', num(`fw.tables.${name}.error_bound_shift`, tb.error_bound_shift, { unit: tb.unit }), ')'] : null),
        tableDetails(name, tb),
        tb.flags?.length ? flagChips(tb.flags) : null,
        h('pre', { class: 'c-array' }, tb.c))) : []),
    );
    keptFigure(el, 'fw-plane', fw, (fig) => renderFwPlane(fig, fw!));
    keptFigure(el, 'fw-speed', fw, (fig) => renderFwSpeed(fig, fw!));
  },
};
