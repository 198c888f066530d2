// The Prove panel: ranges of inputs of the current motor, and for every firmware integer a verdict
// over the whole box (pulab.analyses.prove) — proven with its range drawn against its C word, or
// violated with a motor that opens as the page input. Computed integer by integer in the worker,
// with progress and cancel.
import { h, keepFocus, num, table } from '../dom';
import { ALL_FIELDS, effectiveInput } from '../fields';
import { parseNumber } from '../format';
import { errText, getLang, t, type Key } from '../i18n';
import { encodeHash, getPath, type Input } from '../state';
import type { ApiErr } from '../protocol';
import type { Proof, Proposal, ProveEntry as Entry, ProveRequest, ProveVerdict as Verdict } from '../generated/api-types';
import type { Panel, PanelContext } from './panel';
import { pathOption, sweepPaths } from './sweep';

/** The profiles a proof covers (pulab.analyses.prove.PROFILES). */
const PROFILES = ['inovance', 'ti', 'nxp', 'st', 'microchip'] as const;
type Profile = (typeof PROFILES)[number];

/** One input's range; `typed`: the user typed an end, so it no longer follows the motor. */
interface RangeRow { path: string; lo: string; hi: string; typed?: boolean }

interface Job { cancelled: boolean }

const st = {
  /** Kept as one array of the same row objects: the fields' handlers hold them. */
  rows: null as RangeRow[] | null,
  profile: 'inovance' as Profile,
  job: null as Job | null,
  names: [] as string[],
  entries: {} as Record<string, Entry>,
  proof: null as Proof | null,
  proposal: null as Proposal | null,
  proposing: false,
  error: null as ApiErr | null,
  note: null as null | { key: Key; vars: Record<string, string | number> },
};

/** The channel of this panel's calls: the worker runs them slice by slice. */
const CHANNEL = 'prove';

/** 0.5× to 2× the motor's value at `path`: the report's echoed input first, as it holds the
 * values derived from a datasheet (rated voltage from the DC bus, …), then the value the report
 * derived for an input left empty (its form placeholder: f_b, a raw parameter); whole numbers for an
 * integer input. */
function defaultRow(ctx: PanelContext, path: string): RangeRow {
  const f = ALL_FIELDS.find((x) => x.path === path);
  const derived = f?.placeholderFrom ? getPath(ctx.report, f.placeholderFrom) : undefined;
  const v = Number(getPath(ctx.report?.input, path) ?? getPath(ctx.input, path) ?? derived ?? 1);
  const fmt = (x: number) => String(Number(x.toPrecision(3)));
  if (f?.kind === 'int') return { path, lo: String(Math.floor(v / 2)), hi: String(Math.ceil(v * 2)) };
  return { path, lo: fmt(v / 2), hi: fmt(v * 2) };
}

/** The inputs a family proof can range over: pulab.schema.inputs.SECTIONS (not the datasheet's,
 * which are converted once, nor the analyses'). */
function provePaths(inp: Input): string[] {
  return sweepPaths(inp).filter((p) => /^(motor|drive|conventions|current_loop|pll|raw)\./.test(p));
}

/** A range end as the form reads a number (full-width digits, 1,5); anything else as typed,
 * for pulab to name in its message at the row ("must be a number, got 'abc'"). */
function end(text: string): number | string {
  const p = parseNumber(text);
  return p.ok && p.value !== null ? p.value : text.trim();
}

function request(input: Input): ProveRequest {
  const ranges: ProveRequest['ranges'] = {};
  for (const r of st.rows ?? []) ranges[r.path] = [end(r.lo), end(r.hi)];
  return { input, ranges, profile: st.profile };
}

