// "Your code", Prove mode: a range per input, and for every statement a verdict over the whole
// box (pulab.ctrace.prove through the trace.prove kind, computed in slices in the worker) — proven
// with its range drawn against its C type, or violated with an input that loads into the trace.
// Progress: the proof runs in rounds of growing budget until it is decided; each round's verdicts
// are shown as it ends. Cancel supersedes the running call on its channel (the worker closes it).
import { h, num, table } from '../dom';
import { errText, getLang, t, type Key } from '../i18n';
import { prefill, traceRequest, type CodeState } from '../code-share';
import { Superseded } from '../rpc';
import type { ApiErr } from '../protocol';
import type { CodeProof, CodeStatement } from '../generated/api-types';
import type { PanelContext } from './panel';
import { bar } from './prove';

/** What the code panel lends the Prove mode. */
export interface ProveHost {
  state(): CodeState;
  inputs(): string[];
  /** The inputs annotated `// @q NAME auto` (their ranges are in real units). */
  auto(): string[];
  /** The pointer inputs (given as `&OBJECT`: they take no range). */
  pointers(): string[];
  /** Put these input values into the trace's fields and trace them. */
  load(values: Record<string, number>): void;
}

interface Job { cancelled: boolean }

const CHANNEL = 'code-prove';
/** Runs per round: the proof stops at the first round that decides every statement. */
const BUDGETS = [300, 2000, 12000];

const ps = {
  open: false,
  ranges: {} as Record<string, { lo: string; hi: string; typed: boolean }>,
  job: null as Job | null,
  proof: null as CodeProof | null,
  error: null as ApiErr | null,
  round: 0,
  note: null as null | { key: Key; vars: Record<string, string | number> },
  /** The ranges the last proof was given, as sent. */
  sent: {} as Record<string, [string, string]>,
  /** The code, target and entry the proof (running or shown) is of. */
  of: '',
};

/** What a proof is of: another code, target or entry makes it another proof. */
const proofOf = (s: CodeState): string => JSON.stringify([s.code, s.target, s.entry ?? null]);

/** The value an input without a range keeps: the one the trace uses (typed, or prefilled
 * from the report); null when the trace has none for it. */
function currentValue(host: ProveHost, report: unknown, name: string): string | null {
  const typed = host.state().set[name];
  if (typed !== undefined && typed.trim() !== '') return typed.trim();
  const v = prefill(host.inputs(), report)[name]?.value;
  return v === undefined ? null : String(v);
}

/** An `@q auto` input must have a range (real units, ±1 to start from); every other input starts
 * without one, i.e. fixed at its traced value, as the CLI keeps `--set` for inputs without `--range`. */
function defaultRange(host: ProveHost, name: string): void {
  // The `@q auto` annotations are known only once the code traces: until the user types in the
  // box, it follows them (changed in place: the fields' handlers hold the object).
  const r = (ps.ranges[name] ??= { lo: '', hi: '', typed: false });
  if (!r.typed) Object.assign(r, host.auto().includes(name) ? { lo: '-1', hi: '1' } : { lo: '', hi: '' });
}

/** The hint beside an empty range: which value the proof keeps. */
function fixedHint(host: ProveHost, report: unknown, name: string): string {
  const r = ps.ranges[name];
  if (r.lo.trim() !== '' || r.hi.trim() !== '') return '';
  const v = currentValue(host, report, name);
  return v === null ? t('cpFixedTraced') : t('cpFixedAt', { v });
}

/** The inputs a range can be given to: all but the pointers. */
const ranged = (host: ProveHost): string[] => host.inputs().filter((n) => !host.pointers().includes(n));

async function run(first: HTMLElement, ctx: PanelContext, host: ProveHost): Promise<void> {
  if (!ctx.client) return;
  // The panel may be rebuilt while the proof runs: draw into the box that is on the page.
  const draw = () => renderProve(document.querySelector<HTMLElement>('#panel-code .code-prove-box') ?? first, ctx, host);
  const s = host.state();
  const job: Job = { cancelled: false };
  Object.assign(ps, { job, proof: null, error: null, round: 0, note: null, of: proofOf(s) });
  delete document.documentElement.dataset.codeProveDone;
  draw();
  const t0 = performance.now();
  const range: Record<string, [string, string]> = {};
  for (const name of ranged(host)) {
    const r = ps.ranges[name];
    if (r && (r.lo.trim() !== '' || r.hi.trim() !== '')) range[name] = [r.lo.trim(), r.hi.trim()];
  }
  ps.sent = range;
  for (const [i, budget] of BUDGETS.entries()) {
    ps.round = i + 1;
    draw();
    const req = { ...traceRequest(s, s.target, host.inputs(), ctx.report), range, budget };
    let reply;
    try {
      reply = await ctx.client.call('trace.prove', req, CHANNEL);
    } catch (e) {
      if (!(e instanceof Superseded)) ps.error = { ok: false, field: 'input', message: String(e) };
      break;
    }
    if (job.cancelled) break;
    if (!reply.result.ok) {
      ps.error = reply.result;
      break;
    }
    ps.proof = reply.result.proof;
    if (ps.proof.verdict !== 'unknown') break;
  }
  const p = ps.proof;
  ps.note = job.cancelled ? { key: 'cpCancelled', vars: {} }
    : !p ? null
    : p.verdict === 'unknown' ? { key: 'cpUndecided', vars: { work: p.work, pct: (100 * p.decided_fraction).toFixed(1) } }
    : { key: 'cpDone', vars: { s: ((performance.now() - t0) / 1000).toFixed(2), work: p.work, boxes: p.boxes } };
  ps.job = null;
  document.documentElement.dataset.codeProveDone = job.cancelled ? 'cancelled' : p?.verdict ?? 'error';
  draw();
}

