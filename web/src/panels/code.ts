// "Your code": paste C scaling code, pick a target (and one to compare with), and see every
// intermediate integer with its C type, hex and flags. Everything comes from
// the trace kind of pulab.api.call_json in the worker; the state lives in the URL query (code-share.ts).
import { flagChips, focusedInput, h, sameItems, table } from '../dom';
import { errText, getLang, t } from '../i18n';
import { codeSearch, codeStateFromSearch, DEFAULT_TARGET, DEFAULT_VS, differingSteps, differingVars, prefill, traceRequest, type CodeState } from '../code-share';
import { copyLinkToast } from '../page/toast';
import { LOOP_FIELDS, LOOP_PATH as LOOP_FIELD } from '../fields';
import type { Panel, PanelContext } from './panel';
import { renderProve, type ProveHost } from './code-prove';
import { COLORS, plotRaw } from '../figures/figure';
import type { TraceExample, TraceLine, TraceSequence, TraceTerm, TraceVar } from '../generated/api-types';
import type { ApiErr, Ok } from '../protocol';

type TraceOk = Ok<'trace'>;
type Reply = TraceOk | ApiErr;

const FALLBACK_TARGETS = ['c28x', 'avr', 'msp430', 'arm'];
let state: CodeState | null = null;
let examples: TraceExample[] | null = null;
let targets: string[] = FALLBACK_TARGETS;
let inputs: string[] = [];
/** The functions the pasted code defines, then its statement macros (from the last reply that parsed it). */
let functions: string[] = [];
/** Those of `functions` that are function-like macros (run as the entry on objects they name). */
let macros: string[] = [];
let main: Reply | null = null;
let other: Reply | null = null;
let lastKey = '';
let seq = 0;
let timer: ReturnType<typeof setTimeout> | undefined;
let lastCtx: PanelContext | null = null;
/** The traces (and language) the tables show: unchanged traces are not drawn again. */
let drawn: unknown[] = [];

function st(): CodeState {
  state ??= codeStateFromSearch(location.search) ?? { code: '', target: DEFAULT_TARGET, vs: DEFAULT_VS, set: {} };
  return state;
}

/** The exact decimal of a value that may exceed 2^53: the sign from the number, the bits from the hex. */
function exact(value: number | null, hex: string | null): string {
  if (value === null || hex === null) return '';
  if (Number.isSafeInteger(value)) return String(value);
  const bits = BigInt((hex.length - 2) * 4);
  const u = BigInt(hex);
  return String(value < 0 ? u - (1n << bits) : u);
}

function intCell(key: string, value: number | null, hex: string | null, differs = false): HTMLElement {
  const dec = exact(value, hex);
  return h('span', { class: `num int${differs ? ' differs' : ''}` },
    h('span', { 'data-key': `${key}`, 'data-value': dec || null, title: dec }, dec || '…'),
    hex ? h('code', { class: 'hex', 'data-hex-of': key }, ` ${hex}`) : null);
}

/** A step's value: its integer, or for a pointer input the object it points to. */
function stepCell(key: string, s: TraceLine, differs = false): HTMLElement {
  return s.points_to ? h('code', { class: 'pointer', 'data-points-to-of': key }, `&${s.points_to}`) : intCell(key, s.value, s.hex, differs);
}

function compute(ctx: PanelContext, delay = 0): void {
  clearTimeout(timer);
  timer = setTimeout(() => run(ctx), delay);
}

function run(ctx: PanelContext): void {
  const s = st();
  if (!ctx.client || !s.code) return;
  const report = ctx.report;
  const key = JSON.stringify([s, report ? prefill(inputs, report) : null, inputs]);
  if (key === lastKey) return;
  lastKey = key;
  const id = ++seq;
  const one = (target: string, channel: string) =>
    ctx.client!.call('trace', traceRequest(s, target, inputs, report), channel).then(({ result }) => result);
  const calls = [one(s.target, 'trace'), s.vs && s.vs !== s.target ? one(s.vs, 'trace-vs') : Promise.resolve(null)];
  void Promise.all(calls).then(([a, b]) => {
    if (id !== seq) return;
    main = a;
    other = b;
    const found = [...(a?.functions ?? []), ...(a?.macros ?? [])];
    // A file of functions and nothing else to run: start with the last one defined.
    const pick = a && !a.ok && a.field === 'entry' && !s.entry && found.length > 0;
    if (pick) s.entry = found[found.length - 1];
    if (pick || JSON.stringify(found) !== JSON.stringify(functions)) {
      functions = found;
      macros = a?.macros ?? [];
      builtFor = ''; // the function menu changes
      const el = document.querySelector<HTMLElement>('#panel-code .panel-body');
      if (el && lastCtx) codePanel.render(el, lastCtx);
    }
    if (pick) {
      run(ctx);
      return;
    }
    const names = a?.inputs ?? inputs;
    if (JSON.stringify(names) !== JSON.stringify(inputs)) {
      inputs = names;
      run(ctx); // the prefilled values depend on the inputs the code reads
    }
    const el = document.querySelector<HTMLElement>('#panel-code .panel-body');
    if (el) update(el, ctx);
  }, () => undefined);
}