async function run(el: HTMLElement, ctx: PanelContext): Promise<void> {
  if (!ctx.client) return;
  const client = ctx.client;
  const req = request(effectiveInput(ctx.input));
  const job: Job = { cancelled: false };
  Object.assign(st, { job, names: [], entries: {}, proof: null, proposal: null, error: null, note: null });
  delete document.documentElement.dataset.proveDone;
  provePanel.render(el, ctx);
  const t0 = performance.now();
  const fail = (e: ApiErr) => {
    Object.assign(st, { job: null, error: e });
    provePanel.render(el, ctx);
  };
  const plan = await client.call('prove.plan', req, CHANNEL);
  if (!plan.result.ok) return fail(plan.result);
  st.names = plan.result.plan.names;
  provePanel.render(el, ctx);
  for (const name of st.names) {
    if (job.cancelled) break;
    const r = await client.call('prove.integer', { ...req, name }, CHANNEL);
    if (!r.result.ok) return fail(r.result);
    st.entries[name] = r.result.integer;
    provePanel.render(el, ctx);
  }
  const done = Object.keys(st.entries).length;
  if (done === st.names.length) {
    const s = await client.call('prove.summary', { ...req, integers: st.entries }, CHANNEL);
    if (!s.result.ok) return fail(s.result);
    st.proof = s.result.proof;
    st.note = { key: 'prDone', vars: { n: done, s: ((performance.now() - t0) / 1000).toFixed(2) } };
  } else {
    st.note = { key: 'prCancelled', vars: { done, total: st.names.length } };
  }
  st.job = null;
  document.documentElement.dataset.proveDone = st.proof?.verdict ?? 'cancelled';
  provePanel.render(el, ctx);
}

async function propose(el: HTMLElement, ctx: PanelContext): Promise<void> {
  if (!ctx.client) return;
  Object.assign(st, { proposing: true, proposal: null, error: null });
  provePanel.render(el, ctx);
  const r = await ctx.client.call('prove.propose', request(effectiveInput(ctx.input)), CHANNEL);
  st.proposing = false;
  if (r.result.ok) st.proposal = r.result.proposal;
  else st.error = r.result;
  provePanel.render(el, ctx);
}

const pct = (key: string, v: number | null) => (v === null ? '—' : h('span', {}, '≤ ', num(key, v, { kind: 'pct' })));