function cancel(ctx: PanelContext): void {
  if (!ps.job || !ctx.client) return;
  ps.job.cancelled = true;
  // A newer call on the channel closes the running proof between two slices.
  void ctx.client.call('trace.examples', {}, CHANNEL).catch(() => undefined);
}

const chip = (v: CodeStatement['verdict'], i: number) => h('span', { class: `flag pr-${v}`, 'data-verdict-for': String(i) }, t(`v_${v}` as Key));

function statementRow(st: CodeStatement, i: number, host: ProveHost): HTMLElement {
  const key = `code.prove.statements.${i}`;
  const kinds = st.kinds.map((k) => t(`cpk_${k}` as Key)).join(', ');
  const cx = st.counterexample;
  const c = st.computed;
  const computed = c && st.word && (c[0] < st.word[0] || c[1] > st.word[1])
    ? h('div', { class: 'hint' }, `${t('cpComputed')} [`, num(`${key}.computed.0`, c[0], { kind: 'int' }), ', ', num(`${key}.computed.1`, c[1], { kind: 'int' }), ']')
    : null;
  const why = st.verdict === 'violated' && cx
    ? h('div', {}, kinds, computed, h('div', { class: 'hint' }, Object.entries(cx).map(([k, v]) => `${k} = ${v}`).join(', ')),
      h('button', { type: 'button', class: 'code-prove-load', 'data-load-ce': String(i), onclick: () => host.load(cx) }, t('cpLoad')))
    : st.verdict === 'unknown' ? h('div', {}, kinds, computed, h('div', { class: 'hint' }, t('cpUnknownShare', { pct: (100 * st.proven_fraction).toFixed(1) }))) : '';
  return h('tr', { class: st.verdict === 'proven' ? '' : 'bad' },
    h('td', { class: 'pos' }, `${st.line}:${st.column}`),
    h('td', {}, h('code', {}, st.code)),
    h('td', {}, chip(st.verdict, i)),
    h('td', { class: 'r' }, st.range ? h('span', {}, '[', num(`${key}.range.0`, st.range[0], { kind: 'int' }), ', ', num(`${key}.range.1`, st.range[1], { kind: 'int' }), ']') : '—',
      st.type ? h('div', { class: 'ctype' }, st.type) : null),
    h('td', { class: 'pr-bar-cell' }, bar(st)),
    h('td', { class: 'pr-why' }, why));
}

/** The box the proof ran over and the inputs it kept fixed, exactly as the result gives them. */
function usedBox(p: CodeProof, host: ProveHost): HTMLElement {
  // An `@q auto` input's box is in real units (the raw one depends on the proposed Q).
  const ranges = Object.entries(p.box).map(([name, [lo, hi]]) => h('span', { 'data-box-for': name },
    h('code', {}, name), ' ∈ ', host.auto().includes(name) ? `[${ps.sent[name]?.[0]}, ${ps.sent[name]?.[1]}] ${t('cpReal')} `
      : h('span', {}, '[', num(`code.prove.box.${name}.0`, lo, { kind: 'int' }), ', ', num(`code.prove.box.${name}.1`, hi, { kind: 'int' }), '] ')));
  const fixed = Object.entries(p.set).filter((e): e is [string, number] => typeof e[1] === 'number').map(([name, v]) => h('span', { 'data-set-for': name },
    h('code', {}, name), ' = ', num(`code.prove.set.${name}`, v, { kind: 'int' }), ' '));
  return h('p', { class: 'hint code-prove-used' }, t('cpBoxUsed'), ' ', ...ranges,
    fixed.length ? h('span', {}, '; ', t('cpFixedUsed'), ' ', ...fixed) : null);
}

function proposals(p: CodeProof): HTMLElement | null {
  const list = Object.entries(p.proposals ?? {});
  if (!list.length) return null;
  return h('ul', { class: 'code-prove-proposals' }, list.map(([name, q]) => h('li', { 'data-proposal-for': name },
    q.local ? t(q.shift >= 0 ? 'cpLocalMore' : 'cpLocalLess', { name, type: q.type, lo: q.computed[0], hi: q.computed[1], n: Math.abs(q.shift), err: q.max_error_lsb })
    : q.q === null ? t('cpNoProposal', { name })
      : t('cpProposal', { name, q: q.q, type: q.type, err: String(q.max_error), pct: q.max_error_pct === null ? '—' : q.max_error_pct.toPrecision(3) }))));
}

