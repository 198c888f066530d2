// The Sweep panel: one or two inputs of the current motor over a range, every
// firmware integer's error and status, boundaries bisected in Python (pulab.analyses.sweep), worst cases
// that open as the current motor. Computed chunk by chunk in the worker, with progress and cancel.
import { h, num, table } from '../dom';
import { fmtToward } from '../format';
import { ALL_FIELDS, effectiveInput, fieldLabel, siUnit } from '../fields';
import { errText, getLang, t, type Key } from '../i18n';
import { encodeHash, getPath, type Input } from '../state';
import type { SweepAxis, SweepRequest } from '../generated/api-types';
import type { ApiErr } from '../protocol';
import { runChunks, type ChunkJob } from '../family/chunks';
import { appendPoints, STATUSES, type Plan, type Points, type Summary } from '../family/types';
import { renderSweep1d, renderSweep2d, STATUS_COLORS } from '../figures/sweep-plot';
import type { Panel, PanelContext } from './panel';

interface AxisForm { path: string; start: string; stop: string; n: string; scale: 'linear' | 'log' }

/** Points in the first worker call; later calls adapt (family/chunks.ts). */
const CHUNK = 40;

const st = {
  x: null as AxisForm | null,
  y: null as AxisForm | null,
  twoD: false,
  profile: 'inovance',
  show: 'vendor.LD',
  job: null as ChunkJob | null,
  done: 0,
  total: 0,
  error: null as ApiErr | null,
  plan: null as Plan | null,
  points: null as Points | null,
  summary: null as Summary | null,
  /** The finished run's line, translated at render time. */
  note: null as null | { key: Key; vars: Record<string, string | number> },
};

/** Numeric inputs a sweep can vary (the form's number fields, without the simulation's). */
export function sweepPaths(inp: Input): string[] {
  return ALL_FIELDS.filter((f) => (f.kind === 'number' || f.kind === 'int') && !f.path.startsWith('sim.') && (!f.enabled || f.enabled(inp))).map((f) => f.path);
}

/** A range's input as a choice: its form label and the SI unit its ends are typed in; the path
 * (what `--range`/`--x` take on the command line) as its tooltip. */
export function pathOption(path: string, selected: boolean): HTMLElement {
  const f = ALL_FIELDS.find((x) => x.path === path);
  const unit = siUnit(path);
  const text = f ? `${fieldLabel(f, getLang())}${unit ? `, ${unit}` : ''}` : path;
  return h('option', { value: path, selected, title: path }, text);
}

function defaultAxis(ctx: PanelContext, path: string, lo: number, hi: number, n: number): AxisForm {
  const v = Number(getPath(ctx.report?.input, path) ?? getPath(ctx.input, path) ?? 1);
  const fmt = (x: number) => String(Number(x.toPrecision(3)));
  return { path, start: fmt(v * lo), stop: fmt(v * hi), n: String(n), scale: 'log' };
}

/** The seed's Inovance code, and every profile the report carries (`profiles.NAME`). */
function profiles(ctx: PanelContext): string[] {
  const more = Object.keys(ctx.report?.profiles ?? {});
  return ['inovance', ...more.filter((p) => p !== 'inovance')];
}

function axisReq(a: AxisForm): SweepAxis {
  return { path: a.path, start: Number(a.start), stop: Number(a.stop), n: Number(a.n), scale: a.scale };
}

function request(input: Input): SweepRequest {
  const req: SweepRequest = { input, x: axisReq(st.x as AxisForm), profile: st.profile };
  if (st.twoD && st.y) req.y = axisReq(st.y);
  return req;
}

async function run(el: HTMLElement, ctx: PanelContext): Promise<void> {
  if (!ctx.client) return;
  const client = ctx.client;
  const req = request(effectiveInput(ctx.input));
  const job: ChunkJob = { cancelled: false };
  Object.assign(st, { job, done: 0, total: 0, error: null, plan: null, points: null, summary: null, note: null });
  sweepPanel.render(el, ctx);
  const { result } = await client.call('sweep.plan', req);
  if (!result.ok) {
    Object.assign(st, { job: null, error: result });
    return sweepPanel.render(el, ctx);
  }
  st.plan = result.plan;
  st.total = st.plan.total;
  if (!st.plan.names.includes(st.show)) st.show = st.plan.names[0];
  const summaries: Summary[] = [];
  const t0 = performance.now();
  const end = await runChunks(client, 'sweep.chunk', st.total, CHUNK, (start, count) => ({ ...req, start, count }), (r, done) => {
    const c = r.chunk;
    st.points = appendPoints(st.points, c.points);
    summaries.push(c.summary);
    st.done = done;
    progress(el);
  }, job);
  if (end !== 'done' && end !== 'cancelled') {
    Object.assign(st, { job: null, error: end });
    return sweepPanel.render(el, ctx);
  }
  if (summaries.length) {
    const m = await client.call('sweep.merge', { ...req, summaries });
    if (m.result.ok) st.summary = m.result.summary;
  }
  st.note = end === 'cancelled' ? { key: 'swCancelled', vars: { done: st.done, total: st.total } } : { key: 'swDone', vars: { n: st.total, s: ((performance.now() - t0) / 1000).toFixed(2) } };
  st.job = null;
  document.documentElement.dataset.sweepDone = String(st.done);
  sweepPanel.render(el, ctx);
}