/** The proposal in the vendor's own form: a table per constant, or TI's one GLOBAL_Q. */
function proposalView(p: Proposal): HTMLElement {
  const key = 'prove.proposal';
  const head = h('h4', {}, t('prpTitle', { form: t(`pform_${p.profile}` as Key) }));
  if (p.integers) {
    return h('div', { class: 'pr-proposal' }, head, h('p', { class: 'hint' }, t('prpHeadroom')),
      h('div', { class: 'scroll' }, table([t('prInteger'), t('prpBits'), t('prWorst')],
        Object.entries(p.integers).map(([n, e]) => h('tr', {}, h('td', {}, h('code', {}, n)),
          h('td', { class: 'r' }, num(`${key}.integers.${n}.headroom_bits`, e.headroom_bits, { kind: 'int' })),
          h('td', { class: 'r' }, e.worst_error_pct === null ? '—' : h('span', {}, e.error_bound ? '≤ ' : '', num(`${key}.integers.${n}.worst_error_pct`, e.worst_error_pct, { kind: 'pct' }))))),
        'prove-proposal')));
  }
  if (p.worst_error_pct !== undefined || p.global_q !== undefined) {
    return h('div', { class: 'pr-proposal' }, head,
      h('p', { 'data-key': `${key}.global_q`, 'data-value': JSON.stringify(p.global_q ?? null) },
        p.global_q === null ? t('prpNoGlobalQ') : t('prpGlobalQ', { q: p.global_q ?? '' })),
      p.worst_error_pct ? h('div', { class: 'scroll' }, table([t('prpConstant'), t('prpErr')],
        Object.entries(p.worst_error_pct).map(([n, v]) => h('tr', {}, h('td', {}, h('code', {}, n)), h('td', { class: 'r' }, pct(`${key}.worst_error_pct.${n}`, v)))),
        'prove-proposal')) : null);
  }
  const rows = Object.entries(p.constants ?? {}).map(([n, e]) => {
    const k = `${key}.constants.${n}`;
    if (!e) return h('tr', { class: 'bad' }, h('td', {}, h('code', {}, n)), h('td', { colspan: 4 }, '—'));
    if (!e.holds || !e.range) {
      return h('tr', { class: 'bad' }, h('td', {}, h('code', {}, n)),
        h('td', { colspan: 3 }, e.impossible && e.witnessed
          ? t('prpNone', { lo: e.witnessed[0].toPrecision(4), hi: e.witnessed[1].toPrecision(4) })
          : t('prpNotFound', { lo: e.real_range[0].toPrecision(4), hi: e.real_range[1].toPrecision(4) })),
        h('td', {}, e.current));
    }
    return h('tr', {}, h('td', {}, h('code', {}, n)),
      h('td', { 'data-key': `${k}.format`, 'data-value': JSON.stringify(e.format) }, h('code', {}, e.format)),
      h('td', { class: 'r' }, '[', num(`${k}.range.0`, e.range[0], { kind: 'int' }), ', ', num(`${k}.range.1`, e.range[1], { kind: 'int' }), ']'),
      h('td', { class: 'r' }, pct(`${k}.worst_error_pct`, e.worst_error_pct)),
      h('td', {}, e.current));
  });
  const verdicts = Object.values(p.confirmed ?? {});
  const confirmed = verdicts.length && verdicts.every((v) => v === 'proven') ? 'proven' : verdicts.includes('violated') ? 'violated' : 'unknown';
  return h('div', { class: 'pr-proposal' }, head,
    h('div', { class: 'scroll' }, table([t('prpConstant'), t('prpFormat'), t('prpInts'), t('prpErr'), t('prpNow')], rows, 'prove-proposal')),
    p.divisors && Object.keys(p.divisors).length ? h('p', { class: 'hint', 'data-proposal-divisors': JSON.stringify(p.divisors) },
      t('prpDivisors', { list: Object.entries(p.divisors).map(([d, v]) => `${d.toUpperCase()} = ${v}`).join(', '), verdict: t(`v_${confirmed}` as Key) })) : null);
}

const chip = (v: Verdict, name: string) => h('span', { class: `flag pr-${v}`, 'data-verdict-for': name }, t(`v_${v}` as Key));

/** The proven range as a bar inside the word's limits (linear; a sliver at least, so it shows);
 * the code proof's statements draw the same bar. */
export function bar(e: Pick<Entry, 'range' | 'word' | 'type' | 'verdict'>): HTMLElement | null {
  if (!e.range || !e.word) return null;
  const [w0, w1] = e.word;
  const span = w1 - w0;
  const left = ((e.range[0] - w0) / span) * 100;
  const width = Math.max(0.6, ((e.range[1] - e.range[0]) / span) * 100);
  return h('div', { class: 'pr-bar', title: `${e.type} [${w0}, ${w1}]` },
    h('span', { class: `pr-fill pr-${e.verdict}`, style: `left:${Math.min(left, 99.4)}%;width:${Math.min(width, 100 - Math.min(left, 99.4))}%` }));
}