/** Draw the Prove mode into `box` (the code panel calls it on every update). */
export function renderProve(box: HTMLElement, ctx: PanelContext, host: ProveHost): void {
  const names = ranged(host);
  for (const n of names) defaultRange(host, n);
  // Opened or closed just now: the toggle event that records it comes a task later than a rebuild may.
  const shown = box.querySelector<HTMLDetailsElement>('details.code-prove');
  if (shown) ps.open = shown.open;
  // The code changed under a proof: its verdicts are of other code, so they go (a running one stops).
  if ((ps.proof || ps.job || ps.note || ps.error) && ps.of !== proofOf(host.state())) {
    if (ps.job) cancel(ctx);
    Object.assign(ps, { proof: null, note: null, error: null, round: 0 });
  }
  const key = [getLang(), !!ctx.client, ps.open, !!ps.job, ps.round, JSON.stringify(ps.note), ps.error?.message ?? '', ps.proof?.work ?? -1, names.join(','), host.auto().join(','), JSON.stringify(host.state().set)].join('|');
  if (box.dataset.rendered === key && box.firstChild) return;
  box.dataset.rendered = key;
  const running = ps.job !== null;
  const err = (name: string) => (ps.error && ps.error.field === `range.${name}` ? errText(ps.error) : '');
  const otherErr = ps.error && !ps.error.field.startsWith('range.') ? `${ps.error.field}: ${errText(ps.error)}` : null;
  const p = ps.proof;
  box.replaceChildren(h('details', {
    class: 'code-prove', open: ps.open,
    ontoggle: (ev: Event) => {
      ps.open = (ev.target as HTMLDetailsElement).open;
      // Toggled just before a rebuild: the event reaches the old element, the new one follows it.
      const live = document.querySelector<HTMLDetailsElement>('#panel-code details.code-prove');
      if (live && live !== ev.target && live.open !== ps.open) live.open = ps.open;
    },
  },
  h('summary', {}, t('cpTitle')),
  h('p', { class: 'hint' }, t('cpIntro'), ' ', t('cpAutoHint')),
  h('div', { class: 'code-prove-ranges fields' }, names.map((name) => {
    const r = ps.ranges[name];
    const fixed = h('span', { class: 'hint', 'data-fixed-for': name }, fixedHint(host, ctx.report, name));
    const set = (k: 'lo' | 'hi') => (ev: Event) => {
      r[k] = (ev.target as HTMLInputElement).value;
      r.typed = true;
      fixed.textContent = fixedHint(host, ctx.report, name);
    };
    return h('div', { class: 'code-prove-range' },
      h('code', {}, name), host.auto().includes(name) ? h('span', { class: 'hint' }, t('cpReal')) : null,
      h('label', {}, t('cpLo'), ' ', h('input', { name: `range.${name}.0`, value: r.lo, inputmode: 'numeric', spellcheck: 'false', oninput: set('lo') })),
      h('label', {}, t('cpHi'), ' ', h('input', { name: `range.${name}.1`, value: r.hi, inputmode: 'numeric', spellcheck: 'false', oninput: set('hi') })),
      fixed,
      h('span', { class: 'err', 'data-err-for': `range.${name}` }, err(name)));
  })),
  h('div', { class: 'sweep-run' },
    h('button', { type: 'button', class: 'run-code-prove', disabled: running || !ctx.client || !names.length, onclick: () => void run(box, ctx, host) }, t('cpRun')),
    h('button', { type: 'button', class: 'cancel-code-prove', disabled: !running, onclick: () => cancel(ctx) }, t('cpCancel')),
    h('progress', { class: 'code-prove-progress', max: BUDGETS.length, value: running ? ps.round - 1 : ps.round ? BUDGETS.length : 0 }),
    h('span', { class: 'hint code-prove-note' }, running ? t('cpRound', { i: ps.round, n: BUDGETS.length, work: BUDGETS.slice(0, ps.round).reduce((a, b) => a + b, 0) })
      : ps.note ? t(ps.note.key, ps.note.vars) : '')),
  otherErr ? h('p', { class: 'err' }, otherErr) : null,
  p ? h('p', { class: `pr-overall pr-${p.verdict}`, 'data-verdict': p.verdict }, t('cpOverall', { verdict: t(`v_${p.verdict}` as Key) })) : null,
  p ? usedBox(p, host) : null,
  p ? proposals(p) : null,
  p ? h('div', { class: 'scroll' }, table(['L:C', t('cpStatement'), t('cpVerdict'), t('cpRange'), t('cpBar'), t('cpWhy')],
    p.statements.map((st, i) => statementRow(st, i, host)), 'code-prove-table')) : null));
}
