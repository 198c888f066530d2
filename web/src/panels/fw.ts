// Above base speed: base and maximum speed, the current plane and the torque–speed envelope, and
// the tables firmware stores — the report's "fw" section for the page's motor and the form's
// analysis.fw options, asked of pulab by this panel (it costs more than a report, so it has its
// own request and never delays the numbers of the others).
import { flagChips, h, num, patch, table } from '../dom';
import { errText, t } from '../i18n';
import { effectiveInput } from '../fields';
import { reportInput, type Input } from '../state';
import { keptFigure } from '../figures/figure';
import { renderFwPlane, renderFwSpeed } from '../figures/fw';
import type { FwReport, FwTable } from '../report-types';
import type { Panel, PanelContext } from './panel';

/** The input pulab computes the "fw" section from: the plain report input and analysis.fw. */
export function fwInput(inp: Input): Input {
  const eff = effectiveInput(inp);
  const fw = inp.analysis?.fw;
  return { ...reportInput(eff), analysis: { fw: fw && typeof fw === 'object' && !Array.isArray(fw) ? fw : {} } };
}

class FwView {
  key = '';
  fw: FwReport | null = null;
  error: string | null = null;
  pending = false;
  /** Asked only while the panel is (nearly) on screen: the envelope costs about a second of the
   * report runtime, which the other panels' reports must not wait behind on every keystroke. */
  shown = typeof IntersectionObserver === 'undefined';
  private ctx: PanelContext | null = null;

  constructor(el: HTMLElement) {
    if (this.shown) return;
    new IntersectionObserver((entries) => {
      this.shown = entries.some((e) => e.isIntersecting);
      if (this.shown && this.ctx) this.ask(el, this.ctx);
    }, { rootMargin: '300px' }).observe(el);
  }

  ask(el: HTMLElement, ctx: PanelContext): void {
    this.ctx = ctx;
    if (!ctx.client || !this.shown) return;
    const req = fwInput(ctx.input);
    const key = JSON.stringify(req);
    if (key === this.key) return;
    this.key = key;
    this.pending = true;
    void ctx.client.call('report', req, 'fw').then(({ result }) => {
      if (key !== this.key) return;
      this.pending = false;
      if (result.ok) {
        this.fw = result.report.fw ?? null;
        this.error = null;
        ctx.fieldError?.('fw', null);
      } else {
        // the numbers of an earlier input are not left beside the message
        this.fw = null;
        this.error = `${result.field}: ${errText(result)}`;
        ctx.fieldError?.('fw', result);
      }
      fwPanel.render(el, ctx);
    }, () => undefined);
  }
}

const views = new WeakMap<HTMLElement, FwView>();

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
    if (!v) views.set(el, (v = new FwView(el)));
    v.ask(el, ctx);
    const fw = v.fw;
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