function errorFor(field: string): string {
  for (const r of [main, other]) if (r && !r.ok && r.field === field) return errText(r);
  return '';
}

function caret(code: string, r: Reply | null): HTMLElement | null {
  if (!r || r.ok || !r.line || !r.column) return null;
  const line = code.split('\n')[r.line - 1] ?? '';
  return h('pre', { class: 'code-caret' }, `${r.line} | ${line}\n${' '.repeat(String(r.line).length + 3 + r.column - 1)}^`);
}

function renderInputs(box: HTMLElement, ctx: PanelContext): void {
  const s = st();
  const fromReport = prefill(inputs, ctx.report);
  box.replaceChildren(
    ...(inputs.length === 0 ? [h('p', { class: 'hint' }, t('codeNoInputs'))] : inputs.map((name) => {
      const report = fromReport[name];
      const field = `set.${name}`;
      return h('label', { class: 'field code-input' },
        h('span', { class: 'lbl' }, h('code', {}, name), report ? h('span', { class: 'hint' }, ` ${t('codeFromReport', { name: report.source })}`) : null),
        h('input', {
          type: 'text', name: field, value: s.set[name] ?? '', placeholder: report ? String(report.value) : '', spellcheck: 'false', inputmode: 'numeric',
          oninput: (ev: Event) => {
            s.set[name] = (ev.target as HTMLInputElement).value;
            compute(ctx, 120);
          },
        }),
        h('span', { class: 'err', 'data-err-for': field }, errorFor(field)));
    })),
  );
}

function stepsTable(a: TraceOk, b: TraceOk | null): HTMLElement {
  const pair = (i: number): TraceLine | null => {
    const x = a.steps[i];
    const y = b?.steps[i];
    return y && y.code === x.code && y.line === x.line && y.column === x.column ? y : null;
  };
  const rows: HTMLElement[] = [];
  a.steps.forEach((s, i) => {
    const o = pair(i);
    const k = `code.${a.target}.steps.${i}`;
    const differs = o !== null && o.value !== s.value;
    rows.push(h('tr', { class: `step${differs ? ' differs' : ''}${s.flags.length ? ' flagged' : ''}` },
      h('td', { class: 'pos' }, `${s.line}:${s.column}`),
      h('td', {}, h('code', {}, s.code), s.branch ? h('span', { class: 'hint' }, ` → ${s.branch}`) : null,
        ...s.terms.map((tm, j) => (tm.call && tm.steps ? callSteps(tm, `${k}.terms.${j}`) : null))),
      h('td', {}, s.var ? h('code', {}, s.var) : ''),
      h('td', { class: 'r' }, s.value === null && !s.points_to ? '' : stepCell(`${k}.value`, s, differs), h('div', { class: 'ctype' }, s.type)),
      h('td', {}, flagChips(s.flags)),
      b ? h('td', { class: 'r' }, o ? [stepCell(`code.${b.target}.steps.${i}.value`, o, differs), h('div', { class: 'ctype' }, o.type)] : '—') : null,
      b ? h('td', {}, o ? flagChips(o.flags) : '') : null));
    if (s.terms.length) {
      const terms = s.terms.map((tm, j) => {
        const ot = o?.terms[j] && o.terms[j].expr === tm.expr ? o.terms[j] : null;
        const d = ot !== null && (ot.value !== tm.value || ot.type !== tm.type);
        return h('tr', { class: d ? 'differs' : '' },
          h('td', {}, h('code', {}, tm.expr)),
          h('td', {}, tm.type),
          h('td', { class: 'r' }, intCell(`${k}.terms.${j}.value`, tm.value, tm.hex, d)),
          h('td', {}, flagChips(tm.flags)),
          b ? h('td', {}, ot?.type ?? '') : null,
          b ? h('td', { class: 'r' }, ot ? intCell(`code.${b.target}.steps.${i}.terms.${j}.value`, ot.value, ot.hex, d) : '—') : null,
          b ? h('td', {}, ot ? flagChips(ot.flags) : '') : null);
      });
      const head = [t('codeExpr'), `${t('codeType')} (${a.target})`, a.target, t('flags'), ...(b ? [`${t('codeType')} (${b.target})`, b.target, t('flags')] : [])];
      const open = s.flags.length > 0 || rows[rows.length - 1].classList.contains('differs');
      rows.push(h('tr', { class: 'terms' }, h('td', {}), h('td', { colspan: b ? 6 : 4 },
        h('details', { open }, h('summary', {}, t('codeTerms', { n: s.terms.length })), table(head, terms, 'code-terms')))));
    }
  });
  const head = ['L:C', t('codeSource'), t('codeVariable'), a.target, t('flags'), ...(b ? [b.target, t('flags')] : [])];
  return table(head, rows, 'code-steps');
}