function progress(el: HTMLElement): void {
  const bar = el.querySelector<HTMLProgressElement>('progress.sweep-progress');
  if (bar) {
    bar.max = st.total;
    bar.value = st.done;
  }
  const txt = el.querySelector('.sweep-count');
  if (txt) txt.textContent = `${st.done} / ${st.total}`;
}

function axisControls(which: 'x' | 'y', a: AxisForm, paths: string[], onChange: () => void): HTMLElement {
  const set = (k: Exclude<keyof AxisForm, 'scale'>) => (ev: Event) => {
    a[k] = (ev.target as HTMLInputElement).value;
    onChange();
  };
  const setScale = (ev: Event) => {
    a.scale = (ev.target as HTMLSelectElement).value === 'linear' ? 'linear' : 'log';
    onChange();
  };
  const err = (k: string) => (st.error && st.error.field === `sweep.${which}.${k}` ? errText(st.error) : '');
  const field = (label: string, control: HTMLElement, k: string) =>
    h('label', { class: 'field' }, h('span', { class: 'lbl' }, label), control, h('span', { class: 'err', 'data-err-for': `sweep.${which}.${k}` }, err(k)));
  return h('div', { class: 'sweep-axis' },
    field(t(which === 'x' ? 'swAxisX' : 'swAxisY'), h('select', { name: `sweep.${which}.path`, onchange: set('path') },
      paths.map((p) => pathOption(p, p === a.path))), 'path'),
    field(t('swStart'), h('input', { name: `sweep.${which}.start`, value: a.start, inputmode: 'decimal', oninput: set('start') }), 'start'),
    field(t('swStop'), h('input', { name: `sweep.${which}.stop`, value: a.stop, inputmode: 'decimal', oninput: set('stop') }), 'stop'),
    field(t('swPoints'), h('input', { name: `sweep.${which}.n`, value: a.n, inputmode: 'numeric', oninput: set('n') }), 'n'),
    field(t('swScale'), h('select', { name: `sweep.${which}.scale`, onchange: setScale },
      (['log', 'linear'] as const).map((s) => h('option', { value: s, selected: a.scale === s }, t(s === 'log' ? 'swLog' : 'swLinear')))), 'scale'));
}

const stChip = (s: string) => h('span', { class: `flag st-${s}`, style: `background:${STATUS_COLORS[s as keyof typeof STATUS_COLORS]};color:#fff` }, t(`st_${s}` as Key));
const zh = () => getLang() === 'zh';

