import { h, num, patch, tex } from '../dom';
import { t, type Key } from '../i18n';
import type { PiAxis, Report, SimCurrent, SimEvent } from '../generated/report-types';
import { vendorName } from '../vendors';
import { fixedRun, renderCurrentStep } from '../figures/current-step';
import { keptFigure, simPlaceholder } from '../figures/figure';
import { shippedProfile } from '../page/answer';
import { metricsTable, type MetricColumn, type MetricRow } from './metrics';
import { hardwareTyped } from './vendors';
import type { Panel } from './panel';
import { traceTable } from './vendor';

const DESIGN = (): Record<string, string> => ({
  bandwidth: 'k_p = \\omega_c L,\\quad k_i = \\omega_c R_s,\\quad \\omega_c = 2\\pi f_{bw}',
  damping: 'k_p = 2\\zeta\\omega_0 L - R_s,\\quad k_i = \\omega_0^2 L',
  manual: `k_p,\\ k_i\\ \\text{${t('texGiven')}}`,
  integers: `\\text{pm\\_kp},\\ \\text{pm\\_ki}\\ \\text{${t('texGiven')}} \\Rightarrow k_p = \\frac{\\text{pm\\_kp}}{2^{12}}\\frac{U_b}{I_b},\\ k_i = \\frac{\\text{pm\\_ki}}{2^{16}T_s}\\frac{U_b}{I_b}`,
});

function axisRow(a: 'd' | 'q', g: PiAxis | undefined): HTMLElement {
  const p = `current_pi.${a}`;
  return h(
    'tr',
    {},
    h('th', {}, a),
    h('td', { class: 'r' }, num(`${p}.kp`, g?.kp)),
    h('td', { class: 'r' }, num(`${p}.ki`, g?.ki)),
    h('td', { class: 'r sep' }, num(`${p}.kp_pu`, g?.kp_pu)),
    h('td', { class: 'r' }, num(`${p}.ki_pu`, g?.ki_pu)),
    h('td', { class: 'r sep' }, num(`${p}.pm_kp`, g?.pm_kp, { kind: 'int' }), h('br'), g ? num(`${p}.pm_kp`, g.pm_kp, { kind: 'hex', type: 'long' }) : ''),
    h('td', { class: 'r' }, num(`${p}.pm_ki`, g?.pm_ki, { kind: 'int' }), h('br'), g ? num(`${p}.pm_ki`, g.pm_ki, { kind: 'hex', type: 'long' }) : ''),
    h('td', { class: 'r sep' }, num(`${p}.from_integers.kp`, g?.from_integers.kp)),
    h('td', { class: 'r' }, num(`${p}.from_integers.ki`, g?.from_integers.ki)),
    h('td', { class: 'r' }, num(`${p}.from_integers.bandwidth_hz`, g?.from_integers.bandwidth_hz)),
  );
}

const METRIC_ROWS: MetricRow[] = [
  { key: 'rise_time_s', label: 'riseTime', unit: 'ms', scale: 1e3 },
  { key: 'overshoot_pct', label: 'overshoot', unit: '%' },
  { key: 'settling_time_s', label: 'settling', unit: 'ms', scale: 1e3 },
  { key: 'steady_state_error_a', label: 'sse', unit: 'A' },
];
const EVENTS: SimEvent[] = ['feedback_saturate', 'wrap', 'saturate', 'integral_limit', 'output_limit'];

/** At the plot: why the shipped firmware has no fixed-point trace (the fields its panel names). */
function noTrace(sim: SimCurrent, fw: string, report: Report | null | undefined): HTMLElement | null {
  if (fixedRun(sim, fw)) return null;
  const run = sim.by_profile?.[fw];
  const fields = fw === 'inovance' ? (report?.firmware?.inovance?.problems ?? []).map((p) => p.field)
    : run && !run.ran && 'problems' in run ? run.problems.map((p) => p.field) : [];
  return h('p', { class: 'note bad-text sim-no-trace', role: 'status', 'data-firmware': fw },
    t('sf_cannot', { name: vendorName(fw), fields: [...new Set(fields)].join(', ') || '—' }));
}

