// Above base speed (report "fw"): the current plane — the current limit, the MTPA curve, the
// voltage limit at three speeds and the envelope's currents — and torque and power over speed.
// Every point is pulab's (pulab.analyses.envelope); the page only draws.
import { t } from '../i18n';
import type { FwReport } from '../generated/report-types';
import { COLORS, plotRaw } from './figure';

export function renderFwPlane(el: HTMLElement, fw: FwReport): void {
  const line = (x: number[], y: number[], name: string, color: string, dash = 'solid', width = 1.8): object =>
    ({ type: 'scatter', mode: 'lines', x, y, name, line: { color, dash, width } });
  const data: object[] = [
    line(fw.curves.circle.id_a, fw.curves.circle.iq_a, t('fwCircle'), '#57606a', 'dash', 1.4),
    line(fw.mtpa.map((p) => p.id_a), fw.mtpa.map((p) => p.iq_a), 'MTPA', COLORS.si, 'solid', 2.4),
    line(fw.envelope.map((p) => p.id_a), fw.envelope.map((p) => p.iq_a), t('fwEnvelopeCurrents'), COLORS.fixed, 'solid', 2.4),
    ...fw.curves.ellipses.map((e, k) => line(e.id_a, e.iq_a, t('fwEllipse', { rpm: Math.round(e.speed_rpm) }), ['#8250df', '#bf3989', '#cf222e'][k % 3], 'dot', 1.4)),
  ];
  const r = fw.current_limit_a * 1.15;
  plotRaw(el, data, {
    legend: { orientation: 'h', y: -0.2, x: 0 },
    xaxis: { title: { text: 'i_d [A]' }, range: [-r, r * 0.35], gridcolor: '#eaeef2', zerolinecolor: '#aaa' },
    yaxis: { title: { text: 'i_q [A]' }, range: [-0.05 * r, r], gridcolor: '#eaeef2', zerolinecolor: '#aaa', scaleanchor: 'x' },
  }, 420);
}

export function renderFwSpeed(el: HTMLElement, fw: FwReport): void {
  const s = fw.envelope.map((p) => p.speed_rpm);
  plotRaw(el, [
    { type: 'scatter', mode: 'lines', x: s, y: fw.envelope.map((p) => p.torque_nm), name: `${t('fwTorque')} [N·m]`, line: { color: COLORS.si, width: 2.2 } },
    { type: 'scatter', mode: 'lines', x: s, y: fw.envelope.map((p) => p.power_w), name: `${t('fwPower')} [W]`, yaxis: 'y2', line: { color: COLORS.fixed, width: 2.2 } },
  ], {
    legend: { orientation: 'h', y: 1.1, x: 0 },
    xaxis: { title: { text: `${t('fwSpeed')} [rpm]` }, gridcolor: '#eaeef2' },
    yaxis: { title: { text: 'T [N·m]' }, gridcolor: '#eaeef2', rangemode: 'tozero' },
    yaxis2: { title: { text: 'P [W]' }, overlaying: 'y', side: 'right', rangemode: 'tozero', showgrid: false },
    margin: { l: 64, r: 60, t: 10, b: 44 },
    shapes: [{ type: 'line', x0: fw.base_speed_rpm, x1: fw.base_speed_rpm, yref: 'paper', y0: 0, y1: 1, line: { color: '#8c959f', dash: 'dot', width: 1 } }],
  }, 340);
}