/** The statements a call ran, under the call (keys follow the JSON path: ….terms.J.steps.K). */
function callSteps(tm: TraceTerm, key: string): HTMLElement {
  const steps = tm.steps ?? [];
  const rows = steps.map((s, i) => h('tr', { class: s.flags.length ? 'flagged' : '' },
    h('td', { class: 'pos' }, `${s.line}:${s.column}`),
    h('td', {}, h('code', {}, s.code), s.branch ? h('span', { class: 'hint' }, ` → ${s.branch}`) : null,
      ...s.terms.map((inner, j) => (inner.call && inner.steps ? callSteps(inner, `${key}.steps.${i}.terms.${j}`) : null))),
    h('td', {}, s.var ? h('code', {}, s.var) : ''),
    h('td', { class: 'r' }, s.value === null && !s.points_to ? '' : stepCell(`${key}.steps.${i}.value`, s), h('div', { class: 'ctype' }, s.type)),
    h('td', {}, flagChips(s.flags))));
  return h('details', { class: 'code-call' }, h('summary', {}, t('codeCall', { name: tm.call ?? '', n: steps.length })),
    table(['L:C', t('codeSource'), t('codeVariable'), '', t('flags')], rows, 'code-steps'));
}

/** A variable's value: its integer, or for a pointer the object it points to (`&handle.filter`). */
function varCell(key: string, v: TraceVar, differs: boolean): HTMLElement {
  if (v.c_type !== 'pointer') return intCell(key, v.value, v.hex, differs);
  return h('code', { class: `pointer${differs ? ' differs' : ''}`, 'data-points-to-of': key }, v.points_to ? `&${v.points_to}` : 'NULL');
}

const typeNote = (v: TraceVar): string => (v.bits === null ? v.c_type : `${v.c_type}, ${v.bits} bit`);

function varsTable(a: TraceOk, b: TraceOk | null): HTMLElement {
  const diff = new Set(differingVars(a.vars, b?.vars));
  const rows = Object.entries(a.vars).map(([name, v]) => {
    const o = b?.vars[name];
    const d = diff.has(name);
    const meaning = v.real !== undefined ? `${v.real.toPrecision(6)}${v.si !== undefined ? ` → ${v.si.toPrecision(6)} ${v.unit ?? ''}` : ''} (Q${v.q})` : '';
    return h('tr', { class: d ? 'differs' : '' },
      h('td', {}, h('code', {}, name), v.input ? h('span', { class: 'hint' }, ` ${t('codeInputMark')}`) : null),
      h('td', { title: v.c_type }, `${v.type}`, h('div', { class: 'ctype' }, typeNote(v))),
      h('td', { class: 'r' }, varCell(`code.${a.target}.vars.${name}.value`, v, d)),
      b ? h('td', { class: 'r' }, o ? [varCell(`code.${b.target}.vars.${name}.value`, o, d), h('div', { class: 'ctype' }, typeNote(o))] : '—') : null,
      b ? h('td', {}, d ? h('span', { class: 'flag flag-differs' }, t('codeDiffers')) : '') : null,
      h('td', {}, meaning));
  });
  return table([t('codeVariable'), t('codeType'), a.target, ...(b ? [b.target, ''] : []), t('codeMeaning')], rows, 'code-vars');
}