function results(plan: Plan, pts: Points, sum: Summary): HTMLElement[] {
  const out: HTMLElement[] = [];
  const fig = h('div', { class: 'sweep-fig' });
  out.push(h('label', { class: 'field inline' }, h('span', { class: 'lbl' }, t('swShow')),
    h('select', { name: 'sweep.show', onchange: (ev: Event) => { st.show = (ev.target as HTMLSelectElement).value; draw(); } },
      plan.names.map((n) => h('option', { value: n, selected: n === st.show }, n)))), fig);
  const draw = () => (plan.y ? renderSweep2d(fig, plan, pts, sum, st.show) : renderSweep1d(fig, plan, pts, sum, st.show));
  queueMicrotask(draw);
  const bs = sum.boundaries;
  const shown = bs.slice(0, 200);
  out.push(h('h3', {}, t('swBoundaries'), ` (${bs.length})`), h('p', { class: 'hint' }, t('swBoundariesHint')),
    h('div', { class: 'scroll' }, table([t('swInteger'), t('swChange'), t('swAt'), t('swBefore'), plan.y ? t('swOther') : null, t('swRaw')].filter((x): x is string => x !== null),
      shown.map((b, i) => h('tr', {},
        h('td', {}, h('code', {}, b.name)),
        h('td', {}, stChip(b.from), ' → ', stChip(b.to)),
        h('td', { class: 'r' }, h('span', {}, `${b.path} = `, num(`sweep.summary.boundaries.${i}.at`, b.at, { text: fmtToward(b.at, b.before) }))),
        h('td', { class: 'r' }, num(`sweep.summary.boundaries.${i}.before`, b.before, { text: fmtToward(b.before, b.at) })),
        plan.y ? h('td', { class: 'r' }, num(`sweep.summary.boundaries.${i}.other`, b.other, { sig: 6 })) : null,
        h('td', {}, Object.entries({ ...b.raw, ...b.intermediates }).map(([k, [a, c]]) => `${k} ${a} → ${c}`).join(', '),
          b.message ? h('div', { class: 'hint' }, zh() ? b.message_zh ?? b.message : b.message) : null))),
      'sweep-bounds')));
  if (bs.length > shown.length) out.push(h('p', { class: 'hint' }, t('swMore', { n: bs.length - shown.length })));
  out.push(h('h3', {}, t('swWorst')), h('p', { class: 'hint' }, t('swWorstHint')),
    h('div', { class: 'scroll' }, table([t('swInteger'), t('swStatus'), t('error'), t('value'), t('swWhere'), ''],
      sum.worst.map((w) => h('tr', { class: w.status === 'ok' ? '' : 'bad' },
        h('td', {}, h('code', {}, w.name)), h('td', {}, stChip(w.status)),
        h('td', { class: 'r' }, num(`sweep.summary.worst.${w.name}.error_pct`, w.error_pct, { kind: 'pct' })),
        h('td', { class: 'r' }, num(`sweep.summary.worst.${w.name}.value`, w.value, { kind: 'int' })),
        h('td', {}, `${plan.x.path} = ${w.x}`, plan.y ? `, ${plan.y.path} = ${w.y}` : ''),
        h('td', {}, h('a', { href: encodeHash(w.input as Input), class: 'open-motor', 'data-open-worst': w.name }, t('swOpen'))))), 'sweep-worst')));
  out.push(h('h3', {}, t('swCounts')),
    h('div', { class: 'scroll' }, table([t('swInteger'), ...STATUSES.map((s) => t(`st_${s}` as Key)), '≥ 0.1 %', '≥ 1 %', '≥ 5 %', `max |${t('error')}|`],
      plan.names.map((n) => {
        const p = sum.per_integer[n];
        return [h('code', {}, n), ...STATUSES.map((s) => String(p.counts[s])), String(p.over_pct['0.1']), String(p.over_pct['1']), String(p.over_pct['5']),
          num(`sweep.summary.per_integer.${n}.max_abs_error_pct`, p.max_abs_error_pct, { kind: 'pct' })];
      }), 'sweep-counts')));
  return out;
}

export const sweepPanel: Panel = {
  id: 'sweep',
  title: 'p_sweep',
  needsPython: true,
  render(el, ctx) {
    if (!st.x) st.x = defaultAxis(ctx, 'motor.rated_current_a', 0.1, 100, 400);
    if (!st.y) st.y = { ...defaultAxis(ctx, 'motor.rated_voltage_v', 0.1, 10, 30) };
    // Typing in the motor re-renders every panel; the sweep's DOM (form, plots) is rebuilt only
    // when the sweep's own state or the language changed.
    const key = [getLang(), !!ctx.client, !!st.job, JSON.stringify(st.note), st.twoD, st.error?.message ?? '', st.total].join('|');
    if (el.querySelector('.sweep') && el.dataset.rendered === key) return;
    const paths = sweepPaths(ctx.input);
    const running = st.job !== null;
    const go = () => void run(el, ctx);
    const otherErr = st.error && !st.error.field.startsWith('sweep.x.') && !st.error.field.startsWith('sweep.y.') ? `${st.error.field}: ${errText(st.error)}` : null;
    el.replaceChildren(h('div', { class: 'sweep' },
      h('p', { class: 'hint' }, t('swIntro')),
      h('label', { class: 'field inline' }, h('span', { class: 'lbl' }, t('swProfile')),
        h('select', { name: 'sweep.profile', onchange: (ev: Event) => { st.profile = (ev.target as HTMLSelectElement).value; } },
          profiles(ctx).map((p) => h('option', { value: p, selected: p === st.profile }, p)))),
      axisControls('x', st.x, paths, () => undefined),
      h('label', { class: 'field inline' }, h('input', { type: 'checkbox', name: 'sweep.twoD', checked: st.twoD, onchange: (ev: Event) => {
        st.twoD = (ev.target as HTMLInputElement).checked;
        sweepPanel.render(el, ctx);
      } }), ` ${t('swTwoD')}`),
      st.twoD ? axisControls('y', st.y, paths, () => undefined) : null,
      h('div', { class: 'sweep-run' },
        h('button', { type: 'button', class: 'run-sweep', disabled: running || !ctx.client, onclick: go }, t('swRun')),
        h('button', { type: 'button', class: 'cancel-sweep', disabled: !running, onclick: () => { if (st.job) st.job.cancelled = true; } }, t('swCancel')),
        h('progress', { class: 'sweep-progress', max: Math.max(1, st.total), value: st.done }),
        h('span', { class: 'sweep-count' }, st.total ? `${st.done} / ${st.total}` : ''),
        h('span', { class: 'hint sweep-note' }, st.note ? t(st.note.key, st.note.vars) : '')),
      otherErr ? h('p', { class: 'err' }, otherErr) : null,
      st.plan && st.points && st.summary ? results(st.plan, st.points, st.summary) : null));
    el.dataset.rendered = key;
  },
};
