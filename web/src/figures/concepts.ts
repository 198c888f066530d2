// The course's concept figures, drawn as SVG from the reader's report: Clarke with k = 2/3 vs √2/3,
// the PLL block diagram (the source's lost figure 2.2-1), the Q-format bit layout, and the current
// loop with the places where I_b and U_b enter. `{{figure:NAME}}` in a chapter (docs/render.ts).
// Every number from the report is a <tspan> with data-key/data-value, like the rest of the page.
import { fmtNum } from '../format';
import { getLang } from '../i18n';

export const FIGURES = ['clarke', 'pll', 'qbits', 'current-loop'] as const;
export type FigureName = (typeof FIGURES)[number];

type Value = (path: string) => unknown;

const esc = (s: string): string => s.replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/>/g, '&gt;').replace(/"/g, '&quot;');
const L = (en: string, zh: string): string => esc(getLang() === 'zh' ? zh : en);

/** A report number inside SVG text: the shown digits, with its path and full value. */
function num(value: Value, path: string, digits = 4): string {
  const v = value(path);
  if (typeof v !== 'number') return '<tspan>…</tspan>';
  return `<tspan class="fig-num" data-key="${esc(path)}" data-value="${esc(JSON.stringify(v))}">${esc(fmtNum(v, digits))}</tspan>`;
}

function text(x: number, y: number, body: string, cls = '', anchor = 'middle'): string {
  return `<text x="${x}" y="${y}" text-anchor="${anchor}"${cls ? ` class="${cls}"` : ''}>${body}</text>`;
}

function box(x: number, y: number, w: number, hgt: number, lines: string[], cls = 'fig-box'): string {
  const t = lines.map((l, i) => text(x + w / 2, y + hgt / 2 + (i - (lines.length - 1) / 2) * 15 + 4, l)).join('');
  return `<rect x="${x}" y="${y}" width="${w}" height="${hgt}" rx="5" class="${cls}"/>${t}`;
}

const arrow = (x1: number, y1: number, x2: number, y2: number, cls = 'fig-line'): string =>
  `<line x1="${x1}" y1="${y1}" x2="${x2}" y2="${y2}" class="${cls}" marker-end="url(#fig-arrow)"/>`;

function svg(w: number, hgt: number, label: string, body: string): string {
  return `<svg viewBox="0 0 ${w} ${hgt}" width="${w}" height="${hgt}" role="img" aria-label="${esc(label)}" xmlns="http://www.w3.org/2000/svg">`
    + '<defs><marker id="fig-arrow" viewBox="0 0 10 10" refX="9" refY="5" markerUnits="userSpaceOnUse" markerWidth="9" markerHeight="9" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" class="fig-head"/></marker></defs>'
    + `${body}</svg><figcaption>${esc(label)}</figcaption>`;
}

/** abc axes, and the αβ vector of a balanced current at rated RMS with both Clarke coefficients. */
function clarke(value: Value): string {
  const cx = 150;
  const cy = 150;
  const axes = [0, 120, 240].map((deg, i) => {
    const a = (deg * Math.PI) / 180;
    const x = cx + 120 * Math.cos(a);
    const y = cy - 120 * Math.sin(a);
    return `<line x1="${cx}" y1="${cy}" x2="${x}" y2="${y}" class="fig-axis"/>${text(cx + 135 * Math.cos(a), cy - 135 * Math.sin(a) + 4, 'abc'[i])}`;
  }).join('');
  // lengths in the drawing: peak = 100 px, RMS = 100/√2 px (the ratio is exact, the scale arbitrary)
  const peak = 100;
  const rms = peak / Math.SQRT2;
  const ang = (35 * Math.PI) / 180;
  // the same current vector drawn twice, side by side (offset across its direction)
  const vec = (len: number, off: number, cls: string) => {
    const ox = -off * Math.sin(ang);
    const oy = -off * Math.cos(ang);
    return arrow(cx + ox, cy + oy, cx + ox + len * Math.cos(ang), cy + oy - len * Math.sin(ang), cls);
  };
  return svg(560, 300, L('Clarke transform: k = 2/3 vs √2/3', '克拉克变换：k = 2/3 与 √2/3'),
    axes + text(cx + 112, cy + 20, 'α', 'fig-greek') + text(cx - 8, cy - 122, 'β', 'fig-greek')
    + `<line x1="${cx - 125}" y1="${cy}" x2="${cx + 125}" y2="${cy}" class="fig-axis faint"/><line x1="${cx}" y1="${cy + 125}" x2="${cx}" y2="${cy - 125}" class="fig-axis faint"/>`
    + vec(peak, 6, 'fig-line a') + vec(rms, -6, 'fig-line b')
    + text(300, 60, L('k = 2/3 (amplitude-invariant):', 'k = 2/3（等幅值）：'), 'fig-a', 'start')
    + text(300, 80, `|i<tspan baseline-shift="sub" font-size="10">αβ</tspan>| = ${L('phase peak', '相峰值')} = √2·${num(value, 'base.I_b')} A`, 'fig-a', 'start')
    + text(300, 120, L('k = √2/3 (RMS, Inovance):', 'k = √2/3（有效值，汇川）：'), 'fig-b', 'start')
    + text(300, 140, `|i<tspan baseline-shift="sub" font-size="10">αβ</tspan>| = ${L('phase RMS', '相有效值')} = ${num(value, 'base.I_b')} A`, 'fig-b', 'start')
    + text(300, 180, `|x<tspan baseline-shift="sub" font-size="10">αβ</tspan>| = (3/2)·k·x̂<tspan baseline-shift="sub" font-size="10">${L('phase', '相')}</tspan>`, '', 'start')
    + text(300, 200, L('Park rotates αβ by θ: lengths unchanged.', '派克变换把 αβ 旋转 θ：长度不变。'), '', 'start')
    + text(300, 220, L('Power: 3/2·(u_d i_d + u_q i_q) or 3·(…)', '功率：3/2·(u_d i_d + u_q i_q) 或 3·(…)'), '', 'start'));
}

/** The PLL: angle error → PI (per unit) → speed → integrator ω_b/θ_b → angle, fed back. */
function pll(value: Value): string {
  return svg(640, 190, L('PLL block diagram', '锁相环框图'),
    text(20, 74, 'θ', 'fig-greek', 'start') + arrow(34, 70, 74, 70)
    + `<circle cx="84" cy="70" r="10" class="fig-box"/>` + text(84, 74, '−') + text(70, 98, '+', '', 'middle')
    + arrow(94, 70, 140, 70) + text(117, 62, 'Δθ*')
    + box(140, 40, 170, 60, [L('PI (per unit)', 'PI（标幺）'), `kₚ* = ${num(value, 'pll.kp_pu')}`, `kᵢ* = ${num(value, 'pll.ki_pu')} s⁻¹`])
    + arrow(310, 70, 370, 70) + text(340, 62, 'ω̂*')
    + box(370, 40, 150, 60, [L('integrator', '积分器'), `ω_b/θ_b = ${num(value, 'pll.integrator_gain')} s⁻¹`, '1/s'])
    + arrow(520, 70, 600, 70) + text(612, 74, 'θ̂*', 'fig-greek')
    + `<polyline points="570,70 570,150 84,150 84,84" class="fig-line" marker-end="url(#fig-arrow)" fill="none"/>`
    + text(330, 170, L('θ_b = π: an int16 angle with 32768 ↔ π wraps once per turn by itself.', 'θ_b = π：32768 对应 π 的 int16 角度每转一圈自己回绕一次。')));
}

/** A 16-bit word as bits: the reader's LD (Q13 in a Uint16) and a Q12 current in an int16. */
function qbits(value: Value): string {
  const row = (y: number, raw: number, q: number, signed: boolean, title: string, shown: string): string => {
    const bits = (raw & 0xffff).toString(2).padStart(16, '0');
    const cells = [...bits].map((b, i) => {
      const pos = 15 - i;
      const cls = signed && pos === 15 ? 'fig-bit sign' : pos >= q ? 'fig-bit int' : 'fig-bit frac';
      return `<rect x="${20 + i * 34}" y="${y}" width="32" height="28" class="${cls}"/>${text(37 + i * 34, y + 19, b)}${text(37 + i * 34, y + 42, String(pos), 'fig-small')}`;
    }).join('');
    return text(20, y - 8, title, '', 'start') + cells
      + text(584, y + 19, `= ${shown}`, '', 'start');
  };
  const ld = value('vendor.LD.value');
  return svg(700, 200, L('Q-format bit layout', 'Q 格式的位布局'),
    (typeof ld === 'number' ? row(30, ld, 13, false, L('gMotorExtPer.LD: Uint16, Q13 (3 integer bits, 13 fraction bits)', 'gMotorExtPer.LD：Uint16，Q13（3 位整数，13 位小数）'), num(value, 'vendor.LD.value', 6)) : '')
    + row(120, 4096, 12, true, L('1.0 p.u. current: int16, Q12 (sign, 3 integer bits, 12 fraction bits)', '1.0 p.u. 电流：int16，Q12（符号位，3 位整数，12 位小数）'), '4096')
    + `<rect x="20" y="178" width="14" height="12" class="fig-bit sign"/>${text(40, 188, L('sign', '符号'), 'fig-small', 'start')}`
    + `<rect x="90" y="178" width="14" height="12" class="fig-bit int"/>${text(110, 188, L('integer', '整数'), 'fig-small', 'start')}`
    + `<rect x="170" y="178" width="14" height="12" class="fig-bit frac"/>${text(190, 188, L('fraction: 2⁻¹ … 2⁻ⁿ', '小数：2⁻¹ … 2⁻ⁿ'), 'fig-small', 'start')}`);
}

/** The current loop in SI around the firmware's integer PI: ÷I_b into Q12, ×U_b out of Q12. */
function currentLoop(value: Value): string {
  return svg(700, 220, L('Current loop: where I_b and U_b enter', '电流环：I_b 与 U_b 在哪里进入'),
    text(14, 64, 'i_ref', '', 'start') + arrow(50, 60, 78, 60)
    + box(78, 35, 96, 50, [`÷ I_b · 2¹²`, `I_b = ${num(value, 'base.I_b')} A`], 'fig-box scale')
    + arrow(174, 60, 204, 60)
    + `<circle cx="214" cy="60" r="10" class="fig-box"/>` + text(214, 64, '−')
    + arrow(224, 60, 250, 60) + text(237, 50, 'Q12')
    + box(250, 30, 150, 60, [L('integer PI', '整数 PI'), `pm_kp = ${num(value, 'current_pi.d.pm_kp', 6)} (Q12)`, `pm_ki = ${num(value, 'current_pi.d.pm_ki', 6)} (Q16)`])
    + arrow(400, 60, 460, 60) + text(430, 52, 'pm_ud')
    + box(460, 35, 100, 50, [`× U_b / 2¹²`, `U_b = ${num(value, 'base.U_b')} V`], 'fig-box scale')
    + arrow(560, 60, 580, 60)
    + box(580, 35, 100, 50, [L('motor', '电机'), '1/(R_s + sL)'], 'fig-box plant')
    + `<polyline points="680,60 692,60 692,158 400,158" class="fig-line" fill="none" marker-end="url(#fig-arrow)"/>`
    + box(300, 135, 100, 46, [`÷ I_b · 2¹²`, L('feedback, Q12', '反馈，Q12')], 'fig-box scale')
    + `<polyline points="300,158 214,158 214,72" class="fig-line" fill="none" marker-end="url(#fig-arrow)"/>` + text(686, 176, 'i', 'fig-greek')
    + text(350, 205, L('The PI never sees amperes or volts: both bases are outside it, so its integers depend on I_b/U_b.', 'PI 从不接触安培和伏特：两个基值都在它外面，所以它的整数取决于 I_b/U_b。')));
}

const DRAW: Record<FigureName, (v: Value) => string> = { clarke, pll, qbits, 'current-loop': currentLoop };

export function isFigure(name: string): name is FigureName {
  return (FIGURES as readonly string[]).includes(name);
}

/** The figure's SVG in the current language with the reader's numbers. */
export function drawFigure(name: FigureName, value: Value): string {
  return DRAW[name](value);
}