function row(name: string, e: Entry | undefined): HTMLElement {
  if (!e) return h('tr', { class: 'pending' }, h('td', {}, h('code', {}, name)), h('td', { colspan: 5 }, '…'));
  const key = `prove.integers.${name}`;
  const why = e.verdict === 'violated'
    ? h('div', {}, `${t(`k_${e.kind}` as Key)}: `, h('code', {}, e.statement ?? ''),
      e.raw ? h('div', { class: 'hint' }, Object.entries(e.raw).map(([k, v]) => `${k} = ${v}`).join(', ')) : null,
      e.counterexample ? h('a', { href: encodeHash(e.counterexample), class: 'open-motor', 'data-open-ce': name }, t('prOpen')) : null)
    : e.verdict === 'unknown' ? t('prUnknownShare', { pct: (100 * e.proven_fraction).toFixed(1) }) : '';
  return h('tr', { class: e.verdict === 'proven' ? '' : 'bad' },
    h('td', {}, h('code', {}, name)),
    h('td', {}, chip(e.verdict, name)),
    h('td', { class: 'r' }, e.range ? h('span', {}, '[', num(`${key}.range.0`, e.range[0], { kind: 'int' }), ', ', num(`${key}.range.1`, e.range[1], { kind: 'int' }), ']') : '—'),
    h('td', { class: 'pr-bar-cell' }, bar(e)),
    h('td', { class: 'r' }, e.worst_error_pct === null ? '—' : h('span', {}, e.error_bound ? '≤ ' : '', num(`${key}.worst_error_pct`, e.worst_error_pct, { kind: 'pct' }))),
    h('td', { class: 'pr-why' }, why));
}

/** Whether the error is about row `path`: its range, or the input a range end makes invalid
 * (motor.rs_ohm at −5). */
function atRow(path: string): boolean {
  return !!st.error && (st.error.field === `prove.ranges.${path}` || st.error.field === path);
}

function rangeRows(el: HTMLElement, ctx: PanelContext): HTMLElement {
  const rows = st.rows as RangeRow[];
  const paths = provePaths(ctx.input);
  const err = (path: string) => (atRow(path) ? errText(st.error as ApiErr) : '');
  return h('div', { class: 'pr-ranges' }, rows.map((r, i) => {
    const set = (k: 'lo' | 'hi') => (ev: Event) => { r[k] = (ev.target as HTMLInputElement).value; r.typed = true; };
    return h('div', { class: 'pr-range' },
      h('select', { name: `prove.ranges.${i}.path`, 'aria-label': t('prPath'), onchange: (ev: Event) => {
        r.path = (ev.target as HTMLSelectElement).value;
        // Another input: its own default range, unless the user already typed this row's ends.
        if (!r.typed) { Object.assign(r, defaultRow(ctx, r.path)); provePanel.render(el, ctx); }
      } },
        paths.map((p) => pathOption(p, p === r.path))),
      h('label', {}, t('prLo'), ' ', h('input', { name: `prove.ranges.${i}.lo`, value: r.lo, inputmode: 'decimal', oninput: set('lo') })),
      h('label', {}, t('prHi'), ' ', h('input', { name: `prove.ranges.${i}.hi`, value: r.hi, inputmode: 'decimal', oninput: set('hi') })),
      h('button', { type: 'button', class: 'pr-remove', disabled: rows.length < 2, onclick: () => { rows.splice(i, 1); provePanel.render(el, ctx); } }, t('prRemove')),
      h('span', { class: 'err', 'data-err-for': `prove.ranges.${r.path}` }, err(r.path)));
  }), h('button', { type: 'button', class: 'pr-add', onclick: () => {
    const used = new Set(rows.map((r) => r.path));
    rows.push(defaultRow(ctx, paths.find((p) => !used.has(p)) ?? paths[0]));
    provePanel.render(el, ctx);
  } }, t('prAdd')));
}

/** The controls (profile, ranges, buttons): rebuilt only when they change, never for a result,
 * so that a press on Cancel and the keys typed into a range land on the elements they began on. */
