// Loop design as firmware runs it: margins with the delay, the delay-aware design
// beside the continuous one, Bode plots, the PLL's scaled vs naive margins, the speed loop.
// The robustness view: the nominal integers on the drifted motor ("loop.robust").
// Everything shown comes from the report's "loop" section (sent with the simulation request).
import { h, num, patch, table } from '../dom';
import { t, type Key } from '../i18n';
import type { LoopReport, Margins, RobustAxis, RobustCase } from '../generated/report-types';
import { renderBode } from '../figures/bode';
import { COLORS, keptFigure, simPlaceholder } from '../figures/figure';
import { renderRobustBand, renderRobustHistogram, renderRobustMap, renderRobustStep } from '../figures/robust';
import { renderSpeedStep } from '../figures/speed-step';
import { metricsTable } from './metrics';
import type { Panel } from './panel';

const MARGIN_COLS: [keyof Margins, Key, string][] = [
  ['phase_margin_deg', 'pm', '°'],
  ['gain_margin_db', 'gm', 'dB'],
  ['crossover_hz', 'crossover', 'Hz'],
  ['phase_crossover_hz', 'phaseCrossover', 'Hz'],
  ['bandwidth_hz', 'bwCl', 'Hz'],
  ['spectral_radius', 'maxPole', ''],
];

/** One row of margins: every number with data-key = its path; a missing margin says "none". */
function marginCells(path: string, m: Margins | undefined): HTMLElement[] {
  const cells = MARGIN_COLS.map(([k]) => {
    const v = m?.[k];
    if (m && v === null) return h('span', { class: 'num', 'data-key': `${path}.${k}`, 'data-value': 'null' }, t('noValue'));
    return num(`${path}.${k}`, v, { sig: 4 });
  });
  const ok = m?.stable;
  cells.push(h('span', { class: ok ? 'ok' : 'bad-text', 'data-key': `${path}.stable`, 'data-value': JSON.stringify(ok ?? null) }, ok === undefined ? '…' : ok ? `✔ ${t('yes')}` : `✘ ${t('no')}`));
  return cells;
}

function marginsTable(rows: [string, string, Margins | undefined][], cls: string): HTMLElement {
  return table(
    [t('loopCase'), ...MARGIN_COLS.map(([, label, unit]) => `${t(label)}${unit ? ` [${unit}]` : ''}`), t('stable')],
    rows.map(([label, path, m]) => [label, ...marginCells(path, m)]),
    `margins ${cls}`,
  );
}

/** A figure slot the panel draws itself (kept across renders: keptFigure). */
function figure(name: string): HTMLElement {
  return h('div', { class: 'figure', 'data-figure': name, 'data-keep': name });
}

function currentSection(loop: LoopReport): HTMLElement[] {
  const c = loop.current;
  const rows: [string, string, Margins | undefined][] = [];
  for (const a of ['d', 'q'] as const) {
    rows.push([`${a}: ${t('loopYours')}`, `loop.current.${a}`, c[a]]);
    rows.push([`${a}: ${t('loopFirmware')}`, `loop.current.${a}.firmware`, c[a].firmware]);
    rows.push([`${a}: ${t('loopDesigned')}`, `loop.current.design.${a}`, c.design[a]]);
    rows.push([`${a}: ${t('loopDesignedFw')}`, `loop.current.design.${a}.firmware`, c.design[a].firmware]);
    rows.push([`${a}: ${t('loopContinuous')}`, `loop.current.design.${a}.continuous`, c.design[a].continuous]);
  }
  const d = c.design.d;
  const byPm = c.design.by === 'phase_margin';
  const cont = d.continuous as Margins & { phase_margin_error_deg: number | null; bandwidth_error_pct: number | null };
  const err = byPm
    ? num('loop.current.design.d.continuous.phase_margin_error_deg', cont.phase_margin_error_deg, { sig: 3, unit: '°' })
    : num('loop.current.design.d.continuous.bandwidth_error_pct', cont.bandwidth_error_pct, { sig: 3, unit: '%' });
  const note = h('p', { class: 'note design-note' },
    t('designNote', { what: byPm ? `${t('pm')} ${c.design.target}°` : `${t('bwCl')} ${c.design.target} Hz`, kp: '{kp}', ki: '{ki}', err: '{err}' })
      .split(/(\{kp\}|\{ki\}|\{err\})/)
      .map((part) => part === '{kp}' ? num('loop.current.design.d.kp', d.kp, { sig: 5 })
        : part === '{ki}' ? num('loop.current.design.d.ki', d.ki, { sig: 5 })
          : part === '{err}' ? err : part));
  return [
    h('h3', {}, t('loopCurrentTitle', { d: t(`o.${loop.delay}` as Key) })),
    marginsTable(rows, 'current'),
    note,
    h('h3', {}, t('bodeCurrent')),
    figure('bode-current'),
  ];
}