/** The Prove mode's view of this panel: its state, its inputs, and loading a counterexample. */
const proveHost: ProveHost = {
  state: st,
  inputs: () => inputs,
  auto: () => (main?.ok ? Object.keys(main.vars).filter((n) => main?.ok && main.vars[n].q_auto) : []),
  pointers: () => (main?.ok ? Object.keys(main.vars).filter((n) => main?.ok && main.vars[n].c_type === 'pointer') : []),
  load(values) {
    const s = st();
    for (const [name, v] of Object.entries(values)) s.set[name] = String(v);
    const el = document.querySelector<HTMLElement>('#panel-code .panel-body');
    if (!el || !lastCtx) return;
    el.querySelector<HTMLElement>('.code-inputs')?.removeAttribute('data-key'); // show the values
    update(el, lastCtx);
    compute(lastCtx);
    el.querySelector('.code-trace')?.scrollIntoView({ block: 'start' });
  },
};

/** The binding the user picked in the loop box (role → C name; '' = not bound). */
const loopPick: Record<string, string> = {};
const LOOP_ROLES: [string, RegExp][] = [['error', /err/i], ['feedback', /(^|[._>])(fb|fbk|feedback|meas)/i], ['reference', /ref/i]];
const LOOP_SCALES = LOOP_FIELDS.find((f) => f.path === `${LOOP_FIELD}.scale`)?.options ?? ['inovance'];
/** Report values that describe one worked example, not a constant of the firmware: not given to the loop. */
const EXAMPLE_ONLY = /^current_pi\.step_example\./;

/** `set` of the binding: the typed values, else the report's integer by its path (per axis for a
 * current_pi.d/q path), for every input not bound. */
function loopSet(bound: Set<string>, ctx: PanelContext): Record<string, unknown> {
  const s = st();
  const fromReport = prefill(inputs, ctx.report);
  const out: Record<string, unknown> = {};
  for (const name of inputs) {
    if (bound.has(name)) continue;
    const typed = s.set[name]?.trim();
    const r = fromReport[name];
    if (typed) out[name] = typed;
    else if (r && !EXAMPLE_ONLY.test(r.source)) {
      const axis = /^current_pi\.[dq]\./.exec(r.source);
      out[name] = axis ? { d: r.source.replace(/^current_pi\.[dq]\./, 'current_pi.d.'), q: r.source.replace(/^current_pi\.[dq]\./, 'current_pi.q.') } : r.source;
    }
  }
  return out;
}

/** "In the current loop": bind the routine's inputs and output by name and put it into the simulation. */
function renderLoop(box: HTMLElement, ctx: PanelContext): void {
  const a = main?.ok ? main : null;
  const s = st();
  const current = (ctx.input.sim?.current as Record<string, unknown> | undefined)?.code as Record<string, unknown> | undefined;
  // pulab's verdict on the binding (the simulation names the sim.current.code field at fault)
  const err = current && ctx.simError?.startsWith(LOOP_FIELD) ? ctx.simError : '';
  const key = JSON.stringify([a ? [inputs, Object.keys(a.vars)] : null, !!current, current?.output, getLang(), !!ctx.setLoop, err]);
  if (box.dataset.key === key) return;
  box.dataset.key = key;
  if (ctx.embed) { // an embedded Code view has no loop to put it in
    box.replaceChildren();
    return;
  }
  if (!a || !ctx.setLoop) {
    box.replaceChildren(...(current && ctx.setLoop ? [h('h3', {}, t('cl_title')), loopActive(current, ctx, err)] : []));
    return;
  }
  const written = Object.keys(a.vars).filter((n) => n !== 'return' && !a.vars[n].input && a.vars[n].c_type !== 'pointer');
  const outputs = [...(a.vars.return && a.vars.return.c_type !== 'pointer' ? ['return'] : []), ...written];
  for (const [role, re] of LOOP_ROLES) {
    if (loopPick[role] === undefined || (loopPick[role] && !inputs.includes(loopPick[role]))) loopPick[role] = inputs.find((n) => re.test(n)) ?? '';
  }
  if (!loopPick.output || !outputs.includes(loopPick.output)) {
    const last = [...a.steps].reverse().find((x) => x.var && written.includes(x.var))?.var;
    loopPick.output = outputs.includes('return') ? 'return' : last ?? outputs[0] ?? '';
  }
  loopPick.scale ??= 'inovance';
  const pick = (role: string, label: string, options: string[], none: boolean) =>
    h('label', {}, `${t(label as Parameters<typeof t>[0])} `,
      h('select', { name: `loop.${role}`, onchange: (ev: Event) => { loopPick[role] = (ev.target as HTMLSelectElement).value; } },
        [...(none ? [''] : []), ...options].map((v) => h('option', { value: v, selected: v === loopPick[role] }, v || t('cl_none')))));
  const use = () => {
    const bound = new Set(LOOP_ROLES.map(([r]) => loopPick[r]).filter((n) => n));
    const code: Record<string, unknown> = { text: s.code, target: s.target, scale: loopPick.scale, output: loopPick.output, set: loopSet(bound, ctx) };
    if (s.entry) code.entry = s.entry;
    for (const [role] of LOOP_ROLES) if (loopPick[role]) code[role] = loopPick[role];
    ctx.setLoop?.(code);
  };
  box.replaceChildren(
    h('h3', {}, t('cl_title')),
    h('p', { class: 'hint' }, t('cl_intro')),
    h('div', { class: 'code-controls code-loop' },
      ...LOOP_ROLES.map(([role]) => pick(role, `cl_${role}`, inputs, true)),
      pick('output', 'cl_output', outputs, false),
      pick('scale', 'cl_scale', LOOP_SCALES, false),
      h('button', { type: 'button', class: 'code-loop-use', onclick: use }, t('cl_use'))),
    current ? loopActive(current, ctx, err) : '');
}