function controls(box: HTMLElement, el: HTMLElement, ctx: PanelContext): void {
  const rows = st.rows as RangeRow[];
  const running = st.job !== null;
  // Typed ends are in the fields already: they rebuild nothing.
  const key = [JSON.stringify(rows.map((r) => (r.typed ? r.path : [r.path, r.lo, r.hi]))), getLang(), !!ctx.client, running, st.proposing, st.error?.message ?? ''].join('|');
  if (box.dataset.rendered !== key) {
    box.dataset.rendered = key;
    keepFocus(box, () => box.replaceChildren(
      h('p', { class: 'hint' }, t('prIntro')),
      h('label', { class: 'field inline' }, h('span', { class: 'lbl' }, t('prProfile')), ' ',
        h('select', { name: 'prove.profile', onchange: (ev: Event) => { st.profile = (ev.target as HTMLSelectElement).value as Profile; if (st.proposal) { st.proposal = null; provePanel.render(el, ctx); } } },
          PROFILES.map((p) => h('option', { value: p, selected: p === st.profile }, t(`pf_${p}` as Key))))),
      rangeRows(el, ctx),
      h('div', { class: 'sweep-run' },
        h('button', { type: 'button', class: 'run-prove', disabled: running || !ctx.client, onclick: () => void run(el, ctx) }, t('prRun')),
        h('button', { type: 'button', class: 'cancel-prove', disabled: !running, onclick: () => { if (st.job) st.job.cancelled = true; } }, t('prCancel')),
        h('button', { type: 'button', class: 'run-propose', disabled: running || st.proposing || !ctx.client, onclick: () => void propose(el, ctx) }, st.proposing ? t('prpRunning') : t('prPropose')),
        h('progress', { class: 'prove-progress' }),
        h('span', { class: 'prove-count' }),
        h('span', { class: 'hint prove-note' }))));
  }
  // Progress is written into the same elements.
  const done = Object.keys(st.entries).length;
  const bar = box.querySelector<HTMLProgressElement>('progress.prove-progress');
  if (bar) Object.assign(bar, { max: Math.max(1, st.names.length), value: done });
  box.querySelector('.prove-count')!.textContent = st.names.length ? `${done} / ${st.names.length}` : '';
  box.querySelector('.prove-note')!.textContent = st.note ? t(st.note.key, st.note.vars) : '';
}

export const provePanel: Panel = {
  id: 'prove',
  title: 'p_prove',
  needsPython: true,
  render(el, ctx) {
    st.rows ??= ['motor.rated_current_a', 'motor.rated_voltage_v'].map((p) => defaultRow(ctx, p));
    for (const r of st.rows) if (!r.typed) Object.assign(r, defaultRow(ctx, r.path));
    let root = el.querySelector<HTMLElement>('.prove');
    if (!root) {
      root = h('div', { class: 'prove' }, h('div', { class: 'prove-controls' }), h('div', { class: 'prove-results' }));
      el.replaceChildren(root);
    }
    controls(root.children[0] as HTMLElement, el, ctx);
    // Typing in the motor re-renders every panel; the results are rebuilt only for their own state.
    const results = root.children[1] as HTMLElement;
    const key = [getLang(), JSON.stringify(st.note), st.error?.message ?? '', st.proof?.verdict ?? '', !!st.proposal, st.names.length, Object.keys(st.entries).length].join('|');
    if (results.dataset.rendered === key) return;
    results.dataset.rendered = key;
    const otherErr = st.error && !st.rows.some((r) => atRow(r.path)) ? `${st.error.field}: ${errText(st.error)}` : null;
    results.replaceChildren(
      otherErr ? h('p', { class: 'err' }, otherErr) : '',
      st.proof ? h('p', { class: `pr-overall pr-${st.proof.verdict}`, 'data-verdict': st.proof.verdict }, t('prOverall', { verdict: t(`v_${st.proof.verdict}` as Key) })) : '',
      st.names.length ? h('div', { class: 'scroll' }, table([t('prInteger'), t('prVerdict'), t('prRange'), t('prBar'), t('prWorst'), t('prWhere')],
        st.names.map((n) => row(n, st.entries[n])), 'prove-table')) : '',
      st.names.length ? h('p', { class: 'hint' }, t('prWorstHint')) : '',
      st.proof?.not_analysed.length ? h('p', { class: 'hint' }, t('prNotAnalysed', { names: st.proof.not_analysed.join(', ') })) : '',
      st.proposal ? proposalView(st.proposal) : '');
  },
};