function pllSection(loop: LoopReport): HTMLElement[] {
  const p = loop.pll;
  return [
    h('h3', {}, t('pllMarginsTitle')),
    marginsTable([[t('pllCorrect'), 'loop.pll.correct', p.correct], [t('pllNaive'), 'loop.pll.naive', p.naive]], 'pll'),
    h('p', { class: 'note' },
      `${t('kpTsG')}: `, num('loop.pll.correct.kp_ts_gain', p.correct.kp_ts_gain, { sig: 4 }), ` (${t('pllCorrect')}), `,
      num('loop.pll.naive.kp_ts_gain', p.naive.kp_ts_gain, { sig: 4 }), ` (${t('pllNaive')}); `,
      t('boundary', { b: '' }), num('loop.pll.boundary_kp_ts_gain', p.boundary_kp_ts_gain, { sig: 6 })),
    h('h3', {}, t('bodePll')),
    figure('bode-pll'),
  ];
}

function speedSection(loop: LoopReport): HTMLElement[] {
  const s = loop.speed;
  if (!s) return [];
  const b = s.bases;
  const r = s.response;
  return [
    h('h3', {}, t('speedTitle')),
    table([t('mechBases'), t('value'), t('unit')], [
      ['ω_mb = ω_b/p', num('loop.speed.bases.w_mb', b.w_mb), 'rad/s'],
      ['n_mb', num('loop.speed.bases.n_mb_rpm', b.n_mb_rpm), 'r/min'],
      ['T_mb = P_b/ω_mb', num('loop.speed.bases.torque_nm', b.torque_nm), 'N·m'],
      ['K_t', num('loop.speed.bases.kt_nm_per_a', b.kt_nm_per_a), 'N·m/A'],
      ['H = J·ω_mb²/(2·P_b)', num('loop.speed.bases.inertia_constant_s', b.inertia_constant_s), 's'],
    ], 'speed-bases'),
    table([t('speedGains'), 'kp', 'ki'], [
      ['SI', h('span', {}, num('loop.speed.kp', s.kp), ' A·s/rad'), h('span', {}, num('loop.speed.ki', s.ki), ' A/rad')],
      ['pu', num('loop.speed.kp_pu', s.kp_pu), h('span', {}, num('loop.speed.ki_pu', s.ki_pu), ' 1/s')],
      ['Q12 / Q16·T_sp', num('loop.speed.pm_kp', s.pm_kp, { kind: 'int' }), num('loop.speed.pm_ki', s.pm_ki, { kind: 'int' })],
    ], 'speed-gains'),
    h('p', { class: 'note' }, t('speedFormats')),
    marginsTable([[t('loopYours'), 'loop.speed', s], [t('loopFirmware'), 'loop.speed.firmware', s.firmware]], 'speed'),
    h('h3', {}, t('speedResponse')),
    figure('speed-step'),
    r ? metricsTable('loop.speed.response.metrics', r.metrics, ['float', 'fixed'], [
      { key: 'rise_time_s', label: 'riseTime', unit: 'ms', scale: 1e3 },
      { key: 'overshoot_pct', label: 'overshoot', unit: '%' },
      { key: 'settling_time_s', label: 'settling', unit: 'ms', scale: 1e3 },
      { key: 'load_dip_rpm', label: 'loadDip', unit: 'r/min' },
    ]) : h('span'),
    r ? h('p', { class: 'note' }, `${t('fixedVsFloat')}: `, num('loop.speed.response.fixed_vs_float_max_rpm', r.fixed_vs_float_max_rpm, { unit: 'r/min', sig: 4 })) : h('span'),
    h('h3', {}, t('bodeSpeed')),
    figure('bode-speed'),
  ];
}