function loopActive(current: Record<string, unknown>, ctx: PanelContext, err: string): HTMLElement {
  return h('div', {},
    h('p', { class: 'note code-loop-active' },
      t('cl_active', { output: String(current.output ?? ''), entry: String(current.entry ?? '—'), scale: String(current.scale ?? 'inovance') }), ' ',
      h('button', { type: 'button', class: 'code-loop-remove', onclick: () => ctx.setLoop?.(null) }, t('cl_remove'))),
    err ? h('p', { class: 'err code-loop-err', role: 'alert' }, err) : '');
}

/** The sequence box's own state: how many calls, the generator specs as typed, its last reply. */
const seqState = { calls: '1000', gen: '', reply: null as (Ok<'trace'> & TraceSequence) | ApiErr | null, busy: false };
/** The program (code, entry, target) the sequence box shows the calls of. */
let seqFor = '';

/** `NAME=SPEC; NAME=SPEC` → {NAME: SPEC}: the request's `gen`, split as typed (pulab checks each spec). */
function genSpecs(text: string): Record<string, string> {
  const out: Record<string, string> = {};
  for (const part of text.split(';')) {
    const at = part.indexOf('=');
    if (part.trim()) out[at < 0 ? part.trim() : part.slice(0, at).trim()] = at < 0 ? '' : part.slice(at + 1).trim();
  }
  return out;
}

