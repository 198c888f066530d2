// The board: the sensing chain drawn as stages (shunt → amplifier → ADC → counts → per unit) with
// the number each arrow carries, then the bus and the PWM timer. Every number is the report's
// `board.*` (pulab.model.board); the page computes none.
import { h, num, patch, table, tex } from '../dom';
import { t } from '../i18n';
import type { Panel } from './panel';
import type { BoardRow, Report } from '../generated/report-types';
import { vendorName, type Vendor } from '../vendors';

type Row = BoardRow | null | undefined;

function stage(title: string, ...body: (Node | string | null)[]): HTMLElement {
  return h('div', { class: 'chain-stage' }, h('div', { class: 'chain-title' }, title), ...body);
}

function arrow(...label: (Node | string | null)[]): HTMLElement {
  return h('div', { class: 'chain-arrow' }, h('span', { class: 'chain-label' }, ...label));
}

function currentChain(c: Row, given: Record<string, unknown>): HTMLElement {
  if (!c) return h('p', { class: 'note' }, t('boardNoCurrent'));
  const bits = given.adc_bits ?? 12;
  const ref = given.adc_ref_v ?? 3.3;
  const sensor = c.from === 'max_a'
    ? stage(t('boardTyped'), '± ', num('board.current.max_a', c.max_a, { unit: 'A', mirror: true }))
    : given.sensitivity_v_per_a != null
      ? stage(t('boardSensor'), num('input.board.current.sensitivity_v_per_a', given.sensitivity_v_per_a, { unit: 'V/A' }))
      : stage(t('boardShunt'), num('input.board.current.shunt_ohm', given.shunt_ohm, { unit: 'Ω' }), ' × ',
        given.gain != null ? num('input.board.current.gain', given.gain) : '1');
  return h('div', { class: 'chain' },
    stage(t('boardPhase'), '± ', num('board.current.max_a', c.max_a, { unit: 'A' })),
    arrow(c.sensitivity_v_per_a != null ? num('board.current.sensitivity_v_per_a', c.sensitivity_v_per_a, { unit: 'V/A' }) : '—'),
    sensor,
    arrow(`${ref} V`, given.bipolar === false ? ` (${t('boardUnipolar')})` : ` (${t('boardBipolar')})`),
    stage('ADC', `${bits} bit`),
    arrow(num('board.current.counts_per_a', c.counts_per_a, { unit: t('boardCountsPerA') })),
    stage(t('boardCounts'), num('board.current.a_per_count', c.a_per_count, { unit: t('boardAPerCount') })),
    arrow('÷ I_b'),
    stage(t('boardPu'), num('board.current.pu_per_count', c.pu_per_count, { unit: 'pu' }), h('br'),
      num('board.current.nm_per_count', c.nm_per_count, { unit: 'N·m' })),
  );
}

/** What the chosen firmware's header holds for this board, by the vendor's own names (the
 * Vendors view lists every vendor's). */
function vendorTables(report: Report): HTMLElement[] {
  return Object.entries(report.profiles ?? {}).filter(([, p]) => p.board?.length).map(([v, p]) =>
    h('div', {}, h('h3', {}, `${t('boardHVendor')}: ${vendorName(v as Vendor)}`),
      table([t('vd_const'), t('value'), t('vd_format'), t('vd_si')], (p.board ?? []).map((k) => {
        const c = p.constants[k];
        const at = `profiles.${v}.constants.${k}`;
        return [h('code', {}, k),
          num(`${at}.value`, c.value, c.real ? { sig: 10, mirror: true } : { kind: 'int', mirror: true }),
          c.format, num(`${at}.si`, c.si, { sig: 6, unit: c.unit, mirror: true })];
      }), 'board-vendor')));
}

export const boardPanel: Panel = {
  id: 'board',
  title: 'p_board',
  pure: true,
  render(el, { report }) {
    const b = report?.board;
    const given = (report?.input.board ?? {}) as Record<string, Record<string, unknown>>;
    if (!b) {
      patch(el, h('p', { class: 'note' }, t('boardNone')));
      return;
    }
    const bus = b.bus;
    const pwm = b.pwm;
    patch(el,
      h('p', { class: 'note' }, tex(`I_{max} = \\pm\\frac{V_{ref}}{2\\,R_{sh} G}\\ (\\text{${t('boardBipolarShort')}}),\\quad \\text{LSB} = \\frac{V_{ref}}{2^{n} R_{sh} G},\\quad U_{max} = \\frac{V_{ref}}{k_{div}}`)),
      h('h3', {}, t('boardHCurrent')),
      currentChain(b.current, given.current ?? {}),
      h('h3', {}, t('boardHBus')),
      bus ? table([t('quantity'), t('value')], [
        [t('boardBusMax'), num('board.bus.max_v', bus.max_v, { unit: 'V' })],
        [t('boardVPerCount'), num('board.bus.v_per_count', bus.v_per_count, { unit: 'V' })],
        [t('boardRatio'), num('board.bus.ratio', bus.ratio)],
      ], 'board-bus') : h('p', { class: 'note' }, t('boardNoBus')),
      h('h3', {}, t('boardHPwm')),
      pwm ? table([t('quantity'), t('value')], [
        [t('boardCtrl'), num('board.pwm.control_period_s', pwm.control_period_s, { unit: 's' })],
        [t('boardTicks'), num('board.pwm.period_counts', pwm.period_counts)],
        [t('boardRegister'), num('board.pwm.period_register', pwm.period_register, { kind: 'int' })],
        [t('boardFreqActual'), num('board.pwm.freq_actual_hz', pwm.freq_actual_hz, { unit: 'Hz' })],
        [t('boardDutyBits'), num('board.pwm.duty_bits', pwm.duty_bits, { unit: 'bit' })],
        [t('boardDeadCounts'), num('board.pwm.deadtime_counts', pwm.deadtime_counts)],
        [t('boardDeadV'), num('board.pwm.deadtime_error_v', pwm.deadtime_error_v, { unit: 'V' })],
      ], 'board-pwm') : h('p', { class: 'note' }, t('boardNoPwm')),
      ...(report ? vendorTables(report) : []),
    );
  },
};