/** One row per case: where it is, the plant's drift, and each axis's phase and gain margin. */
function robustRow(label: string, path: string, c: RobustCase): (string | HTMLElement)[] {
  const axis = (a: 'd' | 'q', k: keyof RobustAxis): HTMLElement => {
    const v = c[a][k];
    if (v === null) return h('span', { class: 'num', 'data-key': `${path}.${a}.${k}`, 'data-value': 'null' }, t('noValue'));
    return num(`${path}.${a}.${k}`, v, { sig: 4 });
  };
  return [label, num(`${path}.temperature_c`, c.temperature_c, { sig: 4 }), num(`${path}.current_a`, c.current_a, { sig: 4 }),
    num(`${path}.udc_v`, c.udc_v, { sig: 4 }), num(`${path}.rs_ohm`, c.rs_ohm, { sig: 4 }), num(`${path}.lq_h`, c.lq_h, { sig: 4 }),
    axis('d', 'phase_margin_deg'), axis('q', 'phase_margin_deg'), axis('d', 'gain_margin_db'), axis('q', 'gain_margin_db')];
}

function robustSection(loop: LoopReport): HTMLElement[] {
  const r = loop.robust;
  if (!r) return [];
  const cfg = r.config;
  const hot = r.cases.map((c, k) => [c, k] as const).filter(([c]) => c.kind === 'corner' && c.temperature_c === cfg.temperature_c[1] && c.current_a > 0)[0];
  const rows = [robustRow(t('robustNominal'), 'loop.robust.cases.0', r.cases[0]!)];
  if (hot) rows.push(robustRow(`${cfg.temperature_c[1]} °C, I_peak`, `loop.robust.cases.${hot[1]}`, hot[0]));
  rows.push(robustRow(t('robustWorstPm'), 'loop.robust.worst', r.worst));
  rows.push(robustRow(t('robustWorstGm'), 'loop.robust.worst_gain', r.worst_gain));
  const band = r.safe_bandwidth_hz;
  const mc = r.monte_carlo;
  return [
    h('h3', { class: 'robust-title' }, t('robustTitle')),
    h('p', { class: 'note' }, t('robustNote', { t0: String(cfg.temperature_c[0]), t1: String(cfg.temperature_c[1]), ip: String(+cfg.peak_current_a.toPrecision(4)) })),
    h('p', { class: r.safe ? 'ok' : 'bad-text', 'data-key': 'loop.robust.safe', 'data-value': JSON.stringify(r.safe) }, r.safe ? `✔ ${t('robustSafe')}` : `✘ ${t('robustUnsafe')}`),
    table([t('robustCase'), 'T [°C]', 'I [A]', 'U_dc [V]', 'R_s [Ω]', 'L_q [H]', `${t('pm')} d [°]`, `${t('pm')} q [°]`, `${t('gm')} d [dB]`, `${t('gm')} q [dB]`], rows, 'robust-cases'),
    h('p', { class: 'note robust-band' }, `${t('robustBand', { pm: String(cfg.min_phase_margin_deg), gm: String(cfg.min_gain_margin_db) })}: `,
      ...(band ? [num('loop.robust.safe_bandwidth_hz.0', band[0], { sig: 4 }), ' – ', num('loop.robust.safe_bandwidth_hz.1', band[1], { sig: 4, unit: 'Hz' })]
        : [h('span', { class: 'bad-text', 'data-key': 'loop.robust.safe_bandwidth_hz', 'data-value': 'null' }, t('robustNoBand'))]),
      `; ${t('robustDesigned')}: `, num('loop.robust.designed_bandwidth_hz.q', r.designed_bandwidth_hz.q, { sig: 4, unit: 'Hz' })),
    h('p', { class: 'note' }, `${t('robustHeadroom')}: `, num('loop.robust.headroom.cold_pct', r.headroom.cold_pct, { sig: 3, unit: '%' }), ' / ',
      num('loop.robust.headroom.hot_pct', r.headroom.hot_pct, { sig: 3, unit: '%' })),
    h('h3', {}, t('robustBandPlot')),
    figure('robust-band'),
    h('h3', {}, t('robustMap')),
    figure('robust-map'),
    ...(r.step ? [h('h3', {}, t('robustStep', { a: r.step.axis })), figure('robust-step'),
      h('p', { class: 'note' }, `${t('overshoot')}: `, num('loop.robust.step.metrics.float.overshoot_pct', r.step.metrics.float.overshoot_pct, { sig: 3, unit: '%' }),
        ` (${t('variant_float')}), `, num('loop.robust.step.metrics.fixed.overshoot_pct', r.step.metrics.fixed?.overshoot_pct ?? null, { sig: 3, unit: '%' }),
        ` (${t('variant_fixed')}); ${t('fixedVsFloat')}: `, num('loop.robust.step.fixed_vs_float_max_a', r.step.fixed_vs_float_max_a, { sig: 3, unit: 'A' }))] : []),
    ...(mc ? [h('h3', {}, t('robustHist', { n: String(mc.samples), f: `${(100 * mc.fraction_below).toFixed(1)} %` })), figure('robust-hist')] : []),
  ];
}