/** "Over many calls": the entry called N times with generated inputs, the result per call. */
function renderSeq(box: HTMLElement, ctx: PanelContext): void {
  const s = st();
  if (!s.entry) {
    box.replaceChildren();
    return;
  }
  const r = seqState.reply;
  const runSeq = () => {
    const c = lastCtx ?? ctx; // the page's current context (the worker may have started since)
    if (!c.client || seqState.busy) return;
    seqState.busy = true;
    const req = { ...traceRequest(s, s.target, inputs, c.report), calls: /^\s*\d+\s*$/.test(seqState.calls) ? Number(seqState.calls) : seqState.calls, gen: genSpecs(seqState.gen) };
    void c.client.call('trace', req, 'trace-seq').then(({ result }) => {
      seqState.reply = result as (Ok<'trace'> & TraceSequence) | ApiErr;
    }, () => undefined).finally(() => {
      seqState.busy = false;
      renderSeq(box, ctx);
    });
  };
  const err = r && !r.ok ? `${r.field}: ${errText(r)}` : '';
  const ok = r && r.ok ? r : null;
  const event = ok?.first_event;
  const rows = (ok?.calls ?? []).map((c, k) => h('tr', { class: c.flags.length ? 'flagged' : '' },
    h('td', { class: 'r' }, String(k)),
    h('td', { class: 'r' }, c.return ? intCell(`code.seq.calls.${k}.return.value`, c.return.value, c.return.hex) : '—'),
    h('td', {}, flagChips(c.flags))));
  box.replaceChildren(
    h('h3', {}, t('cs_title')),
    h('p', { class: 'hint' }, t('cs_intro')),
    h('div', { class: 'code-controls code-seq' },
      h('label', {}, `${t('cs_calls')} `, h('input', { type: 'text', name: 'calls', value: seqState.calls, inputmode: 'numeric', size: 6,
        oninput: (ev: Event) => { seqState.calls = (ev.target as HTMLInputElement).value; } })),
      h('label', { class: 'code-seq-gen' }, `${t('cs_gen')} `, h('input', { type: 'text', name: 'gen', value: seqState.gen, spellcheck: 'false',
        placeholder: 'e=sine:amp=1000,period=200', oninput: (ev: Event) => { seqState.gen = (ev.target as HTMLInputElement).value; } })),
      h('button', { type: 'button', class: 'code-seq-run', onclick: runSeq }, t('cs_run'))),
    err ? h('p', { class: 'err code-seq-err', role: 'alert' }, err) : '',
    ok ? h('p', { class: 'note code-seq-event', 'data-key': 'code.seq.first_event', 'data-value': JSON.stringify(event) },
      event ? t('cs_event', { call: event.call, line: event.line, kind: event.kind, name: event.name }) : t('cs_none', { n: ok.calls.length })) : '',
    ...Object.entries(ok?.generated ?? {}).filter(([, g]) => g.clamped > 0).map(([name, g]) =>
      h('p', { class: 'note code-seq-clamped', 'data-key': `code.seq.generated.${name}.clamped`, 'data-value': String(g.clamped) },
        t('cs_clamped', { name, n: g.clamped, type: g.type, call: g.first_clamped ?? '' }))),
    ok ? h('div', { class: 'code-seq-plot figure' }) : '',
    ok ? h('div', { class: 'code-seq-calls' }, table([t('cs_call'), t('cs_return'), t('flags')], rows, 'code-steps')) : '',
  );
  const fig = box.querySelector<HTMLElement>('.code-seq-plot');
  if (ok && fig) seqPlot(fig, ok);
}

/** The result over the calls, the generated inputs below it. */
function seqPlot(el: HTMLElement, r: TraceSequence): void {
  const k = r.calls.map((_, i) => i);
  const gen = Object.entries(r.generated ?? {});
  const palette = [COLORS.si, COLORS.fixed, COLORS.q15, COLORS.pu];
  plotRaw(el, [
    { type: 'scatter', mode: 'lines', x: k, y: r.calls.map((c) => c.return?.value ?? null), name: t('cs_return'), line: { color: COLORS.code, width: 1.6 } },
    ...gen.map(([name, g], i) => ({ type: 'scatter', mode: 'lines', x: k, y: g.values, name, yaxis: 'y2', line: { color: palette[i % palette.length], width: 1.2 } })),
  ], {
    legend: { orientation: 'h', y: 1.1, x: 0 },
    grid: { rows: 2, columns: 1, roworder: 'top to bottom' },
    xaxis: { title: { text: t('cs_call') }, gridcolor: '#eaeef2', anchor: 'y2' },
    yaxis: { title: { text: t('cs_return') }, domain: [0.4, 1], gridcolor: '#eaeef2' },
    yaxis2: { title: { text: t('cs_gen') }, domain: [0, 0.3], gridcolor: '#eaeef2' },
  }, 320);
}

