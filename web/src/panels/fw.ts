// Above base speed: base and maximum speed, the current plane and the torque–speed envelope, and
// the tables firmware stores — the report's "fw" section for the page's motor and the form's
// analysis.fw options, asked of pulab by this panel (it costs more than a report, so it has its
// own request and never delays the numbers of the others).
import { flagChips, h, num, patch, table } from '../dom';
import { t } from '../i18n';
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

function cArray(name: string, tb: FwTable): string {
  // ST's look-up is three macros of drive_parameters.h, the others one array each
  if (tb.segdiv !== undefined && tb.angc && tb.ofst) {
    return [`#define IQMAX   ${tb.iqmax}`, `#define SEGDIV  ${tb.segdiv}`,
      `#define ANGC    {${tb.angc.join(',')}}`, `#define OFST    {${tb.ofst.join(',')}}`].join('\n');
  }
  return `static const int16_t ${name}[${tb.values.length}] = { ${tb.values.join(', ')} };`;
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
      ...(fw ? Object.entries(fw.tables).map(([name, tb]) => h('div', { class: 'fw-table' },
        h('p', {}, h('code', {}, name), ` — ${tb.quantity}, ${tb.format} (`, num(`fw.tables.${name}.scale`, tb.scale, { unit: `${tb.unit}/LSB` }),
          `), ${t('fwErrorBound')} `, num(`fw.tables.${name}.error_bound`, tb.error_bound, { unit: tb.unit }),
          tb.error_bound_shift !== undefined ? [' (>> 15: ', num(`fw.tables.${name}.error_bound_shift`, tb.error_bound_shift, { unit: tb.unit }), ')'] : null),
        tb.flags?.length ? flagChips(tb.flags) : null,
        h('pre', { class: 'c-array' }, cArray(name, tb)))) : []),
    );
    keptFigure(el, 'fw-plane', fw, (fig) => renderFwPlane(fig, fw!));
    keptFigure(el, 'fw-speed', fw, (fig) => renderFwSpeed(fig, fw!));
  },
};