function drawFigures(el: HTMLElement, loop: LoopReport): void {
  const rob = loop.robust;
  keptFigure(el, 'robust-band', rob, (fig) => renderRobustBand(fig, rob!));
  keptFigure(el, 'robust-map', rob, (fig) => renderRobustMap(fig, rob!));
  keptFigure(el, 'robust-step', rob?.step ? rob : undefined, (fig) => renderRobustStep(fig, rob!));
  keptFigure(el, 'robust-hist', rob?.monte_carlo ? rob : undefined, (fig) => renderRobustHistogram(fig, rob!));
  const bode = loop.bode;
  const cur = bode?.current;
  keptFigure(el, 'bode-current', cur, (fig) => renderBode(fig, cur!.f_hz, [
    { curve: cur!.open.d, name: `G_o,d ${t('loopYoursShort')}`, color: COLORS.si },
    { curve: cur!.closed.d, name: `T_d ${t('loopYoursShort')}`, color: COLORS.si, dash: 'dot' },
    { curve: cur!.open.d_design, name: `G_o,d ${t('loopDesignedShort')}`, color: COLORS.pu },
    { curve: cur!.closed.d_design, name: `T_d ${t('loopDesignedShort')}`, color: COLORS.pu, dash: 'dot' },
  ]));
  const pll = bode?.pll;
  keptFigure(el, 'bode-pll', pll, (fig) => renderBode(fig, pll!.f_hz, [
    { curve: pll!.open.correct, name: t('pllCorrect'), color: COLORS.si },
    { curve: pll!.open.naive, name: t('pllNaive'), color: COLORS.naive, dash: 'dash' },
  ]));
  const speed = bode?.speed;
  keptFigure(el, 'bode-speed', speed, (fig) => renderBode(fig, speed!.f_hz, [
    { curve: speed!.open, name: 'G_o', color: COLORS.si },
    { curve: speed!.closed, name: 'T', color: COLORS.si, dash: 'dot' },
  ]));
  const r = loop.speed?.response;
  keptFigure(el, 'speed-step', r, (fig) => renderSpeedStep(fig, r!));
}

export const loopPanel: Panel = {
  id: 'loop',
  title: 'p_loop',
  usesSim: true,
  render(el, ctx) {
    const loop = ctx.simReport?.loop;
    if (!loop) {
      el.replaceChildren(ctx.simError ? simPlaceholder(ctx) : h('div', { class: 'plot-placeholder' }, t('loopWaiting')));
      return;
    }
    patch(el, ...currentSection(loop), ...robustSection(loop), ...pllSection(loop), ...speedSection(loop));
    drawFigures(el, loop);
  },
};