function update(el: HTMLElement, ctx: PanelContext): void {
  const s = st();
  const proveBox = el.querySelector<HTMLElement>('.code-prove-box');
  if (proveBox) renderProve(proveBox, ctx, proveHost);
  const loopEl = el.querySelector<HTMLElement>('.code-loop-box');
  if (loopEl) renderLoop(loopEl, ctx);
  const seqEl = el.querySelector<HTMLElement>('.code-seq-box');
  const seqKey = JSON.stringify([s.code, s.entry ?? '', s.target]);
  if (seqFor !== seqKey) { // another program: the last run's calls are not this one's
    seqFor = seqKey;
    seqState.reply = null;
  }
  if (seqEl && seqEl.dataset.key !== seqKey + getLang()) {
    seqEl.dataset.key = seqKey + getLang();
    renderSeq(seqEl, ctx);
  }
  const box = el.querySelector<HTMLElement>('.code-inputs');
  const boxKey = JSON.stringify([inputs, ctx.report ? prefill(inputs, ctx.report) : null, getLang()]);
  if (box && box.dataset.key !== boxKey) {
    box.dataset.key = boxKey;
    renderInputs(box, ctx);
  }
  el.querySelectorAll<HTMLElement>('[data-err-for]').forEach((e) => (e.textContent = errorFor(e.dataset.errFor ?? '')));
  el.querySelectorAll<HTMLElement>('.code-input').forEach((f) => f.classList.toggle('invalid', !!errorFor(f.querySelector('input')?.name ?? '')));
  const caretBox = el.querySelector<HTMLElement>('.code-caret-box');
  caretBox?.replaceChildren(caret(s.code, main && !main.ok && main.field === 'code' ? main : other) ?? '');
  const out = el.querySelector<HTMLElement>('.code-out');
  if (!out) return;
  el.querySelector('.code-trace')?.classList.toggle('stale', !(main?.ok));
  const a = main?.ok ? main : null;
  const b = other?.ok ? other : null;
  const other_err = [main, other].find((r): r is ApiErr => r !== null && !r.ok && r.field !== 'code' && !r.field.startsWith('set.'));
  out.querySelector('.code-global-err')?.remove();
  if (!a) {
    // The previous run's trace and its verdict would read as this code's: nothing stays.
    out.replaceChildren();
    el.querySelector('.code-trace')?.replaceChildren();
    drawn = [];
    out.classList.add('stale');
    if (other_err) out.prepend(h('p', { class: 'err code-global-err' }, `${other_err.field}: ${errText(other_err)}`));
    return;
  }
  out.classList.remove('stale');
  const shown = [a, b, getLang()];
  if (sameItems(shown, drawn) && out.childElementCount) return;
  drawn = shown;
  const diff = b ? differingVars(a.vars, b.vars) : [];
  const steps = differingSteps(a.steps, b?.steps);
  out.replaceChildren(
    b ? h('p', { class: `code-summary${diff.length || steps.length ? ' differs' : ''}`, 'data-differ': String(diff.length), 'data-steps-differ': String(steps.length) },
      diff.length ? t('codeDiffCount', { n: diff.length, m: Object.keys(a.vars).length, a: a.target, b: b.target })
        : steps.length ? t('codeSameFinal', { a: a.target, b: b.target, n: steps.length, at: `${steps[0].line}:${steps[0].column}`, code: steps[0].code })
          : t('codeSame', { a: a.target, b: b.target })) : '',
    h('h3', {}, t('codeVars')),
    varsTable(a, b),
  );
  el.querySelector<HTMLElement>('.code-trace')?.replaceChildren(
    h('h3', {}, t('codeSteps')),
    stepsTable(a, b),
    h('p', { class: 'hint' }, t('codeCheck')),
  );
}

async function share(root: HTMLElement, embed: boolean): Promise<void> {
  const url = `${location.origin}${location.pathname}${codeSearch(st(), embed)}${location.hash}`;
  document.documentElement.dataset.codeLink = url;
  await copyLinkToast(root, url);
}

function loadExamples(ctx: PanelContext): void {
  if (examples !== null || !ctx.client) return;
  examples = [];
  void ctx.client.call('trace.examples', {}).then(({ result }) => {
    if (!result.ok) return;
    examples = result.examples;
    targets = result.targets;
    const s = st();
    if (!s.code) s.code = examples.find((e) => e.id === 'flux')?.code ?? '';
    const el = document.querySelector<HTMLElement>('#panel-code .panel-body');
    if (el && lastCtx) codePanel.render(el, lastCtx);
  }, () => undefined);
}

/** What the panel's controls were last built for; a new report alone only refreshes its numbers. */
let builtFor = '';