/** The user's routine in the loop (sim.current.code): its distance from SI and from pulab's
 * integers, its clips, its first wrap or saturation and the inputs that started at 0. */
function codeNotes(sim: SimCurrent): HTMLElement[] {
  const c = sim.code;
  if (!c) return [];
  const p = 'sim.current.code';
  const fe = c.first_event;
  return [
    h('p', { class: 'note sim-code' }, `${t('cl_vs')}: `,
      num(`${p}.metrics.vs_si_max_abs_a`, c.metrics.vs_si_max_abs_a, { unit: 'A' }), ' = ',
      num(`${p}.metrics.vs_si_max_lsb`, c.metrics.vs_si_max_lsb, { sig: 4 }), ` ${t('sf_lsb')}`,
      ...(c.metrics.vs_fixed_max_abs_a === null ? [] : ['; ', `${t('cl_vs_fixed')}: `,
        num(`${p}.metrics.vs_fixed_max_abs_a`, c.metrics.vs_fixed_max_abs_a, { unit: 'A' })])),
    h('p', { class: 'note sim-code-events' }, `${t('cl_events')} `,
      num(`${p}.events.feedback_saturate`, c.events.feedback_saturate, { kind: 'int' }), `, ${t('cl_beyond')} `,
      num(`${p}.events.beyond_limit`, c.events.beyond_limit, { kind: 'int' }),
      fe ? ` ${t('cl_first', { call: fe.call, axis: fe.axis, line: fe.line, kind: fe.kind, name: fe.name })}` : ''),
    ...(c.zeroed.length ? [h('p', { class: 'note sim-code-zeroed' }, `${t('cl_zeroed')} `, h('code', {}, c.zeroed.join(', ')))] : []),
  ];
}

/** The shipped firmware's run below the table: its distance from SI and its wraps and saturations. */
function profileNotes(sim: SimCurrent, fw: string): (HTMLElement | null)[] {
  const run = sim.by_profile?.[fw];
  if (!run?.ran) return [];
  const name = vendorName(fw);
  const p = `sim.current.by_profile.${fw}`;
  return [
    hardwareTyped(fw) ? h('p', { class: 'note sim-hw-defaults' }, t('sf_hw_defaults', { name })) : null,
    h('p', { class: 'note' }, `${t('sf_vs_si', { name })}: `,
      num(`${p}.metrics.vs_si_max_abs_a`, run.metrics.vs_si_max_abs_a, { unit: 'A' }), ' = ',
      num(`${p}.metrics.vs_si_max_lsb`, run.metrics.vs_si_max_lsb, { sig: 4 }), ` ${t('sf_lsb')}`),
    h('p', { class: 'note sim-events' }, t('sf_events', { name }), ' ',
      ...EVENTS.flatMap((e, i) => [i ? ', ' : '', `${t(`sf_ev_${e}` as Key)} `, num(`${p}.events.${e}`, run.events[e], { kind: 'int' })])),
  ];
}

export const currentPanel: Panel = {
  id: 'current',
  usesSim: true,
  title: 'p_current',
  render(el, ctx) {
    const { report, simReport, input } = ctx;
    const pi = report?.current_pi;
    const method = pi?.method ?? String(input.current_loop?.method ?? 'bandwidth');
    const ex = pi?.step_example;
    const sim = simReport?.sim?.current;
    const axis = (String((input.sim?.current as Record<string, unknown> | undefined)?.axis ?? 'd') === 'q' ? 'q' : 'd') as 'd' | 'q';
    const fw = shippedProfile(ctx);
    const run = sim?.by_profile?.[fw];
    // The shipped firmware's column: Inovance's `metrics.fixed`, another's `by_profile` run.
    const fxMetrics = fw === 'inovance' ? (sim?.metrics.fixed as Record<string, unknown> | undefined) : run?.ran ? run.metrics : undefined;
    const extra: MetricColumn[] = fxMetrics ? [{ label: t('sf_fixed', { name: vendorName(fw) }),
      path: fw === 'inovance' ? 'sim.current.metrics.fixed' : `sim.current.by_profile.${fw}.metrics`, metrics: fxMetrics }] : [];
    if (sim?.code) extra.push({ label: t('cl_code'), path: 'sim.current.code.metrics', metrics: sim.code.metrics });
    patch(el, ...[
      h('div', { class: 'formulas' },
        tex(DESIGN()[method] ?? DESIGN().manual, true),
        tex('k_p^{pu} = k_p\\frac{I_b}{U_b},\\ k_i^{pu} = k_i\\frac{I_b}{U_b}\\ \\text{(2.1-4)}\\qquad \\text{pm\\_kp} = \\mathrm{round}(k_p^{pu}\\,2^{12}),\\ \\text{pm\\_ki} = \\mathrm{round}(k_i^{pu}\\,T_s\\,2^{16})\\ \\text{(2.2-9)}', true)),
      h('table', { class: 'grid pi' },
        h('thead', {},
          h('tr', {}, h('th', {}), h('th', { colspan: 2 }, t('siGains')), h('th', { colspan: 2, class: 'sep' }, t('puGains')), h('th', { colspan: 2, class: 'sep' }, t('intGains')), h('th', { colspan: 3, class: 'sep' }, t('backGains'))),
          h('tr', {}, h('th', {}, t('axis')), h('th', {}, 'kp [Ω]'), h('th', {}, 'ki [Ω/s]'), h('th', { class: 'sep' }, 'kp_pu'), h('th', {}, 'ki_pu [1/s]'), h('th', { class: 'sep' }, 'pm_kp (Q12)'), h('th', {}, 'pm_ki (Q16·Ts)'), h('th', { class: 'sep' }, 'kp [Ω]'), h('th', {}, 'ki [Ω/s]'), h('th', {}, `${t('impliedBw')} [Hz]`))),
        h('tbody', {}, axisRow('d', pi?.d), axisRow('q', pi?.q))),
      h('h3', {}, t('plotCurrent')),
      // the routine put into the loop could not run: the plot below is the last input's
      ctx.simError?.startsWith('sim.current.code') ? h('p', { class: 'err sim-code-err', role: 'alert' }, ctx.simError) : null,
      sim ? noTrace(sim, fw, report) : null,
      h('div', { class: 'figure', 'data-keep': 'current-step' }),
      sim ? metricsTable('sim.current.metrics', sim.metrics, ['si', 'pu'], METRIC_ROWS, extra) : null,
      sim && fw === 'inovance' ? h('p', { class: 'note' }, `${t('fixedVsSi')}: `,
        num('sim.current.metrics.fixed_vs_si_max_abs_a', sim.metrics.fixed_vs_si_max_abs_a, { unit: 'A' }), ' = ',
        num('sim.current.metrics.fixed_vs_si_max_lsb', sim.metrics.fixed_vs_si_max_lsb, { unit: 'LSB (Q12)' }),
        '; ', h('span', { class: sim.metrics.fixed_wraps ? 'flag-wrap' : '' }, `${t('fixedWraps')}: `,
          num('sim.current.metrics.fixed_wraps', sim.metrics.fixed_wraps, { kind: 'int' }))) : null,
      ...(sim ? profileNotes(sim, fw) : []),
      ...(sim ? codeNotes(sim) : []),
      ex ? h('div', { class: 'step-example' }, h('h3', {}, t('stepExample', { e: ex.error })), traceTable('current_pi.step_example.trace', ex.trace)) : null,
    ]);
    keptFigure(el, 'current-step', sim, (fig) => renderCurrentStep(fig, sim!, axis, ctx.report?.input.drive?.ts_s as number | undefined, fw), () => simPlaceholder(ctx));
  },
};