export const codePanel: Panel = {
  id: 'code',
  title: 'p_code',
  needsPython: true,
  render(el, ctx) {
    lastCtx = ctx;
    const s = st();
    loadExamples(ctx);
    // Rebuilding the editor reads its scroll position, which forces a layout of the whole page:
    // on a new report (every keystroke in the form) only the inputs and the trace are refreshed.
    const key = JSON.stringify([getLang(), examples?.length ?? -1, targets, s.target, s.vs, functions, s.entry]);
    if (builtFor === key && el.querySelector('.code-panel')) {
      update(el, ctx);
      compute(ctx, ctx.report ? 0 : 400);
      return;
    }
    builtFor = key;
    const focused = focusedInput(el);
    const area = el.querySelector<HTMLTextAreaElement>('textarea[name="code"]');
    const sel = area ? [area.selectionStart, area.selectionEnd, area.scrollTop] : null;
    const zh = getLang() === 'zh';
    const current = examples?.find((e) => e.code === s.code)?.id ?? '';
    const select = (name: string, value: string, options: [string, string][], on: (v: string) => void) =>
      h('select', { name, onchange: (ev: Event) => on((ev.target as HTMLSelectElement).value) },
        options.map(([v, l]) => h('option', { value: v, selected: v === value }, l)));
    const changed = () => {
      compute(ctx);
      builtFor = '';
      codePanel.render(el, ctx);
    };
    el.replaceChildren(
      h('div', { class: 'code-panel' },
        h('p', { class: 'hint' }, t('codeIntro')),
        h('div', { class: 'code-controls' },
          h('label', {}, `${t('codeExample')} `, select('example', current, [['', t('codeExampleCustom')], ...(examples ?? []).map((e): [string, string] => [e.id, zh ? e.title_zh : e.title])], (v) => {
            const ex = examples?.find((e) => e.id === v);
            if (!ex) return;
            s.code = ex.code;
            s.set = {};
            changed();
          })),
          h('label', {}, `${t('codeTarget')} `, select('target', s.target, targets.map((x): [string, string] => [x, x]), (v) => {
            s.target = v;
            changed();
          })),
          h('label', {}, `${t('codeVs')} `, select('vs', s.vs, [['', t('codeNone')], ...targets.map((x): [string, string] => [x, x])], (v) => {
            s.vs = v;
            changed();
          })),
          functions.length || s.entry ? h('label', { title: t('codeEntryHint') }, `${t('codeEntry')} `,
            select('entry', s.entry ?? '', [['', t('codeEntryNone')], ...[...new Set([...functions, ...(s.entry ? [s.entry] : [])])].map((x): [string, string] => [x, macros.includes(x) ? `${x}(…)` : `${x}()`])], (v) => {
              s.entry = v;
              s.set = {};
              changed();
            }),
            h('span', { class: 'err', 'data-err-for': 'entry' }, errorFor('entry'))) : null,
          h('button', { type: 'button', class: 'code-share', onclick: () => void share(document.getElementById('app') ?? document.body, false) }, t('codeShare'))),
        h('div', { class: 'code-grid' },
          h('div', { class: 'code-left' },
            h('label', { class: 'code-src' }, h('span', { class: 'lbl' }, t('codeSource')),
              h('textarea', {
                name: 'code', rows: Math.min(24, Math.max(8, s.code.split('\n').length + 1)), spellcheck: 'false', autocapitalize: 'off', autocomplete: 'off', wrap: 'off',
                oninput: (ev: Event) => {
                  s.code = (ev.target as HTMLTextAreaElement).value;
                  const ex = el.querySelector<HTMLSelectElement>('select[name="example"]');
                  if (ex) ex.value = examples?.find((e) => e.code === s.code)?.id ?? '';
                  compute(ctx, 150);
                },
              })),
            h('span', { class: 'err', 'data-err-for': 'code' }),
            h('div', { class: 'code-caret-box' }),
            h('h3', {}, t('codeInputs')),
            h('div', { class: 'code-inputs fields' })),
          h('div', { class: 'code-out' })),
        h('div', { class: 'code-prove-box' }),
        h('div', { class: 'code-loop-box' }),
        h('div', { class: 'code-seq-box' }),
        h('div', { class: 'code-trace' })),
    );
    const ta = el.querySelector<HTMLTextAreaElement>('textarea[name="code"]');
    if (ta) {
      ta.value = s.code;
      if (sel) {
        ta.setSelectionRange(sel[0], sel[1]);
        ta.scrollTop = sel[2];
      }
    }
    update(el, ctx);
    if (focused) el.querySelector<HTMLElement>(`[name="${CSS.escape(focused)}"]`)?.focus();
    // Before the first report, wait a little: the report goes first, and it fills the inputs.
    compute(ctx, ctx.report ? 0 : 400);
  },
};
